"""Materials of rings, balls and rollers: the [material] table (presets or explicit constants)."""

from ...bearings.roller.roller_geometry import ROLLER_KINDS
from ...params import BALL_BEARING_KINDS, BEARING_STEEL, MATERIALS, Material
from ..registry import Adapter, Key, quantity, register

PRESETS = tuple(MATERIALS)


def material(values, prefix: str = "", default: Material = BEARING_STEEL) -> Material:
    """The material of `prefix` ("" for the rings and rollers, "ball_" for balls): its preset, else
    `default`, with explicit elastic constants (rings and rollers only) replacing the preset's."""
    preset = values.get(f"material.{prefix}preset")
    base = MATERIALS[preset] if preset else default
    explicit = {} if prefix else {name: values[f"material.{name}"] for name in ("elastic_modulus", "poisson_ratio",
                                                                               "density") if f"material.{name}" in values}
    if not explicit:
        return base
    return Material(explicit.get("elastic_modulus", base.elastic_modulus),
                    explicit.get("poisson_ratio", base.poisson_ratio),
                    explicit.get("density", base.density), name="custom")


ADAPTER = register(Adapter(
    name="materials",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={
        "material.preset": Key("choice", choices=PRESETS),
        "material.ball_preset": Key("choice", choices=PRESETS, doc="ball material of a hybrid bearing"),
        "material.elastic_modulus": quantity("pressure"),
        "material.poisson_ratio": Key("number"),
        "material.density": quantity("density"),
    },
))
