"""Hertz contact: elliptical point contact (exact and approximate) and line contact.

Notation (docs/theory.md, §Hertz point contact; Hamrock, Schmid & Jacobson, *Fundamentals of
Machine Elements*, ch. 8; Harris & Kotzalas, *Rolling Bearing Analysis* 5th ed., vol. 1, ch. 6):

* curvature sum Σρ [1/m] and curvature difference F(ρ) ∈ [0, 1) [-]; effective radius R = 1/Σρ;
  the principal radius ratio is R_y/R_x = (1 + F)/(1 − F).
* effective modulus E' = 2 / ((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂) [Pa]  (`effective_modulus`).
* ellipticity κ = a/b, with 𝓚, 𝓔 the complete elliptic integrals of parameter m = 1 − 1/κ²,
  solves (Johnson, Contact Mechanics, eq. 4.39 rearranged)
      F(ρ) = ((κ² + 1) 𝓔 − 2 𝓚) / ((κ² − 1) 𝓔) = 1 − 2 (1 − m) ((𝓚 − 𝓔)/m) / 𝓔.
  The right-hand form has no 0/0 at κ = 1 (see elliptic.py).
* then, for a normal load Q [N] (Hamrock & Brewe 1983; Harris & Kotzalas vol. 1, ch. 6):
      a = (6 κ² 𝓔 Q R / (π E'))^{1/3},   b = (6 𝓔 Q R / (π κ E'))^{1/3},
      δ = 𝓚 (9/(2 𝓔 R) · (Q/(π κ E'))²)^{1/3},   p₀ = 3Q / (2π a b),
      Q = K_c δ^{3/2} with K_c = π κ E' √(2 𝓔 R / (9 𝓚³)).

Fidelity levels (`method`): "exact" solves the ellipticity equation (Newton in ln κ from the
Hamrock–Brewe start, derivative by the implicit function theorem) and evaluates 𝓚, 𝓔 by the AGM;
"brewe_hamrock" uses the curve fits of Brewe & Hamrock (1977)
      κ ≈ 1.0339 (R_y/R_x)^0.6360, 𝓔 ≈ 1.0003 + 0.5968 R_x/R_y, 𝓚 ≈ 1.5277 + 0.6023 ln(R_y/R_x);
"hamrock_brewe" the simpler forms of Hamrock & Brewe (1983)
      κ ≈ (R_y/R_x)^{2/π}, 𝓔 ≈ 1 + (π/2 − 1) R_x/R_y, 𝓚 ≈ π/2 + (π/2 − 1) ln(R_y/R_x).
Their errors against the exact solution are measured in tests/test_hertz.py and
benchmarks/hertz_fidelity.py.

All functions are pure and elementwise (broadcast, vmap and jit freely) and differentiable in
forward and reverse mode everywhere on F ∈ [0, 1), including κ = 1 exactly.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..numerics import positive_power, require_float64
from .elliptic import elliptic_integrals_and_difference

POINT_CONTACT_METHODS = ("exact", "brewe_hamrock", "hamrock_brewe")

# Newton steps on ln κ from the Hamrock–Brewe start: the start is within a few % and Newton
# converges quadratically, so 6 steps reach machine precision on 0 ≤ F ≤ 0.9999 (κ ≤ 350, tested).
_ELLIPTICITY_NEWTON_STEPS = 6


def effective_modulus(modulus_1, poisson_1, modulus_2, poisson_2):
    """Effective elastic modulus E' = 2/((1−ν₁²)/E₁ + (1−ν₂²)/E₂) [Pa] (E' = 2E* of Johnson, Contact Mechanics, §4.2)."""
    return 2.0 / ((1.0 - poisson_1**2) / modulus_1 + (1.0 - poisson_2**2) / modulus_2)


def _curvature_difference_of_log_ellipticity(log_ellipticity):
    """F(ρ) [-] as a function of u = ln κ; smooth and odd in u (analytic at u = 0)."""
    m = -jnp.expm1(-2.0 * log_ellipticity)  # m = 1 − 1/κ²
    _, elliptic_e, difference_over_m = elliptic_integrals_and_difference(m)
    return 1.0 - 2.0 * (1.0 - m) * difference_over_m / elliptic_e


def curvature_difference_of_ellipticity(ellipticity):
    """Curvature difference F(ρ) [-] for which a Hertz contact has ellipticity κ = a/b [-]."""
    return _curvature_difference_of_log_ellipticity(jnp.log(ellipticity))


@jax.custom_jvp
def ellipticity(curvature_difference):
    """Exact ellipticity κ = a/b [-] of a Hertz point contact with curvature difference F(ρ) [-].

    Solves F(ρ) = ((κ²+1)𝓔 − 2𝓚)/((κ²−1)𝓔) (Johnson eq. 4.39) by Newton on u = ln κ from the
    Hamrock–Brewe start u₀ = (2/π) ln((1+F)/(1−F)); the derivative comes from the implicit
    function theorem, dκ/dF = 1 / (dF/dκ), in forward and reverse mode.
    """
    def newton_step(_, log_ellipticity):
        value, slope = jax.jvp(
            _curvature_difference_of_log_ellipticity,
            (log_ellipticity,),
            (jnp.ones_like(log_ellipticity),),
        )
        return log_ellipticity - (value - curvature_difference) / slope

    start = (4.0 / jnp.pi) * jnp.arctanh(curvature_difference)
    log_ellipticity = jax.lax.fori_loop(0, _ELLIPTICITY_NEWTON_STEPS, newton_step, start)
    return jnp.exp(log_ellipticity)


@ellipticity.defjvp
def _ellipticity_jvp(primals, tangents):
    (curvature_difference,) = primals
    (curvature_difference_dot,) = tangents
    kappa = ellipticity(curvature_difference)
    _, slope = jax.jvp(curvature_difference_of_ellipticity, (kappa,), (jnp.ones_like(kappa),))
    return kappa, curvature_difference_dot / slope


def ellipticity_and_integrals(curvature_difference, method="exact"):
    """(κ, 𝓚, 𝓔) [-] of a point contact by the chosen fidelity level (see module docstring)."""
    if method == "exact":
        kappa = ellipticity(curvature_difference)
        m = -jnp.expm1(-2.0 * jnp.log(kappa))
        elliptic_k, elliptic_e, _ = elliptic_integrals_and_difference(m)
        return kappa, elliptic_k, elliptic_e
    radius_ratio = (1.0 + curvature_difference) / (1.0 - curvature_difference)  # R_y / R_x
    if method == "brewe_hamrock":
        # Brewe & Hamrock (1977), J. Lubr. Technol. 99(4):485–487, curve fits.
        kappa = 1.0339 * radius_ratio**0.6360
        elliptic_e = 1.0003 + 0.5968 / radius_ratio
        elliptic_k = 1.5277 + 0.6023 * jnp.log(radius_ratio)
        return kappa, elliptic_k, elliptic_e
    if method == "hamrock_brewe":
        # Hamrock & Brewe (1983), J. Lubr. Technol. 105(2):171–177.
        kappa = radius_ratio ** (2.0 / jnp.pi)
        elliptic_e = 1.0 + (jnp.pi / 2.0 - 1.0) / radius_ratio
        elliptic_k = jnp.pi / 2.0 + (jnp.pi / 2.0 - 1.0) * jnp.log(radius_ratio)
        return kappa, elliptic_k, elliptic_e
    raise ValueError(f"method must be one of {POINT_CONTACT_METHODS}, got {method!r}")


class PointContact(eqx.Module):
    """Result of a Hertz point-contact calculation (SI units)."""

    semi_major_axis: jax.Array  # a [m], transverse to rolling for a ball in a groove
    semi_minor_axis: jax.Array  # b [m], along the rolling direction
    approach: jax.Array  # δ [m], mutual approach of distant points of the two bodies
    max_pressure: jax.Array  # p₀ [Pa]
    ellipticity: jax.Array  # κ = a/b [-]
    load_deflection_constant: jax.Array  # K_c [N/m^1.5] in Q = K_c δ^1.5


def load_deflection_constant(curvature_sum, curvature_difference, effective_modulus, method="exact"):
    """Hertz load–deflection constant K_c [N/m^1.5] in Q = K_c δ^{3/2}.

    K_c = π κ E' √(2 𝓔 R / (9 𝓚³)), R = 1/Σρ (from δ and Q above; Harris & Kotzalas vol. 1, ch. 6).
    Arguments: Σρ [1/m], F(ρ) [-], E' [Pa]; `method` as in `ellipticity_and_integrals`.
    """
    kappa, elliptic_k, elliptic_e = ellipticity_and_integrals(curvature_difference, method)
    radius = 1.0 / curvature_sum
    return jnp.pi * kappa * effective_modulus * jnp.sqrt(2.0 * elliptic_e * radius / (9.0 * elliptic_k**3))


def point_contact(load, curvature_sum, curvature_difference, effective_modulus, method="exact"):
    """Hertz elliptical point contact under a normal load.

    Args:
        load: normal load Q [N], ≥ 0 (Q = 0 gives exact zeros and finite gradients).
        curvature_sum: Σρ [1/m], > 0.
        curvature_difference: F(ρ) [-], in [0, 1).
        effective_modulus: E' [Pa] (see `effective_modulus`).
        method: "exact" | "brewe_hamrock" | "hamrock_brewe" (static).

    Returns:
        PointContact with a, b [m], δ [m], p₀ [Pa], κ [-], K_c [N/m^1.5]
        (equations in the module docstring).
    """
    require_float64()
    kappa, elliptic_k, elliptic_e = ellipticity_and_integrals(curvature_difference, method)
    radius = 1.0 / curvature_sum
    load_cube_root = positive_power(load, 1.0 / 3.0)
    scale = (6.0 * elliptic_e * radius / (jnp.pi * effective_modulus)) ** (1.0 / 3.0)
    semi_major = scale * kappa ** (2.0 / 3.0) * load_cube_root
    semi_minor = scale * kappa ** (-1.0 / 3.0) * load_cube_root
    approach = elliptic_k * (
        9.0 / (2.0 * elliptic_e * radius) / (jnp.pi * kappa * effective_modulus) ** 2
    ) ** (1.0 / 3.0) * load_cube_root**2
    # p₀ = 3Q/(2πab) = (3/(2π)) Q^{1/3} / (scale² κ^{1/3})
    max_pressure = 3.0 / (2.0 * jnp.pi) * load_cube_root / (scale**2 * kappa ** (1.0 / 3.0))
    constant = jnp.pi * kappa * effective_modulus * jnp.sqrt(2.0 * elliptic_e * radius / (9.0 * elliptic_k**3))
    return PointContact(semi_major, semi_minor, approach, max_pressure, kappa, constant)


def combined_load_deflection_constant(constant_inner, constant_outer):
    """K_n [N/m^1.5] of two Hertz contacts in series (ball between two raceways), Q = K_n δ_total^{3/2}:
    K_n = (K_i^{-2/3} + K_o^{-2/3})^{-3/2} (Harris & Kotzalas vol. 1, ch. 7)."""
    return (constant_inner ** (-2.0 / 3.0) + constant_outer ** (-2.0 / 3.0)) ** -1.5


def hertz_load(approach, constant):
    """Hertz contact load Q = K_c max(δ, 0)^{3/2} [N] from the approach δ [m] and K_c [N/m^1.5].

    Exact zero and zero gradient for δ ≤ 0 (contact open), so solvers see no NaN.
    """
    return constant * positive_power(approach, 1.5)


class LineContact(eqx.Module):
    """Result of a Hertz line-contact calculation (SI units)."""

    half_width: jax.Array  # b [m], along the rolling direction
    max_pressure: jax.Array  # p₀ [Pa]


def line_contact(load_per_length, radius, effective_modulus):
    """Hertz line contact of two cylinders (plane strain).

    b = √(8 w R / (π E')),  p₀ = √(w E' / (2π R))  (Johnson, Contact Mechanics, eq. 4.43, with E* = E'/2).

    Args:
        load_per_length: w [N/m], ≥ 0.
        radius: effective radius R [m] (1/R = 1/R₁ ± 1/R₂ along rolling), > 0.
        effective_modulus: E' [Pa].
    """
    require_float64()
    half_width = jnp.sqrt(8.0 / jnp.pi) * positive_power(load_per_length * radius / effective_modulus, 0.5)
    max_pressure = positive_power(load_per_length * effective_modulus / (2.0 * jnp.pi * radius), 0.5)
    return LineContact(half_width, max_pressure)


def line_contact_approach_palmgren(load, length):
    """Approach δ [m] of a steel roller line contact, Palmgren's δ = 3.84e-5 Q^0.9 / l^0.8.

    Palmgren's empirical formula (Harris & Kotzalas vol. 1, ch. 6) in mm and N for steel on steel
    (E ≈ 207 GPa, ν = 0.3); valid for steel only. Args: Q [N] ≥ 0, effective length l [m].
    """
    return 3.84e-5 * positive_power(load, 0.9) / (length * 1e3) ** 0.8 * 1e-3
