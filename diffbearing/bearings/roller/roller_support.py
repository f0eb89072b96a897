"""A roller bearing (cylindrical or tapered) mounted on a shaft: `AbstractSupport` through the
roller model (`roller_equilibrium`). At u = 0 it sits at its model's reference (the rollers at
their clearance); its rollers are re-equilibrated inside every ring force (no state carried)."""

import equinox as eqx
import jax
import jax.numpy as jnp

from ...params import _as_float, _is_concrete
from ..interface import AbstractSupport, check_orientation
from . import roller_equilibrium
from .roller_equilibrium import RollerModel, RollerOperating, RollerRaceways
from .roller_geometry import RollerBearing


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

    def locates_axially(self) -> bool:
        """A cylindrical roller bearing carries no axial load."""
        return self.bearing.kind != "cylindrical_roller"
