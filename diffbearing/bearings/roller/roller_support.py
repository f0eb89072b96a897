"""A roller bearing (cylindrical or tapered) mounted on a shaft: `AbstractSupport` through the
roller model (`roller_equilibrium`). At u = 0 it sits at its model's reference (the rollers at
their clearance); its rollers are re-equilibrated inside every ring force (no state carried)."""

import equinox as eqx
import jax
import jax.numpy as jnp

from ... import overrolling
from ...params import _as_float, _is_concrete
from ...ratings import roller_life, static_safety
from ..interface import AbstractSupport, ContactLoads, RingSection, check_orientation
from . import roller_equilibrium
from .roller_equilibrium import RollerModel, RollerOperating, RollerRaceways, RollerResults
from .roller_geometry import RollerBearing, mean_roller_diameter


class RollerSupport(AbstractSupport):
    """A roller bearing (cylindrical or tapered) on the shaft, with its `raceways`; fields as
    `BallSupport`."""

    bearing: RollerBearing
    raceways: RollerRaceways
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: RollerModel = eqx.field(static=True, default=RollerModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        check_orientation(self.orientation)
        if not self.locates_axially() and _is_concrete(self.offset) and float(self.offset) != 0.0:
            raise ValueError("offset: a cylindrical roller bearing takes no axial preload; it must be 0")

    def _operating(self, speed):
        return RollerOperating(jnp.zeros(3), jnp.zeros(2), inner_speed=speed)

    def constants(self):
        return None

    def ring_force(self, displacement, speed, constants, elements=None):
        return roller_equilibrium.ring_force(displacement, self.bearing, self.raceways, self._operating(speed),
                                             self.model)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """`jax.jacfwd` of the ring force (`roller_equilibrium.roller_stiffness_matrix`)."""
        return roller_equilibrium.roller_stiffness_matrix(displacement, self.bearing, self.raceways,
                                                          self._operating(speed), self.model)

    def energy_constants(self, constants):
        """The lamina setup (`roller_equilibrium.lamina_setup`)."""
        return roller_equilibrium.lamina_setup(self.bearing, self.raceways, self.model)

    def static_energy(self, displacement, energy_constants):
        return roller_equilibrium.static_energy(displacement, self.bearing, self.raceways, energy_constants)

    def characteristic_load(self, constants, energy_constants):
        return roller_equilibrium.characteristic_load(self.bearing, energy_constants)

    def pitch_radius(self):
        return 0.5 * self.raceways.pitch_diameter

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Each roller's inner and outer line contact with its laminae (`roller_equilibrium.roller_results`)."""
        return contact_loads(self.bearing, roller_equilibrium.roller_results(
            displacement, self.bearing, self.raceways, self._operating(speed), self.model))

    def dynamic_load_rating(self):
        """ISO 281's C_r (`roller_life.roller_bearing_load_rating`)."""
        return roller_life.roller_bearing_load_rating(self.bearing, self.raceways)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """q_ci, q_ce [N] per lamina (ISO/TS 16281 eqs. (47)–(49), (56)–(57), `roller_life.lamina_ratings`)."""
        return jnp.stack(roller_life.lamina_ratings(rating, self.bearing.roller_count, mean_roller_diameter(self.bearing),
                                                    self.raceways.cup_angle, self.raceways.pitch_diameter,
                                                    contacts.lamina_load.shape[-1]))

    def static_load_rating(self):
        """ISO 76 C₀r (`static_safety.roller_bearing_static_load_rating`: the mean roller diameter,
        the cup angle)."""
        return static_safety.roller_bearing_static_load_rating(self.bearing, self.raceways)

    def equivalent_dynamic_load(self, force):
        """ISO 281 P at the cup angle (`roller_life.roller_equivalent_dynamic_load`)."""
        return roller_life.roller_equivalent_dynamic_load(force, self.raceways.cup_angle)

    def equivalent_static_load(self, force):
        """ISO 76 P₀r at the cup angle (`static_safety.roller_equivalent_static_load`)."""
        return static_safety.roller_equivalent_static_load(force, self.raceways.cup_angle)

    def pressure_safety(self, max_pressure):
        """(4 000 MPa / p_max)² of its largest lamina pressure."""
        return static_safety.pressure_safety(max_pressure, static_safety.ROLLER_PRESSURE_LIMIT,
                                             static_safety.LINE_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "roller"

    def friction_kind(self, model: str) -> str | None:
        """Its own kind (cylindrical or tapered) in both friction models."""
        return self.bearing.kind

    def nominal_contact_angle(self):
        """The cup angle (0 for a cylindrical roller bearing)."""
        return self.raceways.cup_angle

    def ring_section(self) -> RingSection | None:
        """A cylindrical roller bearing's raceways d_m ∓ D, its roller, material and clearance P_d; None for a
        tapered one (its clearance is its axial setting, not a diametral clearance the fits close)."""
        if self.bearing.kind != "cylindrical_roller":
            return None
        pitch, roller = self.raceways.pitch_diameter, mean_roller_diameter(self.bearing)
        return RingSection(pitch - roller, pitch + roller, roller, self.bearing.material,
                           self.raceways.diametral_clearance)

    def with_clearance_change(self, change) -> "RollerSupport":
        """The raceways' diametral clearance P_d + change (a cylindrical roller bearing's)."""
        if self.ring_section() is None:
            raise NotImplementedError("a tapered roller bearing takes no mounting (its axial setting)")
        return eqx.tree_at(lambda support: support.raceways.diametral_clearance, self,
                           self.raceways.diametral_clearance + change)

    def envelope(self, contacts: ContactLoads):
        """The largest lamina approach / mean roller diameter (limit
        `roller_equilibrium.MAX_APPROACH_FRACTION`, as the balls'), 0 and π/2 (no contact angle of
        its own, no low shoulder)."""
        return jnp.stack([jnp.max(contacts.approach) / mean_roller_diameter(self.bearing), 0.0, 0.5 * jnp.pi])

    def frequencies(self, speed, contacts: ContactLoads):
        """`overrolling.frequencies_of_rollers` (the raceways' cone and cup angles)."""
        return overrolling.frequencies_of_rollers(self.bearing, self.raceways, speed, 0.0)

    def locates_axially(self) -> bool:
        """A cylindrical roller bearing carries no axial load."""
        return self.bearing.kind != "cylindrical_roller"


def contact_loads(bearing: RollerBearing, rollers: RollerResults) -> ContactLoads:
    """A roller bearing's per-roller results as its `ContactLoads`: two line contacts a roller,
    inner then outer, each lamina's load [N] its load per length times the lamina width l/n."""
    def pair(inner, outer):
        return jnp.stack([inner, outer], axis=1)

    width = bearing.length / rollers.inner_lamina_load.shape[-1]
    return ContactLoads(rollers.azimuth, pair(rollers.inner_load, rollers.outer_load),
                        pair(rollers.inner_lamina_load * width, rollers.outer_lamina_load * width),
                        pair(rollers.inner_max_pressure, rollers.outer_max_pressure), None,
                        pair(rollers.inner_approach, rollers.outer_approach), ("inner", "outer"), "line")
