"""The thermal–mechanical steady state of a ball bearing (or a preloaded pair, `pair_thermal`) in its
mounting, solved as one fixed point: the friction heat warms the rings, shaft, housing and lubricant through a thermal network
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
heat of the bearing at the state T gives (`AbstractHeatedBearing.heat`: one bearing,
`MountedBallBearing`; a pair, `pair_thermal.MountedBallPair`). Newton (optimistix) on R with the implicit derivative of
the root: ∂T/∂p = −(∂R/∂T)⁻¹ ∂R/∂p, through the inner equilibrium solve's own implicit derivative.
Where no steady state exists inside the model (thermal runaway: a preloaded bearing whose warming
closes its clearance faster than the paths carry the heat away), or the temperatures leave the
mounting model's −60…250 °C, `converged` is False and the values stay finite.
"""

import abc

import equinox as eqx
import jax
import jax.numpy as jnp

from ..bearings.ball import ball_equilibrium
from ..film.viscosity_temperature import walther_viscosity
from ..friction import friction_torque
from ..params import BallBearing, Operating, radial_clearance
from ..newton import implicit_root, newton
from ..ratings import static_safety
from ..systems.operating_clearance import Mounting, operating_clearance_change
from .thermal_network import ThermalNetwork, boundary_heat_flows, node_temperatures

NODES = ("inner_ring", "outer_ring", "lubricant", "shaft", "housing", "ambient", "oil_inlet")
FREE = 5  # the first five nodes are free
EDGES = ((0, 3), (1, 4), (0, 2), (1, 2), (3, 5), (4, 5), (2, 6))
TEMPERATURE_RANGE = (213.15, 523.15)  # K: the mounting model's (−60 … 250 °C)
MAX_STEPS = 60
RESIDUAL_TOLERANCE = 1e-6  # K: the largest |R| of a converged state


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


class BearingHeat(eqx.Module):
    """What a bearing's mechanics give at one set of node temperatures: the heat sources [W] at
    `NODES`, the operating diametral clearance [m], the viscous and load-dependent friction powers
    [W], the mechanical state (the type's equilibrium) and whether that state converged."""

    sources: jax.Array
    clearance: jax.Array
    viscous_power: jax.Array
    load_power: jax.Array
    mechanics: eqx.Module
    converged: jax.Array


class AbstractHeatedBearing(eqx.Module):
    """The mechanical side of the fixed point (module docstring): a bearing (or set) in its
    mounting whose heat at the node temperatures `heat` gives. `MountedBallBearing` here,
    `pair_thermal.MountedBallPair` for a preloaded pair."""

    @abc.abstractmethod
    def heat(self, temperatures) -> BearingHeat:
        """The heat and state at the node `temperatures` [K] (all of `NODES`)."""


class ThermalState(eqx.Module):
    """The solved state (SI): every node's temperature (`NODES`), the operating diametral clearance,
    the mechanical state at it (`BearingHeat.mechanics`), the viscous and load-dependent friction
    powers, the heat leaving at the ambient and the oil inlet, the residual's largest |R| [K],
    whether it converged inside the model."""

    temperatures: jax.Array
    clearance: jax.Array
    mechanics: eqx.Module
    viscous_power: jax.Array
    load_power: jax.Array
    boundary_heat: jax.Array
    residual: jax.Array
    converged: jax.Array


def mounted_at(mounting: Mounting, temperatures) -> Mounting:
    """`mounting` with its ring, shaft and housing temperatures those of the nodes [K]."""
    return eqx.tree_at(lambda m: (m.inner_ring_temperature, m.outer_ring_temperature, m.shaft_temperature,
                                  m.housing_temperature), mounting,
                       (temperatures[0], temperatures[1], temperatures[3], temperatures[4]))


def bearing_at(bearing: BallBearing, mounting: Mounting, operating: Operating, temperatures):
    """(the bearing at the operating clearance its mounting leaves at the node `temperatures`, that
    clearance [m]). The change ΔG shifts the groove centres' radial distance by −ΔG/2 (the
    interference ι − ΔG) and keeps the free contact angle: the same rings as the contact angle
    arccos(1 − G/(2 B D_w)) at a clamped axial position (`bearing_set.clamped_offset`), without that
    angle's infinite slope at G = 0, through which a warming bearing's clearance may pass."""
    pitch, ball = bearing.pitch_diameter, bearing.ball_diameter
    change = operating_clearance_change(mounted_at(mounting, temperatures), bearing.bore, pitch - ball, pitch + ball,
                                        bearing.outer_diameter, ball, bearing.ring_material, operating.inner_speed,
                                        operating.outer_speed).change
    running = eqx.tree_at(lambda b: b.interference, bearing, bearing.interference - change)
    return running, radial_clearance(running)


def palmgren_powers(running: BallBearing, force, speed, viscosity, factors: PalmgrenFactors):
    """(viscous power M₀ω, load-dependent power M₁ω) [W] of one ball bearing carrying `force`
    ([Fx, Fy, Fz] in its own frame [N]) at the relative ring speed `speed` [rad/s] in oil of
    kinematic `viscosity` [m²/s] (`friction_torque`: Palmgren's moments; f₁ from P₀/C₀)."""
    radial, axial = jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])
    f1 = friction_torque.speed_factor(factors.coefficient, factors.exponent,
                                      static_safety.ball_bearing_equivalent_static_load(running, force),
                                      static_safety.ball_bearing_static_load_rating(running))
    load = friction_torque.load_torque(f1, friction_torque.friction_load(running.kind, radial, axial),
                                       running.pitch_diameter) * speed
    viscous = friction_torque.viscous_torque(factors.f0, viscosity, speed, running.pitch_diameter) * speed
    return viscous, load


def ring_sources(viscous_power, load_power):
    """Heat sources [W] at `NODES`: the load-dependent loss half into each ring, the viscous loss
    into the lubricant (module docstring)."""
    zero = jnp.zeros(())
    return jnp.stack([0.5 * load_power, 0.5 * load_power, viscous_power, zero, zero, zero, zero])


class MountedBallBearing(AbstractHeatedBearing):
    """One radial ball bearing in its `mounting` (its fits; the temperatures are the unknowns),
    under `operating`, in `oil`, with Palmgren's `factors`, its equilibrium by `model`."""

    bearing: BallBearing
    mounting: Mounting
    operating: Operating
    oil: WaltherLine
    factors: PalmgrenFactors
    model: ball_equilibrium.BallModel = eqx.field(static=True, default=ball_equilibrium.BallModel())

    def heat(self, temperatures) -> BearingHeat:
        """The equilibrium at the clearance the node temperatures leave, Palmgren's moments at the
        lubricant node's viscosity."""
        running, clearance = bearing_at(self.bearing, self.mounting, self.operating, temperatures)
        solution = ball_equilibrium.solve_equilibrium(running, self.operating, self.model)
        speed = jnp.abs(self.operating.inner_speed - self.operating.outer_speed)
        viscosity = walther_viscosity(self.oil.viscosity_40, self.oil.viscosity_100, temperatures[2])
        viscous, load = palmgren_powers(running, solution.force[:3], speed, viscosity, self.factors)
        return BearingHeat(ring_sources(viscous, load), clearance, viscous, load, solution, solution.converged)


def _assembled(free, paths: ThermalPaths):
    return jnp.concatenate([free, jnp.stack([jnp.asarray(paths.ambient_temperature, float),
                                             jnp.asarray(paths.inlet_temperature, float)])])


def _residual(free, args):
    """R(T) with the heat taken at T clipped into the model's range: a Newton step past its edges
    meets a residual linear in T there, which leads back, and no heat is asked where the mounting
    model and the lubricant's line do not hold; a root inside is unchanged."""
    heated, paths = args
    sources = heated.heat(_assembled(jnp.clip(free, *TEMPERATURE_RANGE), paths)).sources
    return free - node_temperatures(bearing_network(paths), sources)[:FREE]


def _damped_newton(residual, start, args):
    """(root, steps): the house's damped Newton (`newton.newton`: Armijo backtracking on ½‖R‖², and
    Levenberg–Marquardt steps where it stalls); the lubricant's viscosity, steep in its
    temperature, sends full Newton steps far past the root."""
    y, steps = newton(residual, start, args, max_steps=MAX_STEPS, loop="while", fallback=True, floor=1e-10)
    return y, steps.astype(y.dtype)


@eqx.filter_jit
def solve_thermal(heated: AbstractHeatedBearing, paths: ThermalPaths) -> ThermalState:
    """The thermal–mechanical steady state (module docstring) of `heated` cooled by `paths`; the
    start is the network's temperatures for the heat at the ambient temperature. Differentiable in
    every input (implicit function theorem)."""
    network = bearing_network(paths)
    cold = jnp.full(FREE, jnp.asarray(paths.ambient_temperature, float))
    start_sources = jax.lax.stop_gradient(heated.heat(_assembled(cold, paths)).sources)
    start = jax.lax.stop_gradient(node_temperatures(network, start_sources)[:FREE])
    start = jnp.clip(start, *TEMPERATURE_RANGE)
    value, steps = implicit_root(_residual, start, (heated, paths), _damped_newton, has_aux=True)
    inside = jnp.all((value >= TEMPERATURE_RANGE[0]) & (value <= TEMPERATURE_RANGE[1]))
    free = jnp.clip(value, *TEMPERATURE_RANGE)
    temperatures = _assembled(free, paths)
    found = heated.heat(temperatures)
    residual = jax.lax.stop_gradient(jnp.max(jnp.abs(free - node_temperatures(network, found.sources)[:FREE])))
    converged = inside & found.converged & (residual < RESIDUAL_TOLERANCE) & (steps < MAX_STEPS)
    return ThermalState(temperatures, found.clearance, found.mechanics, found.viscous_power, found.load_power,
                        boundary_heat_flows(network, temperatures, found.sources), residual, converged)
