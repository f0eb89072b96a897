"""Effect `mounting`: the equilibrium runs at the operating clearance the [mounting] table gives,
its derivatives through the fit, and the errors a user meets."""

import jax
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.params import radial_clearance, with_radial_clearance
from diffbearing.ratings.life import ball_load_rating
from diffbearing.ratings.static_safety import ball_bearing_static_load_rating

from .helpers import BEARING_6411E, SPINDLE_7014C, central_difference_jvp, example_scene

MOUNTED = BEARING_6411E + """bore = "55 mm"
outer_diameter = "140 mm"

[operating]
inner_speed = "3000 rpm"
force = ["8 kN", "0 N", "0 N"]

[effects]
stiffness = true
mounting = true

[mounting]
shaft_interference = "15 um"
housing_interference = "-5 um"
shaft_roughness = "2 um"
inner_ring_roughness = "1 um"
inner_ring_temperature = "70 degC"
outer_ring_temperature = "60 degC"
shaft_temperature = "70 degC"
housing_temperature = "328.15 K"
housing_material = "cast_iron"
"""


def _scene(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


@pytest.fixture(scope="module")
def mounted(tmp_path_factory):
    return run_model(build_model(load_scene(_scene(tmp_path_factory.mktemp("mounted"), MOUNTED))), progress=False)


def test_mounted_bearing_is_the_bearing_at_its_operating_clearance(mounted, tmp_path):
    """The same bearing given the operating clearance as its own, without [mounting]: the same
    displacement, ball loads and stiffness to 1e-9 (relative)."""
    running = float(mounted.values["mounting.operating_clearance"])
    change = float(mounted.values["mounting.clearance_change"])
    parts = sum(float(mounted.values[f"mounting.{part}"]) for part in ("shaft_fit", "housing_fit", "thermal",
                                                                       "centrifugal"))
    assert running == pytest.approx(28e-6 + change, rel=1e-12) and change == pytest.approx(parts, rel=1e-12)
    assert change < 0  # the shaft fit and the hotter inner ring close the bearing
    plain = MOUNTED.split("[effects]")[0].replace('radial_clearance = "0.028 mm"', f"radial_clearance = {running!r}")
    reference = run_model(build_model(load_scene(_scene(tmp_path, plain + "[effects]\nstiffness = true\n"))),
                          progress=False)
    for key in ("displacement", "balls.inner.load", "stiffness"):
        scale = np.max(np.abs(reference.values[key]))
        np.testing.assert_allclose(mounted.values[key], reference.values[key], rtol=0, atol=1e-9 * scale, err_msg=key)


def test_a_mounted_angular_contact_bearing_is_rated_as_designed():
    """A mounting's clearance change moves a 15° bearing's free contact angle (its rings' geometry),
    not the angle ISO 76 and ISO 281 rate it at: C₀r and C_r are the bearing's as designed (exact),
    after one change and after a second, and do not depend on the clearance (a zero derivative)."""
    cold = radial_clearance(SPINDLE_7014C)
    once = with_radial_clearance(SPINDLE_7014C, cold - 8e-6)
    twice = with_radial_clearance(once, cold + 5e-6)
    assert float(once.free_contact_angle) < float(SPINDLE_7014C.free_contact_angle) < float(twice.free_contact_angle)
    for running in (once, twice):
        assert float(running.nominal_contact_angle) == float(SPINDLE_7014C.free_contact_angle)
        assert float(ball_bearing_static_load_rating(running)) == float(ball_bearing_static_load_rating(SPINDLE_7014C))
        assert float(ball_load_rating(running)) == float(ball_load_rating(SPINDLE_7014C))
    slope = jax.grad(lambda g: ball_bearing_static_load_rating(with_radial_clearance(SPINDLE_7014C, g)))(cold - 8e-6)
    assert float(slope) == 0.0


@pytest.mark.slow
def test_stiffness_against_shaft_interference_matches_central_differences(mounted):
    """d K_xx / d(shaft interference) through the fit, the clearance and the equilibrium, against
    a central difference (step 0.1 µm)."""
    model = mounted.model
    values = dict(model.scene.values)

    def radial_stiffness(interference):
        inputs = model.inputs_from_values(values | {"mounting.shaft_interference": interference})
        return model.function()(inputs)["stiffness"][0, 0]

    point = values["mounting.shaft_interference"]
    _, slope = jax.jvp(radial_stiffness, (point,), (1.0,))
    reference = central_difference_jvp(radial_stiffness, point, 1.0, 1e-7)
    assert float(slope) > 0  # a tighter fit, less clearance, a stiffer bearing
    np.testing.assert_allclose(slope, reference, rtol=1e-5)


def test_tolerance_classes_are_their_interferences(mounted, tmp_path):
    """ISO 286 classes at `fit_value = "min"` (a k5 shaft on the 6411's bore: 2 µm; an M7 housing on
    its 140 mm outside: −18 µm, loose; `bearing_fits`) give what those interferences give, to 1e-12; the
    effective shaft interference is the given one less 0.8 ΣRz, at temperature (DIN 7190)."""
    text = MOUNTED.replace('shaft_interference = "15 um"', 'shaft_tolerance = "k5"\nhousing_tolerance = "M7"\n'
                                                          'fit_value = "min"').replace('housing_interference = "-5 um"', "")
    by_class = run_model(build_model(load_scene(_scene(tmp_path, text, "classes.toml"))), progress=False)
    given = MOUNTED.replace('shaft_interference = "15 um"', 'shaft_interference = "2 um"').replace(
        'housing_interference = "-5 um"', 'housing_interference = "-18 um"')
    by_value = run_model(build_model(load_scene(_scene(tmp_path, given, "values.toml"))), progress=False)
    for key in ("mounting.clearance_change", "mounting.effective_shaft_interference", "balls.inner.load"):
        np.testing.assert_allclose(by_class.values[key], by_value.values[key], rtol=1e-12, err_msg=key)
    # 15 µm less 0.8 (2 + 1) µm of smoothing, plus d (α_shaft − α_ring) × 50 K: steel shaft, both at 70 °C
    effective = 15e-6 - 0.8 * 3e-6 + 55e-3 * (11.7e-6 - 11.5e-6) * 50.0
    assert float(mounted.values["mounting.effective_shaft_interference"]) == pytest.approx(effective, rel=1e-9)


def test_mounting_table_without_the_effect_is_refused(tmp_path):
    text = MOUNTED.replace("mounting = true\n", "")
    with pytest.raises(ValueError, match="mounting.shaft_interference"):
        build_model(load_scene(_scene(tmp_path, text)))


@pytest.mark.parametrize("change, named", [
    (('shaft_interference = "15 um"', 'shaft_interference = "2 mm"'), "mounting.shaft_interference must be ≥"),
    (('bore = "55 mm"\n', ""), "bearing.bore"),
    (('housing_material = "cast_iron"', 'housing_material = "wood"'), "mounting.housing_material"),
    (('housing_material = "cast_iron"', 'housing_material = "cast_iron"\nshaft_tolerance = "k5"'), "not both"),
    (('shaft_interference = "15 um"', 'shaft_tolerance = "k9"'), "mounting.shaft_tolerance"),
])
def test_bad_mounting_exits_2_naming_the_cause(capsys, tmp_path, change, named):
    path = _scene(tmp_path, MOUNTED.replace(*change))
    assert cli.main(["run", path]) == 2
    assert named in capsys.readouterr().err


def test_mounted_cylindrical_roller_bearing_runs_preloaded_at_its_operating_clearance():
    """A cylindrical roller bearing whose fit and hot inner ring close its 20 µm clearance to a
    negative (preloaded) one: the same ring displacement and roller loads as the bearing given
    that clearance, to 1e-9."""
    base = [f"effects.{name}=false" for name in ("stiffness", "life")]
    mounting = ["effects.mounting=true", 'bearing.bore="55 mm"', 'bearing.outer_diameter="160 mm"',
                'mounting.shaft_interference="30 um"', 'mounting.inner_ring_temperature="40 degC"']
    mounted = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"), base + mounting)),
                        progress=False)
    running = float(mounted.values["mounting.operating_clearance"])
    assert running < 0
    given = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"),
                                             base + [f"bearing.radial_clearance={running!r}"])), progress=False)
    for key in ("displacement", "rollers.inner.load", "rollers.inner.lamina_load"):
        scale = np.max(np.abs(given.values[key]))
        np.testing.assert_allclose(mounted.values[key], given.values[key], rtol=0, atol=1e-9 * scale, err_msg=key)


def test_tapered_roller_bearing_mounting_is_refused(capsys):
    assert cli.main(["run", "tapered_roller_bearing", "--set", "effects.mounting=true"]) == 2
    assert "tapered roller bearing's clearance is its axial setting" in capsys.readouterr().err
