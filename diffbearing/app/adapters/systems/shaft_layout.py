"""A shaft scene's layout (`ShaftLayout`: its bearings as their types' parameters, their placement,
the loads; built from the scene by `shaft_layout`) and its bearings as supports (`layout_supports`),
which the shaft's block and the shaft-level effects read (adapters/systems/shaft.py declares the
scene's keys)."""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ....params import _as_float
from ....systems.flexible_shaft import shaft_mesh
from ....systems.operating_clearance import SEAT_MATERIALS
from ....systems.shaft_beam import BeamMesh, ShaftSections
from ....systems.shaft_equilibrium import ShaftLoads
from ....thermal.axial_growth import grown_supports
from ...registry import Reads, mountings
from ..designation import SCENE_LAYER_KEYS


class ShaftLayout(eqx.Module):
    """The scene's shaft: its bearings (each its type's parameters, `Mounting.parameters`, which
    only its type's `Mounting` reads) and their types (`bearing.type`), their
    positions and offsets [m] and orientations (±1), the loads, the shaft speed
    [rad/s], the reference point of the displacement and stiffness [m], each bearing's bore and
    outer diameter [m] and its total width [m] (`bearing.total_width`, else `bearing.width`: a tapered
    bearing's T) (None where its entry gives none; read by the ratings that need them), each
    ball bearing's shoulder depths [h_i, h_o] [m] (None where its entry gives no shoulder diameters,
    and for a roller bearing), for a flexible shaft its sections and mesh (None: rigid), and with
    `effects.mounting` each bearing's change of diametral clearance by its fits and temperatures
    [m] (`AbstractSupport.with_clearance_change`; None: as given) and its inner ring's axial
    displacement against its outer ring by the shaft's and the housing's growth between the
    bearings [m] (`thermal.axial_growth`; None: none)."""

    bearings: tuple
    positions: jax.Array = eqx.field(converter=_as_float)
    offsets: jax.Array = eqx.field(converter=_as_float)
    loads: ShaftLoads
    speed: jax.Array = eqx.field(converter=_as_float)
    stiffness_at: jax.Array = eqx.field(converter=_as_float)
    orientations: tuple = eqx.field(static=True)
    envelopes: tuple = ()
    shoulders: tuple = ()
    sections: ShaftSections | None = None
    mesh: BeamMesh | None = eqx.field(static=True, default=None)
    kinds: tuple = eqx.field(static=True, default=())
    widths: tuple = ()
    clearance_changes: jax.Array | None = None
    axial_growth: jax.Array | None = None


# The model options of the supports an input builder asks for their ratings and friction rows,
# which no option changes (a builder has no settings; the blocks pass the scene's).
NO_OPTIONS = {"effects": {}, "fidelity": {}}


def layout_supports(layout: ShaftLayout, settings: dict = NO_OPTIONS):
    """Each bearing as its type mounts it (`Mounting.support`), at the clearance its fits and
    temperatures leave and its offset moved by the axial growth where the layout has them: what
    the shaft and its effects read."""
    supports = tuple(mountings()[kind].support(bearing, position, offset, orientation, settings)
                     for kind, bearing, position, offset, orientation in zip(layout.kinds, layout.bearings,
                                                                             layout.positions, layout.offsets,
                                                                             layout.orientations))
    if layout.clearance_changes is not None:
        supports = tuple(support.with_clearance_change(change)
                         for support, change in zip(supports, layout.clearance_changes))
    return supports if layout.axial_growth is None else grown_supports(supports, layout.axial_growth)


PLACEMENT = ("position", "orientation", "offset")  # a [[bearings]] entry's keys that place it on the shaft


def _sections(v, positions, loads) -> tuple:
    """(ShaftSections, BeamMesh) of `[[shaft.sections]]`, or (None, None) for a rigid shaft."""
    if "shaft.sections" not in v:
        return None, None
    entries = v["shaft.sections"]
    name = v.get("shaft.material", "steel")
    sections = ShaftSections([e["from"] for e in entries], [e["to"] for e in entries],
                             [e["outer_diameter"] for e in entries], [e["inner_diameter"] for e in entries],
                             SEAT_MATERIALS[name][0])
    return sections, shaft_mesh(sections, positions, [load["position"] for load in loads],
                                v.get("shaft.stiffness_at", 0.0), v.get("shaft.element_length"))


def _check_spacing(entries) -> None:
    """Two bearings' centres at least one rolling element apart (closer, their rows would overlap: a
    double-row bearing is one entry of type double_row_angular_contact_ball, not two at one
    position); ValueError names the later one."""
    size = lambda entry: max(entry.get(f"bearing.{name}", 0.0) for name in ("ball_diameter", "roller_diameter",
                                                                            "roller_large_diameter"))
    order = sorted(range(len(entries)), key=lambda index: entries[index]["position"])
    for first, second in zip(order, order[1:]):
        gap = abs(entries[second]["position"] - entries[first]["position"])
        least = max(size(entries[first]), size(entries[second]))
        if gap < least:
            raise ValueError(f"bearings[{max(first, second)}].position: {gap * 1e3:.4g} mm from bearings"
                             f"[{min(first, second)}], closer than one rolling element ({least * 1e3:.4g} mm)")


def shaft_layout(v, built) -> dict:
    """The `shaft` input: the scene's `ShaftLayout` (its bearings at the clearances they give)."""
    shared = {key: v[key] for key in v if key.startswith("material.")}  # (items() would mark every key read)
    bearings, envelopes, widths, shoulders = [], [], [], []
    for index, entry in enumerate(v["bearings"]):
        reads = Reads({**shared, **entry})
        envelopes.append((reads.get("bearing.bore"), reads.get("bearing.outer_diameter")))
        widths.append(reads.get("bearing.total_width", reads.get("bearing.width")))
        mounting = mountings()[entry["bearing.type"]]
        try:
            bearings.append(mounting.parameters(reads))
        except ValueError as error:
            raise ValueError(f"bearings[{index}]: {str(error).replace('bearing.', '')}") from None
        shoulders.append(None)
        if mounting.shoulders is not None:
            try:
                shoulders[-1] = mounting.shoulders(reads, bearings[-1])
            except ValueError as error:
                raise ValueError(f"bearings[{index}]: {str(error).replace('bearing.', '')}") from None
        unread = sorted(set(entry) - reads.asked - set(PLACEMENT) - set(SCENE_LAYER_KEYS))
        if unread:
            raise ValueError(f"bearings[{index}]: key {unread[0].removeprefix('bearing.')!r} is not read by a "
                             "bearing on a shaft")
    loads = v["loads"]
    positions = [entry["position"] for entry in v["bearings"]]
    _check_spacing(v["bearings"])
    sections, mesh = _sections(v, positions, loads)
    return {"shaft": ShaftLayout(
        tuple(bearings), positions, [entry["offset"] for entry in v["bearings"]],
        ShaftLoads(np.array([load["position"] for load in loads]),  # forces and moments may be a duty cycle's tracers
                   jnp.stack([jnp.asarray(load["force"], float) for load in loads]),
                   jnp.stack([jnp.asarray(load["moment"], float) for load in loads])),
        v.get("shaft.speed", 0.0), v.get("shaft.stiffness_at", 0.0),
        tuple(entry["orientation"] for entry in v["bearings"]), tuple(envelopes), tuple(shoulders), sections, mesh,
        tuple(entry["bearing.type"] for entry in v["bearings"]), tuple(widths))}


# |M| / ((F_r + F_a) d_m/2) above which ISO 281's P and ISO 76's P₀, of forces alone, leave out much:
# for rigid rings the moment adds 4.37 M / (d_m Z) to the largest element load, at 0.25 about half
# of (F_r + F_a) / Z
MOMENT_RATIO = 0.25


def moment_warnings(values: dict, rating: str, load: str, instead: str) -> list[str]:
    """A warning for each bearing whose tilting moment passes `MOMENT_RATIO` (`bearings.moment_ratio`):
    its `rating`, from the standard's `load` of forces alone, leaves it out; `instead` includes it."""
    return [f"bearing {number}: {rating} leaves out the tilting moment it carries (M = {ratio:.2g} (F_r + F_a)·dm/2; "
            f"{load} is of forces alone): {instead} includes it"
            for number, ratio in enumerate(np.asarray(values["bearings.moment_ratio"])) if ratio > MOMENT_RATIO]


def check_dynamic_ratings(settings: dict, inputs: dict) -> None:
    """ValueError naming the [[bearings]] entry whose ISO 281 equivalent dynamic load is undefined
    (a nominal contact angle outside Table 3's 0°…45°) where the shaft's life is asked for (a
    `Block.validate`)."""
    if settings["effects"].get("life", False) is True:
        _check_equivalent_loads(settings, inputs, "equivalent_dynamic_load", "ISO 281 Table 3's 0° to 45°",
                                "its equivalent dynamic load, read by effects.life")


def check_static_ratings(settings: dict, inputs: dict) -> None:
    """ValueError naming the [[bearings]] entry whose ISO 76 equivalent static load is undefined
    (a ball bearing's nominal contact angle outside Table 2's 5°…45°), before a shaft's safety or
    friction reads it (a `Block.validate`)."""
    _check_equivalent_loads(settings, inputs, "equivalent_static_load", "ISO 76 Table 2's 5° to 45°",
                            "its equivalent static load, read by effects.safety and effects.friction")


def _check_equivalent_loads(settings, inputs, method: str, table: str, reader: str) -> None:
    """ValueError naming the first [[bearings]] entry whose support's `method` gives no finite load
    for F_r = F_a = 1 N (its nominal angle outside the standard's `table`)."""
    for number, support in enumerate(layout_supports(inputs["shaft"], settings)):
        load = getattr(support, method)(jnp.array([1.0, 0.0, 1.0]))
        if not isinstance(load, jax.core.Tracer) and not bool(jnp.isfinite(load)):
            angle = float(np.degrees(support.nominal_contact_angle()))
            raise ValueError(f"bearings[{number}].contact_angle: {angle:.4g}° is outside {table} ({reader})")
