"""The double-row angular-contact ball bearing (O arrangement) through the bearing interface: the
back-to-back pair of its rows (identities, at standstill and at speed), one row under a pure
axial load, its ISO 281 and ISO/TS 16281 ratings, its stiffness and a derivative."""

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import BallSupport, Shaft, ShaftLoads, bearing_set, shaft_stiffness, solve_shaft
from diffbearing.bearings.ball.ball_equilibrium import BallModel
from diffbearing.bearings.ball.double_row import DoubleRowSupport
from diffbearing.params import ball_bearing
from diffbearing.ratings import life
from diffbearing.ratings.reference_life import contact_reference_life
from diffbearing.systems.shaft_equilibrium import shaft_force

from .helpers import assert_jvp_matches_central_difference

# one row of a 3208-size double-row bearing: 13 balls of 11.1 mm on d_m = 62.5 mm, 30° (a 7208-like row)
ROW = ball_bearing(ball_diameter=11.1e-3, pitch_diameter=62.5e-3, balls=13, kind="angular_contact_ball",
                   inner_groove_ratio=0.52, outer_groove_ratio=0.53, contact_angle=np.radians(30.0))
SPACING = 15e-3  # m: between the rows' centres
SPEED_MODEL = BallModel(centrifugal=True, gyroscopic=True)


def _loads(force, moment=(0.0, 0.0)):
    return ShaftLoads(np.zeros(1), np.array([force], float), np.array([moment], float))


def _double_row(clearance=0.0, model=BallModel(), spacing=SPACING):
    return DoubleRowSupport(ROW, spacing, 0.0, axial_clearance=clearance, model=model)


@pytest.mark.parametrize("clearance", [0.0, -4e-6, 10e-6])
def test_its_ring_force_is_the_back_to_back_pairs(clearance):
    """F(Δ) of the double-row bearing equals the shaft force of the back-to-back pair of its rows
    with offset −s_a/2 and no spacer (`bearing_set`'s orientations), at random displacements
    (preloaded, zero and positive axial clearance)."""
    bearing = _double_row(clearance)
    rows = (BallSupport(ROW, -0.5 * SPACING, -0.5 * clearance), BallSupport(ROW, 0.5 * SPACING, -0.5 * clearance,
                                                                            orientation=-1))
    pair = Shaft(rows, _loads([0.0, 0.0, 0.0]))  # `bearing_set`'s back-to-back pair, an offset of either sign
    for displacement in np.random.default_rng(1).normal(size=(4, 5)) * np.array([1e-5, 1e-5, 1e-5, 3e-4, 3e-4]):
        np.testing.assert_allclose(bearing.ring_force(jnp.asarray(displacement), 0.0, bearing.constants()),
                                   shaft_force(jnp.asarray(displacement), pair), rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("model", [BallModel(), pytest.param(SPEED_MODEL, marks=pytest.mark.slow)], ids=["static", "speed"])
def test_on_a_shaft_it_is_the_back_to_back_pair(model):
    """One double-row bearing on a shaft and its rows as a back-to-back pair, under radial, axial
    and tilting load (at 12 000 r/min with speed effects: both rows' balls carried by the shaft's
    Newton): the same shaft displacement, bearing load and stiffness."""
    load = _loads([3000.0, -1000.0, 1500.0], (40.0, 0.0))
    speed = 12000 * np.pi / 30 if model.speed_effects else 0.0
    single = Shaft((_double_row(-4e-6, model),), load, speed)
    pair = Shaft(bearing_set(ROW, "back_to_back", spacing=SPACING, offset=2e-6, model=model), load, speed)
    one, two = solve_shaft(single), solve_shaft(pair)
    assert bool(one.converged) and bool(two.converged)
    np.testing.assert_allclose(one.displacement, two.displacement, rtol=1e-8, atol=1e-14)
    np.testing.assert_allclose(shaft_stiffness(one.displacement, single, elements=one.elements, constants=one.constants),
                               shaft_stiffness(two.displacement, pair, elements=two.elements, constants=two.constants),
                               rtol=1e-7)


def test_a_pure_axial_load_rests_on_one_row():
    """Zero clearance, F_z on the inner ring: row 1 (facing +z) carries it all, as a single row
    under the same load; row 2's balls are free; the life is row 1's alone at its own C_r."""
    force = 4000.0
    bearing = _double_row()
    solution = solve_shaft(Shaft((bearing,), _loads([0.0, 0.0, force])))
    alone = solve_shaft(Shaft((BallSupport(ROW, 0.0),), _loads([0.0, 0.0, force])))
    assert bool(solution.converged)
    np.testing.assert_allclose(solution.displacement[2], alone.displacement[2], rtol=1e-10)
    contacts = bearing.contacts(solution.bearing_displacements[0], 0.0, solution.constants[0])
    assert contacts.load.shape == (ROW.ball_count, 4)
    assert np.all(np.asarray(contacts.load[:, 2:]) == 0.0)
    np.testing.assert_allclose(jnp.sum(contacts.load[:, 0] * jnp.sin(contacts.angle[:, 0])), force, rtol=1e-9)
    rating = bearing.dynamic_load_rating()
    np.testing.assert_allclose(rating, 2**0.7 * life.basic_dynamic_load_rating(ROW), rtol=1e-15)
    row = BallSupport(ROW, 0.0).contacts(alone.bearing_displacements[0], 0.0, alone.constants[0])
    np.testing.assert_allclose(contact_reference_life(contacts, bearing.contact_ratings(rating, contacts)),
                               life.reference_rating_life(ROW, life.basic_dynamic_load_rating(ROW),
                                                          row.load[:, 0], row.load[:, 1]), rtol=1e-9)


def test_the_turned_rows_balls_are_matched_by_azimuth():
    """Under a radial load along +x at zero clearance both rows load the balls at ψ = 0 most, and
    symmetrically: ball j and ball −j carry the same load in each row, columns at row 1's azimuths."""
    bearing = _double_row()
    solution = solve_shaft(Shaft((bearing,), _loads([5000.0, 0.0, 0.0])))
    contacts = bearing.contacts(solution.bearing_displacements[0], 0.0, solution.constants[0])
    load = np.asarray(contacts.load)
    assert np.argmax(load[:, 0]) == 0 and np.argmax(load[:, 2]) == 0
    np.testing.assert_allclose(load[:, 0], load[:, 2], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(load[1:, 0], load[1:, 0][::-1], rtol=1e-9, atol=1e-9)


def test_its_stiffness_is_the_jacobian_of_its_ring_force():
    bearing = _double_row(-4e-6)
    displacement = jnp.array([4e-6, -2e-6, 3e-6, 1e-4, -2e-4])
    constants = bearing.constants()
    np.testing.assert_allclose(bearing.ring_stiffness(displacement, 0.0, constants),
                               jax.jacfwd(bearing.ring_force)(displacement, 0.0, constants), rtol=1e-10, atol=1e-3)


def test_the_shaft_displacement_derivative_in_the_row_spacing_matches_central_differences():
    def displacement(spacing):
        return solve_shaft(Shaft((_double_row(-4e-6, spacing=spacing),), _loads([3000.0, 0.0, 1000.0], (60.0, 0.0)))
                           ).displacement

    assert_jvp_matches_central_difference(displacement, jnp.asarray(SPACING), jnp.asarray(1.0), step=1e-6, rtol=1e-6)


def test_its_equivalent_dynamic_load_is_iso_281s_double_row_column():
    """ISO 281 Table 3, double row at 30°: P = F_r + 0.78 F_a up to e = 0.80, then 0.63 F_r + 1.24 F_a (1e-12)."""
    bearing = _double_row()
    np.testing.assert_allclose(bearing.equivalent_dynamic_load(jnp.array([3000.0, 0.0, 2000.0])),
                               3000.0 + 0.78 * 2000.0, rtol=1e-12)
    np.testing.assert_allclose(bearing.equivalent_dynamic_load(jnp.array([3000.0, 0.0, 2500.0])),
                               0.63 * 3000.0 + 1.24 * 2500.0, rtol=1e-12)


def test_bad_rows_are_refused():
    deep = ball_bearing(ball_diameter=11.1e-3, pitch_diameter=62.5e-3, balls=13, kind="deep_groove_ball",
                        inner_groove_ratio=0.52, outer_groove_ratio=0.53, radial_clearance=20e-6)
    with pytest.raises(ValueError, match="angular-contact rows"):
        DoubleRowSupport(deep, SPACING, 0.0)
    with pytest.raises(ValueError, match="row_spacing"):
        DoubleRowSupport(ROW, -1e-3, 0.0)
    with pytest.raises(ValueError, match="axial_clearance"):
        DoubleRowSupport(ROW, SPACING, 0.0, axial_clearance=np.nan)


@jax.jit
def _double_row_and_pair(force, moment, clearance):
    """(displacement, converged) of a shaft on the double-row bearing and on its rows as a pair."""
    loads = ShaftLoads(jnp.zeros(1), force[None], moment[None])
    rows = (BallSupport(ROW, -0.5 * SPACING, -0.5 * clearance), BallSupport(ROW, 0.5 * SPACING, -0.5 * clearance,
                                                                            orientation=-1))
    one = solve_shaft(Shaft((DoubleRowSupport(ROW, SPACING, 0.0, axial_clearance=clearance),), loads))
    two = solve_shaft(Shaft(rows, loads))
    return one.displacement, one.converged, two.displacement, two.converged


@pytest.mark.slow
@hypothesis.settings(max_examples=15, deadline=None)
@hypothesis.given(st.floats(-8e3, 8e3), st.floats(-8e3, 8e3), st.floats(-6e3, 6e3), st.floats(-150.0, 150.0),
                  st.floats(-10e-6, 10e-6))
def test_random_loads_and_clearances_give_the_pairs_solution(radial, tangential, axial, moment, clearance):
    """Over random radial, axial and tilting loads and axial clearances (−10 … 10 µm): the shaft on
    the double-row bearing converges where the pair does, finite, to the pair's displacement."""
    hypothesis.assume(abs(axial) + abs(radial) + abs(tangential) > 100.0)
    one, one_converged, two, two_converged = _double_row_and_pair(
        jnp.array([radial, tangential, axial]), jnp.array([moment, 0.0]), jnp.asarray(clearance))
    assert np.all(np.isfinite(one))
    assert bool(one_converged) == bool(two_converged)
    if bool(two_converged):
        np.testing.assert_allclose(one, two, rtol=1e-7, atol=1e-13)
