"""Closed-form EHL film thickness (fidelity "formula") and the ball-bearing film effect."""

import functools
import json
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.app import cli
from diffbearing.film.film_formulas import dowson_higginson_line_minimum, hamrock_dowson_point, pan_hamrock_line

from .helpers import assert_jvp_matches_central_difference, example_scene

# The starved-EHL paper (docs/papers.md §The starved-EHL paper): roller radius 12.7 mm on an outer
# raceway of radius 66 mm, straight length 12.7 mm, W = 1028 N, E' = 2.26e11 Pa, η0 = 0.08 Pa·s, α = 2.2e-8 1/Pa, inner ring at
# 1000 r/min with the outer ring fixed: pitch diameter 106.6 mm, roller diameter 25.4 mm.
STARVED_EHL = dict(radius=1 / (1 / 12.7e-3 - 1 / 66e-3), viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
STARVED_EHL_LOAD_PER_LENGTH = 1028.0 / 12.7e-3


def starved_ehl_entrainment_speed():
    """Pure rolling, outer ring fixed: u = (d_m/4)(1 − γ²) ω_i, γ = D/d_m (Harris & Kotzalas ch. 8)."""
    pitch, diameter, speed = 106.6e-3, 25.4e-3, 1000 * np.pi / 30
    return pitch / 4 * (1 - (diameter / pitch) ** 2) * speed


def test_pan_hamrock_central_film_is_consistent_with_starved_ehl_paper():
    """docs/papers.md §The starved-EHL paper: the starved-EHL paper's fully flooded central film is 1.207 µm (numerical), and
    the closed-form line formulas give about 1.2 µm; Pan–Hamrock within 5 %."""
    central, minimum = pan_hamrock_line(STARVED_EHL_LOAD_PER_LENGTH, speed=starved_ehl_entrainment_speed(), **STARVED_EHL)
    assert float(central) == pytest.approx(1.207e-6, rel=0.05)
    assert float(minimum) < float(central)
    # Dowson–Higginson's minimum film agrees with Pan–Hamrock's within 20 % in this regime
    assert float(dowson_higginson_line_minimum(STARVED_EHL_LOAD_PER_LENGTH, speed=starved_ehl_entrainment_speed(),
                                               **STARVED_EHL)) == pytest.approx(float(minimum), rel=0.2)


def test_hamrock_dowson_exponents_and_ellipticity_factor():
    """Exact identities of the formula: h_c ∝ u^0.67 η0^0.67 Q^−0.067, h_min ∝ u^0.68 Q^−0.073; the
    ellipticity factors (1 − 0.61 e^{−0.73k}) and (1 − e^{−0.68k})."""
    base = dict(load=2000.0, radius_rolling=6e-3, ellipticity=5.0, speed=8.0, viscosity=0.03,
                pressure_viscosity=2e-8, effective_modulus=2.3e11)
    central, minimum = (float(v) for v in hamrock_dowson_point(**base))
    central2, minimum2 = (float(v) for v in hamrock_dowson_point(**(base | {"speed": 16.0, "load": 4000.0})))
    assert central2 / central == pytest.approx(2**0.67 * 2**-0.067, rel=1e-12)
    assert minimum2 / minimum == pytest.approx(2**0.68 * 2**-0.073, rel=1e-12)
    central3, minimum3 = (float(v) for v in hamrock_dowson_point(**(base | {"ellipticity": 1.0})))
    assert central3 / central == pytest.approx((1 - 0.61 * np.exp(-0.73)) / (1 - 0.61 * np.exp(-3.65)), rel=1e-12)
    assert minimum3 / minimum == pytest.approx((1 - np.exp(-0.68)) / (1 - np.exp(-3.4)), rel=1e-12)
    assert float(hamrock_dowson_point(**(base | {"speed": 0.0}))[0]) == 0.0  # no entrainment, no film


@pytest.mark.parametrize("formula", ["hamrock_dowson", "pan_hamrock"])
def test_film_derivatives_match_central_differences(formula):
    def film(x):  # (load [kN], speed [m/s], viscosity [Pa·s]) → films [µm]
        if formula == "hamrock_dowson":
            out = hamrock_dowson_point(x[0] * 1e3, 6e-3, 5.0, x[1], x[2], 2e-8, 2.3e11)
        else:
            out = pan_hamrock_line(x[0] * 1e3 / 12.7e-3, STARVED_EHL["radius"], x[1], x[2], 2.2e-8, 2.26e11)
        return jnp.stack(out) * 1e6

    point = jnp.array([1.028, 2.63, 0.08])
    for direction in jnp.eye(3):
        assert_jvp_matches_central_difference(jax.jit(film), point, direction, step=1e-5, rtol=1e-7)


def test_ball_film_effect_reports_null_for_unloaded_balls(capsys, tmp_path):
    """The 6411E chamfer paper's bearing under a radial load leaves balls unloaded: their films are null in JSON;
    loaded balls have h_min < h_c, and Λ = h_min/σ."""
    path = tmp_path / "film.json"
    code = cli.main(["run", example_scene("deep_groove_6411"), "--json", str(path),
                     "--set", 'operating.force=["8 kN", "0 N", "0 N"]', "--set", 'operating.inner_speed="3000 rpm"',
                     "--set", 'effects.film="hamrock_dowson"', "--set", 'lubricant.preset="iso_vg_68"',
                     "--set", 'material.roughness="0.2 um"'])
    out = capsys.readouterr().out
    assert code == 0 and "hmin,i [µm]" in out
    document = json.loads(path.read_text())
    loads = np.array(document["balls"]["inner"]["load"])
    for side in ("inner", "outer"):
        film = document["film"][side]
        unloaded = np.array([value is None for value in film["minimum"]])
        assert np.array_equal(unloaded, np.array(document["balls"][side]["load"]) == 0) and unloaded.any()
        central = np.array([c for c in film["central"] if c is not None])
        minimum = np.array([m for m in film["minimum"] if m is not None])
        assert np.all(minimum > 0) and np.all(minimum < central)
        parameter = np.array([p for p in film["film_parameter"] if p is not None])
        np.testing.assert_allclose(parameter, minimum / 0.2e-6, rtol=1e-12)
    assert loads.max() > 0


@pytest.mark.extended
@pytest.mark.slow  # about a minute (2 cores): two point-contact solves
def test_point_contact_film_at_the_most_loaded_balls_through_the_cli(capsys, tmp_path):
    """effects.film = "point" on the 6411E bearing under 8 kN radial load at 3000 r/min: both
    point-contact solves converge at the most loaded ball (on the load line) on the default grid
    (129 × 64 on the half), within 15 % of Hamrock–Dowson at the same ball (on that grid the
    numerical central films lie 8–12 % below it: docs/validation/lubricant_film.md §The point
    contact), with h_min < h_c; the report names the level."""
    path = tmp_path / "point.json"
    code = cli.main(["run", example_scene("deep_groove_6411"), "--json", str(path),
                     "--set", 'operating.force=["8 kN", "0 N", "0 N"]', "--set", 'operating.inner_speed="3000 rpm"',
                     "--set", 'effects.film="point"', "--set", 'lubricant.preset="iso_vg_68"'])
    out = capsys.readouterr().out
    assert code == 0 and "point contact EHL (inner, Newton–Krylov, 129 × 64 half-domain grid): converged" in out
    document = json.loads(path.read_text())
    loads = np.array(document["balls"]["inner"]["load"])
    for side in ("inner", "outer"):
        film = document["film"][side]
        assert film["converged"] is True and film["ball"] == int(np.argmax(loads))
        assert film["central"] == pytest.approx(film["hamrock_dowson_central"], rel=0.15)
        assert 0 < film["minimum"] < film["central"]
        assert np.shape(film["pressure"]) == (129, 64)


def test_ball_film_grows_with_speed_and_needs_a_lubricant(capsys):
    films = []
    for speed in ("1500 rpm", "6000 rpm"):
        code = cli.main(["run", "--set", 'effects.film="hamrock_dowson"', "--set", 'lubricant.preset="iso_vg_32"',
                         "--set", f'operating.inner_speed="{speed}"', "--set", "effects.stiffness=false",
                         "--set", "effects.life=false"])
        out = capsys.readouterr().out
        assert code == 0
        row = next(line for line in out.splitlines() if line.strip().startswith("0 "))
        films.append(float(row.split()[-2]))  # h_c,o of ball 0 [µm]
    assert films[1] > films[0] * 2.0  # h ∝ u^0.67: 4× the speed → about 2.5× the film (less with Fc)
    code = cli.main(["run", "--set", 'effects.film="hamrock_dowson"'])
    err = capsys.readouterr().err
    assert code == 2 and "lubricant" in err


# --- numerical line contact (1-D) -------------------------------------------------------------

from diffbearing.film.line_ehl import line_film, moes_load_parameter  # noqa: E402

STARVED_EHL_LINE = dict(radius=STARVED_EHL["radius"], viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)


@pytest.fixture(scope="module")
def starved_ehl_line_films():
    """The starved-EHL paper's flooded contact as a line contact (Roelands, Dowson–Higginson) at 129 … 513 nodes."""
    speed = starved_ehl_entrainment_speed()
    return {nodes: jax.jit(lambda w: line_film(w, speed=speed, nodes=nodes, **STARVED_EHL_LINE))(STARVED_EHL_LOAD_PER_LENGTH)
            for nodes in (129, 257, 513)}


def test_line_ehl_reproduces_starved_ehl_paper_flooded_central_film(starved_ehl_line_films):
    """docs/papers.md §The starved-EHL paper: fully flooded central film 1.207 µm (the starved-EHL
    paper, 2-D numerical); the 1-D line contact at mid-length within 5 %, grid-converged to 0.5 %
    from 129 to 513 nodes, h_min < h_c; the cavitated zone's pressure is zero to rounding (the Fischer–Burmeister equation)."""
    finest = starved_ehl_line_films[513]
    assert bool(finest.converged)
    assert float(finest.central) == pytest.approx(1.207e-6, rel=0.05)
    assert float(starved_ehl_line_films[129].central) == pytest.approx(float(finest.central), rel=5e-3)
    assert 0 < float(finest.minimum) < float(finest.central)
    pressure = np.asarray(finest.pressure)
    assert np.all(pressure >= -1e-12 * pressure.max()) and pressure.sum() * float(finest.x[1] - finest.x[0]) == pytest.approx(
        STARVED_EHL_LOAD_PER_LENGTH, rel=1e-10)  # load balance is one of the equations


def test_line_ehl_derivatives_match_central_differences():
    """Implicit derivative (lax.custom_root) of central and minimum film with respect to load,
    speed, viscosity and α, forward and reverse, against central differences."""
    def films(x):  # (w [1e5 N/m], u [m/s], η0 [Pa·s], α [1e-8 1/Pa]) → (h_c, h_min) [µm]
        result = line_film(x[0] * 1e5, STARVED_EHL["radius"], x[1], x[2], x[3] * 1e-8, 2.26e11, nodes=129)
        return jnp.stack([result.central, result.minimum]) * 1e6

    point = jnp.array([0.80945, 2.63, 0.08, 2.2])
    function = jax.jit(films)
    for direction in jnp.eye(4):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-6)


@functools.partial(jax.jit, static_argnames="nodes")
def _central_film_and_gradient(load, speed, nodes):
    """((h_c, the film), dh_c/dw) of the starved-EHL paper's line contact at this load and speed
    (one program per grid, whatever the load and speed)."""
    def central(w):
        result = line_film(w, speed=speed, nodes=nodes, **STARVED_EHL_LINE)
        return result.central, result

    return jax.value_and_grad(central, has_aux=True)(load)


@pytest.mark.parametrize("load_factor, speed, nodes, converges", [(10.0, 0.0263, 129, False), (10.0, 0.0263, 257, True),
                                                                   (1.0, 0.001, 129, False), (1.0, 0.001, 257, True)])
def test_line_ehl_hard_cases_converge_or_say_so(load_factor, speed, nodes, converges):
    """High load (Moes M ≈ 200) and very low speed (M ≈ 100), continued in M from 10: values and
    gradients are finite. At such M the 129-node grid is too coarse — its discrete solution has a
    negative film, and the result says it did not converge; 257 nodes give a positive film."""
    load = STARVED_EHL_LOAD_PER_LENGTH * load_factor
    assert float(moes_load_parameter(load, STARVED_EHL["radius"], speed, 0.08, 2.26e11)) > 100
    (value, result), gradient = _central_film_and_gradient(load, speed, nodes)
    assert np.all(np.isfinite(np.asarray(result.pressure))) and np.isfinite(float(value))
    assert np.isfinite(float(gradient)) and float(result.residual) < 1e-10
    assert bool(result.converged) == converges == (float(result.minimum) > 0)


@pytest.mark.parametrize("level, expected, tolerance", [("formula", 1.2389e-6, 1e-3),
                                                        pytest.param("line", 1.207e-6, 0.05, marks=pytest.mark.slow)])
def test_starved_ehl_paper_flooded_and_starved_film_through_the_cli(capsys, tmp_path, level, expected, tolerance):
    """`diffbearing run starved_roller --set effects.film=...`: Pan–Hamrock (1.2389 µm, this formula's
    value) and the numerical line contact against the paper's flooded 1.207 µm within 5 %. The
    scene's starvation (h_oil = 0.8 µm) gives a film below the supply over the density ratio
    (mass conservation: ρ̄h_c ≈ h_oil, ρ̄ = 1.10–1.15 in the Hertz zone) and Er > 1 %."""
    path = tmp_path / "film.json"
    code = cli.main(["run", example_scene("starved_roller"), "--set", f'effects.film="{level}"',
                     "--set", "fidelity.grid=[257, 129]", "--json", str(path)])
    out = capsys.readouterr().out
    assert code == 0 and "central film h_c at x = 0" in out and "starved central film" in out
    values = json.loads(path.read_text())
    film, starvation = values["film"], values["starvation"]
    assert film["central"] == pytest.approx(expected, rel=tolerance)
    assert film["entrainment_speed"] == pytest.approx(starved_ehl_entrainment_speed(), rel=1e-12)
    assert starvation["oil_layer"] == pytest.approx(0.8e-6, rel=1e-12)
    assert 0.8e-6 / 1.16 < starvation["central"] < 0.8e-6 / 1.10
    assert starvation["relative_error"] == pytest.approx(1 - starvation["central"] / film["central"], rel=1e-12)
    if level == "line":
        assert film["converged"] is True and len(film["pressure"]) == 257 and starvation["converged"] is True
        assert film["x"][0] < starvation["meniscus"] == starvation["x"][0] < 0


@pytest.mark.slow  # 56 s with a cold compilation cache (2 cores)
def test_starved_ehl_paper_finite_line_film_through_the_cli(capsys, tmp_path):
    """The starved-EHL paper's roller at the finite line level on a 33 × 96 grid (48 cells on the half
    domain; docs/papers.md §The starved-EHL paper, 1028 N,
    1000 r/min): the flooded central film within 5 % of the paper's 1.207 µm; the minimum at the
    end constriction, just past the flat's end (6.35 mm), for both films ("minimum sits at the
    roller ends"); starved by h_oil = 0.8 µm, the minimum film within 15 % of the paper's
    0.319 µm, and at mid-length the film below the supply over the density ratio (mass
    conservation, as in the line contact); Er > 1 %; each y cell has its meniscus ahead of the
    Hertz zone or, past the crown's start, none (the upper bound: no full film forms)."""
    path = tmp_path / "finite_line.json"
    code = cli.main(["run", example_scene("starved_roller"), "--set", "fidelity.grid=[33, 96]",
                     "--json", str(path)])
    out = capsys.readouterr().out
    assert code == 0 and "finite line EHL (starved by the oil layer, a meniscus per y cell" in out
    values = json.loads(path.read_text())
    film, starvation = values["film"], values["starvation"]
    assert film["converged"] is True and starvation["converged"] is True
    assert film["central"] == pytest.approx(1.207e-6, rel=0.05)
    assert starvation["minimum"] == pytest.approx(0.319e-6, rel=0.15)
    assert 0.8e-6 / 1.16 < starvation["central"] < 0.8e-6 / 1.10 and starvation["relative_error"] > 0.01
    for case in (film, starvation):
        assert 6.35e-3 < case["minimum_position"] < 6.6e-3 and case["minimum"] < 0.6 * case["central"]
        assert np.shape(case["pressure"]) == np.shape(case["thickness"]) == (33, 48) and len(case["y"]) == 48
        assert np.min(case["pressure"]) >= -1e-9 * np.max(case["pressure"])
    meniscus, y = np.array(starvation["meniscus"]), np.array(starvation["y"])
    half_width = 111.32e-6  # Hertz b at the load per flat length (the report's)
    assert np.all(meniscus[y < 6.0e-3] < -1.2 * half_width) and np.all(meniscus[y > 6.6e-3] > 0)


def starved_ehl_default_grid_films(tmp_path, setting, raceway_edge=True):
    """(film, starvation) JSON tables of the starved-EHL paper's roller through the CLI on the 33 × 96 grid with one more
    `--set` (and without the raceway edge radius in the gap where `raceway_edge` is false), after
    checking that the run exits 0 and both Newton solves converge."""
    path = tmp_path / "starved_roller.json"
    scene = example_scene("starved_roller")
    if not raceway_edge:
        text = Path(scene).read_text()
        scene = tmp_path / "no_raceway_edge.toml"
        scene.write_text("\n".join(line for line in text.splitlines() if not line.startswith("raceway_edge_radius")))
    assert cli.main(["run", str(scene), "--set", "fidelity.grid=[33, 96]", "--set", setting, "--json", str(path)]) == 0
    values = json.loads(path.read_text())
    film, starvation = values["film"], values["starvation"]
    assert film["converged"] is True and starvation["converged"] is True
    return film, starvation


@pytest.mark.slow
@pytest.mark.parametrize("load, paper_minimum, raceway_edge", [
    (1607.0, 0.215e-6, True), pytest.param(2471.0, 0.159e-6, False, marks=pytest.mark.extended)])
def test_starved_ehl_paper_heavier_loads_through_the_cli(tmp_path, load, paper_minimum, raceway_edge):
    """The starved-EHL paper's roller starved by h_oil = 0.8 µm at the paper's two heavier loads on a 33 × 96 grid: both
    Newton solves converge (at 2471 N through the load continuation), the starved minimum film is
    within 15 % of the paper's (docs/papers.md §The starved-EHL paper: 0.215 µm at 1607 N, 0.159 µm at 2471 N) and sits at
    the roller end, past the flat's end (6.35 mm). This agreement holds on this grid only: at
    1607 N the resolved end minimum is 0.281 µm, +31 % (`benchmarks/finite_line_grid.py`, cells
    clustered at the flat's end), and it agrees at the supply that the paper's own starvation
    criterion implies, 0.68 to 0.76 of the stated layer (`benchmarks/finite_line_supply.py`;
    docs/validation/lubricant_film.md §The supply the paper's numbers imply). At 2471 N with the
    raceway edge radius in the gap the starved Newton does not converge through the default load
    stages on this grid (docs/validation/lubricant_film.md), so that case runs without it."""
    film, starvation = starved_ehl_default_grid_films(tmp_path, f'contact.load="{load:.0f} N"', raceway_edge)
    assert starvation["minimum"] == pytest.approx(paper_minimum, rel=0.15)
    assert 6.35e-3 < starvation["minimum_position"] < 6.6e-3


@pytest.mark.extended
@pytest.mark.slow
@pytest.mark.parametrize("oil_layer", [1.8, 2.0])
def test_starved_ehl_paper_starvation_criterion_through_the_cli(tmp_path, oil_layer):
    """The starved-EHL paper's starvation criterion on a 33 × 96 grid at 1028 N: at h_oil = 2.0 and 1.8 µm both
    solves converge, and Er < 1 %. The paper has Er < 1 % at 2.0 µm and > 1 % at 1.8 µm; by mass
    conservation the middle of the roller cannot starve while the supply exceeds the ρ̄h that its
    flooded film carries (1.33 µm here), so its columns stay flooded (their menisci on the domain
    inlet) and h_c is the flooded one. The crowned ends, where the film is thinnest, do starve:
    the starved minimum film lies below the flooded one."""
    film, starvation = starved_ehl_default_grid_films(tmp_path, f'operating.oil_layer="{oil_layer} um"')
    assert 0.0 <= starvation["relative_error"] < 0.01
    middle = np.array(starvation["y"]) < 3.0e-3
    assert np.all(np.array(starvation["meniscus"])[middle] == starvation["x"][0])
    assert starvation["minimum"] < 0.95 * film["minimum"]


def test_finite_line_grid_beyond_the_dense_newton_exits_2(capsys):
    """A grid whose half domain is beyond the dense Newton ([129, 257]: 127 × 129 = 16383
    unknowns) with fidelity.solver = "dense" named exits 2 with a one-line message naming
    fidelity.grid, its limit and a grid that works."""
    assert cli.main(["run", example_scene("starved_roller"), "--set", "fidelity.grid=[129, 257]",
                     "--set", 'fidelity.solver="dense"']) == 2
    message = capsys.readouterr().err
    assert "fidelity.grid" in message and "(nx − 2)·⌈ny/2⌉ ≤ 4200" in message and "[65, 129]" in message


@pytest.mark.extended
@pytest.mark.slow
def test_starved_ehl_paper_as_published_through_the_cli(tmp_path):
    """The public scene as written (grid [65, 129]: 65 × 65 on the half domain, 1028 N,
    h_oil = 0.8 µm): both Newton solves converge; the flooded central film within 5 % of the
    paper's 1.207 µm and the starved minimum within 15 % of its 0.319 µm (docs/papers.md §The starved-EHL paper), at the
    roller end; Er > 1 % (starved at 0.8 µm)."""
    path = tmp_path / "published.json"
    assert cli.main(["run", example_scene("starved_roller"), "--json", str(path)]) == 0
    values = json.loads(path.read_text())
    film, starvation = values["film"], values["starvation"]
    assert film["converged"] is True and starvation["converged"] is True
    assert np.shape(film["pressure"]) == (65, 65)
    assert film["central"] == pytest.approx(1.207e-6, rel=0.05)
    assert starvation["minimum"] == pytest.approx(0.319e-6, rel=0.15)
    assert 6.35e-3 < starvation["minimum_position"] < 6.6e-3 and starvation["relative_error"] > 0.01


@pytest.mark.extended
@pytest.mark.slow  # about 2 minutes (2 cores): flooded and starved, each compiled
def test_newton_krylov_finite_line_through_the_cli(capsys, tmp_path):
    """The public scene with fidelity.solver = "krylov" on [65, 96] (65 × 48 uniform cells on the
    half, from a 33 × 48 dense solve): both solves converge, the report names the solver and the
    starved model it defaults to (the θ-model), the flooded central film is within 5 % of the
    paper's 1.207 µm and the starved film is thinner."""
    path = tmp_path / "krylov.json"
    code = cli.main(["run", example_scene("starved_roller"), "--json", str(path), "--set", "fidelity.grid=[65, 96]",
                     "--set", 'fidelity.solver="krylov"'])
    out = capsys.readouterr().out
    assert code == 0 and "finite line EHL (Newton–Krylov, 65 × 48 half-domain grid, fully flooded): converged" in out
    assert "finite line EHL (starved by the oil layer, the mass-conserving θ-model): converged" in out
    values = json.loads(path.read_text())
    film, starvation = values["film"], values["starvation"]
    assert film["converged"] is True and starvation["converged"] is True
    assert film["central"] == pytest.approx(1.207e-6, rel=0.05)
    assert starvation["central"] < film["central"] and starvation["relative_error"] > 0.01


def test_starvation_without_an_oil_layer_exits_2(capsys, tmp_path):
    text = Path(example_scene("starved_roller")).read_text()
    scene = tmp_path / "no_oil_layer.toml"
    scene.write_text("\n".join(line for line in text.splitlines() if not line.startswith("oil_layer")))
    code = cli.main(["run", str(scene), "--set", 'effects.film="formula"'])
    err = capsys.readouterr().err
    assert code == 2 and "effects.starvation needs operating.oil_layer" in err


@pytest.mark.slow
def test_ball_film_derivatives_match_central_differences():
    """The per-ball films of the scene model (through the implicit bearing equilibrium) with
    respect to inner-ring speed and viscosity, forward and reverse, against central differences;
    derivatives stay finite at the unloaded balls, whose film is NaN (null) by design."""
    import equinox as eqx

    from diffbearing import build_model, load_scene

    model = build_model(load_scene(example_scene("deep_groove_6411"), [
        'operating.force=["8 kN", "0 N", "0 N"]', 'operating.inner_speed="3000 rpm"', "effects.life=false",
        'effects.film="hamrock_dowson"', 'lubricant.preset="iso_vg_68"']))
    run = model.function()
    loaded = np.asarray(run(model.inputs)["balls.inner.load"]) > 0
    assert loaded.any() and not loaded.all()

    def films(x):  # (inner speed [1000 rad/s], viscosity [Pa·s]) → loaded balls' films [µm]
        inputs = eqx.tree_at(lambda i: (i["operating"].inner_speed, i["lubricant"].viscosity), model.inputs,
                             (x[0] * 1e3, x[1]))
        out = run(inputs)
        return jnp.concatenate([out[f"film.{side}.{kind}"][loaded] for side in ("inner", "outer")
                                for kind in ("central", "minimum")]) * 1e6

    point = jnp.array([float(model.inputs["operating"].inner_speed) / 1e3, float(model.inputs["lubricant"].viscosity)])
    function = jax.jit(films)
    for direction in jnp.eye(2):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-5)

    def all_films(x):
        inputs = eqx.tree_at(lambda i: i["operating"].inner_speed, model.inputs, x)
        return jnp.nansum(run(inputs)["film.inner.minimum"])

    assert np.isfinite(float(jax.jit(jax.grad(all_films))(model.inputs["operating"].inner_speed)))
