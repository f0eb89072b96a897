"""The thermal–mechanical fixed point of a preloaded spindle pair (`diffbearing.thermal.pair_thermal`):
energy balance, the fixed point's identity, the preload the warm pair carries against the set's
equilibrium at the solved clearance solved apart, derivatives against central differences, thermal
runaway reported, not a NaN."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.params import Operating
from diffbearing.systems.bearing_set import bearing_set, preload_offset
from diffbearing.systems.operating_clearance import Mounting
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, solve_shaft
from diffbearing.thermal import bearing_thermal as bt
from diffbearing.thermal.pair_thermal import MountedBallPair
from diffbearing.thermal.thermal_network import node_temperatures

from .helpers import SPINDLE_7014C, assert_jvp_matches_central_difference

AMBIENT = 293.15
BEARING = SPINDLE_7014C  # back to back, 500 N preload as matched
MOUNTING = Mounting(shaft_interference=5e-6, housing_interference=-2e-6, reference_temperature=AMBIENT)
OIL = bt.WaltherLine(22e-6, 4.3e-6)  # ISO VG 22
FACTORS = bt.PalmgrenFactors(1.0, 0.001, 0.33)  # HR 1's 72-B series f1; f0 of oil mist
PATHS = bt.ThermalPaths(inner_ring_shaft=40.0, outer_ring_housing=60.0, inner_ring_lubricant=8.0,
                        outer_ring_lubricant=8.0, shaft_ambient=2.0, housing_ambient=30.0, oil_flow=0.0,
                        ambient_temperature=AMBIENT, inlet_temperature=AMBIENT)
SPACING = 40e-3
OFFSET = float(preload_offset(BEARING, 500.0))


def _pair(offset=OFFSET, rpm=4000.0, mounting=MOUNTING):
    operating = Operating(rpm * jnp.pi / 30, 0.0, jnp.array([2e3, 0.0, 1e3]), jnp.zeros(2))
    return MountedBallPair(BEARING, mounting, operating, OIL, FACTORS, SPACING, offset)


solve = jax.jit(bt.solve_thermal)


@pytest.mark.slow
def test_the_warm_pair_balances_energy_and_carries_the_preload_of_its_clearance():
    """At 4000 r/min: converged; the heat leaving equals the friction power (1e-10); the temperatures
    are the network's for their heat (1e-8 K); each bearing's axial load is the set's equilibrium at
    the solved clearance and the offset its stacks' axial growth leaves, solved apart (1e-6
    relative); the inner rings run warmer than the outer, which closes the clearance and raises the
    preload above the cold pair's."""
    pair = _pair()
    state = solve(pair, PATHS)
    assert bool(state.converged)
    assert float(jnp.sum(state.boundary_heat)) == pytest.approx(float(state.lubricant_power + state.ring_power),
                                                                rel=1e-10)
    sources = jax.jit(lambda p, t: p.heat(t).sources)(pair, state.temperatures)
    np.testing.assert_allclose(node_temperatures(bt.bearing_network(PATHS), sources)[:bt.SEAT_NODES],
                               state.temperatures[:bt.SEAT_NODES], atol=1e-8)
    running = bt.bearing_at(BEARING, MOUNTING, pair.operating, state.temperatures)[0]
    # the inner stack (rings, spacer) at the inner rings' temperature grows by α s (T_i − T_o) against
    # the outer: a back-to-back pair's inner rings, pushed together by e, move apart by half of it each
    grown = OFFSET - 0.5 * SPACING * MOUNTING.ring_expansion * (state.temperatures[0] - state.temperatures[1])
    apart = solve_shaft(Shaft(bearing_set(running, "back_to_back", spacing=SPACING, offset=grown),
                              ShaftLoads(jnp.zeros(1), pair.operating.force[None], pair.operating.moment[None]),
                              pair.operating.inner_speed))
    for warm, alone in zip(state.mechanics.bearing_forces, apart.bearing_forces):
        assert float(warm[2]) == pytest.approx(float(alone[2]), rel=1e-6)
    cold = solve(_pair(rpm=0.0), PATHS)
    assert float(state.temperatures[0]) > float(state.temperatures[1]) > AMBIENT
    assert float(state.clearance) < float(cold.clearance)
    assert abs(float(state.mechanics.bearing_forces[1][2])) > 2.0 * abs(float(cold.mechanics.bearing_forces[1][2]))


@pytest.mark.slow
def test_derivatives_of_the_warm_pair_are_central_differences():
    """∂(inner ring temperature, each bearing's axial load)/∂(preload offset, speed) through the
    fixed point and the set's equilibrium against central differences (1e-5)."""
    def outputs(x):
        state = bt.solve_thermal(_pair(offset=x[0], rpm=x[1]), PATHS)
        return jnp.stack([state.temperatures[0], *(f[2] for f in state.mechanics.bearing_forces)])

    point = jnp.array([OFFSET, 4000.0])
    for index, step in enumerate((1e-8, 1.0)):
        assert_jvp_matches_central_difference(outputs, point, jnp.zeros(2).at[index].set(1.0), step, rtol=1e-5,
                                              atol=1e-6)


@pytest.mark.slow
def test_a_pair_that_warms_into_runaway_is_reported_not_a_nan():
    """At 12 000 r/min the warming inner rings close the clearance faster than these paths carry the
    heat away: no steady state inside −60 … 250 °C — not converged, every value finite."""
    state = solve(_pair(rpm=12000.0), PATHS)
    assert not bool(state.converged)
    assert all(bool(jnp.all(jnp.isfinite(leaf))) for leaf in jax.tree.leaves(state))
