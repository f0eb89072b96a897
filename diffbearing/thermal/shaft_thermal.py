"""The bearings on a shaft, rigid (`systems.shaft_equilibrium`) or flexible (`systems.flexible_shaft`),
in the thermal–mechanical fixed point (`bearing_thermal`): each bearing sits at its own seat of the
network (its rings, lubricant, shaft and housing nodes; `mounting_paths.shaft_paths` joins the
seats along the shaft and the housing), its fits and the temperatures of its seat set its operating
clearance (the mounting model through its type's `AbstractSupport.ring_section` and
`with_clearance_change`), and the shaft's equilibrium with every bearing at its clearance sets the
loads each carries, its preload included, and with the viscosity at its seat's lubricant node its
friction heat: a warm front pair that closes its clearance shows in every bearing's load. The
shaft's axial growth against the housing's between the seats moves each locating bearing's
offset (`axial_growth`).

A bearing type takes part where its support gives a `ring_section` (ball bearings, cylindrical
roller bearings); its heat is its friction model's (`bearing_thermal.AbstractFrictionHeat`, one per
bearing: its friction kind's Palmgren factors, `shaft_factors`, or SKF's rows).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..film.viscosity_temperature import walther_viscosity
from ..systems.flexible_shaft import FlexibleShaft, solve_flexible_shaft
from ..systems.operating_clearance import mounted_clearance_change
from ..systems.shaft_beam import BeamMesh, ShaftSections
from ..systems.shaft_equilibrium import Shaft, ShaftLoads, solve_shaft
from .axial_growth import grown_supports, mounted_axial_growth
from .bearing_thermal import (
    SEAT_NODES,
    AbstractHeatedBearing,
    BearingHeat,
    PalmgrenFactors,
    WaltherLine,
    mounted_at,
    ring_sources,
    seat_temperatures,
)


class MountedShaft(AbstractHeatedBearing):
    """A shaft on `supports` (each an `AbstractSupport` with a `ring_section`, at its clearance
    as given), bearing k in `mountings[k]` (its fits; the temperatures are the unknowns) with bore
    and outside diameter `bores[k]`, `outer_diameters[k]` [m] and friction model `friction[k]`, under
    `loads`, turning at `speed` [rad/s] (outer rings fixed), in `oil`; rigid, or with `sections`
    (and their `mesh`, `reference` the point of `flexible_shaft.FlexibleShaft`) a Timoshenko beam.
    Bearing k's nodes are seat k's (`bearing_thermal.node_names`)."""

    supports: tuple
    mountings: tuple
    bores: jax.Array
    outer_diameters: jax.Array
    friction: tuple
    loads: ShaftLoads
    speed: jax.Array
    oil: WaltherLine
    sections: ShaftSections | None = None
    reference: jax.Array = 0.0
    mesh: BeamMesh | None = eqx.field(static=True, default=None)

    def __check_init__(self):
        if not (len(self.supports) == len(self.mountings) == len(self.friction)):
            raise ValueError("supports, mountings, friction: one each per bearing")
        for number, support in enumerate(self.supports):
            if support.ring_section() is None:
                raise ValueError(f"bearings[{number}]: its type takes no mounting (no diametral clearance the fits "
                                 "and temperatures change)")

    def mountings_at(self, temperatures) -> tuple:
        """Each bearing's mounting at its seat's node `temperatures` (`bearing_thermal.mounted_at`)."""
        return tuple(mounted_at(mounting, temperatures, seat) for seat, mounting in enumerate(self.mountings))

    def clearance_changes(self, temperatures):
        """Each bearing's change of diametral clearance [m] (K,) by its fits at its seat's node
        `temperatures` and the shaft's speed (`operating_clearance.mounted_clearance_change`)."""
        return jnp.stack([mounted_clearance_change(support, mounting, bore, outside, self.speed).change
                          for support, mounting, bore, outside in zip(self.supports, self.mountings_at(temperatures),
                                                                      self.bores, self.outer_diameters)])

    def supports_at(self, temperatures) -> tuple:
        """The supports at the clearances the node `temperatures` leave, the locating ones' offsets
        moved by the shaft's and the housing's axial growth between the seats (`axial_growth`)."""
        warm = tuple(support.with_clearance_change(change)
                     for support, change in zip(self.supports, self.clearance_changes(temperatures)))
        return grown_supports(warm, self.axial_growth(temperatures))

    def axial_growth(self, temperatures):
        """Each bearing's inner ring's axial displacement against its outer ring [m] (K,) by the
        shaft's and the housing's growth between the seats at the node `temperatures`
        (`axial_growth.mounted_axial_growth`)."""
        return mounted_axial_growth(jnp.stack([support.position for support in self.supports]),
                                    self.mountings_at(temperatures))

    def equilibrium(self, supports, loads):
        """The shaft's equilibrium on `supports` under `loads` at its speed, rigid or flexible."""
        shaft = Shaft(supports, loads, self.speed)
        if self.sections is None:
            return solve_shaft(shaft)
        return solve_flexible_shaft(FlexibleShaft(shaft, self.sections, self.reference, self.mesh))

    def heat(self, temperatures) -> BearingHeat:
        """The shaft's equilibrium at the warm clearances; each bearing's friction heat from the load
        it carries at its seat's lubricant viscosity, into its seat's nodes. `clearance`,
        `lubricant_power` and `ring_power` are per bearing (K,)."""
        warm = self.supports_at(temperatures)
        solution = self.equilibrium(warm, self.loads)
        viscosities = walther_viscosity(self.oil.viscosity_40, self.oil.viscosity_100,
                                        seat_temperatures(temperatures, len(warm))[:, 2])
        powers = [friction.powers(support, force[:3], jnp.abs(self.speed), viscosity)
                  for support, force, friction, viscosity in zip(warm, solution.bearing_forces, self.friction,
                                                                  viscosities)]
        lubricant, rings = jnp.stack([p[0] for p in powers]), jnp.stack([p[1] for p in powers])
        sources = jnp.concatenate([*(ring_sources(own, ring)[:SEAT_NODES] for own, ring in zip(lubricant, rings)),
                                   jnp.zeros(2)])
        clearance = jnp.stack([support.ring_section().clearance for support in warm])
        return BearingHeat(sources, clearance, lubricant, rings, solution, solution.converged)


def shaft_factors(supports, f0) -> tuple[PalmgrenFactors, ...]:
    """Each bearing's `PalmgrenFactors`: f₀ `f0[k]` and the f₁ factors of its friction kind
    (`AbstractSupport.friction_kind`)."""
    return tuple(PalmgrenFactors.of_kind(support.friction_kind("palmgren"), own) for support, own in zip(supports, f0))
