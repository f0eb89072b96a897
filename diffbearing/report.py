"""Readable report and JSON of a run: SI values converted to display units only here."""

import json

import numpy as np

from .units import registry

_ANGULAR_SPEED_DISPLAY = ("rad/s", "rpm")


def to_display(value, unit: str, display: str):
    """Convert an SI value (scalar or array) from `unit` to the `display` unit."""
    if unit == display:
        return np.asarray(value)
    return np.asarray(registry().Quantity(np.asarray(value, dtype=float), unit).to(display).magnitude)


def _format_number(value) -> str:
    value = float(value)
    if value == 0 or 1e-3 <= abs(value) < 1e6:
        return f"{value:.4g}" if abs(value) >= 1e3 else f"{value:.5g}"
    return f"{value:.4e}"


def _format(value) -> str:
    array = np.asarray(value)
    if array.ndim == 0:
        return _format_number(array)
    return "[" + ", ".join(_format_number(v) for v in array.ravel()[:8]) + (", …]" if array.size > 8 else "]")


def _unit_label(display: str) -> str:
    return display.replace("**", "^").replace("um", "µm") if display else "-"


def _header(result) -> list[str]:
    scene, inputs = result.model.scene, result.model.inputs
    bearing, operating = inputs.bearing, inputs.operating
    force = to_display(operating.force, "N", "kN")
    moment = np.asarray(operating.moment)
    speeds = [to_display(s, *_ANGULAR_SPEED_DISPLAY) for s in (operating.inner_speed, operating.outer_speed)]
    return [
        scene.title,
        f"scene: {scene.source}",
        "",
        f"Bearing    {bearing.kind}, {bearing.ball_count} balls, Dw = {float(bearing.ball_diameter) * 1e3:.4f} mm, "
        f"dm = {float(bearing.pitch_diameter) * 1e3:.3f} mm, fi = {float(bearing.inner_groove_ratio):.4f}, "
        f"fo = {float(bearing.outer_groove_ratio):.4f}",
        f"Materials  rings {bearing.ring_material.name}, balls {bearing.ball_material.name}",
        f"Operating  inner ring {float(speeds[0]):.1f} r/min, outer ring {float(speeds[1]):.1f} r/min; "
        f"F = [{', '.join(f'{f:.3f}' for f in force)}] kN; M = [{', '.join(f'{m:.1f}' for m in moment)}] N·m",
    ]


def _displacement_lines(displacement) -> list[str]:
    d = np.asarray(displacement)
    return ["", "Inner-ring displacement (from the just-touching position at the free contact angle)",
            f"  δx = {d[0] * 1e6:.3f} µm, δy = {d[1] * 1e6:.3f} µm, δz = {d[2] * 1e6:.3f} µm, "
            f"θx = {d[3] * 1e3:.4f} mrad, θy = {d[4] * 1e3:.4f} mrad"]


def _stiffness_lines(matrix) -> list[str]:
    k = np.asarray(matrix)
    names = ["x", "y", "z", "θx", "θy"]
    lines = ["", "Stiffness K = dF/dΔ (balls re-equilibrated; rows F: N, M: N·m; columns δ: µm, θ: mrad)",
             "  " + " " * 6 + "".join(f"{'∂/∂' + n:>13}" for n in names)]
    scale = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # per µm and per mrad
    row_names = ["Fx", "Fy", "Fz", "Mx", "My"]
    for i in range(5):
        lines.append(f"  {row_names[i]:<6}" + "".join(f"{k[i, j] * scale[j]:>13.5g}" for j in range(5)))
    return lines


def _ball_table_lines(result, outputs) -> list[str]:
    keys = [key for key in outputs if key.startswith("balls.") and key in result.values]
    if not keys:
        return []
    short = {"balls.azimuth": "ψ", "balls.inner.load": "Qi", "balls.inner.contact_angle": "αi",
             "balls.inner.max_pressure": "p0i", "balls.outer.load": "Qo", "balls.outer.contact_angle": "αo",
             "balls.outer.max_pressure": "p0o", "balls.orbital_speed": "ωm", "balls.centrifugal_force": "Fc",
             "balls.gyroscopic_moment": "Mg"}
    shown = [key for key in short if key in keys]
    header = "".join(f"{short[k] + ' [' + _unit_label(outputs[k].display) + ']':>12}" for k in shown)
    lines = ["", "Balls (load distribution; semi-axes and spin speed in --json)", "   #" + header]
    columns = [to_display(result.values[k], outputs[k].unit, outputs[k].display) for k in shown]
    for j in range(len(columns[0])):
        lines.append(f"  {j:>2}" + "".join(f"{_format_number(c[j]):>12}" for c in columns))
    return lines


def format_report(result) -> str:
    """The text report of a run: header, aligned tables per output group, notes, timing."""
    lines = _header(result)
    outputs = result.model.outputs
    values = result.values
    sections: dict[str, dict[str, dict]] = {}
    for key, out in outputs.items():
        if key not in values or key.startswith("balls.") or key in ("displacement", "stiffness", "converged", "residual"):
            continue
        parts = key.split(".")
        if len(parts) == 3 and parts[1] in ("inner", "outer"):
            section, column, row = parts[0], parts[1], parts[2]
        else:
            section, column, row = parts[0], "value", ".".join(parts[1:])
        entry = sections.setdefault(section, {}).setdefault(row, {"out": out})
        entry[column] = values[key]
    for section, rows in sections.items():
        lines += ["", section.replace("_", " ").capitalize()]
        scalar_rows = [row for row in rows.values() if "value" in row]
        sided_rows = [row for row in rows.values() if "value" not in row]
        for row in scalar_rows:
            out = row["out"]
            cell = _format(to_display(row["value"], out.unit, out.display))
            lines.append(f"  {out.description:<48}{cell:>16}  {_unit_label(out.display)}")
        if sided_rows:
            lines.append(f"  {'':<48}{'inner':>16}{'outer':>16}")
            for row in sided_rows:
                out = row["out"]
                label = out.description.removesuffix(", inner")
                cells = [_format(to_display(row[c], out.unit, out.display)) if c in row else "" for c in ("inner", "outer")]
                lines.append(f"  {label:<48}" + "".join(f"{cell:>16}" for cell in cells) + f"  {_unit_label(out.display)}")
    if "displacement" in values:
        lines += _displacement_lines(values["displacement"])
    if "stiffness" in values:
        lines += _stiffness_lines(values["stiffness"])
    lines += _ball_table_lines(result, outputs)
    if "converged" in values:
        state = "converged" if bool(values["converged"]) else "DID NOT CONVERGE"
        lines += ["", f"Equilibrium solver: {state} (largest scaled residual {float(values['residual']):.1e})"]
    if result.model.not_implemented:
        lines += ["", "Not computed (effect not available yet): " + ", ".join(result.model.not_implemented)]
    lines += ["", f"compile {result.compile_s:.2f} s, run {result.run_s * 1e3:.2f} ms (after compilation)"]
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


def json_document(result) -> dict:
    """The JSON document of a run: SI values under the output keys (README, "JSON keys")."""
    flat = {key: np.asarray(value).tolist() for key, value in result.values.items()}
    flat["timing.compile_s"] = result.compile_s
    flat["timing.run_s"] = result.run_s
    document = {"title": result.model.scene.title, **nest(flat)}
    document["not_computed"] = list(result.model.not_implemented)
    return document


def write_json(result, path: str) -> None:
    with open(path, "w") as file:
        json.dump(json_document(result), file, indent=2)
        file.write("\n")
