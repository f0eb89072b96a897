"""Numerical guards shared by every physics block.

* `require_float64` — the library computes in float64 only (docs/conventions.md, §Units and
  precision).
* NaN-safe branches (the double-`where` trick of jax-md's `safe_mask`): the value is exact and
  the gradient finite where a contact opens (`max(δ, 0)^1.5`) or a load vanishes (`Q^(1/3)`).
* `without_gradient` — a start's or a solve's inputs held, where an implicit derivative stands for
  the solve's own.
"""

import equinox as eqx
import jax
import jax.numpy as jnp


def require_float64() -> None:
    """Raise if JAX runs in float32: every physics block of diffbearing needs float64."""
    if not jax.config.read("jax_enable_x64"):
        raise RuntimeError(
            "diffbearing needs float64: call jax.config.update('jax_enable_x64', True) "
            "before the first JAX computation (the CLI and the tests do this)"
        )


def without_gradient(tree):
    """`tree` with every floating array leaf under `jax.lax.stop_gradient`: the inputs of a start or
    a solve whose root an implicit derivative differentiates, so that a derivative's program holds
    no tangents of its loops (a `stop_gradient` of the outputs alone leaves them traced)."""
    return jax.tree.map(lambda x: jax.lax.stop_gradient(x) if eqx.is_inexact_array(x) else x, tree)


def positive_power(x, exponent):
    """`max(x, 0) ** exponent` with an exact zero and a zero (not NaN) gradient for x ≤ 0.

    For 0 < exponent < 1 the true derivative at x = 0⁺ is infinite; it is reported as 0 at x = 0
    exactly, which is what a Newton step on a contact that is just closing needs.
    """
    is_positive = x > 0
    safe_x = jnp.where(is_positive, x, 1.0)
    return jnp.where(is_positive, safe_x**exponent, 0.0)


def safe_sqrt(x):
    """`sqrt(max(x, 0))` with a zero gradient at x ≤ 0 instead of inf/NaN."""
    return positive_power(x, 0.5)


def safe_norm(x, axis=None):
    """Euclidean norm with a zero (not NaN) gradient at x = 0."""
    return safe_sqrt(jnp.sum(x * x, axis=axis))
