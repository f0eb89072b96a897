"""Generic solvers used by the bearing models (pure JAX, jit- and vmap-able).

`minimise_convex`: regularized Newton with Armijo backtracking for a smooth convex function of a
small vector (Ueda & Yamashita 2010: (H + μI) p = −g with μ = c‖g‖, c = `REGULARIZATION`, globally convergent for convex
functions, quadratic near a non-degenerate minimum). It needs no good start: where the Hessian
vanishes (a zero-clearance bearing at zero load) the step falls back to steepest descent.
"""

import jax
import jax.numpy as jnp

REGULARIZATION = 1e-3


def minimise_convex(function, y0, args, *, gradient_tolerance=1e-12, max_steps=200, max_halvings=40):
    """Minimise a convex `function(y, args)` from `y0`; return (y, ‖gradient‖, steps).

    y is a 1-D array in well-scaled units (so that a unit step is a sensible trial step).
    """
    gradient_and_hessian = jax.value_and_grad(function)
    hessian = jax.hessian(function)

    def cond(state):
        _, gradient_norm, step = state
        return (gradient_norm > gradient_tolerance) & (step < max_steps)

    def body(state):
        y, _, step = state
        value, gradient = gradient_and_hessian(y, args)
        matrix = hessian(y, args)
        regularization = REGULARIZATION * jnp.linalg.norm(gradient)
        direction = -jnp.linalg.solve(matrix + regularization * jnp.eye(y.shape[0]), gradient)
        slope = jnp.dot(gradient, direction)

        def halve(search):
            t, _ = search
            return t * 0.5, function(y + 0.5 * t * direction, args)

        def not_sufficient(search):
            t, trial = search
            return (trial > value + 1e-4 * t * slope) & (t > 0.5**max_halvings)

        t, _ = jax.lax.while_loop(not_sufficient, halve, (1.0, function(y + direction, args)))
        y = y + t * direction
        return y, jnp.linalg.norm(jax.grad(function)(y, args)), step + 1

    initial = (y0, jnp.linalg.norm(jax.grad(function)(y0, args)), 0)
    return jax.lax.while_loop(cond, body, initial)
