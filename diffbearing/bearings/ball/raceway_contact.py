"""Ball–raceway contact geometry: curvature sums and Hertz constants of the two contacts.

docs/theory.md §Groove geometry and clearance (Harris & Kotzalas vol. 1, ch. 2), with γ = D_w cos α / d_m:

    inner: Σρ_i = (1/D_w)(4 − 1/f_i + 2γ/(1−γ)),  F_i = (1/f_i + 2γ/(1−γ)) / (4 − 1/f_i + 2γ/(1−γ))
    outer: Σρ_o = (1/D_w)(4 − 1/f_o − 2γ/(1+γ)),  F_o = (1/f_o − 2γ/(1+γ)) / (4 − 1/f_o − 2γ/(1+γ))

Functions take the bearing pytree first, so `jax.grad(f)(bearing, ...)` reaches its geometry.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ...contact.hertz import effective_modulus, load_deflection_constant
from ...params import BallBearing


def diameter_ratio(bearing: BallBearing, contact_angle):
    """γ = D_w cos α / d_m [-] at contact angle α [rad]."""
    return bearing.ball_diameter * jnp.cos(contact_angle) / bearing.pitch_diameter


def inner_curvature(bearing: BallBearing, contact_angle):
    """(Σρ_i [1/m], F(ρ)_i [-]) of the ball–inner-raceway contact at contact angle α [rad]."""
    gamma = diameter_ratio(bearing, contact_angle)
    raceway = 2.0 * gamma / (1.0 - gamma)
    total = 4.0 - 1.0 / bearing.inner_groove_ratio + raceway
    return total / bearing.ball_diameter, (1.0 / bearing.inner_groove_ratio + raceway) / total


def outer_curvature(bearing: BallBearing, contact_angle):
    """(Σρ_o [1/m], F(ρ)_o [-]) of the ball–outer-raceway contact at contact angle α [rad]."""
    gamma = diameter_ratio(bearing, contact_angle)
    raceway = 2.0 * gamma / (1.0 + gamma)
    total = 4.0 - 1.0 / bearing.outer_groove_ratio - raceway
    return total / bearing.ball_diameter, (1.0 / bearing.outer_groove_ratio - raceway) / total


def both_curvatures(bearing: BallBearing, inner_contact_angle, outer_contact_angle):
    """(Σρ, F(ρ)), each (2, ...): the inner contact's in row 0, the outer's in row 1, for one
    elementwise Hertz evaluation of both sides (a program then holds the ellipticity solve once)."""
    pairs = zip(inner_curvature(bearing, inner_contact_angle), outer_curvature(bearing, outer_contact_angle))
    sums, differences = (jnp.stack(jnp.broadcast_arrays(*pair)) for pair in pairs)
    return sums, differences


def ball_raceway_modulus(bearing: BallBearing):
    """Effective modulus E' [Pa] of the ball against a ring (`hertz.effective_modulus`)."""
    ball, ring = bearing.ball_material, bearing.ring_material
    return effective_modulus(ball.elastic_modulus, ball.poisson_ratio, ring.elastic_modulus, ring.poisson_ratio)


def contact_constants(bearing: BallBearing, inner_contact_angle, outer_contact_angle, method="exact"):
    """Hertz load–deflection constants (K_i, K_o) [N/m^1.5] in Q = K δ^{3/2} at the given angles [rad]
    (both sides at once, `both_curvatures`)."""
    inner, outer = load_deflection_constant(*both_curvatures(bearing, inner_contact_angle, outer_contact_angle),
                                            ball_raceway_modulus(bearing), method)
    return inner, outer


# K_i(α), K_o(α) depend on α only through cos α (via γ) and are analytic in it on [0, 1]: a Chebyshev
# interpolant of degree 16 in t = 2 cos α − 1 built from exact solutions reproduces them to
# ~1e-14 (measured for D_w/d_m up to 0.28 in tests/test_ball_equilibrium.py), at a few flops per
# evaluation instead of a full ellipticity solve. It is built from the bearing inside each solve,
# so derivatives with respect to the geometry flow through the nodes.
CHEBYSHEV_DEGREE = 16


class ContactConstantTable(eqx.Module):
    """Chebyshev coefficients of K_i and K_o [N/m^1.5] in t = 2 cos α − 1."""

    inner: jax.Array
    outer: jax.Array


def contact_constant_table(bearing: BallBearing, method="exact") -> ContactConstantTable:
    """Chebyshev interpolants of the Hertz constants over all contact angles (Chebyshev nodes of the first kind)."""
    count = CHEBYSHEV_DEGREE + 1
    node = (jnp.arange(count) + 0.5) * jnp.pi / count
    angle = jnp.arccos(0.5 + 0.5 * jnp.cos(node))
    inner, outer = contact_constants(bearing, angle, angle, method)
    transform = 2.0 / count * jnp.cos(jnp.arange(count)[:, None] * node[None, :])
    transform = transform.at[0].multiply(0.5)
    return ContactConstantTable(transform @ inner, transform @ outer)


def _clenshaw(coefficients, t):
    """Σ_j c_j T_j(t) by Clenshaw's recurrence (polynomial operations only: smooth derivatives),
    one `lax.scan` step per coefficient (a program holds the recurrence once per call, not unrolled).
    `coefficients` (n, k): n series, each evaluated at its row of `t` (n, ...)."""
    def step(carry, coefficient):
        upper, lower = carry
        return (2.0 * t * upper - lower + coefficient, upper), None

    zeros = jnp.zeros_like(t)
    per_row = coefficients.T.reshape(coefficients.shape[::-1] + (1,) * (t.ndim - 1))  # (k, n, 1, ...)
    (upper, lower), _ = jax.lax.scan(step, (zeros, zeros), per_row[:0:-1])
    return t * upper - lower + per_row[0]


def table_constants(table: ContactConstantTable, inner_angle, outer_angle):
    """(K_i, K_o) [N/m^1.5] at the contact angles [rad] from a `ContactConstantTable` (both sides
    in one recurrence)."""
    t = jnp.stack(jnp.broadcast_arrays(2.0 * jnp.cos(inner_angle) - 1.0, 2.0 * jnp.cos(outer_angle) - 1.0))
    inner, outer = _clenshaw(jnp.stack([table.inner, table.outer]), t)
    return inner, outer


def rolling_radius(bearing: BallBearing, contact_angle, side: str):
    """Equivalent radius R_x = D_w (1 ∓ γ)/2 [m] of a ball–raceway contact in the rolling
    direction, γ = D_w cos α / d_m, − inner, + outer (Hamrock & Dowson, ball bearings)."""
    sign = {"inner": -1.0, "outer": 1.0}[side]
    return 0.5 * bearing.ball_diameter * (1.0 + sign * diameter_ratio(bearing, contact_angle))
