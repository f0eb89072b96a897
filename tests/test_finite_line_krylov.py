"""The matrix-free Newton–Krylov finite line EHL: its pieces against the dense solver's (FFT
deflection, Jacobian column blocks), its flooded solution against the dense Newton's on the
same uniform cells, and its implicit derivatives against central differences."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.bearings.roller.roller_profile import roller_profile
from diffbearing.contact.influence import love_rectangle
from diffbearing.film.finite_line_ehl import finite_line_film
from diffbearing.film.finite_line_krylov import finite_line_film_krylov
from diffbearing.film.line_ehl import FluidParameters, moes_load_parameter
from diffbearing.film.nested_krylov import Stage, UniformLevel, interpolate_level, krylov_levels

from .helpers import assert_jvp_matches_central_difference
from .test_film_formulas import STARVED_EHL_LINE, starved_ehl_entrainment_speed

PROFILE = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
GRID = (65, 32)  # two levels: 33 × 32 dense, then 65 × 32 by Newton–Krylov


def _solve(load, layer=None, grid=GRID, solver=finite_line_film_krylov, profile=PROFILE, **options):
    return solver(load, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed(), 0.08, 2.2e-8, 2.26e11, profile,
                  14.7e-3, 12.7e-3, grid=grid, oil_layer=layer, **options)


def _level(nx, ny, supply=None):
    """A small level of the starved-EHL paper's roller at 1028 N in its dimensionless units."""
    fluid = FluidParameters(jnp.asarray(2.0e-4), jnp.asarray(0.4e9), jnp.asarray(0.08), jnp.asarray(2.2e-8),
                            "roelands", "dowson_higginson")
    return UniformLevel(nx, ny, 66.0, lambda y: 1e-3 * jnp.maximum(y - 57.0, 0.0) ** 2, fluid, supply, 0.0, 57.0 * np.pi)


def test_levels_halve_to_the_dense_grid_and_bad_grids_are_refused():
    assert krylov_levels((257, 257)) == [(33, 65), (65, 65), (129, 129), (257, 257)]
    assert krylov_levels((257, 257), 32) == [(33, 33), (65, 65), (129, 129), (257, 257)]
    assert krylov_levels((129, 40)) == [(33, 40), (65, 40), (129, 40)]
    for grid in ((100, 64), (16, 64), (129, 4)):
        with pytest.raises(ValueError, match="grid"):
            krylov_levels(grid)


def test_fft_film_is_the_dense_love_sum_with_the_mirror_image():
    """H_el = (1/2π) Σ_k P_k [C(x_i − x_k, y_j − y_k) + C(x_i − x_k, y_j + y_k)]: the FFT
    convolution against the direct double sum, to round-off."""
    level = _level(17, 6)
    pressure = jax.random.uniform(jax.random.key(0), (17, 6))
    x, y = np.asarray(level.columns.x), np.asarray(level.columns.y)
    dx, dy = level.spacing, float(level.cell)
    offset_x = (x[:, None] - x[None, :])[:, None, :, None]
    kernel = (love_rectangle(offset_x, (y[:, None] - y[None, :])[None, :, None, :], dx / 2, dy / 2)
              + love_rectangle(offset_x, (y[:, None] + y[None, :])[None, :, None, :], dx / 2, dy / 2)) / (2 * np.pi)
    direct = jnp.einsum("ijkl,kl->ij", kernel, pressure)
    np.testing.assert_allclose(level.elastic(pressure), direct, rtol=1e-12, atol=1e-12 * float(jnp.max(direct)))


@pytest.mark.slow  # 14 s flooded, more starved (2 cores)
@pytest.mark.parametrize("supply, held", [(None, False), (3.0, False), (3.0, True)])
def test_preconditioner_blocks_are_the_exact_column_blocks_of_the_jacobian(supply, held):
    """Applied to J's own columns of one y cell, the preconditioner returns the unit vectors where J
    has no coupling to other columns: so the blocks are the exact ones. Checked as M⁻¹(J e) = e
    for J restricted to block-diagonal plus the H₀ border, assembled from jax.jacfwd; starved, at
    a stage of the supply continuation (the layer × 0.8), free and with the menisci held."""
    level = _level(17, 6, supply)
    stage = Stage(jnp.asarray(held), jnp.asarray(0.8)) if supply is not None else None
    key = jax.random.key(1)
    pressure = jax.random.uniform(key, (15, 6)) * jnp.exp(-jnp.arange(15.0) / 4)[:, None]
    unknowns = jnp.append(pressure.reshape(-1), -0.5)
    if supply is not None:
        unknowns = jnp.concatenate([unknowns, jnp.linspace(-4.0, -2.0, 6)])
    jacobian = jax.jacfwd(level.residual)(unknowns, stage)
    interior, ny = 15 * 6, 6
    # column of each unknown and equation: pressures row-major (x, y), then H₀ / balance, then menisci
    column = np.concatenate([np.tile(np.arange(ny), 15), [-1], np.arange(ny) if supply is not None else []])
    same = (column[:, None] == column[None, :]) | (column[:, None] == -1) | (column[None, :] == -1)
    same[interior, interior] = False  # the balance does not read H₀
    block_jacobian = jnp.where(same, jacobian, 0.0)
    apply = level.preconditioner(unknowns, stage)
    for index in (0, 7, 40, interior - 1, interior, len(unknowns) - 1):
        np.testing.assert_allclose(apply(block_jacobian[:, index]), jnp.eye(len(unknowns))[index], atol=1e-9)


def test_stages_hold_the_menisci_and_scale_the_supply():
    """`Stage`: held, the meniscus rows become X_m − X_m,now (zero, with the identity as their
    Jacobian rows) and the Reynolds rows and the load balance are the level's own; a supply factor
    is the level with that much oil (its meniscus rows), and the factor 1, free, the level itself."""
    level = _level(17, 6, 3.0)
    pressure = jax.random.uniform(jax.random.key(2), (15, 6)) * jnp.exp(-jnp.arange(15.0) / 4)[:, None]
    unknowns = jnp.concatenate([pressure.reshape(-1), jnp.array([-0.5]), jnp.linspace(-4.0, -2.0, 6)])
    held = Stage(jnp.asarray(True), jnp.asarray(1.0))
    rows = level.interior + 1
    np.testing.assert_array_equal(level.residual(unknowns, held)[:rows], level.residual(unknowns)[:rows])
    assert float(jnp.max(jnp.abs(level.residual(unknowns, held)[rows:]))) == 0.0
    np.testing.assert_array_equal(jax.jacfwd(level.residual)(unknowns, held)[rows:], jnp.eye(len(unknowns))[rows:])
    np.testing.assert_array_equal(level.residual(unknowns, Stage(jnp.asarray(False), jnp.asarray(1.0))),
                                  level.residual(unknowns))
    thinner = _level(17, 6, 3.0 * 0.7)
    np.testing.assert_allclose(level.residual(unknowns, Stage(jnp.asarray(False), jnp.asarray(0.7))),
                               thinner.residual(unknowns), rtol=1e-14, atol=1e-14)


def test_interpolated_menisci_lie_upstream_of_where_the_fine_gap_closes_below_the_layer():
    """`interpolate_level`, starved, no pressure: in a column whose gap H₀ + X²/2 + g(Y) closes
    below H_oil the meniscus is a cell upstream of the first node where it does (the coarse one,
    downstream of it, is moved); where the crown keeps the gap above H_oil, at the highest."""
    fluid = FluidParameters(jnp.asarray(2.0e-4), jnp.asarray(0.4e9), jnp.asarray(0.08), jnp.asarray(2.2e-8),
                            "roelands", "dowson_higginson")

    def level(nx, ny):
        return UniformLevel(nx, ny, 66.0, lambda y: 0.1 * jnp.maximum(y - 57.0, 0.0) ** 2, fluid, 3.0, 0.0,
                            57.0 * np.pi)

    coarse, fine = level(17, 8), level(33, 16)
    unknowns = jnp.concatenate([jnp.zeros(15 * 8), jnp.array([1.0]), jnp.full(8, 0.5)])
    _, offset, menisci = fine.unpack(interpolate_level(unknowns, coarse, fine))
    gap = fine.film(jnp.zeros((33, 16)), offset)
    closes = np.asarray(gap <= 3.0)
    assert float(offset) == 1.0 and closes.any(axis=0).any() and not closes.any(axis=0).all()
    x = np.asarray(fine.columns.x)
    expected = np.where(closes.any(axis=0), x[np.argmax(closes, axis=0)] - fine.spacing, x[-1] - 0.5 * fine.spacing)
    np.testing.assert_allclose(menisci, expected, rtol=0, atol=1e-12)


@pytest.fixture(scope="module")
def flooded():
    """(Newton–Krylov, dense on the same uniform cells) flooded films at 1028 N."""
    return (jax.jit(lambda w: _solve(w))(1028.0),
            jax.jit(lambda w: _solve(w, solver=finite_line_film, axial_clustering=0.0))(1028.0))


@pytest.mark.slow  # about 4 minutes with a cold compilation cache (2 cores): both solvers
def test_newton_krylov_solves_the_dense_solvers_equations(flooded):
    """The same discrete equations on the same 65 × 32 uniform cells, flooded: the Newton–Krylov
    solution is the dense Newton's, to the solvers' tolerance (1e-10 in the residual, scaled for Newton–Krylov)."""
    krylov, dense = flooded
    assert bool(krylov.converged) and bool(dense.converged) and float(krylov.residual) < 1e-10
    scale = float(jnp.max(dense.pressure))
    np.testing.assert_allclose(krylov.pressure, dense.pressure, atol=1e-6 * scale)
    np.testing.assert_allclose(krylov.thickness, dense.thickness, rtol=1e-6)


def _dry_under_the_layer(film, layer):
    """The y cells with no pressure whose gap closes below the oil layer somewhere."""
    pressure, thickness = np.asarray(film.pressure), np.asarray(film.thickness)
    return [j for j in range(pressure.shape[1]) if pressure[:, j].max() <= 0 and thickness[:, j].min() < layer]


@pytest.mark.extended
@pytest.mark.slow  # about 80 s (2 cores): both solvers
def test_newton_krylov_solves_the_dense_solvers_starved_equations():
    """Starved by 0.8 µm of oil at 1028 N on 65 × 48 uniform cells (33 × 48 dense, then Newton–Krylov):
    both converge on the same discrete equations and agree over the middle of the roller (y < 3 mm:
    films to 2e-4, menisci to 0.1 µm), but take different roots at its end: the dense Newton's
    leaves the first column past the flat's end dry under a gap thinner than the layer (a root that
    the layer, which passes no gap thinner than itself as a partial film, does not allow:
    docs/benchmarks.md §Finite line EHL by Newton–Krylov), the Newton–Krylov's, whose menisci start
    upstream of where each column's gap closes below the layer, forms a full film there."""
    krylov = jax.jit(lambda w: _solve(w, 0.8e-6, grid=(65, 48)))(1028.0)
    dense = jax.jit(lambda w: _solve(w, 0.8e-6, grid=(65, 48), solver=finite_line_film, axial_clustering=0.0))(1028.0)
    assert bool(krylov.converged) and bool(dense.converged)
    middle = np.asarray(dense.y) < 3e-3
    np.testing.assert_allclose(krylov.thickness[:, middle], dense.thickness[:, middle], rtol=2e-4)
    np.testing.assert_allclose(krylov.meniscus[middle], dense.meniscus[middle], atol=1e-7)
    assert _dry_under_the_layer(krylov, 0.8e-6) == [] and len(_dry_under_the_layer(dense, 0.8e-6)) >= 1


@pytest.mark.extended
@pytest.mark.slow  # about a minute (2 cores)
def test_newton_krylov_starved_at_a_heavier_load_converges_through_the_supply_continuation():
    """1607 N starved by 0.8 µm on 65 × 65 (33 × 65 dense first): a Newton–Krylov step that moves
    every meniscus stalled here (scaled residual 0.08); with the menisci held first and the supply
    continued from the flux of that solution it converges, with a positive film, the menisci of
    the flat's middle inside the inlet and those of the roller's crowned end at the highest."""
    film = jax.jit(lambda w: _solve(w, 0.8e-6, grid=(65, 65)))(1607.0)
    assert bool(film.converged) and float(film.residual) < 1e-10 and float(film.minimum) > 0.0
    assert _dry_under_the_layer(film, 0.8e-6) == []
    y, meniscus, x = np.asarray(film.y), np.asarray(film.meniscus), np.asarray(film.x)
    assert np.all((meniscus[y < 5e-3] > x[0]) & (meniscus[y < 5e-3] < 0.0))
    assert meniscus[-1] == pytest.approx(x[-1] - 0.5 * (x[1] - x[0]), rel=1e-12)


@pytest.mark.extended
@pytest.mark.slow  # about a minute (2 cores): the solve, its forward and reverse derivatives, two more solves
def test_newton_krylov_film_derivatives_match_central_differences():
    """d(h_c, h_min)/dW [µm/kN] at 1028 N, flooded, 65 × 32: the implicit derivatives (GMRES
    tangent solve forward, the transposed one in reverse) against a central difference of ±1 N,
    whose truncation and solver-tolerance error is below 1e-4 relative here."""

    def films(load_kilonewton):
        film = _solve(1e3 * load_kilonewton)
        return jnp.stack([film.central, film.minimum]) * 1e6

    solved = _solve(1028.0)
    assert bool(solved.converged) and float(solved.minimum) > 0.1e-6  # the end constriction resolved
    assert_jvp_matches_central_difference(jax.jit(films), jnp.asarray(1.028), jnp.asarray(1.0), 1e-3, rtol=5e-4)


@pytest.mark.slow  # about 30 s and 80 s (2 cores)
@pytest.mark.parametrize("load, layer, speed_factor", [
    pytest.param(2471.0, None, 6e-4, marks=pytest.mark.extended), (1028.0, 0.1e-6, 1.0)],
    ids=["M-above-200", "severe-starvation"])  # M above 200 stays in CI through the dense solver (test_starved_film.py)
def test_newton_krylov_hard_cases_say_whether_they_converged_and_stay_finite(load, layer, speed_factor):
    """Hard cases on 65 × 48: the paper's heaviest load at 6e-4 of its speed (Moes M ≈ 205 on the
    flat's length), and 1028 N starved by 0.1 µm of oil (a twelfth of the flooded film). Whether
    or not Newton–Krylov converges, `converged` agrees with the residual and the film, and the
    films and their load derivatives are finite."""
    speed = starved_ehl_entrainment_speed() * speed_factor
    assert speed_factor == 1.0 or float(moes_load_parameter(load / 12.7e-3, STARVED_EHL_LINE["radius"], speed, 0.08,
                                                            2.26e11)) > 200

    def solve(w):
        film = finite_line_film_krylov(w, STARVED_EHL_LINE["radius"], speed, 0.08, 2.2e-8, 2.26e11, PROFILE, 14.7e-3,
                                       12.7e-3, grid=(65, 48), oil_layer=layer)
        return jnp.stack([film.central, film.minimum]), (film.converged, film.residual, jnp.min(film.thickness))

    (values, (converged, residual, lowest)), (slopes, _) = jax.jit(lambda w: jax.jvp(solve, (w,), (1.0,)))(load)
    assert bool(converged) == (float(residual) < 1e-10 and float(lowest) > 0)
    assert bool(jnp.all(jnp.isfinite(values))) and bool(jnp.all(jnp.isfinite(slopes)))
