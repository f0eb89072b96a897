"""Boundary dimensions by designation: a bearing's series (618, 619, 160, 60, 62, 63, 64 deep groove
ball; 222, 223, 230, 231, 232, 240, 241 spherical roller) and bore code give its bore d, outside
diameter D and width B (and the smallest chamfer r_s min where the standard gives it) from ISO 15's
dimension series, as GOST 8338-75 and GOST 24696-81 tabulate them (`boundary_dimensions.csv`: each
row with its source table and, where one agrees, a second source).

A designation is the series followed by the bore code, as the catalogues write it: 00 → 10, 01 → 12,
02 → 15, 03 → 17 mm, 04 … 96 → five times the code in mm, "/d" for d in mm (62/22, 230/500), and a
single digit below 10 mm (623 → 3 mm); a suffix that begins with a letter, after a space or not
(22220 E, 22220E, 24130 CC/W33), is kept apart and not read; one that begins with a hyphen or a
digit (6205-2RS, 6205 2RS) is refused: give the designation without it. The 7x, QJ and NU series,
tapered (ISO 355) and thrust (ISO 104) bearings are not in the data yet.
"""

import csv
import dataclasses
import fnmatch
import functools
import importlib.resources
import re

SOURCES = {
    "GOST 8338-75": "GOST 8338-75 'Rolling bearings. Radial single-row ball bearings. Basic dimensions' (ISO 15 dimension "
                    "series 18, 19, 00, 10, 02, 03, 04), Tables 1–7",
    "GOST 24696-81": "GOST 24696-81 'Rolling bearings. Radial spherical double-row roller bearings with symmetrical rollers. "
                     "Basic dimensions' (ISO 15 dimension series 30, 31, 32, 40, 41, 22, 23), Tables 1–6",
}
# the bearing type each source's series are of
SOURCE_TYPES = {"GOST 8338-75": "deep_groove_ball", "GOST 24696-81": "spherical_roller"}
# a designation: series digits, bore code (two digits, a single digit, or /d), then an optional suffix
DESIGNATION = re.compile(r"\s*(?P<digits>\d+)(?P<slash>/\d+(?:\.\d+)?)?\s*(?P<suffix>[A-Za-z].*)?\s*")


@dataclasses.dataclass(frozen=True)
class BoundaryDimensions:
    """A bearing's boundary dimensions [m] with where they come from."""

    designation: str  # as the catalogue writes it, suffix dropped
    series: str
    bore: float
    outside_diameter: float
    width: float
    chamfer: float | None  # r_s min [m], None where the standard's table gives none
    source: str  # the standard and its table
    bearing_type: str  # the scene type whose series it is
    suffix: str = ""


@functools.cache
def _table() -> dict[tuple[str, str], dict]:
    text = importlib.resources.files("diffbearing.catalog").joinpath("boundary_dimensions.csv").read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return {(row["series"], row["bore_code"]): row for row in rows}


def series() -> tuple[str, ...]:
    """The series the data holds, longest first (a designation's prefix is matched against them)."""
    return tuple(sorted({key[0] for key in _table()}, key=lambda name: (-len(name), name)))


def split_designation(designation: str) -> tuple[str, str, str]:
    """(series, bore code, suffix) of a designation; ValueError naming `bearing.designation`."""
    match = DESIGNATION.fullmatch(str(designation))
    if match is None:
        raise ValueError(f"bearing.designation: {designation!r} is not a designation (series and bore code, e.g. "
                         "6205, 22220 E, 62/22)")
    digits, slash, suffix = match.group("digits"), match.group("slash"), (match.group("suffix") or "").strip()
    for name in series():
        if not digits.startswith(name):
            continue
        code = slash if slash and digits == name else digits[len(name):]
        if code and (name, code) in _table():
            return name, code, suffix
    known = ", ".join(sorted(series(), key=lambda name: (len(name), name)))
    raise ValueError(f"bearing.designation: {designation!r} is not in the data (series {known}: ISO 15 as GOST 8338-75 "
                     "and GOST 24696-81 tabulate them; give bore, outer_diameter and width instead)")


def boundary_dimensions(designation: str) -> BoundaryDimensions:
    """The boundary dimensions of `designation` (module docstring); ValueError naming
    `bearing.designation` where the data has no such bearing."""
    name, code, suffix = split_designation(designation)
    row = _table()[(name, code)]
    chamfer = float(row["r_smin_mm"]) / 1e3 if row["r_smin_mm"] else None
    source = f"{row['source']} {row['table']}" + (f"; checked: {row['checked']}" if row["checked"] else "")
    return BoundaryDimensions(name + code, name, float(row["d_mm"]) / 1e3, float(row["D_mm"]) / 1e3,
                              float(row["B_mm"]) / 1e3, chamfer, source, SOURCE_TYPES[row["source"]], suffix)


def designations(pattern: str = "*") -> list[BoundaryDimensions]:
    """Every bearing of the data whose designation matches the shell `pattern` (fnmatch: 62*, 222??)."""
    found = [boundary_dimensions(name + code) for name, code in _table()]
    return [entry for entry in found if fnmatch.fnmatchcase(entry.designation, pattern)]
