"""The `diffbearing` command: runs, JSON, --set, plots, one-line errors with exit code 2 (bad input)
and 3 (a result outside the model), warnings of limits passed."""

import dataclasses
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli, registry, stored_models
from diffbearing.app.compilation_cache import compilation_cache_folder

from .helpers import BEARING_6411E, example_scene


def run_cli(capsys, *arguments):
    code = cli.main(list(arguments))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_default_run_prints_report(capsys, monkeypatch):
    """On a terminal, the first run announces its compilation on stderr (blocks, then seconds)."""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    code, out, err = run_cli(capsys, "run")
    assert code == 0, err
    assert err.startswith("diffbearing: compiling program 1 of 1 (raceway_contact, equilibrium, stiffness, life; ")
    assert err.endswith(" s\n") and err.count("\n") == 1
    assert "Aero-engine angular-contact ball bearing" in out
    assert "free contact angle α0" in out and "deg" in out
    assert "load–deflection constant K" in out and "N/mm^1.5" in out
    assert "Equilibrium solver: converged" in out and "Stiffness K = dF/dΔ" in out


def test_json_has_documented_keys_in_si(capsys, tmp_path, monkeypatch):
    """(and the model compiled in this process for the last test is reused: nothing on stderr)"""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    path = tmp_path / "out.json"
    code, _, err = run_cli(capsys, "run", "--json", str(path))
    assert code == 0 and err == "", err
    document = json.loads(path.read_text())
    assert document["geometry"]["free_contact_angle"] == pytest.approx(np.radians(25), rel=1e-14)
    assert document["geometry"]["radial_clearance"] == pytest.approx(2 * 0.98e-3 * (1 - np.cos(np.radians(25))), rel=1e-12)
    assert set(document["hertz"]["inner"]) == {"curvature_sum", "curvature_difference", "ellipticity",
                                              "load_deflection_constant", "static_limit_load"}
    assert document["timing"]["compile_s"] >= 0 and document["timing"]["run_s"] > 0  # 0: compiled model reused


def test_set_overrides_values(capsys, tmp_path):
    path = tmp_path / "out.json"
    code, _, err = run_cli(capsys, "run", "--set", "bearing.contact_angle=30 deg", "--set",
                           'operating.force=["0 N", "0 N", "5 kN"]', "--set", 'operating.moment=[0, 0]',
                           "--set", "operating.inner_speed=3000 rpm",
                           "--json", str(path))
    assert code == 0, err
    document = json.loads(path.read_text())
    assert document["geometry"]["free_contact_angle"] == pytest.approx(np.radians(30), rel=1e-14)
    # pure axial load: every ball carries Fz / (Z sin αi); 3000 r/min doubles the orbital speed of 1500
    inner = document["balls"]["inner"]
    assert sum(q * np.sin(a) for q, a in zip(inner["load"], inner["contact_angle"])) == pytest.approx(5e3, rel=1e-9)
    # axisymmetric load: every ball orbits alike, between ω(1 − Dw/dm)/2 and ω/2
    orbital = np.array(document["balls"]["orbital_speed"])
    np.testing.assert_allclose(orbital, orbital[0], rtol=1e-9)
    omega = 3000 * np.pi / 30
    assert omega * (1 - 28 / 252) / 2 < orbital[0] < omega / 2


def test_plot_is_written(capsys, tmp_path):
    path = tmp_path / "plot.png"
    code, _, err = run_cli(capsys, "run", "--plot", str(path))
    assert code == 0, err
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("override, named", [
    ("bearing.pitch_diameter=97.5 N", "bearing.pitch_diameter: '97.5 N' is not a length"),
    ("bearing.ball_diamter=3", "unknown key 'bearing.ball_diamter' (did you mean 'bearing.ball_diameter'?)"),
    ("bearing.balls=2", "bearing.balls must be an integer ≥ 3"),
    ("bearing.inner_groove_radius=13 mm", "bearing.inner_groove_radius must be > 0.014 m"),
    ("bearing.ball_diameter=nan", "bearing.ball_diameter: nan is not a finite number"),
    ("bearing.ball_diameter=-28 mm", "bearing.ball_diameter must be > 0 m"),
    ("bearing.pitch_diameter=150 mm", "so that the balls fit on the pitch circle"),
    ("effects.film=\"sommerfeld\"", "effects.film: expected one of"),
    ("operating.force=[1, 2]", "operating.force: expected a list of 3 force values"),
    ("bearing.type=\"thrust\"", "bearing.type: expected one of"),
    ('operating.radial_displacement=["5 µm", "0 µm"]', "operating.force: Fx and Fy must be 0"),
])
def test_bad_input_exits_2_naming_the_key(capsys, override, named):
    code, out, err = run_cli(capsys, "run", "--set", override)
    assert code == 2
    assert named in err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_missing_required_key_and_unknown_table(capsys, tmp_path):
    scene = tmp_path / "scene.toml"
    scene.write_text('[bearing]\ntype = "deep_groove_ball"\nball_diameter = "10 mm"\npitch_diameter = "50 mm"\n'
                     'balls = 9\ninner_groove_ratio = 0.52\nouter_groove_ratio = 0.53\n')
    code, _, err = run_cli(capsys, "run", str(scene))
    assert code == 2 and "missing required key: one of 'bearing.contact_angle', 'bearing.radial_clearance'" in err
    scene.write_text('[bearings]\ntype = "deep_groove_ball"\n')
    code, _, err = run_cli(capsys, "run", str(scene))
    assert code == 2 and "unknown table '[bearings]' (did you mean '[bearing]'?)" in err
    code, _, err = run_cli(capsys, "run", str(tmp_path / "absent.toml"))
    assert code == 2 and "scene file not found" in err


def test_packaged_6411e_scene_runs(capsys):
    code, out, err = run_cli(capsys, "run", example_scene("deep_groove_6411"))
    assert code == 0, err
    assert "9.2248" in out  # α0 [deg] from the 28 µm clearance (paper: 9.23°)


def test_effects_not_named_are_never_traced(monkeypatch):
    """A block is called (hence traced) only when the scene names its effect."""
    ball = registry.ADAPTERS["ball"]
    real = next(block for block in ball.blocks if block.name == "stiffness")
    calls = []

    def spy(inputs, settings, results):
        calls.append(1)
        return real.compute(inputs, settings, results)

    blocks = tuple(dataclasses.replace(b, compute=spy) if b is real else b for b in ball.blocks)
    monkeypatch.setitem(registry.ADAPTERS, "ball", dataclasses.replace(ball, blocks=blocks))
    monkeypatch.setattr(registry, "_COMPILED", {})  # no compiled model from an earlier test
    monkeypatch.setattr(stored_models, "_folder", lambda: None)  # nor one stored on disk
    off = run_model(build_model(load_scene(overrides=["effects.stiffness=false"])))
    assert calls == [] and "stiffness" not in off.values
    on = run_model(build_model(load_scene(overrides=["effects.stiffness=true"])))
    assert calls == [1] and on.values["stiffness"].shape == (5, 5)
    assert [b.name for b in on.model.blocks] == ["raceway_contact", "equilibrium", "stiffness", "life"]


def test_speed_effect_outputs_only_when_named():
    values = run_model(build_model(load_scene(overrides=["effects.centrifugal=false", "effects.gyroscopic=false",
                                                         "effects.stiffness=false"]))).values
    assert "balls.centrifugal_force" not in values and "balls.gyroscopic_moment" not in values


def test_float32_is_refused():
    code = ("import jax\nfrom diffbearing import point_contact\n"
            "try:\n    point_contact(1.0, 100.0, 0.5, 2e11)\nexcept RuntimeError as e:\n    print(e)\n")
    output = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "diffbearing needs float64" in output


def test_console_script_exit_code(tmp_path):
    completed = subprocess.run([sys.executable, "-m", "diffbearing.app.cli", "run", "--set", "bearing.balls=1"],
                               capture_output=True, text=True)
    assert completed.returncode == 2
    assert completed.stderr.strip() == "diffbearing: error: bearing.balls must be an integer ≥ 3, got 1"


def test_reference_is_generated_from_the_adapters():
    """docs/reference.md is what `python -m diffbearing.app.reference` writes: every scene key and
    output of the code, no more."""
    from pathlib import Path

    from diffbearing.app.reference import generate

    written = (Path(__file__).resolve().parents[1] / "docs" / "reference.md").read_text()
    assert written == generate(), "regenerate: python -m diffbearing.app.reference > docs/reference.md"


DEEP_GROOVE_6411E = 'title = "6411E deep-groove ball bearing"\n' + BEARING_6411E + """
[operating]
inner_speed = "0 rpm"
force = ["0 N", "0 N", "10 kN"]
moment = ["0 N*m", "0 N*m"]
"""


@pytest.fixture(scope="module")
def scene_6411E(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenes") / "6411E.toml"
    path.write_text(DEEP_GROOVE_6411E)
    return str(path)


def test_load_beyond_the_model_exits_3_with_one_line(capsys, scene_6411E, tmp_path):
    """A typo (1e9 N for 1e3 N) pushes the balls through the raceways: the solver's residual is small,
    but the state is outside the model (an approach of 2 D_w; the loaded contacts stay at α = 0, the
    far balls' grooves face away from them); the report says so, the CLI prints one line and exits 3."""
    path = tmp_path / "out.json"
    code, out, err = run_cli(capsys, "run", scene_6411E, "--set", 'operating.force=["1e9 N", "0 N", "0 N"]',
                             "--json", str(path))
    assert code == 3
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("diffbearing: error: equilibrium outside the model: ")
    assert "passes the limit of 1 % of Dw" in lines[0]
    assert "converged to a state OUTSIDE THE MODEL" in out
    document = json.loads(path.read_text())
    assert document["converged"] is False
    assert len(document["errors"]) == 1 and document["validity"]["approach_ratio"] > 0.01
    assert abs(document["validity"]["contact_angle"]) < 1e-9


def test_peak_pressure_above_iso76_runs_with_a_warning(capsys, scene_6411E, tmp_path):
    """Fr = 100 kN on the 6411E: p0 ≈ 4.5 GPa at the inner raceway, inside the model (exit 0) but above
    the ISO 76 static limit of 4.2 GPa: one warning, in the report and in the JSON."""
    path = tmp_path / "out.json"
    code, out, err = run_cli(capsys, "run", scene_6411E, "--set", 'operating.force=["100 kN", "0 N", "0 N"]',
                             "--json", str(path))
    assert code == 0, err
    document = json.loads(path.read_text())
    assert document["converged"] is True and document["errors"] == []
    assert 4.4e9 < max(document["balls"]["inner"]["max_pressure"]) < 4.6e9
    (warning,) = document["warnings"]
    assert warning.startswith("peak contact pressure 4.") and "(inner raceway, ball 0)" in warning
    assert "exceeds the ISO 76 static limit 4.2 GPa" in warning and warning in out


def test_both_aero_scenes_run_and_agree(capsys, tmp_path):
    """The packaged aero-engine angular-contact scenes (d_m = 252 mm) run through the CLI: the
    built-in example at 1500 r/min and the 201-point speed sweep to 20000 r/min, every point
    converged. The sweep's 1500 r/min point is the same computation as the example (same load):
    displacement and stiffness agree to 1e-10."""
    single_path, sweep_path = tmp_path / "single.json", tmp_path / "sweep.json"
    code, _, err = run_cli(capsys, "run", example_scene("aero_angular_contact"), "--json", str(single_path))
    assert code == 0, err
    code, out, err = run_cli(capsys, "run", example_scene("aero_speed_sweep"), "--json", str(sweep_path))
    assert code == 0, err
    assert "Sweep over 201 points" in out
    single, sweep = json.loads(single_path.read_text()), json.loads(sweep_path.read_text())
    assert single["converged"] is True and all(sweep["converged"])
    speeds = np.array(sweep["sweep"]["operating.inner_speed"])
    (index,) = np.flatnonzero(np.isclose(speeds, 1500 * np.pi / 30, rtol=1e-12))
    for key in ("displacement", "stiffness"):
        np.testing.assert_allclose(np.array(sweep[key][index]), np.array(single[key]), rtol=1e-10,
                                   atol=1e-10 * np.abs(np.array(single[key])).max())


# --- examples and bad input a new user tries ----------------------------------------------------

def test_examples_lists_every_packaged_scene(capsys):
    from diffbearing import examples

    code, out, _ = run_cli(capsys, "examples")
    listed = examples()
    assert code == 0 and set(listed) == {"aero_angular_contact", "aero_speed_sweep", "deep_groove_6411", "cage_b7005",
                                         "starved_roller", "tapered_roller", "tapered_roller_bearing",
                                         "cylindrical_roller_bearing", "mounted_6411", "spindle_pair", "gearbox_shaft",
                                         "gearbox_6411_ratings", "flexible_shaft", "double_row_pulley",
                                         "slewing_ring", "self_aligning_shaft", "thrust_ball_shaft",
                                         "needle_roller_shaft", "thrust_roller_shaft",
                                         "spherical_roller_shaft", "gearbox_duty_cycle",
                                         "gearbox_shaft_duty_cycle", "designation_6205", "gearbox_6411_thermal_speed",
                                         "spindle_pair_thermal", "spindle_shaft_thermal", "motor_6205_grease"}
    for name, description in listed.items():
        assert description and f"{name}" in out and description in out
    assert "aero_angular_contact" in next(line for line in out.splitlines() if "(default)" in line)


@pytest.mark.parametrize("name", ["aero_angular_contact", "aero_speed_sweep", "deep_groove_6411", "cage_b7005",
                                  "tapered_roller", "tapered_roller_bearing", "cylindrical_roller_bearing",
                                  "mounted_6411", "gearbox_6411_ratings", "motor_6205_grease",
                                  pytest.param("starved_roller", marks=(pytest.mark.slow, pytest.mark.extended)),
                                  pytest.param("spindle_pair", marks=pytest.mark.slow),
                                  pytest.param("gearbox_shaft", marks=pytest.mark.slow),
                                  pytest.param("flexible_shaft", marks=pytest.mark.slow),
                                  pytest.param("double_row_pulley", marks=pytest.mark.slow),
                                  pytest.param("slewing_ring", marks=pytest.mark.slow),
                                  pytest.param("self_aligning_shaft", marks=pytest.mark.slow),
                                  pytest.param("thrust_ball_shaft", marks=pytest.mark.slow),
                                  pytest.param("needle_roller_shaft", marks=pytest.mark.slow),
                                  pytest.param("thrust_roller_shaft", marks=pytest.mark.slow),
                                  pytest.param("spherical_roller_shaft", marks=pytest.mark.slow),
                                  pytest.param("gearbox_6411_thermal_speed", marks=pytest.mark.slow),
                                  pytest.param("spindle_pair_thermal", marks=pytest.mark.slow),
                                  pytest.param("spindle_shaft_thermal", marks=(pytest.mark.slow, pytest.mark.extended))])
def test_every_example_runs_by_name(capsys, tmp_path, name):
    """`diffbearing run NAME` runs each packaged example to exit 0 and writes its JSON."""
    path = tmp_path / "out.json"
    code, out, err = run_cli(capsys, "run", name, "--json", str(path))
    assert code == 0, err
    assert f"scene: example {name}" in out
    assert json.loads(path.read_text())["errors"] == []


def test_json_into_a_missing_folder_exits_2_before_computing(capsys, tmp_path):
    import time

    start = time.perf_counter()
    code, out, err = run_cli(capsys, "run", "--json", str(tmp_path / "no" / "such" / "folder" / "out.json"))
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "--json" in err and "does not exist" in err
    assert time.perf_counter() - start < 5.0  # refused before the model is built or compiled


@pytest.mark.parametrize("override, named", [
    ('lubricant.viscosity="-0.01 Pa*s"', "lubricant.viscosity must be > 0"),
    ("cage.eccentricity=2", "cage.eccentricity must be ≥ 0 and ≤ 1"),
])
def test_bad_values_name_their_key(capsys, override, named):
    code, out, err = run_cli(capsys, "run", "cage_b7005", "--set", override)
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err


def test_a_key_nothing_reads_is_refused(capsys):
    """The default example has no film effect: a lubricant given to it would be silently unused."""
    code, _, err = run_cli(capsys, "run", "--set", 'lubricant.preset="iso_vg_32"')
    assert code == 2 and "'lubricant.preset' not read by anything this scene runs" in err


def test_persistent_compilation_cache_folder(monkeypatch, tmp_path):
    monkeypatch.setenv("DIFFBEARING_CACHE", str(tmp_path))
    assert compilation_cache_folder() == str(tmp_path)
    monkeypatch.setenv("DIFFBEARING_CACHE", "off")
    assert compilation_cache_folder() is None
    monkeypatch.delenv("DIFFBEARING_CACHE")
    assert compilation_cache_folder().endswith(".cache/diffbearing/jax")


# a fresh process: run_model, then where its compiled programs went
_CACHED_RUN = """
import sys
import jax
jax.config.update("jax_enable_x64", True)
if len(sys.argv) > 1:
    jax.config.update("jax_compilation_cache_dir", sys.argv[1])
from diffbearing import build_model, load_scene, run_model
run_model(build_model(load_scene("tapered_roller")))
print(jax.config.jax_compilation_cache_dir)
"""


@pytest.mark.parametrize("setting", ["folder", "off", "own"])
def test_run_model_keeps_its_programs_in_the_cache_unless_told_otherwise(tmp_path, setting):
    """From Python, `run_model` keeps the compiled programs in DIFFBEARING_CACHE (not at import); with
    DIFFBEARING_CACHE=off nowhere; a cache folder the user set for JAX is used as it is."""
    ours, own = tmp_path / "ours", tmp_path / "own"
    env = {key: value for key, value in os.environ.items() if not key.startswith("JAX_")}
    env["DIFFBEARING_CACHE"] = "off" if setting == "off" else str(ours)
    done = subprocess.run([sys.executable, "-c", _CACHED_RUN] + ([str(own)] if setting == "own" else []),
                          env=env, capture_output=True, text=True, check=True)
    used = done.stdout.strip().splitlines()[-1]
    assert used == {"folder": str(ours), "off": "None", "own": str(own)}[setting]
    assert (ours.is_dir() and any(ours.iterdir())) == (setting == "folder")
    assert (own.is_dir() and any(own.iterdir())) == (setting == "own")


def test_build_model_switches_the_cache_on_for_the_input_builders(tmp_path):
    """`build_model` alone (the mounted bearing's fits and temperatures are array operations that
    compile) keeps its programs in DIFFBEARING_CACHE, for a later process to load."""
    env = {key: value for key, value in os.environ.items() if not key.startswith("JAX_")}
    env["DIFFBEARING_CACHE"] = str(tmp_path / "ours")
    code = ("import jax; jax.config.update('jax_enable_x64', True)\n"
            "from diffbearing import build_model, load_scene; build_model(load_scene('mounted_6411'))")
    subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert any((tmp_path / "ours").glob("jit_*-cache"))  # JAX's entries (pint keeps its units in pint/)


def test_a_setting_of_another_level_is_a_warning(capsys, tmp_path):
    """The starved-roller example's grid belongs to the finite line level: switched to the film
    formula by --set, the run goes on and the report says the grid is not used."""
    path = tmp_path / "formula.json"
    code, out, err = run_cli(capsys, "run", "starved_roller", "--set", 'effects.film="formula"', "--json", str(path))
    assert code == 0, err
    warning = "fidelity.grid is not used by this scene's effects"
    assert warning in out and any(warning in line for line in json.loads(path.read_text())["warnings"])


def test_a_solver_that_does_not_converge_exits_3(capsys):
    """A tolerance no conjugate-gradient run reaches (1e-300): the contact solve stops at its
    iteration limit, the report says so, and the run ends with one line and exit code 3."""
    code, out, err = run_cli(capsys, "run", "tapered_roller", "--set", "fidelity.tolerance=1e-300")
    assert code == 3 and "DID NOT CONVERGE" in out
    assert err.strip() == ("diffbearing: error: the roller contact solution (influence; or its loaded zone reached "
                           "the grid's edge) did not converge (its outputs are the last iterate)")


def test_rating_effects_only_when_named():
    """The default scene names none of safety, frequencies, friction or a cleanliness: none of their
    blocks is in its model; naming them adds exactly theirs."""
    rating_blocks = {"safety", "frequencies", "friction", "modified_life"}
    plain = {block.name for block in build_model(load_scene()).blocks}
    assert not plain & rating_blocks
    named = build_model(load_scene(overrides=["effects.safety=true", "effects.frequencies=true",
                                              "effects.friction=palmgren", "lubricant.preset=iso_vg_68",
                                              "lubricant.temperature=60 degC", "lubricant.cleanliness=high"]))
    assert {block.name for block in named.blocks} - plain == rating_blocks


def test_switching_an_effect_off_by_set_leaves_its_keys_as_a_warning(capsys):
    """The ratings example with its life effect switched off: the cleanliness that only a_ISO reads
    is reported unread, the run goes on; the same key added by --set to a scene that never reads it
    is still refused."""
    code, out, err = run_cli(capsys, "run", "gearbox_6411_ratings", "--set", "effects.life=false")
    assert code == 0, err
    assert "lubricant.cleanliness is not read with effects.life as set (the scene file's effects read it)" in out
    code, _, err = run_cli(capsys, "run", "--set", 'lubricant.preset="iso_vg_68"')
    assert code == 2 and "'lubricant.preset' not read by anything" in err


@pytest.mark.parametrize("override, expected", [
    ("sweep.operating.inner_speed.num=3", {"start": "0 rpm", "stop": "20000 rpm", "num": 3}),
    ('sweep."operating.inner_speed".stop="100 Hz"', {"start": "0 rpm", "stop": "100 Hz", "num": 201}),
    ('sweep.operating.inner_speed={start = "1 rpm", stop = "2 rpm", num = 2}', {"start": "1 rpm", "stop": "2 rpm", "num": 2}),
])
def test_set_reaches_the_sweep_table(override, expected):
    scene = load_scene("aero_speed_sweep", [override])
    assert scene.sweep == {"operating.inner_speed": expected}
    axis = build_model(scene).sweep_axes["operating.inner_speed"]
    assert axis.shape == (expected["num"],)


@pytest.mark.parametrize("override, named", [
    ("sweep.operating.inner_sped.num=3", "unknown key 'operating.inner_sped' (did you mean 'operating.inner_speed'?)"),
    ("sweep.operating.force.num=3", "the scene has no {start, stop, num} sweep of operating.force"),
])
def test_a_bad_sweep_override_exits_2(capsys, override, named):
    code, _, err = run_cli(capsys, "run", "aero_speed_sweep", "--set", override)
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err
