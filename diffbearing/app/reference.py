"""The scene-key and output reference (docs/reference.md), generated from the adapters.

    python -m diffbearing.app.reference > docs/reference.md

A test keeps the file in step with the code.
"""

from . import schema
from .registry import ADAPTERS


def _kind(key) -> str:
    if key.kind == "quantity":
        return f"quantity ({key.dimension})"
    if key.kind == "quantities":
        return f"{key.length} quantities ({key.dimension})"
    if key.kind == "choice":
        return "one of " + ", ".join(f"`{str(c).lower()}`" if isinstance(c, bool) else f'`"{c}"`' for c in key.choices)
    if key.kind in ("integers",) and key.length:
        return f"{key.length} integers"
    return key.kind


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def generate() -> str:
    """The Markdown reference: every scene key (by table) and every output (by adapter)."""
    lines = ["# Scene keys and outputs", "",
             "Generated from the adapters (`python -m diffbearing.app.reference > docs/reference.md`); "
             "do not edit by hand.", "",
             "## Scene keys", "",
             "A quantity is a unit string (`\"28 mm\"`, `\"1500 rpm\"`) or a bare SI number. A key that "
             "nothing the scene runs reads is refused.", ""]
    owners: dict[str, list[str]] = {}
    for adapter in ADAPTERS.values():
        for dotted in adapter.keys:
            owners.setdefault(dotted, []).append(adapter.name)
    keys = schema.schema()
    tables: dict[str, list[str]] = {}
    for dotted in keys:
        tables.setdefault(dotted.partition(".")[0] if "." in dotted else "", []).append(dotted)
    for table, names in tables.items():
        lines += [f"### {'[' + table + ']' if table else 'top level'}", "", "| key | kind | read by | notes |",
                  "|---|---|---|---|"]
        for dotted in names:
            key = keys[dotted]
            readers = ", ".join(owners.get(dotted, ["every scene"]))
            if key.read_by:
                readers += " (blocks " + ", ".join(f"`{name}`" for name in dict.fromkeys(key.read_by)) + ")"
            lines.append(f"| `{dotted}` | {_cell(_kind(key))} | {readers} | {_cell(key.doc)} |")
        lines.append("")
    lines += ["## Outputs", "",
              "SI units in JSON (`--json`); the report shows the display unit. A block runs when its effect "
              "is on (or always, for a block without one).", ""]
    for adapter in ADAPTERS.values():
        for block in adapter.blocks:
            switch = "always" if block.enabled_by is None else f"`effects.{block.enabled_by[0]} = " + (
                str(block.enabled_by[1]).lower() if isinstance(block.enabled_by[1], bool)
                else f'"{block.enabled_by[1]}"') + "`"
            lines += [f"### `{block.name}` ({adapter.name}; {', '.join(block.bearing_types)}; {switch})", "",
                      "| key | SI unit | report unit | description |", "|---|---|---|---|"]
            for out in block.outputs:
                note = f" (with `effects.{out.effect}`)" if out.effect else ""
                lines.append(f"| `{out.key}` | {out.unit or '-'} | {out.display or '-'} | "
                             f"{_cell(out.description)}{note} |")
            lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    print(generate(), end="")
