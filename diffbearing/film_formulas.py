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
* Film parameter Λ = h_min / √(σ₁² + σ₂²) (σ the RMS roughness of each surface).

Loads of zero give no film: the formulas are not defined there, and the caller masks them.
"""

import jax.numpy as jnp

from .numerics import positive_power


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
