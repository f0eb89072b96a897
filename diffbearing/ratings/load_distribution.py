"""Closed-form load distribution of a ball bearing: Sjövall integrals and Stribeck's estimate.

Rigid rings, one contact angle α for every ball, Hertz Q ∝ δ^{3/2} (Harris & Kotzalas vol. 1, §7.2;
docs/theory.md, §Load distribution; the cage paper):

    Q(ψ) = Q_max [1 − (1 − cos ψ)/(2ε)]^{3/2} on the loaded arc |ψ| ≤ ψ_l = arccos(1 − 2ε) (ε ≤ 1),
    J_r(ε) = (1/2π) ∫ [·]^{3/2} cos ψ dψ,   J_a(ε) = (1/2π) ∫ [·]^{3/2} dψ,
    F_r = Z Q_max J_r cos α,   F_a = Z Q_max J_a sin α,   J_r/J_a = F_r tan α / F_a.

The load zone spans 2ψ_l. Stribeck's rule Q_max ≈ 5 F_r/(Z cos α) covers a small clearance
(4.37 for none). Integrals by 200-point Gauss–Legendre on the loaded arc (error < 1e-9; the
integrand vanishes like (ψ_l − ψ)^{3/2} at the ends); everything is differentiable in ε.
"""

import jax
import jax.numpy as jnp
import numpy as np

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(200)


def sjovall_integrals(load_zone_parameter):
    """(J_r(ε), J_a(ε)) [-] for ε ∈ (0, ∞); for ε ≥ 1 every ball is loaded (ψ_l = π)."""
    epsilon = jnp.asarray(load_zone_parameter)
    half_zone = jnp.arccos(jnp.clip(1.0 - 2.0 * epsilon, -1.0, 1.0))
    psi = half_zone * _NODES
    bracket = jnp.clip(1.0 - (1.0 - jnp.cos(psi)) / (2.0 * epsilon), 0.0, None) ** 1.5
    weight = half_zone * _WEIGHTS / (2.0 * jnp.pi)
    return jnp.sum(weight * bracket * jnp.cos(psi)), jnp.sum(weight * bracket)


def load_zone_half_angle(load_zone_parameter):
    """ψ_l = arccos(1 − 2ε) [rad], half the angular extent of the load zone (π for ε ≥ 1)."""
    return jnp.arccos(jnp.clip(1.0 - 2.0 * jnp.asarray(load_zone_parameter), -1.0, 1.0))


def load_zone_parameter(radial_to_axial):
    """ε [-] with J_r(ε)/J_a(ε) = F_r tan α / F_a (`radial_to_axial`), for 0.6 < ratio < 1.

    J_r/J_a falls from 1 (ε → 0, one ball) to 0.6 (ε = 1, full circle); solved by bisection on
    ln ε over [1e-4, 1] (60 halvings), derivative by the implicit function theorem.
    """
    target = jnp.asarray(radial_to_axial)

    def ratio(log_epsilon):
        radial, axial = sjovall_integrals(jnp.exp(log_epsilon))
        return radial / axial

    def bisect(target):
        def step(_, bounds):
            low, high = bounds
            middle = 0.5 * (low + high)
            too_small = ratio(middle) > target  # J_r/J_a decreases with ε
            return jnp.where(too_small, middle, low), jnp.where(too_small, high, middle)

        low, high = jax.lax.fori_loop(0, 60, step, (jnp.log(1e-4), 0.0))
        return 0.5 * (low + high)

    @jax.custom_jvp
    def solve(target):
        return bisect(target)

    @solve.defjvp
    def _(primals, tangents):
        log_epsilon = solve(primals[0])
        _, slope = jax.jvp(ratio, (log_epsilon,), (jnp.ones_like(log_epsilon),))
        return log_epsilon, tangents[0] / slope

    return jnp.exp(solve(target))


def max_ball_load(radial_load, ball_count, contact_angle, load_zone_parameter_value):
    """Q_max = F_r / (Z J_r(ε) cos α) [N] (Sjövall)."""
    radial, _ = sjovall_integrals(load_zone_parameter_value)
    return radial_load / (ball_count * radial * jnp.cos(contact_angle))


def stribeck_max_ball_load(radial_load, ball_count, contact_angle=0.0):
    """Stribeck's Q_max ≈ 5 F_r / (Z cos α) [N] (the 6411E chamfer paper uses it with F_r = C_r)."""
    return 5.0 * radial_load / (ball_count * jnp.cos(contact_angle))
