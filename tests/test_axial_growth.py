"""The axial thermal growth between the bearings that locate a shaft (`diffbearing.thermal.axial_growth`):
the trapezoid rule over each span in closed form, in any order of the bearings, nothing where both
sides grow alike, a matched pair's growth as the general one's; a back-to-back pair whose inner side
grows loses preload and a face-to-face pair gains it, each bearing as if its offset had moved by half
the growth; a floating bearing is left as it is; derivatives against central differences."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.bearings.ball.ball_support import BallSupport
from diffbearing.systems.bearing_set import bearing_set, preload_offset
from diffbearing.systems.operating_clearance import RING_EXPANSION, Mounting
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, solve_shaft
from diffbearing.thermal.axial_growth import axial_growth, grown_supports, mounted_axial_growth, pair_growth

from .helpers import SPINDLE_7014C, assert_jvp_matches_central_difference
from .test_shaft_thermal import _cylindrical

REFERENCE = 293.15
STEEL, CAST_IRON = 11.5e-6, 10.4e-6


def test_the_growth_is_the_trapezoid_rule_over_each_span():
    """Three bearings at z = 0, 0.1, 0.4 m, the shaft at 40, 50, 30 °C against a housing at 25 °C
    throughout (cast iron): u = Σ α_s (T̄_s − T_ref) Δz − α_h (T_h − T_ref) z, about the mean
    (1e-18 m); the bearings listed in another order get the same growth each (1e-18 m)."""
    positions, shaft = jnp.array([0.0, 0.1, 0.4]), jnp.array([40.0, 50.0, 30.0]) + 273.15
    housing = jnp.full(3, 25.0 + 273.15)
    got = axial_growth(positions, shaft, housing, STEEL, CAST_IRON, REFERENCE)
    inner = np.array([0.0, STEEL * 0.1 * 25.0, STEEL * (0.1 * 25.0 + 0.3 * 20.0)])
    outer = CAST_IRON * 5.0 * np.asarray(positions)
    want = inner - outer - np.mean(inner - outer)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-18)
    order = jnp.array([2, 0, 1])
    np.testing.assert_allclose(axial_growth(positions[order], shaft[order], housing[order], STEEL, CAST_IRON,
                                            REFERENCE), want[np.asarray(order)], rtol=0, atol=1e-18)


def test_sides_that_grow_alike_leave_no_growth_and_a_pair_is_the_general_case():
    """Both sides at one temperature of one material: no growth (0 exactly); a matched pair's
    `pair_growth` of the strain α (T_i − T_o) is `axial_growth` of its two stacks at the rings'
    temperatures (1e-20 m); `mounted_axial_growth` reads each mounting's shaft and housing temperatures."""
    positions = jnp.array([-0.03, 0.05])
    assert np.all(np.asarray(axial_growth(positions, jnp.full(2, 340.0), jnp.full(2, 340.0), STEEL, STEEL,
                                          REFERENCE)) == 0.0)
    inner, outer = 333.15, 318.15
    general = axial_growth(jnp.array([-0.02, 0.02]), jnp.full(2, inner), jnp.full(2, outer), STEEL, STEEL, REFERENCE)
    np.testing.assert_allclose(pair_growth(0.04, STEEL * (inner - outer)), general, rtol=0, atol=1e-20)
    mountings = tuple(Mounting(shaft_temperature=t, housing_temperature=300.0, reference_temperature=REFERENCE)
                      for t in (330.0, 320.0))
    np.testing.assert_allclose(mounted_axial_growth(positions, mountings),
                               axial_growth(positions, jnp.array([330.0, 320.0]), jnp.full(2, 300.0), RING_EXPANSION,
                                            RING_EXPANSION, REFERENCE), rtol=0, atol=1e-20)


OFFSET = float(preload_offset(SPINDLE_7014C, 500.0))
UNLOADED = ShaftLoads(jnp.zeros(1), jnp.zeros((1, 3)), jnp.zeros((1, 2)))


def _preload(supports):
    return abs(float(solve_shaft(Shaft(supports, UNLOADED, 0.0)).bearing_forces[0][2]))


def test_a_back_to_back_pair_loses_preload_and_a_face_to_face_pair_gains_it():
    """The 7014 C pair matched for 500 N, its inner stack 2 µm longer than its outer: back to back
    (the preload pushes the inner rings together) the pair carries less, face to face (it pushes
    them apart) more; either as the pair whose offset is e ∓ 1 µm (1e-9 relative)."""
    growth = pair_growth(0.04, 2e-6 / 0.04)
    for arrangement, sign in (("back_to_back", -1.0), ("face_to_face", 1.0)):
        cold = bearing_set(SPINDLE_7014C, arrangement, spacing=0.04, offset=OFFSET)
        grown = _preload(grown_supports(cold, growth))
        assert (grown - _preload(cold)) * sign > 50.0
        moved = bearing_set(SPINDLE_7014C, arrangement, spacing=0.04, offset=OFFSET + sign * 1e-6)
        assert grown == pytest.approx(_preload(moved), rel=1e-9)


def test_a_floating_bearing_keeps_its_rings():
    """A cylindrical roller bearing carries no axial load: its support is left as it is (the same
    object); a ball bearing's offset moves by o u."""
    roller, ball = _cylindrical(), BallSupport(SPINDLE_7014C, position=0.1, offset=1e-6, orientation=-1)
    moved = grown_supports((roller, ball), jnp.array([3e-6, 2e-6]))
    assert moved[0] is roller
    assert float(moved[1].offset) == pytest.approx(1e-6 - 2e-6, abs=1e-21)


def test_derivatives_are_central_differences():
    """∂u/∂(shaft temperatures, the span) against central differences (1e-8)."""
    def growth(x):
        return axial_growth(jnp.stack([0.0, x[2]]), x[:2], jnp.full(2, 300.0), STEEL, CAST_IRON, REFERENCE) * 1e6

    point = jnp.array([330.0, 320.0, 0.2])
    for index, step in ((0, 1e-2), (1, 1e-2), (2, 1e-4)):
        assert_jvp_matches_central_difference(growth, point, jnp.zeros(3).at[index].set(1.0), step, rtol=1e-8)
    assert float(jax.grad(lambda x: growth(x)[1])(point)[0]) > 0.0
