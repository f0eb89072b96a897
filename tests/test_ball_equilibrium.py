"""Quasi-static ball bearing: hard cases converge, stiffness is exact, the papers' numbers reproduced."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene
from diffbearing.bearings.ball.ball_equilibrium import (
    BallModel,
    ball_results,
    constant_table,
    ring_force,
    solve_equilibrium,
    solve_with_balls,
    stiffness_at_balls,
    stiffness_matrix,
)
from diffbearing.params import Operating, ball_bearing

from .helpers import assert_jvp_matches_central_difference, central_difference_jvp

RPM = np.pi / 30
SPEED = BallModel(centrifugal=True, gyroscopic=True)


def deep_groove_6411E(radial_clearance=28e-6):
    """The 6411E chamfer paper's bearing (docs/papers.md §The 6411E chamfer paper):
    re = 14.17 mm, ri = 13.9 mm, Dw = 26.9875 mm, Z = 7."""
    return ball_bearing(ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7, kind="deep_groove_ball",
                        inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=radial_clearance)


def solve_everything(bearing, operating):
    """The solution, its balls (from the solved state, as the scenes run them) and its stiffness
    from the solve's ball centres."""
    solution, results = solve_with_balls(bearing, operating, SPEED)
    stiffness = stiffness_matrix(solution.displacement, bearing, operating, SPEED, solution.ball_centres)
    return solution, results, stiffness


def load_sensitivity(bearing, operating):
    """A scalar of the solution (peak inner load + displacement) for gradient checks."""
    solution = solve_equilibrium(bearing, operating, SPEED)
    results = ball_results(solution.displacement, bearing, operating, SPEED, solution.ball_centres)
    return jnp.max(results.inner_load) * 1e-3 + jnp.sum(solution.displacement * jnp.array([1e5, 1e5, 1e5, 1e3, 1e3]))


@pytest.fixture(scope="module")
def solve():
    return jax.jit(solve_everything)


@pytest.fixture(scope="module")
def balancing_force():
    """The ring force at a solved state (`ring_force` with the solve's ball centres), compiled once."""
    return jax.jit(lambda displacement, bearing, operating, centres: ring_force(displacement, bearing, operating, SPEED,
                                                                             ball_centres=centres))


@pytest.fixture(scope="module")
def gradient():
    return jax.jit(jax.grad(load_sensitivity, argnums=(0, 1)))


HARD_CASES = {
    # name: (radial clearance [m], inner speed [r/min], force [N], moment [N·m])
    "radial load with clearance (half the balls unloaded)": (28e-6, 0.0, [10e3, 0, 0], [0, 0]),
    "radial load with clearance at 3000 r/min": (28e-6, 3000.0, [10e3, 0, 0], [0, 0]),
    "pure axial load, zero clearance (zero stiffness at start)": (0.0, 0.0, [0, 0, 10e3], [0, 0]),
    "pure moment, zero clearance": (0.0, 0.0, [0, 0, 0], [500.0, 0]),
    "reversed axial load (other shoulder)": (28e-6, 0.0, [0, 0, -10e3], [0, 0]),
    "combined loads with moments at speed": (28e-6, 5000.0, [4e3, -3e3, 6e3], [150.0, -80.0]),
    "zero load": (28e-6, 0.0, [0, 0, 0], [0, 0]),
    "zero load at speed (inner contacts open)": (28e-6, 6000.0, [0, 0, 0], [0, 0]),
    "high speed, outer contact angle below 5°": (28e-6, 20000.0, [0, 0, 500.0], [0, 0]),
    "heavy load, peak pressure above 4 GPa": (28e-6, 0.0, [101e3, 0, 0], [0, 0]),
}


@pytest.mark.parametrize("name", list(HARD_CASES))
def test_hard_cases_converge_with_finite_values_and_gradients(solve, gradient, balancing_force, name):
    clearance, speed, force, moment = HARD_CASES[name]
    bearing = deep_groove_6411E(clearance)
    operating = Operating(speed * RPM, 0.0, force, moment)
    solution, results, stiffness = solve(bearing, operating)
    assert bool(solution.converged), float(solution.residual)
    for value in [solution.displacement, stiffness, *jax.tree.leaves(results)]:
        assert np.all(np.isfinite(value))
    # the solved loads balance the applied load
    applied = np.concatenate([force, moment])
    np.testing.assert_allclose(balancing_force(solution.displacement, bearing, operating, solution.ball_centres),
                               applied, atol=1e-9 * (np.linalg.norm(applied) + 1e3))
    d_bearing, d_operating = gradient(bearing, operating)
    for leaf in jax.tree.leaves((d_bearing, d_operating)):
        assert np.all(np.isfinite(leaf))
    inner_loads = np.asarray(results.inner_load)
    if name.startswith("radial load with clearance"):
        assert np.sum(inner_loads == 0.0) >= 3  # the unloaded half carries exactly nothing
    if name == "zero load":  # exact zeros at standstill
        assert np.all(inner_loads == 0.0) and np.all(np.asarray(stiffness) == 0.0)
        assert np.all(np.asarray(solution.displacement) == 0.0)
    if name.startswith("zero load at speed"):  # the ring floats in the play centrifugal force opens
        assert np.all(inner_loads < 1e-9)
    if name.startswith("high speed"):
        assert np.degrees(np.min(results.outer_contact_angle)) < 5.0
    if name.startswith("heavy load"):
        assert np.max(results.inner_max_pressure) > 4e9
    if name.startswith("reversed"):
        assert np.all(np.asarray(results.inner_contact_angle) < 0)


def test_chamfer_paper_contact_angle_and_axial_shift(solve):
    """6411E under Fa = 10 kN (docs/papers.md §The 6411E chamfer paper): α′ = 18.10°, δa = 0.17 mm.

    The paper iterated with tabulated Hertz coefficients ("within a few percent of α′"): 1 % on α′;
    δa is printed to two digits: ±0.01 mm. δa is the inner ring's axial shift from the
    just-touching position at α0, which is this model's δz.
    """
    solution, results, _ = solve(deep_groove_6411E(), Operating(0.0, 0.0, [0, 0, 10e3], [0, 0]))
    angle = np.degrees(np.asarray(results.inner_contact_angle))
    np.testing.assert_allclose(angle, 18.10, rtol=0.01)
    assert abs(float(solution.displacement[2]) - 0.17e-3) <= 0.01e-3


def test_radial_load_zero_clearance_matches_sjovall(solve):
    """Zero clearance, pure radial load, standstill: the load zone is 180° (ε = 0.5) and Sjövall's
    Q_max = F_r / (Z J_r(0.5)) with J_r(0.5) = 0.2288 (Harris & Kotzalas table 7.1) holds: the
    contact angle stays 0, rings rigid, Hertz Q ∝ δ^1.5 — all the integral's assumptions. With
    Z = 7 the discrete sum differs from the integral; the azimuth of ball 0 is on the load line."""
    fr = 20e3
    _, results, _ = solve(deep_groove_6411E(0.0), Operating(0.0, 0.0, [fr, 0, 0], [0, 0]))
    loads = np.asarray(results.inner_load)
    psi = np.asarray(results.azimuth)
    # the discrete Sjövall sum (exact for this model): Fr = Qmax Σ cos^{5/2} ψ over cos ψ > 0
    cosines = np.clip(np.cos(psi), 0, None)
    np.testing.assert_allclose(loads.max(), fr / np.sum(cosines**2.5), rtol=1e-9)
    np.testing.assert_allclose(loads.max(), fr / (7 * 0.2288), rtol=0.03)


@pytest.fixture(scope="module")
def aero_bearing():
    return build_model(load_scene()).inputs


@pytest.fixture(scope="module")
def aero_force():
    return jax.jit(lambda d, b, o: ring_force(d, b, o, SPEED))


@pytest.mark.parametrize("speed_rpm", [0.0, 1500.0, 12000.0])
def test_stiffness_matches_central_difference(solve, aero_bearing, aero_force, speed_rpm):
    """K = dF/dΔ from jacfwd through the implicit ball solve against a central difference of the
    solved model: relative 1e-5 on entries above 1e-3 of the largest in their block.

    Steps: 1e-8 m and 1e-8 m / R_i rad; the per-ball solve converges to 1e-13 D_w, whose noise
    (≈ 3e-15 m × 1e9 N/m) stays below 1e-6 of K at this step, and truncation is O(h²) ≈ 1e-8.
    """
    bearing, operating = aero_bearing["bearing"], Operating(speed_rpm * RPM, 0.0, aero_bearing["operating"].force,
                                                    aero_bearing["operating"].moment)
    solution, _, stiffness = solve(bearing, operating)
    assert bool(solution.converged)
    arm = 0.5 * float(bearing.pitch_diameter)
    steps = np.array([1e-8, 1e-8, 1e-8, 1e-8 / arm, 1e-8 / arm])
    columns = []
    for j in range(5):
        e = np.zeros(5)
        e[j] = steps[j]
        plus = aero_force(solution.displacement + e, bearing, operating)
        minus = aero_force(solution.displacement - e, bearing, operating)
        columns.append((np.asarray(plus) - np.asarray(minus)) / (2 * steps[j]))
    reference = np.stack(columns, axis=1)
    stiffness = np.asarray(stiffness)
    for rows in (slice(0, 3), slice(3, 5)):
        for cols in (slice(0, 3), slice(3, 5)):
            block, ref = stiffness[rows, cols], reference[rows, cols]
            large = np.abs(ref) > 1e-3 * np.abs(ref).max()
            np.testing.assert_allclose(block[large], ref[large], rtol=1e-5)


def test_the_solved_ball_centres_give_the_balls_and_stiffness_of_a_new_ball_solve(solve, aero_bearing):
    """`ball_results` and `stiffness_matrix` given the solve's ball centres equal those that solve the
    balls again at Δ (to the per-ball tolerance, 1e-13 D_w: relative 1e-9), and trace no Newton loop;
    the balls of the solved state (`solve_with_balls`) are `ball_results` at the solve's centres and
    `stiffness_at_balls` at them (as the scenes run it) is `stiffness_matrix`, both to 1e-12."""
    bearing, operating = aero_bearing["bearing"], aero_bearing["operating"]
    solution, balls, stiffness = solve(bearing, operating)
    assert bool(solution.converged)
    again = jax.jit(lambda d, b, o: (ball_results(d, b, o, SPEED), stiffness_matrix(d, b, o, SPEED)))
    balls_again, stiffness_again = again(solution.displacement, bearing, operating)
    np.testing.assert_allclose(stiffness, stiffness_again, rtol=1e-9, atol=1e-9 * float(jnp.max(jnp.abs(stiffness))))
    for field in ("inner_load", "outer_load", "inner_contact_angle", "outer_contact_angle", "centre"):
        np.testing.assert_allclose(getattr(balls, field), getattr(balls_again, field), rtol=1e-9,
                                   atol=1e-9 * float(jnp.max(jnp.abs(getattr(balls, field)))))
    given = jax.jit(lambda d, c: ball_results(d, bearing, operating, SPEED, c))(solution.displacement,
                                                                               solution.ball_centres)
    for field, value in vars(balls).items():
        np.testing.assert_allclose(getattr(given, field), value, rtol=1e-12, atol=1e-12 * float(jnp.max(jnp.abs(value))))
    at_balls = jax.jit(lambda d, x: stiffness_at_balls(d, x, bearing, operating, SPEED))(solution.displacement,
                                                                                         balls.centre)
    np.testing.assert_allclose(at_balls, stiffness, rtol=1e-12, atol=1e-12 * float(jnp.max(jnp.abs(stiffness))))
    # the solve's table of Hertz constants is the bearing's, and the stiffness given it builds none of its own
    table = constant_table(bearing, SPEED)
    for side in ("inner", "outer"):
        coefficients = getattr(table, side)  # the higher ones cancel to rounding of the first: compared against it
        np.testing.assert_allclose(getattr(solution.constant_table, side), coefficients, rtol=0,
                                   atol=1e-14 * float(jnp.max(jnp.abs(coefficients))))
    with_table = jax.jit(lambda d, x, t: stiffness_at_balls(d, x, bearing, operating, SPEED, t))
    np.testing.assert_allclose(with_table(solution.displacement, balls.centre, solution.constant_table), at_balls,
                               rtol=1e-14, atol=1e-14 * float(jnp.max(jnp.abs(at_balls))))
    built = jax.make_jaxpr(lambda d, x: stiffness_at_balls(d, x, bearing, operating, SPEED))(
        solution.displacement, balls.centre)
    handed = jax.make_jaxpr(lambda d, x, t: stiffness_at_balls(d, x, bearing, operating, SPEED, t))(
        solution.displacement, balls.centre, table)
    assert str(built).count("scan[") > str(handed).count("scan["), "the table's ellipticity solves are not traced"
    solved = jax.make_jaxpr(lambda d, c: stiffness_matrix(d, bearing, operating, SPEED, c))(
        solution.displacement, solution.ball_centres)
    resolved = jax.make_jaxpr(lambda d: stiffness_matrix(d, bearing, operating, SPEED))(solution.displacement)
    assert "while[" not in str(solved) and "while[" in str(resolved)


def test_solved_ball_centres_derivative_matches_a_central_difference_of_new_ball_solves(solve, aero_bearing):
    """d(ball centres)/dδz from the solved centres' implicit derivative (`balls.centre`) against a
    central difference of ball solves at δz ± 1e-8 m: relative 1e-5 (the per-ball solve's 1e-13 D_w
    noise over the step)."""
    bearing, operating = aero_bearing["bearing"], aero_bearing["operating"]
    solution, _, _ = solve(bearing, operating)
    direction = jnp.zeros(5).at[2].set(1.0)
    _, tangent = jax.jit(lambda d, c: jax.jvp(lambda x: ball_results(x, bearing, operating, SPEED, c).centre,
                                              (d,), (direction,)))(solution.displacement, solution.ball_centres)
    resolved = jax.jit(lambda d: ball_results(d, bearing, operating, SPEED).centre)
    reference = central_difference_jvp(resolved, solution.displacement, direction, 1e-8)
    np.testing.assert_allclose(tangent, reference, rtol=1e-5, atol=1e-5 * float(jnp.max(jnp.abs(reference))))


def test_the_joint_roots_derivative_of_the_ball_centres_matches_central_differences(aero_bearing):
    """At speed, ring and balls are one root differentiated as one (`ball_equilibrium._joint_tangent_solve`):
    d(Δ, ball centres)/dF_x of `solve_with_balls` at 1500 r/min, forward and reverse mode, against
    central differences of whole solves at F_x ± 1 N (relative 1e-5; 1e-8 µm/N absolute, about
    1e-5 of the largest entry: the solves' 1e-13 D_w noise over the step)."""
    import equinox as eqx

    bearing, operating = aero_bearing["bearing"], aero_bearing["operating"]

    def solved(force_x):  # Δ and the ball centres [µm]
        loaded = eqx.tree_at(lambda o: o.force, operating, jnp.asarray(operating.force).at[0].set(force_x))
        solution, balls = solve_with_balls(bearing, loaded, SPEED)
        return solution.displacement * 1e6, balls.centre * 1e6

    assert_jvp_matches_central_difference(solved, jnp.asarray(operating.force[0]), jnp.ones(()), 1.0, rtol=1e-5,
                                          atol=1e-8)


def _loop_sizes(closed_jaxpr):
    """Sorted equation counts of the bodies of every `while` loop in a jaxpr, nested ones included."""
    from jax.extend.core import jaxprs_in_params

    sizes = []

    def walk(jaxpr):
        for eqn in jaxpr.eqns:
            if eqn.primitive.name == "while":
                sizes.append(len(eqn.params["body_jaxpr"].jaxpr.eqns))
            for inner in jaxprs_in_params(eqn.params):
                walk(inner)

    walk(closed_jaxpr.jaxpr)
    return sorted(sizes)


def test_a_gradient_holds_the_solves_loops_as_they_run_without_tangents(aero_bearing):
    """The starts and the joint solve take their inputs without derivative (`numerics.without_gradient`;
    the implicit root stands for theirs): the gradient's program holds each of their loops as the
    solve alone does, with no tangents carried through the iterations."""
    import equinox as eqx

    bearing, operating = aero_bearing["bearing"], aero_bearing["operating"]

    def axial_displacement(force):
        loaded = eqx.tree_at(lambda o: o.force, operating, force)
        return solve_equilibrium(bearing, loaded, SPEED).displacement[2]

    force = jnp.asarray(operating.force)
    alone = _loop_sizes(jax.make_jaxpr(axial_displacement)(force))
    assert len(alone) >= 3 and _loop_sizes(jax.make_jaxpr(jax.grad(axial_displacement))(force)) == alone


def _block_asymmetry(k):
    """Largest |K_ij − K_ji| over the translation–translation and translation–rotation blocks,
    relative to each block's largest entry."""
    k = np.asarray(k)
    return max(np.abs(k[0:3, 0:3] - k[0:3, 0:3].T).max() / np.abs(k[0:3, 0:3]).max(),
               np.abs(k[0:3, 3:5] - k[3:5, 0:3].T).max() / np.abs(k[0:3, 3:5]).max(),
               np.abs(k[3:5, 3:5] - k[3:5, 3:5].T).max() / np.abs(k[3:5, 3:5]).max())


def test_stiffness_symmetric_at_standstill_and_positive_definite(solve, aero_bearing):
    """At zero speed the force field is elastic, so K is symmetric. The Jones model evaluates the
    Hertz constant at the current contact angle, and K(α) δ^1.5 along the line of centres is not
    exactly a gradient: measured asymmetry 1.3e-5 of the block scale (bound 5e-5). With the
    constants frozen at α0 the field is the gradient of Σ (2/5) K δ^{5/2} and K is symmetric to
    rounding. All 28 balls are loaded in the aero-engine bearing, so K (its symmetric part) is positive definite."""
    operating = Operating(0.0, 0.0, aero_bearing["operating"].force, aero_bearing["operating"].moment)
    solution, results, stiffness = solve(aero_bearing["bearing"], operating)
    assert np.all(np.asarray(results.inner_load) > 0)
    assert _block_asymmetry(stiffness) < 5e-5
    arm = np.diag([1, 1, 1, 1 / 0.126, 1 / 0.126])
    scaled = arm @ np.asarray(stiffness) @ arm
    assert np.all(np.linalg.eigvalsh(0.5 * (scaled + scaled.T)) > 0)

    fixed = BallModel(hertz_constants="free_contact_angle")
    frozen = solve_equilibrium(aero_bearing["bearing"], operating, fixed)
    assert _block_asymmetry(stiffness_matrix(frozen.displacement, aero_bearing["bearing"], operating, fixed)) < 1e-13


def test_static_model_agrees_with_speed_model_at_standstill(aero_bearing):
    """With speed effects off, the closed-form static ball positions give the same solution."""
    operating = Operating(0.0, 0.0, aero_bearing["operating"].force, aero_bearing["operating"].moment)
    static = jax.jit(lambda b, o: solve_equilibrium(b, o, BallModel()))(aero_bearing["bearing"], operating)
    speed = jax.jit(lambda b, o: solve_equilibrium(b, o, SPEED))(aero_bearing["bearing"], operating)
    np.testing.assert_allclose(static.displacement, speed.displacement, rtol=1e-9, atol=1e-15)


@pytest.mark.parametrize("make", [deep_groove_6411E, lambda: build_model(load_scene()).inputs["bearing"]])
def test_constant_table_reproduces_exact_hertz_constants(make):
    """The Chebyshev table of K_i(α), K_o(α) matches the exact solve to 1e-13 over −90°…90°
    (D_w/d_m = 0.28 for the 6411E, 0.11 for the aero-engine bearing), and so does its derivative (1e-9)."""
    from diffbearing.bearings.ball.raceway_contact import contact_constant_table, contact_constants, table_constants

    bearing = make()
    table = contact_constant_table(bearing)
    angle = jnp.linspace(-np.pi / 2, np.pi / 2, 1001)
    for exact, approximate in zip(contact_constants(bearing, angle, angle), table_constants(table, angle, angle)):
        np.testing.assert_allclose(approximate, exact, rtol=1e-13)
    slope_exact = jax.vmap(jax.grad(lambda a: contact_constants(bearing, a, a)[0]))(angle[1:-1])
    slope_table = jax.vmap(jax.grad(lambda a: table_constants(table, a, a)[0]))(angle[1:-1])
    np.testing.assert_allclose(slope_table, slope_exact, atol=1e-9 * float(jnp.max(jnp.abs(slope_exact))))


def test_constant_table_derivative_matches_central_difference(aero_bearing):
    """The `hertz.constant_table` output's derivative with respect to the groove ratios and the
    ball diameter, forward and reverse, against a central difference (h = 1e-6 of each), to 1e-6
    of each side's largest coefficient (the higher coefficients are rounding-sized)."""
    import equinox as eqx

    from diffbearing.bearings.ball.raceway_contact import contact_constant_table

    bearing = aero_bearing["bearing"]
    geometry = jnp.array([bearing.inner_groove_ratio, bearing.outer_groove_ratio, bearing.ball_diameter])

    def table(values):
        changed = eqx.tree_at(lambda b: (b.inner_groove_ratio, b.outer_groove_ratio, b.ball_diameter), bearing,
                              tuple(values))
        built = contact_constant_table(changed)
        return built.inner / jnp.max(jnp.abs(built.inner)), built.outer / jnp.max(jnp.abs(built.outer))

    for direction in jnp.diag(geometry):  # each value in turn, the step 1e-6 of it
        assert_jvp_matches_central_difference(table, geometry, direction, 1e-6, rtol=0.0, atol=1e-6)


def test_preload_by_axial_displacement_inverts_preload_by_force(solve):
    """Solve with Fz = 6 kN, then prescribe the δz found: the axial force returned is 6 kN and the
    other components are unchanged (displacement control is the inverse of force control)."""
    bearing = deep_groove_6411E(0.0)
    by_force, _, _ = solve(bearing, Operating(3000 * RPM, 0.0, [4e3, 1e3, 6e3], [50.0, 0.0]))
    prescribed = Operating(3000 * RPM, 0.0, [4e3, 1e3, 0.0], [50.0, 0.0],
                           axial_displacement=by_force.displacement[2])
    by_displacement = jax.jit(lambda b, o: solve_equilibrium(b, o, SPEED))(bearing, prescribed)
    assert bool(by_displacement.converged)
    np.testing.assert_allclose(by_displacement.force, [4e3, 1e3, 6e3, 50.0, 0.0], rtol=1e-8, atol=1e-6)
    np.testing.assert_allclose(by_displacement.displacement, by_force.displacement, rtol=1e-8, atol=1e-14)


def test_prescribed_radial_displacement_inverts_radial_force_control(solve):
    """Solve with [Fx, Fy] = [4, 1] kN, then prescribe the δx, δy found: the radial force returned is
    the applied one and the other components are unchanged; the radial force's derivative with
    respect to the prescribed displacement (the implicit adjoint) matches a central difference."""
    bearing = deep_groove_6411E(0.0)
    by_force, _, _ = solve(bearing, Operating(3000 * RPM, 0.0, [4e3, 1e3, 6e3], [50.0, 0.0]))
    prescribed = Operating(3000 * RPM, 0.0, [0.0, 0.0, 6e3], [50.0, 0.0],
                           radial_displacement=by_force.displacement[:2])
    solver = jax.jit(lambda b, o: solve_equilibrium(b, o, SPEED))
    by_displacement = solver(bearing, prescribed)
    assert bool(by_displacement.converged)
    np.testing.assert_allclose(by_displacement.force, [4e3, 1e3, 6e3, 50.0, 0.0], rtol=1e-8, atol=1e-6)
    np.testing.assert_allclose(by_displacement.displacement, by_force.displacement, rtol=1e-8, atol=1e-14)

    def radial_force(shift_micrometres):
        operating = Operating(3000 * RPM, 0.0, [0.0, 0.0, 6e3], [50.0, 0.0], radial_displacement=shift_micrometres * 1e-6)
        return solver(bearing, operating).force[:2] / 1e3

    assert_jvp_matches_central_difference(radial_force, jnp.asarray(by_force.displacement[:2]) * 1e6,
                                          jnp.array([1.0, -0.5]), 1e-4, rtol=1e-5)
    with pytest.raises(ValueError, match="operating.force: Fx and Fy must be 0 with operating.radial_displacement"):
        Operating(0.0, 0.0, [1.0, 0.0, 6e3], [0.0, 0.0], radial_displacement=[1e-6, 0.0])


def test_imposed_misalignment_inverts_moment_control(solve):
    """Solve under [Mx, My] = [50, −120] N·m with the tilts free, then impose the tilts found: the
    moments returned are the applied ones and the other components are unchanged; the moments'
    derivative with respect to the imposed tilt (the implicit adjoint) matches a central difference."""
    bearing = deep_groove_6411E()
    by_moment, _, _ = solve(bearing, Operating(3000 * RPM, 0.0, [6e3, 1e3, 2e3], [50.0, -120.0]))
    imposed = Operating(3000 * RPM, 0.0, [6e3, 1e3, 2e3], [0.0, 0.0], misalignment=by_moment.displacement[3:])
    solver = jax.jit(lambda b, o: solve_equilibrium(b, o, SPEED))
    by_tilt = solver(bearing, imposed)
    assert bool(by_tilt.converged)
    np.testing.assert_allclose(by_tilt.force, [6e3, 1e3, 2e3, 50.0, -120.0], rtol=1e-8, atol=1e-6)
    np.testing.assert_allclose(by_tilt.displacement, by_moment.displacement, rtol=1e-8, atol=1e-14)

    def moments(tilt):
        operating = Operating(3000 * RPM, 0.0, [6e3, 1e3, 2e3], [0.0, 0.0], misalignment=tilt)
        return solver(bearing, operating).force[3:]

    assert_jvp_matches_central_difference(moments, jnp.asarray(by_moment.displacement[3:]), jnp.array([1.0, -0.5]),
                                          1e-6, rtol=1e-5)


def test_inner_raceway_control_converges_and_balances():
    """Inner-raceway control (gyroscopic moment reacted at the inner contact) at 12000 r/min: the
    ball equations and the ring balance hold, and the outer contact angles differ from outer control."""
    bearing = build_model(load_scene()).inputs["bearing"]
    operating = Operating(12000 * RPM, 0.0, [15e3, 18e3, 35e3], [100.0, 300.0])
    inner = BallModel(centrifugal=True, gyroscopic=True, race_control="inner")
    solution = jax.jit(lambda b, o: solve_equilibrium(b, o, inner))(bearing, operating)
    assert bool(solution.converged)
    np.testing.assert_allclose(solution.force, [15e3, 18e3, 35e3, 100.0, 300.0], rtol=1e-9)
    outer = jax.jit(lambda b, o: solve_equilibrium(b, o, SPEED))(bearing, operating)
    assert not np.allclose(solution.displacement, outer.displacement, rtol=1e-6)


def test_solution_gradient_matches_central_difference(solve, gradient):
    """d(peak inner load + weighted Δ)/d(Fx, inner speed, f_i, D_w) through both implicit solves
    (ring and balls: `newton.implicit_root`) at speed, against central differences of
    the solved model (relative steps 1e-6; tolerance 1e-5)."""
    import equinox as eqx

    bearing = deep_groove_6411E()
    operating = Operating(5000 * RPM, 0.0, [4e3, -3e3, 6e3], [150.0, -80.0])
    d_bearing, d_operating = gradient(bearing, operating)

    def objective(b, o):
        solution, results, _ = solve(b, o)
        return (np.max(results.inner_load) * 1e-3
                + float(np.sum(np.asarray(solution.displacement) * np.array([1e5, 1e5, 1e5, 1e3, 1e3]))))

    cases = [
        ("Fx", lambda b, o, h: (b, eqx.tree_at(lambda x: x.force, o, o.force + np.array([h, 0.0, 0.0]))), 4e3,
         d_operating.force[0]),
        ("inner speed", lambda b, o, h: (b, eqx.tree_at(lambda x: x.inner_speed, o, o.inner_speed + h)), 5000 * RPM,
         d_operating.inner_speed),
        ("f_i", lambda b, o, h: (eqx.tree_at(lambda x: x.inner_groove_ratio, b, b.inner_groove_ratio + h), o), 0.515,
         d_bearing.inner_groove_ratio),
        ("D_w", lambda b, o, h: (eqx.tree_at(lambda x: x.ball_diameter, b, b.ball_diameter + h), o), 26.9875e-3,
         d_bearing.ball_diameter),
    ]
    for name, perturb, scale, derivative in cases:
        h = 1e-6 * scale
        central = (objective(*perturb(bearing, operating, h)) - objective(*perturb(bearing, operating, -h))) / (2 * h)
        np.testing.assert_allclose(float(derivative), central, rtol=1e-5, err_msg=name)


@pytest.mark.slow
def test_stiffness_derivative_matches_central_difference(aero_bearing):
    """d K_zz/d f_i and d K_zz/d F_z at 12 000 r/min (second order: forward mode through the ring
    solve's implicit derivative and the stiffness' own implicit ball solve, as the stiffness-design
    notebook differentiates) against central differences of the solved model; relative steps 1e-6,
    tolerance 1e-5."""
    import equinox as eqx

    operating = Operating(12000 * RPM, 0.0, aero_bearing["operating"].force, aero_bearing["operating"].moment)

    def axial_stiffness(parameters):
        inner_ratio, axial_force = parameters
        bearing = eqx.tree_at(lambda b: b.inner_groove_ratio, aero_bearing["bearing"], inner_ratio)
        loaded = eqx.tree_at(lambda o: o.force, operating, jnp.asarray(operating.force).at[2].set(axial_force))
        solution = solve_equilibrium(bearing, loaded, SPEED)
        return stiffness_matrix(solution.displacement, bearing, loaded, SPEED)[2, 2]

    point = jnp.array([float(aero_bearing["bearing"].inner_groove_ratio), float(operating.force[2])])
    derivative = jax.jit(jax.jacfwd(axial_stiffness))(point)
    value = jax.jit(axial_stiffness)
    for k in range(2):
        h = 1e-6 * point[k]
        step = jnp.zeros(2).at[k].set(h)
        central = (value(point + step) - value(point - step)) / (2 * h)
        np.testing.assert_allclose(derivative[k], central, rtol=1e-5)


@pytest.mark.slow
def test_stiffness_at_the_solved_balls_differentiates_as_the_stiffness_matrix(aero_bearing):
    """d K_zz/d f_i and d K_zz/d F_z at 12 000 r/min (forward mode) of `stiffness_at_balls` at the
    solve's Δ and balls (`ball_results(...).centre`, each with its implicit derivative: the scenes'
    way) equal those of `stiffness_matrix` solving its balls at Δ (checked against central
    differences in `test_stiffness_derivative_matches_central_difference`), to 1e-9."""
    import equinox as eqx

    operating = Operating(12000 * RPM, 0.0, aero_bearing["operating"].force, aero_bearing["operating"].moment)

    def axial_stiffness(parameters, at_balls):
        inner_ratio, axial_force = parameters
        bearing = eqx.tree_at(lambda b: b.inner_groove_ratio, aero_bearing["bearing"], inner_ratio)
        loaded = eqx.tree_at(lambda o: o.force, operating, jnp.asarray(operating.force).at[2].set(axial_force))
        solution = solve_equilibrium(bearing, loaded, SPEED)
        if at_balls:
            centre = ball_results(solution.displacement, bearing, loaded, SPEED, solution.ball_centres).centre
            return stiffness_at_balls(solution.displacement, centre, bearing, loaded, SPEED)[2, 2]
        return stiffness_matrix(solution.displacement, bearing, loaded, SPEED)[2, 2]

    point = jnp.array([float(aero_bearing["bearing"].inner_groove_ratio), float(operating.force[2])])
    scenes_way, reference = (jax.jit(jax.jacfwd(lambda p, a=at_balls: axial_stiffness(p, a)))(point)
                             for at_balls in (True, False))
    np.testing.assert_allclose(scenes_way, reference, rtol=1e-9)


def test_negative_clearance_squeezes_every_ball_by_half_the_interference():
    """A 6411E with G_r = −10 µm (preloaded): at zero load the ring stays centred and every ball
    carries K_n(0) (5 µm)^{3/2} (Hertz, both contacts in series at α = 0), to 1e-10; the radial
    stiffness is positive where a zero-clearance bearing has none; d Q/d G_r against a central
    difference."""
    from diffbearing.bearings.ball.ball_equilibrium import free_contact_constant
    from diffbearing.params import radial_clearance

    def preloaded(clearance):
        return ball_bearing(ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7, kind="deep_groove_ball",
                            inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=clearance)

    bearing = preloaded(-10e-6)
    assert float(bearing.free_contact_angle) == 0.0 and float(radial_clearance(bearing)) == pytest.approx(-10e-6)
    at_rest = Operating(0.0, 0.0, np.zeros(3), np.zeros(2))
    solution = solve_equilibrium(bearing, at_rest)
    assert bool(solution.converged) and float(jnp.max(jnp.abs(solution.displacement))) < 1e-15
    loads = ball_results(solution.displacement, bearing, at_rest).inner_load
    expected = float(free_contact_constant(bearing, BallModel())) * (5e-6) ** 1.5
    np.testing.assert_allclose(loads, expected, rtol=1e-10)  # the solve's Chebyshev table of K(α): 2e-12
    assert float(stiffness_matrix(solution.displacement, bearing, at_rest)[0, 0]) > 0.0

    def largest_load(clearance):
        bearing = preloaded(clearance)
        return jnp.max(ball_results(solve_equilibrium(bearing, at_rest).displacement, bearing, at_rest).inner_load)

    assert_jvp_matches_central_difference(jax.jit(largest_load), jnp.asarray(-10e-6), jnp.asarray(1.0), 1e-8,
                                          rtol=1e-6)
