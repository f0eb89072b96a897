"""The scene-file schema: which keys exist, their kind and dimension (DESIGN.md, "Scene files").

A scene is TOML. A quantity is a unit string ("28 mm", "1500 rpm") or a bare SI number. Every
key a scene may hold is listed here; an unknown key, a wrong dimension or a missing required key
raises ValueError naming the dotted key. `validate` returns a copy with every quantity in SI.
"""

import dataclasses
import difflib

from .units import to_si

BEARING_TYPES = ("deep_groove_ball", "angular_contact_ball", "cylindrical_roller", "tapered_roller")
PROFILE_KINDS = ("straight", "circular", "lundberg", "johns_gohar", "fujiwara_kawase")


@dataclasses.dataclass(frozen=True)
class Key:
    """One scene key: `kind` is quantity | quantities | number | integer | integers | boolean |
    choice | text; `dimension` names an entry of units.SI_UNITS; `choices` lists allowed values
    (for choice; True/False may be among them); `length` fixes the size of a list."""

    kind: str
    dimension: str = "dimensionless"
    choices: tuple = ()
    length: int | None = None
    doc: str = ""


def _q(dimension, doc=""):
    return Key("quantity", dimension, doc=doc)


SCHEMA: dict[str, dict[str, Key]] = {
    "": {"title": Key("text", doc="free text shown in the report")},
    "bearing": {
        "type": Key("choice", choices=BEARING_TYPES),
        "bore": _q("length"),
        "outer_diameter": _q("length"),
        "ball_diameter": _q("length"),
        "pitch_diameter": _q("length"),
        "balls": Key("integer"),
        "inner_groove_radius": _q("length"),
        "outer_groove_radius": _q("length"),
        "inner_groove_ratio": Key("number"),
        "outer_groove_ratio": Key("number"),
        "contact_angle": _q("angle", "free contact angle"),
        "radial_clearance": _q("length", "diametral"),
        "dynamic_load_rating": _q("force"),
        "roller_diameter": _q("length"),
        "roller_small_diameter": _q("length"),
        "roller_large_diameter": _q("length"),
        "roller_length": _q("length"),
        "rollers": Key("integer"),
        "cone_half_angle": _q("angle"),
    },
    "material": {
        "preset": Key("choice", choices=("bearing_steel", "52100", "gcr15", "silicon_nitride")),
        "ball_preset": Key("choice", choices=("bearing_steel", "52100", "gcr15", "silicon_nitride"),
                           doc="ball material of a hybrid bearing"),
        "elastic_modulus": _q("pressure"),
        "poisson_ratio": Key("number"),
        "density": _q("density"),
        "roughness": _q("length", "composite RMS roughness √(σ₁² + σ₂²) of the contacting surfaces"),
    },
    "lubricant": {
        "preset": Key("choice", choices=("iso_vg_32", "iso_vg_46", "iso_vg_68", "iso_vg_100", "iso_vg_150", "iso_vg_220")),
        "viscosity": _q("viscosity"),
        "pressure_viscosity": _q("inverse_pressure"),
        "density": _q("density"),
        "viscosity_law": Key("choice", choices=("barus", "roelands")),
        "density_law": Key("choice", choices=("incompressible", "dowson_higginson")),
    },
    "operating": {
        "inner_speed": _q("angular_speed"),
        "outer_speed": _q("angular_speed"),
        "force": Key("quantities", "force", length=3, doc="[Fx, Fy, Fz] on the inner ring"),
        "moment": Key("quantities", "moment", length=2, doc="[Mx, My] on the inner ring"),
        "oil_layer": _q("length", "inlet oil supply layer"),
        "axial_displacement": _q("length", "preload by axial displacement: δz held fixed, Fz must be 0"),
    },
    "effects": {
        "centrifugal": Key("boolean"),
        "gyroscopic": Key("boolean"),
        "stiffness": Key("boolean"),
        "life": Key("boolean"),
        "film": Key("choice", choices=(False, "hamrock_dowson", "formula", "line", "finite_line")),
        "starvation": Key("boolean"),
        "cage": Key("choice", choices=(False, True, "dynamics")),
        "contact": Key("choice", choices=("slices", "influence")),
    },
    "fidelity": {
        "hertz": Key("choice", choices=("exact", "brewe_hamrock", "hamrock_brewe")),
        "race_control": Key("choice", choices=("outer", "inner"), doc="raceway control hypothesis of the ball kinematics"),
        "hertz_constants": Key("choice", choices=("contact_angle", "free_contact_angle"),
                               doc="Hertz constants of the ball contacts at their current angle or at α0"),
        "grid": Key("integers", length=2,
                    doc="[nx, ny] cells along rolling and along the whole roller (2-D EHL solves the half y ≥ 0)"),
        "tolerance": Key("number"),
    },
    "profile": {
        "kind": Key("choice", choices=PROFILE_KINDS),
        "flat_length": _q("length"),
        "crown_radius": _q("length"),
        "design_load": _q("force"),
        "k1": Key("number"),
        "k2": Key("number"),
        "zm": _q("length"),
    },
    "contact": {
        "raceway": Key("choice", choices=("inner", "outer")),
        "raceway_radius": _q("length"),
        "raceway_edge_radius": _q("length"),
        "load": _q("force"),
        "tilt": _q("angle"),
    },
    "cage": {
        "guidance": Key("choice", choices=("outer_ring",), doc="the model covers outer-ring land guidance"),
        "pocket": Key("choice", choices=("outer_lock", "cylindrical")),
        "pocket_clearance": _q("length", "diametral"),
        "guide_clearance": _q("length", "diametral"),
        "land_width": _q("length"),
        "land_diameter": _q("length", "outer-ring guiding bore; default d_m + 0.8 D_w"),
        "land_spacing": _q("length", "axial distance of the two land centres; default D_w + land_width"),
        "friction": Key("number"),
        "film_threshold": _q("length", "land film below which metal contact takes over; default 1 µm"),
        "contact_stiffness": _q("stiffness", "land metal contact stiffness; default 3e7 N/m"),
        "eccentricity": Key("number", doc="cage offset / radial guide clearance"),
        "offset_angle": _q("angle", "from the radial load direction"),
        "pushing_balls": Key("integer", doc="default: the balls in the load zone"),
        "resisting_balls": Key("integer", doc="default: the balls outside the load zone"),
        "duration": _q("time", "time simulated by effects.cage = 'dynamics'; default 10 cage revolutions"),
    },
}

# Keys without which a bearing type cannot be built: one name, or a tuple meaning "one of".
REQUIRED = {
    "deep_groove_ball": ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls",
                         ("bearing.inner_groove_radius", "bearing.inner_groove_ratio"),
                         ("bearing.outer_groove_radius", "bearing.outer_groove_ratio"),
                         ("bearing.contact_angle", "bearing.radial_clearance")),
    "angular_contact_ball": ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls",
                             ("bearing.inner_groove_radius", "bearing.inner_groove_ratio"),
                             ("bearing.outer_groove_radius", "bearing.outer_groove_ratio"),
                             ("bearing.contact_angle", "bearing.radial_clearance")),
    "cylindrical_roller": ("bearing.roller_diameter", "bearing.roller_length"),
    "tapered_roller": ("bearing.roller_small_diameter", "bearing.roller_large_diameter", "bearing.roller_length"),
}


def lookup(dotted: str) -> Key:
    """The schema entry of a dotted key ("operating.inner_speed"); ValueError if unknown."""
    table, _, name = dotted.rpartition(".")
    if table not in SCHEMA or name not in SCHEMA[table]:
        known = [f"{t}.{k}" if t else k for t, keys in SCHEMA.items() for k in keys]
        close = difflib.get_close_matches(dotted, known, n=1)
        hint = f" (did you mean '{close[0]}'?)" if close else ""
        raise ValueError(f"unknown key '{dotted}'{hint}")
    return SCHEMA[table][name]


def convert(dotted: str, value):
    """Check one scene value against its schema entry and return it in SI."""
    key = lookup(dotted)
    if key.kind == "quantity":
        return to_si(value, key.dimension, dotted)
    if key.kind == "quantities":
        if not isinstance(value, list) or (key.length is not None and len(value) != key.length):
            raise ValueError(f"{dotted}: expected a list of {key.length} {key.dimension} values, got {value!r}")
        return [to_si(item, key.dimension, f"{dotted}[{i}]") for i, item in enumerate(value)]
    if key.kind == "number":
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"{dotted}: expected a number, got {value!r}")
        return float(value)
    if key.kind == "integer":
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"{dotted}: expected an integer, got {value!r}")
        return value
    if key.kind == "integers":
        if not isinstance(value, list) or not all(isinstance(v, int) and not isinstance(v, bool) for v in value):
            raise ValueError(f"{dotted}: expected a list of integers, got {value!r}")
        if key.length is not None and len(value) != key.length:
            raise ValueError(f"{dotted}: expected a list of {key.length} integers, got {value!r}")
        return value
    if key.kind == "boolean":
        if not isinstance(value, bool):
            raise ValueError(f"{dotted}: expected true or false, got {value!r}")
        return value
    if key.kind == "choice":
        if not any(type(choice) is type(value) and choice == value for choice in key.choices):
            shown = ", ".join(repr(c).replace("'", '"').lower() if isinstance(c, bool) else f'"{c}"' for c in key.choices)
            raise ValueError(f"{dotted}: expected one of {shown}, got {value!r}")
        return value
    if key.kind == "text":
        if not isinstance(value, str):
            raise ValueError(f"{dotted}: expected a string, got {value!r}")
        return value
    raise AssertionError(f"schema kind {key.kind!r}")


def validate(document: dict) -> dict[str, object]:
    """Validate a parsed TOML scene; return {dotted key: SI value} (the [sweep] table kept raw)."""
    flat: dict[str, object] = {}
    for table, content in document.items():
        if table == "sweep":
            continue
        if isinstance(content, dict):
            if table not in SCHEMA:
                close = difflib.get_close_matches(table, [t for t in SCHEMA if t], n=1)
                hint = f" (did you mean '[{close[0]}]'?)" if close else ""
                raise ValueError(f"unknown table '[{table}]'{hint}")
            for name, value in content.items():
                dotted = f"{table}.{name}"
                if isinstance(value, dict):
                    raise ValueError(f"unknown key '{dotted}' (a table where a value was expected)")
                flat[dotted] = convert(dotted, value)
        else:
            flat[table] = convert(table, content)
    if "bearing.type" not in flat:
        raise ValueError("missing required key 'bearing.type'")
    for required in REQUIRED[flat["bearing.type"]]:
        options = required if isinstance(required, tuple) else (required,)
        present = [name for name in options if name in flat]
        if not present:
            raise ValueError(f"missing required key '{options[0]}'" if len(options) == 1
                             else f"missing required key: one of {', '.join(repr(o) for o in options)}")
        if len(present) > 1:
            raise ValueError(f"give only one of {', '.join(repr(o) for o in present)}")
    return flat
