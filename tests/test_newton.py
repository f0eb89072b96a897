"""The damped Newton's mixed-precision step (`newton.refined_solve`): a float32 LU refined to float64."""

import jax
import jax.numpy as jnp
import numpy as np

from diffbearing.newton import REFINED, newton, refined_solve


def _matrix(size, condition, seed, symmetric=False):
    """A dense float64 matrix of the given 2-norm condition number (random orthogonal factors;
    `symmetric`: positive definite)."""
    generator = np.random.default_rng(seed)
    left, _ = np.linalg.qr(generator.standard_normal((size, size)))
    right = left if symmetric else np.linalg.qr(generator.standard_normal((size, size)))[0]
    return jnp.asarray(left @ np.diag(np.geomspace(1.0, 1.0 / condition, size)) @ right.T)


def test_a_refined_step_solves_to_the_forcing_term_where_float32_can():
    """cond(J) = 1e3: float32's LU refined twice in float64 leaves ‖b − Jx‖/‖b‖ below `REFINED`,
    and x agrees with the float64 LU's to 1e-11 of its largest entry."""
    matrix = _matrix(300, 1e3, 0)
    rhs = jnp.asarray(np.random.default_rng(1).standard_normal(300))
    solution = jax.jit(refined_solve)(matrix, rhs)
    assert float(jnp.linalg.norm(rhs - matrix @ solution) / jnp.linalg.norm(rhs)) <= REFINED
    np.testing.assert_allclose(solution, jnp.linalg.solve(matrix, rhs), rtol=0.0,
                               atol=1e-11 * float(jnp.max(jnp.abs(solution))))


def test_a_matrix_float32_cannot_factor_falls_back_to_float64():
    """cond(J) = 1e10, beyond float32 (ε ≈ 6e-8): the refinement stalls, and the step is the
    float64 LU's (the same numbers to round-off), not the float32 one's."""
    matrix = _matrix(200, 1e10, 2)
    rhs = jnp.asarray(np.random.default_rng(3).standard_normal(200))
    solution = jax.jit(refined_solve)(matrix, rhs)
    float64 = jnp.linalg.solve(matrix, rhs)
    factor = jax.scipy.linalg.lu_factor(matrix.astype(jnp.float32))
    float32 = jax.scipy.linalg.lu_solve(factor, rhs.astype(jnp.float32)).astype(jnp.float64)
    scale = float(jnp.max(jnp.abs(float64)))
    np.testing.assert_allclose(solution, float64, rtol=0.0, atol=1e-9 * scale)
    assert float(jnp.max(jnp.abs(float32 - float64))) > 1e-3 * scale


def test_newton_with_float32_factors_reaches_the_float64_root():
    """F(y) = A y + 0.1 y³ − b (200 unknowns, A symmetric positive definite, cond(A) = 1e2: the
    gradient of a convex function, one root): Newton with `single_precision_factor` reaches the
    same root as with float64 LU, to 1e-12, below the same floor."""
    matrix = _matrix(200, 1e2, 4, symmetric=True)
    rhs = jnp.asarray(np.random.default_rng(5).standard_normal(200))

    def residual(y, _):
        return matrix @ y + 0.1 * y**3 - rhs

    roots = [jax.jit(lambda y0, mixed=mixed: newton(residual, y0, max_steps=30, floor=1e-12,
                                                    single_precision_factor=mixed)[0])(jnp.zeros(200))
             for mixed in (False, True)]
    assert float(jnp.linalg.norm(residual(roots[1], None))) <= 1e-12
    np.testing.assert_allclose(roots[1], roots[0], rtol=0.0, atol=1e-12)


def _counted(function):
    """`function` with a count of the times it is traced (called in Python)."""
    def counted(*arguments):
        counted.calls += 1
        return function(*arguments)

    counted.calls = 0
    return counted


def test_the_damped_newton_traces_its_residual_once_per_use_and_reaches_the_root():
    """F(y) = y³ + y − b, damped with Levenberg–Marquardt fallback from a far start: the residual is
    traced once in the Jacobian's pass (which also gives F), once in the line search and once in
    the fallback, the loops' first passes holding their first trials; without the fallback, twice.
    The root is reached below the floor, and a start already there takes no step."""
    target = jnp.array([2.0, -30.0, 0.5])
    residual = _counted(lambda y, _: y**3 + y - target)
    root, steps = jax.jit(lambda y0: newton(residual, y0, max_steps=60, loop="while", fallback=True, floor=1e-13))(
        jnp.full(3, 5.0))
    assert residual.calls == 3
    assert float(jnp.linalg.norm(root**3 + root - target)) <= 1e-13 and 0 < int(steps) < 60
    plain = _counted(lambda y, _: y**3 + y - target)
    jax.make_jaxpr(lambda y0: newton(plain, y0, max_steps=60, floor=1e-13))(jnp.full(3, 5.0))
    assert plain.calls == 2
    _, again = jax.jit(lambda y0: newton(residual, y0, max_steps=60, loop="while", floor=1e-13))(root)
    assert int(again) == 0


def test_the_convex_minimisation_traces_its_energy_for_the_line_search_and_its_gradient_once():
    """f(y) = Σ cosh(y − c) (convex, minimum at c): the energy is traced at the start and once in
    the line search, its gradient once (in the Hessian's pass, which gives both)."""
    from diffbearing.newton import minimise_convex

    centre = jnp.array([0.3, -2.0, 1.0])
    energy = _counted(lambda y, _: jnp.sum(jnp.cosh(y - centre)))
    minimum, _ = jax.jit(lambda y0: minimise_convex(energy, y0, None, gradient_tolerance=1e-12))(jnp.zeros(3))
    np.testing.assert_allclose(minimum, centre, rtol=0.0, atol=1e-12)
    assert energy.calls == 3  # the start, the line search, and the gradient (by jax.grad, in the Hessian's pass)


def test_a_guard_is_for_the_default_jacobian_only():
    try:
        newton(lambda y, _: y, jnp.zeros(2), max_steps=3, jacobian=lambda y, _: jnp.eye(2), guard=True)
    except ValueError as error:
        assert "guard" in str(error)
    else:
        raise AssertionError("a guard with the caller's jacobian is refused")
