"""The four-point-contact ball bearing through the bearing interface: its axial play (closed form),
one diagonal under a pure axial load equal to an angular-contact bearing at that diagonal's angle,
the mirror identity of its arches over random states (contacts opening and closing on their own),
a slewing ring's moment load against the 4.37 M / (d_m Z sin α) of rigid rings, its ratings, its
stiffness (a central difference, symmetric where the force is an energy's gradient), on a shaft."""

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest
import scipy.optimize

from diffbearing import BallSupport, Shaft, ShaftLoads, shaft_stiffness, solve_shaft
from diffbearing.bearings.ball.ball_equilibrium import BallModel
from diffbearing.bearings.ball import four_point
from diffbearing.bearings.ball.four_point import FourPointSupport, axial_clearance
from diffbearing.bearings.ball.raceway_contact import ball_raceway_modulus, both_curvatures
from diffbearing.contact import hertz
from diffbearing.params import ball_bearing, groove_curvature_centre_distance
from diffbearing.ratings import life, static_safety
from diffbearing.systems.static_capacity import capacity_point, rigid_ring_line

from .helpers import assert_jvp_matches_central_difference

# a QJ 208-size bearing (illustrative internals): 12 balls of 15 mm on d_m = 65 mm, arches at 35°
ARCHES = ball_bearing(ball_diameter=15e-3, pitch_diameter=65e-3, balls=12, inner_groove_ratio=0.52,
                      outer_groove_ratio=0.53, contact_angle=np.radians(35.0))
CLEARANCE = 60e-6  # m: diametral radial clearance
# a slewing ring of the size of SKF's RKS.062.20.1094 (20 mm balls on a 1094 mm raceway diameter;
# ball count, conformity and angle illustrative), without clearance
SLEWING = ball_bearing(ball_diameter=20e-3, pitch_diameter=1.094, balls=137, inner_groove_ratio=0.535,
                       outer_groove_ratio=0.535, contact_angle=np.radians(45.0))
MIRROR = np.array([1.0, 1.0, -1.0, -1.0, -1.0])  # Δ and F under the reflection z → −z


def _support(clearance=CLEARANCE, model=BallModel(), arches=ARCHES):
    return FourPointSupport(arches, 0.0, clearance, model=model)


@jax.jit
def _ring_force(support, displacement):
    return support.ring_force(displacement, 0.0, support.constants())


@jax.jit
def _contacts(support, displacement):
    return support.contacts(displacement, 0.0, support.constants())


def _axial(value):
    return jnp.array([0.0, 0.0, value, 0.0, 0.0])


def test_its_axial_play_is_the_closed_form():
    """No load until the inner ring has moved by half the axial play s_a/2 = √((BD)² − (BD cos α₀ −
    G_r/2)²) − BD sin α₀ (a ball free between its arches); beyond it, a load, and none at all for
    a negative clearance's preload gone (G_r = 0: loaded at once)."""
    support = _support()
    half = 0.5 * float(axial_clearance(support))
    distance = float(groove_curvature_centre_distance(ARCHES))
    radial = distance * np.cos(np.radians(35.0)) - 0.5 * CLEARANCE
    np.testing.assert_allclose(half, np.sqrt(distance**2 - radial**2) - distance * np.sin(np.radians(35.0)), rtol=1e-14)
    assert 60e-6 < 2 * half < 110e-6  # ≈ G_r cot α₀ for a small clearance
    below, above = _ring_force(support, _axial(half - 0.2e-6)), _ring_force(support, _axial(half + 0.2e-6))
    assert np.all(np.abs(np.asarray(below)) < 1e-6)  # the free balls' placeholder weight ε: ≈ 1e-7 N
    assert float(above[2]) > 1e-3
    assert float(_ring_force(_support(0.0), _axial(0.2e-6))[2]) > 1.0


@pytest.mark.parametrize("travel", [5e-6, 20e-6])
def test_one_diagonal_is_an_angular_contact_bearing(travel):
    """A pure axial displacement beyond half the play: each ball rests on one diagonal (O_1–I_1),
    the other pair open, and F_z equals that of a single-row angular-contact bearing of the same
    balls and grooves whose groove centres are those of that diagonal, B D_w (sin α_f, cos α_f)
    with B D_w cos α_f = B D_w cos α₀ − G_r/2, at the matching axial displacement (rtol 1e-8: the
    free-ball weight ε). The reversed displacement gives the reversed force (the other diagonal)."""
    support = _support()
    shift = 0.5 * float(axial_clearance(support)) + travel
    distance = float(groove_curvature_centre_distance(ARCHES))
    alpha0 = np.radians(35.0)
    alpha_f = np.arccos(np.cos(alpha0) - 0.5 * CLEARANCE / distance)
    row = BallSupport(ball_bearing(ball_diameter=15e-3, pitch_diameter=65e-3, balls=12, inner_groove_ratio=0.52,
                                   outer_groove_ratio=0.53, contact_angle=alpha_f), 0.0)
    matching = shift + distance * (np.sin(alpha0) - np.sin(alpha_f))
    want = row.ring_force(_axial(matching), 0.0, row.constants())
    got = _ring_force(support, _axial(shift))
    np.testing.assert_allclose(got[2], want[2], rtol=1e-8)
    np.testing.assert_allclose(np.asarray(got)[[0, 1, 3, 4]], 0.0, atol=1e-9 * float(want[2]))
    contacts = _contacts(support, _axial(shift))
    assert np.all(np.asarray(contacts.load[:, 2:]) == 0.0)
    np.testing.assert_allclose(contacts.angle[:, 0], contacts.angle[:, 1], rtol=1e-9)  # both on the diagonal's line
    np.testing.assert_allclose(_ring_force(support, _axial(-shift)), MIRROR * got, rtol=1e-12, atol=1e-9)


@hypothesis.settings(max_examples=10, deadline=None)
@hypothesis.given(st.floats(-40e-6, 40e-6), st.floats(-40e-6, 40e-6), st.floats(-80e-6, 80e-6),
                  st.floats(-1e-3, 1e-3), st.floats(-1e-3, 1e-3), st.floats(-20e-6, 60e-6))
def test_random_states_balance_and_mirror(dx, dy, dz, tx, ty, clearance):
    """Over random displacements and clearances (preloaded to 60 µm; balls free, on one diagonal,
    on three or four halves): every ball in balance to 1e-9 of the largest contact load, finite
    results, and the arches' mirror identity F(PΔ) = P F(Δ), P the reflection z → −z, to 1e-9."""
    support = _support(clearance)
    displacement = jnp.array([dx, dy, dz, tx, ty])
    force = _ring_force(support, displacement)
    assert np.all(np.isfinite(np.asarray(force)))
    mirrored = _ring_force(support, MIRROR * displacement)
    scale = float(jnp.max(jnp.abs(force[:3]))) + 1.0
    np.testing.assert_allclose(mirrored[:3], MIRROR[:3] * force[:3], atol=1e-9 * scale)
    np.testing.assert_allclose(mirrored[3:], MIRROR[3:] * force[3:], atol=1e-9 * scale * 0.05)
    contacts = _contacts(support, displacement)
    positions = support.ball_positions(displacement, support.constants())
    residual = support.ball_residual(positions, (support.groove_centres(displacement), support.constants(), None))
    assert float(jnp.max(jnp.abs(residual))) <= 1e-9 * (float(jnp.max(contacts.load)) + 1.0)


def test_a_slewing_ring_under_a_moment_follows_rigid_ring_theory():
    """Zero clearance, 45° arches, a small tilt: every ball carries one diagonal, Q(ψ) = Q_max
    |cos ψ|^{3/2}, so M = Q_max sin α (d_m/2) Σ_j |cos ψ_j|^{5/2} and Q_max = 4.37 M / (d_m Z sin α)
    for many balls (the slewing-ring design formula; 2/mean|cos ψ|^{5/2} = 4.370): to 0.3 % (the
    contact angles' change under load); no axial force."""
    support = _support(0.0, arches=SLEWING)
    tilt = 2e-6 / (0.5 * 1.094)  # rad: about 2 µm of axial travel at the raceway
    displacement = jnp.array([0.0, 0.0, 0.0, tilt, 0.0])
    force = _ring_force(support, displacement)
    contacts = _contacts(support, displacement)
    psi = 2 * np.pi * np.arange(137) / 137
    factor = 2.0 / np.mean(np.abs(np.cos(psi)) ** 2.5)
    np.testing.assert_allclose(factor, 4.370, atol=5e-4)
    moment = float(jnp.hypot(force[3], force[4]))
    predicted = factor * moment / (1.094 * 137 * np.sin(np.radians(45.0)))
    np.testing.assert_allclose(float(jnp.max(contacts.load)), predicted, rtol=3e-3)
    assert abs(float(force[2])) < 1e-6 * float(jnp.max(contacts.load))


def test_its_ratings_are_a_double_row_bearings():
    """C_r = 2^0.7 × one row's (ISO 281 eq. (2), i = 2), C₀r with i = 2 (ISO 76), P₀ = F_r + 0.58 F_a
    at 35° (SKF and Schaeffler print it for QJ bearings: ISO 76 Table 2's double-row row)."""
    support = _support()
    np.testing.assert_allclose(support.dynamic_load_rating(), 2**0.7 * life.basic_dynamic_load_rating(ARCHES),
                               rtol=1e-14)
    np.testing.assert_allclose(support.static_load_rating(), 2 * static_safety.ball_bearing_static_load_rating(ARCHES),
                               rtol=1e-14)
    np.testing.assert_allclose(support.equivalent_static_load(jnp.array([3000.0, 4000.0, 2000.0])),
                               5000.0 + 0.58 * 2000.0, rtol=1e-12)


def test_its_stiffness_is_the_force_derivative():
    """dF/dΔ (forward mode through the balls' implicit balance) against a central difference at a
    combined state; with the Hertz constants held at α₀ the force is an energy's gradient and the
    stiffness symmetric (1e-9)."""
    support = _support()
    displacement = jnp.array([8e-6, -3e-6, 50e-6, 2e-4, -1e-4])
    assert_jvp_matches_central_difference(lambda d: _ring_force(support, d), displacement,
                                          jnp.array([1.0, 0.5, -1.0, 20.0, 10.0]) * 1e-6, 1e-3, rtol=1e-6)
    held = _support(model=BallModel(hertz_constants="free_contact_angle"))
    stiffness = jax.jit(lambda d: held.ring_stiffness(d, 0.0, held.constants()))(displacement)
    weight = np.array([1.0, 1.0, 1.0, 0.03, 0.03])  # moments per metre of pitch radius
    scaled = np.asarray(stiffness) * weight[:, None] * weight[None, :]
    np.testing.assert_allclose(scaled, scaled.T, atol=1e-9 * np.max(np.abs(scaled)))


def test_its_static_energy_is_exact_on_one_diagonal():
    """The start energy's gradient (each diagonal as an angular-contact row) equals the ring force
    where every ball rests on one diagonal, the Hertz constants held at α₀ (1e-8)."""
    held = _support(model=BallModel(hertz_constants="free_contact_angle"))
    displacement = _axial(0.5 * float(axial_clearance(held)) + 15e-6).at[0].set(2e-6)
    gradient = jax.grad(held.static_energy)(displacement, held.energy_constants(held.constants()))
    np.testing.assert_allclose(gradient, _ring_force(held, displacement), rtol=1e-8, atol=1e-8 * float(gradient[2]))


@pytest.mark.slow
def test_a_slewing_ring_alone_carries_axial_load_and_moment():
    """A slewing ring as a shaft's only bearing under an axial load, a radial load and a tilting
    moment: converged, its ring force the applied load (1e-8), the shaft's stiffness its own."""
    support = FourPointSupport(SLEWING, 0.0, 0.1e-3)
    loads = ShaftLoads(np.zeros(1), np.array([[20e3, 0.0, 150e3]]), np.array([[0.0, 200e3]]))
    solution = solve_shaft(Shaft((support,), loads))
    assert bool(solution.converged)
    local = solution.bearing_displacements[0]
    np.testing.assert_allclose(_ring_force(support, local), [20e3, 0.0, 150e3, 0.0, 200e3], rtol=1e-8, atol=1e-3)
    shaft = Shaft((support,), loads)
    np.testing.assert_allclose(shaft_stiffness(solution.displacement, shaft, constants=solution.constants),
                               support.ring_stiffness(local, 0.0, support.constants()), rtol=1e-9)


def _rigid_ring_point(ratio, limit_load, balls=137, pitch_diameter=1.094, angle=0.25 * np.pi):
    """(F_a [N], M_y [N·m]) of rigid rings without clearance whose most loaded ball carries Q_lim,
    F_x = 0 and M_y / F_a = `ratio` [m], each diagonal of a ball a contact pair at the fixed angle
    α (the diagonal model of slewing-ring analyses): the inner ring's axial motion at ball j
    w = 1 + b cos ψ and radial v = c cos ψ shorten or lengthen its diagonals by u_{1,2} = ±w sin α
    + v cos α; Q_k = Q_lim max(u_k, 0)^{3/2} / max u^{3/2}; F_a = Σ (Q_1 − Q_2) sin α, M_y =
    −Σ (Q_1 − Q_2) sin α (d_m/2) cos ψ, F_x = Σ (Q_1 + Q_2) cos α cos ψ; (b, c) from F_x = 0 and the
    ratio."""
    psi = 2 * np.pi * np.arange(balls) / balls

    def loads(unknowns):
        b, c = unknowns
        axial, radial = 1.0 + b * np.cos(psi), c * np.cos(psi)
        first, second = (np.maximum(side * axial * np.sin(angle) + radial * np.cos(angle), 0.0) ** 1.5
                         for side in (1.0, -1.0))
        scale = limit_load / max(first.max(), second.max())
        force = scale * np.sum(first - second) * np.sin(angle)
        moment = -scale * np.sum((first - second) * np.cos(psi)) * np.sin(angle) * 0.5 * pitch_diameter
        return force, moment, scale * np.sum((first + second) * np.cos(psi)) * np.cos(angle)

    def equations(unknowns):
        force, moment, radial = loads(unknowns)
        return [moment / force - ratio, radial / force]

    found = scipy.optimize.root(equations, [-0.5, 0.0], tol=1e-13)
    assert found.success
    return loads(found.x)[:2]


def test_the_capacity_curve_meets_the_pressure_limit_and_rigid_ring_theory():
    """`static_capacity.capacity_point` on three rays of a slewing ring without clearance at a light
    limit of 500 MPa (approaches of a few µm against arches 1.4 mm apart): the largest pressure at
    each point is the limit (1e-8), and each point is the diagonal model's of rigid rings
    (`_rigid_ring_point`, the inner ring moving radially as well where axial load and moment
    combine) to 0.3 % (the contact angles' change under load); the ends are the 4.37 rule's line,
    F_a/(Z sin α) + 4.37 M/(d_m Z sin α) = Q_lim (Q_lim the ball load of that pressure at α₀),
    whose middle is conservative: the point lies 14 % beyond it."""
    support = _support(0.0, arches=SLEWING)
    limit = 0.5e9
    sums, differences = both_curvatures(SLEWING, np.radians(45.0), np.radians(45.0))
    unit = hertz.point_contact(np.ones(2), sums, differences, ball_raceway_modulus(SLEWING))
    limit_load = float((limit / np.max(np.asarray(unit.max_pressure))) ** 3)
    axial_end, moment_end = rigid_ring_line(137, 1.094, np.radians(45.0), limit_load)
    points = [capacity_point(support, np.cos(angle) * 1e4, np.sin(angle) * 2e3, limit)
              for angle in (0.0, 0.25 * np.pi, 0.5 * np.pi)]
    assert all(point.converged for point in points)
    for point in points:
        contacts = _contacts(support, jnp.asarray(point.displacement))
        np.testing.assert_allclose(float(jnp.max(contacts.max_pressure)), limit, rtol=1e-8)
    np.testing.assert_allclose(points[0].axial_load, axial_end, rtol=3e-3)
    np.testing.assert_allclose(points[2].moment, moment_end, rtol=3e-3)
    np.testing.assert_allclose([points[1].axial_load, points[1].moment], _rigid_ring_point(0.2, limit_load), rtol=3e-3)
    assert points[1].axial_load / axial_end + points[1].moment / moment_end == pytest.approx(1.14, abs=0.01)


def test_its_equivalent_dynamic_load_is_the_qj_catalogue_rule():
    """P = F_r + 0.66 F_a for F_a/F_r ≤ 0.95, else 0.6 F_r + 1.07 F_a at 35° (SKF and Schaeffler for
    QJ bearings: ISO 281 Table 3's double-row row), 1e-12."""
    support = _support()
    np.testing.assert_allclose(support.equivalent_dynamic_load(jnp.array([3000.0, 4000.0, 4000.0])),
                               5000.0 + 0.66 * 4000.0, rtol=1e-12)
    np.testing.assert_allclose(support.equivalent_dynamic_load(jnp.array([0.0, 2000.0, 4000.0])),
                               0.6 * 2000.0 + 1.07 * 4000.0, rtol=1e-12)


@pytest.mark.slow
def test_a_ball_solve_stopped_short_says_so(monkeypatch):
    """The shaft counts each ball's balance (`balance_residual`) in its convergence: solved, every
    ball balanced to 1e-6 N and the shaft's residual below 1e-9; with the exact-balance Newton
    skipped (the convex start alone, Hertz constants at α₀) the balls are off by the constants'
    angle dependence and the shaft reports not converged, with finite values."""
    loads = ShaftLoads(np.zeros(1), np.array([[1000.0, 0.0, 3000.0]]), np.zeros((1, 2)))
    solution = solve_shaft(Shaft((_support(),), loads))
    assert bool(solution.converged) and float(solution.residual) < 1e-9
    support = _support()
    assert float(support.balance_residual(solution.bearing_displacements[0], 0.0, support.constants(), 1.0)) < 1e-6
    monkeypatch.setattr(four_point, "BALL_NEWTON_STEPS", 0)
    short = solve_shaft(Shaft((_support(),), loads))
    assert not bool(short.converged)
    assert np.all(np.isfinite(np.asarray(short.displacement)))
