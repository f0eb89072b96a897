"""The double-row angular-contact ball bearing as a scene's [[bearings]] entry (adapters/bearings/
double_row.py): the packaged example against the Python interface, its ISO 76 rating written out,
SKF's double-row series, the element loads of its more loaded row, and the errors a user meets."""

import importlib.resources

import numpy as np
import pytest

from diffbearing import Shaft, ShaftLoads, build_model, load_scene, run_model, solve_shaft
from diffbearing.app import cli
from diffbearing.bearings.ball.double_row import DoubleRowSupport
from diffbearing.friction import skf_friction
from diffbearing.ratings.reference_life import contact_reference_life

from .test_double_row import ROW, SPACING

SCENE = importlib.resources.files("diffbearing.scenes") / "double_row_pulley.toml"
# the scene's 15 mm between the rows' balls, less 2 (f_i − ½) D_w sin α₀: the rows' planes of inner groove centres
REFERENCE_SPACING = SPACING - 2 * 0.02 * 11.1e-3 * np.sin(np.radians(30.0))


@pytest.fixture(scope="module")
def pulley():
    return run_model(build_model(load_scene(str(SCENE))), progress=False)


def test_the_example_is_the_python_interfaces_solution(pulley):
    """The scene's bearing load, displacement and L10r equal `solve_shaft` on the `DoubleRowSupport`
    of the same geometry (the example's rows are tests/test_double_row.py's) to 1e-9."""
    values = pulley.values
    assert bool(values["shaft.converged"])
    support = DoubleRowSupport(ROW, REFERENCE_SPACING, 0.0, axial_clearance=10e-6)
    shaft = Shaft((support,), ShaftLoads(np.array([0.03]), np.array([[4000.0, 0.0, 600.0]]), np.zeros((1, 2))),
                  1500 * np.pi / 30)
    solution = solve_shaft(shaft)
    np.testing.assert_allclose(values["bearings.force"][0], solution.bearing_forces[0], rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(values["shaft.displacement"], solution.displacement, rtol=1e-9, atol=1e-15)
    contacts = support.contacts(solution.bearing_displacements[0], shaft.speed, solution.constants[0])
    life = contact_reference_life(contacts, support.contact_ratings(support.dynamic_load_rating(), contacts))
    assert float(values["bearings.L10r"][0]) == pytest.approx(float(life), rel=1e-9)


def test_its_static_safety_is_iso_76_with_two_rows(pulley):
    """C₀r = f₀ i Z D_w² cos α with i = 2 and f₀ of ISO 76 Table 1 at γ = D_w cos α / d_m = 0.1538
    (between 15.2 at 0.15 and 14.9 at 0.16), P₀r = F_r + 2 × 0.33 F_a (Table 2's double-row column
    at 30°), from the load the bearing carries."""
    values = pulley.values
    gamma = 11.1 * np.cos(np.radians(30.0)) / 62.5
    f0 = 15.2 + (14.9 - 15.2) * (gamma - 0.15) / 0.01
    rating = f0 * 2 * 13 * 11.1**2 * np.cos(np.radians(30.0))
    force = np.asarray(values["bearings.force"][0])
    load = np.hypot(force[0], force[1]) + 0.66 * abs(force[2])
    assert float(values["bearings.static_load_rating"][0]) == pytest.approx(rating, rel=1e-12)
    assert float(values["bearings.iso76"][0]) == pytest.approx(rating / load, rel=1e-9)


def test_its_friction_is_skfs_double_row_series(pulley):
    """SKF's moment of an angular-contact bearing of the "double_row" series (Table 3) under the load
    it carries, with its ISO 76 C₀ (two rows), d, D of the entry, grease."""
    values = pulley.values
    force = np.asarray(values["bearings.force"][0])
    lubricant = pulley.model.inputs["lubricant"]
    expected = skf_friction.frictional_moment(
        "angular_contact_ball", "double_row", np.hypot(force[0], force[1]), abs(force[2]), 1500 * np.pi / 30,
        float(lubricant.viscosity / lubricant.density), 0.04, 0.08, supply="grease",
        static_load_rating=float(values["bearings.static_load_rating"][0]))
    assert float(values["bearings.friction.torque"][0]) == pytest.approx(float(expected.total), rel=1e-9)


def test_each_positions_element_load_is_its_more_loaded_rows(pulley):
    """The shaft's per-element inner loads of a double-row bearing: at each azimuth the larger of its
    two rows' ball loads (`ContactLoads` columns 0 and 2)."""
    values, layout = pulley.values, pulley.model.inputs["shaft"]
    support = DoubleRowSupport(ROW, REFERENCE_SPACING, 0.0, axial_clearance=10e-6)
    local = values["bearings.displacement"][0]
    contacts = support.contacts(local, layout.speed, support.constants())
    rows = np.asarray(contacts.load)[:, [0, 2]]
    assert rows.min() < 0.5 * rows.max()  # the moment loads the rows unequally
    np.testing.assert_allclose(values["bearings.elements.inner_load"][0], rows.max(axis=1), rtol=1e-9)


@pytest.mark.parametrize("change, named", [
    (('friction = "skf"', 'friction = "palmgren"'), "effects.friction: bearings[0] (double_row_angular_contact_ball) "
                                                    "is not covered by the 'palmgren' friction model"),
    (('row_spacing = "15 mm"', 'row_spacing = "0.2 mm"'), "bearings[0]: row_spacing must be > 0.000222 m"),
    (('axial_clearance = "10 um"', 'inner_groove_radius = "5.8 mm"'),
     "bearings[0]: bearing: give exactly one of inner_groove_ratio and inner_groove_radius"),
    (('contact_angle = "30 deg"', ''), "bearings[0]: missing required key 'contact_angle'"),
    (('contact_angle = "30 deg"', 'contact_angle = "50 deg"'),
     "bearings[0].contact_angle: 50° is outside ISO 281 Table 3's 0° to 45°"),
    (('contact_angle = "30 deg"', 'contact_angle = "50 deg"', 'life = true', 'life = false'),
     "bearings[0].contact_angle: 50° is outside ISO 76 Table 2's 5° to 45°"),
])
def test_bad_double_row_entries_are_refused(capsys, tmp_path, change, named):
    path = tmp_path / "bad.toml"
    text = SCENE.read_text()
    for old, new in zip(change[::2], change[1::2]):
        text = text.replace(old, new)
    path.write_text(text)
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err


def test_a_double_row_bearing_alone_is_sent_to_a_shaft(capsys, tmp_path):
    path = tmp_path / "single.toml"
    path.write_text('[bearing]\ntype = "double_row_angular_contact_ball"\nball_diameter = "11.1 mm"\n'
                    'pitch_diameter = "62.5 mm"\nballs = 13\ncontact_angle = "30 deg"\nrow_spacing = "15 mm"\n'
                    '[operating]\nforce = ["1 kN", "0 N", "0 N"]\n')
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and "bearing.type: a double_row_angular_contact_ball bearing is modelled on a shaft only" in err
