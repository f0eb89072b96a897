"""Quantities with units at the boundary (scene files, CLI): strings parsed by pint into SI.

Inside the library everything is SI float64; this module is the only place that knows units.
"""

import functools
import math
import os
import shutil

import pint

from .compilation_cache import cache_folder_in_use

# Dimension names used by the scene schema, and the SI unit each is converted to.
SI_UNITS = {
    "length": "m",
    "force": "N",
    "moment": "N*m",
    "angle": "rad",
    "angular_speed": "rad/s",
    "pressure": "Pa",
    "viscosity": "Pa*s",
    "kinematic_viscosity": "m^2/s",
    "density": "kg/m^3",
    "inverse_pressure": "1/Pa",
    "stiffness": "N/m",
    "time": "s",
    "temperature": "K",
    "thermal_expansion": "1/K",
    "temperature_difference": "K",
    "volume_flow": "m^3/s",
    "heat_transfer_coefficient": "W/(m^2*K)",
    "dimensionless": "",
}


@functools.cache
def registry() -> pint.UnitRegistry:
    """The one pint registry of diffbearing (rpm, deg, µm, ... all understood; "60 degC" is read as
    333.15 K, a temperature, not a product with an offset unit; "r" and "rev" are revolutions, as in
    the catalogues' r/min).

    pint's parsed definitions are kept in the "pint" folder of diffbearing's cache
    (`compilation_cache.cache_folder_in_use`: the user's JAX cache folder, else DIFFBEARING_CACHE's;
    none with DIFFBEARING_CACHE=off and no JAX cache folder): a process
    then builds the registry in about 0.05 s instead of 0.3–0.45 s. pint writes that cache in place,
    so a process that reads a half-written file parses the definitions itself and removes the
    folder, which the next process writes anew."""
    folder = cache_folder_in_use()
    cache = None if folder is None else os.path.join(folder, "pint")
    try:
        units = pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=cache)
    except Exception:  # noqa: BLE001 — a half-written cache file: any error of pint's loader
        if cache is not None:
            shutil.rmtree(cache, ignore_errors=True)
        units = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    units.define("rev = revolution")
    units.define("r = revolution")
    return units


def _angular_speed(quantity: pint.Quantity) -> float:
    """A speed in rad/s: a unit with an angle in it (rad/s, deg/s, rpm, r/min) converts as it says; a
    bare frequency (Hz, 1/s, 1/min, min⁻¹) counts revolutions, 2π rad each — not radians, which is
    pint's reading of 1/s (radian is dimensionless there)."""
    root = quantity.to_root_units()
    if "radian" in root.units._units:
        return float(quantity.to("rad/s").magnitude)
    return 2.0 * math.pi * float(quantity.to("1/s").magnitude)


def to_si(value, dimension: str, key: str) -> float:
    """Convert a scene value to an SI float.

    `value` is a quantity string ("28 mm", "1500 rpm", "25 deg") or a bare number taken as SI;
    "inf" is accepted for an infinite length (a flat raceway). Raises ValueError naming `key` when
    the string does not parse, has the wrong dimension (e.g. "97.5 N" for a length) or is not
    finite ("nan mm", "-inf N").
    """
    if isinstance(value, bool):
        raise ValueError(f"{key}: expected a {dimension.replace('_', ' ')}, got {value!r}")
    if isinstance(value, (int, float)):
        if math.isnan(value) or value == -math.inf:
            raise ValueError(f"{key}: {value!r} is not a finite number")
        return float(value)
    if not isinstance(value, str):
        raise ValueError(f"{key}: expected a quantity string such as \"28 mm\", got {value!r}")
    text = value.strip()
    if text.lower() in ("inf", "infinity"):
        return math.inf
    try:
        quantity = registry().Quantity(text)
    except Exception as error:  # pint raises several error types for malformed strings
        raise ValueError(f"{key}: cannot read {value!r} as a quantity ({type(error).__name__})") from None
    target = SI_UNITS[dimension]
    try:
        if dimension == "angular_speed":
            converted = _angular_speed(quantity)
        else:
            converted = float(quantity.to(target).magnitude) if target else float(quantity.to("dimensionless").magnitude)
    except pint.DimensionalityError:
        wanted = dimension.replace("_", " ")
        article = "an" if wanted[0] in "aeiou" else "a"
        raise ValueError(f"{key}: {value!r} is not {article} {wanted} (expected units convertible to {target or '1'})") from None
    if not math.isfinite(converted):
        raise ValueError(f"{key}: {value!r} is not a finite number (only a flat raceway's radius is written \"inf\")")
    return converted
