"""The model's envelope (docs/theory.md §Envelopes): a scene value outside it is refused with a
ValueError (exit 2 from the CLI) that names the key the user wrote and the allowed range."""

from pathlib import Path

import pytest

import diffbearing.scenes
from diffbearing import build_model, load_scene

SCENES = Path(diffbearing.scenes.__file__).parent


def refused(example: str, *overrides: str) -> str:
    with pytest.raises(ValueError) as error:
        build_model(load_scene(example, list(overrides)))
    return str(error.value)


@pytest.mark.parametrize("override, message", [
    ('mounting.shaft_interference="5 mm"', "mounting.shaft_interference must be ≥ -0.00055 m and ≤ 0.00055 m"),
    ('mounting.inner_ring_temperature="-300 degC"', "mounting.inner_ring_temperature must be ≥ 213.15 K"),
    ('mounting.outer_ring_temperature="2000 degC"', "mounting.outer_ring_temperature must be ≥ 213.15 K and ≤ 523.15 K"),
    ('mounting.shaft_bore="80 mm"', "mounting.shaft_bore must be ≥ 0 m and < 0.055 m (a hollow shaft's bore inside"),
    ('mounting.housing_outer_diameter="100 mm"', "mounting.housing_outer_diameter must be > 0.14 m"),
    ("mounting.shaft_expansion=-1e-5", "mounting.shaft_expansion must be > 0 1/K and < 0.0001 1/K"),
    ('mounting.housing_expansion="1e-3 1/K"', "mounting.housing_expansion must be > 0 1/K and < 0.0001 1/K"),
])
def test_mountings_outside_the_envelope_name_their_key(override, message):
    assert message in refused("mounted_6411", override)


def test_a_mounting_that_closes_the_clearance_beyond_the_model_names_the_fit():
    """An interference within ±1 % of the bore whose fit still closes the clearance below −1 % of d_m
    (a 97.5 mm pitch, a thin inner ring) names the fit, not bearing.radial_clearance."""
    message = refused("mounted_6411", 'mounting.shaft_interference="0.54 mm"', 'bearing.bore="54 mm"',
                      'mounting.housing_interference="1.4 mm"')
    assert message.startswith("mounting.housing_interference: the mounting closes the clearance to"), message
    assert "below the model's floor of −1 % of d_m (-975 µm)" in message


@pytest.mark.parametrize("override, message", [
    ('bearing.width="0 mm"', "bearing.width must be > 0.01"),
    ('bearing.spacer="-2 mm"', "bearing.spacer must be ≥ 0 m"),
    ('operating.preload="-500 N"', "operating.preload must be ≥ 0 N (a set with end play"),
])
def test_sets_outside_the_envelope_name_their_key(override, message):
    assert message in refused("spindle_pair", override)


def test_two_shaft_bearings_closer_than_a_ball_are_refused(tmp_path):
    scene = tmp_path / "one_position.toml"
    scene.write_text((SCENES / "gearbox_shaft.toml").read_text().replace('position = "100 mm"', 'position = "-90 mm"'))
    assert "bearings[1].position: 10 mm from bearings[0], closer than one rolling element (26.99 mm)" in refused(str(scene))


@pytest.mark.parametrize("example, overrides, message", [
    ("gearbox_6411_ratings", ['bearing.fatigue_load_limit="0 N"'], "bearing.fatigue_load_limit must be > 0 N and < 62016 N"),
    ("gearbox_6411_ratings", ['bearing.fatigue_load_limit="200 kN"'], "< 62016 N (C0 by ISO 76), got 200000 N"),
    ("cylindrical_roller_bearing", ['bearing.fatigue_load_limit="1000 kN"', "effects.life=true",
                                    'lubricant.cleanliness="high"', 'lubricant.preset="iso_vg_68"'],
     "bearing.fatigue_load_limit must be > 0 N and < 150170 N (C0 by ISO 76)"),
])
def test_a_fatigue_load_limit_outside_zero_to_c0_is_refused(example, overrides, message):
    assert message in refused(example, *overrides)


@pytest.mark.parametrize("effect", ["effects.life=true", "effects.safety=true"])
def test_an_angle_beyond_table_3_is_refused_where_a_rating_needs_it(effect):
    message = refused("aero_angular_contact", 'bearing.contact_angle="50 deg"', effect)
    assert message == "bearing.contact_angle: ISO 281's equivalent load (life, safety) rates radial ball bearings up " \
                      "to 45°, got 50°"


LOW_SHOULDER_SCENE = """title = "a 40° angular-contact bearing (7205 B type) loaded against its low shoulder"
[bearing]
type = "angular_contact_ball"
ball_diameter = "7.938 mm"
pitch_diameter = "38.5 mm"
balls = 12
inner_groove_ratio = 0.52
outer_groove_ratio = 0.53
contact_angle = "40 deg"
[operating]
inner_speed = "3000 rpm"
force = ["0 N", "0 N", "-2 kN"]
"""


def test_an_axial_load_against_the_low_shoulder_exits_3(tmp_path, capsys):
    """Fz = −2 kN pushes the inner ring towards the open side: the solved contacts sit at −41.6°, a
    state the full-groove model reaches but no angular-contact bearing has; +2 kN is fine."""
    from diffbearing.app import cli

    path = tmp_path / "low_shoulder.toml"
    path.write_text(LOW_SHOULDER_SCENE)
    assert cli.main(["run", str(path)]) == 3
    err = capsys.readouterr().err
    assert "equilibrium outside the model: a ball loaded at α = -41.6° past its raceway's edge (an angular-contact " \
           "bearing's low-shoulder side" in err and len(err.strip().splitlines()) == 1
    assert cli.main(["run", str(path), "--set", 'operating.force=["0 N", "0 N", "2 kN"]']) == 0


@pytest.mark.parametrize("example, speed", [("aero_angular_contact", "1e9 rpm"), ("cylindrical_roller_bearing", "1e6 rpm")])
def test_a_speed_beyond_any_rolling_bearing_is_refused(example, speed):
    message = refused(example, f'operating.inner_speed="{speed}"')
    assert message.startswith("operating.inner_speed: n·d_m = ") and "is far beyond any rolling bearing (limit 1e+07" in message


@pytest.mark.parametrize("force", ['["4 kN", "0 kN", "0 kN"]', '["4 kN", "0 kN", "1 kN"]', '["0 kN", "0 kN", "-1 kN"]'])
def test_a_tapered_bearing_without_enough_axial_load_is_refused(force):
    """Fz ≤ Fr tan α_o has no equilibrium (its cup pushes each roller along α_o = 15°): refused
    naming operating.force with the axial load it needs, 4 kN · tan 15° = 1072 N."""
    message = refused("tapered_roller_bearing", f"operating.force={force}")
    assert message.startswith("operating.force: a tapered roller bearing takes Fr = ")
    if force.startswith('["4'):
        assert "Fz > Fr tan α_o = 1072 N" in message


def test_a_tapered_bearing_just_above_the_axial_limit_converges():
    """Fz = 1.1 Fr tan α_o, a few rollers loaded: an equilibrium exists and is found."""
    from diffbearing import run_model

    result = run_model(build_model(load_scene("tapered_roller_bearing", ['operating.force=["4 kN", "0 kN", "1.18 kN"]'])),
                       progress=False)
    assert bool(result.values["converged"]), result.problems


@pytest.mark.parametrize("speed, warned", [("9000 rpm", False), ("12000 rpm", True)])
def test_a_tapered_bearing_warns_above_its_own_speed_factor(speed, warned):
    """A tapered roller bearing's n·d_m warning is the ball bearings' 1e6 over its bearing factor
    b_f = 2: 5e5 mm·r/min; the packaged one (d_m 50.686 mm) at 9000 r/min (4.56e5) runs without it,
    at 12 000 r/min (6.08e5) with it, though a ball bearing would not warn there."""
    from diffbearing import run_model

    result = run_model(build_model(load_scene("tapered_roller_bearing", [f'operating.inner_speed="{speed}"'])),
                       progress=False)
    factor = float(speed.split()[0]) * 50.686
    assert float(result.values["validity.speed_factor"]) == pytest.approx(factor, rel=1e-12)
    lines = [line for line in result.problems[1] if line.startswith("n·d_m")]
    assert lines == ([f"n·d_m = {factor:.3g} mm·r/min is above 5e+05, where standard bearings of this type stop (a ball "
                      "bearing's 1e+06 over its bearing factor 2; the rib, cage and lubrication, not modelled here, set "
                      "the limit)"] if warned else [])


POINT_FILM = ['operating.force=["8 kN", "0 N", "0 N"]', 'effects.film="point"', 'lubricant.preset="iso_vg_68"']


def test_a_point_contact_grid_beyond_the_machine_is_refused_with_its_memory():
    """fidelity.grid = [4097, 4097]: 2049 dense column blocks of 4095² in float64, held twice —
    2 × 8 B × 2049 × 4095² = 512 GiB, refused before anything compiles."""
    message = refused("deep_groove_6411", *POINT_FILM, 'operating.inner_speed="3000 rpm"',
                      "fidelity.grid=[4097, 4097]")
    assert message.startswith("fidelity.grid: the 4097 × 2049 half-domain grid needs about 512 GiB"), message


def test_a_point_contact_film_at_standstill_is_refused():
    """No rolling, no film: refused naming the speed (it compiled 97 s, then printed h < 0)."""
    message = refused("deep_groove_6411", *POINT_FILM)
    assert message.startswith("operating.inner_speed: effects.film = \"point\" needs rolling"), message


def test_shoulder_diameters_check_each_contact_ellipse(tmp_path, capsys):
    """With both shoulder diameters (item 5 of issue 46), each ball's share of its contact load past
    the shoulder edge is `groove_chamfer.truncated_load_share` of the run's own contact angle and
    semi-major axis, with the shoulder depths from the diameters and the groove bottoms
    d_m ∓ (D_w + G_r/2) (1e-12); shallow shoulders warn with the share; shoulders below the contact
    centres exit 3; one diameter alone, or one outside groove bottom…curvature centre, exits 2."""
    import json

    import numpy as np

    from diffbearing.app import cli
    from diffbearing.bearings.ball import groove_chamfer

    def run(inner, outer, *more):
        code = cli.main(["run", "gearbox_6411_ratings", "--set", f"bearing.inner_shoulder_diameter={inner}",
                         "--set", f"bearing.outer_shoulder_diameter={outer}", *more])
        return (code, *capsys.readouterr())

    path = tmp_path / "out.json"
    code, out, err = run("72.5 mm", "122.5 mm", "--json", str(path))
    assert code == 0, err
    assert "passes the inner ring's shoulder edge: 4.1" in out  # 4.15 % (ball 0)
    document = json.loads(path.read_text())
    geometry, balls = document["geometry"], document["balls"]
    bearing = build_model(load_scene("gearbox_6411_ratings")).inputs["bearing"]
    span = float(bearing.ball_diameter) + geometry["radial_clearance"] / 2
    pitch = float(bearing.pitch_diameter)
    depths = {"inner": (72.5e-3 - (pitch - span)) / 2, "outer": ((pitch + span) - 122.5e-3) / 2}
    for side, ratio in (("inner", bearing.inner_groove_ratio), ("outer", bearing.outer_groove_ratio)):
        expected = groove_chamfer.truncated_load_share(np.abs(balls[side]["contact_angle"]),
                                                       np.asarray(balls[side]["semi_major_axis"]),
                                                       float(ratio * bearing.ball_diameter), depths[side])
        np.testing.assert_allclose(balls[side]["shoulder_share"], expected, rtol=1e-12, atol=1e-15)
    assert max(balls["inner"]["shoulder_share"]) > 0.04

    code, out, err = run("70.6 mm", "124.4 mm")
    assert code == 3 and len(err.strip().splitlines()) == 1 and "past its shoulder edge" in err, err
    code, out, err = run("78 mm", "117 mm")
    assert code == 0 and "shoulder edge" not in out, err
    code = cli.main(["run", "gearbox_6411_ratings", "--set", "bearing.inner_shoulder_diameter=78 mm"])
    assert code == 2 and "bearing.outer_shoulder_diameter: give both shoulder diameters" in capsys.readouterr().err
    code, out, err = run("60 mm", "117 mm")
    assert code == 2 and "bearing.inner_shoulder_diameter must be between 70.5 mm and 98.3 mm" in err, err
