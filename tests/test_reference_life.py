"""ISO/TS 16281 from a bearing's contacts (`ratings.reference_life`): one formula by contact kind,
equal to the ball and roller lives it replaces on random loads, on the contacts a solve gives, and
through a toy bearing type; finite where nothing is loaded; its derivative against central
differences."""

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import BallSupport, RollerSupport, solve_equilibrium
from diffbearing.bearings.interface import ContactLoads
from diffbearing.params import Operating
from diffbearing.ratings import life, roller_life
from diffbearing.ratings.reference_life import contact_reference_life

from .helpers import assert_jvp_matches_central_difference
from .test_life import bearing_6411E

RANDOM = hypothesis.settings(max_examples=30, deadline=None)


def _contacts(inner, outer, kind):
    """ContactLoads of lamina loads inner, outer (Z, L) [N] (point contacts: L = 1)."""
    laminae = jnp.stack([inner, outer], axis=1)
    load = jnp.sum(laminae, axis=-1)
    count = load.shape[0]
    return ContactLoads(jnp.linspace(0.0, 2 * np.pi, count, endpoint=False), load, laminae, jnp.zeros_like(load),
                        None if kind == "line" else jnp.zeros_like(load), jnp.zeros_like(load), ("inner", "outer"),
                        kind)


_point_life = jax.jit(lambda inner, outer, ratings: contact_reference_life(_contacts(inner, outer, "point"), ratings))
_line_life = jax.jit(lambda inner, outer, ratings: contact_reference_life(_contacts(inner, outer, "line"), ratings))


@RANDOM
@hypothesis.given(st.lists(st.floats(0.0, 2e4), min_size=7, max_size=7), st.lists(st.floats(0.0, 2e4), min_size=7, max_size=7))
def test_point_contacts_give_the_ball_bearings_reference_life(inner, outer):
    """Random ball loads on a 6411E (unloaded balls included): the generic life equals
    `life.reference_rating_life` to rounding."""
    hypothesis.assume(max(inner) > 1.0)
    bearing = bearing_6411E()
    rating = life.basic_dynamic_load_rating(bearing)
    inner, outer = jnp.asarray(inner), jnp.asarray(outer)
    expected = life.reference_rating_life(bearing, rating, inner, outer)
    got = _point_life(inner[:, None], outer[:, None], jnp.stack(life.raceway_ratings(bearing, rating)))
    np.testing.assert_allclose(got, expected, rtol=1e-12)


@RANDOM
@hypothesis.given(st.integers(0, 2**31 - 1), st.floats(0.0, 0.7))
def test_line_contacts_give_the_roller_bearings_lamina_life(seed, unloaded):
    """Random lamina loads (Z = 14 rollers × 20 laminae, a share of them zero): the generic life
    equals `roller_life.roller_reference_rating_life` to rounding."""
    loads = np.random.default_rng(seed).uniform(0.0, 300.0, (2, 14, 20))
    loads[:, np.random.default_rng(seed + 1).uniform(size=(14, 20)) < unloaded] = 0.0
    hypothesis.assume(loads[0].max() > 1.0)
    rating = roller_life.roller_dynamic_load_rating(14, 10e-3, 9.6e-3, 0.0, 65e-3)
    expected = roller_life.roller_reference_rating_life(rating, 14, 10e-3, 0.0, 65e-3, loads[0], loads[1])
    got = _line_life(loads[0], loads[1], jnp.stack(roller_life.lamina_ratings(rating, 14, 10e-3, 0.0, 65e-3, 20)))
    np.testing.assert_allclose(got, expected, rtol=1e-12)


def test_nothing_loaded_lives_forever_with_a_finite_gradient():
    zero = jnp.zeros((7, 1))
    ratings = jnp.array([1e4, 1e4])
    assert float(_point_life(zero, zero, ratings)) == np.inf
    gradient = jax.grad(lambda q: contact_reference_life(_contacts(q, q, "point"), ratings))(zero)
    assert np.all(np.isfinite(gradient)) and np.all(gradient == 0.0)


def test_the_generic_lifes_derivative_matches_central_differences():
    rng = np.random.default_rng(3)
    inner, outer = jnp.asarray(rng.uniform(0.0, 5e3, (9, 1))), jnp.asarray(rng.uniform(0.0, 5e3, (9, 1)))
    ratings = jnp.array([4e4, 5e4])
    assert_jvp_matches_central_difference(lambda loads: _point_life(loads[0], loads[1], ratings),
                                          jnp.stack([inner, outer]), jnp.asarray(rng.normal(size=(2, 9, 1))) * 100.0,
                                          step=1e-3, rtol=1e-7)


def test_a_ball_supports_contacts_are_its_balls():
    """BallSupport.contacts at a solved 6411E state: the balls' loads, angles, pressures and
    approaches in columns (inner, outer), and its life the ball bearing's."""
    from diffbearing import ball_results

    bearing = bearing_6411E()
    operating = Operating(0.0, 0.0, jnp.array([8e3, 0.0, 2e3]), jnp.zeros(2))
    solution = solve_equilibrium(bearing, operating)
    support = BallSupport(bearing, 0.0)
    contacts = support.contacts(solution.displacement, 0.0, None)
    balls = ball_results(solution.displacement, bearing, operating)
    assert contacts.kind == "point" and contacts.on("inner") == (0,) and contacts.on("outer") == (1,)
    for column, side in enumerate(("inner", "outer")):
        np.testing.assert_array_equal(contacts.load[:, column], getattr(balls, f"{side}_load"))
        np.testing.assert_array_equal(contacts.angle[:, column], getattr(balls, f"{side}_contact_angle"))
        np.testing.assert_array_equal(contacts.approach[:, column], getattr(balls, f"{side}_approach"))
    rating = support.dynamic_load_rating()
    np.testing.assert_allclose(contact_reference_life(contacts, support.contact_ratings(rating, contacts)),
                               life.reference_rating_life(bearing, rating, balls.inner_load, balls.outer_load),
                               rtol=1e-12)


def test_a_roller_supports_contacts_are_its_laminae():
    """RollerSupport.contacts at a solved tapered roller bearing (seed 004's rollers): its lamina
    loads [N] and the lamina life of `roller_reference_rating_life` at ISO 281's rating."""
    from diffbearing import RollerOperating, roller_results, solve_roller_equilibrium

    from .test_roller_equilibrium import tapered

    bearing, raceways = tapered()
    operating = RollerOperating(jnp.array([6e3, 0.0, 3e3]), jnp.zeros(2))
    solution = solve_roller_equilibrium(bearing, raceways, operating)
    support = RollerSupport(bearing, raceways, 0.0)
    contacts = support.contacts(solution.displacement, 0.0, None)
    rollers = roller_results(solution.displacement, bearing, raceways, operating)
    assert contacts.kind == "line" and contacts.angle is None
    width = bearing.length / rollers.inner_lamina_load.shape[-1]
    np.testing.assert_array_equal(contacts.lamina_load[:, 0], rollers.inner_lamina_load * width)
    np.testing.assert_array_equal(jnp.max(contacts.approach), rollers.largest_approach)
    rating = support.dynamic_load_rating()
    diameter = 0.5 * (bearing.small_diameter + bearing.large_diameter)
    expected = roller_life.roller_reference_rating_life(rating, bearing.roller_count, diameter, raceways.cup_angle,
                                                        raceways.pitch_diameter, rollers.inner_lamina_load * width,
                                                        rollers.outer_lamina_load * width)
    np.testing.assert_allclose(contact_reference_life(contacts, support.contact_ratings(rating, contacts)), expected,
                               rtol=1e-12)


def test_an_unknown_contact_kind_is_refused():
    with pytest.raises(ValueError, match="contact kind"):
        ContactLoads(jnp.zeros(1), jnp.zeros((1, 1)), jnp.zeros((1, 1, 1)), jnp.zeros((1, 1)), None,
                     jnp.zeros((1, 1)), ("inner",), "needle")
