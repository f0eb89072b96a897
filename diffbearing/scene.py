"""Scenes: read a TOML scene, apply overrides, build the parameter pytrees, assemble the model.

`load_scene(path, overrides)` → `Scene` (validated, SI); `build_model(scene)` → `Model` with the
inputs pytree and exactly the blocks the scene's effects call for; `run_model(model)` compiles
and runs it, timing both.
"""

import copy
import dataclasses
import functools
import importlib.resources
import time
import tomllib
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from . import effects as effect_registry
from .params import (BEARING_STEEL, _as_float, _is_concrete, LUBRICANTS, MATERIALS, Lubricant, Material, Operating,
                     ball_bearing, ball_cage, check_range, wooster_pressure_viscosity)
from .roller_geometry import RollerLoading, roller_bearing
from .roller_profile import roller_profile
from .schema import lookup, validate

DEFAULT_SCENE = "aero_angular_contact.toml"


@dataclasses.dataclass(frozen=True)
class Scene:
    """A validated scene: `values` maps dotted keys to SI values; `sweep` is the raw [sweep] table."""

    title: str
    values: dict
    sweep: dict | None
    source: str

    @property
    def bearing_type(self) -> str:
        return self.values["bearing.type"]

    def table(self, name: str) -> dict:
        """{key: value} of one table ("effects", "fidelity", ...)."""
        prefix = name + "."
        return {k[len(prefix):]: v for k, v in self.values.items() if k.startswith(prefix)}


def parse_override(text: str) -> tuple[str, object]:
    """'dotted.key=VALUE' → (key, value); VALUE is a TOML value, or else taken as a string."""
    key, sep, raw = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ValueError(f"--set expects dotted.key=VALUE, got {text!r}")
    try:
        value = tomllib.loads(f"value = {raw}")["value"]
    except tomllib.TOMLDecodeError:
        value = raw.strip()
    return key, value


def apply_overrides(document: dict, overrides) -> dict:
    """A copy of a parsed scene with each (dotted key, value) set; unknown keys raise ValueError."""
    document = copy.deepcopy(document)
    for key, value in overrides:
        lookup(key)
        table, _, name = key.rpartition(".")
        target = document.setdefault(table, {}) if table else document
        target[name] = value
    return document


def read_document(path: str | None) -> tuple[dict, str]:
    """Parsed TOML of a scene file (the built-in default when `path` is None) and its name."""
    if path is None:
        text = importlib.resources.files("diffbearing.scenes").joinpath(DEFAULT_SCENE).read_text()
        source = f"built-in example ({DEFAULT_SCENE})"
    else:
        file = Path(path)
        if not file.is_file():
            raise ValueError(f"scene file not found: {path}")
        text, source = file.read_text(), str(file)
    try:
        return tomllib.loads(text), source
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{source}: not valid TOML ({error})") from None


def load_scene(path: str | None = None, overrides=()) -> Scene:
    """Read, override and validate a scene; `overrides` holds 'dotted.key=VALUE' strings."""
    document, source = read_document(path)
    document = apply_overrides(document, [parse_override(text) for text in overrides])
    values = validate(document)
    sweep = document.get("sweep")
    return Scene(title=values.get("title", Path(source).stem), values=values, sweep=sweep, source=source)


def _material(values: dict, prefix: str, default: Material) -> Material:
    preset = values.get(f"material.{prefix}preset")
    base = MATERIALS[preset] if preset else default
    explicit = {name: values[f"material.{name}"] for name in ("elastic_modulus", "poisson_ratio", "density")
                if f"material.{name}" in values and not prefix}
    if not explicit:
        return base
    return Material(explicit.get("elastic_modulus", base.elastic_modulus),
                    explicit.get("poisson_ratio", base.poisson_ratio),
                    explicit.get("density", base.density), name="custom")


def _lubricant(values: dict) -> Lubricant | None:
    if not any(key.startswith("lubricant.") for key in values):
        return None
    base = LUBRICANTS[values["lubricant.preset"]] if "lubricant.preset" in values else None
    viscosity = values.get("lubricant.viscosity", base.viscosity if base else None)
    if viscosity is None:
        raise ValueError("missing required key: one of 'lubricant.preset', 'lubricant.viscosity'")
    alpha = values.get("lubricant.pressure_viscosity",
                       base.pressure_viscosity if base else wooster_pressure_viscosity(viscosity))
    density = values.get("lubricant.density", base.density if base else 870.0)
    return Lubricant(viscosity, alpha, density, name=base.name if base else "custom",
                     viscosity_law=values.get("lubricant.viscosity_law", "roelands"),
                     density_law=values.get("lubricant.density_law", "dowson_higginson"))


def build_inputs(scene: Scene) -> effect_registry.SceneInputs:
    """Parameter pytrees of a scene (ValueError names any bad value)."""
    return inputs_from_values(scene.values)


def inputs_from_values(v: dict) -> effect_registry.SceneInputs:
    """Parameter pytrees from {dotted key: SI value}; values may be JAX tracers (sweeps under vmap)."""
    if v["bearing.type"] in effect_registry.ROLLER_TYPES:
        return roller_inputs_from_values(v)
    ring = _material(v, "", BEARING_STEEL)
    bearing = ball_bearing(
        kind=v["bearing.type"],
        ball_diameter=v["bearing.ball_diameter"], pitch_diameter=v["bearing.pitch_diameter"],
        balls=v["bearing.balls"],
        inner_groove_ratio=v.get("bearing.inner_groove_ratio"),
        outer_groove_ratio=v.get("bearing.outer_groove_ratio"),
        inner_groove_radius=v.get("bearing.inner_groove_radius"),
        outer_groove_radius=v.get("bearing.outer_groove_radius"),
        contact_angle=v.get("bearing.contact_angle"), radial_clearance=v.get("bearing.radial_clearance"),
        ball_material=_material(v, "ball_", ring), ring_material=ring,
        bore=v.get("bearing.bore"), outer_diameter=v.get("bearing.outer_diameter"),
        dynamic_load_rating=v.get("bearing.dynamic_load_rating"),
    )
    operating = Operating(
        inner_speed=v.get("operating.inner_speed", 0.0), outer_speed=v.get("operating.outer_speed", 0.0),
        force=v.get("operating.force", [0.0, 0.0, 0.0]), moment=v.get("operating.moment", [0.0, 0.0]),
        axial_displacement=v.get("operating.axial_displacement"),
    )
    cage, offset = _cage(v, bearing, operating) if v.get("effects.cage", False) is not False else (None, None)
    duration = v.get("cage.duration")
    if duration is not None:
        check_range("cage.duration", duration, low=0.0, unit=" s")
    return effect_registry.SceneInputs(bearing=bearing, operating=operating, lubricant=_lubricant(v),
                                       roughness=_roughness(v), cage=cage, cage_offset=offset,
                                       cage_duration=None if duration is None else _as_float(duration))


def _cage(v: dict, bearing, operating):
    """(Cage, centre offset (x, y) [m]) of a [cage] table. Pushing and resisting balls default to
    the balls inside and outside the Sjövall load zone; given counts must fit in it."""
    from .cage_forces import loaded_ball_count

    for key in ("pocket_clearance", "guide_clearance", "land_width"):
        if f"cage.{key}" not in v:
            raise ValueError(f"effects.cage needs cage.{key}")
    loaded = loaded_ball_count(bearing, operating.force)
    count = bearing.ball_count
    pushing = v.get("cage.pushing_balls", loaded)
    resisting = v.get("cage.resisting_balls", count - loaded)
    if _is_concrete(loaded, pushing, resisting):
        check_range("cage.pushing_balls", pushing, low=1.0, high=float(loaded), low_open=False, high_open=False,
                    why=f"pushing balls are among the {int(loaded)} balls in the Sjövall load zone of operating.force")
        check_range("cage.resisting_balls", resisting, low=0.0, high=float(count - loaded), low_open=False,
                    high_open=False, why=f"resisting balls are among the {count - int(loaded)} balls outside "
                                         "the Sjövall load zone of operating.force")
    optional = {name: v[f"cage.{name}"] for name in ("land_diameter", "land_spacing", "film_threshold", "contact_stiffness")
                if f"cage.{name}" in v}
    cage = ball_cage(bearing, pocket=v.get("cage.pocket", "outer_lock"), pocket_clearance=v["cage.pocket_clearance"],
                     guide_clearance=v["cage.guide_clearance"], land_width=v["cage.land_width"],
                     friction=v.get("cage.friction", 0.1), pushing_balls=pushing, resisting_balls=resisting, **optional)
    eccentricity = v.get("cage.eccentricity", 0.0)
    check_range("cage.eccentricity", eccentricity, low=0.0, low_open=False,
                why="the cage offset over the radial guide clearance; above 1 the cage presses into the land")
    force = jnp.asarray(operating.force)
    direction = jnp.arctan2(force[1], force[0]) + v.get("cage.offset_angle", 0.0)
    offset = eccentricity * 0.5 * cage.guide_clearance * jnp.stack([jnp.cos(direction), jnp.sin(direction)])
    return cage, offset


def _roughness(v: dict):
    """Composite RMS roughness [m] of the scene's surfaces, or None."""
    if "material.roughness" not in v:
        return None
    check_range("material.roughness", v["material.roughness"], low=0.0, unit=" m")
    return _as_float(v["material.roughness"])


def _raceway_curvature(v: dict) -> float:
    """Signed raceway curvature [1/m] in the rolling direction: convex (inner) > 0, concave < 0."""
    raceway = v.get("contact.raceway", "inner")
    sign = 1.0 if raceway == "inner" else -1.0
    if "contact.raceway_radius" in v:
        radius = v["contact.raceway_radius"]
        if not isinstance(radius, jax.core.Tracer) and np.isposinf(radius):
            return 0.0  # "inf": a flat raceway
        check_range("contact.raceway_radius", radius, low=0.0, unit=" m", why='or "inf" for a flat raceway')
        return sign / radius
    if "bearing.pitch_diameter" in v and v["bearing.type"] == "cylindrical_roller":
        # cylindrical roller: raceway radii (d_m ∓ D)/2 at the inner and outer ring
        radius = 0.5 * (v["bearing.pitch_diameter"] - sign * v["bearing.roller_diameter"])
        check_range("bearing.pitch_diameter", radius, low=0.0, unit=" m",
                    why="the inner raceway radius (d_m − D)/2 must be positive")
        return sign / radius
    raise ValueError("missing required key: one of 'contact.raceway_radius', 'bearing.pitch_diameter' "
                     "(the latter for cylindrical rollers)")


def _roller_entrainment_speed(v: dict):
    """Mean entrainment speed u [m/s] of a cylindrical roller in pure rolling:
    u = (d_m/4)(1 − γ²)|ω_i − ω_o|, γ = D/d_m (Harris & Kotzalas vol. 1, ch. 8); 0 without speeds."""
    if "bearing.pitch_diameter" not in v or v["bearing.type"] != "cylindrical_roller":
        return 0.0
    relative = v.get("operating.inner_speed", 0.0) - v.get("operating.outer_speed", 0.0)
    ratio = v["bearing.roller_diameter"] / v["bearing.pitch_diameter"]
    return 0.25 * v["bearing.pitch_diameter"] * (1.0 - ratio**2) * abs(relative)


def roller_inputs_from_values(v: dict) -> effect_registry.SceneInputs:
    """Parameter pytrees of a roller–raceway contact scene (cylindrical or tapered roller)."""
    length = v["bearing.roller_length"]
    kind = v.get("profile.kind", "straight")
    parameters = {name: v.get(f"profile.{name}") for name in ("flat_length", "crown_radius", "design_load", "k1", "k2", "zm")}
    if kind in ("straight", "circular"):
        parameters.pop("design_load")  # a design load belongs to the logarithmic kinds; others ignore it
    profile = roller_profile(kind, length=length, **parameters)
    bearing = roller_bearing(kind=v["bearing.type"], length=length, diameter=v.get("bearing.roller_diameter"),
                             small_diameter=v.get("bearing.roller_small_diameter"),
                             large_diameter=v.get("bearing.roller_large_diameter"),
                             cone_half_angle=v.get("bearing.cone_half_angle", 0.0), profile=profile,
                             material=_material(v, "", BEARING_STEEL))
    if "contact.load" not in v:
        raise ValueError("missing required key 'contact.load' (the roller load Q)")
    loading = RollerLoading(load=v["contact.load"], tilt=v.get("contact.tilt", 0.0),
                            raceway_curvature=_raceway_curvature(v), entrainment_speed=_roller_entrainment_speed(v),
                            oil_layer=v.get("operating.oil_layer"))
    return effect_registry.SceneInputs(bearing=bearing, operating=loading, lubricant=_lubricant(v))


@dataclasses.dataclass
class Model:
    """A scene assembled: its inputs pytree and the blocks to run, in order."""

    scene: Scene
    inputs: effect_registry.SceneInputs
    blocks: list
    settings: dict
    not_implemented: list
    sweep_axes: dict = dataclasses.field(default_factory=dict)  # {dotted key: SI values} of a [sweep] table

    @property
    def outputs(self) -> dict:
        return effect_registry.outputs_of(self.blocks, self.settings["effects"])

    def function(self):
        """The pure function inputs → {output key: array} (jit, vmap and grad it freely)."""
        return effect_registry.evaluate(self.blocks, self.settings)


def build_model(scene: Scene) -> Model:
    """Assemble the model of a scene: only the blocks its effects name (and what they require)."""
    inputs = build_inputs(scene)
    from .sweep import sweep_axes

    axes = sweep_axes(scene.sweep) if scene.sweep else {}  # bad entries fail here, before compiling
    blocks, missing = effect_registry.resolve(scene.bearing_type, scene.table("effects"))
    settings = {"effects": scene.table("effects"), "fidelity": scene.table("fidelity")}
    if scene.bearing_type in effect_registry.ROLLER_TYPES and "contact" in settings["effects"]:
        effect_registry.contact_settings(settings)  # bad grid or tolerance fails here, before compiling
    if scene.bearing_type in effect_registry.ROLLER_TYPES and settings["effects"].get("film", False) is not False:
        effect_registry.film_settings(settings, inputs)
        effect_registry.starvation_settings(settings, inputs)
    if settings["effects"].get("cage", False) is not False:
        effect_registry.cage_settings(inputs)
    if settings["effects"].get("film", False) is not False and inputs.lubricant is None:
        raise ValueError("effects.film needs a [lubricant] table (lubricant.preset or lubricant.viscosity)")
    return Model(scene=scene, inputs=inputs, blocks=blocks, settings=settings, not_implemented=missing,
                 sweep_axes=axes)


@dataclasses.dataclass
class RunResult:
    """Outputs of one run (NumPy arrays, SI) with compile and run times [s]."""

    model: Model
    values: dict
    compile_s: float  # 0 when the compiled model was reused from an earlier run in this process
    run_s: float
    sweep_axes: dict = dataclasses.field(default_factory=dict)  # {dotted key: SI values} of a sweep

    @functools.cached_property
    def problems(self) -> tuple[list[str], list[str]]:
        """(errors, warnings) of the blocks' checks, one line each (a sweep's name their point)."""
        shape = tuple(len(values) for values in self.sweep_axes.values())
        return effect_registry.problems(self.model.blocks, self.values, shape)


def run_model(model: Model, progress: bool = True) -> RunResult:
    """Compile (timed; reused when cached), then run (timed, excluding compilation) the model;
    a scene with a [sweep] table runs as one vmapped batch (see sweep.py)."""
    if model.sweep_axes:
        from .sweep import run_sweep

        return run_sweep(model, model.sweep_axes, progress=progress)
    start = time.perf_counter()
    executable, cached = effect_registry.compiled(model.blocks, model.settings, model.inputs)
    compile_s = 0.0 if cached else time.perf_counter() - start
    start = time.perf_counter()
    values = jax.block_until_ready(executable(model.inputs))
    run_s = time.perf_counter() - start
    return RunResult(model, {key: np.asarray(value) for key, value in values.items()}, compile_s, run_s)
