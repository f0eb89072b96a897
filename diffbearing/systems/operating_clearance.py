"""Operating clearance of a mounted bearing: the diametral clearance left after the interference
fits, the temperatures of the parts and the centrifugal growth of the rotating rings.

Fits (Lamé, thick-walled cylinders in plane stress; Timoshenko & Goodier, Theory of Elasticity,
3rd ed. 1970, §28; Shigley's Mechanical Engineering Design, 10th ed., eqs. 3-56 and 3-57): an
inner body (the shaft, or the outer ring) pressed into an outer body (the inner ring, or the
housing) with a diametral interference I at the nominal diameter d carries the fit pressure

    p = I / (d [ (1/E_o)((D_o² + d²)/(D_o² − d²) + ν_o) + (1/E_i)((d² + d_i²)/(d² − d_i²) − ν_i) ]),

d_i the inner body's bore, D_o the outer body's outer diameter. An annulus (d₁, d₂) loaded by p on
its inner surface grows on its outer one by 2p d₁² d₂ / (E (d₂² − d₁²)) (diametral); loaded on its
outer surface, it shrinks on its inner one by 2p d₂² d₁ / (E (d₂² − d₁²)). The inner ring is the
annulus from its bore to its raceway diameter, the outer ring the one from its raceway to its
outside diameter (Harris & Kotzalas, Essential Concepts of Bearing Technology, 5th ed. 2007,
§8.2). The effective interference is the measured one less the smoothing of both surfaces,
0.8 (Rz₁ + Rz₂) diametral (DIN 7190-1:2017, §6.2).

Temperatures (linear expansion from the reference temperature): the raceway diameters grow with
their rings, each rolling element with the mean of the two rings' temperatures (Harris &
Kotzalas §8.3 take the rolling elements at the ring temperatures' mean), and the interferences
change with the shaft's, housing's and rings' growth at the fit diameters.

Speed: a ring spinning at ω as a free annulus (d₁, d₂) of density ρ grows on its outer surface by
d₂ ρω² [(3 + ν)(d₁/2)² + (1 − ν)(d₂/2)²] / (4E) and on its inner one by
d₁ ρω² [(3 + ν)(d₂/2)² + (1 − ν)(d₁/2)²] / (4E) (Timoshenko & Goodier §32, rotating disk with a
hole); the fit's loss of pressure with speed is not modelled.

The clearance change is the sum of the contributions: positive opens the bearing.
"""

import equinox as eqx
import jax.numpy as jnp

from ..params import Material, check_range

# Shaft and housing materials: (elastic constants, linear expansion [1/K]); E and ν from Shigley's
# Mechanical Engineering Design, 10th ed., Table A-5 (carbon steel, grey cast iron, aluminium
# alloys), expansion coefficients typical of those materials at room temperature.
SEAT_MATERIALS = {
    "steel": (Material(207e9, 0.292, 7850.0, name="steel"), 11.7e-6),
    "cast_iron": (Material(100e9, 0.211, 7200.0, name="cast_iron"), 10.8e-6),
    "aluminium": (Material(71.7e9, 0.333, 2800.0, name="aluminium"), 23.4e-6),
}
RING_EXPANSION = 11.5e-6  # 1/K, through-hardened bearing steel (AISI 52100) near room temperature


def fit_pressure(interference, diameter, inner_bore, outer_diameter, inner: Material, outer: Material):
    """Fit pressure p [Pa] of an inner body (bore `inner_bore` [m], 0 for a solid shaft) pressed
    into an outer body (outside `outer_diameter` [m], None for an unbounded one) with the
    diametral interference `interference` [m] at `diameter` [m] (module docstring; Shigley eq. 3-56);
    negative for a loose fit (then no pressure acts: see `contact_pressure`)."""
    outer_ratio = 0.0 if outer_diameter is None else diameter / outer_diameter
    outer_compliance = ((1.0 + outer_ratio**2) / (1.0 - outer_ratio**2) + outer.poisson_ratio) / outer.elastic_modulus
    inner_ratio = inner_bore / diameter
    inner_compliance = ((1.0 + inner_ratio**2) / (1.0 - inner_ratio**2) - inner.poisson_ratio) / inner.elastic_modulus
    return interference / (diameter * (outer_compliance + inner_compliance))


def contact_pressure(interference, diameter, inner_bore, outer_diameter, inner: Material, outer: Material):
    """`fit_pressure` where the fit is tight, 0 where it is loose (I ≤ 0) [Pa]."""
    return jnp.maximum(fit_pressure(interference, diameter, inner_bore, outer_diameter, inner, outer), 0.0)


def outer_surface_growth(pressure, inner_diameter, outer_diameter, material: Material):
    """Diametral growth [m] of an annulus's outer surface under the pressure [Pa] on its inner one
    (Lamé: 2p d₁² d₂ / (E (d₂² − d₁²)))."""
    return 2.0 * pressure * inner_diameter**2 * outer_diameter / (
        material.elastic_modulus * (outer_diameter**2 - inner_diameter**2))


def inner_surface_shrinkage(pressure, inner_diameter, outer_diameter, material: Material):
    """Diametral shrinkage [m] of an annulus's inner surface under the pressure [Pa] on its outer
    one (Lamé: 2p d₂² d₁ / (E (d₂² − d₁²)))."""
    return 2.0 * pressure * outer_diameter**2 * inner_diameter / (
        material.elastic_modulus * (outer_diameter**2 - inner_diameter**2))


def spin_growth(speed, inner_diameter, outer_diameter, material: Material):
    """(inner, outer) diametral growth [m] of a free annulus spinning at `speed` [rad/s]
    (Timoshenko & Goodier §32, plane stress)."""
    inner_radius, outer_radius = 0.5 * inner_diameter, 0.5 * outer_diameter
    nu, factor = material.poisson_ratio, material.density * speed**2 / (4.0 * material.elastic_modulus)
    inner = inner_diameter * factor * ((3.0 + nu) * outer_radius**2 + (1.0 - nu) * inner_radius**2)
    outer = outer_diameter * factor * ((3.0 + nu) * inner_radius**2 + (1.0 - nu) * outer_radius**2)
    return inner, outer


class Mounting(eqx.Module):
    """How a bearing sits on its shaft and in its housing [SI]: diametral interferences (negative
    for a loose fit), the shaft's bore (0: solid) and the housing's outer diameter (None: a large
    housing), the surface roughnesses Rz of the four fit surfaces, the temperatures of the inner
    and outer rings, shaft and housing against the reference temperature [K or °C, differences
    only], the linear expansion coefficients [1/K] and the materials of shaft and housing."""

    shaft_interference: jnp.ndarray = 0.0
    housing_interference: jnp.ndarray = 0.0
    shaft_bore: jnp.ndarray = 0.0
    housing_outer_diameter: jnp.ndarray | None = None
    roughness: jnp.ndarray = (0.0, 0.0, 0.0, 0.0)  # Rz of shaft, inner ring bore, outer ring outside, housing bore
    inner_ring_temperature: jnp.ndarray = 0.0
    outer_ring_temperature: jnp.ndarray = 0.0
    shaft_temperature: jnp.ndarray = 0.0
    housing_temperature: jnp.ndarray = 0.0
    reference_temperature: jnp.ndarray = 0.0
    ring_expansion: jnp.ndarray = RING_EXPANSION
    element_expansion: jnp.ndarray = RING_EXPANSION
    shaft_expansion: jnp.ndarray = RING_EXPANSION
    housing_expansion: jnp.ndarray = RING_EXPANSION
    shaft: Material | None = None  # None: the rings' material
    housing: Material | None = None

    def __check_init__(self):
        check_range("mounting.shaft_bore", self.shaft_bore, low=0.0, low_open=False, unit=" m")
        check_range("mounting.housing_outer_diameter", self.housing_outer_diameter, low=0.0, unit=" m")
        for index, name in enumerate(("shaft", "inner_ring", "outer_ring", "housing")):  # the scene's keys
            check_range(f"mounting.{name}_roughness", jnp.asarray(self.roughness)[index], low=0.0, low_open=False,
                        unit=" m")


class OperatingClearance(eqx.Module):
    """The contributions to the change of diametral clearance [m] (positive opens), the fit
    pressures [Pa] and the inner ring's hoop stress at its bore [Pa]."""

    shaft_fit: jnp.ndarray  # − growth of the inner raceway by the shaft fit
    housing_fit: jnp.ndarray  # − shrinkage of the outer raceway by the housing fit
    thermal: jnp.ndarray  # rings' and rolling elements' expansion
    centrifugal: jnp.ndarray  # spinning rings' growth
    fit_pressure_inner: jnp.ndarray
    fit_pressure_outer: jnp.ndarray
    hoop_stress_inner: jnp.ndarray
    shaft_interference: jnp.ndarray  # effective diametral interferences [m]: smoothed, at temperature
    housing_interference: jnp.ndarray
    # the inner ring's axial thermal strain over the outer ring's, α_r (ΔT_inner ring − ΔT_outer ring)
    # [-]: a matched pair's inner stack grows by it times its length against the outer
    # (`thermal.axial_growth.pair_growth`)
    axial_strain: jnp.ndarray = 0.0

    @property
    def change(self):
        return self.shaft_fit + self.housing_fit + self.thermal + self.centrifugal


def operating_clearance_change(mounting: Mounting, bore, inner_raceway, outer_raceway, outside, element_size,
                               ring: Material, inner_speed=0.0, outer_speed=0.0) -> OperatingClearance:
    """The change of diametral clearance [m] of a mounted bearing and its parts (module docstring).

    Args:
        mounting: fits and temperatures (`Mounting`).
        bore, outside: the bearing's bore d and outside diameter D [m].
        inner_raceway, outer_raceway: the raceway diameters [m] (groove bottoms of a ball bearing).
        element_size: the rolling element's diameter [m] (ball, or roller at mid-length).
        ring: the rings' material (its density for the centrifugal growth).
        inner_speed, outer_speed: ring speeds [rad/s].
    """
    shaft = ring if mounting.shaft is None else mounting.shaft
    housing = ring if mounting.housing is None else mounting.housing
    rise = {name: getattr(mounting, f"{name}_temperature") - mounting.reference_temperature
            for name in ("inner_ring", "outer_ring", "shaft", "housing")}
    element_rise = 0.5 * (rise["inner_ring"] + rise["outer_ring"])
    roughness = jnp.asarray(mounting.roughness)
    shaft_interference = (mounting.shaft_interference - 0.8 * (roughness[0] + roughness[1])
                          + bore * (mounting.shaft_expansion * rise["shaft"] - mounting.ring_expansion * rise["inner_ring"]))
    housing_interference = (mounting.housing_interference - 0.8 * (roughness[2] + roughness[3])
                            + outside * (mounting.ring_expansion * rise["outer_ring"]
                                         - mounting.housing_expansion * rise["housing"]))
    inner_pressure = contact_pressure(shaft_interference, bore, mounting.shaft_bore, inner_raceway, shaft, ring)
    outer_pressure = contact_pressure(housing_interference, outside, outer_raceway, mounting.housing_outer_diameter,
                                      ring, housing)
    thermal = (mounting.ring_expansion * (rise["outer_ring"] * outer_raceway - rise["inner_ring"] * inner_raceway)
               - 2.0 * mounting.element_expansion * element_rise * element_size)
    inner_growth = spin_growth(inner_speed, bore, inner_raceway, ring)[1]
    outer_growth = spin_growth(outer_speed, outer_raceway, outside, ring)[0]
    ratio = bore / inner_raceway
    return OperatingClearance(
        shaft_fit=-outer_surface_growth(inner_pressure, bore, inner_raceway, ring),
        housing_fit=-inner_surface_shrinkage(outer_pressure, outer_raceway, outside, ring),
        thermal=thermal,
        centrifugal=outer_growth - inner_growth,
        fit_pressure_inner=inner_pressure,
        fit_pressure_outer=outer_pressure,
        hoop_stress_inner=inner_pressure * (1.0 + ratio**2) / (1.0 - ratio**2),
        shaft_interference=shaft_interference,
        housing_interference=housing_interference,
        axial_strain=mounting.ring_expansion * (rise["inner_ring"] - rise["outer_ring"]),
    )


def mounted_clearance_change(support, mounting: Mounting, bore, outside, inner_speed=0.0,
                             outer_speed=0.0) -> OperatingClearance:
    """`operating_clearance_change` of a bearing on a shaft (an `AbstractSupport` whose type takes a
    mounting: its `ring_section`), of bore `bore` and outside diameter `outside` [m]."""
    rings = support.ring_section()
    return operating_clearance_change(mounting, bore, rings.inner_raceway_diameter, rings.outer_raceway_diameter,
                                      outside, rings.element_diameter, rings.material, inner_speed, outer_speed)
