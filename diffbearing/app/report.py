"""Readable report and JSON of a run: SI values converted to display units only here.

The report is generic: each active adapter adds its header, its own lines and its sweep columns
(registry.Adapter); every other output appears in a table of its section with its display unit.
"""

import json

import numpy as np

from .duty_cycle import case_dimension, damage_life, describe
from .formatting import format_number, format_value, swept_display, to_display, unit_label
from .registry import adapters_for
from .scene import derived_values
from .schema import lookup


def active_adapters(model) -> list:
    """The adapters of the model's bearing type with a block in the model, in registration order."""
    running = set(model.blocks)
    return [adapter for adapter in adapters_for(model.scene.bearing_type) if running & set(adapter.blocks)]


def _header(result) -> list[str]:
    """The adapter's header (or the title and source), then the values the scene did not write itself."""
    lines = next((adapter.header(result) for adapter in active_adapters(result.model) if adapter.header is not None),
                 [result.model.scene.title, f"scene: {result.model.scene.source}"])
    return lines + derived_lines(result.model.scene)


def derived_lines(scene) -> list[str]:
    """One line for each value the scene did not give itself (`Scene.derived`: a designation's), with its source."""
    if not scene.derived:
        return []
    lines = ["", "Not written in the scene (any value given there overrides these):"]
    for key, value, schema_key in derived_values(scene):
        shown, display = swept_display(np.asarray(value, float), lookup(schema_key).dimension)
        lines.append(f"  {key} = {format_number(shown)} {unit_label(display)}  ({scene.derived[key]})")
    return lines


def _swept_cells(key, values, dimension=None) -> tuple[str, list[str]]:
    shown, display = swept_display(values, dimension or lookup(key).dimension)
    cells = [("[" + ", ".join(format_number(x) for x in np.ravel(v)) + "]") if np.ndim(v) else format_number(v)
             for v in shown]
    return f"{key} [{unit_label(display)}]", cells


def _problem_lines(result, most=None) -> list[str]:
    """The run's errors (outside the model, not converged) and warnings (limits passed), `most` of each."""
    lines = []
    for title, found in zip(("ERRORS (outside the model or not converged)", "Warnings"), result.problems):
        if found:
            shown = found if most is None else found[:most]
            lines += ["", f"{title}:"] + [f"  {line}" for line in shown]
            if len(found) > len(shown):
                lines.append(f"  … {len(found) - len(shown)} more in --json")
    return lines


def format_sweep_report(result) -> str:
    """Report of a sweep: one row per grid point with the swept values and the key results."""
    lines = _header(result)
    axes = result.sweep_axes
    shape = tuple(len(v) for v in axes.values())
    grid = f"{' × '.join(str(n) for n in shape)} = " if len(shape) > 1 else ""
    batch = ("mapped point by point (an iterative solver)" if any(b.sequential_sweep for b in result.model.blocks)
             else "one vmapped batch")
    lines += ["", f"Sweep over {grid}{int(np.prod(shape))} points ({', '.join(axes)}), {batch}"]
    grids = np.meshgrid(*[np.arange(n) for n in shape], indexing="ij")
    flat_index = [g.ravel() for g in grids]
    columns = []
    for k, (key, values) in enumerate(axes.items()):
        header, cells = _swept_cells(key, values)
        columns.append((header, [cells[i] for i in flat_index[k]]))
    values = {key: np.reshape(value, (-1,) + np.shape(value)[len(shape):]) for key, value in result.values.items()}
    for adapter in active_adapters(result.model):
        if adapter.sweep_columns is not None:
            columns += adapter.sweep_columns(values)
    widths = [max(len(h), *(len(c) for c in cells)) + 2 for h, cells in columns]
    lines.append("  " + "".join(f"{h:>{w}}" for (h, _), w in zip(columns, widths)))
    rows = len(columns[0][1])
    shown = list(range(rows)) if rows <= 40 else list(range(20)) + [None] + list(range(rows - 20, rows))
    for row in shown:
        if row is None:
            lines.append(f"  … {rows - 40} more rows in --json …")
            continue
        lines.append("  " + "".join(f"{cells[row]:>{w}}" for (_, cells), w in zip(columns, widths)))
    lines += _problem_lines(result, most=10)
    lines += ["", f"compile {result.compile_s:.2f} s, run {result.run_s:.3f} s for {rows} points "
              f"({result.run_s / rows * 1e3:.2f} ms per point, after compilation)"]
    return "\n".join(lines)


def _case_table(result, columns) -> list[str]:
    """Rows of `columns` [(header, cells)], one per point."""
    widths = [max(len(h), *(len(c) for c in cells)) + 2 for h, cells in columns]
    lines = ["  " + "".join(f"{h:>{w}}" for (h, _), w in zip(columns, widths))]
    for row in range(len(columns[0][1])):
        lines.append("  " + "".join(f"{cells[row]:>{w}}" for (_, cells), w in zip(columns, widths)))
    return lines


def format_duty_report(result) -> str:
    """Report of a duty cycle: each case's keys, share and key results, then the cycle's lives by
    Palmgren–Miner (`duty_cycle.py`), their hours at the mean speed, each case's share of the damage."""
    duty, values = result.duty, result.values
    lines = _header(result)
    lines += ["", f"Duty cycle of {duty.count} load cases, one vmapped batch; each case sets {', '.join(duty.cases)} "
              "(the lines above show the scene's own values)"]
    columns = [("case", [str(number) for number in range(duty.count)]),
               (duty.share_kind, [format_number(share) for share in duty.shares])]
    if duty.share_kind != "revolution_share":
        columns.append(("revolution share", [format_number(share) for share in values["duty.revolution_share"]]))
    columns += [_swept_cells(key, array, case_dimension(key)) for key, array in duty.cases.items()]
    case_values = {key: value for key, value in values.items() if not key.startswith("duty.")}
    for adapter in active_adapters(result.model):
        if adapter.sweep_columns is not None:
            columns += adapter.sweep_columns(case_values)
    damaged = damage_life(values)
    if damaged is not None:
        columns.append((f"damage share ({damaged.rpartition('.')[2]})",
                        [f"{share:.1%}" for share in values["duty.damage_share"]]))
    lines += _case_table(result, columns)
    lines += ["", "Cycle (Palmgren–Miner, 1/L = Σ u_i/L_i over the revolutions' shares)"]
    if "life.a1" in values:
        reliability = format_number(result.model.scene.values["life.reliability"])
        lines.append(f"  {'L_n at the reliability R = ' + reliability + ' %':<56}"
                     f"{'a₁ = ' + format_number(np.ravel(values['life.a1'])[0]):>14}")
    for key, out in result.model.outputs.items():  # each life over the cycle, one or each bearing's of a shaft
        if f"duty.{key}" in values:
            hours = values.get(f"duty.hours.{key}")
            extra = "" if hours is None else f"  ({format_value(hours, most=None)} h)"
            lines.append(f"  {out.description:<56} {format_value(values[f'duty.{key}'], most=None):>13}  "
                         f"{unit_label(out.display)}{extra}")
    for key in ("duty.equivalent_load", "duty.mean_speed"):
        if key in values:
            description, unit, display = describe(key, result.model.outputs)
            lines.append(f"  {description:<56}{format_number(to_display(values[key], unit, display)):>14}  {unit_label(display)}")
    lines += _problem_lines(result, most=10)
    lines += ["", f"compile {result.compile_s:.2f} s, run {result.run_s:.3f} s for {duty.count} cases (after compilation)"]
    return "\n".join(lines)


def _output_tables(result) -> list[str]:
    """The outputs of the generic tables, one section per first key part; an output keyed
    section.inner.name / section.outer.name shares a row with its other side."""
    lines = []
    values = result.values
    sections: dict[str, dict[str, dict]] = {}
    for key, out in result.model.outputs.items():
        if key not in values or not out.in_report or out.column:
            continue
        parts = key.split(".")
        if len(parts) == 3 and parts[1] in ("inner", "outer"):
            section, side, row = parts[0], parts[1], parts[2]
        else:
            section, side, row = parts[0], "value", ".".join(parts[1:])
        entry = sections.setdefault(section, {}).setdefault(row, {"out": out})
        entry[side] = values[key]
    for section, rows in sections.items():
        lines += ["", section.replace("_", " ").capitalize()]
        scalar_rows = [row for row in rows.values() if "value" in row]
        sided_rows = [row for row in rows.values() if "value" not in row]
        for row in scalar_rows:
            out = row["out"]
            cell = format_value(to_display(row["value"], out.unit, out.display))
            lines.append(f"  {out.description:<48}{cell:>16}  {unit_label(out.display)}")
        if sided_rows:
            lines.append(f"  {'':<48}{'inner':>16}{'outer':>16}")
            for row in sided_rows:
                out = row["out"]
                label = out.description.removesuffix(", inner")
                cells = [format_value(to_display(row[c], out.unit, out.display)) if c in row else ""
                         for c in ("inner", "outer")]
                lines.append(f"  {label:<48}" + "".join(f"{cell:>16}" for cell in cells) + f"  {unit_label(out.display)}")
    return lines


def format_report(result) -> str:
    """The text report of a run: header, output tables, the adapters' own lines, problems, timing."""
    if result.sweep_axes:
        return format_sweep_report(result)
    if result.duty is not None:
        return format_duty_report(result)
    lines = _header(result) + _output_tables(result)
    for adapter in active_adapters(result.model):
        if adapter.report is not None:
            lines += adapter.report(result)
    lines += _problem_lines(result)
    if result.model.not_implemented:
        lines += ["", "Not computed (effect not available yet): " + ", ".join(result.model.not_implemented)]
    run = f"{result.run_s:.1f} s" if result.run_s >= 1.0 else f"{result.run_s * 1e3:.2f} ms"
    lines += ["", f"compile {result.compile_s:.2f} s, run {run} (after compilation)"]
    return "\n".join(lines)


def nest(flat: dict) -> dict:
    """{'a.b.c': v} → {'a': {'b': {'c': v}}}."""
    tree: dict = {}
    for key, value in flat.items():
        node = tree
        *path, last = key.split(".")
        for part in path:
            node = node.setdefault(part, {})
        node[last] = value
    return tree


def _json_value(value):
    """Array → nested lists; NaN (a quantity that does not exist, e.g. the film of an unloaded
    ball) → null."""
    array = np.asarray(value)
    if array.dtype.kind == "f" and np.isnan(array).any():
        return np.where(np.isnan(array), None, array.astype(object)).tolist()
    return array.tolist()


def json_document(result) -> dict:
    """The JSON document of a run: SI values under the output keys (README, "JSON keys")."""
    flat = {key: _json_value(value) for key, value in result.values.items()}
    flat["timing.compile_s"] = result.compile_s
    flat["timing.run_s"] = result.run_s
    document = {"title": result.model.scene.title, **nest(flat)}
    if result.sweep_axes:
        document["sweep"] = {key: np.asarray(values).tolist() for key, values in result.sweep_axes.items()}
    if result.duty is not None:  # beside the cycle's values under "duty"
        document.setdefault("duty", {})["cases"] = {key: np.asarray(values).tolist()
                                                     for key, values in result.duty.cases.items()}
        document["duty"][result.duty.share_kind] = result.duty.shares.tolist()
    document["derived"] = dict(result.model.scene.derived)  # the keys the scene did not write, with their source
    document["not_computed"] = list(result.model.not_implemented)
    document["errors"], document["warnings"] = (list(found) for found in result.problems)
    return document


def write_json(result, path: str) -> None:
    with open(path, "w") as file:
        json.dump(json_document(result), file, indent=2)
        file.write("\n")
