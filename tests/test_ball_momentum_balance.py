"""Every ball rebuilt in 3-D at a converged state with speed: ΣF = 0 and Σ r × F = dL/dt.

No sign convention of the model is taken on trust. The test places each ball, its contact points
and normals in 3-D from the groove geometry, takes the normal and friction forces the model
applies, the centrifugal force m ω_m² d_m/2 and the ball's angular velocity ω_b from the
kinematics, and checks, ball by ball:

* the kinematics: with ω_b the ball rolls without sliding at both contacts and does not spin at
  the controlling one (this fixes the direction of ω_b from physics, not from a formula's sign);
* the contact forces: normal forces point from the contact point to the ball centre, friction
  lies in the tangent plane;
* the force balance ΣF = 0 (the centrifugal force as the inertial term);
* the moment balance about the ball centre Σ r × F = ω_m ẑ × (J ω_b), J = ρ π D_w⁵ / 60;
* the inner ring: the forces the inner raceway exerts on the balls (normal and friction, with the
  moments of the friction taken at its contact point) add up to the applied load.
"""

import jax
import numpy as np
import pytest

from diffbearing import build_model, load_scene
from diffbearing.bearings.ball.ball_equilibrium import (
    BallModel,
    ball_azimuths,
    ball_state,
    constant_table,
    contact_forces,
    equilibrium_positions,
    inner_groove_centres,
    inner_groove_radius_of_centres,
    solve_equilibrium,
)
from diffbearing.params import Operating, ball_bearing

RPM = np.pi / 30
TOLERANCE = 1e-9


def aero_bearing():
    """The built-in aero-engine bearing of the stiffness paper: 28 balls of 28 mm on d_m = 252 mm,
    α₀ = 25°."""
    return build_model(load_scene()).inputs["bearing"]


def bearing_218():
    """A 218-size angular-contact bearing: 16 balls of 22.23 mm, d_m = 125.26 mm, f = 0.5232, α₀ = 40°
    (Harris & Kotzalas' example bearing)."""
    return ball_bearing(ball_diameter=22.23e-3, pitch_diameter=125.26e-3, balls=16, kind="angular_contact_ball",
                        inner_groove_ratio=0.5232, outer_groove_ratio=0.5232, contact_angle=np.radians(40.0))


CASES = {
    # name: (bearing, inner speed [r/min], force [N], moment [N·m])
    "aero-engine bearing, combined load and moment, 12000 r/min": (aero_bearing, 12000.0, [15e3, 18e3, 35e3], [100.0, 300.0]),
    "218, 40°, pure thrust, 10000 r/min": (bearing_218, 10000.0, [0.0, 0.0, 17.8e3], [0.0, 0.0]),
    "218, 40°, pure thrust, 20000 r/min": (bearing_218, 20000.0, [0.0, 0.0, 17.8e3], [0.0, 0.0]),
}
CONTROLS = ("outer", "inner")


def model_for(control):
    return BallModel(centrifugal=True, gyroscopic=True, race_control=control)


@pytest.fixture(scope="module")
def solved_state():
    """jit-compiled (solution, per-ball state, contact forces), one per raceway control."""
    def make(control):
        model = model_for(control)

        def run(bearing, operating):
            solution = solve_equilibrium(bearing, operating, model)
            table = constant_table(bearing, model)
            centres = inner_groove_centres(bearing, solution.displacement)
            positions = equilibrium_positions(solution.displacement, bearing, operating, model, table)
            state = ball_state(bearing, operating, centres, positions, model, table=table)
            return solution, centres, positions, state, contact_forces(bearing, state, model)

        return jax.jit(run)

    return {control: make(control) for control in CONTROLS}


def basis(psi):
    """(ẑ, e_r, e_t) at azimuth ψ: axial, radially outward, direction of increasing ψ."""
    axial = np.array([0.0, 0.0, 1.0])
    radial = np.array([np.cos(psi), np.sin(psi), 0.0])
    return axial, radial, np.cross(axial, radial)


def unit(v):
    return v / np.linalg.norm(v)


@pytest.mark.parametrize("control", CONTROLS)
@pytest.mark.parametrize("case", list(CASES))
def test_every_ball_balances_forces_and_angular_momentum_in_3d(solved_state, case, control):
    make, speed_rpm, force, moment = CASES[case]
    bearing = make()
    operating = Operating(speed_rpm * RPM, 0.0, force, moment)
    solution, centres, positions, state, forces = jax.tree.map(np.asarray, solved_state[control](bearing, operating))
    assert bool(solution.converged), float(solution.residual)

    diameter, pitch = float(bearing.ball_diameter), float(bearing.pitch_diameter)
    density = float(bearing.ball_material.density)
    mass, inertia = density * np.pi * diameter**3 / 6.0, density * np.pi * diameter**5 / 60.0
    f_inner, f_outer = float(bearing.inner_groove_ratio), float(bearing.outer_groove_ratio)
    arm = float(inner_groove_radius_of_centres(bearing))
    inner_speed = float(operating.inner_speed)
    ring_force, ring_moment = np.zeros(3), np.zeros(3)

    for j, psi in enumerate(np.asarray(ball_azimuths(bearing))):
        axial, radial, tangential = basis(psi)

        def in_3d(v):  # (axial, radial) of the ball's plane → 3-D
            return v[0] * axial + v[1] * radial

        # geometry: ball centre X and inner groove centre A relative to the outer groove centre O
        x, a = in_3d(positions[j]), in_3d(centres[j])
        r_outer = 0.5 * diameter * unit(x)  # ball centre → outer contact, on the line from O
        r_inner = 0.5 * diameter * unit(x - a)  # ball centre → inner contact, on the line from A
        # the ball's surface reaches past each groove radius (f D_w) by the approach the model uses
        np.testing.assert_allclose(np.linalg.norm(x + r_outer) - f_outer * diameter, state["outer_approach"][j],
                                   atol=1e-12 * diameter)
        np.testing.assert_allclose(np.linalg.norm(x + r_inner - a) - f_inner * diameter, state["inner_approach"][j],
                                   atol=1e-12 * diameter)

        inner_normal, outer_normal = in_3d(forces["inner_normal"][j]), in_3d(forces["outer_normal"][j])
        inner_friction, outer_friction = in_3d(forces["inner_friction"][j]), in_3d(forces["outer_friction"][j])
        centrifugal = in_3d(forces["centrifugal"][j])
        load_scale = np.linalg.norm(inner_normal) + np.linalg.norm(outer_normal) + np.linalg.norm(centrifugal)

        # normal forces push from the contact point to the ball centre; friction is tangential
        for normal, r in ((inner_normal, r_inner), (outer_normal, r_outer)):
            np.testing.assert_allclose(normal, -np.linalg.norm(normal) * unit(r), atol=1e-12 * load_scale)
        for friction, r in ((inner_friction, r_inner), (outer_friction, r_outer)):
            assert abs(friction @ unit(r)) <= 1e-12 * load_scale
        # the controlling raceway carries all the friction
        idle = outer_friction if control == "inner" else inner_friction
        assert np.all(idle == 0.0)

        # the centrifugal force, from the orbital speed alone
        orbital = float(state["orbital_speed"][j])
        np.testing.assert_allclose(centrifugal, mass * orbital**2 * 0.5 * pitch * radial, rtol=1e-12)

        # ω_b from the kinematics; check it rolls at both contacts and does not spin at the controlling one
        spin, beta = float(state["spin_speed"][j]), float(state["pitch_angle"][j])
        omega_ball = spin * (np.cos(beta) * axial - np.sin(beta) * radial) + orbital * axial
        centre = 0.5 * pitch * radial  # Jones's kinematics: the ball centre on the pitch circle
        speed_scale = abs(inner_speed) * pitch
        for r, ring_speed in ((r_outer, 0.0), (r_inner, inner_speed)):
            ball_surface = np.cross(orbital * axial, centre) + np.cross(omega_ball, r)
            ring_surface = np.cross(ring_speed * axial, centre + r)
            assert abs((ball_surface - ring_surface) @ tangential) <= 1e-12 * speed_scale
        controlling, ring_speed = (r_outer, 0.0) if control == "outer" else (r_inner, inner_speed)
        assert abs((omega_ball - ring_speed * axial) @ unit(controlling)) <= 1e-12 * abs(inner_speed)

        # force balance, centrifugal force as the inertial term
        total = inner_normal + outer_normal + inner_friction + outer_friction + centrifugal
        assert np.linalg.norm(total) <= TOLERANCE * load_scale, (j, total, load_scale)

        # angular-momentum balance about the ball centre: the ball's L = J ω_b precesses with the orbit
        moment_of_forces = (np.cross(r_outer, outer_normal + outer_friction)
                            + np.cross(r_inner, inner_normal + inner_friction))
        angular_momentum_rate = np.cross(orbital * axial, inertia * omega_ball)
        assert np.linalg.norm(angular_momentum_rate) > 0.0
        np.testing.assert_allclose(moment_of_forces, angular_momentum_rate,
                                   rtol=0.0, atol=TOLERANCE * np.linalg.norm(angular_momentum_rate),
                                   err_msg=f"ball {j}: Σ r × F ≠ dL/dt")

        # what the inner raceway exerts on this ball, with moments about the inner ring's centre
        # (its circle of groove centres, radius R_i, taken in the unloaded position)
        on_ball = inner_normal + inner_friction
        contact_from_ring_centre = arm * radial + (x + r_inner - a)
        ring_force += on_ball
        ring_moment += np.cross(contact_from_ring_centre, on_ball)

    applied = np.concatenate([force, moment])
    got = np.concatenate([ring_force, ring_moment[:2]])
    scale = np.abs(np.concatenate([force, np.asarray(moment) / arm])).max()
    np.testing.assert_allclose(got * np.array([1, 1, 1, 1 / arm, 1 / arm]),
                               applied * np.array([1, 1, 1, 1 / arm, 1 / arm]), rtol=0.0,
                               atol=TOLERANCE * scale)


def test_gyroscopic_moment_spreads_the_contact_angles_of_a_thrust_bearing(solved_state):
    """218 bearing, 17.8 kN thrust, 10000 r/min, outer-raceway control: the outer friction that
    supplies dL/dt pushes the ball radially outward and, axially, with the outer normal force. Against
    the centrifugal-only solution the gyroscopic moment therefore raises α_i and lowers α_o."""
    bearing = bearing_218()
    operating = Operating(10000 * RPM, 0.0, [0.0, 0.0, 17.8e3], [0.0, 0.0])
    _, _, _, with_gyro, forces = solved_state["outer"](bearing, operating)
    outer_friction = np.asarray(forces["outer_friction"][0])
    outer_normal = np.asarray(forces["outer_normal"][0])
    assert outer_friction[1] > 0 and np.sign(outer_friction[0]) == np.sign(outer_normal[0])

    centrifugal_only = BallModel(centrifugal=True)

    def angles(b, o):
        solution = solve_equilibrium(b, o, centrifugal_only)
        table = constant_table(b, centrifugal_only)
        centres = inner_groove_centres(b, solution.displacement)
        positions = equilibrium_positions(solution.displacement, b, o, centrifugal_only, table)
        return ball_state(b, o, centres, positions, centrifugal_only, table=table)

    without = jax.jit(angles)(bearing, operating)
    assert float(with_gyro["inner_angle"][0]) > float(without["inner_angle"][0])
    assert float(with_gyro["outer_angle"][0]) < float(without["outer_angle"][0])
