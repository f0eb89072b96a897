"""Matrix-free Newton–Krylov for large nonlinear systems, and the implicit derivative of its root.

Each Newton step solves J d = −F inexactly by restarted GMRES (`jax.scipy.sparse.linalg.gmres`,
which stops inside a restart cycle on the residual's norm; lineax's GMRES tests each component
against its own and only at a cycle's end) on Jacobian-vector products (`jax.linearize`),
left-preconditioned by the caller's approximate inverse of J; the
relative tolerance of the linear solve is the forcing term η_k of Eisenstat & Walker (Choosing the
forcing terms in an inexact Newton method, SIAM J. Sci. Comput. 17, 1996, choice 2:
η_k = 0.9 (‖F_k‖/‖F_{k−1}‖)², safeguarded by 0.9 η²_{k−1} where that exceeds 0.1), so that early
steps cost few Krylov iterations and the last ones converge fast. Globalised by Armijo backtracking
on ½‖F/s‖² (each equation divided by its size s, `newton_krylov`) as `newton.newton` (Nocedal &
Wright, Numerical Optimization, 2nd ed. 2006, §11.5), with the slope of the step taken (one more
Jacobian-vector product: where the step is limited it is not −(1 − η)‖F/s‖²); a step
that lowers nothing is not taken, and the iteration stops there.

`krylov_root` differentiates the root by the implicit function theorem (`jax.lax.custom_root`),
its tangent system J x = b solved by the same preconditioned GMRES; reverse mode solves
Jᵀx = b by GMRES with the transposed preconditioner M⁻ᵀ (`jax.lax.custom_linear_solve`).
"""

import jax
import jax.numpy as jnp

ARMIJO = 1e-4  # c of the sufficient-decrease test
FORCING_LARGEST = 1e-3  # η_max: the loosest linear solve, unless the caller asks a tighter one
FORCING_SMALLEST = 1e-10  # η_min
TANGENT_TOLERANCE = 1e-14  # relative tolerance of the tangent (derivative) solves: forward and reverse agree to ~1e-12
# XLA options for a program that holds these solves (`jax.jit(f, compiler_options=COMPILER_OPTIONS)`,
# or `.lower(...).compile(COMPILER_OPTIONS)`): XLA's CPU loop emitters instead of its fusion emitters,
# which take most of the compiler's memory over the nested solves (the starved finite line contact on
# 257 × 257 compiles in 1.0 instead of 2.3 GiB, docs/benchmarks.md). Programs without them keep XLA's
# defaults: there the fusion emitters compile and run faster.
COMPILER_OPTIONS = {"xla_cpu_use_fusion_emitters": False}


def gmres(linear, rhs, preconditioner, tolerance, *, restart: int, max_steps: int):
    """x with linear(x) ≈ rhs [-]: restarted GMRES (`jax.scipy.sparse.linalg.gmres`, incremental
    Givens QR: a cycle ends as soon as it has converged) on the left-preconditioned system
    M⁻¹A x = M⁻¹b (`preconditioner`: v ↦ M⁻¹v, linear), to ‖M⁻¹(b − Ax)‖ ≤ tolerance ‖M⁻¹b‖, in
    at most `max_steps` cycles of `restart` iterations."""
    solution, _ = jax.scipy.sparse.linalg.gmres(lambda v: preconditioner(linear(v)), preconditioner(rhs), tol=tolerance,
                                                atol=0.0, restart=restart, maxiter=max_steps,
                                                solve_method="incremental")
    return solution


def newton_krylov(function, y0, args, preconditioner_at, *, tolerance: float, max_steps: int, restart: int = 30,
                  linear_steps: int = 20, shortest: float = 1e-3, limit=None, scale=None,
                  loosest: float = FORCING_LARGEST):
    """Root of `function(y, args)` [-] from `y0` by inexact Newton (module docstring).

    Args:
        function: F(y, args) → an array of y's shape (1-D).
        preconditioner_at: (y, args) → a linear map v ↦ M⁻¹v approximating J(y)⁻¹.
        tolerance: stop where max|F/s| ≤ tolerance.
        max_steps: the most Newton steps.
        restart, linear_steps: GMRES's Krylov dimension and its most restarts per step.
        shortest: the shortest step length the backtracking tries.
        limit: (d, y) → d shortened (e.g. a largest change per unknown), applied to every step d
            from y.
        loosest: the largest forcing term η_k (the loosest relative tolerance of a linear solve).
        scale: y → s > 0 of F's shape, the size of each equation (None: 1): the stopping test and
            the merit ½‖F/s‖² of the backtracking read F/s, s taken at each step's start point
            (equations of very different sizes otherwise let the largest decide every step).

    Returns (y, Newton steps)."""

    def sizes(y):
        return jnp.ones_like(y) if scale is None else scale(y)

    def evaluate(y, size):
        residual = function(y, args)
        return residual, 0.5 * jnp.sum((residual / size) ** 2)

    def busy(state):
        y, residual, count, _, stalled = state
        return (jnp.max(jnp.abs(residual / sizes(y))) > tolerance) & (count < max_steps) & ~stalled

    def step(state):
        y, residual, count, forcing, _ = state
        size = sizes(y)
        merit = 0.5 * jnp.sum((residual / size) ** 2)
        _, linear = jax.linearize(lambda point: function(point, args), y)
        direction = gmres(linear, -residual, preconditioner_at(y, args), forcing, restart=restart,
                          max_steps=linear_steps)
        if limit is not None:
            direction = limit(direction, y)
        slope = jnp.vdot(residual / size, linear(direction) / size)  # d(½‖F/s‖²) along the step taken

        def shorter(search):
            length, trial_merit, _ = search
            return (trial_merit > merit + ARMIJO * length * jnp.minimum(slope, 0.0)) & (length > shortest)

        def halve(search):
            length = 0.5 * search[0]
            trial_residual, trial_merit = evaluate(y + length * direction, size)
            return length, jnp.where(jnp.isfinite(trial_merit), trial_merit, jnp.inf), trial_residual

        first_residual, first_merit = evaluate(y + direction, size)
        length, trial_merit, trial_residual = jax.lax.while_loop(
            shorter, halve, (jnp.asarray(1.0), jnp.where(jnp.isfinite(first_merit), first_merit, jnp.inf),
                             first_residual))
        lowered = trial_merit < merit
        ratio = jnp.sqrt(trial_merit / merit)
        safeguard = 0.9 * forcing**2
        next_forcing = jnp.clip(jnp.where(safeguard > loosest, jnp.maximum(0.9 * ratio**2, safeguard), 0.9 * ratio**2),
                                FORCING_SMALLEST, loosest)
        return (jnp.where(lowered, y + length * direction, y), jnp.where(lowered, trial_residual, residual), count + 1,
                next_forcing, ~lowered)

    state = (y0, function(y0, args), jnp.asarray(0), jnp.asarray(loosest), jnp.asarray(False))
    y, _, count, _, _ = jax.lax.while_loop(busy, step, state)
    return y, count


def krylov_root(function, solution, args, preconditioner, *, restart: int = 30, linear_steps: int = 50):
    """`solution` (a root of `function(y, args)` found without derivatives) with the implicit
    derivative dy* = −J⁻¹ (∂F/∂args) d args, J x = b solved by GMRES preconditioned by
    `preconditioner` (v ↦ M⁻¹v, built at the root without derivatives); forward and reverse mode."""

    def solve(linear, rhs):
        return gmres(linear, rhs, preconditioner, TANGENT_TOLERANCE, restart=restart, max_steps=linear_steps)

    def transpose_solve(transposed, rhs):  # Jᵀx = b, left-preconditioned by M⁻ᵀ
        preconditioner_transposed = jax.linear_transpose(preconditioner, rhs)
        return gmres(transposed, rhs, lambda v: preconditioner_transposed(v)[0], TANGENT_TOLERANCE, restart=restart,
                     max_steps=linear_steps)

    def tangent_solve(linear, rhs):
        return jax.lax.custom_linear_solve(linear, rhs, solve, transpose_solve)

    return jax.lax.custom_root(lambda y: function(y, args), jax.lax.stop_gradient(solution),
                               lambda _, start: start, tangent_solve)
