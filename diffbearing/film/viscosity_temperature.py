"""Kinematic viscosity of a mineral oil against temperature: the Ubbelohde–Walther line of ASTM
D341 through the viscosities at 40 °C and 100 °C.

    log₁₀ log₁₀(ν + 0.7) = A − B log₁₀ T,    ν in mm²/s, T in K

(ASTM D341's simplified form, exact to well below 1 % above ν ≈ 2 mm²/s; the form the catalogues'
viscosity–temperature charts are drawn on).
"""

import jax.numpy as jnp

WALTHER_SHIFT = 0.7  # mm²/s
REFERENCE_TEMPERATURES = (313.15, 373.15)  # K: 40 °C and 100 °C


def _loglog(viscosity_mm2):
    return jnp.log10(jnp.log10(viscosity_mm2 + WALTHER_SHIFT))


def walther_viscosity(viscosity_40, viscosity_100, temperature):
    """Kinematic viscosity ν [m²/s] at `temperature` [K] on the Walther line through ν₄₀ and ν₁₀₀ [m²/s]."""
    low, high = (jnp.log10(t) for t in REFERENCE_TEMPERATURES)
    at_40, at_100 = _loglog(viscosity_40 * 1e6), _loglog(viscosity_100 * 1e6)
    slope = (at_40 - at_100) / (high - low)
    value = at_40 - slope * (jnp.log10(temperature) - low)
    return (10.0 ** (10.0**value) - WALTHER_SHIFT) * 1e-6
