"""Complete elliptic integrals K(m) and E(m) by the arithmetic–geometric mean (AGM).

Parameter convention: m = e² (the "parameter", as in scipy.special.ellipk and Matlab's ellipke);
Johnson (Contact Mechanics, §4.2) writes K(e), E(e) with the eccentricity e.

The AGM (Abramowitz & Stegun 17.6) with a₀ = 1, b₀ = √(1−m), c₀² = m gives
    K = π / (2 a_N),    K − E = K Σ_{n≥0} 2^{n−1} c_n².
It converges quadratically; `AGM_STEPS` fixed steps reach machine precision for m ≤ 1 − 1e-12,
so the function is a fixed-length loop (`fori_loop`) of smooth operations: jit-, vmap- and
autodiff-friendly in forward and reverse mode, also at m = 0 and for m < 0 (analytic there).

Hertz contact needs (K − E)/m, which tends to π/4 as m → 0: `elliptic_integrals_and_difference`
computes it without dividing by m (the c_n² terms are carried as c_n²/m), so the circular limit
κ → 1 of the ellipticity equation has no 0/0.
"""

import jax
import jax.numpy as jnp

AGM_STEPS = 8


def elliptic_integrals_and_difference(m):
    """Return (K(m), E(m), (K(m) − E(m))/m) for m < 1, elementwise; all dimensionless.

    Source: A&S 17.6.1–17.6.4 (AGM scale); c₁ = m / (2(1 + b₀)) and c_{n+1} = c_n² / (4 a_{n+1})
    keep every term free of cancellation.
    """
    m = jnp.asarray(m)
    a = jnp.ones_like(m)
    b = jnp.sqrt(1.0 - m)
    # s_n = c_n² / m; s_0 = 1, s_1 = m / (4 (1 + b0)²)
    a_next = 0.5 * (a + b)
    s = m / (4.0 * (1.0 + b) ** 2)
    c_squared = m * s
    weighted_sum = 0.5 + s  # Σ 2^{n−1} s_n for n = 0, 1
    b = jnp.sqrt(a * b)
    a = a_next

    def step(_, carry):
        a, b, s, c_squared, weight, weighted_sum = carry
        a_next = 0.5 * (a + b)
        # c_{n+1}² = c_n⁴ / (16 a_{n+1}²)
        ratio = c_squared / (16.0 * a_next**2)
        weight = 2.0 * weight
        weighted_sum = weighted_sum + weight * s * ratio
        return a_next, jnp.sqrt(a * b), s * ratio, c_squared * ratio, weight, weighted_sum

    carry = (a, b, s, c_squared, jnp.ones_like(m), weighted_sum)
    a, _, _, _, _, weighted_sum = jax.lax.fori_loop(0, AGM_STEPS, step, carry)
    elliptic_k = jnp.pi / (2.0 * a)
    difference_over_m = elliptic_k * weighted_sum
    elliptic_e = elliptic_k - m * difference_over_m
    return elliptic_k, elliptic_e, difference_over_m


def complete_elliptic_integrals(m):
    """Complete elliptic integrals of the first and second kind, (K(m), E(m)), dimensionless."""
    elliptic_k, elliptic_e, _ = elliptic_integrals_and_difference(m)
    return elliptic_k, elliptic_e
