"""The starved finite line contact by the θ-model (Newton–Krylov): the flooded limit, the starved-EHL
paper's roller against the meniscus model, a heavy load the meniscus model does not reach, implicit
derivatives against central differences, and bad input named."""

import jax
import jax.numpy as jnp
import pytest

from diffbearing.app import cli
from diffbearing.bearings.roller.roller_profile import with_raceway_edge
from diffbearing.film.starved_finite_line import starved_finite_line_film

from .helpers import assert_jvp_matches_central_difference, example_scene
from .test_film_formulas import STARVED_EHL_LINE, starved_ehl_entrainment_speed
from .test_finite_line_krylov import PROFILE, _solve

GRID = (65, 32)  # the march grid itself (33 × 32 dense, 65 × 32 Newton–Krylov for the flooded start)


PAPERS_PROFILE = with_raceway_edge(PROFILE, 100e-3)  # seed 003's roller with its raceway's edge radius (the scene's)


def _starved(load, layer, grid=GRID, profile=PROFILE):
    return starved_finite_line_film(load, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed(), 0.08, 2.2e-8,
                                    2.26e11, profile, 14.7e-3, 12.7e-3, layer, grid=grid)


def test_bad_oil_layer_is_named():
    with pytest.raises(ValueError, match="oil_layer"):
        _starved(1028.0, -1e-6)


def test_the_theta_model_needs_the_krylov_solver(capsys):
    code = cli.main(["run", example_scene("starved_roller"), "--set", 'fidelity.starvation_model="theta"'])
    err = capsys.readouterr().err
    assert code == 2 and "fidelity.starvation_model" in err and len(err.strip().splitlines()) == 1


@pytest.mark.slow  # about 40 s (2 cores)
def test_a_layer_that_fills_the_inlet_is_the_flooded_film():
    """A 1 mm layer, thicker than the gap anywhere on the inlet edge, starves nothing: the θ-model's
    films are `finite_line_film_krylov`'s flooded ones within 0.1 % (the same discrete equations where
    θ = 1 but for the wedge term's conservative face before the second node)."""
    flooded = jax.jit(lambda load: _solve(load))(1028.0)
    solved = jax.jit(lambda layer: _starved(1028.0, layer))(1e-3)
    assert bool(flooded.converged) and bool(solved.converged)
    assert float(solved.central) == pytest.approx(float(flooded.central), rel=1e-3)
    assert float(solved.minimum) == pytest.approx(float(flooded.minimum), rel=1e-3)


@pytest.mark.slow  # about two minutes (2 cores)
def test_the_papers_roller_starved_on_129_squared():
    """On 129 × 129 under the paper's 0.8 µm: at 1028 N the central film is the meniscus model's
    (0.7008 µm on the same grid, docs/benchmarks.md §Finite line EHL by Newton–Krylov) within 0.5 %,
    the minimum film positive at the flat's end; at 2471 N on the paper's roller with its raceway
    edge, where the meniscus model's coarse grids close the film (h < 0 at the roller end) and the
    flooded film did not converge from a 33 × 33 coarsest grid, both converge with positive films
    (each solve jitted, as the CLI runs it)."""
    solve = jax.jit(lambda load, profile: _starved(load, 0.8e-6, (129, 129), profile))
    light = solve(1028.0, PROFILE)
    assert bool(light.converged)
    assert float(light.central) == pytest.approx(0.7008e-6, rel=5e-3)
    assert 0.0 < float(light.minimum) < float(light.central) and float(light.minimum_position) > 6.35e-3
    heavy = solve(2471.0, PAPERS_PROFILE)
    assert bool(heavy.converged) and 0.0 < float(heavy.minimum) < float(heavy.central)
    # jitted, as the CLI runs it: op by op this solve stalls at 129² on round-off alone
    # (docs/validation/lubricant_film.md §The θ-model by Newton–Krylov)
    flooded = jax.jit(lambda load: _solve(load, grid=(129, 129), profile=PAPERS_PROFILE))(2471.0)
    assert bool(flooded.converged) and 0.0 < float(flooded.minimum) < float(flooded.central)


@pytest.mark.slow  # about two minutes (2 cores)
def test_starved_film_derivatives_match_central_differences():
    """d(h_c, h_min)/d(h_oil, load) at 0.8 µm and 1028 N on 65 × 65 (on 65 × 32 the film closes at
    the roller end): the implicit derivatives, forward and reverse, against central differences."""

    def films(x):  # (layer [µm], load [N]) → films [µm]
        solved = _starved(x[1], 1e-6 * x[0], (65, 65))
        return jnp.stack([solved.central, solved.minimum]) * 1e6

    point = jnp.array([0.8, 1028.0])
    assert bool(jax.jit(lambda x: _starved(x[1], 1e-6 * x[0], (65, 65)).converged)(point))
    for direction in jnp.eye(2):
        assert_jvp_matches_central_difference(jax.jit(films), point, direction, step=1e-4, rtol=1e-4)
