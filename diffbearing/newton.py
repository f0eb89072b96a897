"""One damped Newton for the models' nonlinear systems, and the implicit derivative of its root.

`newton` solves F(y, args) = 0. Each step is the Newton step d = −J⁻¹F, from a dense Jacobian
(`jacobian(y, args)`, by default `jax.jacfwd` of F; LU) or from the caller's
`linear_step(y, args) → d` where J has a structure to exploit (the ball bearing's
block-arrow Jacobian through its Schur complement, its balls' 2×2 blocks); `limit(d)` may shorten
it (a largest change per unknown). Then, with `line_search`, globalised on the merit m = ½‖F‖²
(Nocedal & Wright, Numerical Optimization, 2nd ed. 2006, §3.1 and §11.5): the length t is halved
from 1 while m(y + td) > m(y) + c t s, with c = `ARMIJO` and s = −m(y), down to `shortest`, and
the point is taken where it lowers the merit; with `fallback`, where the Newton point lowers
nothing (a kink of a piecewise smooth F), Levenberg–Marquardt steps (JᵀJ + μ diag JᵀJ) d = −JᵀF
(Moré, The Levenberg–Marquardt algorithm, 1978) with μ raised ×10 from 1e-6 until the merit
falls. A step that lowers nothing is not taken, and the iteration stops there. Without
`line_search`, full (limited) Newton steps.

With `single_precision_factor`, the dense step is solved by mixed-precision iterative
refinement (Langou et al., Exploiting the performance of 32 bit floating point arithmetic in
obtaining 64 bit accuracy, SC 2006; Higham, Accuracy and Stability of Numerical Algorithms,
2nd ed. 2002, §12.1): J is factorized once in float32 (on x86 CPUs about 1.7× faster than in
float64 at 4000 unknowns), and the float64 residual b − Jx corrected `REFINEMENTS` times through
that factor; where the corrected step still misses b by more than `REFINED` relative (cond(J)
too large for float32), the float64 LU solves it instead. A step so refined is an inexact Newton
step with forcing term `REFINED` (Dembo, Eisenstat & Steihaug, Inexact Newton methods, SIAM J.
Numer. Anal. 19, 1982), which keeps Newton's local convergence; the root's tolerance is unchanged.

Minimising a smooth f is the same routine: its minimum is the root of F = ∇f, J is the Hessian,
and with `objective` = f the merit is f itself, so the Armijo test above holds with the slope
s = ∇f·d, and only a step that passes it is taken (Nocedal & Wright §3.1); where the predicted
decrease −s is below what f's rounding resolves, 1e-12 (1 + |f|), the full step is taken.
`minimise_convex` is that with the regularised Hessian of Ueda & Yamashita (2010).

Stopping: `loop="scan"` runs `max_steps` steps (`lax.scan`; the steps after the iteration has
stopped do no work), `loop="while"` stops early (`lax.while_loop`); both stop where ‖F‖₂ ≤ `floor`
(line search) or, without line search, after a step with |d| ≤ a + r|y| in every component,
(a, r) = `step_tolerance`.

`implicit_root` differentiates a root by the implicit function theorem (`jax.lax.custom_root`).
"""

import jax
import jax.numpy as jnp

ARMIJO = 1e-4  # c of the sufficient-decrease test
RESOLUTION = 1e-12  # relative rounding of an objective: a smaller predicted decrease is not tested
REGULARIZATION = 1e-3  # c of μ = c‖∇f‖ in `minimise_convex`
REFINEMENTS = 2  # float64 corrections of a float32-factored step (`single_precision_factor`)
REFINED = 1e-8  # ‖b − Jx‖/‖b‖ a refined step must reach, else the float64 LU solves it


def newton(function, y0, args=None, *, max_steps: int, loop: str = "scan", jacobian=None, linear_step=None,
           limit=None, line_search: bool = True, shortest: float = 1e-6, fallback: bool = False, objective=None,
           floor=None, step_tolerance=None, single_precision_factor: bool = False, guard: bool = False):
    """Root of `function(y, args)` from `y0` by damped Newton (module docstring); returns (y, steps).

    Args:
        function: F(y, args), an array of y's size (with `objective`: ∇f); None with a
            `linear_step` and no line search, which evaluate no residual of their own.
        y0: the start; an array, or a pytree of arrays with `linear_step` and no line search.
        max_steps: the most Newton steps (`loop="scan"`: exactly this many scan iterations).
        loop: "scan" (fixed count) or "while" (stops early).
        jacobian: J(y, args), dense; default `jax.jacfwd(function)`. With `objective`, (H, ∇f)(y, args):
            the Hessian and the gradient from one pass.
        linear_step: (y, args) → d = −J⁻¹F, instead of the dense solve.
        limit: d → d shortened (e.g. a largest change per unknown); applied to every step.
        line_search: backtrack on the merit; False: full (limited) steps.
        shortest: the shortest step length the backtracking tries.
        fallback: Levenberg–Marquardt steps where the Newton point lowers nothing (dense J).
        objective: f(y, args) when minimising f (the merit, its Armijo test with s = ∇f·d).
        floor: line search: no step once ‖F‖₂ ≤ floor (None: none).
        step_tolerance: without line search, (a, r) scalars or pytrees like y: stop after a step
            with |d| ≤ a + r|y| in every component.
        single_precision_factor: solve the dense steps by a float32 LU refined in float64
            (`refined_solve`; module docstring), for Jacobians of thousands of unknowns.
        guard: the default dense J regularised as in `guarded_solve` (`guarded`): a direction
            nothing resists keeps the step finite.

    `steps` counts the steps taken or tried (an int array).
    """
    if loop not in ("scan", "while"):
        raise ValueError(f"loop: 'scan' or 'while', got {loop!r}")
    # the default dense J comes with F from one forward pass (`jax.jacfwd` with the residual as aux),
    # so the damped iteration traces F once in the step and once in the line search, not again to start
    joint = jacobian is None and linear_step is None
    if joint:
        jacobian = jax.jacfwd(function)
    if guard and not joint:
        raise ValueError("guard: regularises the default dense jacobian only")
    if fallback and jacobian is None:
        raise ValueError("fallback: Levenberg–Marquardt steps need the dense jacobian")
    limited = (lambda d: d) if limit is None else limit
    dense_solve = refined_solve if single_precision_factor else jnp.linalg.solve

    def newton_step(y, residual):  # (d, J): the limited Newton step, and the dense J it came from
        if linear_step is not None:
            return limited(linear_step(y, args)), None
        matrix = jacobian(y, args)
        return limited(dense_solve(matrix, -residual)), matrix

    if not line_search:
        absolute, relative = (0.0, 0.0) if step_tolerance is None else step_tolerance

        def like(value, y):  # a tolerance per leaf of y
            return value if jax.tree.structure(value) == jax.tree.structure(y) else jax.tree.map(lambda _: value, y)

        def full_step(state):
            y, _, count = state
            step, _ = newton_step(y, None if linear_step is not None else function(y, args))
            small = jax.tree.map(lambda d, y, a, r: jnp.all(jnp.abs(d) <= a + r * jnp.abs(y)), step, y,
                                 like(absolute, y), like(relative, y))
            return jax.tree.map(jnp.add, y, step), jnp.all(jnp.stack(jax.tree.leaves(small))), count + 1

        def busy(state):
            return ~state[1]

        return _iterate(full_step, busy, (y0, jnp.asarray(False), jnp.asarray(0)), max_steps, loop)

    def evaluate(y):  # (merit, F); when minimising, (f, None): ∇f comes with the Hessian at the next step
        if objective is not None:
            return objective(y, args), None
        residual = function(y, args)
        return 0.5 * jnp.sum(residual**2), residual

    def untried(y):  # (merit, F) placeholders before a loop's first evaluation (F has y's shape)
        return jnp.zeros((), y.dtype), (None if objective is not None else jnp.zeros_like(y))

    def levenberg_marquardt(y, residual, start, matrix):
        normal = matrix.T @ matrix
        gradient = matrix.T @ residual
        scale = jnp.diag(normal) + 1e-12

        def trial(damping):
            return y - limited(jnp.linalg.solve(normal + damping * jnp.diag(scale), gradient))

        damping, merit, following = _trials(lambda damping: evaluate(trial(damping)), jnp.asarray(1e-6, y.dtype), 10.0,
                                            lambda damping, merit: ~(merit < start) & (damping < 1e6), untried(y))
        return trial(damping), merit, following

    def line_search_from(y, step, start, slope, resolved):
        """(length, merit, F, sufficient) of the Armijo backtracking from length 1 (`_trials`)."""
        def sufficient(length, merit):
            return (merit <= start + ARMIJO * length * slope) | resolved

        length, merit, following = _trials(lambda length: evaluate(y + length * step), jnp.asarray(1.0, y.dtype), 0.5,
                                           lambda length, merit: ~sufficient(length, merit) & (length > shortest),
                                           untried(y))
        return length, merit, following, sufficient(length, merit)

    def damped_step(state):  # state: (y, F at y where known, stopped, count); F unknown before a joint first step
        y, residual, _, count = state
        first = joint & (count == 0)
        if joint:
            matrix, residual = jax.jacfwd(lambda y: (r := function(y, args), r), has_aux=True)(y)
            matrix = guarded(matrix) if guard else matrix
            step = limited(dense_solve(matrix, -residual))
        else:
            step, matrix = newton_step(y, residual)
        start = 0.5 * jnp.sum(residual**2)
        length, merit, following, _ = line_search_from(y, step, start, -start, jnp.asarray(False))
        point = y + length * step
        if fallback:
            point, merit, following = jax.lax.cond(merit < start, lambda: (point, merit, following),
                                                   lambda: levenberg_marquardt(y, residual, start, matrix))
        # a start already below the floor takes no step (known only now, with F from the Jacobian's pass)
        converged = jnp.asarray(False) if floor is None else first & (jnp.linalg.norm(residual) <= floor)
        accepted = (merit < start) & ~converged
        return (jnp.where(accepted, point, y), jnp.where(accepted, following, residual), ~accepted,
                count + jnp.where(converged, 0, 1))

    def busy(state):
        _, residual, stopped, count = state
        return ~stopped if floor is None else ~stopped & ((joint & (count == 0)) | (jnp.linalg.norm(residual) > floor))

    if objective is None:
        known = jnp.zeros_like(y0) if joint else function(y0, args)
        return _iterate(damped_step, busy, (y0, known, jnp.asarray(False), jnp.asarray(0)), max_steps, loop)

    def descent_step(state):  # minimising f: the step from H and ∇f at y (one trace of each), f alone in the search
        y, start, _, count = state
        matrix, gradient = jacobian(y, args)
        converged = jnp.asarray(False) if floor is None else jnp.linalg.norm(gradient) <= floor
        step = limited(dense_solve(matrix, -gradient))
        slope = jnp.dot(gradient, step)
        resolved = -slope <= RESOLUTION * (1.0 + jnp.abs(start))
        length, merit, _, sufficient = line_search_from(y, step, start, slope, resolved)
        accepted = sufficient & ~converged
        return (jnp.where(accepted, y + length * step, y), jnp.where(accepted, merit, start), ~accepted,
                count + jnp.where(converged, 0, 1))

    return _iterate(descent_step, lambda state: ~state[2], (y0, objective(y0, args), jnp.asarray(False),
                                                            jnp.asarray(0)), max_steps, loop)


def _trials(evaluate_at, initial, factor, more, untried):
    """(p, merit, F) of the trials p = initial, initial·factor, initial·factor², … each evaluated by
    `evaluate_at(p)` → (merit, F), while `more(p, merit)`: a backtracking line search (factor ½) or
    a rising damping (factor 10). One `while_loop` whose first pass is the first trial, so the
    evaluation is traced once; `untried`: (merit, F) placeholders of its shapes."""
    def going(search):
        p, merit, _, tried = search
        return ~tried | more(p, merit)

    def advance(search):
        p = jnp.where(search[3], factor * search[0], search[0])
        return (p, *evaluate_at(p), jnp.asarray(True))

    p, merit, following, _ = jax.lax.while_loop(going, advance, (initial, *untried, jnp.asarray(False)))
    return p, merit, following


def guarded(matrix):
    """J + 1e-12 (max |J_kk| + 1) I (Levenberg–Marquardt form): at a singular J (zero load, every
    contact open, a direction nothing resists) a step solved with it stays finite and, with a zero
    right-hand side, zero."""
    return matrix + 1e-12 * (jnp.max(jnp.abs(jnp.diag(matrix))) + 1.0) * jnp.eye(matrix.shape[0])


def guarded_solve(matrix, rhs):
    """x = J⁻¹ r (LU) with J `guarded`."""
    return jnp.linalg.solve(guarded(matrix), rhs)


def refined_solve(matrix, rhs):
    """x with matrix·x = rhs (float64): LU in float32, `REFINEMENTS` float64 corrections
    x ← x + LU⁻¹(rhs − matrix·x), and the float64 LU where that leaves ‖rhs − matrix·x‖ above
    `REFINED`·‖rhs‖ (module docstring)."""
    factor = jax.scipy.linalg.lu_factor(matrix.astype(jnp.float32))

    def correction(residual):
        return jax.scipy.linalg.lu_solve(factor, residual.astype(jnp.float32)).astype(rhs.dtype)

    solution = correction(rhs)
    for _ in range(REFINEMENTS):
        solution = solution + correction(rhs - matrix @ solution)
    refined = jnp.linalg.norm(rhs - matrix @ solution) <= REFINED * jnp.linalg.norm(rhs)
    return jax.lax.cond(refined, lambda: solution, lambda: jnp.linalg.solve(matrix, rhs))


def _iterate(step, busy, state, max_steps: int, loop: str):
    """(y, steps) after `step` applied while `busy`, at most `max_steps` times."""
    if loop == "while":
        state = jax.lax.while_loop(lambda state: busy(state) & (state[-1] < max_steps), step, state)
    else:
        state = jax.lax.scan(lambda state, _: (jax.lax.cond(busy(state), step, lambda state: state, state), None),
                             state, None, length=max_steps)[0]
    return state[0], state[-1]


def minimise_convex(function, y0, args, *, gradient_tolerance=1e-12, max_steps=200, shortest=0.5**40):
    """Minimum of a smooth convex `function(y, args)` from `y0` (a small 1-D array in well-scaled
    units, so that a unit step is a sensible trial); returns (y, steps).

    Newton on ∇f with Armijo backtracking on f (module docstring), the Hessian regularised as
    (H + μI) d = −∇f with μ = c‖∇f‖, c = `REGULARIZATION` (Ueda & Yamashita, Convergence properties
    of the regularized Newton method for the unconstrained nonconvex optimization, 2010): globally
    convergent for convex functions, quadratic near a non-degenerate minimum, and it needs no good
    start: where the Hessian vanishes (a zero-clearance bearing at zero load) the step is steepest
    descent. Stops at ‖∇f‖ ≤ `gradient_tolerance`, where no step along d lowers f enough, or
    after `max_steps`.
    """
    gradient = jax.grad(function)

    def regularised_hessian(y, args):  # (H + μI, ∇f) from one forward pass over the gradient
        hessian, slope = jax.jacfwd(lambda y: (g := gradient(y, args), g), has_aux=True)(y)
        return hessian + REGULARIZATION * jnp.linalg.norm(slope) * jnp.eye(y.shape[0]), slope

    return newton(gradient, y0, args, max_steps=max_steps, loop="while", jacobian=regularised_hessian,
                  objective=function, shortest=shortest, floor=gradient_tolerance)


def block_matrices(linear, shape):
    """(..., k, k) blocks of a linear map that is block-diagonal on arrays of `shape` (..., k): each
    row of k unknowns (a rolling element's state) maps onto its own k equations alone."""
    size = shape[-1]
    units = jnp.broadcast_to(jnp.eye(size).reshape((size,) + (1,) * (len(shape) - 1) + (size,)), (size, *shape))
    return jnp.moveaxis(jax.vmap(linear)(units), 0, -1)


def block_tangent_solve(linear, rhs):
    """x with linear(x) = rhs for a block-diagonal map on (..., k) arrays, block by block."""
    return jnp.linalg.solve(block_matrices(linear, rhs.shape), rhs[..., None])[..., 0]


def block_newton(residual, start, args, *, max_steps: int, step_tolerance: float):
    """Damped Newton on a block-diagonal system F(y, args) = 0 of (..., k) unknowns (each block a
    rolling element's state, `block_matrices`), all blocks at once: each block's step halved until
    its ½‖F_j‖² falls (Armijo, c = 2e-4 · length; at most 30 halvings). Stops when no unknown moves
    more than `step_tolerance` or after `max_steps`; returns y."""
    def merit(y):
        value = residual(y, args)
        return 0.5 * jnp.sum(value**2, axis=-1), value

    def step(carry):
        y, _, count = carry
        start_merit, value = merit(y)
        linear = jax.linearize(lambda s: residual(s, args), y)[1]
        direction = -jnp.linalg.solve(block_matrices(linear, y.shape), value[..., None])[..., 0]

        def failing(length, trial):
            return trial > (1.0 - 2e-4 * length) * start_merit

        def shorten(search):
            length, trial, halvings = search
            length = jnp.where(failing(length, trial), 0.5 * length, length)
            return length, merit(y + length[..., None] * direction)[0], halvings + 1

        def busy(search):
            length, trial, halvings = search
            return jnp.any(failing(length, trial)) & (halvings < 30)

        ones = jnp.ones(y.shape[:-1])
        length, _, _ = jax.lax.while_loop(busy, shorten, (ones, merit(y + direction)[0], 0))
        change = length[..., None] * direction
        return y + change, jnp.max(jnp.abs(change)), count + 1

    def moving(carry):
        _, size, count = carry
        return (size > step_tolerance) & (count < max_steps)

    return jax.lax.while_loop(moving, step, (start, jnp.asarray(jnp.inf), 0))[0]


def dense_tangent_solve(linear, rhs):
    """x with linear(x) = rhs, by LU of the dense matrix of the linear map (`jax.jacfwd`)."""
    return jnp.linalg.solve(jax.jacfwd(linear)(rhs), rhs)


def least_squares_tangent_solve(linear, rhs):
    """x with linear(x) = rhs by least squares on the dense matrix of the linear map: finite where
    it is singular (a stiffness with a direction nothing resists: the pseudo-inverse)."""
    return jnp.linalg.lstsq(jax.jacfwd(linear)(rhs), rhs)[0]


def implicit_root(residual, guess, args, solve, tangent_solve=dense_tangent_solve, has_aux=False):
    """The root y* of residual(y, args) = 0 that `solve(residual, guess, args)` finds, with its
    implicit derivative dy* = −(∂F/∂y)⁻¹ (∂F/∂args) d args (implicit function theorem; forward and
    reverse mode, and again for higher orders, by `jax.lax.custom_root`). The solve itself is
    not differentiated, nor is the guess. `tangent_solve(linear, b)` solves the linearised
    residual, linear(x) = b, at the root; by default dense (`dense_tangent_solve`).
    With `has_aux`, `solve` returns (y*, aux) and aux carries no derivative."""
    return jax.lax.custom_root(lambda y: residual(y, args), guess, lambda _, start: solve(residual, start, args),
                               tangent_solve, has_aux=has_aux)
