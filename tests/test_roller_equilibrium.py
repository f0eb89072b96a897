"""Whole roller bearings: exact identities of the load distribution, Stribeck's and Harris's line-contact
closed forms, the stiffness against central differences, and the hard cases (open clearance, tilt
that lifts roller ends, zero load, edge loading, pure axial load)."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from scipy.integrate import quad

from diffbearing.bearings.roller import roller_equilibrium as re
from diffbearing.bearings.roller.roller_geometry import roller_bearing
from diffbearing.bearings.roller.roller_profile import roller_profile

from .helpers import assert_jvp_matches_central_difference, central_difference_jvp


def cylindrical(clearance=20e-6, profile=None, length=14.7e-3, rollers=14):
    """Seed 003's cylindrical roller bearing: 14 rollers of 25.4 mm, d_m = 106.6 mm."""
    if profile is None:
        profile = roller_profile("circular", length=length, flat_length=length - 2e-3, crown_radius=0.2)
    bearing = roller_bearing(kind="cylindrical_roller", diameter=25.4e-3, length=length, roller_count=rollers,
                             profile=profile)
    return bearing, re.roller_raceways(bearing, pitch_diameter=106.6e-3, diametral_clearance=clearance)


def tapered(clearance=0.0):
    """Seed 004's tapered roller (7.0/8.0 mm, l = 12 mm, θ = 2.4°, Johns–Gohar at 1 kN), 18 rollers, 15° cup."""
    bearing = roller_bearing(kind="tapered_roller", small_diameter=7e-3, large_diameter=8e-3, length=12e-3,
                             cone_half_angle=np.radians(2.4), roller_count=18,
                             profile=roller_profile("johns_gohar", design_load=1e3))
    return bearing, re.roller_raceways(bearing, pitch_diameter=50.7e-3, diametral_clearance=clearance,
                                       cup_angle=np.radians(15.0))


def operating(force, moment=(0.0, 0.0), misalignment=None, inner_speed=0.0):
    return re.RollerOperating(force=jnp.asarray(force, float), moment=jnp.asarray(moment, float),
                              inner_speed=inner_speed, misalignment=misalignment)


@pytest.fixture(scope="module")
def solve():
    return jax.jit(re.solve_roller_equilibrium, static_argnums=3)


@pytest.fixture(scope="module")
def results():
    return jax.jit(re.roller_results, static_argnums=4)


@pytest.fixture(scope="module")
def stiffness():
    return jax.jit(re.roller_stiffness_matrix, static_argnums=4)


@pytest.fixture(scope="module")
def force():
    return jax.jit(re.ring_force, static_argnums=4)


STATIC, SPEED = re.RollerModel(), re.RollerModel(centrifugal=True)


def test_long_straight_roller_agrees_with_stribeck_and_harris(solve, results):
    """Zero clearance, uncrowned rollers, pure radial load: every lamina of roller j has the approach
    δ_r cos ψ_j, so Q_max = F_r / (Z J_r(½)) with the line-contact integral J_r(½) = (1/2π)∫cos^{19/9}ψ dψ
    = 0.24480 (Stribeck's 4.08 F_r/Z; Harris & Kotzalas vol. 1 Table 7.1 prints J_r(0.5) = 0.2453 for
    line contact). For Z = 14 the roller sum differs from the integral by 2.5e-4 (measured), so the
    bound is 1e-3. The ring deflection is Harris's δ_r = 7.68e-5 Q_max^0.9 / l^0.8 [mm, N] (Palmgren, both
    contacts) within 4 %: ISO/TS 16281's lamina constant c_L = 35948 gives 35948^-0.9 = 7.93e-5 instead
    of 7.68e-5, +3.3 %."""
    length = 40e-3
    bearing, raceways = cylindrical(0.0, roller_profile("straight"), length=length)
    radial = 50e3
    load = operating([radial, 0.0, 0.0])
    solution = solve(bearing, raceways, load, STATIC)
    assert bool(solution.converged)
    per_roller = results(solution.displacement, bearing, raceways, load, STATIC)
    integral = quad(lambda psi: np.cos(psi) ** (19.0 / 9.0), -np.pi / 2, np.pi / 2)[0] / (2 * np.pi)
    q_max = float(per_roller.inner_load[0])
    np.testing.assert_allclose(q_max, radial / (14 * integral), rtol=1e-3)
    np.testing.assert_allclose(q_max, radial / (14 * 0.2453), rtol=3e-3)
    harris = 7.68e-5 * q_max**0.9 / (length * 1e3) ** 0.8 * 1e-3
    np.testing.assert_allclose(float(solution.displacement[0]), harris, rtol=0.04)
    # without centrifugal force both contacts of a lamina carry the same load (to rounding), and Σ Q_j cos ψ_j = F_r exactly
    np.testing.assert_allclose(per_roller.inner_load, per_roller.outer_load, rtol=1e-13)
    np.testing.assert_allclose(jnp.sum(per_roller.inner_load * jnp.cos(per_roller.azimuth)), radial, rtol=1e-10)


def test_pure_axial_load_on_a_tapered_bearing(solve, results):
    """Every roller carries Q = F_a / (Z sin α_o) at the cup (exact identity of the ring balance); the rib
    takes Q_f = 2 sin θ Q per roller (roller balance along its axis, no speed)."""
    bearing, raceways = tapered()
    axial = 3e3
    load = operating([0.0, 0.0, axial])
    solution = solve(bearing, raceways, load, STATIC)
    assert bool(solution.converged)
    per_roller = results(solution.displacement, bearing, raceways, load, STATIC)
    cup_load = axial / (18 * np.sin(np.radians(15.0)))
    np.testing.assert_allclose(per_roller.outer_load, cup_load, rtol=1e-9)
    np.testing.assert_allclose(per_roller.rib_load, 2 * np.sin(np.radians(2.4)) * cup_load, rtol=1e-9)
    np.testing.assert_allclose(solution.displacement[jnp.array([0, 1, 3, 4])], 0.0, atol=1e-15)


@pytest.mark.slow  # 35 s: compiles the aligned solve at speed
def test_a_tapered_bearing_at_speed_needs_the_axial_push_of_its_rollers_centrifugal_forces(solve, results):
    """At 1000 rad/s under F_r = 300 N, the rings held aligned, an equilibrium exists only for F_z above F_r tan α_o +
    Z F_c sin α_o cos α_m / cos θ (`tapered_axial_load_needed`; at rest F_r tan α_o exactly). 2 %
    above it the solve converges, with the bound's premises as identities of the solution: the ring
    takes the cup's push less F_c, F_z = sin α_o Σ Q_o and F_x = cos α_o Σ Q_o cos ψ, and every cup
    load is at least Q_c = F_c cos α_m / cos θ. 2 % below it the solve stops unconverged, finite."""
    bearing, raceways = tapered()
    cup, half = np.radians(15.0), np.radians(2.4)
    rest = float(re.tapered_axial_load_needed(bearing, raceways, operating([300.0, 0.0, 0.0]), STATIC))
    assert rest == pytest.approx(300.0 * np.tan(cup), rel=1e-14)
    needed = float(re.tapered_axial_load_needed(bearing, raceways, operating([300.0, 0.0, 0.0], inner_speed=1e3), SPEED))
    centrifugal = float(re.roller_centrifugal_force(bearing, raceways, operating([0.0] * 3, inner_speed=1e3)))
    lightest = centrifugal * np.cos(cup - half) / np.cos(half)
    assert needed == pytest.approx(rest + 18 * lightest * np.sin(cup), rel=1e-14) and needed > 1.9 * rest

    aligned = jnp.zeros(2)
    above = operating([300.0, 0.0, 1.02 * needed], inner_speed=1e3, misalignment=aligned)
    solution = solve(bearing, raceways, above, SPEED)
    assert bool(solution.converged)
    per_roller = results(solution.displacement, bearing, raceways, above, SPEED)
    cup_loads = per_roller.outer_load
    assert float(jnp.sin(cup) * jnp.sum(cup_loads)) == pytest.approx(1.02 * needed, rel=1e-8)
    assert float(jnp.cos(cup) * jnp.sum(cup_loads * jnp.cos(per_roller.azimuth))) == pytest.approx(300.0, rel=1e-8)
    assert float(jnp.min(cup_loads)) >= lightest * (1.0 - 1e-8)

    below = solve(bearing, raceways, operating([300.0, 0.0, 0.98 * needed], inner_speed=1e3, misalignment=aligned),
                  SPEED)
    assert not bool(below.converged) and float(below.residual) > 1e-3
    assert np.all(np.isfinite(below.displacement)) and np.all(np.isfinite(below.force))


def test_cylindrical_bearing_refuses_an_axial_force(solve):
    bearing, raceways = cylindrical()
    with pytest.raises(ValueError, match="operating.force"):
        re.solve_roller_equilibrium(bearing, raceways, operating([1e3, 0.0, 10.0]))


ARM = 0.5 * 50.7e-3  # m: the scale of tilts and moments in the block comparison


def _difference_stiffness(force, displacement, bearing, raceways, load, model):
    """Central-difference stiffness, steps 1e-11 m and 1e-11 m / ARM rad: a lamina just opening has a
    kink in dq/dδ ∝ δ^{1/9}, so the step must be far below the approaches (rounding error ≈ 1e-16 F/h ≈ 1e-9 K)."""
    steps = 1e-11 * np.array([1.0, 1.0, 1.0, 1.0 / ARM, 1.0 / ARM])
    columns = [central_difference_jvp(lambda d: force(d, bearing, raceways, load, model), displacement,
                                      jnp.eye(5)[k], steps[k]) for k in range(5)]
    return np.stack(columns, axis=1)


def _assert_blocks_match(exact, reference, rtol=1e-5):
    """Entries above 1e-3 of their block's largest (force/translation, force/tilt, moment/translation,
    moment/tilt) agree to `rtol`. In units where tilts and moments carry the arm ARM, a block below
    1e-6 of the matrix's largest entry is zero by symmetry: there both must be below that."""
    scale = np.array([1.0, 1.0, 1.0, ARM, ARM])
    exact = np.asarray(exact) / scale[:, None] / scale[None, :]
    reference = np.asarray(reference) / scale[:, None] / scale[None, :]
    floor = 1e-6 * np.abs(exact).max()
    for rows in (slice(0, 3), slice(3, 5)):
        for cols in (slice(0, 3), slice(3, 5)):
            block, ref = exact[rows, cols], reference[rows, cols]
            large = np.abs(block).max()
            if large < floor:
                np.testing.assert_array_less(np.abs(ref), floor)
                continue
            mask = np.abs(block) > 1e-3 * large
            np.testing.assert_allclose(block[mask], ref[mask], rtol=rtol)


CASES = [
    ("cylindrical", dict(force=[8e3, 0.0, 0.0]), STATIC),
    ("cylindrical", dict(force=[6e3, 2e3, 0.0], moment=[0.0, 20.0]), STATIC),
    ("cylindrical", dict(force=[8e3, 0.0, 0.0], misalignment=jnp.array([0.0, 5e-4]), inner_speed=900.0), SPEED),
    ("tapered", dict(force=[0.0, 0.0, 3e3]), STATIC),
    ("tapered", dict(force=[4e3, 0.0, 2e3], misalignment=jnp.array([0.0, 5e-4])), STATIC),
    ("tapered", dict(force=[4e3, 0.0, 2e3], moment=[0.0, 5.0], inner_speed=1500.0), SPEED),
]


@pytest.mark.parametrize("kind, case, model", CASES)
def test_stiffness_matches_central_differences(solve, stiffness, force, kind, case, model):
    bearing, raceways = cylindrical() if kind == "cylindrical" else tapered()
    load = operating(**case)
    solution = solve(bearing, raceways, load, model)
    assert bool(solution.converged)
    exact = stiffness(solution.displacement, bearing, raceways, load, model)
    reference = _difference_stiffness(force, solution.displacement, bearing, raceways, load, model)
    _assert_blocks_match(exact, reference)
    assert np.all(np.isfinite(exact))
    if not model.centrifugal:  # a conservative field: K = Kᵀ
        np.testing.assert_allclose(exact, exact.T, rtol=0, atol=1e-12 * np.abs(exact).max())


@pytest.mark.slow
def test_displacement_derivative_through_the_solve(solve):
    """dΔ/d(F_r, F_a, clearance) through the implicit ring solve (with centrifugal force: the rollers'
    implicit solves under it) against a central difference; slow: 35 s of compiling JVP and VJP."""
    bearing, raceways = tapered(5e-6)

    def displacement(x):
        load = operating(jnp.stack([x[0], 0.0, x[1]]), inner_speed=1500.0)
        changed = re.RollerRaceways(raceways.pitch_diameter, x[2], raceways.cup_angle)
        return solve(bearing, changed, load, SPEED).displacement * 1e6

    assert_jvp_matches_central_difference(displacement, jnp.array([4e3, 2e3, 5e-6]), jnp.array([1e3, 5e2, 2e-6]),
                                          1e-4, rtol=1e-5, atol=1e-6)


def _assert_finite_gradient(function, point):
    gradient = jax.jacrev(function)(point)
    assert np.all(np.isfinite(gradient)), gradient


@pytest.mark.slow
def test_radial_load_with_clearance_leaves_rollers_out_of_contact(solve, results):
    """50 µm clearance, 2 kN: rollers outside the load zone carry exact zeros, and the solution and its
    gradient with respect to the load are finite, with and without centrifugal force."""
    bearing, raceways = cylindrical(50e-6)
    for model in (STATIC, SPEED):
        load = operating([2e3, 0.0, 0.0], inner_speed=300.0)
        solution = solve(bearing, raceways, load, model)
        assert bool(solution.converged), model
        per_roller = results(solution.displacement, bearing, raceways, load, model)
        assert np.sum(per_roller.inner_load == 0.0) >= 7
        _assert_finite_gradient(lambda f: solve(bearing, raceways, operating(jnp.stack([f, 0.0, 0.0]), inner_speed=300.0),
                                                model).displacement, jnp.asarray(2e3))


def test_misalignment_that_lifts_one_end_of_every_roller(solve, results):
    """2 mrad imposed tilt on a light radial load: one end of every loaded roller is open (exact zero
    lamina loads), the moment the tilt needs is an output, and everything stays finite."""
    bearing, raceways = cylindrical(0.0, roller_profile("straight"))
    load = operating([1e3, 0.0, 0.0], misalignment=jnp.array([0.0, 2e-3]))
    solution = solve(bearing, raceways, load, STATIC)
    assert bool(solution.converged)
    per_roller = results(solution.displacement, bearing, raceways, load, STATIC)
    loaded = np.asarray(per_roller.inner_load) > 0
    laminae = np.asarray(per_roller.inner_lamina_load)[loaded]
    assert np.all((laminae[:, 0] == 0.0) | (laminae[:, -1] == 0.0))
    assert abs(float(solution.force[4])) > 0  # the moment the imposed tilt needs
    _assert_finite_gradient(lambda t: solve(bearing, raceways, operating([1e3, 0.0, 0.0], misalignment=jnp.stack([0.0, t])),
                                            STATIC).force, jnp.asarray(2e-3))


def test_prescribed_radial_displacement_inverts_radial_force_control(solve):
    """The tapered bearing under [Fx, Fy, Fz] = [4, 1, 2] kN, then with the δx, δy found prescribed:
    the radial force returned is the applied one and the displacement is unchanged."""
    bearing, raceways = tapered()
    by_force = solve(bearing, raceways, operating([4e3, 1e3, 2e3]), STATIC)
    prescribed = re.RollerOperating(force=jnp.array([0.0, 0.0, 2e3]), moment=jnp.zeros(2),
                                    radial_displacement=by_force.displacement[:2])
    by_displacement = solve(bearing, raceways, prescribed, STATIC)
    assert bool(by_force.converged) and bool(by_displacement.converged)
    np.testing.assert_allclose(by_displacement.force, [4e3, 1e3, 2e3, 0.0, 0.0], rtol=1e-8, atol=1e-6)
    np.testing.assert_allclose(by_displacement.displacement, by_force.displacement, rtol=1e-8, atol=1e-14)


def test_prescribed_axial_displacement_inverts_axial_force_control(solve):
    """The tapered bearing under [Fx, Fy, Fz] = [4, 1, 2] kN with its tilts held, then with the δz
    found prescribed (setting by displacement) and Fz = 0: the axial force returned is the
    applied 2 kN and the displacement is unchanged; with the cone set 5 µm further in, the axial
    force rises (the preload a tighter setting adds)."""
    bearing, raceways = tapered()
    held = jnp.zeros(2)
    by_force = solve(bearing, raceways, operating([4e3, 1e3, 2e3], misalignment=held), STATIC)

    def set_at(axial):
        return re.RollerOperating(force=jnp.array([4e3, 1e3, 0.0]), moment=jnp.zeros(2), misalignment=held,
                                  axial_displacement=axial)

    by_displacement = solve(bearing, raceways, set_at(by_force.displacement[2]), STATIC)
    assert bool(by_force.converged) and bool(by_displacement.converged)
    assert np.asarray(re.prescribed_coordinates(bearing, set_at(0.0))).tolist() == [0, 0, 1, 1, 1]
    np.testing.assert_allclose(by_displacement.force[:3], [4e3, 1e3, 2e3], rtol=1e-8)
    np.testing.assert_allclose(by_displacement.force[3:], by_force.force[3:], rtol=1e-8)
    np.testing.assert_allclose(by_displacement.displacement, by_force.displacement, rtol=1e-8, atol=1e-14)
    tighter = solve(bearing, raceways, set_at(by_force.displacement[2] + 5e-6), STATIC)
    assert bool(tighter.converged) and float(tighter.force[2]) > 2.2e3
    cylinder, cylinder_raceways = cylindrical()
    with pytest.raises(ValueError, match="operating.axial_displacement: a cylindrical roller bearing"):
        re.solve_roller_equilibrium(cylinder, cylinder_raceways, set_at(0.0), STATIC)


@pytest.mark.parametrize("kind", ["cylindrical", "tapered"])
def test_zero_load(solve, stiffness, kind):
    """No load, no clearance: Δ = 0, the stiffness is finite (zero: q ∝ δ^{10/9} has no stiffness at
    δ = 0) and so is the gradient."""
    bearing, raceways = cylindrical(0.0) if kind == "cylindrical" else tapered()
    load = operating([0.0, 0.0, 0.0])
    solution = solve(bearing, raceways, load, STATIC)
    assert bool(solution.converged)
    np.testing.assert_array_equal(solution.displacement, 0.0)
    assert np.all(np.isfinite(stiffness(solution.displacement, bearing, raceways, load, STATIC)))
    _assert_finite_gradient(lambda f: solve(bearing, raceways, operating(jnp.stack([f, 0.0, f])), STATIC).displacement,
                            jnp.asarray(0.0))


def test_heavy_load_on_a_tilted_straight_roller_loads_its_edge(solve, results):
    """Straight rollers, 60 kN and 1 mrad imposed tilt: the most loaded roller's largest lamina load sits at
    one end (edge loading), the solve converges and the result is finite."""
    bearing, raceways = cylindrical(0.0, roller_profile("straight"))
    load = operating([60e3, 0.0, 0.0], misalignment=jnp.array([0.0, 1e-3]))
    solution = solve(bearing, raceways, load, STATIC)
    assert bool(solution.converged)
    per_roller = results(solution.displacement, bearing, raceways, load, STATIC)
    most = int(np.argmax(per_roller.inner_load))
    assert int(np.argmax(per_roller.inner_lamina_load[most])) in (0, STATIC.laminae - 1)
    assert np.all(np.isfinite(per_roller.inner_max_pressure))
