"""The starved numerical point contact (θ-model): bad input refused, the flooded limit, the
starvation trend against Chevalier's formula, implicit derivatives against central differences, and
a severe starvation that says whether it converged and stays finite."""

import json

import jax
import jax.numpy as jnp
import pytest

from diffbearing.app import cli
from diffbearing.film.film_formulas import starved_film
from diffbearing.film.line_ehl import density_ratio
from diffbearing.film.point_ehl import point_film
from diffbearing.film.starved_point_ehl import starved_point_film

from .helpers import assert_jvp_matches_central_difference, example_scene

# a circular contact: Rx = Ry = 10 mm, 50 N (p₀ 1.07 GPa), u = 1 m/s; η₀ 0.08 Pa·s, α 2.2e-8 1/Pa,
# E' 2.26e11 Pa (as tests/test_point_ehl.py)
OIL = dict(viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
CIRCLE = dict(radius_rolling=10e-3, radius_transverse=10e-3, speed=1.0)
LOAD = 50.0
COARSE = (33, 16)


def _starved(load, oil_layer, grid):
    return starved_point_film(load, **CIRCLE, **OIL, oil_layer=oil_layer, grid=grid)


def _flooded_central(grid):
    return float(jax.jit(lambda q: point_film(q, **CIRCLE, **OIL, grid=grid).central)(LOAD))


@pytest.fixture(scope="module")
def coarse_flooded():
    return _flooded_central(COARSE)


@pytest.mark.parametrize("layer, grid, match", [(-1e-6, COARSE, "oil_layer"), (1e-6, (33, 4), "grid")])
def test_bad_input_names_the_parameter(layer, grid, match):
    with pytest.raises(ValueError, match=match):
        _starved(LOAD, layer, grid)


@pytest.mark.slow
def test_a_layer_that_fills_the_inlet_is_the_flooded_film(coarse_flooded):
    """A layer of 150 µm, thicker than the gap anywhere on the inlet edge (about 36 µm at its
    centre), starves nothing: the θ-model's solution is `point_film`'s within 0.1 % (the same
    discrete equations where θ = 1 but for the wedge term's conservative face before the second
    node)."""
    solved = jax.jit(lambda layer: _starved(LOAD, layer, COARSE))(150e-6)
    assert bool(solved.film.converged)
    assert float(solved.film.central) == pytest.approx(coarse_flooded, rel=1e-3)


@pytest.mark.slow  # about 65 s (2 cores)
def test_starved_film_derivatives_match_central_differences(coarse_flooded):
    """d(h_c, h_min)/d(h_oil, Q) at a layer of twice the flooded central film on 33 × 16:
    the implicit derivatives, forward and reverse, against central differences."""

    def films(x):  # (layer [µm], load [N]) → films [µm]
        solved = _starved(x[1], 1e-6 * x[0], COARSE)
        return jnp.stack([solved.film.central, solved.film.minimum]) * 1e6

    point = jnp.array([2e6 * coarse_flooded, LOAD])
    assert bool(jax.jit(lambda x: _starved(x[1], 1e-6 * x[0], COARSE).film.converged)(point))
    for direction in jnp.eye(2):
        assert_jvp_matches_central_difference(jax.jit(films), point, direction, step=1e-4, rtol=1e-4)


@pytest.mark.slow  # a 2-D film's hard case: CI's slow suite (the default run's time)
def test_severe_starvation_says_whether_it_converged_and_stays_finite(coarse_flooded):
    """A hard case: a layer of a third of the flooded film on 33 × 16 (where the march does not reach
    the steady solution). Converged or not, the result says so by its residual, and the films and
    their layer derivatives are finite."""

    def solve(layer):
        solved = _starved(LOAD, layer, COARSE)
        return jnp.stack([solved.film.central, solved.film.minimum]), (solved.film.converged, solved.film.residual,
                                                                         jnp.min(solved.film.thickness))

    (values, (converged, residual, lowest)), (slopes, _) = jax.jit(
        lambda layer: jax.jvp(solve, (layer,), (1e-7,)))(coarse_flooded / 3.0)
    assert bool(converged) == (float(residual) <= 1e-9 and float(lowest) > 0)
    assert bool(jnp.all(jnp.isfinite(values))) and bool(jnp.all(jnp.isfinite(slopes)))


@pytest.mark.slow  # about a minute (2 cores): two solves on 129 × 64
def test_starvation_follows_chevalier():
    """On 129 × 64 (marched on 65 × 32, then the nested iteration) the starved central film over the
    flooded one at layers of 1 and ½ flooded central films: 0.702 and 0.398 (measured), against
    Chevalier, Lubrecht, Cann, Colin & Dalmaz (1998) h/h_ff = r/(1 + r^γ)^{1/γ}, r = h_oil/(ρ̄ h_ff),
    γ = 2.5, ρ̄ at p₀ = 1.07 GPa: 0.675 and 0.391, within 5 %."""
    grid = (129, 64)
    flooded = _flooded_central(grid)
    solve = jax.jit(lambda layer: _starved(LOAD, layer, grid))
    density = float(density_ratio(1.07e9))
    for ratio in (1.0, 0.5):
        solved = solve(ratio * flooded)
        assert bool(solved.film.converged)
        chevalier = float(starved_film(flooded, ratio * flooded, density, 2.5)) / flooded
        assert float(solved.film.central) / flooded == pytest.approx(chevalier, rel=0.05)
        assert 0.0 < float(solved.film.minimum) < float(solved.film.central)


SCENE_ARGUMENTS = ["--set", 'operating.force=["8 kN", "0 N", "0 N"]', "--set", 'operating.inner_speed="3000 rpm"',
                   "--set", 'effects.film="point"', "--set", "effects.starvation=true",
                   "--set", 'lubricant.preset="iso_vg_68"', "--set", "effects.stiffness=false"]


@pytest.mark.slow  # about a minute (2 cores)
def test_a_ball_scene_starved_by_a_thick_layer_is_flooded(capsys, tmp_path):
    """Through the CLI, the 6411 at 8 kN and 3000 r/min with effects.starvation and a 0.5 mm layer
    (thicker than either contact's inlet gap) on 33 × 32: the starved films are the flooded ones of
    the same contacts within 0.1 % (as the function's), and the report names the level."""
    path = tmp_path / "starved.json"
    code = cli.main(["run", example_scene("deep_groove_6411"), "--json", str(path), *SCENE_ARGUMENTS,
                     "--set", 'operating.oil_layer="0.5 mm"', "--set", "fidelity.grid=[33, 32]"])
    out = capsys.readouterr().out
    assert code == 0 and "starved point contact EHL (inner, θ-model" in out
    document = json.loads(path.read_text())
    for side in ("inner", "outer"):
        flooded, starved = document["film"][side], document["starvation"][side]
        assert starved["converged"] is True
        assert starved["central"] == pytest.approx(flooded["central"], rel=1e-3)
        assert starved["minimum"] == pytest.approx(flooded["minimum"], rel=1e-3)
        assert abs(starved["relative_error"]) < 1e-3


def test_a_ball_scene_names_the_grid_the_starved_solver_cannot_take(capsys):
    code = cli.main(["run", example_scene("deep_groove_6411"), *SCENE_ARGUMENTS, "--set", 'operating.oil_layer="1 um"',
                     "--set", "fidelity.grid=[33, 8]"])
    err = capsys.readouterr().err
    assert code == 2 and "fidelity.grid" in err and len(err.strip().splitlines()) == 1
