"""Operating clearance from fits, temperatures and speed against the elasticity it comes from:
the compound cylinder and the spinning annulus solved here from u = A r + B/r (+ the body-force
term) and their boundary conditions, independently of the closed forms the module uses; and
against SKF's worked example of a pump bearing's operating clearance."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.params import BEARING_STEEL, Material
from diffbearing.systems import bearing_fits
from diffbearing.systems.operating_clearance import (
    Mounting,
    fit_pressure,
    inner_surface_shrinkage,
    operating_clearance_change,
    outer_surface_growth,
    spin_growth,
)

from .helpers import assert_jvp_matches_central_difference

jax.config.update("jax_enable_x64", True)

CAST_IRON = Material(110e9, 0.27, 7200.0, name="cast_iron")
ALUMINIUM = Material(70e9, 0.33, 2700.0, name="aluminium")


def _radial_stress(material, a, b, r):
    """σ_r of u = A r + B/r in plane stress, as coefficients of (A, B)."""
    factor = material.elastic_modulus / (1.0 - material.poisson_ratio**2)
    return np.array([factor * (1.0 + material.poisson_ratio), -factor * (1.0 - material.poisson_ratio) / r**2])


def _compound_cylinder(interference, bore, diameter, outside, inner, outer):
    """(fit pressure, diametral growth of the outer body's outside, diametral shrinkage of the
    inner body's bore): u = A r + B/r in each body, σ_r = 0 on the free surfaces, σ_r continuous
    and u_outer − u_inner = I/2 at the fit radius."""
    r_in, r_fit, r_out = 0.5 * bore, 0.5 * diameter, 0.5 * outside
    rows, rhs = [], []
    if bore > 0:
        rows.append(np.concatenate([_radial_stress(inner, 0, 0, r_in), [0, 0]]))
    else:  # solid: B = 0
        rows.append([0.0, 1.0, 0.0, 0.0])
    rhs.append(0.0)
    rows.append(np.concatenate([_radial_stress(inner, 0, 0, r_fit), -_radial_stress(outer, 0, 0, r_fit)]))
    rhs.append(0.0)
    rows.append([-r_fit, -1.0 / r_fit, r_fit, 1.0 / r_fit])
    rhs.append(0.5 * interference)
    rows.append(np.concatenate([[0, 0], _radial_stress(outer, 0, 0, r_out)]))
    rhs.append(0.0)
    a_in, b_in, a_out, b_out = np.linalg.solve(np.array(rows, dtype=float), np.array(rhs))
    pressure = -_radial_stress(outer, 0, 0, r_fit) @ [a_out, b_out]
    growth = 2.0 * (a_out * r_out + b_out / r_out)
    shrinkage = -2.0 * (a_in * r_in + b_in / r_in) if bore > 0 else 0.0
    return pressure, growth, shrinkage


def test_fit_pressure_and_ring_growth_are_the_compound_cylinders():
    """Inner ring (52100) on a hollow aluminium shaft: fit pressure and raceway growth equal the
    compound cylinder's to 1e-10 (relative)."""
    interference, shaft_bore, bore, raceway = 20e-6, 25e-3, 50e-3, 62e-3
    pressure = fit_pressure(interference, bore, shaft_bore, raceway, ALUMINIUM, BEARING_STEEL)
    growth = outer_surface_growth(pressure, bore, raceway, BEARING_STEEL)
    want_pressure, want_growth, _ = _compound_cylinder(interference, shaft_bore, bore, raceway, ALUMINIUM, BEARING_STEEL)
    np.testing.assert_allclose(pressure, want_pressure, rtol=1e-10)
    np.testing.assert_allclose(growth, want_growth, rtol=1e-10)
    solid = fit_pressure(interference, bore, 0.0, raceway, BEARING_STEEL, BEARING_STEEL)
    np.testing.assert_allclose(solid, _compound_cylinder(interference, 0.0, bore, raceway, BEARING_STEEL,
                                                         BEARING_STEEL)[0], rtol=1e-10)


def test_outer_ring_shrinkage_is_the_compound_cylinders():
    """Outer ring (52100, raceway 98 mm, outside 110 mm) in a cast-iron housing of 160 mm: fit
    pressure and raceway shrinkage equal the compound cylinder's to 1e-10 (relative)."""
    interference, raceway, outside, housing = 15e-6, 98e-3, 110e-3, 160e-3
    pressure = fit_pressure(interference, outside, raceway, housing, BEARING_STEEL, CAST_IRON)
    shrinkage = inner_surface_shrinkage(pressure, raceway, outside, BEARING_STEEL)
    want_pressure, _, want_shrinkage = _compound_cylinder(interference, raceway, outside, housing, BEARING_STEEL,
                                                          CAST_IRON)
    np.testing.assert_allclose(pressure, want_pressure, rtol=1e-10)
    np.testing.assert_allclose(shrinkage, want_shrinkage, rtol=1e-10)


def test_same_material_ring_growth_is_harris_closed_form():
    """One material for shaft and ring: ΔD_i = I (d/D_i)(1 − (d_s/d)²)/(1 − (d_s/D_i)²)
    (Harris & Kotzalas, 5th ed. vol. 1, eq. 8.9 form), to 1e-12."""
    interference, shaft_bore, bore, raceway = 30e-6, 30e-3, 60e-3, 75e-3
    pressure = fit_pressure(interference, bore, shaft_bore, raceway, BEARING_STEEL, BEARING_STEEL)
    growth = outer_surface_growth(pressure, bore, raceway, BEARING_STEEL)
    closed = interference * (bore / raceway) * (1 - (shaft_bore / bore) ** 2) / (1 - (shaft_bore / raceway) ** 2)
    np.testing.assert_allclose(growth, closed, rtol=1e-12)


def test_spin_growth_is_the_spinning_annulus():
    """u = A r + B/r − (1 − ν²) ρ ω² r³ / (8E) with σ_r = 0 on both surfaces (plane stress):
    the inner and outer diametral growth at 10 000 rad/s to 1e-10."""
    material, speed, d_in, d_out = BEARING_STEEL, 1e4, 50e-3, 62e-3
    e, nu, rho = material.elastic_modulus, material.poisson_ratio, material.density
    particular = -(1 - nu**2) * rho * speed**2 / (8 * e)  # u_p = c r³, σ_r,p = E/(1−ν²)(3 + ν) c r²
    rows = [_radial_stress(material, 0, 0, 0.5 * d) for d in (d_in, d_out)]
    rhs = [-e / (1 - nu**2) * (3 + nu) * particular * (0.5 * d) ** 2 for d in (d_in, d_out)]
    a, b = np.linalg.solve(np.array(rows), np.array(rhs))
    want = [2 * (a * r + b / r + particular * r**3) for r in (0.5 * d_in, 0.5 * d_out)]
    np.testing.assert_allclose(spin_growth(speed, d_in, d_out, material), want, rtol=1e-10)


def test_uniform_temperature_scales_the_clearance():
    """Rings, elements, shaft and housing 40 K above the reference with one coefficient: the
    interferences are unchanged and the clearance D_o − D_i − 2D_w grows by α ΔT of itself
    (identity to 1e-15 m)."""
    bore, inner, outer, outside, ball = 50e-3, 62e-3, 87.04e-3, 110e-3, 12.5e-3
    mounting = Mounting(shaft_interference=10e-6, inner_ring_temperature=60.0, outer_ring_temperature=60.0,
                        shaft_temperature=60.0, housing_temperature=60.0, reference_temperature=20.0)
    hot = operating_clearance_change(mounting, bore, inner, outer, outside, ball, BEARING_STEEL)
    cold = operating_clearance_change(Mounting(shaft_interference=10e-6), bore, inner, outer, outside, ball,
                                      BEARING_STEEL)
    np.testing.assert_allclose(hot.shaft_fit, cold.shaft_fit, rtol=1e-14)
    np.testing.assert_allclose(hot.thermal, 11.5e-6 * 40.0 * (outer - inner - 2 * ball), rtol=0, atol=1e-15)


def test_hot_inner_ring_closes_the_clearance():
    """An inner ring 10 K hotter than the outer ring, the rolling elements at the rings' mean: the
    clearance changes by α(0·D_o − ΔT D_i) − 2α(ΔT/2)D_w = −α ΔT (D_i + D_w), to 1e-12."""
    bore, inner, outer, outside, ball = 50e-3, 62e-3, 87.04e-3, 110e-3, 12.5e-3
    change = operating_clearance_change(Mounting(inner_ring_temperature=10.0), bore, inner, outer, outside, ball,
                                        BEARING_STEEL)
    np.testing.assert_allclose(change.change, -11.5e-6 * 10.0 * (inner + ball), rtol=1e-12)


def test_loose_fit_gives_no_pressure_and_smoothing_reduces_interference():
    """A loose shaft fit (−5 µm) leaves the clearance alone; 0.8 (Rz₁ + Rz₂) of smoothing makes a
    12 µm interference with Rz 2.5 µm on both surfaces act as 8 µm."""
    bore, inner, outer, outside, ball = 50e-3, 62e-3, 87.04e-3, 110e-3, 12.5e-3
    loose = operating_clearance_change(Mounting(shaft_interference=-5e-6), bore, inner, outer, outside, ball,
                                       BEARING_STEEL)
    assert float(loose.shaft_fit) == 0.0 and float(loose.fit_pressure_inner) == 0.0
    rough = operating_clearance_change(Mounting(shaft_interference=12e-6, roughness=(2.5e-6, 2.5e-6, 0.0, 0.0)), bore,
                                       inner, outer, outside, ball, BEARING_STEEL)
    smooth = operating_clearance_change(Mounting(shaft_interference=8e-6), bore, inner, outer, outside, ball,
                                        BEARING_STEEL)
    np.testing.assert_allclose(rough.shaft_fit, smooth.shaft_fit, rtol=1e-12)


def test_clearance_change_derivatives_match_central_differences():
    """d(clearance change, fit pressures)/d(interferences, temperature, speed) against central
    differences (forward and reverse mode)."""
    bore, inner, outer, outside, ball = 50e-3, 62e-3, 87.04e-3, 110e-3, 12.5e-3

    def change(x):
        mounting = Mounting(shaft_interference=x[0], housing_interference=x[1], inner_ring_temperature=x[2],
                            shaft_bore=20e-3, housing_outer_diameter=150e-3)
        result = operating_clearance_change(mounting, bore, inner, outer, outside, ball, BEARING_STEEL, inner_speed=x[3])
        return jnp.stack([result.change * 1e6, result.fit_pressure_inner * 1e-6, result.fit_pressure_outer * 1e-6])

    point = jnp.array([20e-6, 8e-6, 15.0, 900.0])
    for direction in (jnp.array([1e-6, 0, 0, 0]), jnp.array([0, 1e-6, 0, 0]), jnp.array([0, 0, 1.0, 0]),
                      jnp.array([0, 0, 0, 100.0])):
        assert_jvp_matches_central_difference(change, point, direction, 1e-3, rtol=1e-7, atol=1e-12)


@pytest.mark.parametrize("field, value, key", [("shaft_bore", -1e-3, "mounting.shaft_bore"),
                                               ("housing_outer_diameter", 0.0, "mounting.housing_outer_diameter"),
                                               ("roughness", (0.0, 0.0, -1e-6, 0.0), "mounting.outer_ring_roughness")])
def test_bad_mounting_is_refused(field, value, key):
    """ValueError naming the scene key (each roughness its own: shaft, inner_ring, outer_ring, housing)."""
    with pytest.raises(ValueError, match=f"^{key} must be"):
        Mounting(**{field: value})


# SKF, Rolling bearings, PUB BU/P1 17000/1 EN (2018), example C.3 "Centrifugal pump", the NU 311 ECP:
# d = 55 mm, D = 120 mm (F = 70.5 mm from the NU 311 ECP's product table and E = 106.5 mm from
# the N 311 ECP's, so D_w = 18 mm), solid steel shaft k6, thick housing K7, Normal clearance, the
# inner ring 10 °C hotter than the outer ring; SKF's Δr_temp = 0.012 ΔT d_m is α = 12e-6 1/K.
# Columns (min, avg, max) of the operating clearance, SKF's sign: negative interference, negative
# reduction. The interferences are the example's Δ₁, Δ₂; the reductions and clearances its results.
SKF_C3 = {"initial": (40.0, 55.0, 70.0), "shaft": (-32.0, -19.0, -6.0), "housing": (-20.0, 0.0, 20.0),
          "fit": (-42.0, -15.0, -5.0), "temperature": -11.0, "operating": (-13.0, 30.0, 55.0)}


def test_skf_centrifugal_pump_operating_clearance():
    """SKF's worked example C.3 (constants above): its probable (mean) k6 and K7 interferences are
    `bearing_fits`' 19 and 0 µm; diffbearing's operating clearance is within 2 % of its probable
    30 µm and within the printed 1 µm of its −13 and 55 µm; the fit reductions within 2 % (min and
    probable) or the printed digit (max: 6 µm × d/F), the thermal one within the printed digit
    (SKF takes d_m = (d + D)/2 = 87.5 mm, the rolling elements' pitch circle here is F + D_w = 88.5 mm)."""
    bore, outside, inner, outer = 55e-3, 120e-3, 70.5e-3, 106.5e-3
    assert bearing_fits.shaft_interference("k6", bore) * 1e6 == pytest.approx(-SKF_C3["shaft"][1], abs=1e-9)
    assert bearing_fits.housing_interference("K7", outside) * 1e6 == pytest.approx(-SKF_C3["housing"][1], abs=1e-9)
    operating = []
    for column, initial in enumerate(SKF_C3["initial"]):
        mounting = Mounting(shaft_interference=-SKF_C3["shaft"][column] * 1e-6,
                            housing_interference=-SKF_C3["housing"][column] * 1e-6,
                            inner_ring_temperature=10.0, shaft_temperature=10.0, ring_expansion=12e-6,
                            element_expansion=12e-6, shaft_expansion=12e-6, housing_expansion=12e-6)
        change = operating_clearance_change(mounting, bore, inner, outer, outside, 0.5 * (outer - inner), BEARING_STEEL)
        fit = float(change.shaft_fit + change.housing_fit) * 1e6
        operating.append(initial + float(change.change) * 1e6)
        assert fit == pytest.approx(SKF_C3["fit"][column], rel=0.02, abs=0.5 if column == 2 else 0.0)
        assert float(change.thermal) * 1e6 == pytest.approx(SKF_C3["temperature"], abs=0.5)
        assert float(change.centrifugal) == 0.0
    assert operating == pytest.approx(SKF_C3["operating"], abs=0.5)
    assert operating[1] == pytest.approx(SKF_C3["operating"][1], rel=0.02)  # the probable operating clearance
