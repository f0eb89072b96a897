"""The four-point-contact ball bearing as a scene's [[bearings]] entry (adapters/bearings/
four_point.py): the packaged slewing-ring example against the Python interface, its ISO 76 rating
written out, its moment warning, and the errors a user meets."""

import importlib.resources

import numpy as np
import pytest

from diffbearing import Shaft, ShaftLoads, build_model, load_scene, run_model, solve_shaft
from diffbearing.app import cli
from diffbearing.bearings.ball.four_point import FourPointSupport
from diffbearing.ratings.reference_life import contact_reference_life

from .test_four_point import SLEWING

SCENE = importlib.resources.files("diffbearing.scenes") / "slewing_ring.toml"
LOADS = ShaftLoads(np.zeros(1), np.array([[16e3, 0.0, 87e3]]), np.array([[0.0, 160e3]]))


@pytest.fixture(scope="module")
def ring():
    return run_model(build_model(load_scene(str(SCENE))), progress=False)


@pytest.mark.slow
def test_the_example_is_the_python_interfaces_solution(ring):
    """The scene's bearing load, displacement and L10r equal `solve_shaft` on the `FourPointSupport`
    of the same geometry (tests/test_four_point.py's slewing ring, 100 µm clearance) to 1e-9."""
    values = ring.values
    assert bool(values["shaft.converged"])
    support = FourPointSupport(SLEWING, 0.0, 100e-6)
    shaft = Shaft((support,), LOADS, np.pi / 30)
    solution = solve_shaft(shaft)
    np.testing.assert_allclose(values["bearings.force"][0], solution.bearing_forces[0], rtol=1e-9, atol=1e-4)
    np.testing.assert_allclose(values["shaft.displacement"], solution.displacement, rtol=1e-9, atol=1e-15)
    contacts = support.contacts(solution.bearing_displacements[0], shaft.speed, solution.constants[0])
    life = contact_reference_life(contacts, support.contact_ratings(support.dynamic_load_rating(), contacts))
    assert float(values["bearings.L10r"][0]) == pytest.approx(float(life), rel=1e-9)
    assert float(values["bearings.max_element_load"][0]) == pytest.approx(float(np.max(contacts.load[:, ::2])),
                                                                          rel=1e-9)
    # ISO 281: F_a/F_r = 5.4 beyond e = 1.34 at 45°, P = 0.54 F_r + 0.81 F_a (Table 3, double row), (C_r/P)³
    force = np.asarray(values["bearings.force"][0])
    load = 0.54 * np.hypot(force[0], force[1]) + 0.81 * abs(force[2])
    assert float(values["bearings.L10"][0]) == pytest.approx((float(support.dynamic_load_rating()) / load) ** 3,
                                                             rel=1e-9)
    assert any("L10 leaves out the tilting moment" in warning for warning in ring.problems[1])


@pytest.mark.slow
def test_its_static_safety_is_iso_76_as_two_rows_and_warns_of_the_moment(ring):
    """C₀r = f₀ i Z D_w² cos α with i = 2 and f₀ of ISO 76 Table 1 at γ = 20 cos 45° / 1094 = 0.01293
    (between 14.9 at 0.01 and 15.1 at 0.02), P₀r = F_r + 0.44 F_a (Table 2's double-row column at
    45°); the tilting moment, which P₀ leaves out, named in a warning."""
    values = ring.values
    gamma = 20.0 * np.cos(np.radians(45.0)) / 1094.0
    f0 = 14.9 + (15.1 - 14.9) * (gamma - 0.01) / 0.01
    assert float(values["bearings.static_load_rating"][0]) == pytest.approx(
        f0 * 2 * 137 * 20.0**2 * np.cos(np.radians(45.0)), rel=1e-12)
    force = np.asarray(values["bearings.force"][0])
    load = np.hypot(force[0], force[1]) + 2 * 0.22 * abs(force[2])
    assert float(values["bearings.equivalent_static_load"][0]) == pytest.approx(load, rel=1e-12)
    rating = float(values["bearings.static_load_rating"][0])
    assert float(values["bearings.iso76"][0]) == pytest.approx(rating / load, rel=1e-12)
    assert any("s0 leaves out the tilting moment" in warning for warning in ring.problems[1])


@pytest.mark.parametrize("change, named", [
    (('radial_clearance = "100 um"', ''), "bearings[0]: missing required key 'radial_clearance'"),
    (('radial_clearance = "100 um"', 'radial_clearance = "5 mm"'), "bearings[0]: radial_clearance must be"),
    (('radial_clearance = "100 um"', 'radial_clearance = "100 um"\nrow_spacing = "15 mm"'),
     "row_spacing"),
    (('frequencies = true', 'frequencies = true\ncentrifugal = true'),
     "effects.centrifugal, effects.gyroscopic: the four-point-contact model is static"),
])
def test_bad_four_point_entries_are_refused(capsys, tmp_path, change, named):
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.read_text().replace(*change))
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err


def test_a_four_point_bearing_alone_is_sent_to_a_shaft(capsys, tmp_path):
    path = tmp_path / "single.toml"
    path.write_text('[bearing]\ntype = "four_point_contact_ball"\nball_diameter = "15 mm"\n'
                    'pitch_diameter = "65 mm"\nballs = 12\ncontact_angle = "35 deg"\nradial_clearance = "60 um"\n'
                    '[operating]\nforce = ["1 kN", "0 N", "0 N"]\n')
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and "bearing.type: a four_point_contact_ball bearing is modelled on a shaft only" in err
