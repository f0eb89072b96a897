"""Designations: the shipped ISO 15 boundary dimensions (GOST 8338-75 for deep groove ball bearings,
GOST 24696-81 for spherical roller bearings, GOST 8328-75 for the 22 and 23 width series of
cylindrical roller bearings, and through their dimension series the angular contact, self-aligning,
four-point and other cylindrical roller series) against the catalogue dimensions of 44 bearings
across 28 series, two standards' dimension series 22 and 23 against each other, the dimension
series' own identities (D set by the diameter series alone), the parsing of designations, their use
in a scene and a shaft's entries (the values the scene did not write, named in the report and the
JSON), the estimated ball sets (deep groove against published sets, angular contact against Timken's
47 7200 B/7300 B bearings and Harris's 218), and `diffbearing bearings`."""

import csv
import json
from pathlib import Path

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.catalog import designations

from .helpers import assert_exits_2_naming, example_scene

# d × D × B [mm] as the manufacturers' catalogues print them (SKF, FAG: the same ISO 15 values)
CATALOGUE = {
    "6200": (10, 30, 9), "6203": (17, 40, 12), "6205": (25, 52, 15), "6208": (40, 80, 18), "6211": (55, 100, 21),
    "6220": (100, 180, 34), "6305": (25, 62, 17), "6308": (40, 90, 23), "6312": (60, 130, 31), "6316": (80, 170, 39),
    "6406": (30, 90, 23), "6411": (55, 140, 33), "6005": (25, 47, 12), "6010": (50, 80, 16), "6020": (100, 150, 24),
    "16005": (25, 47, 8), "61905": (25, 42, 9), "61805": (25, 37, 7), "22208": (40, 80, 23), "22220": (100, 180, 46),
    "22312": (60, 130, 46), "22320": (100, 215, 73), "23024": (120, 180, 46), "23120": (100, 165, 52),
    "24024": (120, 180, 60), "24122": (110, 180, 69),
    # other types in the same dimension series (ISO 15): angular contact, self-aligning, four-point, cylindrical roller
    "7205 B": (25, 52, 15), "7308 BECBP": (40, 90, 23), "7220": (100, 180, 34), "1205": (25, 52, 15), "1306": (30, 72, 19),
    "QJ 208 MA": (40, 80, 18), "NU 310": (50, 110, 27), "NU 205 ECP": (25, 52, 15), "NU1010": (50, 80, 16),
    "N 312": (60, 130, 31), "NU 412": (60, 150, 35),
    # the 22 and 23 width series: cylindrical roller (GOST 8328-75), and by them self-aligning ball bearings
    "NU 2205": (25, 52, 18), "NU 2310": (50, 110, 40), "NU 2320": (100, 215, 73), "NJ 2212": (60, 110, 28),
    "NUP 2308": (40, 90, 33), "2205": (25, 52, 18), "2305": (25, 62, 24),
}
TYPES = {"7": "angular_contact_ball", "1": "self_aligning_ball", "Q": "four_point_contact_ball", "N": "cylindrical_roller"}


@pytest.mark.parametrize("designation", CATALOGUE)
def test_boundary_dimensions_are_the_catalogues(designation):
    """Each bearing's d, D, B from the shipped tables equal the catalogue's (exact, in mm), with the
    standard's table named."""
    found = designations.boundary_dimensions(designation)
    assert (round(found.bore * 1e3, 6), round(found.outside_diameter * 1e3, 6), round(found.width * 1e3, 6)) == \
        CATALOGUE[designation]
    assert any(f"{standard} Table" in found.source for standard in ("GOST 8338-75", "GOST 24696-81", "GOST 8328-75"))
    if designation[0] in TYPES and not designation.startswith("16"):
        assert found.bearing_type == TYPES[designation[0]]
        assert found.source.startswith("ISO 15 dimension series") == (found.series not in ("NU22", "NU23"))


# d × D × B (a thrust bearing's height H) [mm] of the double-row, needle, thrust and 213 series, as SKF's
# catalogue prints them (3205 A, 3308 A, NA 4905, 81105 TN, 51105, 21310 E …), with the bearing type
OTHER_TYPES = {
    "3205 A": (25, 52, 20.6, "double_row_angular_contact_ball"), "3210": (50, 90, 30.2, "double_row_angular_contact_ball"),
    "3308 A": (40, 90, 36.5, "double_row_angular_contact_ball"), "NA 4905": (25, 42, 17, "needle_roller"),
    "NA4910": (50, 72, 22, "needle_roller"), "NA 4920": (100, 140, 40, "needle_roller"),
    "81105 TN": (25, 42, 11, "cylindrical_roller_thrust"), "81212": (60, 95, 26, "cylindrical_roller_thrust"),
    "81120 TN": (100, 135, 25, "cylindrical_roller_thrust"), "51105": (25, 42, 11, "thrust_ball"),
    "51110": (50, 70, 14, "thrust_ball"), "51206": (30, 52, 16, "thrust_ball"), "51210": (50, 78, 22, "thrust_ball"),
    "21308 E": (40, 90, 23, "spherical_roller"), "21310 E": (50, 110, 27, "spherical_roller"),
    "51305": (25, 52, 18, "thrust_ball"), "51310": (50, 95, 31, "thrust_ball"), "51410": (50, 110, 43, "thrust_ball"),
}


# d × D, T, B, C [mm] of tapered roller bearings as SKF's catalogue prints them (30205 J2/Q, …)
TAPERED = {"30205": (25, 52, 16.25, 15, 13), "30210": (50, 90, 21.75, 20, 17), "30308": (40, 90, 25.25, 23, 20),
           "31310": (50, 110, 29.25, 27, 19), "32010 X": (50, 80, 20, 20, 15.5), "32210": (50, 90, 24.75, 23, 19),
           "32310": (50, 110, 42.25, 40, 33)}


@pytest.mark.parametrize("designation", TAPERED)
def test_the_tapered_series_are_the_catalogues(designation):
    """Tapered roller bearings of the 302, 303, 313, 320, 322, 323 series (Timken's catalogue, checked
    against URB's and SKF's): d, D, T, B, C as SKF prints them (exact), with the ISO 355 series named."""
    found = designations.boundary_dimensions(designation)
    assert found.bearing_type == "tapered_roller" and "ISO 355 series" in found.source
    assert [round(x * 1e3, 6) for x in (found.bore, found.outside_diameter, found.total_width, found.width,
                                        found.outer_ring_width)] == list(TAPERED[designation])


@pytest.mark.parametrize("designation", OTHER_TYPES)
def test_the_double_row_needle_and_thrust_series_are_the_catalogues(designation):
    """GOST 4252-75 (32, 33), GOST 4657-82 (NA49), GOST 23526-79 (811, 812) and, through their dimension
    series, the thrust ball 511, 512 (ISO 104) and spherical roller 213 (ISO 15, as 63): d, D, B (H) of
    each as SKF prints it (exact), its type."""
    found = designations.boundary_dimensions(designation)
    *dimensions, bearing_type = OTHER_TYPES[designation]
    assert [round(x * 1e3, 6) for x in (found.bore, found.outside_diameter, found.width)] == dimensions
    assert found.bearing_type == bearing_type
    assert ("ISO 104 dimension series" in found.source) == (found.series in ("511", "512"))


@pytest.mark.parametrize("same_diameter_series", [("62", "222", "232", "NU22"), ("63", "223", "NU23"), ("60", "230", "240"),
                                                  ("231", "241"), ("62", "32"), ("63", "33"), ("619", "NA49"),
                                                  ("62", "302", "322"), ("63", "303", "313", "323"), ("60", "320")])
def test_the_outside_diameter_is_the_diameter_series_alone(same_diameter_series):
    """ISO 15: D depends on the bore and the diameter series only, so series of one diameter series
    (62, 222, 232, 32, 302, 322: 2; 63, 223, 33, 303, 313, 323: 3; 60, 230, 240, 320: 0; 231, 241: 1;
    619, NA49: 9), read from four standards and three catalogues, agree on every bore they share."""
    by_series = [{entry.bore: entry.outside_diameter for entry in designations.designations(f"{name}*")
                  if entry.series == name} for name in same_diameter_series]
    shared = set(by_series[0]).intersection(*by_series[1:])
    assert len(shared) >= 10
    for bore in shared:
        assert len({table[bore] for table in by_series}) == 1, bore


@pytest.mark.parametrize("one, other", [("NU22", "222"), ("NU23", "223")])
def test_the_width_is_the_dimension_series_alone(one, other):
    """ISO 15: d, D and B are the dimension series', so GOST 8328-75's cylindrical roller series 22, 23
    and GOST 24696-81's spherical roller 222, 223 agree on every bore they share (read apart from two
    standards: the check of each one's reading)."""
    first, second = ({entry.bore: (entry.outside_diameter, entry.width) for entry in designations.designations(f"{name}*")
                      if entry.series == name} for name in (one, other))
    shared = set(first) & set(second)
    assert len(shared) >= 25
    for bore in shared:
        assert first[bore] == second[bore], bore


@pytest.mark.parametrize("name", designations.series())
def test_each_series_grows_with_its_bore(name):
    """Within a series D and B never fall as d grows; B < (D − d)/2 · 3 and D > d (a ring's section)."""
    entries = sorted((entry for entry in designations.designations("*") if entry.series == name), key=lambda e: e.bore)
    bores, outsides, widths = (np.array([getattr(entry, field) for entry in entries])
                               for field in ("bore", "outside_diameter", "width"))
    assert np.all(np.diff(bores) > 0) and np.all(np.diff(outsides) >= 0) and np.all(np.diff(widths) >= 0)
    assert np.all(outsides > bores) and np.all(widths < 3 * (outsides - bores) / 2)


@pytest.mark.parametrize("written, designation, suffix, bore", [
    ("22220 E", "22220", "E", 0.1), ("24130 CC/W33", "24130", "CC/W33", 0.15), ("230/500", "230/500", "", 0.5),
    ("623", "623", "", 0.003), ("6205-2RS", None, None, None), ("6205 2RS", None, None, None)])
def test_designations_are_read_as_catalogues_write_them(written, designation, suffix, bore):
    if designation is None:  # a suffix must follow the digits without a hyphen: refused, naming the key
        with pytest.raises(ValueError, match="bearing.designation"):
            designations.boundary_dimensions(written)
        return
    found = designations.boundary_dimensions(written)
    assert (found.designation, found.suffix, found.bore) == (designation, suffix, bore)


@pytest.mark.parametrize("written", ["NU 2220", "62", "7205-B", "53205", "abc", "NA 6905", "33205"])
def test_a_designation_outside_the_data_is_refused_naming_the_key(written):
    with pytest.raises(ValueError, match="bearing.designation"):
        designations.boundary_dimensions(written)


def _scene(tmp_path, bearing_lines: str):
    """gearbox_6411_ratings with `bearing_lines` for its bore and outer diameter."""
    text = open(example_scene("gearbox_6411_ratings")).read().replace('bore = "55 mm"\nouter_diameter = "140 mm"\n',
                                                                      bearing_lines)
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return str(path)


def test_a_scenes_designation_gives_its_boundary_dimensions_and_says_so(capsys, tmp_path):
    """gearbox_6411_ratings with `designation = "6411"` for its bore and outer diameter: the same results
    as the example (1e-12), bore 55, D 140, B 33 mm from GOST 8338-75 Table 7, each named in the report
    and in the JSON's "derived"; a bore the scene gives overrides the designation's."""
    path = _scene(tmp_path, 'designation = "6411"\n')
    scene = load_scene(path)
    assert (scene.values["bearing.bore"], scene.values["bearing.outer_diameter"], scene.values["bearing.width"]) == \
        (0.055, 0.14, 0.033)
    assert set(scene.derived) == {"bearing.bore", "bearing.outer_diameter", "bearing.width"}
    example = run_model(build_model(load_scene(example_scene("gearbox_6411_ratings"))), progress=False).values
    values = run_model(build_model(scene), progress=False).values
    for key in ("life.L10rm", "friction.torque", "safety.iso76"):
        assert float(values[key]) == pytest.approx(float(example[key]), rel=1e-12)
    document = tmp_path / "out.json"
    assert cli.main(["run", path, "--json", str(document)]) == 0
    out = capsys.readouterr().out
    assert "bearing.bore = 55 mm  (designation 6411: GOST 8338-75 Table 7)" in out
    assert json.loads(document.read_text())["derived"]["bearing.width"] == "designation 6411: GOST 8338-75 Table 7"
    given = load_scene(_scene(tmp_path, 'designation = "6411"\nbore = "54 mm"\n'))
    assert given.values["bearing.bore"] == pytest.approx(0.054) and "bearing.bore" not in given.derived


@pytest.mark.parametrize("lines, named", [
    ('designation = "22220"\n', "bearing.designation: '22220' is a bearing of type spherical_roller"),
    ('designation = "NU 310"\n', "bearing.designation: 'NU 310' is a bearing of type cylindrical_roller"),
    ('designation = "NA 6905"\n', "bearing.designation: 'NA 6905' is not in the data"),
    ('designation = "6222"\n', "bearing.bore must be"),  # its 110 mm bore does not fit the scene's own balls
])
def test_a_bad_designation_in_a_scene_exits_2(capsys, tmp_path, lines, named):
    assert_exits_2_naming(capsys, ["run", _scene(tmp_path, lines)], named)


def test_the_bearings_command_lists_the_data(capsys):
    """`diffbearing bearings '62*'`: every 62-series bearing with d, D, B and its source; a pattern no
    designation matches exits 2."""
    assert cli.main(["bearings", "62*"]) == 0
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("6205 "))
    assert row.split()[1:5] == ["deep_groove_ball", "25", "52", "15"] and "GOST 8338-75 Table 5" in row
    assert cli.main(["bearings", "NA69*"]) == 2 and "no designation matches" in capsys.readouterr().err


# published internal geometry (balls × diameter [mm]) and the NSK catalogue's C_r, C₀r [kN] (NSK
# "Rolling Bearings" CAT. E1102, which are ISO 281's and ISO 76's of these balls), SKF's (above ISO 281's)
BALL_SETS = {"6205": (9, 7.938, (14.0, 7.85), (14.8, 7.8)), "6203": (8, 6.747, (9.55, 4.80), (9.95, 4.75)),
             "6208": (9, 11.906, (29.1, 17.8), None), "6308": (8, 15.081, (40.5, 24.0), None)}


@pytest.mark.parametrize("designation", BALL_SETS)
def test_the_estimated_ball_set_is_the_published_one(designation):
    """From d and D alone (typical proportions) and from the catalogue's C_r, C₀r (NSK's, and SKF's
    higher ones where given): the published ball count and diameter (to 1 µm)."""
    from diffbearing.catalog.internal_geometry import estimate_ball_set

    balls, diameter, nsk, skf = BALL_SETS[designation]
    dimensions = designations.boundary_dimensions(designation)
    for ratings in (nsk, skf) if skf else (nsk,):
        found = estimate_ball_set(dimensions.bore, dimensions.outside_diameter, ratings[0] * 1e3, ratings[1] * 1e3)
        assert (found.balls, round(found.ball_diameter * 1e3, 3)) == (balls, diameter)
    typical = estimate_ball_set(dimensions.bore, dimensions.outside_diameter)
    assert (typical.balls, round(typical.ball_diameter * 1e3, 3)) == (balls, diameter)
    assert typical.pitch_diameter == pytest.approx((dimensions.bore + dimensions.outside_diameter) / 2, rel=1e-15)


def test_every_ball_designation_has_a_ball_set_that_fits_its_rings():
    """Over every deep groove ball designation of the data: at least 3 balls, each under half the
    section (D − d)/2, Conrad-assembled (Z ≤ φ/(2 asin(D_w/d_m)) + 1), CN clearance where d ≤ 100 mm."""
    from diffbearing.catalog.internal_geometry import FILLING_ANGLE, estimate_ball_set, normal_clearance

    for entry in designations.designations("*"):
        if entry.bearing_type != "deep_groove_ball":
            continue
        found = estimate_ball_set(entry.bore, entry.outside_diameter)
        assert found.balls >= 3 and found.ball_diameter < (entry.outside_diameter - entry.bore) / 2, entry
        assert found.balls <= FILLING_ANGLE / (2 * np.arcsin(found.ball_diameter / found.pitch_diameter)) + 1
        assert (normal_clearance(entry.bore) is None) == (entry.bore > 0.1 or entry.bore <= 2.5e-3), entry


BALL_SET = ("balls", "ball_diameter", "pitch_diameter", "inner_groove_ratio", "outer_groove_ratio")


def _runs_with_estimates(capsys, tmp_path, text: str, keys) -> Path:
    """Run the scene `text` through the CLI: exit 0, each [bearing] key of `keys` named ESTIMATED in
    the JSON's "derived" and listed in the report; the scene's path."""
    path = tmp_path / "estimated.toml"
    path.write_text(text)
    document = tmp_path / "out.json"
    assert cli.main(["run", str(path), "--json", str(document)]) == 0
    out = capsys.readouterr().out
    derived = json.loads(document.read_text())["derived"]
    for key in keys:
        assert derived[f"bearing.{key}"].startswith("ESTIMATED") and f"bearing.{key} = " in out
    return path


def test_a_scene_of_a_designation_alone_runs_with_its_estimates_marked(capsys, tmp_path):
    """A [bearing] table holding only type and designation = "6205": the run converges with the
    published 9 × 7.938 mm balls, d_m 38.5 mm, f 0.52/0.53 and ISO 5753-1's CN middle, 12.5 µm (5–20 µm),
    each named ESTIMATED in the report and the JSON."""
    path = _runs_with_estimates(capsys, tmp_path, '[bearing]\ntype = "deep_groove_ball"\ndesignation = "6205"\n[operating]\n'
                                'inner_speed = "3000 rpm"\nforce = ["3 kN", "0 N", "0.5 kN"]\n[effects]\nlife = true\n',
                                BALL_SET + ("radial_clearance",))
    scene = load_scene(str(path))
    assert (scene.values["bearing.balls"], scene.values["bearing.radial_clearance"]) == (9, pytest.approx(12.5e-6))


@pytest.mark.parametrize("lines, named", [
    ('bore = "25 mm"\nouter_diameter = "52 mm"\nstatic_load_rating = "7.85 kN"\n', "bearing.static_load_rating is read with"),
])
def test_a_catalogue_c0_without_a_designation_exits_2(capsys, tmp_path, lines, named):
    assert_exits_2_naming(capsys, ["run", _scene(tmp_path, lines)], named)


def test_a_bore_past_the_clearance_table_asks_for_the_clearance(capsys, tmp_path):
    path = tmp_path / "big.toml"
    path.write_text('[bearing]\ntype = "deep_groove_ball"\ndesignation = "6222"\n[operating]\ninner_speed = "1000 rpm"\n'
                    'force = ["10 kN", "0 N", "0 N"]\n')
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and "bearing.radial_clearance: needed" in err, err


@pytest.mark.parametrize("key", ["dynamic_load_rating", "static_load_rating"])
def test_a_catalogue_rating_that_is_not_positive_exits_2_naming_it(capsys, tmp_path, key):
    path = tmp_path / "bad.toml"
    other = "static_load_rating" if key == "dynamic_load_rating" else "dynamic_load_rating"
    path.write_text(f'[bearing]\ntype = "deep_groove_ball"\ndesignation = "6205"\n{key} = "-1 kN"\n{other} = "7 kN"\n'
                    '[operating]\ninner_speed = "1000 rpm"\nforce = ["1 kN", "0 N", "0 N"]\n')
    code = cli.main(["run", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and f"bearing.{key}" in err and len(err.strip().splitlines()) == 1, err


def _timken_angular_contact():
    """Timken's 7200 B and 7300 B rows (tests/data/timken_7200_7300_B.csv): designation, d, D, B [mm], C_r, C₀r [kN]."""
    text = (Path(__file__).parent / "data" / "timken_7200_7300_B.csv").read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return [(row["designation"], *(float(row[key]) for key in ("d_mm", "D_mm", "B_mm", "C_kN", "C0_kN"))) for row in rows]


def test_the_72_and_73_series_are_timkens_angular_contact_bearings():
    """Each of the 47 7200 B/7300 B bearings of Timken's angular contact catalogue: d, D, B as the
    designation gives them through ISO 15's dimension series 02 and 03 (GOST 8338-75's 62, 63), exact."""
    rows = _timken_angular_contact()
    assert len(rows) == 47
    for designation, bore, outside, width, _, _ in rows:
        found = designations.boundary_dimensions(designation)
        assert (found.bore * 1e3, found.outside_diameter * 1e3, found.width * 1e3) == (bore, outside, width), designation
        assert found.bearing_type == "angular_contact_ball" and found.suffix == "B"


def test_the_angular_contact_ball_set_reproduces_timkens_ratings():
    """From Timken's C_r, C₀r at 40°, the estimated ball sets' ISO 281 and ISO 76 ratings: each within
    3 % of Timken's, 39 of the 47 within 0.5 %, rms 0.7 % (the sets are the bearings' own: Timken's
    ratings are ISO 281's, as the 7218 B below shows); from d, D alone (typical proportions) rms 5.5 %
    on C_r and 5.9 % on C₀r, the 7200 B, smallest, 25 % over."""
    from diffbearing.catalog.internal_geometry import ANGULAR_CONTACT, _ratings, estimate_ball_set

    angle = np.radians(40.0)
    fitted, typical = [], []
    for _, bore, outside, _, dynamic, static in _timken_angular_contact():
        for found, errors in ((estimate_ball_set(bore * 1e-3, outside * 1e-3, dynamic * 1e3, static * 1e3,
                                                 ANGULAR_CONTACT, angle), fitted),
                              (estimate_ball_set(bore * 1e-3, outside * 1e-3, proportions=ANGULAR_CONTACT), typical)):
            rated = _ratings(found.balls, found.ball_diameter, found.pitch_diameter, angle)
            errors.append((rated[0] / (dynamic * 1e3) - 1.0, rated[1] / (static * 1e3) - 1.0))
    fitted, typical = np.abs(fitted), np.abs(typical)
    assert fitted.max() < 0.03 and np.all(fitted < 0.005, axis=1).sum() == 39
    np.testing.assert_allclose(np.sqrt(np.mean(fitted ** 2, axis=0)), [0.0072, 0.0066], atol=5e-4)
    np.testing.assert_allclose(np.sqrt(np.mean(typical ** 2, axis=0)), [0.055, 0.059], atol=1e-3)
    assert typical.max() == pytest.approx(0.2526, abs=1e-3)


def test_the_7218_b_from_its_ratings_has_harris_218_ball_set():
    """Harris & Kotzalas, Rolling Bearing Analysis (5th ed.), the 218 angular contact ball bearing of
    their examples: 16 balls of 22.23 mm, α 40°. From Timken's 7218 B ratings (106.6, 93.7 kN) the
    estimate finds that set (7/8 in balls), and its ISO 281 C_r 106.55 kN, ISO 76 C₀r 93.69 kN."""
    from diffbearing.catalog.internal_geometry import ANGULAR_CONTACT, _ratings, estimate_ball_set

    found = estimate_ball_set(0.09, 0.16, 106.6e3, 93.7e3, ANGULAR_CONTACT, np.radians(40.0))
    assert (found.balls, round(found.ball_diameter * 1e3, 3)) == (16, 22.225)
    np.testing.assert_allclose(_ratings(16, 22.225e-3, 0.125, np.radians(40.0)), [106.55e3, 93.69e3], rtol=1e-3)


@pytest.mark.parametrize("suffix, degrees", [("B", 40), ("BECBP", 40), ("BE", 40), ("AC", 25), ("ACD", 25), ("A5", 25),
                                             ("A", 30), ("C", 15), ("CD", 15), ("", None), ("E", None)])
def test_the_contact_angle_of_a_suffix(suffix, degrees):
    """SKF's, FAG's, NSK's and Timken's suffixes: B 40°, AC 25°, A 30°, C 15°, NSK's A5 25°; none else."""
    from diffbearing.catalog.internal_geometry import contact_angle_of_suffix

    angle = contact_angle_of_suffix(suffix)
    assert angle == (None if degrees is None else pytest.approx(np.radians(degrees), rel=1e-15))


def test_an_angular_contact_designation_alone_runs_with_its_angle_marked(capsys, tmp_path):
    """A [bearing] table of type, designation = "7218 B" and Timken's ratings: the run converges with
    Harris's 16 × 22.225 mm balls and the suffix's 40°, each named ESTIMATED in the report and JSON;
    its free contact angle is the suffix's."""
    path = _runs_with_estimates(capsys, tmp_path, '[bearing]\ntype = "angular_contact_ball"\ndesignation = "7218 B"\n'
                                'dynamic_load_rating = "106.6 kN"\nstatic_load_rating = "93.7 kN"\n[operating]\n'
                                'inner_speed = "3000 rpm"\nforce = ["5 kN", "0 N", "8 kN"]\n[effects]\nlife = true\n',
                                BALL_SET + ("contact_angle",))
    assert "radial_clearance" not in " ".join(load_scene(str(path)).derived)
    scene = load_scene(str(path))
    assert (scene.values["bearing.balls"], scene.values["bearing.contact_angle"]) == (16, pytest.approx(np.radians(40)))


@pytest.mark.parametrize("lines, named", [
    ('type = "angular_contact_ball"\ndesignation = "7205"\n', "bearing.designation: an angular contact bearing's contact"),
    ('type = "angular_contact_ball"\ndesignation = "7205"\nradial_clearance = "20 um"\ndynamic_load_rating = "14 kN"\n'
     'static_load_rating = "8.67 kN"\n', "bearing.designation: an angular contact bearing's contact"),
])
def test_an_angular_contact_designation_without_its_angle_exits_2(capsys, tmp_path, lines, named):
    path = tmp_path / "ac.toml"
    path.write_text(f'[bearing]\n{lines}[operating]\ninner_speed = "1000 rpm"\nforce = ["1 kN", "0 N", "1 kN"]\n')
    assert_exits_2_naming(capsys, ["run", str(path)], named)


def test_an_angular_contact_designation_with_its_clearance_needs_no_suffix(tmp_path):
    """A 7205 with its radial clearance and no catalogue ratings needs no contact angle: the clearance
    sets it (no contact angle estimated)."""
    path = tmp_path / "ac.toml"
    path.write_text('[bearing]\ntype = "angular_contact_ball"\ndesignation = "7205"\nradial_clearance = "20 um"\n'
                    '[operating]\ninner_speed = "1000 rpm"\nforce = ["1 kN", "0 N", "1 kN"]\n')
    scene = load_scene(str(path))
    assert "bearing.contact_angle" not in scene.derived and scene.values["bearing.balls"] == 12


def _designated_gearbox_shaft(tmp_path, replace=True):
    """gearbox_shaft with each entry's bore and outer_diameter written as `designation = "6411"`
    (and, `replace` False, its ball set left out too: all estimated)."""
    text = open(example_scene("gearbox_shaft")).read()
    text = text.replace('bore = "55 mm"\nouter_diameter = "140 mm"\n', 'designation = "6411"\n')
    if not replace:
        for line in ('ball_diameter = "26.9875 mm"\n', 'pitch_diameter = "97.5 mm"\n', "balls = 7\n",
                     'inner_groove_radius = "13.9 mm"\n', 'outer_groove_radius = "14.17 mm"\n',
                     'radial_clearance = "0.028 mm"\n'):
            text = text.replace(line, "")
    path = tmp_path / "designated.toml"
    path.write_text(text)
    return str(path)


def test_a_shafts_entries_with_designations_equal_the_written_shaft(tmp_path):
    """The entries of gearbox_shaft written with designation = "6411" for d, D: every value the
    example writes, exact; the designation's d, D, B named `bearings[i].bore` … with GOST 8338-75's
    table; the ball set the scene writes overrides the estimate (nothing else derived)."""
    original = load_scene(example_scene("gearbox_shaft")).values["bearings"]
    scene = load_scene(_designated_gearbox_shaft(tmp_path))
    for index, (written, designated) in enumerate(zip(original, scene.values["bearings"], strict=True)):
        assert {key: value for key, value in designated.items() if key in written} == written
        assert designated["bearing.width"] == 0.033 and designated["bearing.designation"] == "6411"
        assert {key for key in scene.derived if key.startswith(f"bearings[{index}].")} == {
            f"bearings[{index}].{key}" for key in ("bore", "outer_diameter", "width")}
    assert scene.derived["bearings[1].bore"] == "designation 6411: GOST 8338-75 Table 7"


@pytest.mark.slow
def test_a_shaft_of_designations_alone_runs_with_its_estimates_marked(capsys, tmp_path):
    """gearbox_shaft's entries holding only designation = "6411" and their placement: the shaft
    converges on the estimated 7 × 25.4 mm ball sets, each value named ESTIMATED in report and JSON."""
    document = tmp_path / "out.json"
    assert cli.main(["run", _designated_gearbox_shaft(tmp_path, replace=False), "--json", str(document)]) == 0
    out = capsys.readouterr().out
    result = json.loads(document.read_text())
    for index in (0, 1):
        for key in ("balls", "ball_diameter", "pitch_diameter", "inner_groove_ratio", "outer_groove_ratio",
                    "radial_clearance"):
            assert result["derived"][f"bearings[{index}].{key}"].startswith("ESTIMATED")
            assert f"bearings[{index}].{key} = " in out
    assert "Shaft equilibrium: converged" in out


@pytest.mark.parametrize("change, named", [
    (('designation = "6411"\n', 'designation = "6499"\n'), "bearings[0]: designation: '6499' is not in the data"),
    (('type = "deep_groove_ball"\ndesignation = "6411"\n', 'type = "deep_groove_ball"\ndesignation = "7211 B"\n'),
     "bearings[0]: designation: '7211 B' is a bearing of type angular_contact_ball"),
])
def test_a_bad_designation_in_a_shaft_entry_exits_2(capsys, tmp_path, change, named):
    path = _designated_gearbox_shaft(tmp_path)
    Path(path).write_text(Path(path).read_text().replace(*change, 1))
    assert_exits_2_naming(capsys, ["run", path], named)
