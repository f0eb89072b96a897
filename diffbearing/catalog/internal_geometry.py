"""Estimated internal geometry of a single-row deep groove ball bearing from its boundary
dimensions d, D — the typical proportions — or, given the catalogue's C_r and C₀r, the ball set whose
ISO 281 and ISO 76 ratings reproduce them. Every value here is an estimate; the scene layer marks it
so (`Scene.derived`) and any value the scene gives overrides it.

* Pitch diameter d_m = (d + D)/2.
* Ball diameter: the inch size (k/64 in, ISO 3290's grades are made in these) nearest
  `BALL_SHARE` (D − d) = 0.3 (D − d): 7.938 mm (5/16 in) for a 6205, 6.747 mm (17/64 in) for a 6203,
  11.906 mm for a 6208 — their balls; 25.4 mm for a 6411, whose are 26.988 mm (the 64 series' share is
  nearer 0.32).
* Ball count: the most a Conrad assembly (the inner ring pushed aside, the balls in through the gap)
  admits over a filling arc of `FILLING_ANGLE` = 3.4 rad (195°): Z = ⌊φ / (2 asin(D_w/d_m)) + 1⌋ —
  9, 8, 9, 7 for the 6205, 6203, 6208, 6411, their counts.
* From C_r and C₀r: of the inch sizes within 0.2–0.45 (D − d) and the counts a Conrad assembly admits,
  the pair minimising (ln C_r/C)² + (ln C₀r/C₀)² + 0.2 (ln D_w/0.3(D − d))² (the last term chooses the
  typical size among pairs that fit alike, e.g. against a manufacturer's ratings above ISO 281's).
* Groove ratios f_i = 0.52, f_o = 0.53 (`GROOVE_RATIOS`), the usual deep groove conformities.
* Radial clearance: the middle of ISO 5753-1's normal group CN for the bore (`NORMAL_CLEARANCE`, d up
  to 100 mm, as two manufacturers' tables print it); none beyond.
"""

import dataclasses

import numpy as np

from ..params import check_range
from ..ratings import life, static_safety

INCH = 25.4e-3
INCH_BALLS = np.arange(1, 129) * INCH / 64  # 1/64 in … 2 in in 1/64 in steps [m]
BALL_SHARE = 0.3  # D_w / (D − d)
FILLING_ANGLE = 3.4  # rad: the arc a Conrad assembly fills
GROOVE_RATIOS = (0.52, 0.53)  # f_i, f_o
PRIOR_WEIGHT = 0.2  # of (ln D_w/(0.3 (D − d)))² in the fit to the ratings
# ISO 5753-1 group N (CN) radial internal clearance of deep groove ball bearings: bore over [mm] →
# (smallest, largest) [µm], each row to the next row's bore (shjfbearing.com and ktaiballbearing.com
# print the same table)
NORMAL_CLEARANCE = ((2.5, 2, 13), (10, 3, 18), (18, 5, 20), (24, 5, 20), (30, 6, 20), (40, 6, 23), (50, 8, 28),
                    (65, 10, 30), (80, 12, 36))
CLEARANCE_LIMIT = 100e-3  # m: the largest bore of NORMAL_CLEARANCE's last row


@dataclasses.dataclass(frozen=True)
class BallSet:
    """An estimated deep groove ball set (SI) and how each value was found."""

    balls: int
    ball_diameter: float
    pitch_diameter: float
    inner_groove_ratio: float
    outer_groove_ratio: float
    radial_clearance: float | None
    how: str


def conrad_ball_count(ball_diameter, pitch_diameter) -> int:
    """The most balls a Conrad assembly admits: ⌊φ / (2 asin(D_w/d_m)) + 1⌋, φ = `FILLING_ANGLE`."""
    return int(np.floor(FILLING_ANGLE / (2.0 * np.arcsin(ball_diameter / pitch_diameter)) + 1.0))


def normal_clearance(bore) -> float | None:
    """The middle of ISO 5753-1's CN range [m] for the bore [m] (d ≤ 100 mm), else None."""
    if not 2.5e-3 < bore <= CLEARANCE_LIMIT:
        return None
    row = [entry for entry in NORMAL_CLEARANCE if bore * 1e3 > entry[0]][-1]
    return 0.5 * (row[1] + row[2]) * 1e-6


def _ratings(balls, ball_diameter, pitch_diameter):
    """ISO 281 C_r and ISO 76 C₀r [N] of a deep groove ball set (α = 0)."""
    return (float(life.ball_dynamic_load_rating(balls, ball_diameter, pitch_diameter, 0.0)),
            float(static_safety.ball_static_load_rating(balls, ball_diameter, pitch_diameter, 0.0)))


def estimate_ball_set(bore, outside_diameter, dynamic_load_rating=None, static_load_rating=None) -> BallSet:
    """The estimated ball set of a deep groove ball bearing of bore d and outside diameter D [m]
    (module docstring); with both catalogue ratings C_r, C₀r [N] the set that reproduces them
    (ValueError naming a rating that is not positive)."""
    for key, rating in (("bearing.dynamic_load_rating", dynamic_load_rating), ("bearing.static_load_rating",
                                                                                static_load_rating)):
        check_range(key, rating, low=0.0, unit=" N", why="a catalogue's load rating")
    pitch = 0.5 * (bore + outside_diameter)
    section = outside_diameter - bore
    typical = BALL_SHARE * section
    clearance = normal_clearance(bore)
    if dynamic_load_rating is None or static_load_rating is None:
        ball = float(INCH_BALLS[np.argmin(np.abs(INCH_BALLS - typical))])
        return BallSet(conrad_ball_count(ball, pitch), ball, pitch, *GROOVE_RATIOS, clearance,
                       "typical proportions: D_w ≈ 0.3 (D − d), Conrad filling")
    best = None
    for ball in INCH_BALLS[(INCH_BALLS >= 0.2 * section) & (INCH_BALLS <= 0.45 * section)]:
        for balls in range(5, conrad_ball_count(ball, pitch) + 1):
            dynamic, static = _ratings(balls, ball, pitch)
            misfit = (np.log(dynamic_load_rating / dynamic) ** 2 + np.log(static_load_rating / static) ** 2
                      + PRIOR_WEIGHT * np.log(ball / typical) ** 2)
            if best is None or misfit < best[0]:
                best = (misfit, balls, float(ball), dynamic, static)
    _, balls, ball, dynamic, static = best
    return BallSet(balls, ball, pitch, *GROOVE_RATIOS, clearance,
                   f"from the catalogue's C_r, C₀r (ISO 281, ISO 76 give {dynamic / 1e3:.3g}, {static / 1e3:.3g} kN)")


# a scene's [bearing] keys of the ball set, with the keys that stand in for each (a groove radius for
# its ratio, a contact angle for the clearance): a key is estimated only where the scene gives none of them
BALL_SET_KEYS = {"balls": (), "ball_diameter": (), "pitch_diameter": (), "inner_groove_ratio": ("inner_groove_radius",),
                 "outer_groove_ratio": ("outer_groove_radius",), "radial_clearance": ("contact_angle",)}


def ball_set_estimates(given, bore, outside_diameter, dynamic_load_rating=None,
                       static_load_rating=None) -> dict[str, tuple[float, str]]:
    """{[bearing] key: (estimated SI value, how it was found)} of the ball-set keys not among the
    scene's `given` [bearing] keys, from its catalogue ratings C_r, C₀r [N] where it gives both."""
    estimate = estimate_ball_set(bore, outside_diameter, dynamic_load_rating, static_load_rating)
    how = {"balls": estimate.how, "ball_diameter": estimate.how, "pitch_diameter": "(d + D)/2",
           "inner_groove_ratio": "the usual deep groove conformity", "outer_groove_ratio": "the usual deep groove conformity",
           "radial_clearance": "the middle of ISO 5753-1's normal group CN for the bore"}
    values = {}
    for key, instead in BALL_SET_KEYS.items():
        if key in given or any(other in given for other in instead):
            continue
        value = getattr(estimate, key)
        if value is None:
            raise ValueError(f"bearing.{key}: needed (ISO 5753-1's normal clearance is tabulated here up to d = "
                             f"{CLEARANCE_LIMIT * 1e3:g} mm only)")
        values[key] = (value, how[key])
    return values


# bearing type → its [bearing] keys estimated from the boundary dimensions ((the scene's [bearing] keys,
# d, D, C_r, C₀r) → {key: (value, how)}); a type without one takes only d, D, B from its designation
GEOMETRY_ESTIMATES = {"deep_groove_ball": ball_set_estimates}
