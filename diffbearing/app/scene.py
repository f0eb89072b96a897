"""Scenes: read a TOML scene (a file or a packaged example), apply overrides, validate.

`load_scene(path_or_name, overrides)` → `Scene` with every value in SI; `examples()` lists the
packaged example scenes.
"""

import copy
import dataclasses
import importlib.resources
import tomllib
from pathlib import Path

from ..catalog.designations import boundary_dimensions
from ..catalog.internal_geometry import GEOMETRY_ESTIMATES
from .units import to_si
from .schema import lookup, validate

DEFAULT_EXAMPLE = "aero_angular_contact"


@dataclasses.dataclass(frozen=True)
class Scene:
    """A validated scene: `values` maps dotted keys to SI values; `sweep` is the raw [sweep] table;
    `switched` names the effects an override changed from the file's (their keys may go unread)."""

    title: str
    values: dict
    sweep: dict | None
    source: str
    switched: tuple[str, ...] = ()
    duty: list | None = None  # the raw [[duty]] array (app/duty_cycle.py)
    derived: dict = dataclasses.field(default_factory=dict)  # {key: where its value came from} of keys the scene did not write

    @property
    def bearing_type(self) -> str:
        return self.values["bearing.type"]

    def table(self, name: str) -> dict:
        """{key: value} of one table ("effects", "fidelity", ...)."""
        prefix = name + "."
        return {k[len(prefix):]: v for k, v in self.values.items() if k.startswith(prefix)}


SWEEP_FIELDS = ("start", "stop", "num")


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


def _sweep_override(document: dict, key: str, value) -> None:
    """Set one [sweep] entry or one of its fields: `sweep.operating.inner_speed.num=11` (or the
    entry quoted, `sweep."operating.inner_speed".num`), or a whole entry,
    `sweep.operating.force=[[...], ...]` / `={start = ..., stop = ..., num = ...}`."""
    try:
        path = []
        tree = tomllib.loads(f"{key} = 0")
        while isinstance(tree, dict):
            (name, tree), = tree.items()
            path.append(name)
    except (tomllib.TOMLDecodeError, ValueError):
        raise ValueError(f"--set: cannot read {key!r} as a dotted key") from None
    field = path[-1] if path[-1] in SWEEP_FIELDS else None
    entry = ".".join(path[1:-1] if field else path[1:])
    try:
        lookup(entry)
    except ValueError as error:
        raise ValueError(f"{key}: {error} (a [sweep] entry names a scene key)") from None
    sweep = document.setdefault("sweep", {})
    if field is None:
        sweep[entry] = value
    elif isinstance(sweep.get(entry), dict):
        sweep[entry][field] = value
    else:
        raise ValueError(f"--set {key}: the scene has no {{start, stop, num}} sweep of {entry} to change; give the "
                         f"whole entry, sweep.{entry}={{start = ..., stop = ..., num = ...}}")


def apply_overrides(document: dict, overrides) -> dict:
    """A copy of a parsed scene with each (dotted key, value) set; unknown keys raise ValueError.
    Keys under `sweep.` set the [sweep] table (`_sweep_override`)."""
    document = copy.deepcopy(document)
    for key, value in overrides:
        if key.startswith("sweep."):
            _sweep_override(document, key, value)
            continue
        lookup(key)
        table, _, name = key.rpartition(".")
        target = document.setdefault(table, {}) if table else document
        target[name] = value
    return document


def _switched_effects(original: dict, overridden: dict) -> tuple[str, ...]:
    """The effects whose value the overrides changed from the file's."""
    before, after = original.get("effects", {}), overridden.get("effects", {})
    return tuple(f"effects.{name}" for name in after if before.get(name) != after[name])


def _example_files() -> dict:
    return {entry.name.removesuffix(".toml"): entry for entry in importlib.resources.files("diffbearing.scenes").iterdir()
            if entry.name.endswith(".toml")}


def examples() -> dict[str, str]:
    """{name: one-line description} of the packaged example scenes (the first comment line of each)."""
    described = {}
    for name, entry in sorted(_example_files().items()):
        first = entry.read_text().splitlines()[0]
        described[name] = first.lstrip("# ").strip() if first.startswith("#") else ""
    return described


def read_document(path: str | None) -> tuple[dict, str]:
    """Parsed TOML of a scene file or packaged example (the default example when `path` is None)
    and its name."""
    name = DEFAULT_EXAMPLE if path is None else path
    files = _example_files()
    if name in files and not Path(name).is_file():
        text, source = files[name].read_text(), f"example {name}"
    else:
        file = Path(path)
        if not file.is_file():
            raise ValueError(f"scene file not found: {path} (nor a packaged example: diffbearing examples lists them)")
        text, source = file.read_text(), str(file)
    try:
        return tomllib.loads(text), source
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{source}: not valid TOML ({error})") from None


# the scene keys a designation sets, and the field of `BoundaryDimensions` each takes
# (a tapered bearing's total width T too; a value the designation's data lacks is not set)
DESIGNATION_KEYS = {"bore": "bore", "outer_diameter": "outside_diameter", "width": "width", "total_width": "total_width"}


def _expand_table(table: dict, where: str) -> dict[str, str]:
    """Set a [bearing] table's (or a [[bearings]] entry's) `bore`, `outer_diameter` and `width` from
    its `designation` where it gives none, and the inside its type estimates (in place); {`where`.key:
    its source} of those set. ValueError naming `bearing.<key>`."""
    if "designation" not in table:
        if "static_load_rating" in table:
            raise ValueError("bearing.static_load_rating is read with bearing.designation only (the catalogue's C0, "
                             "which with its C fits the estimated ball set)")
        return {}
    dimensions = boundary_dimensions(table["designation"])
    if "type" in table and table["type"] != dimensions.bearing_type:
        raise ValueError(f"bearing.designation: {table['designation']!r} is a bearing of type {dimensions.bearing_type} "
                         f"({dimensions.source}), the scene's bearing.type is {table['type']!r}")
    derived = {}
    for key, field in DESIGNATION_KEYS.items():
        if key not in table and getattr(dimensions, field) is not None:
            table[key] = getattr(dimensions, field)
            derived[f"{where}.{key}"] = f"designation {dimensions.designation}: {dimensions.source}"
    estimate = GEOMETRY_ESTIMATES.get(dimensions.bearing_type)
    if estimate is None and "static_load_rating" in table:
        raise ValueError(f"bearing.static_load_rating: no internal geometry of a {dimensions.bearing_type} bearing is "
                         "estimated from its ratings")
    if estimate is not None:
        def scene_value(key, dimension):
            return to_si(table[key], dimension, f"bearing.{key}") if key in table else None

        for key, (value, how) in estimate(scene_value, set(table), dimensions.suffix).items():
            table[key] = value
            derived[f"{where}.{key}"] = f"ESTIMATED: {how}"
    return derived


def expand_designation(document: dict) -> dict[str, str]:
    """Expand the designation of the scene's [bearing] table and of each [[bearings]] entry of a shaft
    (`_expand_table`, in place); {key: its source} of the values set, keyed `bearing.<key>` and
    `bearings[i].<key>`. ValueError naming `bearing.designation` (`bearings[i]: designation`) for a
    designation the data lacks or one of another bearing type."""
    derived = {}
    if isinstance(document.get("bearing"), dict):
        derived |= _expand_table(document["bearing"], "bearing")
    entries = document.get("bearings")
    for index, entry in enumerate(entries if isinstance(entries, list) else []):
        if not isinstance(entry, dict):
            continue
        try:
            derived |= _expand_table(entry, f"bearings[{index}]")
        except ValueError as error:
            raise ValueError(f"bearings[{index}]: {str(error).replace('bearing.', '')}") from None
    return derived


def derived_values(scene: Scene) -> list[tuple[str, object, str]]:
    """(key, SI value, the schema key whose dimension it has) of each value the scene did not write
    (`Scene.derived`): a [bearing] key's own, a [[bearings]] entry's `bearings[i].<key>` from the entry."""
    rows = []
    for key in scene.derived:
        where, _, name = key.partition(".")
        if where == "bearing":
            rows.append((key, scene.values[key], key))
        else:
            rows.append((key, scene.values["bearings"][_entry_index(where)][f"bearing.{name}"], f"bearing.{name}"))
    return rows


def _entry_index(where: str) -> int:
    """i of "bearings[i]"."""
    return int(where.removeprefix("bearings[").removesuffix("]"))


def load_scene(path: str | None = None, overrides=()) -> Scene:
    """Read, override and validate a scene (a file path, a packaged example's name, or None for
    the default example); `overrides` holds 'dotted.key=VALUE' strings."""
    original, source = read_document(path)
    document = apply_overrides(original, [parse_override(text) for text in overrides])
    derived = expand_designation(document)
    values = validate(document)
    sweep = document.get("sweep")
    return Scene(title=values.get("title", Path(source).stem), values=values, sweep=sweep, source=source,
                 switched=_switched_effects(original, document), duty=document.get("duty"), derived=derived)
