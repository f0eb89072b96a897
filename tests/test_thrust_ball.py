"""The thrust ball bearing through the bearing interface: equal ball loads under a pure axial load,
Harris's thrust bearing at speed (the contact angles' closed form with equal grooves), the tilt
stiffness of rigid washers, the 90° bearing's floating housing washer, its ISO 281, ISO/TS 16281 and
ISO 76 ratings (L10r = L10 under a pure axial load), the gyroscopic minimum axial load, derivatives
against central differences, and its scene entry's checks."""

import importlib.resources

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, minimum_axial_load, run_model, thrust_ball_bearing, thrust_ball_support
from diffbearing.bearings.ball import kinematics
from diffbearing.bearings.ball.ball_equilibrium import BallModel
from diffbearing.ratings import reference_life, thrust_ball_ratings


from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference, palmgren_moment

SCENE = importlib.resources.files("diffbearing.scenes") / "thrust_ball_shaft.toml"

# a 51110-size bearing (illustrative internals, the thrust_ball_shaft example's): 18 balls of
# 7.938 mm on d_m = 60 mm, f = 0.54 on both washers
GEOMETRY = dict(ball_diameter=7.938e-3, pitch_diameter=60e-3, balls=18, inner_groove_ratio=0.54,
                outer_groove_ratio=0.54)
AXIAL_BEARING = thrust_ball_bearing(**GEOMETRY)
ANGULAR_BEARING = thrust_ball_bearing(**GEOMETRY, contact_angle=np.radians(60.0))
CENTRIFUGAL = BallModel(centrifugal=True, gyroscopic=False)
SPEED_EFFECTS = BallModel(centrifugal=True, gyroscopic=True)
SPEED = 6000.0 * np.pi / 30.0  # rad/s


@jax.jit
def _force(support, displacement, speed):
    return support.ring_force(displacement, speed, support.constants())


@jax.jit
def _stiffness(support, displacement, speed):
    return support.ring_stiffness(displacement, speed, support.constants())


@jax.jit
def _contacts(support, displacement, speed):
    return support.contacts(displacement, speed, support.constants())


def _under_axial_load(support, axial_load, speed=0.0, steps=40):
    """Δ = [0, 0, δz, 0, 0] with ring force F_z = `axial_load` [N] (Newton on δz from the static
    closed form's start)."""
    bearing = support.bearing
    displacement = jnp.zeros(5).at[2].set(1e-6)
    for _ in range(steps):
        residual = float(_force(support, displacement, speed)[2]) - axial_load
        step = residual / float(_stiffness(support, displacement, speed)[2, 2])
        displacement = displacement.at[2].add(-step)
        if abs(step) < 1e-15 * float(bearing.ball_diameter):
            break
    return displacement


@pytest.mark.parametrize("bearing", [AXIAL_BEARING, ANGULAR_BEARING], ids=["90deg", "60deg"])
@hypothesis.settings(max_examples=6, deadline=None)
@hypothesis.given(axial_load=st.floats(200.0, 40e3))
def test_a_pure_axial_load_loads_every_ball_alike(bearing, axial_load):
    """Every ball alike on both washers, Q_j sin α_j = F_a / Z (1e-10), no radial force or moment;
    at 90° the angle stays 90°, at 60° it rises with the load (the contact's approach)."""
    support = thrust_ball_support(bearing, 0.0)
    displacement = _under_axial_load(support, axial_load)
    contacts = _contacts(support, displacement, 0.0)
    np.testing.assert_allclose(contacts.load * np.sin(contacts.angle), axial_load / bearing.ball_count, rtol=1e-10)
    np.testing.assert_allclose(contacts.angle, contacts.angle[0, 0], rtol=1e-12)
    if bearing.groove_facing == "axial":
        np.testing.assert_allclose(contacts.angle, 0.5 * np.pi, rtol=1e-15)
    else:
        assert float(contacts.angle[0, 0]) > float(bearing.free_contact_angle)
    force = _force(support, displacement, 0.0)
    np.testing.assert_allclose(force, [0.0, 0.0, axial_load, 0.0, 0.0], atol=1e-9 * axial_load)


@pytest.mark.parametrize("axial_load", [300.0, 3000.0, 30e3])
def test_at_speed_its_contacts_turn_by_harris_closed_form(axial_load):
    """Harris's thrust bearing at speed, centrifugal force F_c alone, equal grooves: every ball
    alike, α_i − 90° = 90° − α_o = arctan(F_c / (2 Q_a)), Q_a = F_a/Z, and Q_i = Q_o = Q_a / cos of
    that turn (1e-9), F_c at the solved orbital speed."""
    support = thrust_ball_support(AXIAL_BEARING, 0.0, model=CENTRIFUGAL)
    displacement = _under_axial_load(support, axial_load, SPEED)
    contacts = _contacts(support, displacement, SPEED)
    (inner_angle, outer_angle), (inner_load, outer_load) = contacts.angle.T, contacts.load.T
    bearing = AXIAL_BEARING
    orbital, _, _ = kinematics.ball_speeds(SPEED, inner_angle[0], outer_angle[0],
                                           bearing.ball_diameter / bearing.pitch_diameter)
    centrifugal = kinematics.centrifugal_force(bearing.ball_material.density, bearing.ball_diameter,
                                               bearing.pitch_diameter, orbital)
    ball_load = axial_load / bearing.ball_count
    turn = np.arctan(float(centrifugal) / (2.0 * ball_load))
    assert turn > 1e-3  # the speed matters here
    np.testing.assert_allclose(inner_angle - 0.5 * np.pi, turn, rtol=1e-9)
    np.testing.assert_allclose(0.5 * np.pi - outer_angle, turn, rtol=1e-9)
    np.testing.assert_allclose(inner_load, ball_load / np.cos(turn), rtol=1e-9)
    np.testing.assert_allclose(outer_load, ball_load / np.cos(turn), rtol=1e-9)


def test_its_tilt_stiffness_is_its_axial_stiffness_times_half_the_radius_squared():
    """Rigid washers at 90°, standstill, a pure axial load: each ball's approach moves by R θ sin ψ
    under a tilt θ, so K_θθ = K_zz R²/2 with R = d_m/2 (1e-10), and the floating housing washer
    leaves no radial force or stiffness; the angular-contact thrust bearing is centred by its rings."""
    support = thrust_ball_support(AXIAL_BEARING, 0.0)
    displacement = _under_axial_load(support, 5000.0)
    stiffness = np.asarray(_stiffness(support, displacement, 0.0))
    radius = 0.5 * float(AXIAL_BEARING.pitch_diameter)
    np.testing.assert_allclose(stiffness[3, 3], stiffness[2, 2] * radius**2 / 2.0, rtol=1e-10)
    np.testing.assert_allclose(stiffness[4, 4], stiffness[2, 2] * radius**2 / 2.0, rtol=1e-10)
    assert np.all(stiffness[:2] == 0.0) and np.all(stiffness[:, :2] == 0.0)
    moved = displacement.at[0].set(20e-6).at[4].set(1e-4)
    force = np.asarray(_force(support, moved, 0.0))
    assert force[0] == 0.0 and force[1] == 0.0 and abs(force[4]) > 1.0
    angular = thrust_ball_support(ANGULAR_BEARING, 0.0)
    assert float(_stiffness(angular, _under_axial_load(angular, 5000.0), 0.0)[0, 0]) > 1e6


@pytest.mark.slow
def test_its_stiffness_is_the_force_derivative_at_speed():
    """At speed with both speed effects, under a tilt: the ring stiffness against a central
    difference of the ring force, and the JVP of the ring force against one (rtol 1e-6)."""
    support = thrust_ball_support(AXIAL_BEARING, 0.0, model=SPEED_EFFECTS)
    displacement = _under_axial_load(support, 3000.0, SPEED).at[4].set(2e-5)
    direction = jnp.array([0.0, 0.0, 1e-6, 0.0, 1e-5])
    force = lambda d: support.ring_force(d, SPEED, None)
    assert_jvp_matches_central_difference(force, displacement, direction, 1e-3, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(_stiffness(support, displacement, SPEED) @ direction,
                               jax.jvp(force, (displacement,), (direction,))[1], rtol=1e-9, atol=1e-6)


def test_its_reference_life_is_its_basic_life_under_a_pure_axial_load():
    """ISO/TS 16281 with every ball loaded alike, Q = F_a/(Z sin α): L10r = (C_a/F_a)³ (sin α / sin α₀)³
    (1e-10), which at 90° is ISO 281's L10 (P_a = F_a); at 60° the loaded angle has risen above α₀,
    so the balls carry less than the standard's F_a/(Z sin α₀). C_a as `thrust_ball_ratings` gives it."""
    for bearing in (AXIAL_BEARING, ANGULAR_BEARING):
        support = thrust_ball_support(bearing, 0.0)
        displacement = _under_axial_load(support, 8000.0)
        rating = support.dynamic_load_rating()
        contacts = _contacts(support, displacement, 0.0)
        life = reference_life.contact_reference_life(contacts, support.contact_ratings(rating, contacts))
        basic = (rating / support.equivalent_dynamic_load(jnp.array([0.0, 0.0, 8000.0]))) ** 3
        np.testing.assert_allclose(basic, (rating / 8000.0) ** 3, rtol=1e-12)
        turned = (np.sin(contacts.angle[0, 0]) / np.sin(bearing.free_contact_angle)) ** 3
        np.testing.assert_allclose(life, basic * turned, rtol=1e-10)
    assert float(turned) > 1.001  # the 60° bearing's angle has moved
    np.testing.assert_allclose(thrust_ball_support(AXIAL_BEARING, 0.0).dynamic_load_rating(),
                               thrust_ball_ratings.thrust_ball_dynamic_load_rating(18, 7.938e-3, 60e-3, 0.5 * np.pi))


def test_at_its_minimum_axial_load_the_traction_just_carries_the_gyroscopic_moment():
    """At F_a,min (μ = 0.05, 6000 r/min) the solved state's controlling (housing washer) friction
    2 M_g/D_w equals μ Q_o to 5 %: the closed form reads the ball's speeds and pitch angle at α₀,
    the solve at contacts turned by 5.2° at this light load (β 82.5° → 77.4°); F_a,min grows as n²."""
    traction = 0.05
    least = float(minimum_axial_load(AXIAL_BEARING, SPEED, traction))
    np.testing.assert_allclose(minimum_axial_load(AXIAL_BEARING, 2.0 * SPEED, traction), 4.0 * least, rtol=1e-12)
    support = thrust_ball_support(AXIAL_BEARING, 0.0, model=SPEED_EFFECTS)
    displacement = _under_axial_load(support, least, SPEED)
    state = AXIAL_BEARING
    contacts = _contacts(support, displacement, SPEED)
    inner_angle, outer_angle = contacts.angle[0]
    orbital, spin, beta = kinematics.ball_speeds(SPEED, inner_angle, outer_angle,
                                                 state.ball_diameter / state.pitch_diameter)
    moment = kinematics.gyroscopic_moment(state.ball_material.density, state.ball_diameter, orbital, spin, beta)
    np.testing.assert_allclose(2.0 * float(moment) / float(state.ball_diameter), traction * float(contacts.load[0, 1]),
                               rtol=0.05)


@pytest.mark.parametrize("keys, named", [
    (dict(contact_angle=np.radians(40.0)), "bearing.contact_angle"),
    (dict(contact_angle=np.radians(80.0)), "bearing.contact_angle must be ≥ 0.785398 rad and ≤ 1.309"),
    (dict(inner_groove_ratio=0.45), "bearing.inner_groove_ratio"),
    (dict(balls=2), "bearing.balls"),
])
def test_bad_geometry_names_its_key(keys, named):
    with pytest.raises(ValueError, match=named):
        thrust_ball_bearing(**{**GEOMETRY, **keys})


@pytest.mark.parametrize("change, named", [
    (('balls = 18', 'balls = 18\ncontact_angle = "30 deg"'), "bearings[2]: contact_angle must be ≥ 0.785398 rad"),
    (('inner_groove_ratio = 0.54', 'inner_groove_ratio = 0.4'), "bearings[2]: inner_groove_ratio must be > 0.5"),
    (('balls = 18', 'balls = 18\nradial_clearance = "20 um"'), "bearings[2]: key 'radial_clearance' is not read"),
])
def test_a_bad_thrust_entry_exits_2_naming_its_key(capsys, tmp_path, change, named):
    """The example with one bad key in its thrust bearing's entry: exit 2, one line naming it."""
    text = SCENE.read_text()
    path = tmp_path / "bad.toml"
    path.write_text(text.replace(*change))
    assert_exits_2_naming(capsys, ["run", str(path)], named)


@pytest.mark.slow
def test_the_example_carries_its_thrust_on_the_thrust_bearing():
    """The thrust_ball_shaft example: converged; the cylindrical roller bearings carry no axial
    load and the thrust bearing all of it and no radial load (1e-9); the shaft's loads balance. The
    thrust bearing's Palmgren moment is HR 1's 511 row written out (f₀ 1.5 in oil, f₁ = 0.0012
    (P₀/C₀a)^0.33, M₁ = f₁ F_a d_m), 1e-12."""
    model = build_model(load_scene(str(SCENE)))
    result = run_model(model, progress=False)
    assert bool(result.values["shaft.converged"]) and not result.problems[0]
    forces = np.asarray(result.values["bearings.force"])
    np.testing.assert_allclose(forces[:2, 2], 0.0, atol=1e-9)
    np.testing.assert_allclose(forces[2, :2], 0.0, atol=1e-9)
    np.testing.assert_allclose(abs(forces[2, 2]), 6000.0, rtol=1e-9)  # in its own (turned) frame
    np.testing.assert_allclose(forces[:, 0].sum(), 1500.0, rtol=1e-9)
    lubricant, values = model.inputs["lubricant"], result.values
    f1 = 0.0012 * (float(values["bearings.equivalent_static_load"][2]) / float(values["bearings.static_load_rating"][2])) ** 0.33
    thrust = palmgren_moment(1.5, f1, 6000.0, lubricant.viscosity / lubricant.density, 3000.0, 60e-3)
    assert float(values["bearings.friction.torque"][2]) == pytest.approx(thrust, rel=1e-12)


def test_the_closed_forms_derivatives_match_central_differences():
    """F_a,min in the speed and the ball diameter, and the ISO/TS 16281 thrust raceway ratings in the
    grooves' ratios and the contact angle of a 60° bearing, against central differences (1e-7)."""
    def least(point):
        speed, ball = point
        bearing = thrust_ball_bearing(**{**GEOMETRY, "ball_diameter": ball})
        return minimum_axial_load(bearing, speed, 0.05)

    assert_jvp_matches_central_difference(least, jnp.array([SPEED, 7.938e-3]), jnp.array([1.0, 1e-5]), 1e-3,
                                          rtol=1e-7)

    def ratings(point):
        inner, outer, angle = point
        return jnp.stack(thrust_ball_ratings.thrust_ball_raceway_ratings(30e3, 18, 7.938e-3, 60e-3, angle, inner, outer))

    assert_jvp_matches_central_difference(ratings, jnp.array([0.54, 0.55, np.radians(60.0)]), jnp.array([1.0, -1.0, 5.0]),
                                          1e-5, rtol=1e-7)


@hypothesis.settings(max_examples=8, deadline=None)
@hypothesis.given(axial=st.floats(-5e-6, 40e-6), tilt_x=st.floats(-3e-4, 3e-4), tilt_y=st.floats(-3e-4, 3e-4),
                  radial=st.floats(-50e-6, 50e-6))
def test_random_states_at_standstill_are_its_static_energys_gradient(axial, tilt_x, tilt_y, radial):
    """A 90° bearing at standstill over axial approaches (some balls open), tilts and radial shifts:
    every contact normal stays axial, so the ring force is the gradient of the static energy (the
    Hertz constants at α₀ are exact; 1e-9), finite, with no radial component."""
    support = thrust_ball_support(AXIAL_BEARING, 0.0)
    displacement = jnp.array([radial, 0.5 * radial, axial, tilt_x, tilt_y])
    force = np.asarray(_force(support, displacement, 0.0))
    held = support.energy_constants(None)
    gradient = np.asarray(jax.grad(support.static_energy)(displacement, held))
    assert np.all(np.isfinite(force)) and force[0] == 0.0 and force[1] == 0.0
    np.testing.assert_allclose(force, gradient, rtol=1e-9, atol=1e-9 * (1.0 + np.max(np.abs(force))))
