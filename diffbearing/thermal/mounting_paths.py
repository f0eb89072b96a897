"""The conductances of a ball bearing's heat paths (`bearing_thermal.ThermalPaths`) from the
geometry of the rings, the shaft and the housing, their materials, and the cooling (the air, the
oil, a circulating oil flow): closed forms of `conductance` and one convection correlation.

- inner ring – shaft: radial conduction through the inner ring, from its raceway diameter to its
  bore, over the bearings' width;
- outer ring – housing: through the outer ring, from its raceway to its outside, then through the
  housing's wall to its outer diameter, over the housing's length (in series);
- each ring – lubricant: convection h_oil over the raceway's cylinder (π d × width), h_oil of a
  cylinder turning in the oil at half the rings' relative speed (the oil in a bearing swirls at
  about its cage's speed; `rotating_cylinder_coefficient` on the pitch diameter, the oil's
  viscosity at the inlet temperature: the warmer oil carries more) plus free convection in a
  liquid, `STILL_OIL`; or the scene's coefficient;
- shaft – ambient: each of the shaft's two ends a fin in air (`fin`; the shaft's length beyond
  the bearing on each side), h of the turning shaft in air plus `STILL_AIR`; or the scene's;
- housing – ambient: convection h_housing over its outside cylinder and both end faces;
- the oil's flow: ρc V̇ with DIN 732's ρc of mineral oil (`thermal_speed.OIL_HEAT_PER_FLOW`).

Bearings at several seats along a shaft (`shaft_paths`): each seat has these paths with its own
bearing's geometry and a housing piece of the housing's length around it; the shaft's end fins and
the housing's end faces belong to the outermost seats; the shaft and the housing conduct axially
between neighbouring seats (the shaft's surface between two seats, inside the housing, is left
out: no path from it to the air).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..film.viscosity_temperature import walther_viscosity
from .bearing_thermal import ThermalPaths, WaltherLine
from .conductance import advection, convection, cylindrical_shell, fin, in_series, rotating_cylinder_coefficient
from .thermal_speed import OIL_HEAT_PER_FLOW

# Fluid properties (Incropera et al., 6th ed., Table A.4, air at 300 K; Table A.5, engine oil near 350 K)
AIR_VISCOSITY, AIR_CONDUCTIVITY, AIR_PRANDTL = 15.89e-6, 26.3e-3, 0.707  # m²/s, W/(m·K), -
OIL_CONDUCTIVITY = 0.138  # W/(m·K)
# Free convection (Incropera Table 1.1: gases 2–25, liquids 50–1000 W/(m²·K)): air about a machine
# with its radiation, and the still oil's lower end, the floors under the turning parts' coefficients
STILL_AIR, STILL_OIL = 10.0, 50.0  # W/(m²·K)
# Conductivities [W/(m·K)] near room temperature: bearing steel and a steel shaft as Incropera's
# Table A.1 1 Cr–½ Mo steel (42.3); a grey cast iron housing, about 50; aluminium alloy 2024-T6, 177
CONDUCTIVITIES = {"bearing_steel": 42.3, "steel": 42.3, "cast_iron": 50.0, "aluminium": 177.0}


class MountingGeometry(eqx.Module):
    """The parts [m] and their conductivities [W/(m·K)]: the bore d, outside D and width B of the
    bearings (a pair's both), the raceway diameters d_m ∓ D_w, the shaft's bore and its length
    beyond the bearings on each side, the housing's outer diameter and length."""

    bore: jax.Array
    outer_diameter: jax.Array
    width: jax.Array
    inner_raceway_diameter: jax.Array
    outer_raceway_diameter: jax.Array
    shaft_bore: jax.Array
    shaft_length: jax.Array
    housing_outer_diameter: jax.Array
    housing_length: jax.Array
    ring_conductivity: jax.Array
    shaft_conductivity: jax.Array
    housing_conductivity: jax.Array


class Cooling(eqx.Module):
    """The ambient and oil inlet temperatures [K], the circulating oil's flow [m³/s] (0: a bath, oil
    mist or grease), the housing's outside coefficient h [W/(m²·K)], the relative ring speed [rad/s],
    the oil's Walther line, and the shaft's and the oil's coefficients where the scene gives them
    (None: the correlations of the module docstring)."""

    ambient_temperature: jax.Array
    inlet_temperature: jax.Array
    oil_flow: jax.Array
    housing_coefficient: jax.Array
    speed: jax.Array
    oil: WaltherLine
    shaft_coefficient: jax.Array | None = None
    oil_coefficient: jax.Array | None = None


def oil_coefficient(cooling: Cooling, pitch_diameter):
    """h [W/(m²·K)] between the rings and the oil (module docstring)."""
    if cooling.oil_coefficient is not None:
        return cooling.oil_coefficient
    viscosity = walther_viscosity(cooling.oil.viscosity_40, cooling.oil.viscosity_100, cooling.inlet_temperature)
    prandtl = viscosity * OIL_HEAT_PER_FLOW / OIL_CONDUCTIVITY
    return STILL_OIL + rotating_cylinder_coefficient(0.5 * cooling.speed, pitch_diameter, viscosity, OIL_CONDUCTIVITY,
                                                     prandtl)


def shaft_coefficient(cooling: Cooling, shaft_diameter):
    """h [W/(m²·K)] of the shaft's ends in air (module docstring)."""
    if cooling.shaft_coefficient is not None:
        return cooling.shaft_coefficient
    return STILL_AIR + rotating_cylinder_coefficient(cooling.speed, shaft_diameter, AIR_VISCOSITY, AIR_CONDUCTIVITY,
                                                     AIR_PRANDTL)


def _shaft_section(geometry: MountingGeometry):
    """The shaft's cross-section at a seat [m²]: π/4 (d² − d_bore²)."""
    return 0.25 * jnp.pi * (geometry.bore ** 2 - geometry.shaft_bore ** 2)


def _seat_paths(geometry: MountingGeometry, cooling: Cooling, ends: int) -> dict:
    """The conductances [W/K] of one seat's paths (`bearing_thermal.PATH_NAMES`), the shaft and the
    housing reaching past it on `ends` of its two sides (2: a single seat; on a shaft the outermost
    seats 1, the others 0): a shaft end's fin and a housing end face on each."""
    g = geometry
    pitch = 0.5 * (g.inner_raceway_diameter + g.outer_raceway_diameter)
    oil = oil_coefficient(cooling, pitch)
    air = shaft_coefficient(cooling, g.bore)
    housing_surface = jnp.pi * g.housing_outer_diameter * g.housing_length \
        + ends * 0.25 * jnp.pi * (g.housing_outer_diameter ** 2 - g.outer_diameter ** 2)
    return dict(
        inner_ring_shaft=cylindrical_shell(g.ring_conductivity, g.width, 0.5 * g.bore, 0.5 * g.inner_raceway_diameter),
        outer_ring_housing=in_series(
            cylindrical_shell(g.ring_conductivity, g.width, 0.5 * g.outer_raceway_diameter, 0.5 * g.outer_diameter),
            cylindrical_shell(g.housing_conductivity, g.housing_length, 0.5 * g.outer_diameter,
                              0.5 * g.housing_outer_diameter)),
        inner_ring_lubricant=convection(oil, jnp.pi * g.inner_raceway_diameter * g.width),
        outer_ring_lubricant=convection(oil, jnp.pi * g.outer_raceway_diameter * g.width),
        shaft_ambient=ends * fin(air, jnp.pi * g.bore, g.shaft_conductivity, _shaft_section(g), g.shaft_length),
        housing_ambient=convection(cooling.housing_coefficient, housing_surface),
        oil_flow=advection(cooling.oil_flow, OIL_HEAT_PER_FLOW),
    )


def mounting_paths(geometry: MountingGeometry, cooling: Cooling) -> ThermalPaths:
    """The `ThermalPaths` of the parts and the cooling (module docstring)."""
    return ThermalPaths(**_seat_paths(geometry, cooling, 2), ambient_temperature=cooling.ambient_temperature,
                        inlet_temperature=cooling.inlet_temperature)


def shaft_paths(seats: tuple[MountingGeometry, ...], positions, cooling: Cooling) -> ThermalPaths:
    """The `ThermalPaths` of bearings at several `seats` along a shaft, at axial `positions` [m]
    (concrete: their order sets which seats neighbour; module docstring): each seat's own paths, the
    shaft's ends beyond the outermost seats, and conduction along the shaft and the housing between neighbouring seats —
    through the mean of the two seats' shaft sections, and through the housing's wall outside the
    larger outer diameter — over the distance of their centres."""
    order = [int(seat) for seat in np.argsort(np.asarray(positions))]
    ends = {order[0]: 1, order[-1]: 1} if len(order) > 1 else {order[0]: 2}
    own = [_seat_paths(geometry, cooling, ends.get(seat, 0)) for seat, geometry in enumerate(seats)]
    pairs = tuple(zip(order, order[1:]))
    shaft, housing = [], []
    for near, far in pairs:
        first, second = seats[near], seats[far]
        distance = jnp.abs(jnp.asarray(positions[far]) - jnp.asarray(positions[near]))
        shaft.append(first.shaft_conductivity * 0.5 * (_shaft_section(first) + _shaft_section(second)) / distance)
        wall = 0.25 * jnp.pi * (first.housing_outer_diameter ** 2 - jnp.maximum(first.outer_diameter,
                                                                                  second.outer_diameter) ** 2)
        housing.append(first.housing_conductivity * wall / distance)
    stacked = {name: jnp.stack([jnp.asarray(paths[name], float) for paths in own]) for name in own[0]}
    return ThermalPaths(**stacked, ambient_temperature=cooling.ambient_temperature,
                        inlet_temperature=cooling.inlet_temperature,
                        shaft_axial=jnp.stack(shaft) if pairs else None, housing_axial=jnp.stack(housing) if pairs else None,
                        axial_pairs=pairs)
