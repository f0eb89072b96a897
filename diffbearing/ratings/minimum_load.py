"""Minimum load of a rolling bearing in operation: below it the rolling elements may skid.

The manufacturers' rule of thumb (SKF, *Rolling bearings* 2018, "Requisite minimum load"; Schaeffler
HR 1 requires P/C_r ≥ 0.01 for ball bearings with cage alike): an equivalent dynamic load of at
least 0.01 C_r on ball bearings and 0.02 C_r on roller bearings.
"""

BALL_MINIMUM_LOAD_RATIO = 0.01
ROLLER_MINIMUM_LOAD_RATIO = 0.02


def minimum_load(dynamic_load_rating, rolling_element: str):
    """Requisite minimum equivalent load [N] from the basic dynamic load rating C_r [N];
    `rolling_element` is "ball" or "roller"."""
    ratios = {"ball": BALL_MINIMUM_LOAD_RATIO, "roller": ROLLER_MINIMUM_LOAD_RATIO}
    if rolling_element not in ratios:
        raise ValueError(f"rolling_element must be one of {tuple(ratios)}, got {rolling_element!r}")
    return ratios[rolling_element] * dynamic_load_rating
