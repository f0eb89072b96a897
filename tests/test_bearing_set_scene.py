"""Bearing sets through scenes (`bearing.arrangement`): a DB pair under axial load against the single
bearing's scene, the preload as a force and as an offset, the set at its operating clearance, its
life, and the errors a user meets."""

from pathlib import Path

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.bearings.ball import groove_chamfer
from diffbearing.systems.bearing_set import preload_offset

from .helpers import example_scene

STATIC = ["effects.centrifugal=false", "effects.gyroscopic=false", "effects.stiffness=false"]


def run(overrides=(), scene="spindle_pair"):
    return run_model(build_model(load_scene(scene, list(STATIC) + list(overrides))), progress=False)


def _scene_without(keys, folder) -> str:
    """The packaged spindle_pair scene with the lines of `keys` (names within their tables) left out."""
    text = Path(example_scene("spindle_pair")).read_text()
    path = folder / "scene.toml"
    path.write_text("\n".join(line for line in text.splitlines() if line.split("=")[0].strip() not in keys))
    return str(path)


def single(tmp_path, axial, overrides=()):
    """The spindle_pair's bearing alone (no set keys) under an axial load [N]."""
    path = _scene_without(("arrangement", "set_size", "width", "preload"), tmp_path)
    return run_model(build_model(load_scene(path, list(STATIC) + [f'operating.force=["0 N", "0 N", "{axial!r} N"]']
                                            + list(overrides))), progress=False)


@pytest.mark.slow
def test_pair_under_axial_load_is_each_bearing_alone(tmp_path):
    """Issue 26: the DB pair of the packaged example under a pure axial load of 1.2 kN; each
    bearing's displacement, ball loads, static safety, overrolling frequencies, friction torque and
    a_ISO life L10rm and the contact ellipses' shares beyond low-set shoulders are the single
    bearing's under its own axial load, to 1e-9 (the set's torque their sum), with the same
    [fidelity] (Brewe–Hamrock contacts, inner-raceway control); with no load each carries the 500 N
    preload. With the inner shoulder lower still, bearing 0's contact centres pass its edge: an error
    (the CLI's exit 3) naming it."""
    # a hot oil and a dirty one, so that a_ISO stays below its cap of 50 (0.67 and 43); shoulders
    # (inner 18.2° above the groove bottom) that truncate both bearings' inner contact ellipses
    shoulders = ["bearing.inner_shoulder_diameter=79.45 mm", "bearing.outer_shoulder_diameter=99.8 mm"]
    ratings = ["effects.safety=true", "effects.frequencies=true", "effects.friction=palmgren", "lubricant.preset=iso_vg_32",
               "fidelity.hertz=brewe_hamrock", "fidelity.race_control=inner", "effects.life=true",
               "lubricant.cleanliness=custom", "lubricant.contamination_factor=0.02", "lubricant.temperature=90 degC"]
    pair = run(['operating.force=["0 N", "0 N", "1.2 kN"]'] + shoulders + ratings)
    assert bool(pair.values["set.converged"]) and "balls.inner.load" not in pair.values
    axial = [float(pair.values[f"set.bearings.{n}.force"][2]) for n in range(2)]
    torque = 0.0
    assert axial[0] - axial[1] == pytest.approx(1200.0, rel=1e-9)
    for number, load in enumerate(axial):
        alone = single(tmp_path, load, shoulders + ratings)
        np.testing.assert_allclose(pair.values[f"set.bearings.{number}.displacement"], alone.values["displacement"],
                                   rtol=1e-9, atol=1e-9 * abs(float(alone.values["displacement"][2])))
        np.testing.assert_allclose(pair.values[f"set.bearings.{number}.balls.inner.load"],
                                   alone.values["balls.inner.load"], rtol=1e-9)
        for mine, theirs in (("iso76", "safety.iso76"), ("static_safety", "safety.static"),
                             ("frequencies.cage", "frequencies.cage"), ("frequencies.ball_spin", "frequencies.ball_spin"),
                             ("friction.torque", "friction.torque"), ("L10rm", "life.L10rm"), ("a_iso", "life.a_iso_reference")):
            assert float(pair.values[f"set.bearings.{number}.{mine}"]) == pytest.approx(float(alone.values[theirs]),
                                                                                        rel=1e-9), mine
        torque += float(alone.values["friction.torque"])
        share = np.asarray(pair.values[f"set.bearings.{number}.balls.inner.shoulder_share"])
        assert share.min() > 0.0
        np.testing.assert_allclose(share, alone.values["balls.inner.shoulder_share"], rtol=1e-9)
        assert [line for line in pair.problems[1] if f"bearing {number}: the contact ellipse" in line]
    assert float(pair.values["set.friction.torque"]) == pytest.approx(torque, rel=1e-9)
    lower = ["bearing.inner_shoulder_diameter=79.3 mm", "bearing.outer_shoulder_diameter=99.8 mm"]
    riding = run(['operating.force=["0 N", "0 N", "1.2 kN"]'] + lower + ratings)
    bearing = riding.model.inputs["bearing"]
    # the edge's angle from the groove bottom, seen from the groove centre: h = r (1 − cos θ_s)
    depth = (0.0793 - float(groove_chamfer.groove_bottom_diameters(bearing)[0])) / 2.0
    edge = np.arccos(1.0 - depth / (0.52 * float(bearing.ball_diameter)))
    past = np.degrees(np.max(riding.values["set.bearings.0.balls.inner.contact_angle"]) - edge)
    errors = riding.problems[0]
    assert past > 0.0 and len(errors) == 1 and errors[0].startswith(
        f"bearing 0 outside the model: a loaded contact lies {past:.2f}° past its shoulder edge"), errors
    unloaded = run(['operating.force=["0 N", "0 N", "0 N"]'])
    np.testing.assert_allclose([float(unloaded.values[f"set.bearings.{n}.force"][2]) for n in range(2)], [500.0, 500.0],
                               rtol=1e-9)


@pytest.mark.slow
def test_preload_as_force_and_as_offset_agree(tmp_path):
    """The 500 N preload is an offset of `preload_offset`; given that offset instead, the set reports
    500 N (to 1e-9) and the same bearing loads."""
    by_force = run()
    offset = float(by_force.values["set.preload_offset"])
    bearing = build_model(load_scene("spindle_pair")).inputs["bearing"]
    assert offset == pytest.approx(float(preload_offset(bearing, 500.0)), rel=1e-12)
    by_offset = run(["operating.preload_offset=" + repr(offset)], scene=_scene_without(("preload",), tmp_path))
    assert float(by_offset.values["set.preload_force"]) == pytest.approx(500.0, rel=1e-9)
    for n in range(2):
        np.testing.assert_allclose(by_offset.values[f"set.bearings.{n}.force"], by_force.values[f"set.bearings.{n}.force"],
                                   rtol=1e-9, atol=1e-9)


@pytest.mark.slow
def test_set_at_its_operating_clearance():
    """Effect `mounting` on a set at standstill: with no fit and every temperature at the reference
    it changes nothing (exact); an inner ring 10 K hotter than the outer closes the clearance and raises the
    preload, and each bearing then carries what the single bearing carries at the running contact
    angle, pushed by the matched offset plus the moved reference (f_i + f_o − 1) D_w (sin α₀ − sin α₀')
    less half the inner stack's axial growth α s (T_i − T_o) over the outer's."""
    from diffbearing.bearings.ball.ball_equilibrium import BallModel, ring_force
    from diffbearing.params import Operating
    from diffbearing.systems.operating_clearance import RING_EXPANSION

    at_rest = ['operating.force=["0 N", "0 N", "0 N"]', 'operating.inner_speed="0 rpm"']
    plain = run(at_rest)
    neutral = run(at_rest + ["effects.mounting=true"])
    for n in range(2):
        np.testing.assert_allclose(neutral.values[f"set.bearings.{n}.force"], plain.values[f"set.bearings.{n}.force"],
                                   rtol=1e-12, atol=1e-9)
    hot = at_rest + ["effects.mounting=true", 'mounting.inner_ring_temperature="30 degC"',
                     'mounting.shaft_temperature="30 degC"']
    warm = run(hot)
    assert float(warm.values["mounting.clearance_change"]) < 0.0
    carried = float(warm.values["set.bearings.0.force"][2])
    assert carried > 1.5 * 500.0
    model = build_model(load_scene("spindle_pair", list(STATIC) + hot))
    running = model.inputs["bearing"]
    catalogue = build_model(load_scene("spindle_pair", STATIC)).inputs["bearing"]
    distance = (running.inner_groove_ratio + running.outer_groove_ratio - 1.0) * running.ball_diameter
    # the inner rings 10 K warmer than the outer: the inner stack grows by α s · 10 K over the
    # centre distance s, and each inner ring of the back-to-back pair moves back by half of it
    growth = float(model.inputs["bearing_set"].spacing) * RING_EXPANSION * 10.0
    assert float(warm.values["set.axial_growth"]) == pytest.approx(growth, rel=1e-12)
    push = float(warm.values["set.preload_offset"]) + distance * (np.sin(catalogue.free_contact_angle)
                                                                 - np.sin(running.free_contact_angle)) - 0.5 * growth
    alone = ring_force(np.array([0.0, 0.0, push, 0.0, 0.0]), running, Operating(0.0, 0.0, np.zeros(3), np.zeros(2)),
                       BallModel())
    assert carried == pytest.approx(float(alone[2]), rel=1e-9)


@pytest.mark.slow
def test_life_of_the_set():
    """Effect `life` on a set: each bearing's ISO/TS 16281 L10r and the set's, (Σ L^(−10/9))^(−9/10)."""
    result = run(["effects.life=true"])
    lives = [float(result.values[f"set.bearings.{n}.L10r"]) for n in range(2)]
    assert float(result.values["set.L10r"]) == pytest.approx(sum(v ** (-10 / 9) for v in lives) ** (-0.9), rel=1e-12)
    assert float(result.values["set.L10r"]) < min(lives)


@pytest.mark.parametrize("override, named", [
    ('bearing.arrangement="tandem"', "tandem pair cannot be preloaded"),
    ('operating.outer_speed="100 rpm"', "operating.outer_speed"),
    ("bearing.set_size=3", "bearing.set_size"),
    ('bearing.type="deep_groove_ball"', "bearing.arrangement: sets are of angular_contact_ball bearings"),
    ('operating.preload_offset="5 um"', "one of preload and preload_offset"),
    ('operating.misalignment=["0 mrad", "0 mrad"]', "operating.misalignment: not with a bearing set"),
])
def test_bad_sets_are_refused(capsys, override, named):
    code = cli.main(["run", "spindle_pair", "--set", override])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err


@pytest.mark.slow
def test_preload_offset_is_the_matched_bearings_when_the_fit_closes_the_clearance():
    """A shaft fit that closes the pair's 37.9 µm clearance below zero (the running bearings carry an
    interference): the 500 N preload still becomes the offset of the bearings as matched, to 1e-12."""
    at_rest = ['operating.force=["0 N", "0 N", "0 N"]', 'operating.inner_speed="0 rpm"']
    plain = run(at_rest)
    tight = run(at_rest + ["effects.mounting=true", 'mounting.shaft_interference="80 um"'])
    assert float(tight.values["mounting.operating_clearance"]) < 0.0
    assert float(tight.values["set.preload_offset"]) == pytest.approx(float(plain.values["set.preload_offset"]),
                                                                      rel=1e-12)
    assert bool(tight.values["set.converged"])


@pytest.mark.slow  # 10 s (2 cores)
def test_pair_skf_friction_is_each_bearings_at_its_load():
    """effects.friction = "skf" on the DB pair (8000 r/min, speed effects off, VG 32 grease) under 1.2 kN
    axial: each bearing's SKF moment is the physics function's at that bearing's solved load (1e-12),
    the set's torque their sum."""
    from diffbearing.friction import skf_friction

    pair = run(['operating.force=["0 N", "0 N", "1.2 kN"]', "effects.friction=skf", "bearing.bore=70 mm",
                "bearing.outer_diameter=110 mm", "lubricant.preset=iso_vg_32", "lubricant.supply=grease"])
    model = build_model(load_scene(example_scene("spindle_pair"), list(STATIC) + [
        "effects.friction=skf", "bearing.bore=70 mm", "bearing.outer_diameter=110 mm", "lubricant.preset=iso_vg_32",
        "lubricant.supply=grease"]))
    lubricant = model.inputs["lubricant"]
    total = 0.0
    for number in range(2):
        force = pair.values[f"set.bearings.{number}.force"]
        want = skf_friction.frictional_moment("angular_contact_ball", "single_row", float(np.hypot(force[0], force[1])),
                                              abs(float(force[2])), 8000 * np.pi / 30, lubricant.viscosity / lubricant.density,
                                              70e-3, 110e-3, supply="grease").total
        assert float(pair.values[f"set.bearings.{number}.friction.torque"]) == pytest.approx(float(want), rel=1e-12)
        total += float(want)
    assert float(pair.values["set.friction.torque"]) == pytest.approx(total, rel=1e-12)


def test_hybrid_set_says_its_ratings_are_all_steel():
    """A set of hybrid bearings (silicon nitride balls) flags them and warns that C0 and p_limit are
    ISO 76's all-steel values (`tests/test_static_safety.py` for the single bearing)."""
    result = run(["effects.safety=true", "material.ball_preset=silicon_nitride"])
    assert float(result.values["safety.hybrid"]) == 1.0
    assert any("hybrid bearing" in line for line in result.problems[1])


@pytest.mark.parametrize("ratio, missing, reason", [
    (3.0, 0.0, "each ball's centrifugal force is 3× the applied load per ball"),
    (0.5, 120.0, "the axial load is 120 N short of 1.25 (F_r + 2|M|/s) tan α₀"),
    (0.5, 0.0, None),
])
def test_an_unconverged_set_says_why(ratio, missing, reason):
    """The set's check names the reason a solve did not converge (its balls lifted by their
    centrifugal force, a tandem pair short of axial load), or none; and the tandem pair's missing
    axial load is 1.25 (F_r + 2|M|/s) tan α₀ − F_z: 1.25 (300 + 2·6/0.03) tan 30° − 200 = 305.2 N."""
    from diffbearing.app.adapters.systems.bearing_set import _checks, tandem_missing_axial_load
    from diffbearing.params import ball_bearing

    values = {"set.validity.approach_ratio": 1e-3, "set.validity.contact_angle": 0.5,
              "set.validity.lowest_contact_angle": 0.3, "set.converged": False, "set.residual": 0.1,
              "set.validity.centrifugal_ratio": ratio, "set.validity.missing_axial_load": missing,
              "set.preload_force": 0.0}
    for number in range(2):
        values |= {f"set.bearings.{number}.balls.{side}.max_pressure": np.full(12, 1e9) for side in ("inner", "outer")}
        values[f"set.bearings.{number}.balls.inner.load"] = np.full(12, 100.0)
    errors, _ = _checks(values)
    assert len(errors) == 1 and errors[0].startswith("shaft equilibrium of the set did not converge: largest scaled "
                                                     "residual 1.0e-01 (tolerance 1e-09)")
    assert (reason in errors[0]) if reason else errors[0].endswith("(tolerance 1e-09)")
    bearing = ball_bearing(ball_diameter=0.01, pitch_diameter=0.06, balls=12, kind="angular_contact_ball",
                           inner_groove_ratio=0.52, outer_groove_ratio=0.53, contact_angle=np.radians(30.0))
    short = tandem_missing_axial_load(bearing, np.array([300.0, 0.0, 200.0]), np.array([6.0, 0.0]), 0.03, "tandem")
    assert float(short) == pytest.approx(1.25 * (300.0 + 400.0) * np.tan(np.radians(30.0)) - 200.0, rel=1e-12)
    assert float(tandem_missing_axial_load(bearing, np.array([300.0, 0.0, 200.0]), np.array([6.0, 0.0]), 0.03,
                                           "back_to_back")) == 0.0
