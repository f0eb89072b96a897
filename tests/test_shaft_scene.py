"""A shaft on several bearings through scenes ([[bearings]], [[loads]], [shaft]): one bearing on the
shaft against the single-bearing scene, the system life, and the errors a user meets."""

import importlib.resources

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.app.adapters.systems.shaft import misalignment_warnings
from diffbearing.bearings.interface import RIGID_MISALIGNMENT
from diffbearing.app.adapters.systems.shaft_layout import layout_supports
from diffbearing.systems.flexible_shaft import flexible_shaft, solve_flexible_shaft
from diffbearing.systems.shaft_equilibrium import Shaft

from .helpers import BEARING_6411E

ENTRY = BEARING_6411E.replace("[bearing]", "[[bearings]]") + 'dynamic_load_rating = "101 kN"\n'
LOAD = ["4 kN", "1 kN", "2.5 kN"]


def _run(tmp_path, text, name):
    path = tmp_path / name
    path.write_text(text)
    return run_model(build_model(load_scene(str(path))), progress=False)


def test_one_bearing_shaft_is_the_single_bearing_run(tmp_path):
    """Issue 26: the 6411E alone on a shaft (at z = 40 mm, loaded there, turned "-z" with the load
    turned too) against the single-bearing scene: its displacement in its own frame, its load, its
    largest ball load, every ball's loads, contact angles and pressures (`bearings.elements.*`), its
    L10r and a_ISO life L10rm, its static safety, overrolling frequencies, friction torque and each
    ball's share of its contact load beyond low-set shoulders to 1e-9, with the same [fidelity]
    (Brewe–Hamrock contacts, inner-raceway control); the shaft's lives and friction are that
    bearing's, and its shoulder warning names the bearing."""
    effects = ('[effects]\nlife = true\nsafety = true\nfrequencies = true\nfriction = "palmgren"\n'
               '[fidelity]\nhertz = "brewe_hamrock"\nrace_control = "inner"\n'
               '[lubricant]\npreset = "iso_vg_68"\ntemperature = "90 degC"\nsupply = "grease"\ncleanliness = "custom"\n'
               'contamination_factor = 0.05\n')
    shoulders = 'inner_shoulder_diameter = "72.5 mm"\nouter_shoulder_diameter = "122.5 mm"\n'
    shaft = _run(tmp_path, ENTRY + shoulders + 'position = "40 mm"\norientation = "-z"\n[shaft]\nspeed = "3000 rpm"\n'
                 f'[[loads]]\nposition = "40 mm"\nforce = ["{LOAD[0]}", "-{LOAD[1]}", "-{LOAD[2]}"]\n' + effects,
                 "shaft.toml")
    single = _run(tmp_path, BEARING_6411E + shoulders + 'dynamic_load_rating = "101 kN"\n[operating]\ninner_speed = "3000 rpm"\n'
                  f'force = ["{LOAD[0]}", "{LOAD[1]}", "{LOAD[2]}"]\n' + effects, "single.toml")
    assert bool(shaft.values["shaft.converged"]) and bool(single.values["converged"])
    scale = np.max(np.abs(single.values["displacement"]))
    np.testing.assert_allclose(shaft.values["bearings.displacement"][0], single.values["displacement"], rtol=1e-9,
                               atol=1e-9 * scale)
    np.testing.assert_allclose(shaft.values["bearings.force"][0], single.values["force"], rtol=1e-9, atol=1e-9)
    assert float(shaft.values["bearings.max_element_load"][0]) == pytest.approx(
        float(np.max(single.values["balls.inner.load"])), rel=1e-9)
    np.testing.assert_allclose(shaft.values["bearings.elements.azimuth"][0], single.values["balls.azimuth"], rtol=1e-15)
    for side in ("inner", "outer"):
        for field in ("load", "contact_angle", "max_pressure"):
            np.testing.assert_allclose(shaft.values[f"bearings.elements.{side}_{field}"][0],
                                       single.values[f"balls.{side}.{field}"], rtol=1e-9,
                                       atol=1e-9 * float(np.max(np.abs(single.values[f"balls.{side}.{field}"]))))
    assert float(shaft.values["bearings.L10r"][0]) == pytest.approx(float(single.values["life.L10r"]), rel=1e-9)
    assert float(shaft.values["shaft.L10r"]) == pytest.approx(float(single.values["life.L10r"]), rel=1e-12)
    for mine, theirs in (("static_load_rating", "static_load_rating"), ("equivalent_static_load", "equivalent_static_load"),
                         ("iso76", "iso76"), ("static_safety", "static")):
        assert float(shaft.values[f"bearings.{mine}"][0]) == pytest.approx(float(single.values[f"safety.{theirs}"]),
                                                                           rel=1e-9), mine
    for field in ("cage", "ball_pass_outer", "ball_pass_inner", "ball_spin"):
        assert float(shaft.values[f"bearings.frequencies.{field}"][0]) == pytest.approx(
            float(single.values[f"frequencies.{field}"]), rel=1e-9), field
    assert float(shaft.values["bearings.friction.torque"][0]) == pytest.approx(float(single.values["friction.torque"]),
                                                                               rel=1e-9)
    assert float(shaft.values["shaft.friction.power"]) == pytest.approx(float(single.values["friction.power"]), rel=1e-9)
    assert float(shaft.values["bearings.a_iso"][0]) == pytest.approx(float(single.values["life.a_iso_reference"]), rel=1e-9)
    assert 0.1 < float(shaft.values["bearings.a_iso"][0]) < 50.0
    assert float(shaft.values["shaft.L10rm"]) == pytest.approx(float(single.values["life.L10rm"]), rel=1e-9)
    share = single.values["balls.inner.shoulder_share"]
    assert np.max(share) > 0.0
    for side in ("inner", "outer"):
        np.testing.assert_allclose(shaft.values[f"bearings.elements.{side}_shoulder_share"][0],
                                   single.values[f"balls.{side}.shoulder_share"], rtol=1e-9, atol=1e-12)
    assert f"bearing 0: the contact ellipse of ball {np.argmax(share)} passes the inner ring's shoulder edge: " \
           f"{np.max(share) * 100:.3g} %" in " ".join(shaft.problems[1])
    # issue 46: the single bearing's free tilt (2.80 mrad) is warned of; on the shaft it is 0.2 mrad
    # short of the 10′ a rigid bearing permits
    tilt = float(np.hypot(*single.values["displacement"][3:]))
    assert any(f"tilts freely by {tilt * 1e3:.3g} mrad" in line for line in single.problems[1])
    assert (tilt > RIGID_MISALIGNMENT) == any("its rings tilt" in line for line in shaft.problems[1])


def test_a_bearing_tilted_beyond_ten_arcmin_is_warned_of():
    """A bearing's rings tilted against each other by more than 10′ (2.909 mrad), on either axis:
    a warning naming the bearing and the tilt; within it, none; a bearing that permits 2.5° (a
    self-aligning one) tilted by 1.01 × 10′, none."""
    limit = np.radians(10.0 / 60.0)
    tilts = np.array([[0.0, 0.0, 0.0, 0.99 * limit, 0.0], [0.0, 0.0, 0.0, 0.6 * limit, 0.9 * limit],
                      [0.0, 0.0, 0.0, 0.0, -1.01 * limit], [0.0, 0.0, 0.0, 0.0, -1.01 * limit]])
    warnings = misalignment_warnings(tilts, [limit, limit, limit, np.radians(2.5)])
    assert len(warnings) == 2
    assert warnings[0].startswith(f"bearing 1: its rings tilt {np.hypot(0.6, 0.9) * limit * 1e3:.3g} mrad")
    assert warnings[1].startswith("bearing 2: its rings tilt 2.94 mrad (10.1′)")


@pytest.mark.slow
def test_gearbox_shaft_balances_its_load(capsys, tmp_path):
    """The packaged gearbox_shaft: the bearings' reactions (shaft frame, at each bearing) balance
    the gear's force and moment about z = 0 exactly; the system life is below each bearing's."""
    result = run_model(build_model(load_scene("gearbox_shaft")), progress=False)
    reaction = np.asarray(result.values["bearings.reaction"])
    positions = np.array([-0.1, 0.1])
    force = np.array([6e3, 2e3, 1.5e3])
    np.testing.assert_allclose(reaction[:, :3].sum(axis=0), force, rtol=1e-9)
    # moments about z = 0: each bearing's own moment plus z × its force; the gear's 90 N·m about y and 0.03 m × F
    moment_x = reaction[:, 3].sum() - (positions * reaction[:, 1]).sum()
    moment_y = reaction[:, 4].sum() + (positions * reaction[:, 0]).sum()
    np.testing.assert_allclose([moment_x, moment_y], [-0.03 * force[1], 90.0 + 0.03 * force[0]], rtol=1e-9)
    lives = np.asarray(result.values["bearings.L10r"])
    assert float(result.values["shaft.L10r"]) == pytest.approx(np.sum(lives ** (-10 / 9)) ** (-0.9), rel=1e-12)


@pytest.mark.parametrize("entry, named", [
    ('orientation = "sideways"\nposition = "0 mm"\n', "bearings[0].orientation"),
    ('position = "0 mm"\nfoo = 1\n', "bearings[0]: unknown key 'bearing.foo'"),
    ("", "bearings[0]: missing required key 'position'"),
    ('position = "0 mm"\nroller_length = "10 mm"\n', "bearings[0]: key 'roller_length' is not read"),
    ('position = "0 mm"\ninner_shoulder_diameter = "72.5 mm"\n',
     "bearings[0]: outer_shoulder_diameter: give both shoulder diameters with inner_shoulder_diameter"),
    ('position = "0 mm"\ninner_shoulder_diameter = "60 mm"\nouter_shoulder_diameter = "122.5 mm"\n',
     "bearings[0]: inner_shoulder_diameter must be between 70.5 mm and 98.3 mm"),
])
def test_bad_shafts_are_refused(capsys, tmp_path, entry, named):
    path = tmp_path / "bad.toml"
    path.write_text(ENTRY + entry + '[[loads]]\nposition = "0 mm"\nforce = ["1 kN", "0 N", "0 N"]\n')
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err


CYLINDRICAL = """
[[bearings]]
type = "cylindrical_roller"
position = "-100 mm"
roller_diameter = "25.4 mm"
roller_length = "14.7 mm"
pitch_diameter = "106.6 mm"
rollers = 12
radial_clearance = "20 um"
[bearings.profile]
kind = "circular"
flat_length = "12.7 mm"
crown_radius = "50 mm"
"""


OIL = '[lubricant]\npreset = "iso_vg_68"\ntemperature = "60 degC"\n'


def test_roller_bearing_on_a_shaft_is_the_whole_roller_bearing_run(tmp_path):
    """A cylindrical roller bearing (the packaged example's) and the 6411E on a shaft under a gear
    load: the roller bearing's radial displacement and tilt, roller loads and its L10r equal the whole roller
    bearing scene's under the load and moment it carries on the shaft, to 1e-9, both with 20 laminae."""
    shaft = _run(tmp_path, CYLINDRICAL + ENTRY + 'position = "100 mm"\n[[loads]]\nposition = "20 mm"\n'
                 'force = ["5 kN", "2 kN", "1 kN"]\n[shaft]\nspeed = "1500 rpm"\n[effects]\nlife = true\nsafety = true\n'
                 'frequencies = true\nfriction = "palmgren"\n[fidelity]\nlaminae = 20\n' + OIL, "gearbox.toml")
    assert bool(shaft.values["shaft.converged"])
    force = [float(value) for value in shaft.values["bearings.force"][0]]
    assert force[2] == 0.0  # no axial load on the cylindrical roller bearing
    text = (CYLINDRICAL.replace("[[bearings]]", "[bearing]").replace("[bearings.profile]", "[profile]")
            .replace('position = "-100 mm"\n', "")
            + f'[operating]\nforce = ["{force[0]!r} N", "{force[1]!r} N", "0 N"]\n'
            + f'moment = ["{force[3]!r} N*m", "{force[4]!r} N*m"]\ninner_speed = "1500 rpm"\n'
            + '[effects]\ncontact = "slices"\nlife = true\nsafety = true\nfrequencies = true\nfriction = "palmgren"\n'
            + '[fidelity]\nlaminae = 20\n' + OIL)
    alone = _run(tmp_path, text, "roller.toml")
    local = np.asarray(shaft.values["bearings.displacement"][0])
    np.testing.assert_allclose(local[[0, 1, 3, 4]], np.asarray(alone.values["displacement"])[[0, 1, 3, 4]], rtol=1e-9,
                               atol=1e-9 * np.max(np.abs(local[:2])))
    assert float(shaft.values["bearings.L10r"][0]) == pytest.approx(float(alone.values["life.L10r"]), rel=1e-9)
    assert float(shaft.values["bearings.static_safety"][0]) == pytest.approx(float(alone.values["safety.static"]),
                                                                             rel=1e-9)
    assert float(shaft.values["bearings.iso76"][0]) == pytest.approx(float(alone.values["safety.iso76"]), rel=1e-9)
    assert float(shaft.values["bearings.frequencies.ball_pass_inner"][0]) == pytest.approx(
        float(alone.values["frequencies.ball_pass_inner"]), rel=1e-12)
    assert float(shaft.values["bearings.friction.torque"][0]) == pytest.approx(float(alone.values["friction.torque"]),
                                                                               rel=1e-9)
    # the roller bearing's Hertz approach limit reaches the shaft (bearings.validity's first column)
    assert float(shaft.values["bearings.validity"][0][0]) == pytest.approx(
        float(alone.values["validity.approach_ratio"]), rel=1e-9)
    rollers = len(alone.values["rollers.azimuth"])  # 12, the 6411E's 7 balls padded with NaN to 12
    assert np.isnan(shaft.values["bearings.elements.inner_contact_angle"][0]).all()
    assert np.isnan(shaft.values["bearings.elements.inner_load"][1][7:]).all()
    for side in ("inner", "outer"):
        loads = np.asarray(alone.values[f"rollers.{side}.load"])
        np.testing.assert_allclose(shaft.values[f"bearings.elements.{side}_load"][0][:rollers], loads, rtol=1e-9,
                                   atol=1e-9 * loads.max())


@pytest.mark.slow
def test_element_loads_derivatives_through_the_shaft():
    """d(every ball's inner load, both bearings)/d(the gear load) through the gearbox shaft's equilibrium
    against a central difference, forward and reverse (the balls out of contact stay at zero)."""
    import equinox as eqx

    from .helpers import assert_jvp_matches_central_difference, example_scene

    model = build_model(load_scene(example_scene("gearbox_shaft"), ["effects.stiffness=false"]))
    function = model.function()

    def element_loads(forces):
        inputs = eqx.tree_at(lambda i: i["shaft"].loads.forces, model.inputs, forces)
        return function(inputs)["bearings.elements.inner_load"]

    forces = model.inputs["shaft"].loads.forces
    direction = np.ones_like(forces) * np.array([100.0, -50.0, 30.0])
    assert_jvp_matches_central_difference(element_loads, forces, direction, 1e-3, rtol=1e-6, atol=1e-6)


SECTIONS = """
[[shaft.sections]]
from = "-130 mm"
to = "-60 mm"
outer_diameter = "55 mm"

[[shaft.sections]]
from = "-60 mm"
to = "130 mm"
outer_diameter = "70 mm"
inner_diameter = "20 mm"
"""


@pytest.mark.slow
def test_flexible_shaft_scene(tmp_path):
    """The gearbox shaft as a Timoshenko beam of two sections ([[shaft.sections]]): the scene's
    bearing loads and deflection line are `flexible_shaft`'s own (1e-12, 1e-9); the reactions balance the
    gear's force and moment about z = 0 (1e-9, an identity of any equilibrium: the beam's internal
    forces cancel); the reference point's displacement is its node's."""
    text = (importlib.resources.files("diffbearing.scenes").joinpath("gearbox_shaft.toml").read_text()
            .replace("[shaft]\n", '[shaft]\nstiffness_at = "30 mm"\nelement_length = "20 mm"\n')
            .replace("stiffness = true\n", "") + SECTIONS)
    result = _run(tmp_path, text, "flexible.toml")
    assert bool(result.values["shaft.converged"])
    layout = result.model.inputs["shaft"]
    flexible = flexible_shaft(Shaft(layout_supports(layout, result.model.settings), layout.loads, layout.speed),
                              layout.sections, 0.03, 0.02)
    own = solve_flexible_shaft(flexible)
    np.testing.assert_allclose(result.values["bearings.force"], np.stack(own.bearing_forces), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(result.values["shaft.deflection"], own.node_displacements, rtol=1e-9, atol=1e-15)
    nodes = np.asarray(result.values["shaft.nodes"])
    assert np.max(np.diff(nodes)) <= 0.02 + 1e-15 and nodes[0] == pytest.approx(-0.13) and nodes[-1] == pytest.approx(0.13)
    at = int(np.argmin(np.abs(nodes - 0.03)))
    np.testing.assert_allclose(result.values["shaft.displacement"], result.values["shaft.deflection"][at], rtol=1e-15)
    reaction = np.asarray(result.values["bearings.reaction"])
    force, positions = np.array([6e3, 2e3, 1.5e3]), np.array([-0.1, 0.1])
    np.testing.assert_allclose(reaction[:, :3].sum(axis=0), force, rtol=1e-9)
    moment_x = reaction[:, 3].sum() - (positions * reaction[:, 1]).sum()
    moment_y = reaction[:, 4].sum() + (positions * reaction[:, 0]).sum()
    np.testing.assert_allclose([moment_x, moment_y], [-0.03 * force[1], 90.0 + 0.03 * force[0]], rtol=1e-9)


@pytest.mark.parametrize("extra, named", [
    ('[[shaft.sections]]\nfrom = "-130 mm"\nto = "0 mm"\nouter_diameter = "50 mm"\n'
     '[[shaft.sections]]\nfrom = "10 mm"\nto = "130 mm"\nouter_diameter = "50 mm"\n', "shaft.sections[1]: starts at"),
    ('[[shaft.sections]]\nfrom = "-50 mm"\nto = "130 mm"\nouter_diameter = "50 mm"\n',
     "bearings[0].position = -100 mm lies off the shaft, whose sections run from -50 mm to 130 mm"),
    ('[[shaft.sections]]\nfrom = "-130 mm"\nto = "130 mm"\nouter_diameter = "50 mm"\nbore = "10 mm"\n',
     "shaft.sections[0]: unknown key 'bore'"),
    ('[shaft]\nmaterial = "steel"\n', "'shaft.material' not read"),
])
def test_bad_flexible_shafts_are_refused(capsys, tmp_path, extra, named):
    path = tmp_path / "bad.toml"
    text = (ENTRY + 'position = "-100 mm"\n' + ENTRY + 'position = "100 mm"\n'
            + '[[loads]]\nposition = "0 mm"\nforce = ["1 kN", "0 N", "0 N"]\n' + extra)
    path.write_text(text)
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err
