"""Boundary dimensions by designation: a bearing's series and bore code give its bore d, outside
diameter D and width B (a thrust bearing's height H, a tapered bearing's inner ring width, with its
total width T and outer ring width C; and the smallest chamfer r_s min where the source gives it)
(`boundary_dimensions.csv`: each row with its source table and, where one agrees, a second source).
Read from ISO 15's and ISO 104's dimension series as these GOST standards tabulate them: GOST 8338-75
deep groove ball 618, 619, 160, 60, 62, 63, 64; GOST 24696-81 spherical roller 222, 223, 230, 231,
232, 240, 241; GOST 8328-75 cylindrical roller NU22, NU23 (its NU 2220 width is illegible in the copy
read, and left out); GOST 4252-75 double-row angular contact ball 32, 33; GOST 4657-82 needle roller
NA49; GOST 23526-79 cylindrical roller thrust 811, 812. Where no copy of the standard was found
(ISO 355 / GOST 27365 for tapered, ISO 104 / GOST 7872 for thrust ball bearings), from manufacturers'
catalogues, each row against a second where it has the bearing: tapered 302, 303, 313, 320, 322, 323
(Timken's, with the ISO 355 dimension series it prints; URB's, SKF's) and thrust ball 513, 514 (URB's,
SKF's).

Series of other bearing types in a tabulated dimension series take its d, D, B, as ISO 15 and ISO 104
define them by dimension series alone (`SAME_DIMENSION_SERIES`): angular contact 70, 72, 73;
self-aligning 12, 13, 22, 23; four-point QJ2, QJ3; spherical roller 213; cylindrical roller NU, N, NJ,
NUP 2, 3, 4, 10 and N, NJ, NUP 22, 23; thrust ball 511, 512.

A designation is the series followed by the bore code, as the catalogues write it: 00 → 10, 01 → 12,
02 → 15, 03 → 17 mm, 04 … 96 → five times the code in mm, "/d" for d in mm (62/22, 230/500), and a
single digit below 10 mm (623 → 3 mm); a suffix that begins with a letter, after a space or not
(22220 E, 22220E, 24130 CC/W33, 32010 X), is kept apart (an angular contact bearing's names its
contact angle, `internal_geometry.CONTACT_ANGLES`); one that begins with a hyphen or a digit
(6205-2RS, 6205 2RS) is refused: give the designation without it.
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
    "GOST 8328-75": "GOST 8328-75 'Rolling bearings. Radial roller bearings with short cylindrical rollers. Types and basic "
                    "dimensions' (ISO 15 dimension series 22, 23: Tables 4, 6)",
    "GOST 4252-75": "GOST 4252-75 'Rolling bearings. Radial-thrust double-row ball bearings. Basic dimensions' (ISO 15 "
                    "dimension series 32, 33), Tables 1, 2; the smallest chamfers from its Amendment No. 2",
    "GOST 4657-82": "GOST 4657-82 'Rolling bearings. Needle roller bearings with machined rings. Basic dimensions' (ISO 15 "
                    "dimension series 49), Table 2",
    "GOST 23526-79": "GOST 23526-79 'Rolling bearings. Single thrust cylindrical roller bearings. Basic dimensions' (ISO 104 "
                     "dimension series 11, 12), Tables 1, 2 (B: the height H); the smallest chamfers from its Amendment No. 1",
    # no copy of ISO 355 (GOST 27365) nor of ISO 104 (GOST 7872) for thrust ball bearings was found: manufacturers'
    # catalogues, each row against a second where it has the bearing
    "Timken Metric Tapered Roller Bearings": "Timken 'Metric Tapered Roller Bearings' catalogue, the ISO 302 … 323 series "
                                             "with the ISO 355 dimension series it prints",
    "URB General Catalogue v.14_2017": "URB Group 'Rolling Bearings General Catalogue' v.14_2017 (tapered roller and "
                                       "thrust ball bearings)",
    "SKF General Catalogue 6000": "SKF General Catalogue 6000 (Russian edition; tapered roller and thrust ball bearings)",
}
# ISO 15 (ISO 104 for thrust bearings) gives boundary dimensions by dimension series, whatever the
# bearing inside: series of other types in the dimension series of a tabulated one take its d, D, B.
# series → (the tabulated series of the same dimension series, the standard and that dimension series,
# the scene's bearing type)
SAME_DIMENSION_SERIES = {
    "70": ("60", "ISO 15 10", "angular_contact_ball"), "72": ("62", "ISO 15 02", "angular_contact_ball"),
    "73": ("63", "ISO 15 03", "angular_contact_ball"),
    "12": ("62", "ISO 15 02", "self_aligning_ball"), "13": ("63", "ISO 15 03", "self_aligning_ball"),
    "22": ("NU22", "ISO 15 22", "self_aligning_ball"), "23": ("NU23", "ISO 15 23", "self_aligning_ball"),
    **{f"{kind}{digits}": (f"NU{digits}", f"ISO 15 {digits}", "cylindrical_roller")
       for kind in ("N", "NJ", "NUP") for digits in ("22", "23")},
    "QJ2": ("62", "ISO 15 02", "four_point_contact_ball"), "QJ3": ("63", "ISO 15 03", "four_point_contact_ball"),
    "213": ("63", "ISO 15 03", "spherical_roller"),
    **{f"{kind}{digits}": (base, f"ISO 15 {dimension}", "cylindrical_roller") for kind in ("NU", "N", "NJ", "NUP")
       for digits, base, dimension in (("2", "62", "02"), ("3", "63", "03"), ("4", "64", "04"), ("10", "60", "10"))},
    # ISO 104 likewise for thrust bearings: the thrust ball 511, 512 take the 811, 812's d, D and height
    "511": ("811", "ISO 104 11", "thrust_ball"), "512": ("812", "ISO 104 12", "thrust_ball"),
}
# a designation: a letter prefix (NU, N, NJ, NUP, NA, QJ) or none, the series digits and bore code (two
# digits, a single digit, or /d), then an optional suffix
DESIGNATION = re.compile(r"\s*(?P<prefix>NUP|NU|NJ|NA|N|QJ)?\s*(?P<digits>\d+)(?P<slash>/\d+(?:\.\d+)?)?\s*"
                         r"(?P<suffix>[A-Za-z].*)?\s*")


@dataclasses.dataclass(frozen=True)
class BoundaryDimensions:
    """A bearing's boundary dimensions [m] with where they come from."""

    designation: str  # as the catalogue writes it, suffix dropped
    series: str
    bore: float
    outside_diameter: float
    width: float  # B: a tapered bearing's inner ring width, a thrust bearing's height H
    chamfer: float | None  # r_s min [m], None where the standard's table gives none
    source: str  # the standard and its table
    bearing_type: str  # the scene type whose series it is
    suffix: str = ""
    total_width: float | None = None  # T [m] of a tapered roller bearing
    outer_ring_width: float | None = None  # C [m] of a tapered roller bearing


@functools.cache
def _table() -> dict[tuple[str, str], dict]:
    text = importlib.resources.files("diffbearing.catalog").joinpath("boundary_dimensions.csv").read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return {(row["series"], row["bore_code"]): row for row in rows}


def series() -> tuple[str, ...]:
    """The series the data holds, tabulated or of the same dimension series, longest first (a
    designation's prefix is matched against them)."""
    names = {key[0] for key in _table()} | set(SAME_DIMENSION_SERIES)
    return tuple(sorted(names, key=lambda name: (-len(name), name)))


def _tabulated(name: str) -> str:
    """The tabulated series whose rows serve `name`."""
    return SAME_DIMENSION_SERIES[name][0] if name in SAME_DIMENSION_SERIES else name


def split_designation(designation: str) -> tuple[str, str, str]:
    """(series, bore code, suffix) of a designation; ValueError naming `bearing.designation`."""
    match = DESIGNATION.fullmatch(str(designation))
    if match is None:
        raise ValueError(f"bearing.designation: {designation!r} is not a designation (series and bore code, e.g. "
                         "6205, 22220 E, NU 310, 62/22)")
    written, slash = (match.group("prefix") or "") + match.group("digits"), match.group("slash")
    suffix = (match.group("suffix") or "").strip()
    for name in series():
        if not written.startswith(name):
            continue
        code = slash if slash and written == name else written[len(name):]
        if code and (_tabulated(name), code) in _table():
            return name, code, suffix
    known = ", ".join(sorted(series(), key=lambda name: (len(name), name)))
    raise ValueError(f"bearing.designation: {designation!r} is not in the data (series {known}: ISO 15 and ISO 104 as "
                     "the GOST standards of `diffbearing bearings` tabulate them; give bore, outer_diameter and width "
                     "instead)")


def boundary_dimensions(designation: str) -> BoundaryDimensions:
    """The boundary dimensions of `designation` (module docstring); ValueError naming
    `bearing.designation` where the data has no such bearing."""
    name, code, suffix = split_designation(designation)
    row = _table()[(_tabulated(name), code)]
    chamfer = float(row["r_smin_mm"]) / 1e3 if row["r_smin_mm"] else None
    source = f"{row['source']} {row['table']}" + (f"; checked: {row['checked']}" if row["checked"] else "")
    bearing_type = row["bearing_type"]
    if name in SAME_DIMENSION_SERIES:
        base, dimension, bearing_type = SAME_DIMENSION_SERIES[name]
        standard, _, number = dimension.rpartition(" ")
        source = f"{standard} dimension series {number}, as the {base} series: {source}"
    total, outer = (float(row[key]) / 1e3 if row[key] else None for key in ("T_mm", "C_mm"))
    return BoundaryDimensions(name + code, name, float(row["d_mm"]) / 1e3, float(row["D_mm"]) / 1e3,
                              float(row["B_mm"]) / 1e3, chamfer, source, bearing_type, suffix, total, outer)


def designations(pattern: str = "*") -> list[BoundaryDimensions]:
    """Every bearing of the data whose designation matches the shell `pattern` (fnmatch: 62*, NU3*),
    the series of the same dimension series as a tabulated one included."""
    codes = [(name, code) for name, code in _table()]
    codes += [(name, code) for name, (base, _, _) in SAME_DIMENSION_SERIES.items() for series_, code in _table()
              if series_ == base and not code.startswith("/") and len(code) == 2]
    found = [boundary_dimensions(name + code) for name, code in codes]
    return [entry for entry in found if fnmatch.fnmatchcase(entry.designation, pattern)]
