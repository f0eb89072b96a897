"""The thermal–mechanical steady state of a radial ball bearing in its mounting, solved as one fixed
point: the friction heat warms the rings, shaft, housing and lubricant through a thermal network
(`thermal_network`); their temperatures set the operating clearance (the mounting model,
`systems.operating_clearance`) and the lubricant's viscosity (its Walther line); the clearance and
the load set the ball loads (`ball_equilibrium`), and with the viscosity the friction heat.

Nodes (`NODES`): inner ring, outer ring, lubricant, shaft, housing (free); ambient and oil inlet
(held). Paths (`ThermalPaths`, conductances [W/K]): inner ring – shaft, outer ring – housing, each
ring – lubricant, shaft – ambient, housing – ambient, and the circulating oil's flow from the inlet
(ρc V̇; 0 for a bath or grease). Heat (Palmgren's moments, `friction.friction_torque`; Harris &
Kotzalas, Rolling Bearing Analysis, 5th ed., vol. 1, ch. 13, for the split): the load-dependent
loss M₁ ω, generated in the ball–raceway contacts, half into each ring (the balls pass their share
on to the rings they roll between); the viscous loss M₀ ω into the lubricant.

Palmgren's P₁ is the bearing's external load (`friction_torque.friction_load`), so a clearance the
warmth closes into a preload raises the heat only where it shows in that load (the axial load of an
angular contact pair's bearings), not the internal preload of a single radial bearing: a
contact-level loss model would see it.

The unknowns are the five free temperatures T; the residual is R(T) = T − T_network(Q(T)), Q the
heat of the bearing at the state T gives. Newton (optimistix) on R with the implicit derivative of
the root: ∂T/∂p = −(∂R/∂T)⁻¹ ∂R/∂p, through the inner equilibrium solve's own implicit derivative.
Where no steady state exists inside the model (thermal runaway: a preloaded bearing whose warming
closes its clearance faster than the paths carry the heat away), or the temperatures leave the
mounting model's −60…250 °C, `converged` is False and the values stay finite.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import optimistix as optx

from ..bearings.ball import ball_equilibrium
from ..film.viscosity_temperature import walther_viscosity
from ..friction import friction_torque
from ..params import BallBearing, Operating, radial_clearance, with_radial_clearance
from ..ratings import static_safety
from ..systems.operating_clearance import Mounting, operating_clearance_change
from .thermal_network import ThermalNetwork, boundary_heat_flows, node_temperatures

NODES = ("inner_ring", "outer_ring", "lubricant", "shaft", "housing", "ambient", "oil_inlet")
FREE = 5  # the first five nodes are free
EDGES = ((0, 3), (1, 4), (0, 2), (1, 2), (3, 5), (4, 5), (2, 6))
TEMPERATURE_RANGE = (213.15, 523.15)  # K: the mounting model's (−60 … 250 °C)
SOLVER = optx.Newton(rtol=1e-10, atol=1e-8)


class ThermalPaths(eqx.Module):
    """The conductances [W/K] of a radial bearing's heat paths (module docstring) and the held
    temperatures [K] of the ambient and the oil inlet."""

    inner_ring_shaft: jax.Array
    outer_ring_housing: jax.Array
    inner_ring_lubricant: jax.Array
    outer_ring_lubricant: jax.Array
    shaft_ambient: jax.Array
    housing_ambient: jax.Array
    oil_flow: jax.Array
    ambient_temperature: jax.Array
    inlet_temperature: jax.Array


def bearing_network(paths: ThermalPaths) -> ThermalNetwork:
    """The paths as a `ThermalNetwork` over `NODES`."""
    conductances = jnp.stack([jnp.asarray(x, float) for x in (
        paths.inner_ring_shaft, paths.outer_ring_housing, paths.inner_ring_lubricant, paths.outer_ring_lubricant,
        paths.shaft_ambient, paths.housing_ambient, paths.oil_flow)])
    held = jnp.stack([jnp.asarray(paths.ambient_temperature, float), jnp.asarray(paths.inlet_temperature, float)])
    return ThermalNetwork(NODES, EDGES, (5, 6), conductances, held)


class WaltherLine(eqx.Module):
    """The lubricant's Walther line: kinematic viscosities at 40 °C and 100 °C [m²/s]."""

    viscosity_40: jax.Array
    viscosity_100: jax.Array


class PalmgrenFactors(eqx.Module):
    """Palmgren's f₀ and f₁ = a (P₀/C₀)^b of the bearing's kind (`friction_torque.PALMGREN_CONSTANTS`)."""

    f0: jax.Array
    coefficient: jax.Array
    exponent: float = eqx.field(static=True)


class ThermalState(eqx.Module):
    """The solved state (SI): every node's temperature (`NODES`), the operating diametral clearance,
    the equilibrium at it, the viscous and load-dependent friction powers, the heat leaving at the
    ambient and the oil inlet, the residual's largest |R| [K], whether it converged inside the model."""

    temperatures: jax.Array
    clearance: jax.Array
    equilibrium: ball_equilibrium.Equilibrium
    viscous_power: jax.Array
    load_power: jax.Array
    boundary_heat: jax.Array
    residual: jax.Array
    converged: jax.Array


def _mounted(mounting: Mounting, temperatures) -> Mounting:
    return eqx.tree_at(lambda m: (m.inner_ring_temperature, m.outer_ring_temperature, m.shaft_temperature,
                                  m.housing_temperature), mounting,
                       (temperatures[0], temperatures[1], temperatures[3], temperatures[4]))


def bearing_at(bearing: BallBearing, mounting: Mounting, operating: Operating, temperatures):
    """(the bearing at the operating clearance its mounting leaves at the node `temperatures`, that
    clearance [m])."""
    pitch, ball = bearing.pitch_diameter, bearing.ball_diameter
    change = operating_clearance_change(_mounted(mounting, temperatures), bearing.bore, pitch - ball, pitch + ball,
                                        bearing.outer_diameter, ball, bearing.ring_material, operating.inner_speed,
                                        operating.outer_speed)
    clearance = radial_clearance(bearing) + change.change
    return with_radial_clearance(bearing, clearance), clearance


def bearing_heat(temperatures, bearing: BallBearing, mounting: Mounting, operating: Operating, oil: WaltherLine,
                 factors: PalmgrenFactors, model: ball_equilibrium.BallModel):
    """(heat sources [W] at `NODES`, the clearance, the equilibrium, viscous and load powers [W]) of the
    bearing at the node `temperatures` [K]: its equilibrium at that clearance, Palmgren's moments at
    the lubricant node's viscosity (module docstring)."""
    running, clearance = bearing_at(bearing, mounting, operating, temperatures)
    solution = ball_equilibrium.solve_equilibrium(running, operating, model)
    force = solution.force[:3]
    radial, axial = jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])
    f1 = friction_torque.speed_factor(factors.coefficient, factors.exponent,
                                      static_safety.ball_bearing_equivalent_static_load(running, force),
                                      static_safety.ball_bearing_static_load_rating(running))
    speed = jnp.abs(operating.inner_speed - operating.outer_speed)
    load_power = friction_torque.load_torque(f1, friction_torque.friction_load(running.kind, radial, axial),
                                             running.pitch_diameter) * speed
    viscosity = walther_viscosity(oil.viscosity_40, oil.viscosity_100, temperatures[2])
    viscous_power = friction_torque.viscous_torque(factors.f0, viscosity, speed, running.pitch_diameter) * speed
    zero = jnp.zeros(())
    sources = jnp.stack([0.5 * load_power, 0.5 * load_power, viscous_power, zero, zero, zero, zero])
    return sources, clearance, solution, viscous_power, load_power


def _assembled(free, paths: ThermalPaths):
    return jnp.concatenate([free, jnp.stack([jnp.asarray(paths.ambient_temperature, float),
                                             jnp.asarray(paths.inlet_temperature, float)])])


def _residual(free, args):
    bearing, mounting, operating, oil, factors, paths, model = args
    temperatures = _assembled(free, paths)
    sources = bearing_heat(temperatures, bearing, mounting, operating, oil, factors, model)[0]
    return free - node_temperatures(bearing_network(paths), sources)[:FREE]


def solve_bearing_thermal(bearing: BallBearing, mounting: Mounting, operating: Operating, oil: WaltherLine,
                          factors: PalmgrenFactors, paths: ThermalPaths,
                          model: ball_equilibrium.BallModel = ball_equilibrium.BallModel()) -> ThermalState:
    """The bearing's thermal–mechanical steady state (module docstring). `mounting` holds the fits
    (its temperatures are the unknowns, replaced); the start is the network's temperatures for the
    heat at the ambient temperature. Differentiable in every input (implicit function theorem)."""
    args = (bearing, mounting, operating, oil, factors, paths, model)
    cold = jnp.full(FREE, jnp.asarray(paths.ambient_temperature, float))
    start_sources = bearing_heat(jax.lax.stop_gradient(_assembled(cold, paths)), *args[:5], model)[0]
    start = jax.lax.stop_gradient(node_temperatures(bearing_network(paths), start_sources)[:FREE])
    start = jnp.clip(start, *TEMPERATURE_RANGE)
    solution = optx.root_find(_residual, SOLVER, start, args=args, max_steps=40, throw=False,
                              adjoint=optx.ImplicitAdjoint())
    inside = jnp.all((solution.value >= TEMPERATURE_RANGE[0]) & (solution.value <= TEMPERATURE_RANGE[1]))
    free = jnp.where(inside, solution.value, jnp.clip(solution.value, *TEMPERATURE_RANGE))
    temperatures = _assembled(free, paths)
    sources, clearance, equilibrium, viscous, load = bearing_heat(temperatures, *args[:5], model)
    network = bearing_network(paths)
    residual = jnp.max(jnp.abs(free - node_temperatures(network, sources)[:FREE]))
    converged = (solution.result == optx.RESULTS.successful) & inside & equilibrium.converged & (residual < 1e-6)
    return ThermalState(temperatures, clearance, equilibrium, viscous, load,
                        boundary_heat_flows(network, temperatures, sources), residual, converged)
