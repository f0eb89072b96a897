"""Quantities with units at the boundary (scene files, CLI): strings parsed by pint into SI.

Inside the library everything is SI float64; this module is the only place that knows units.
"""

import functools
import math

import pint

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
    "dimensionless": "",
}


@functools.cache
def registry() -> pint.UnitRegistry:
    """The one pint registry of diffbearing (rpm, deg, µm, ... all understood; "60 degC" is read as
    333.15 K, a temperature, not a product with an offset unit)."""
    return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


def to_si(value, dimension: str, key: str) -> float:
    """Convert a scene value to an SI float.

    `value` is a quantity string ("28 mm", "1500 rpm", "25 deg") or a bare number taken as SI;
    "inf" is accepted for an infinite length (a flat raceway). Raises ValueError naming `key` when
    the string does not parse or has the wrong dimension (e.g. "97.5 N" for a length).
    """
    if isinstance(value, bool):
        raise ValueError(f"{key}: expected a {dimension.replace('_', ' ')}, got {value!r}")
    if isinstance(value, (int, float)):
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
        return float(quantity.to(target).magnitude) if target else float(quantity.to("dimensionless").magnitude)
    except pint.DimensionalityError:
        wanted = dimension.replace("_", " ")
        raise ValueError(f"{key}: {value!r} is not a {wanted} (expected units convertible to {target or '1'})") from None
