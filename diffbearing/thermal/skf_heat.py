"""SKF's four-component frictional moment (`friction.skf_friction`: M = φ_ish φ_rs M_rr + M_sl +
M_seal + M_drag) as the heat of a bearing in the thermal–mechanical fixed point
(`bearing_thermal.AbstractFrictionHeat`): the rolling, sliding and seal moments, generated where the
rolling elements and the seal lips touch the rings, half into each ring; the oil bath's drag M_drag,
generated in the oil the bearing churns, into the lubricant. Each at the load the bearing carries in
the state and the viscosity of its lubricant node (SKF's model reads the operating viscosity)."""

import jax.numpy as jnp

from ..bearings.interface import AbstractSupport
from ..friction.skf_friction import SkfBearing, bearing_moment
from .bearing_thermal import AbstractFrictionHeat


class SkfHeat(AbstractFrictionHeat):
    """SKF's model of a bearing described by `bearing` (`skf_friction.SkfBearing`: series, lubrication,
    d, D, drag and seals): its kind the support's `friction_kind("skf")`, its C₀ and cup angle as its
    type rates them."""

    bearing: SkfBearing

    def powers(self, support: AbstractSupport, force, speed, viscosity) -> tuple:
        """(M_drag ω, (M − M_drag) ω) [W] (module docstring)."""
        moment = bearing_moment(support.friction_kind("skf"), support.static_load_rating(),
                                support.nominal_contact_angle(), self.bearing, viscosity, speed, force)
        return moment.drag * jnp.abs(speed), moment.power - moment.drag * jnp.abs(speed)
