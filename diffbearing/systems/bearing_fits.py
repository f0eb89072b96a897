"""Interferences of bearing seats from ISO 286 tolerance classes and the bearing's ISO 492 Normal
tolerances (docs/theory.md §Operating clearance).

Seats from 10 to 500 mm (ISO 286-1:2010, nominal size ranges "over a, up to and including b"):
shafts g, h, j, js, k, m, n, p and housings G, H, J, JS, K, M, N, P in grades 5, 6 and 7 (housings 6
and 7). The standard tolerance grades IT5–IT7 and the shafts' fundamental deviations are ISO 286-1's
tabulated values (Tables 1 and 2; ISO 286-2 lists the same classes); a hole's deviation follows
from the shaft's of the same letter by ISO 286-1's rules: G: EI = −es(g); H: EI = 0; JS: ±IT/2;
K, M, N, P (grades ≤ 7): ES = −ei(k, m, n, p) + Δ, Δ = IT_n − IT_(n−1). The ring's own tolerances
are the mean-diameter deviations of ISO 492:2014 Normal class: the bore 0 / −t_d, the outside
0 / −t_D. The j and J classes, which follow no rule, are ISO 286-2's tabulated deviations (as the
NSK, NTN and Koyo catalogues print them).

Diametral interference (shaft minus bore, ring outside minus housing bore; negative: a loose
fit) at the extreme sizes, `"max"` and `"min"`, or `"probable"`: both parts at the middle of
their tolerance, the mean of the extremes (the middle of the ranges the catalogues print as
"probable interference").
"""

import bisect

SIZE_LIMITS = (10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500)  # mm: ranges (10, 18], (18, 30], …
STANDARD_TOLERANCES = {  # µm, ISO 286-1 Table 1
    5: (8, 9, 11, 13, 15, 18, 20, 23, 25, 27),
    6: (11, 13, 16, 19, 22, 25, 29, 32, 36, 40),
    7: (18, 21, 25, 30, 35, 40, 46, 52, 57, 63),
}
SHAFT_DEVIATIONS = {  # µm, ISO 286-1 Table 2: es for g and h (upper), ei for k, m, n, p (lower)
    "g": (-6, -7, -9, -10, -12, -14, -15, -17, -18, -20),
    "h": (0,) * 10,
    "k": (1, 2, 2, 2, 3, 3, 4, 4, 4, 5),  # grades 4 to 7
    "m": (7, 8, 9, 11, 13, 15, 17, 20, 21, 23),
    "n": (12, 15, 17, 20, 23, 27, 31, 34, 37, 40),
    "p": (18, 22, 26, 32, 37, 43, 50, 56, 62, 68),
}
# µm, ISO 286-2: lower deviations ei of j5 and j6 (the same), of j7; upper deviations ES of J6, J7
J_SHAFT_LOWER = {5: (-3, -4, -5, -7, -9, -11, -13, -16, -18, -20), 6: (-3, -4, -5, -7, -9, -11, -13, -16, -18, -20),
                 7: (-6, -8, -10, -12, -15, -18, -21, -26, -28, -32)}
J_HOUSING_UPPER = {6: (6, 8, 10, 13, 16, 18, 22, 25, 29, 33), 7: (10, 12, 14, 18, 22, 26, 30, 36, 39, 43)}
SHAFT_GRADES, HOUSING_GRADES = (5, 6, 7), (6, 7)
# ISO 492:2014, Normal tolerance class, lower deviations [µm] of the mean bore diameter (ranges of d
# as SIZE_LIMITS) and of the mean outside diameter (ranges of D: BORE… below)
BORE_DEVIATIONS = (-8, -10, -12, -15, -20, -25, -30, -35, -40, -45)
OUTSIDE_LIMITS = (6, 18, 30, 50, 80, 120, 150, 180, 250, 315, 400, 500, 630)
OUTSIDE_DEVIATIONS = (-8, -9, -11, -13, -15, -18, -25, -30, -35, -40, -45, -50)
FIT_VALUES = ("probable", "max", "min")


def _range(diameter_mm: float, limits, name: str) -> int:
    """Index of the size range "over limits[i], up to and including limits[i + 1]"."""
    if not limits[0] < diameter_mm <= limits[-1]:
        raise ValueError(f"{name}: ISO 286 classes are tabulated here for {limits[0]} to {limits[-1]} mm, got "
                         f"{diameter_mm:g} mm")
    return bisect.bisect_left(limits, diameter_mm) - 1


def _class(tolerance: str, grades, letters, name: str) -> tuple[str, int]:
    letter, grade = tolerance.rstrip("0123456789"), tolerance[len(tolerance.rstrip("0123456789")):]
    if letter not in letters or not grade or int(grade) not in grades:
        raise ValueError(f"{name}: one of {', '.join(l + str(g) for l in letters for g in grades)}, got {tolerance!r}")
    return letter, int(grade)


def shaft_deviations(tolerance: str, diameter) -> tuple[float, float]:
    """(ei, es) [m] of a shaft class ("k5", "m6", …) at the nominal diameter [m]."""
    letter, grade = _class(tolerance, SHAFT_GRADES, ("g", "h", "j", "js", "k", "m", "n", "p"), "mounting.shaft_tolerance")
    index = _range(float(diameter) * 1e3, SIZE_LIMITS, "mounting.shaft_tolerance")
    width = STANDARD_TOLERANCES[grade][index]
    if letter == "js":
        lower = -width / 2
    elif letter == "j":
        lower = J_SHAFT_LOWER[grade][index]
    elif letter in ("g", "h"):
        lower = SHAFT_DEVIATIONS[letter][index] - width
    else:
        lower = SHAFT_DEVIATIONS[letter][index]
    return lower * 1e-6, (lower + width) * 1e-6


def housing_deviations(tolerance: str, diameter) -> tuple[float, float]:
    """(EI, ES) [m] of a housing (hole) class ("H7", "M6", …) at the nominal diameter [m]."""
    letter, grade = _class(tolerance, HOUSING_GRADES, ("G", "H", "J", "JS", "K", "M", "N", "P"),
                           "mounting.housing_tolerance")
    index = _range(float(diameter) * 1e3, SIZE_LIMITS, "mounting.housing_tolerance")
    width = STANDARD_TOLERANCES[grade][index]
    if letter == "JS":
        lower = -width / 2
    elif letter == "J":
        lower = J_HOUSING_UPPER[grade][index] - width
    elif letter in ("G", "H"):
        lower = -SHAFT_DEVIATIONS[letter.lower()][index]
    else:  # ES = −ei + Δ, Δ = IT_n − IT_(n−1)
        step = width - STANDARD_TOLERANCES[grade - 1][index]
        lower = -SHAFT_DEVIATIONS[letter.lower()][index] + step - width
    return lower * 1e-6, (lower + width) * 1e-6


def _value(smallest, largest, fit_value: str):
    if fit_value not in FIT_VALUES:
        raise ValueError(f"mounting.fit_value: one of {FIT_VALUES}, got {fit_value!r}")
    return {"max": largest, "min": smallest, "probable": 0.5 * (smallest + largest)}[fit_value]


def shaft_interference(tolerance: str, bore, fit_value: str = "probable") -> float:
    """Diametral interference [m] of the inner ring (bore [m], ISO 492 Normal) on a shaft of class `tolerance`."""
    lower, upper = shaft_deviations(tolerance, bore)
    ring = BORE_DEVIATIONS[_range(float(bore) * 1e3, SIZE_LIMITS, "bearing.bore")] * 1e-6
    return _value(lower, upper - ring, fit_value)


def housing_interference(tolerance: str, outside, fit_value: str = "probable") -> float:
    """Diametral interference [m] of the outer ring (outside diameter [m], ISO 492 Normal) in a
    housing of class `tolerance`."""
    lower, upper = housing_deviations(tolerance, outside)
    ring = OUTSIDE_DEVIATIONS[_range(float(outside) * 1e3, OUTSIDE_LIMITS, "bearing.outer_diameter")] * 1e-6
    return _value(ring - upper, -lower, fit_value)
