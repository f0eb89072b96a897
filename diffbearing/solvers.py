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

    y is a 1-D array in well-scaled units (so that a unit step is a sensible trial step). Where the
    predicted decrease −g·p is below 1e-12 (1 + |f|), below what the function's rounding lets Armijo's
    test resolve, the full Newton step is taken. It stops when the gradient is below
    `gradient_tolerance`, when no step along the Newton direction lowers the function, or after
    `max_steps`.
    """
    value_and_gradient = jax.value_and_grad(function)
    hessian = jax.hessian(function)

    def cond(state):
        _, _, gradient, step, stalled = state
        return (jnp.linalg.norm(gradient) > gradient_tolerance) & (step < max_steps) & ~stalled

    def body(state):
        y, value, gradient, step, _ = state
        regularization = REGULARIZATION * jnp.linalg.norm(gradient)
        direction = -jnp.linalg.solve(hessian(y, args) + regularization * jnp.eye(y.shape[0]), gradient)
        slope = jnp.dot(gradient, direction)

        resolved = -slope <= 1e-12 * (1.0 + jnp.abs(value))

        def insufficient(t, trial):
            return (trial > value + 1e-4 * t * slope) & ~resolved

        def halve(search):
            t, _ = search
            return t * 0.5, function(y + 0.5 * t * direction, args)

        def keep_halving(search):
            t, trial = search
            return insufficient(t, trial) & (t > 0.5**max_halvings)

        t, trial = jax.lax.while_loop(keep_halving, halve, (1.0, function(y + direction, args)))
        stalled = insufficient(t, trial)
        y = jnp.where(stalled, y, y + t * direction)
        value, gradient = value_and_gradient(y, args)
        return y, value, gradient, step + 1, stalled

    value, gradient = value_and_gradient(y0, args)
    y, _, gradient, steps, _ = jax.lax.while_loop(cond, body, (y0, value, gradient, 0, False))
    return y, jnp.linalg.norm(gradient), steps
