"""The thermal–mechanical fixed point of a mounted ball bearing (`diffbearing.thermal.bearing_thermal`):
the energy balance to round-off, the fixed point against an independent loop of guesses (Picard),
the clearance against the mounting model at the solved temperatures, a bearing at rest at the
ambient temperature, derivatives through the fixed point against central differences, and thermal
runaway reported, not a NaN."""

import os

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.friction.skf_friction import SkfBearing
from diffbearing.params import BEARING_STEEL, Operating, ball_bearing, radial_clearance
from diffbearing.systems.operating_clearance import SEAT_MATERIALS, Mounting, operating_clearance_change
from diffbearing.thermal import bearing_thermal as bt
from diffbearing.thermal.skf_heat import SkfHeat
from diffbearing.thermal.thermal_network import node_temperatures

from .helpers import assert_jvp_matches_central_difference

AMBIENT = 293.15
# the mounted_6411 example's bearing and fits (a 6411E, 15 µm on the shaft, a loose cast-iron housing)
BEARING = ball_bearing(kind="deep_groove_ball", ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7,
                       inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=28e-6, bore=55e-3,
                       outer_diameter=140e-3, ball_material=BEARING_STEEL, ring_material=BEARING_STEEL)
MOUNTING = Mounting(shaft_interference=15e-6, housing_interference=-5e-6, reference_temperature=AMBIENT,
                    housing=SEAT_MATERIALS["cast_iron"][0], housing_expansion=SEAT_MATERIALS["cast_iron"][1])
OIL = bt.WaltherLine(68e-6, 8.7e-6)  # ISO VG 68
FACTORS = bt.PalmgrenFactors(2.0, 0.0009, 0.5)  # HR 1's 62 series, oil
PATHS = bt.ThermalPaths(inner_ring_shaft=5.0, outer_ring_housing=8.0, inner_ring_lubricant=1.0, outer_ring_lubricant=1.0,
                        shaft_ambient=0.8, housing_ambient=2.0, oil_flow=0.5, ambient_temperature=AMBIENT,
                        inlet_temperature=AMBIENT + 20.0)


def _operating(rpm=3000.0):
    return Operating(inner_speed=rpm * jnp.pi / 30, outer_speed=0.0, force=[8e3, 0.0, 0.0], moment=[0.0, 0.0],
                     misalignment=[0.0, 0.0])


def _mounted(mounting=MOUNTING, operating=None):
    return bt.MountedBallBearing(BEARING, mounting, _operating() if operating is None else operating, OIL, FACTORS)


solve = jax.jit(bt.solve_thermal)
heat = jax.jit(lambda heated, temperatures: heated.heat(temperatures).sources)


@pytest.mark.slow
def test_the_fixed_point_balances_energy_and_is_the_loop_of_guesses():
    """At 3000 r/min under 8 kN: converged; the heat leaving at the ambient and the oil inlet equals the
    friction power (1e-10); the temperatures are the network's for the heat they give (1e-9 K) and the
    limit of Picard's loop T ← T_network(Q(T)) from the ambient (1e-7 K); the clearance is the mounting
    model's at the solved ring, shaft and housing temperatures (1e-15 m)."""
    operating = _operating()
    heated = _mounted(operating=operating)
    state = solve(heated, PATHS)
    assert bool(state.converged)
    power = float(state.lubricant_power + state.ring_power)
    assert float(jnp.sum(state.boundary_heat)) == pytest.approx(power, rel=1e-10)
    network = bt.bearing_network(PATHS)
    sources = heat(heated, state.temperatures)
    np.testing.assert_allclose(node_temperatures(network, sources)[:bt.SEAT_NODES], state.temperatures[:bt.SEAT_NODES], atol=1e-9)
    temperatures = jnp.full(7, AMBIENT).at[6].set(AMBIENT + 20.0)
    for _ in range(60):
        sources = heat(heated, temperatures)
        temperatures = node_temperatures(network, sources)
    np.testing.assert_allclose(temperatures, state.temperatures, atol=1e-7)
    mounted = bt.mounted_at(MOUNTING, state.temperatures)
    change = operating_clearance_change(mounted, 0.055, 0.0975 - 0.0269875, 0.0975 + 0.0269875, 0.14, 0.0269875,
                                        BEARING_STEEL, operating.inner_speed, 0.0).change
    assert float(state.clearance) == pytest.approx(float(radial_clearance(BEARING) + change), abs=1e-15)
    # the inner ring runs hotter than the outer: the heat of its contacts leaves through the thinner shaft path
    assert float(state.temperatures[0]) > float(state.temperatures[1]) > AMBIENT


@pytest.mark.slow
def test_a_bearing_at_rest_stays_at_the_ambient_temperature():
    """No speed, no heat: every free node at the held temperatures' mix (the oil inlet 20 K above the
    ambient warms the lubricant), the clearance the cold mounted one's."""
    state = solve(_mounted(operating=_operating(0.0)), PATHS)
    assert bool(state.converged) and float(state.lubricant_power + state.ring_power) == 0.0
    zero = node_temperatures(bt.bearing_network(PATHS), jnp.zeros(7))
    np.testing.assert_allclose(state.temperatures, zero, atol=1e-9)


@pytest.mark.slow
def test_derivatives_through_the_fixed_point_are_central_differences():
    """∂(inner ring temperature, clearance)/∂(housing–ambient conductance, shaft interference, speed)
    through the implicit root against central differences (1e-5, and 1e-4 K absolute: the inner ring's
    temperature does not depend on the fit here — Palmgren's P₁ of a radially loaded deep groove
    bearing is F_r, whatever the clearance — and the difference quotient of that zero is rounding)."""
    def outputs(x):
        paths = bt.ThermalPaths(5.0, 8.0, 1.0, 1.0, 0.8, x[0], 0.5, AMBIENT, AMBIENT + 20.0)
        mounting = Mounting(shaft_interference=x[1], housing_interference=-5e-6, reference_temperature=AMBIENT,
                            housing=SEAT_MATERIALS["cast_iron"][0], housing_expansion=SEAT_MATERIALS["cast_iron"][1])
        state = bt.solve_thermal(_mounted(mounting, _operating(x[2])), paths)
        return jnp.stack([state.temperatures[0], state.clearance * 1e6])

    point = jnp.array([2.0, 15e-6, 3000.0])
    for index, step in enumerate((1e-4, 1e-8, 1e-1)):
        assert_jvp_matches_central_difference(outputs, point, jnp.zeros(3).at[index].set(1.0), step, rtol=1e-5,
                                              atol=1e-4)


@pytest.mark.slow
def test_derivatives_through_the_fixed_point_with_skf_heat_are_central_differences():
    """SKF's four components as the heat (64 series, an oil bath with a drag loss factor, so heat
    goes into the lubricant as well as the rings): ∂(inner ring and lubricant temperatures,
    clearance)/∂(shaft interference, speed, axial load) through the implicit root against central
    differences (1e-5, and 1e-6 K absolute: SKF's moment reads the applied loads, not the clearance,
    so the temperatures do not depend on the fit). The axial load moves SKF's M_rr and M_sl (its
    G_rr, G_sl read F_a)."""
    skf = SkfHeat(SkfBearing("64", "oil_bath", jnp.asarray(0.055), jnp.asarray(0.14), jnp.asarray(0.0005), None))

    def outputs(x):
        mounting = Mounting(shaft_interference=x[0] * 1e-6, housing_interference=-5e-6, reference_temperature=AMBIENT,
                            housing=SEAT_MATERIALS["cast_iron"][0], housing_expansion=SEAT_MATERIALS["cast_iron"][1])
        operating = Operating(inner_speed=x[1] * jnp.pi / 30, outer_speed=0.0, force=jnp.stack([8e3, 0.0, x[2] * 1e3]),
                              moment=jnp.zeros(2), misalignment=jnp.zeros(2))
        state = bt.solve_thermal(bt.MountedBallBearing(BEARING, mounting, operating, OIL, skf), PATHS)
        return jnp.stack([state.temperatures[0], state.temperatures[2], state.clearance * 1e6,
                          jnp.where(state.converged, 0.0, jnp.nan)])

    point = jnp.array([15.0, 3000.0, 2.0])
    for index, step in enumerate((1e-2, 1e-1, 1e-3)):
        assert_jvp_matches_central_difference(outputs, point, jnp.zeros(3).at[index].set(1.0), step, rtol=1e-5,
                                              atol=1e-6)


@pytest.mark.slow
def test_thermal_runaway_is_reported_not_a_nan():
    """Paths a thousand times weaker (a bearing barely cooled): no steady state inside the model's
    −60 … 250 °C — not converged, every value finite."""
    weak = jax.tree.map(lambda x: x * 1e-3, PATHS)
    weak = bt.ThermalPaths(*(getattr(weak, name) for name in ("inner_ring_shaft", "outer_ring_housing",
                                                               "inner_ring_lubricant", "outer_ring_lubricant",
                                                               "shaft_ambient", "housing_ambient", "oil_flow")),
                           AMBIENT, AMBIENT + 20.0)
    state = solve(_mounted(), weak)
    assert not bool(state.converged)
    assert all(bool(jnp.all(jnp.isfinite(leaf))) for leaf in jax.tree.leaves(state))


SEED = int(os.environ.get("DIFFBEARING_SEED", "20261204"))
# the draws' envelope: shaft interference [m], speed [r/min], F_r, F_a [N], then the seven paths [W/K]
# (inner ring – shaft, outer ring – housing, each ring – lubricant, shaft – ambient, housing –
# ambient, the oil's flow) and the oil inlet's temperature above the ambient [K]
RANDOM_ENVELOPE = ((-10e-6, 20e-6), (0.0, 6000.0), (1e3, 20e3), (0.0, 3e3), (1.0, 50.0), (1.0, 50.0), (0.2, 10.0),
                   (0.2, 10.0), (0.1, 5.0), (0.5, 50.0), (0.0, 5.0), (-10.0, 40.0))
LOG_DRAWN = range(4, 10)  # the conductances of the parts, log-uniform


def _random_case(row):
    interference, rpm, radial, axial, *conductances, inlet = (row[i] for i in range(12))
    mounting = Mounting(shaft_interference=interference, housing_interference=-5e-6, reference_temperature=AMBIENT,
                        housing=SEAT_MATERIALS["cast_iron"][0], housing_expansion=SEAT_MATERIALS["cast_iron"][1])
    operating = Operating(inner_speed=rpm * jnp.pi / 30, outer_speed=0.0, force=jnp.stack([radial, 0.0, axial]),
                          moment=jnp.zeros(2), misalignment=jnp.zeros(2))
    paths = bt.ThermalPaths(*conductances, AMBIENT, AMBIENT + inlet)
    state = bt.solve_thermal(bt.MountedBallBearing(BEARING, mounting, operating, OIL, FACTORS), paths)
    power = state.lubricant_power + state.ring_power
    return state.converged, state.temperatures, state.clearance, power, jnp.sum(state.boundary_heat)


def test_random_mounted_bearings_converge_or_say_so():
    """48 seeded random mounted 6411s over fits, speeds, loads, paths and oil inlet temperatures
    (`RANDOM_ENVELOPE`; DIFFBEARING_SEED sets the seed): every output finite; each converges — its
    heat balance closed (1e-8) inside the model's −60 … 250 °C — or reports that its temperatures
    left the model (a node held at 250 °C, not converged). A single bearing's Palmgren heat falls
    as it warms (its viscosity does), so a steady state exists wherever the model holds."""
    rng = np.random.default_rng(SEED)
    rows = np.stack([np.exp(rng.uniform(np.log(low), np.log(high), 48)) if column in LOG_DRAWN else
                     rng.uniform(low, high, 48) for column, (low, high) in enumerate(RANDOM_ENVELOPE)], axis=1)
    converged, temperatures, clearance, power, leaving = (np.asarray(x) for x in jax.jit(jax.vmap(_random_case))(rows))
    assert all(np.all(np.isfinite(x)) for x in (temperatures, clearance, power, leaving)), SEED
    np.testing.assert_allclose(leaving[converged], power[converged], rtol=1e-8, atol=1e-9, err_msg=str(SEED))
    assert np.all(temperatures[converged] <= bt.TEMPERATURE_RANGE[1]), SEED
    left = np.max(temperatures, axis=1) >= bt.TEMPERATURE_RANGE[1]
    assert np.all(converged | left), (SEED, rows[~(converged | left)])
    assert np.mean(converged) > 0.5, (SEED, np.mean(converged))
