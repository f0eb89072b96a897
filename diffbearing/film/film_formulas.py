"""Elastohydrodynamic film thickness by closed-form regression formulas (fidelity "formula").

Isothermal, Newtonian, fully flooded, smooth surfaces, pure rolling; u is the mean entrainment
speed (u₁ + u₂)/2, η₀ the viscosity at inlet temperature, α the pressure–viscosity coefficient,
E' = 2/((1−ν₁²)/E₁ + (1−ν₂²)/E₂) and R (Rx) the reduced radius in the rolling direction.
Dimensionless groups (Hamrock, Schmid & Jacobson, Fundamentals of Machine Elements, ch. 8 and
Fundamentals of Fluid Film Lubrication, chs. 21–22):

    U = η₀ u / (E' Rx),   G = α E',   W = Q / (E' Rx²) (point),   W' = w / (E' R) (line).

* Point contact (Hamrock & Dowson 1977, ASME J. Lubr. Technol. 99, 264):
  H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73 k}),
  H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^{−0.68 k}),  h = H·Rx, k = a/b the ellipticity
  (here the exact Hertz κ; the fit used k = 1.03 (Ry/Rx)^0.64, within a few % of it).
* Line contact (Pan & Hamrock 1989, ASME J. Tribol. 111, 246):
  H_c = 2.922 W'^−0.166 U^0.692 G^0.470,  H_min = 1.714 W'^−0.128 U^0.694 G^0.568,  h = H·R.
* Line contact minimum film (Dowson & Higginson 1977 form): H_min = 2.65 U^0.70 G^0.54 W'^−0.13.
* Line contact central film (Moes 1992, as in Venner & Lubrecht, Multilevel Methods in
  Lubrication, 2000, §8.6), in Moes' groups M = W'(2U)^−½, L = G(2U)^¼, H = (h/R)(2U)^−½:
  H_c = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s},
  H_RI = 3M^−1, H_EI = 1.621M^−1/5, H_RP = 1.287L^2/3, H_EP = 1.311M^−1/8 L^3/4,
  s = (7 + 8 e^{−2 H_EI/H_RI})/5: all four asymptotes (rigid/elastic, isoviscous/piezoviscous),
  fitted to incompressible Barus solutions.
* Starved film from an inlet oil layer (Chevalier, Lubrecht, Cann, Colin & Dalmaz 1998,
  ASME J. Tribol. 120, 126): h/h_ff = r/(1 + r^γ)^{1/γ}, r = h_oil/(ρ̄ h_ff) the supply over what
  the flooded contact passes (ρ̄ the density ratio in the Hertz zone); γ sets how sharp the
  transition is (large for line contacts, which have no side flow).
* Film parameter Λ = h_min / √(σ₁² + σ₂²) (σ the RMS roughness of each surface).

Loads of zero give no film: the formulas are not defined there, and the caller masks them.
"""

import jax.numpy as jnp

from ..numerics import positive_power


def _groups(speed, viscosity, pressure_viscosity, effective_modulus, radius):
    """(U, G) of the formulas [-]."""
    return viscosity * speed / (effective_modulus * radius), pressure_viscosity * effective_modulus


def hamrock_dowson_point(load, radius_rolling, ellipticity, speed, viscosity, pressure_viscosity, effective_modulus):
    """(central, minimum) film thickness [m] of an elliptical point contact (Hamrock & Dowson 1977).

    Args: load Q [N] > 0; Rx [m] in the rolling direction; k = a/b [-] (a across rolling);
    mean entrainment speed u [m/s] ≥ 0; η₀ [Pa·s]; α [1/Pa]; E' [Pa].
    """
    speed_group, material_group = _groups(speed, viscosity, pressure_viscosity, effective_modulus, radius_rolling)
    load_group = load / (effective_modulus * radius_rolling**2)
    central = (2.69 * positive_power(speed_group, 0.67) * material_group**0.53 * load_group**-0.067
               * (1.0 - 0.61 * jnp.exp(-0.73 * ellipticity)))
    minimum = (3.63 * positive_power(speed_group, 0.68) * material_group**0.49 * load_group**-0.073
               * (1.0 - jnp.exp(-0.68 * ellipticity)))
    return central * radius_rolling, minimum * radius_rolling


def pan_hamrock_line(load_per_length, radius, speed, viscosity, pressure_viscosity, effective_modulus):
    """(central, minimum) film thickness [m] of a line contact (Pan & Hamrock 1989).

    Args: w [N/m] > 0; R [m]; u [m/s] ≥ 0; η₀ [Pa·s]; α [1/Pa]; E' [Pa].
    """
    speed_group, material_group = _groups(speed, viscosity, pressure_viscosity, effective_modulus, radius)
    load_group = load_per_length / (effective_modulus * radius)
    central = 2.922 * load_group**-0.166 * positive_power(speed_group, 0.692) * material_group**0.470
    minimum = 1.714 * load_group**-0.128 * positive_power(speed_group, 0.694) * material_group**0.568
    return central * radius, minimum * radius


def dowson_higginson_line_minimum(load_per_length, radius, speed, viscosity, pressure_viscosity, effective_modulus):
    """Minimum film thickness [m] of a line contact, Dowson & Higginson: 2.65 U^0.70 G^0.54 W'^−0.13 · R."""
    speed_group, material_group = _groups(speed, viscosity, pressure_viscosity, effective_modulus, radius)
    load_group = load_per_length / (effective_modulus * radius)
    return 2.65 * positive_power(speed_group, 0.70) * material_group**0.54 * load_group**-0.13 * radius


def film_parameter(minimum_film, roughness):
    """Λ = h_min / σ [-] with σ the composite RMS roughness √(σ₁² + σ₂²) [m]."""
    return minimum_film / roughness


def moes_line_central(load_per_length, radius, speed, viscosity, pressure_viscosity, effective_modulus):
    """Central film thickness [m] of a line contact, Moes (1992) four-asymptote formula.

    Args: w [N/m] > 0; R [m]; u [m/s] > 0 (mean entrainment speed); η₀ [Pa·s]; α [1/Pa]; E' [Pa].
    """
    speed_group, material_group = _groups(speed, viscosity, pressure_viscosity, effective_modulus, radius)
    root = jnp.sqrt(2.0 * speed_group)
    load = load_per_length / (effective_modulus * radius) / root  # M
    material = material_group * jnp.sqrt(root)  # L
    rigid_isoviscous = 3.0 / load
    elastic_isoviscous = 1.621 * load**-0.2
    rigid_piezoviscous = 1.287 * material ** (2.0 / 3.0)
    elastic_piezoviscous = 1.311 * load**-0.125 * material**0.75
    exponent = (7.0 + 8.0 * jnp.exp(-2.0 * elastic_isoviscous / rigid_isoviscous)) / 5.0
    isoviscous = (rigid_isoviscous ** (7.0 / 3.0) + elastic_isoviscous ** (7.0 / 3.0)) ** (3.0 * exponent / 7.0)
    piezoviscous = (rigid_piezoviscous**-3.5 + elastic_piezoviscous**-3.5) ** (-2.0 * exponent / 7.0)
    return (isoviscous + piezoviscous) ** (1.0 / exponent) * radius * root


def starved_film(flooded_film, oil_layer, density_ratio=1.0, sharpness=2.5):
    """Starved film [m] from the flooded one [m] and the inlet oil layer h_oil [m] (Chevalier 1998):
    h = h_ff · r/(1 + r^γ)^{1/γ}, r = h_oil/(ρ̄ h_ff); ρ̄ [-] the density ratio in the Hertz zone,
    γ = `sharpness` [-] (Chevalier's point contacts ≈ 2.5; see `benchmarks/line_ehl.py` for line contacts).
    """
    supply = oil_layer / (density_ratio * flooded_film)
    return flooded_film * supply / (1.0 + supply**sharpness) ** (1.0 / sharpness)
