"""The lubricant ([lubricant] table: preset, explicit viscosity, or the viscosities at 40 °C and
100 °C with an operating temperature) and the surfaces' roughness."""

import collections

import jax.numpy as jnp

from ...bearings.roller.roller_geometry import ROLLER_KINDS
from ...film.viscosity_temperature import REFERENCE_TEMPERATURES, walther_viscosity
from ...params import (
    BALL_BEARING_KINDS,
    ISO_VG_VISCOSITY_100,
    LUBRICANTS,
    MINERAL_OIL_DENSITY,
    Lubricant,
    _as_float,
    check_range,
    wooster_pressure_viscosity,
)
from ..registry import SHAFT, Adapter, InputBuilder, Key, quantity, register

TEMPERATURE_RANGE = (253.15, 473.15)  # K: the Walther line's range of the lubricant's temperature (−20 … 200 °C)


def walther_line(values) -> tuple | None:
    """(ν₄₀, ν₁₀₀) [m²/s] of the scene's oil (its keys, else its ISO VG preset), or None."""
    given = [values.get(f"lubricant.kinematic_viscosity_{t}") for t in (40, 100)]
    if any(v is not None for v in given):
        if None in given:
            raise ValueError("lubricant.kinematic_viscosity_40 and lubricant.kinematic_viscosity_100 go together "
                             "(the Walther line through both)")
        for t, value in zip((40, 100), given):
            check_range(f"lubricant.kinematic_viscosity_{t}", value, low=2e-6, unit=" m^2/s", why="at least 2 mm²/s")
        if not given[0] > given[1]:
            raise ValueError(f"lubricant.kinematic_viscosity_100 must be below the viscosity at 40 °C "
                             f"{given[0] * 1e6:g} mm²/s, got {given[1] * 1e6:g} mm²/s")
        return tuple(given)
    if "lubricant.preset" in values:
        grade = int(values["lubricant.preset"].removeprefix("iso_vg_"))
        return grade * 1e-6, ISO_VG_VISCOSITY_100[grade] * 1e-6
    return None


def lubricant_input(values, built) -> dict:
    base = LUBRICANTS[values["lubricant.preset"]] if "lubricant.preset" in values else None
    density = values.get("lubricant.density", base.density if base else MINERAL_OIL_DENSITY)
    pair = walther_line(values)
    if "lubricant.temperature" in values or "lubricant.kinematic_viscosity_40" in values:
        if "lubricant.viscosity" in values:
            raise ValueError("lubricant.viscosity is the viscosity at the operating temperature: give it, or "
                             "lubricant.temperature with the oil's viscosities at 40 °C and 100 °C, not both")
        if pair is None:
            raise ValueError("lubricant.temperature needs the oil's viscosities: lubricant.preset, or "
                             "lubricant.kinematic_viscosity_40 and lubricant.kinematic_viscosity_100")
        temperature = values.get("lubricant.temperature", REFERENCE_TEMPERATURES[0])
        check_range("lubricant.temperature", temperature, low=TEMPERATURE_RANGE[0], high=TEMPERATURE_RANGE[1],
                    low_open=False, high_open=False, unit=" K", why="−20 °C to 200 °C")
        viscosity = walther_viscosity(*pair, temperature) * density
    else:
        viscosity = values.get("lubricant.viscosity", base.viscosity if base else None)
    if viscosity is None:
        raise ValueError("missing required key: one of 'lubricant.preset', 'lubricant.viscosity', "
                         "'lubricant.kinematic_viscosity_40' (this scene's effects need a lubricant)")
    alpha = values.get("lubricant.pressure_viscosity",
                       base.pressure_viscosity if base else wooster_pressure_viscosity(viscosity))
    return {"lubricant": Lubricant(viscosity, alpha, density, name=base.name if base else "custom",
                                   viscosity_law=values.get("lubricant.viscosity_law", "roelands"),
                                   density_law=values.get("lubricant.density_law", "dowson_higginson"))}


def lubricant_at(values, temperature) -> Lubricant:
    """The scene's oil at `temperature` [K] on its Walther line (a scene whose temperature another
    effect sets: `effects.thermal`); ValueError where the scene gives no line or a temperature of its own."""
    for key in ("lubricant.temperature", "lubricant.viscosity"):
        if key in values:
            raise ValueError(f"{key}: the lubricant's temperature is the thermal network's with effects.thermal (give "
                             "the oil's viscosities at 40 °C and 100 °C, or lubricant.preset)")
    if walther_line(values) is None:
        raise ValueError("effects.thermal needs the oil's Walther line: lubricant.preset, or "
                         "lubricant.kinematic_viscosity_40 and lubricant.kinematic_viscosity_100")
    inside = jnp.clip(temperature, *TEMPERATURE_RANGE)  # a state beyond it is the thermal effect's error
    return lubricant_input(collections.ChainMap({"lubricant.temperature": inside}, values), {})["lubricant"]


def _roughness(values, built) -> dict:
    """Composite RMS roughness [m] of the scene's surfaces, or None."""
    if "material.roughness" not in values:
        return {"roughness": None}
    check_range("material.roughness", values["material.roughness"], low=0.0, unit=" m")
    return {"roughness": _as_float(values["material.roughness"])}


TYPES = BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT  # a shaft's bearings share its lubricant

ADAPTER = register(Adapter(
    name="lubricant",
    bearing_types=TYPES,
    keys={
        "lubricant.preset": Key("choice", choices=tuple(LUBRICANTS), doc="ISO VG mineral oil: at 40 °C, or at "
                                                                         "lubricant.temperature on its Walther line"),
        "lubricant.viscosity": quantity("viscosity", "dynamic viscosity η₀ at the operating temperature"),
        "lubricant.kinematic_viscosity_40": quantity("kinematic_viscosity", "kinematic viscosity at 40 °C"),
        "lubricant.kinematic_viscosity_100": quantity("kinematic_viscosity", "kinematic viscosity at 100 °C"),
        "lubricant.temperature": quantity("temperature", "operating temperature: the viscosity on the oil's "
                                                         "Walther line (ASTM D341) through 40 °C and 100 °C"),
        "lubricant.pressure_viscosity": quantity("inverse_pressure", "α; default: Wooster's estimate from η₀"),
        "lubricant.density": quantity("density"),
        "lubricant.viscosity_law": Key("choice", choices=("barus", "roelands")),
        "lubricant.density_law": Key("choice", choices=("incompressible", "dowson_higginson")),
        "material.roughness": quantity("length", "composite RMS roughness √(σ₁² + σ₂²) of the contacting surfaces"),
    },
    # a ball bearing's with effects.thermal: the thermal effect's, at the temperature it solves
    inputs=(InputBuilder(("lubricant",), BALL_BEARING_KINDS, lubricant_input, scene_keys=("!effects.thermal",)),
            InputBuilder(("lubricant",), ROLLER_KINDS, lubricant_input),
            InputBuilder(("lubricant",), SHAFT, lubricant_input, scene_keys=("!effects.thermal",)),
            InputBuilder(("roughness",), TYPES, _roughness)),
))
