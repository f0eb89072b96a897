"""`effects.thermal` from a scene (`diffbearing.app.adapters.effects.thermal`): the packaged spindle
pair and a single bearing run with the solved state holding together (the equilibrium's clearance is
the state's, the set's axial loads the fixed point's, the heat balance closed), the thermal speed
ratings beside it; bad inputs exit 2 naming their key; a runaway exits 3 with finite values."""

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.friction.friction_torque import PALMGREN_CONSTANTS
from diffbearing.film.viscosity_temperature import walther_viscosity
from diffbearing.params import ISO_VG_VISCOSITY_100, with_radial_clearance
from diffbearing.ratings.static_safety import ball_bearing_static_load_rating

from .helpers import BEARING_6411E, assert_exits_2_naming, example_scene

SINGLE = BEARING_6411E + """
bore = "55 mm"
outer_diameter = "140 mm"
width = "33 mm"

[lubricant]
preset = "iso_vg_68"
supply = "oil_bath"
cleanliness = "-/17/14"

[operating]
inner_speed = "3000 rpm"
force = ["8 kN", "0 N", "0 N"]

[mounting]
shaft_interference = "15 um"
housing_interference = "-5 um"
housing_material = "cast_iron"

[effects]
mounting = true
thermal = true
life = true
"""


def _run(path, overrides=()):
    return run_model(build_model(load_scene(str(path), overrides=list(overrides))), progress=False)


@pytest.mark.slow
def test_the_spindle_pair_example_holds_one_state():
    """spindle_pair_thermal: converged; the mounting's operating clearance at the solved temperatures
    is the state's (1e-15 m), and so are the set's axial loads (1e-8); the heat leaving is the friction
    heat (1e-10); the inner rings run warmer than the outer and the warm pair's preload is more than
    three times the matched 500 N; ISO 15312's n_θr is reported beside it."""
    result = _run(example_scene("spindle_pair_thermal"))
    values = result.values
    errors, _ = result.problems
    assert errors == []
    assert float(values["thermal.clearance"]) == pytest.approx(float(values["mounting.operating_clearance"]), abs=1e-15)
    assert float(values["thermal.heat_to_ambient"] + values["thermal.heat_to_oil"]) == pytest.approx(
        float(values["thermal.power"]), rel=1e-10)
    for number in range(2):  # the set's equilibrium after it, at the mounting's clearance, is the fixed point's
        assert float(values[f"set.bearings.{number}.force"][2]) == pytest.approx(
            float(values["thermal.bearing_axial_loads"][number]), rel=1e-8)
    assert float(values["thermal.inner_ring_temperature"]) > float(values["thermal.outer_ring_temperature"])
    assert float(values["thermal.operating_preload"]) > 3.0 * float(values["set.preload_force"])
    assert float(values["thermal_speed.reference_speed"]) > 0.0


@pytest.mark.slow
def test_a_single_bearing_runs_at_the_state_it_solves(tmp_path):
    """A 6411 on a tight shaft: the equilibrium's clearance is the state's (1e-15 m); the load heat is
    Palmgren's f₁ P₁ d_m ω with P₁ = F_r = 8 kN (HR 1's 62-series factors; 1e-9); a_ISO's viscosity is
    the oil's at the network's lubricant temperature (1e-12)."""
    path = tmp_path / "single.toml"
    path.write_text(SINGLE)
    result = _run(path)
    values = result.values
    assert bool(values["thermal.converged"])
    assert float(values["thermal.equilibrium_clearance"]) == pytest.approx(float(values["thermal.clearance"]), abs=1e-15)
    _, _, coefficient, exponent = PALMGREN_CONSTANTS["deep_groove_ball"]
    # C₀ of the bearing as the scene gives it (the fixed point keeps its free contact angle, `bearing_at`)
    rating = float(ball_bearing_static_load_rating(with_radial_clearance(result.model.inputs["bearing"], 28e-6)))
    f1 = coefficient * (8e3 / rating) ** exponent  # P₀ = F_r (ISO 76: X₀ F_r = 0.6 F_r below it)
    assert float(values["thermal.ring_power"]) == pytest.approx(f1 * 8e3 * 97.5e-3 * 3000 * np.pi / 30, rel=1e-9)
    assert min(float(values[f"thermal.{node}_temperature"]) for node in ("inner_ring", "outer_ring", "lubricant")) > 293.15
    # a_ISO's κ reads the viscosity at the network's lubricant temperature (ISO VG 68's Walther line)
    viscosity = walther_viscosity(68e-6, ISO_VG_VISCOSITY_100[68] * 1e-6, float(values["thermal.lubricant_temperature"]))
    assert float(values["life.kinematic_viscosity"]) == pytest.approx(float(viscosity), rel=1e-12)


@pytest.mark.slow
def test_skf_heat_is_the_skf_friction_at_the_state(tmp_path):
    """With effects.friction = "skf" the fixed point's heat is SKF's four components: the 6411 (64
    series) and the spindle pair each heat their network by the friction the friction effect reports
    at the solved loads and lubricant (1e-10); in an oil bath without a drag factor every watt goes
    into the rings. With Palmgren's the pair's heat is the friction effect's too (1e-9)."""
    path = tmp_path / "single.toml"
    path.write_text(SINGLE.replace("life = true", 'life = true\nfriction = "skf"').replace(
        'cleanliness = "-/17/14"', 'cleanliness = "-/17/14"\n\n[friction]\nseries = "64"'))
    values = _run(path).values
    assert bool(values["thermal.converged"])
    assert float(values["thermal.power"]) == pytest.approx(float(values["friction.power"]), rel=1e-10)
    assert float(values["thermal.lubricant_power"]) == 0.0
    pair = _run(example_scene("spindle_pair_thermal"), ['effects.friction="skf"']).values
    assert bool(pair["thermal.converged"])
    assert float(pair["thermal.power"]) == pytest.approx(float(pair["set.friction.power"]), rel=1e-10)
    # Palmgren's: the mounted pair rated at its nominal 15° in both (f₁ = a (P₀/C₀)^b reads C₀)
    pair = _run(example_scene("spindle_pair_thermal"), ['effects.friction="palmgren"']).values
    assert float(pair["thermal.power"]) == pytest.approx(float(pair["set.friction.power"]), rel=1e-9)


@pytest.mark.parametrize("override, named", [
    ("effects.mounting=false", "effects.mounting"),
    ('mounting.inner_ring_temperature="60 degC"', "mounting.inner_ring_temperature"),
    ('lubricant.temperature="60 degC"', "lubricant.temperature"),
    ('thermal.oil_flow="-1 l/min"', "thermal.oil_flow"),
    ('thermal.housing_outer_diameter="100 mm"', "thermal.housing_outer_diameter"),
    ('thermal.housing_heat_transfer_coefficient="0 W/(m^2*K)"', "thermal.housing_heat_transfer_coefficient"),
])
def test_bad_thermal_inputs_exit_2_naming_their_key(capsys, tmp_path, override, named):
    path = tmp_path / "single.toml"
    path.write_text(SINGLE)
    assert_exits_2_naming(capsys, ["run", str(path), "--set", override], named)


@pytest.mark.slow
def test_a_pair_whose_housing_runs_hotter_loses_preload():
    """The spindle pair at 12 000 r/min in a housing cooled only by still air: the heat leaves through
    the shaft, the outer ring runs hotter than the inner, the clearance opens and the warm pair keeps
    less than the matched 500 N."""
    values = _run(example_scene("spindle_pair_thermal"), ['operating.inner_speed="12000 rpm"',
                                                          'thermal.housing_heat_transfer_coefficient="10 W/(m^2*K)"']).values
    assert bool(values["thermal.converged"])
    assert float(values["thermal.outer_ring_temperature"]) > float(values["thermal.inner_ring_temperature"])
    assert float(values["thermal.operating_preload"]) < 500.0


@pytest.mark.slow
def test_a_pair_in_runaway_exits_3_with_finite_values(capsys, tmp_path):
    """The water-cooled spindle pair at 12 000 r/min: the warming inner rings raise the preload faster
    than the paths carry its heat away — no steady state: exit 3, the reason named, every value in the
    JSON finite."""
    import json

    from diffbearing.app import cli

    out = tmp_path / "out.json"
    code = cli.main(["run", "spindle_pair_thermal", "--set", 'operating.inner_speed="12000 rpm"', "--json", str(out)])
    err = capsys.readouterr().err
    assert code == 3 and "no steady state" in err, err
    data = json.loads(out.read_text())
    assert data["errors"] and all(np.isfinite(value) for value in data["thermal"].values() if not isinstance(value, list))
