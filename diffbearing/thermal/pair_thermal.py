"""A preloaded pair of angular contact ball bearings (`systems.bearing_set`) in the thermal–mechanical
fixed point (`bearing_thermal`): the warmth of the rings changes each bearing's operating clearance
(the mounting model; `bearing_thermal.bearing_at`) while the set stays clamped at its matched
offset, so the preload the pair carries changes with the temperatures, and with it the heat; and
the pair's inner rings and inner spacer, at the inner rings' temperature, grow axially against its
outer rings and outer spacer, at the outer rings' (`axial_growth.pair_growth` of the mounting's
`OperatingClearance.axial_strain`: the rings' expansion coefficient for both stacks), which moves
each bearing's offset.

The two bearings share one set of nodes (inner rings, outer rings, lubricant, shaft, housing): a
lumped pair, their heat summed, the paths those of both bearings side by side. Each bearing's
friction heat comes from the load it carries in the set's equilibrium (`shaft_equilibrium`),
its preload included, so a pair that warms into a higher preload runs hotter, and one whose warmth
opens its clearance loses preload.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..bearings.ball import ball_equilibrium
from ..film.viscosity_temperature import walther_viscosity
from ..params import BallBearing, Operating
from ..systems.bearing_set import bearing_set
from ..systems.operating_clearance import Mounting
from ..systems.shaft_equilibrium import Shaft, ShaftLoads, solve_shaft
from .axial_growth import grown_supports, pair_growth
from .bearing_thermal import (
    AbstractFrictionHeat,
    AbstractHeatedBearing,
    BearingHeat,
    WaltherLine,
    bearing_at,
    ring_sources,
)


class MountedBallPair(AbstractHeatedBearing):
    """A matched pair (`arrangement` of `bearing_set.ARRANGEMENTS`) of `bearing` (as matched: its
    clearance the matched one), centres `spacing` [m] apart, each inner ring pushed by the matched
    `offset` [m] (`bearing_set.preload_offset` of a preload force), in its `mounting` (fits; the
    temperatures are the unknowns), under `operating` (force and moment on the shaft at the middle
    of the set, the inner rings turning), in `oil`, its heat by the friction model `friction`."""

    bearing: BallBearing
    mounting: Mounting
    operating: Operating
    oil: WaltherLine
    friction: AbstractFrictionHeat
    spacing: jax.Array
    offset: jax.Array
    arrangement: str = eqx.field(static=True, default="back_to_back")
    model: ball_equilibrium.BallModel = eqx.field(static=True, default=ball_equilibrium.BallModel())

    def supports(self, temperatures):
        """(the two `BallSupport`s at the clearance the node `temperatures` leave, their offsets
        moved by the stacks' axial growth, that clearance [m])."""
        running, clearance, mounted = bearing_at(self.bearing, self.mounting, self.operating, temperatures)
        cold = bearing_set(running, self.arrangement, spacing=self.spacing, offset=self.offset, model=self.model)
        return grown_supports(cold, pair_growth(self.spacing, mounted.axial_strain)), clearance

    def preload_at(self, temperatures):
        """The preload [N] the pair carries at the node `temperatures`: each bearing's axial load with
        no external load on the set (the rings turning)."""
        supports, _ = self.supports(temperatures)
        unloaded = Shaft(supports, ShaftLoads(jnp.zeros(1), jnp.zeros((1, 3)), jnp.zeros((1, 2))),
                         self.operating.inner_speed)
        return jnp.abs(solve_shaft(unloaded).bearing_forces[0][2])

    def heat(self, temperatures) -> BearingHeat:
        """The set's equilibrium at the node temperatures; each bearing's friction heat from the
        load it carries, at the lubricant node's viscosity, summed."""
        supports, clearance = self.supports(temperatures)
        shaft = Shaft(supports, ShaftLoads(jnp.zeros(1), self.operating.force[None], self.operating.moment[None]),
                      self.operating.inner_speed)
        solution = solve_shaft(shaft)
        viscosity = walther_viscosity(self.oil.viscosity_40, self.oil.viscosity_100, temperatures[2])
        speed = jnp.abs(self.operating.inner_speed)
        powers = [self.friction.powers(support, force[:3], speed, viscosity)
                  for support, force in zip(supports, solution.bearing_forces)]
        lubricant, rings = sum(p[0] for p in powers), sum(p[1] for p in powers)
        return BearingHeat(ring_sources(lubricant, rings), clearance, lubricant, rings, solution, solution.converged)
