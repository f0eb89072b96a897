"""The thermal–mechanical steady state of a ball bearing (or a preloaded pair, `pair_thermal`; the
bearings on a shaft, `shaft_thermal`) in its mounting, solved as one fixed point: the friction heat
warms the rings, shaft, housing and lubricant through a thermal network
(`thermal_network`); their temperatures set the operating clearance (the mounting model,
`systems.operating_clearance`) and the lubricant's viscosity (its Walther line); the clearance and
the load set the ball loads (`ball_equilibrium`), and with the viscosity the friction heat.

Nodes (`NODES`): inner ring, outer ring, lubricant, shaft, housing (free); ambient and oil inlet
(held). Paths (`ThermalPaths`, conductances [W/K]): inner ring – shaft, outer ring – housing, each
ring – lubricant, shaft – ambient, housing – ambient, and the circulating oil's flow from the inlet
(ρc V̇; 0 for a bath or grease). Bearings at several seats along a shaft have these five nodes
each, the neighbouring seats' shaft and housing nodes joined by conduction along them. Heat (a
friction model, `AbstractFrictionHeat`; Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., vol.
1, ch. 13, for the split): the losses in the rolling contacts half into each ring (the balls pass
their share on to the rings they roll between), the losses in the oil around them into the
lubricant. Palmgren's moments (`PalmgrenFactors`, `friction.friction_torque`): the load-dependent
M₁ ω into the rings, the viscous M₀ ω into the lubricant. SKF's (`skf_heat.SkfHeat`,
`friction.skf_friction`): the rolling, sliding and seal moments into the rings, the oil bath's drag
into the lubricant.

Palmgren's P₁ and SKF's loads are the bearing's external load, so a clearance the warmth closes
into a preload raises the heat only where it shows in that load (the axial load of an angular
contact pair's bearings), not the internal preload of a single radial bearing: a
contact-level loss model would see it.

The unknowns are the free temperatures T (five a seat); the residual is R(T) = T − T_network(Q(T)), Q the
heat of the bearing at the state T gives (`AbstractHeatedBearing.heat`: one bearing,
`MountedBallBearing`; a pair, `pair_thermal.MountedBallPair`; a shaft, `shaft_thermal.MountedShaft`).
Newton (optimistix) on R with the implicit derivative of
the root: ∂T/∂p = −(∂R/∂T)⁻¹ ∂R/∂p, through the inner equilibrium solve's own implicit derivative.
Where no steady state exists inside the model (thermal runaway: a preloaded bearing whose warming
closes its clearance faster than the paths carry the heat away), or the temperatures leave the
mounting model's −60…250 °C, `converged` is False and the values stay finite.
"""

import abc

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..bearings.ball import ball_equilibrium
from ..bearings.ball.ball_support import BallSupport
from ..bearings.interface import AbstractSupport
from ..film.viscosity_temperature import walther_viscosity
from ..friction import friction_torque
from ..params import BallBearing, Operating, clearance_changed, radial_clearance
from ..newton import implicit_root, newton
from ..systems.operating_clearance import Mounting, mounted_clearance_change
from .thermal_network import ThermalNetwork, boundary_heat_flows, node_temperatures

NODES = ("inner_ring", "outer_ring", "lubricant", "shaft", "housing", "ambient", "oil_inlet")
SEAT_NODES = 5  # a seat's free nodes, the first five of NODES; the held ambient and oil inlet after all seats
SEAT_EDGES = ((0, 3), (1, 4), (0, 2), (1, 2), (3, "ambient"), (4, "ambient"), (2, "oil_inlet"))
TEMPERATURE_RANGE = (213.15, 523.15)  # K: the mounting model's (−60 … 250 °C)
MAX_STEPS = 60
RESIDUAL_TOLERANCE = 1e-6  # K: the largest |R| of a converged state


class ThermalPaths(eqx.Module):
    """The conductances [W/K] of a radial bearing's heat paths (module docstring) and the held
    temperatures [K] of the ambient and the oil inlet. For bearings at several seats along a shaft
    (`shaft_thermal`) each path is an array, one per seat in the order of their positions, and
    `shaft_axial`, `housing_axial` (one fewer) join the shaft and housing nodes of the neighbouring
    seats `axial_pairs` (None and (): one seat)."""

    inner_ring_shaft: jax.Array
    outer_ring_housing: jax.Array
    inner_ring_lubricant: jax.Array
    outer_ring_lubricant: jax.Array
    shaft_ambient: jax.Array
    housing_ambient: jax.Array
    oil_flow: jax.Array
    ambient_temperature: jax.Array
    inlet_temperature: jax.Array
    shaft_axial: jax.Array | None = None
    housing_axial: jax.Array | None = None
    axial_pairs: tuple[tuple[int, int], ...] = eqx.field(static=True, default=())

    @property
    def seats(self) -> int:
        return int(np.size(self.inner_ring_shaft))


PATH_NAMES = ("inner_ring_shaft", "outer_ring_housing", "inner_ring_lubricant", "outer_ring_lubricant", "shaft_ambient",
              "housing_ambient", "oil_flow")


def node_names(seats: int) -> tuple[str, ...]:
    """`NODES` for one seat; for several, each seat's five free nodes numbered (`inner_ring_0`, …),
    then the ambient and the oil inlet."""
    if seats == 1:
        return NODES
    return tuple(f"{name}_{seat}" for seat in range(seats) for name in NODES[:SEAT_NODES]) + NODES[SEAT_NODES:]


def seat_node(seat: int, node: int) -> int:
    """The index of a seat's free node (`NODES[node]`, node < 5) in the network."""
    return SEAT_NODES * seat + node


def seat_temperatures(temperatures, seats: int):
    """The free nodes' temperatures [K] (`seats`, 5): a row per seat, its columns `NODES[:5]`."""
    return jnp.reshape(temperatures[:SEAT_NODES * seats], (seats, SEAT_NODES))


def bearing_network(paths: ThermalPaths) -> ThermalNetwork:
    """The paths as a `ThermalNetwork` over `node_names(paths.seats)`."""
    seats = paths.seats
    held = {"ambient": SEAT_NODES * seats, "oil_inlet": SEAT_NODES * seats + 1}
    per_seat = [jnp.broadcast_to(jnp.asarray(getattr(paths, name), float), (seats,)) for name in PATH_NAMES]
    edges, conductances = [], []
    for seat in range(seats):
        for (near, far), values in zip(SEAT_EDGES, per_seat):
            edges.append((seat_node(seat, near), held[far] if far in held else seat_node(seat, far)))
            conductances.append(values[seat])
    if seats > 1:
        for node, values in ((3, paths.shaft_axial), (4, paths.housing_axial)):
            for number, (near, far) in enumerate(paths.axial_pairs):
                edges.append((seat_node(near, node), seat_node(far, node)))
                conductances.append(jnp.asarray(values, float)[number])
    temperatures = jnp.stack([jnp.asarray(paths.ambient_temperature, float), jnp.asarray(paths.inlet_temperature, float)])
    return ThermalNetwork(node_names(seats), tuple(edges), (held["ambient"], held["oil_inlet"]),
                          jnp.stack(conductances), temperatures)


class WaltherLine(eqx.Module):
    """The lubricant's Walther line: kinematic viscosities at 40 °C and 100 °C [m²/s]."""

    viscosity_40: jax.Array
    viscosity_100: jax.Array


class AbstractFrictionHeat(eqx.Module):
    """A friction model's heat of one bearing: `powers(support, force, speed, viscosity)` → (the
    power into the lubricant, the power into the rings) [W] of the bearing `support` carrying `force`
    ([Fx, Fy, Fz] in its own frame [N]) at the relative ring speed `speed` [rad/s] in oil of kinematic
    `viscosity` [m²/s]. `PalmgrenFactors` here; `skf_heat.SkfHeat`, SKF's four components."""

    @abc.abstractmethod
    def powers(self, support: AbstractSupport, force, speed, viscosity) -> tuple:
        """(power into the lubricant, power into the rings) [W]."""


class PalmgrenFactors(AbstractFrictionHeat):
    """Palmgren's f₀ and f₁ = a (P₀/C₀)^b of the bearing's kind (`friction_torque.PALMGREN_CONSTANTS`):
    the viscous loss M₀ ω into the lubricant, the load-dependent M₁ ω into the rings (`palmgren_powers`)."""

    f0: jax.Array
    coefficient: jax.Array
    exponent: float = eqx.field(static=True)

    @classmethod
    def of_kind(cls, kind: str, f0) -> "PalmgrenFactors":
        """f₀ `f0` and the f₁ factors of a bearing `kind`'s row of `friction_torque.PALMGREN_CONSTANTS`."""
        _, _, coefficient, exponent = friction_torque.PALMGREN_CONSTANTS[kind]
        return cls(jnp.asarray(f0, float), coefficient, exponent)

    def powers(self, support: AbstractSupport, force, speed, viscosity) -> tuple:
        return palmgren_powers(support, force, speed, viscosity, self)


class BearingHeat(eqx.Module):
    """What a bearing's mechanics give at one set of node temperatures: the heat sources [W] at
    `NODES`, the operating diametral clearance [m], the friction powers into the lubricant and into
    the rings [W], the mechanical state (the type's equilibrium) and whether that state converged."""

    sources: jax.Array
    clearance: jax.Array
    lubricant_power: jax.Array
    ring_power: jax.Array
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
    the mechanical state at it (`BearingHeat.mechanics`), the friction powers into the lubricant and
    into the rings, the heat leaving at the ambient and the oil inlet, the residual's largest |R| [K],
    whether it converged inside the model."""

    temperatures: jax.Array
    clearance: jax.Array
    mechanics: eqx.Module
    lubricant_power: jax.Array
    ring_power: jax.Array
    boundary_heat: jax.Array
    residual: jax.Array
    converged: jax.Array


def mounted_at(mounting: Mounting, temperatures, seat: int = 0) -> Mounting:
    """`mounting` with its ring, shaft and housing temperatures those of the `seat`'s nodes [K]."""
    return eqx.tree_at(lambda m: (m.inner_ring_temperature, m.outer_ring_temperature, m.shaft_temperature,
                                  m.housing_temperature), mounting,
                       tuple(temperatures[seat_node(seat, node)] for node in (0, 1, 3, 4)))


def bearing_at(bearing: BallBearing, mounting: Mounting, operating: Operating, temperatures):
    """(the bearing at the operating clearance its mounting leaves at the node `temperatures`, that
    clearance [m], the mounting's `OperatingClearance` there): the change ΔG as
    `params.clearance_changed` makes it (the free contact angle kept)."""
    mounted = mounted_clearance_change(BallSupport(bearing, 0.0), mounted_at(mounting, temperatures), bearing.bore,
                                       bearing.outer_diameter, operating.inner_speed, operating.outer_speed)
    running = clearance_changed(bearing, mounted.change)
    return running, radial_clearance(running), mounted


def palmgren_powers(support: AbstractSupport, force, speed, viscosity, factors: PalmgrenFactors):
    """(viscous power M₀ω, load-dependent power M₁ω) [W] of a bearing (`support`: its friction kind,
    P₀, C₀ and contact angle as its type rates them) carrying `force` ([Fx, Fy, Fz] in its own frame
    [N]) at the relative ring speed `speed` [rad/s] in oil of kinematic `viscosity` [m²/s]
    (`friction_torque`: Palmgren's moments; f₁ from P₀/C₀)."""
    radial, axial = jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])
    f1 = friction_torque.speed_factor(factors.coefficient, factors.exponent, support.equivalent_static_load(force),
                                      support.static_load_rating())
    pitch = 2.0 * support.pitch_radius()
    load = friction_torque.load_torque(f1, friction_torque.friction_load(support.friction_kind("palmgren"), radial, axial,
                                                                         support.nominal_contact_angle()), pitch) * speed
    viscous = friction_torque.viscous_torque(factors.f0, viscosity, speed, pitch) * speed
    return viscous, load


def ring_sources(lubricant_power, ring_power):
    """Heat sources [W] at `NODES`: the rings' share half into each ring (the contacts between them),
    the lubricant's into the lubricant (module docstring)."""
    zero = jnp.zeros(())
    return jnp.stack([0.5 * ring_power, 0.5 * ring_power, lubricant_power, zero, zero, zero, zero])


class MountedBallBearing(AbstractHeatedBearing):
    """One radial ball bearing in its `mounting` (its fits; the temperatures are the unknowns),
    under `operating`, in `oil`, its heat by the friction model `friction`, its equilibrium by `model`."""

    bearing: BallBearing
    mounting: Mounting
    operating: Operating
    oil: WaltherLine
    friction: AbstractFrictionHeat
    model: ball_equilibrium.BallModel = eqx.field(static=True, default=ball_equilibrium.BallModel())

    def heat(self, temperatures) -> BearingHeat:
        """The equilibrium at the clearance the node temperatures leave, the friction model's heat at
        the lubricant node's viscosity."""
        running, clearance, _ = bearing_at(self.bearing, self.mounting, self.operating, temperatures)
        solution = ball_equilibrium.solve_equilibrium(running, self.operating, self.model)
        speed = jnp.abs(self.operating.inner_speed - self.operating.outer_speed)
        viscosity = walther_viscosity(self.oil.viscosity_40, self.oil.viscosity_100, temperatures[2])
        lubricant, rings = self.friction.powers(BallSupport(running, 0.0), solution.force[:3], speed, viscosity)
        return BearingHeat(ring_sources(lubricant, rings), clearance, lubricant, rings, solution, solution.converged)


def _free_count(paths: ThermalPaths) -> int:
    return SEAT_NODES * paths.seats


def _assembled(free, paths: ThermalPaths):
    return jnp.concatenate([free, jnp.stack([jnp.asarray(paths.ambient_temperature, float),
                                             jnp.asarray(paths.inlet_temperature, float)])])


def _residual(free, args):
    """R(T) with the heat taken at T clipped into the model's range: a Newton step past its edges
    meets a residual linear in T there, which leads back, and no heat is asked where the mounting
    model and the lubricant's line do not hold; a root inside is unchanged."""
    heated, paths = args
    sources = heated.heat(_assembled(jnp.clip(free, *TEMPERATURE_RANGE), paths)).sources
    return free - node_temperatures(bearing_network(paths), sources)[:_free_count(paths)]


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
    count = _free_count(paths)
    cold = jnp.full(count, jnp.asarray(paths.ambient_temperature, float))
    start_sources = jax.lax.stop_gradient(heated.heat(_assembled(cold, paths)).sources)
    start = jax.lax.stop_gradient(node_temperatures(network, start_sources)[:count])
    start = jnp.clip(start, *TEMPERATURE_RANGE)
    value, steps = implicit_root(_residual, start, (heated, paths), _damped_newton, has_aux=True)
    inside = jnp.all((value >= TEMPERATURE_RANGE[0]) & (value <= TEMPERATURE_RANGE[1]))
    free = jnp.clip(value, *TEMPERATURE_RANGE)
    temperatures = _assembled(free, paths)
    found = heated.heat(temperatures)
    residual = jax.lax.stop_gradient(jnp.max(jnp.abs(free - node_temperatures(network, found.sources)[:count])))
    converged = inside & found.converged & (residual < RESIDUAL_TOLERANCE) & (steps < MAX_STEPS)
    return ThermalState(temperatures, found.clearance, found.mechanics, found.lubricant_power, found.ring_power,
                        boundary_heat_flows(network, temperatures, found.sources), residual, converged)
