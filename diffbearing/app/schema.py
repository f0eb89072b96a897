"""The scene-file schema: which keys exist, their kind and dimension (docs/scenes.md).

A scene is TOML. A quantity is a unit string ("28 mm", "1500 rpm") or a bare SI number. The keys
a scene may hold are those the adapters declare; an unknown key, a wrong dimension or a missing
required key raises ValueError naming the dotted key. `validate` returns a copy with every
quantity in SI. A scene with `[[bearings]]` tables and no `bearing.type` is a shaft on several
bearings: its type is "shaft" (adapters/systems/shaft.py).
"""

import difflib

from . import adapters  # noqa: F401  (registers the built-in adapters)
from .registry import ADAPTERS, SHAFT_TYPE, Key, adapters_for, all_keys
from .units import to_si


def bearing_types() -> tuple[str, ...]:
    """The bearing types some registered adapter models."""
    return tuple(dict.fromkeys(t for adapter in ADAPTERS.values() for t in adapter.bearing_types))


def schema() -> dict[str, Key]:
    """{dotted key: Key} of every key a scene may hold: the title, the bearing type, and the keys
    the registered adapters declare."""
    return {"title": Key("text", doc="free text shown in the report"),
            "bearing.type": Key("choice", choices=bearing_types()), **all_keys()}


def lookup(dotted: str) -> Key:
    """The schema entry of a dotted key ("operating.inner_speed"); ValueError if unknown."""
    keys = schema()
    if dotted not in keys:
        close = difflib.get_close_matches(dotted, list(keys), n=1)
        hint = f" (did you mean '{close[0]}'?)" if close else ""
        raise ValueError(f"unknown key '{dotted}'{hint}")
    return keys[dotted]


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
    if key.kind == "tables":
        if not isinstance(value, list) or not value or not all(isinstance(item, dict) for item in value):
            raise ValueError(f"{dotted}: expected one or more [[{dotted}]] tables, got {value!r}")
        return [key.entry(index, item, convert) for index, item in enumerate(value)]
    if key.kind == "text":
        if not isinstance(value, str):
            raise ValueError(f"{dotted}: expected a string, got {value!r}")
        return value
    raise AssertionError(f"schema kind {key.kind!r}")


def validate(document: dict) -> dict[str, object]:
    """Validate a parsed TOML scene; return {dotted key: SI value} (the [sweep] table and the
    [[duty]] array kept raw: app/sweep.py, app/duty_cycle.py check them)."""
    flat: dict[str, object] = {}
    tables = {dotted.partition(".")[0] for dotted in schema() if "." in dotted}
    for table, content in document.items():
        if table in ("sweep", "duty"):
            continue
        if isinstance(content, dict):
            if table not in tables:
                close = difflib.get_close_matches(table, sorted(tables), n=1)
                hint = f" (did you mean '[{close[0]}]'?)" if close else ""
                raise ValueError(f"unknown table '[{table}]'{hint}")
            for name, value in content.items():
                dotted = f"{table}.{name}"
                if isinstance(value, dict):
                    raise ValueError(f"unknown key '{dotted}' (a table where a value was expected)")
                flat[dotted] = convert(dotted, value)
        else:
            flat[table] = convert(table, content)
    if "bearing.type" not in flat and "bearings" in flat:
        flat["bearing.type"] = SHAFT_TYPE  # [[bearings]]: a shaft on several bearings (adapters/systems/shaft.py)
    if "bearing.type" not in flat:
        raise ValueError("missing required key 'bearing.type'")
    required_keys = [key for adapter in adapters_for(flat["bearing.type"])
                     for key in adapter.required.get(flat["bearing.type"], ())]
    for required in dict.fromkeys(required_keys):
        options = required if isinstance(required, tuple) else (required,)
        present = [name for name in options if name in flat]
        if not present:
            raise ValueError(f"missing required key '{options[0]}'" if len(options) == 1
                             else f"missing required key: one of {', '.join(repr(o) for o in options)}")
        if len(present) > 1:
            raise ValueError(f"give only one of {', '.join(repr(o) for o in present)}")
    return flat
