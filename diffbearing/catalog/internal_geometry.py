"""Estimated internal geometry of a single-row deep groove or angular contact ball bearing from its
boundary dimensions d, D — the type's typical proportions — or, given the catalogue's C_r and C₀r, the
ball set whose ISO 281 and ISO 76 ratings reproduce them. Every value here is an estimate; the scene
layer marks it so (`Scene.derived`) and any value the scene gives overrides it.

* Pitch diameter d_m = (d + D)/2.
* Ball diameter: the inch size (k/64 in, ISO 3290's grades are made in these) nearest the type's
  share of the section D − d (`BallSetProportions.ball_share`): 0.3 for deep groove ball bearings —
  7.938 mm (5/16 in) for a 6205, 6.747 mm (17/64 in) for a 6203, 11.906 mm for a 6208, their balls;
  25.4 mm for a 6411, whose are 26.988 mm (the 64 series' share is nearer 0.32) — and 0.315 for
  angular contact ball bearings (the median of the sets that reproduce Timken's ratings of its 47
  72 B and 73 B bearings, tests/test_designations.py).
* Ball count: deep groove, the most a Conrad assembly (the inner ring pushed aside, the balls in
  through the gap) admits over a filling arc of `FILLING_ANGLE` = 3.4 rad (195°):
  Z = ⌊φ / (2 asin(D_w/d_m)) + 1⌋ — 9, 8, 9, 7 for the 6205, 6203, 6208, 6411, their counts; angular
  contact (a one-sided outer shoulder: the balls go in whole, the cage sets the pitch),
  Z = ⌊`CAGE_FILL` π / asin(D_w/d_m)⌋, 0.88 of the balls that would touch around the pitch circle.
* From C_r and C₀r: of the inch sizes within 0.2–0.45 (D − d) and the counts the type admits (Conrad
  filling; for angular contact up to the balls touching), the pair minimising (ln C_r/C)² +
  (ln C₀r/C₀)² + 0.2 (ln D_w/(share (D − d)))² (the last term chooses the typical size among pairs
  that fit alike, e.g. against a manufacturer's ratings above ISO 281's).
* Contact angle of an angular contact ball bearing from its designation's suffix (`CONTACT_ANGLES`:
  B 40°, AC 25°, A 30°, C 15°, NSK's A5 25°), the free contact angle of the model (its clearance
  follows from it).
* Groove ratios f_i = 0.52, f_o = 0.53 (`GROOVE_RATIOS`), the usual conformities.
* Deep groove radial clearance: the middle of ISO 5753-1's normal group CN for the bore
  (`NORMAL_CLEARANCE`, d up to 100 mm, as two manufacturers' tables print it); none beyond.
"""

import dataclasses
from collections.abc import Callable

import numpy as np

from ..params import check_range
from ..ratings import life, static_safety

INCH = 25.4e-3
INCH_BALLS = np.arange(1, 129) * INCH / 64  # 1/64 in … 2 in in 1/64 in steps [m]
FILLING_ANGLE = 3.4  # rad: the arc a Conrad assembly fills
CAGE_FILL = 0.88  # of the balls that would touch: an angular contact bearing's typical count
GROOVE_RATIOS = (0.52, 0.53)  # f_i, f_o
PRIOR_WEIGHT = 0.2  # of (ln D_w/(share (D − d)))² in the fit to the ratings
CANDIDATE_BLOCK = 1024  # the fit's candidate sets are rated in blocks of this many
# an angular contact ball bearing's free contact angle [deg] by the suffix its designation begins with
# (SKF's, FAG's, NSK's and Timken's designation systems), the longest matching first
CONTACT_ANGLES = {"A5": 25.0, "AC": 25.0, "A": 30.0, "B": 40.0, "C": 15.0}
# ISO 5753-1 group N (CN) radial internal clearance of deep groove ball bearings: bore over [mm] →
# (smallest, largest) [µm], each row to the next row's bore (shjfbearing.com and ktaiballbearing.com
# print the same table)
NORMAL_CLEARANCE = ((2.5, 2, 13), (10, 3, 18), (18, 5, 20), (24, 5, 20), (30, 6, 20), (40, 6, 23), (50, 8, 28),
                    (65, 10, 30), (80, 12, 36))
CLEARANCE_LIMIT = 100e-3  # m: the largest bore of NORMAL_CLEARANCE's last row


@dataclasses.dataclass(frozen=True)
class BallSet:
    """An estimated ball set (SI) and how it was found."""

    balls: int
    ball_diameter: float
    pitch_diameter: float
    inner_groove_ratio: float
    outer_groove_ratio: float
    how: str


def conrad_ball_count(ball_diameter, pitch_diameter) -> int:
    """The most balls a Conrad assembly admits: ⌊φ / (2 asin(D_w/d_m)) + 1⌋, φ = `FILLING_ANGLE`."""
    return int(np.floor(FILLING_ANGLE / (2.0 * np.arcsin(ball_diameter / pitch_diameter)) + 1.0))


def touching_ball_count(ball_diameter, pitch_diameter) -> int:
    """The most balls of diameter D_w on a pitch circle d_m, touching: ⌊π / asin(D_w/d_m)⌋."""
    return int(np.floor(np.pi / np.arcsin(ball_diameter / pitch_diameter)))


def caged_ball_count(ball_diameter, pitch_diameter) -> int:
    """An angular contact bearing's typical count: ⌊`CAGE_FILL` π / asin(D_w/d_m)⌋."""
    return int(np.floor(CAGE_FILL * np.pi / np.arcsin(ball_diameter / pitch_diameter)))


@dataclasses.dataclass(frozen=True)
class BallSetProportions:
    """A ball bearing type's typical ball set: D_w ≈ `ball_share` (D − d), `typical_count(D_w, d_m)`
    balls, at most `most_balls(D_w, d_m)` (what its assembly admits)."""

    ball_share: float
    typical_count: Callable[[float, float], int]
    most_balls: Callable[[float, float], int]
    how: str


DEEP_GROOVE = BallSetProportions(0.3, conrad_ball_count, conrad_ball_count,
                                 "typical proportions: D_w ≈ 0.3 (D − d), Conrad filling")
ANGULAR_CONTACT = BallSetProportions(0.315, caged_ball_count, touching_ball_count,
                                     "typical proportions: D_w ≈ 0.315 (D − d), 0.88 of the balls that would touch")


def normal_clearance(bore) -> float | None:
    """The middle of ISO 5753-1's CN range [m] for the bore [m] (d ≤ 100 mm), else None."""
    if not 2.5e-3 < bore <= CLEARANCE_LIMIT:
        return None
    row = [entry for entry in NORMAL_CLEARANCE if bore * 1e3 > entry[0]][-1]
    return 0.5 * (row[1] + row[2]) * 1e-6


def contact_angle_of_suffix(suffix: str) -> float | None:
    """The free contact angle [rad] an angular contact designation's suffix names (`CONTACT_ANGLES`),
    None for a suffix that names none."""
    for letters in sorted(CONTACT_ANGLES, key=len, reverse=True):
        if suffix.upper().startswith(letters):
            return float(np.radians(CONTACT_ANGLES[letters]))
    return None


def _ratings(balls, ball_diameter, pitch_diameter, contact_angle):
    """ISO 281 C_r and ISO 76 C₀r [N] of a single-row ball set (floats, or arrays of candidate sets)."""
    dynamic = np.asarray(life.ball_dynamic_load_rating(balls, ball_diameter, pitch_diameter, contact_angle))
    static = np.asarray(static_safety.ball_static_load_rating(balls, ball_diameter, pitch_diameter, contact_angle))
    return (float(dynamic), float(static)) if dynamic.ndim == 0 else (dynamic, static)


def estimate_ball_set(bore, outside_diameter, dynamic_load_rating=None, static_load_rating=None,
                      proportions=DEEP_GROOVE, contact_angle=0.0) -> BallSet:
    """The estimated ball set of a ball bearing of bore d and outside diameter D [m] with the type's
    `proportions` (module docstring); with both catalogue ratings C_r, C₀r [N] the set whose ratings
    at the free contact angle `contact_angle` [rad] reproduce them (ValueError naming a rating that
    is not positive)."""
    for key, rating in (("bearing.dynamic_load_rating", dynamic_load_rating), ("bearing.static_load_rating",
                                                                                static_load_rating)):
        check_range(key, rating, low=0.0, unit=" N", why="a catalogue's load rating")
    pitch = 0.5 * (bore + outside_diameter)
    section = outside_diameter - bore
    typical = proportions.ball_share * section
    if dynamic_load_rating is None or static_load_rating is None:
        ball = float(INCH_BALLS[np.argmin(np.abs(INCH_BALLS - typical))])
        return BallSet(proportions.typical_count(ball, pitch), ball, pitch, *GROOVE_RATIOS, proportions.how)
    # every candidate (D_w, Z) at once: one evaluation of each rating over the arrays
    candidates = [(ball, balls) for ball in INCH_BALLS[(INCH_BALLS >= 0.2 * section) & (INCH_BALLS <= 0.45 * section)]
                  for balls in range(5, proportions.most_balls(ball, pitch) + 1)]
    diameters, counts = (np.array(column, float) for column in zip(*candidates))
    # padded to a multiple of `CANDIDATE_BLOCK`, so that the ratings' array programs keep a few shapes
    padded = -len(counts) % CANDIDATE_BLOCK
    dynamic, static = (np.asarray(rating)[:len(counts)] for rating in _ratings(
        np.pad(counts, (0, padded), constant_values=5.0), np.pad(diameters, (0, padded), constant_values=typical),
        pitch, contact_angle))
    misfit = (np.log(dynamic_load_rating / dynamic) ** 2 + np.log(static_load_rating / static) ** 2
              + PRIOR_WEIGHT * np.log(diameters / typical) ** 2)
    best = int(np.argmin(misfit))  # the first of equal misfits, as the loop over sizes, then counts, found it
    balls, ball, dynamic, static = int(counts[best]), float(diameters[best]), float(dynamic[best]), float(static[best])
    return BallSet(balls, ball, pitch, *GROOVE_RATIOS,
                   f"from the catalogue's C_r, C₀r (ISO 281, ISO 76 give {dynamic / 1e3:.3g}, {static / 1e3:.3g} kN)")


# a scene's [bearing] keys of the ball set, with the keys that stand in for each (a groove radius for
# its ratio): a key is estimated only where the scene gives none of them
BALL_SET_KEYS = {"balls": (), "ball_diameter": (), "pitch_diameter": (), "inner_groove_ratio": ("inner_groove_radius",),
                 "outer_groove_ratio": ("outer_groove_radius",)}
# the keys that set a ball bearing's free contact angle, either standing in for the other
ANGLE_KEYS = ("contact_angle", "radial_clearance")


def _ball_set_values(given, estimate: BallSet) -> dict[str, tuple[float, str]]:
    """{key: (value, how)} of the ball-set keys not among the scene's `given` keys."""
    how = {"pitch_diameter": "(d + D)/2", "inner_groove_ratio": "the usual conformity",
           "outer_groove_ratio": "the usual conformity"}
    return {key: (getattr(estimate, key), how.get(key, estimate.how)) for key, instead in BALL_SET_KEYS.items()
            if key not in given and not any(other in given for other in instead)}


def deep_groove_estimates(scene_value, given, suffix) -> dict[str, tuple[float, str]]:
    """{[bearing] key: (estimated SI value, how it was found)} of a deep groove ball bearing's
    ball-set keys and clearance not among the scene's `given` keys; `scene_value(key, kind)` is a
    [bearing] key's SI value or None; from the catalogue ratings C_r, C₀r where the scene gives both."""
    bore = scene_value("bore", "length")
    estimate = estimate_ball_set(bore, scene_value("outer_diameter", "length"),
                                 scene_value("dynamic_load_rating", "force"), scene_value("static_load_rating", "force"))
    values = _ball_set_values(given, estimate)
    if not any(key in given for key in ANGLE_KEYS):
        clearance = normal_clearance(bore)
        if clearance is None:
            raise ValueError(f"bearing.radial_clearance: needed (ISO 5753-1's normal clearance is tabulated here up to "
                             f"d = {CLEARANCE_LIMIT * 1e3:g} mm only)")
        values["radial_clearance"] = (clearance, "the middle of ISO 5753-1's normal group CN for the bore")
    return values


def angular_contact_estimates(scene_value, given, suffix) -> dict[str, tuple[float, str]]:
    """As `deep_groove_estimates`, for an angular contact ball bearing: its ball set, and its free
    contact angle from the designation's suffix (`CONTACT_ANGLES`) where the scene gives neither
    contact angle nor clearance; ValueError naming `bearing.designation` where the angle is needed
    (for the values or for the fit to the ratings) and neither suffix nor scene gives it."""
    ratings = scene_value("dynamic_load_rating", "force"), scene_value("static_load_rating", "force")
    angle = scene_value("contact_angle", "angle")
    if angle is None:
        angle = contact_angle_of_suffix(suffix)
    needed = not any(key in given for key in ANGLE_KEYS) or None not in ratings
    if angle is None and needed:
        letters = ", ".join(f"{name} {value:g}°" for name, value in CONTACT_ANGLES.items())
        raise ValueError(f"bearing.designation: an angular contact bearing's contact angle is needed: write its suffix "
                         f"({letters}; e.g. 7205 B) or give bearing.contact_angle")
    estimate = estimate_ball_set(scene_value("bore", "length"), scene_value("outer_diameter", "length"), *ratings,
                                 proportions=ANGULAR_CONTACT, contact_angle=angle if angle is not None else 0.0)
    values = _ball_set_values(given, estimate)
    if not any(key in given for key in ANGLE_KEYS):
        values["contact_angle"] = (angle, f"the designation's suffix {suffix!r}")
    return values


# bearing type → its [bearing] keys estimated from the boundary dimensions ((the scene's SI value of a
# [bearing] key, its given keys, the designation's suffix) → {key: (value, how)}); a type without one
# takes only d, D, B from its designation
GEOMETRY_ESTIMATES = {"deep_groove_ball": deep_groove_estimates, "angular_contact_ball": angular_contact_estimates}
