"""The lubricant ([lubricant] table: preset or explicit viscosity) and the surfaces' roughness."""

from ...params import (BALL_BEARING_KINDS, LUBRICANTS, MINERAL_OIL_DENSITY, Lubricant, _as_float, check_range,
                       wooster_pressure_viscosity)
from ...roller_geometry import ROLLER_KINDS
from ..registry import Adapter, InputBuilder, Key, quantity, register


def _lubricant(values, built) -> dict:
    base = LUBRICANTS[values["lubricant.preset"]] if "lubricant.preset" in values else None
    viscosity = values.get("lubricant.viscosity", base.viscosity if base else None)
    if viscosity is None:
        raise ValueError("missing required key: one of 'lubricant.preset', 'lubricant.viscosity' "
                         "(this scene's effects need a lubricant)")
    alpha = values.get("lubricant.pressure_viscosity",
                       base.pressure_viscosity if base else wooster_pressure_viscosity(viscosity))
    density = values.get("lubricant.density", base.density if base else MINERAL_OIL_DENSITY)
    return {"lubricant": Lubricant(viscosity, alpha, density, name=base.name if base else "custom",
                                   viscosity_law=values.get("lubricant.viscosity_law", "roelands"),
                                   density_law=values.get("lubricant.density_law", "dowson_higginson"))}


def _roughness(values, built) -> dict:
    """Composite RMS roughness [m] of the scene's surfaces, or None."""
    if "material.roughness" not in values:
        return {"roughness": None}
    check_range("material.roughness", values["material.roughness"], low=0.0, unit=" m")
    return {"roughness": _as_float(values["material.roughness"])}


TYPES = BALL_BEARING_KINDS + ROLLER_KINDS

ADAPTER = register(Adapter(
    name="lubricant",
    bearing_types=TYPES,
    keys={
        "lubricant.preset": Key("choice", choices=tuple(LUBRICANTS)),
        "lubricant.viscosity": quantity("viscosity", "dynamic viscosity η₀ at the operating temperature"),
        "lubricant.pressure_viscosity": quantity("inverse_pressure", "α; default: Wooster's estimate from η₀"),
        "lubricant.density": quantity("density"),
        "lubricant.viscosity_law": Key("choice", choices=("barus", "roelands")),
        "lubricant.density_law": Key("choice", choices=("incompressible", "dowson_higginson")),
        "material.roughness": quantity("length", "composite RMS roughness √(σ₁² + σ₂²) of the contacting surfaces"),
    },
    inputs=(InputBuilder(("lubricant",), TYPES, _lubricant), InputBuilder(("roughness",), TYPES, _roughness)),
))
