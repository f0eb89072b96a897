"""The self-aligning ball bearing as a scene's [[bearings]] entry (adapters/bearings/
self_aligning.py): the packaged line-shaft example against the Python interface (a flexible shaft
bending past a rigid bearing's 10′, which it takes without a moment or a warning), and the errors a
user meets."""

import importlib.resources

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli

SCENE = importlib.resources.files("diffbearing.scenes") / "self_aligning_shaft.toml"


@pytest.fixture(scope="module")
def line_shaft():
    return run_model(build_model(load_scene(str(SCENE))), progress=False)


@pytest.mark.slow
def test_the_line_shaft_bends_past_ten_arcmin_and_its_bearings_carry_no_moment(line_shaft):
    """Each bearing carries half the pulley's pull (statics of a beam on two pivots, 1e-9) and no
    moment, its rings tilted by more than 10′ with no misalignment warning (it permits 2.5°); the
    slope of a simply supported Euler beam, F L² / (16 E I), to 5 % (shear and the bearings' own
    deflections: Timoshenko on elastic supports)."""
    values = line_shaft.values
    assert bool(values["shaft.converged"])
    forces = np.asarray(values["bearings.force"])
    np.testing.assert_allclose(forces[:, 0], [1500.0, 1500.0], rtol=1e-9)
    assert np.all(np.abs(forces[:, 3:]) == 0.0)
    tilts = np.hypot(*np.asarray(values["bearings.displacement"])[:, 3:].T)
    inertia = np.pi * 0.04**4 / 64
    slope = 3000.0 * 0.8**2 / (16 * 207e9 * inertia)
    np.testing.assert_allclose(tilts, slope, rtol=0.05)
    assert np.all(tilts > np.radians(10 / 60))
    assert not any("tilt" in warning for warning in line_shaft.problems[1])


@pytest.mark.parametrize("change, named", [
    (('radial_clearance = "20 um"', '', 1), "bearings[0]: missing required key 'radial_clearance'"),
    (('radial_clearance = "20 um"', 'radial_clearance = "2 mm"', 1), "bearings[0]: radial_clearance must be"),
    (('inner_groove_ratio = 0.53', 'inner_groove_ratio = 0.53\nouter_groove_ratio = 0.53', 1), "outer_groove_ratio"),
    (('frequencies = true', 'frequencies = true\nfriction = "skf"\n[lubricant]\npreset = "iso_vg_68"\n'
                            'temperature = "60 degC"', 1),
     "effects.friction: bearings[0] (self_aligning_ball) is not covered by the 'skf' friction model"),
])
def test_bad_self_aligning_entries_are_refused(capsys, tmp_path, change, named):
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.read_text().replace(*change))
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err
