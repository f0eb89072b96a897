"""Whole roller bearings from scenes: the two packaged examples through the CLI, checked against the
identities of their equilibrium; bad input (exit 2, one line); imposed misalignment with the moments
as outputs; the influence-coefficient re-solve; a sweep; the single-contact layout left as it was.

Each example is run once per module (fixtures); the compiled models are reused within the process."""

import contextlib
import io
import json
import math

import numpy as np
import pytest

from diffbearing import build_model, load_scene
from diffbearing.app import cli

from .helpers import example_scene


def _cli(*arguments) -> tuple[int, str, str]:
    """(exit code, stdout, stderr) of the `diffbearing` command run in this process."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(list(arguments))
    return code, out.getvalue(), err.getvalue()


def _run(folder, *arguments):
    """(exit code, report, stderr, JSON document) of `diffbearing run ... --json` (JSON in `folder`)."""
    path = folder / "out.json"
    code, out, err = _cli("run", *arguments, "--json", str(path))
    return code, out, err, (json.loads(path.read_text()) if path.is_file() else None)


@pytest.fixture(scope="module")
def tapered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("tapered")
    return _run(folder, example_scene("tapered_roller_bearing"), "--plot", str(folder / "plot.png")) + (
        folder / "plot.png",)


@pytest.fixture(scope="module")
def cylindrical(tmp_path_factory):
    folder = tmp_path_factory.mktemp("cylindrical")
    return _run(folder, example_scene("cylindrical_roller_bearing"), "--plot", str(folder / "plot.png")) + (
        folder / "plot.png",)


def _finite(document) -> bool:
    """Every number of the results is finite (NaN is written as null)."""
    def numbers(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key not in ("errors", "warnings", "not_computed", "title"):
                    yield from numbers(value)
        elif isinstance(node, list):
            for value in node:
                yield from numbers(value)
        else:
            yield node

    return all(isinstance(x, (bool, int, float)) and math.isfinite(x) for x in numbers(document))


def test_tapered_example_runs_and_balances(tapered):
    """18 rollers, 4 kN radial and 2 kN axial with the rings held aligned: exit 0; the cup's reactions
    (Q_o along n_o = (sin α_o, cos α_o)) and the cone's (Q_i along n_i plus the rib force Q_f along
    the roller axis t = (cos α_m, −sin α_m)) both sum to the applied force (an identity of the
    solved equilibrium, to the solver's tolerance); each roller's lamina loads add up to its load."""
    code, out, err, document, plot = tapered
    assert code == 0, err
    assert document["converged"] is True and document["errors"] == [] and _finite(document)
    rollers = document["rollers"]
    psi = np.array(rollers["azimuth"])
    inner, outer, rib = (np.array(rollers[side]["load"]) for side in ("inner", "outer", "rib"))
    cup, half = np.radians(15.0), np.radians(2.4)
    cone, axis = cup - 2 * half, cup - half
    fr, fa = 4e3, 2e3
    np.testing.assert_allclose(np.sum(outer * np.cos(cup) * np.cos(psi)), fr, rtol=1e-6)
    np.testing.assert_allclose(np.sum(outer * np.sin(cup)), fa, rtol=1e-6)
    np.testing.assert_allclose(np.sum((inner * np.cos(cone) - rib * np.sin(axis)) * np.cos(psi)), fr, rtol=1e-6)
    np.testing.assert_allclose(np.sum(inner * np.sin(cone) + rib * np.cos(axis)), fa, rtol=1e-6)
    np.testing.assert_allclose(np.sum(outer * np.cos(cup) * np.sin(psi)), 0.0, atol=1e-6 * fr)
    assert np.all(rib >= 0) and rib.max() > 0  # the cone's rib holds the rollers in
    width = 12e-3 / 30
    lamina = np.array(rollers["inner"]["lamina_load"])
    assert lamina.shape == (18, 30) and len(rollers["lamina_position"]) == 30
    np.testing.assert_allclose(lamina.sum(axis=1) * width, inner, rtol=1e-12, atol=1e-9)
    # aligned rings: the tilt is imposed (zero) and the bearing takes a moment about y
    assert document["displacement"][3:] == [0.0, 0.0]
    assert -40 < document["force"][4] < -15  # N·m (measured −27.16)
    stiffness = np.array(document["stiffness"])
    assert stiffness.shape == (5, 5) and stiffness[0, 0] > 0 and stiffness[2, 2] > 0
    np.testing.assert_allclose(stiffness, stiffness.T, rtol=1e-6, atol=1e-9 * np.abs(stiffness).max())
    assert "Qrib [N]" in out and "cup angle αo = 15°" in out and "My = -27.16" in out
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_cylindrical_example_runs_and_balances(cylindrical):
    """12 rollers, 20 µm clearance, 2.04 kN radial: exit 0; Σ Q_j cos ψ_j = Fr exactly (the outer and
    inner loads are equal, no rib); the most loaded roller carries about the starved-EHL paper's 1028 N;
    no rib force output; no axial stiffness."""
    code, out, err, document, plot = cylindrical
    assert code == 0, err
    assert document["converged"] is True and document["errors"] == [] and _finite(document)
    rollers = document["rollers"]
    psi = np.array(rollers["azimuth"])
    inner, outer = np.array(rollers["inner"]["load"]), np.array(rollers["outer"]["load"])
    np.testing.assert_allclose(np.sum(inner * np.cos(psi)), 2040.0, rtol=1e-6)
    np.testing.assert_allclose(outer, inner, rtol=1e-12, atol=1e-9)
    assert "rib" not in rollers and "Qrib" not in out
    assert 1020 < inner.max() < 1040 and int(np.sum(inner > 0)) == 3
    stiffness = np.array(document["stiffness"])
    assert np.all(stiffness[2] == 0) and np.all(stiffness[:, 2] == 0)
    np.testing.assert_allclose(stiffness, stiffness.T, rtol=1e-6, atol=1e-9 * np.abs(stiffness).max())
    assert "3 of 12 rollers loaded" in out and "diametral clearance Pd = 20 µm" in out
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_blocks_of_each_layout():
    """A roller scene with contact.load is one contact, as before; with operating.force, the bearing."""
    assert [b.name for b in build_model(load_scene("tapered_roller")).blocks] == ["roller_geometry",
                                                                                 "roller_contact_influence"]
    assert {b.name for b in build_model(load_scene("tapered_roller_bearing")).blocks} == {
        "roller_bearing_equilibrium", "roller_bearing_stiffness", "roller_life"}
    influence = build_model(load_scene("cylindrical_roller_bearing", ['effects.contact="influence"']))
    assert {b.name for b in influence.blocks} == {"roller_bearing_equilibrium", "roller_bearing_stiffness",
                                                  "roller_bearing_influence", "roller_life"}


@pytest.mark.parametrize("scene, overrides, named", [
    ("cylindrical_roller_bearing", ['operating.force=["2 kN", "0 N", "1 kN"]'],
     "operating.force: a cylindrical roller bearing without ribs carries no axial load; Fz must be 0, got 1000 N"),
    ("cylindrical_roller_bearing", ['contact.rollers="all"'], "'contact.rollers' not read by anything this scene runs"),
    ("cylindrical_roller_bearing", ["contact.tilt=0.001"], "'contact.tilt' not read by anything this scene runs"),
    ("cylindrical_roller_bearing", ["contact.load=1 kN"], "give only one of 'contact.load', 'operating.force'"),
    ("cylindrical_roller_bearing", ["bearing.rollers=14"], "bearing.rollers: 14 rollers of 25.4 mm do not fit"),
    ("cylindrical_roller_bearing", ["bearing.contact_angle=10 deg"], "a cylindrical roller bearing has contact angle 0"),
    ("cylindrical_roller_bearing", ["fidelity.laminae=1"], "fidelity.laminae must be an integer from 2 to 1000"),
    ("tapered_roller_bearing", ["operating.moment=[0, 0]"], "operating.moment: with operating.misalignment"),
    ("tapered_roller_bearing", ["bearing.contact_angle=3 deg"], "bearing.contact_angle must be > 0.0837758 rad"),
    ("tapered_roller_bearing", ['operating.misalignment=["0.1 rad", "0 rad"]'], "operating.misalignment must be"),
    ("cylindrical_roller_bearing", ['operating.radial_displacement=["20 µm", "0 µm"]'],
     "operating.force: Fx and Fy must be 0 with operating.radial_displacement"),
    ("tapered_roller", ['operating.force=["1 kN", "0 N", "0 N"]'], "give only one of 'contact.load', 'operating.force'"),
    ("cylindrical_roller_bearing", ['operating.axial_displacement="10 µm"'],
     "operating.axial_displacement: a cylindrical roller bearing without ribs has no axial position to set"),
    ("tapered_roller_bearing", ['operating.axial_displacement="10 µm"'],
     "operating.force: Fz must be 0 with operating.axial_displacement"),
])
def test_bad_bearing_input_exits_2_with_one_line(scene, overrides, named):
    arguments = [item for override in overrides for item in ("--set", override)]
    code, out, err = _cli("run", scene, *arguments)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert named in err, err


def test_a_roller_scene_needs_a_load_or_a_force(tmp_path):
    text = open(example_scene("cylindrical_roller_bearing")).read()
    text = text.replace('force = ["2.04 kN", "0 kN", "0 kN"]', "")
    path = tmp_path / "no_load.toml"
    path.write_text(text)
    with pytest.raises(ValueError, match="missing required key: one of 'contact.load', 'operating.force'"):
        load_scene(str(path))


def test_imposed_misalignment_makes_the_moments_outputs(tmp_path, cylindrical):
    """0.5 mrad about y on the cylindrical example: the tilt is held, the load still balances, and the
    moment the rollers need is close to K_θyθy θ of the aligned bearing (measured 4.08 against 4.22 N·m)."""
    code, out, err, document = _run(tmp_path, example_scene("cylindrical_roller_bearing"), "--set",
                                    'operating.misalignment=["0 mrad", "0.5 mrad"]')
    assert code == 0, err
    assert document["displacement"][3:] == [0.0, 0.5e-3]
    rollers = document["rollers"]
    np.testing.assert_allclose(np.sum(np.array(rollers["inner"]["load"]) * np.cos(rollers["azimuth"])), 2040.0,
                               rtol=1e-6)
    aligned = np.array(cylindrical[3]["stiffness"])[4, 4] * 0.5e-3
    moment = document["force"][4]
    assert 0.9 * aligned < moment < aligned and abs(document["force"][3]) < 1e-9
    assert "moments at the imposed misalignment" in out and "My = 4.08" in out
    assert rollers["tilt"][0] == pytest.approx(0.25e-3, rel=1e-9)  # a free roller takes half the ring's tilt


def test_a_tapered_bearing_set_by_axial_displacement(tmp_path, tapered):
    """The packaged tapered bearing with its δz prescribed at the value its 2 kN axial load gives,
    and Fz = 0: the axial force is an output, 2 kN to 1e-8, every roller load the same to 1e-8; the
    report names δz as prescribed and prints the axial force."""
    applied = tapered[3]
    code, out, err, document = _run(tmp_path, example_scene("tapered_roller_bearing"), "--set",
                                    'operating.force=["4 kN", "0 kN", "0 kN"]', "--set",
                                    f'operating.axial_displacement="{applied["displacement"][2] * 1e6!r} um"')
    assert code == 0, err
    assert document["force"][2] == pytest.approx(2e3, rel=1e-8)
    np.testing.assert_allclose(document["rollers"]["inner"]["load"], applied["rollers"]["inner"]["load"], rtol=1e-8,
                               atol=1e-6)
    assert "prescribed (load an output): δz, θx, θy" in out and "axial force at the prescribed δz: Fz = 2.0000 kN" in out


@pytest.mark.slow  # 50 s: the tapered solve at speed through the CLI
def test_a_tapered_bearing_short_of_its_axial_load_at_speed_says_by_how_much(tmp_path):
    """The packaged tapered bearing at 9000 r/min (centrifugal force on) under Fr 300 N and Fz 120 N:
    above the F_r tan α_o = 80.4 N it needs at rest (so accepted as input), below the
    F_r tan α_o + Z F_c sin α_o cos α_m / cos θ it needs at this speed. No equilibrium exists: exit 3,
    one line with the shortfall (`tapered_axial_load_needed` less 120 N, to the printed digits),
    every output finite."""
    from diffbearing.bearings.roller.roller_equilibrium import RollerModel, tapered_axial_load_needed

    overrides = ('operating.force=["300 N", "0 N", "120 N"]', 'operating.inner_speed="9000 r/min"',
                 "effects.centrifugal=true")
    code, out, err, document = _run(tmp_path, example_scene("tapered_roller_bearing"),
                                    *(item for override in overrides for item in ("--set", override)))
    assert code == 3, err
    (error,) = err.strip().splitlines()
    inputs = build_model(load_scene("tapered_roller_bearing", list(overrides))).inputs
    needed = float(tapered_axial_load_needed(inputs["bearing"], inputs["raceways"], inputs["operating"],
                                             RollerModel(centrifugal=True)))
    assert 150.0 < needed < 170.0
    assert f"no equilibrium exists: the axial load is {needed - 120.0:.4g} N short of F_r tan α_o" in error
    assert document["validity"]["missing_axial_load"] == pytest.approx(needed - 120.0, rel=1e-12)
    assert _finite(document)


STRAIGHT = """
title = "Straight rollers"

[bearing]
type = "cylindrical_roller"
roller_diameter = "25.4 mm"
roller_length = "14.7 mm"
pitch_diameter = "106.6 mm"
rollers = 12
radial_clearance = "20 um"

[profile]
kind = "straight"

[material]
elastic_modulus = "205.66 GPa"
poisson_ratio = 0.3

[operating]
force = ["2.04 kN", "0 kN", "0 kN"]

[contact]
rollers = "all"

[effects]
contact = "influence"

[fidelity]
grid = [16, 96]
"""


def test_influence_peak_of_a_straight_roller_is_above_the_laminae(tmp_path):
    """Straight rollers in the cylindrical example's bearing, every roller's contacts re-solved by
    influence coefficients: each loaded contact's peak (the edge peak) is above its laminae's Hertz
    peak; unloaded rollers stay at 0; the pressure map carries the roller's load on the grid's cells."""
    path = tmp_path / "straight.toml"
    path.write_text(STRAIGHT)
    code, out, err, document = _run(tmp_path, str(path))
    assert code == 0, err
    assert _finite(document)
    rollers = document["rollers"]
    influence = rollers["influence"]
    assert influence["converged"] is True and influence["roller"] == 0 and influence["rollers"] == list(range(12))
    for side in ("inner", "outer"):
        load = np.array(rollers[side]["load"])
        peak, laminae = np.array(rollers[side]["max_pressure"]), np.array(rollers[side]["lamina_max_pressure"])
        loaded = load > 0
        assert loaded.sum() == 3 and np.all(peak[loaded] > 1.05 * laminae[loaded]) and np.all(peak[~loaded] == 0)
        pressure = np.array(influence[side]["pressure"])
        x, y = np.array(influence[side]["x"]), np.array(influence["y"])
        assert pressure.shape == (16, 96) and pressure.max() == pytest.approx(peak[0], rel=1e-12)
        assert pressure.sum() * (x[1] - x[0]) * (y[1] - y[0]) == pytest.approx(load[0], rel=1e-6)
    assert "straight roller: the edge peak grows as the cells shrink" in out


def test_tapered_influence_of_the_most_loaded_roller(tmp_path, tapered):
    """The tapered example with contact = "influence": only the most loaded roller's peaks change."""
    code, out, err, document = _run(tmp_path, example_scene("tapered_roller_bearing"), "--set",
                                    'effects.contact="influence"', "--set", "fidelity.grid=[16, 64]")
    assert code == 0, err
    slices = tapered[3]["rollers"]["inner"]["max_pressure"]
    peaks = document["rollers"]["inner"]["max_pressure"]
    assert document["rollers"]["influence"]["rollers"] == [0] and peaks[1:] == slices[1:]
    assert peaks[0] == pytest.approx(slices[0], rel=0.05)  # the logarithmic crown leaves no edge peak


SWEEP = """
[sweep]
"operating.force" = [["1.5 kN", "0 N", "0 N"], ["2.04 kN", "0 N", "0 N"], ["3 kN", "0 N", "0 N"]]
"""


def test_a_force_sweep_matches_the_single_run(tmp_path, cylindrical):
    """A sweep of operating.force over the cylindrical example: every point converges, the 2.04 kN point
    is the example's computation (displacement and stiffness to 1e-10), loads grow with the force."""
    path = tmp_path / "sweep.toml"
    path.write_text(open(example_scene("cylindrical_roller_bearing")).read() + SWEEP)
    code, out, err, document = _run(tmp_path, str(path))
    assert code == 0, err
    assert all(document["converged"]) and "Sweep over 3 points" in out and "Qi max [N]" in out
    single = cylindrical[3]
    for key in ("displacement", "stiffness"):
        np.testing.assert_allclose(np.array(document[key][1]), np.array(single[key]), rtol=1e-10,
                                   atol=1e-10 * np.abs(np.array(single[key])).max())
    largest = np.array(document["rollers"]["inner"]["load"]).max(axis=1)
    assert np.all(np.diff(largest) > 0)


def test_a_geometry_sweep_runs_and_a_bad_corner_exits_2(tmp_path):
    """The raceways of a swept geometry are built from traced values (validated at the grid's corners
    before compiling): a sweep of the cone half angle and pitch diameter runs; a pitch circle too small
    for the rollers at a corner is bad input (exit 2, one line)."""
    path = tmp_path / "geometry.toml"
    path.write_text(open(example_scene("tapered_roller_bearing")).read() + '\n[sweep]\n"bearing.cone_half_angle" = '
                    '["2.0 deg", "2.4 deg"]\n"bearing.pitch_diameter" = ["50.686 mm", "52 mm"]\n')
    code, out, err, document = _run(tmp_path, str(path))
    assert code == 0, err
    assert np.array(document["converged"]).shape == (2, 2) and np.all(document["converged"])
    # the laminae's approaches depend on the cup angle, not on d_m or θ, except through the sizing of the
    # logarithmic crown at the cone's curvature: the displacement barely moves
    displacement = np.array(document["displacement"])
    np.testing.assert_allclose(displacement, np.broadcast_to(displacement[1, 0], displacement.shape), rtol=1e-4,
                               atol=1e-12)
    bad = tmp_path / "bad.toml"
    bad.write_text(open(example_scene("cylindrical_roller_bearing")).read() + '\n[sweep]\n"bearing.pitch_diameter" = '
                   '["106.6 mm", "90 mm"]\n')
    code, out, err = _cli("run", str(bad))
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "bearing.rollers: 12 rollers of 25.4 mm do not fit on the 90 mm pitch circle" in err


def test_peak_pressure_above_iso76_is_a_warning(tmp_path, cylindrical):
    """250 kN on the cylindrical example: converged (exit 0) with p_max ≈ 4.7 GPa, above the ISO 76
    limit of roller bearings (4.0 GPa): one warning, in the report and in the JSON."""
    code, out, err, document = _run(tmp_path, example_scene("cylindrical_roller_bearing"), "--set",
                                    'operating.force=["250 kN", "0 N", "0 N"]')
    assert code == 0, err
    assert document["converged"] is True and document["errors"] == []
    (warning,) = document["warnings"]
    assert warning.startswith("peak contact pressure 4.") and "(inner raceway, roller 0)" in warning
    assert "ISO 76 static limit 4 GPa of roller bearings" in warning and warning in out


def test_a_sweep_with_influence_maps_its_points(tmp_path):
    """contact = "influence" in a force sweep: the points are mapped one after another (iterative
    contact solves), each with the most loaded roller's pressure maps; peaks grow with the force."""
    path = tmp_path / "sweep.toml"
    path.write_text(open(example_scene("cylindrical_roller_bearing")).read() + SWEEP)
    code, out, err, document = _run(tmp_path, str(path), "--set", 'effects.contact="influence"', "--set",
                                    "fidelity.grid=[16, 64]", "--set", "effects.stiffness=false")
    assert code == 0, err
    assert "mapped point by point" in out and all(document["rollers"]["influence"]["converged"])
    assert np.array(document["rollers"]["influence"]["inner"]["pressure"]).shape == (3, 16, 64)
    peaks = np.array(document["rollers"]["inner"]["max_pressure"])[:, 0]
    laminae = np.array(document["rollers"]["inner"]["lamina_max_pressure"])[:, 0]
    assert np.all(np.diff(peaks) > 0) and np.all(peaks > laminae)
