"""Readable report and JSON of a run: SI values converted to display units only here."""

import json

import numpy as np

from .ball_equilibrium import RESIDUAL_TOLERANCE
from .units import registry

_ANGULAR_SPEED_DISPLAY = ("rad/s", "rpm")


def to_display(value, unit: str, display: str):
    """Convert an SI value (scalar or array) from `unit` to the `display` unit."""
    if unit == display or not display:
        return np.asarray(value)
    return np.asarray(registry().Quantity(np.asarray(value, dtype=float), unit).to(display).magnitude)


def _format_number(value) -> str:
    value = float(value)
    if value == 0 or 1e-3 <= abs(value) < 1e3:
        return f"{value:.5g}"
    if 1e3 <= abs(value) < 1e6:
        return f"{value:.1f}" if abs(value) < 1e4 else f"{value:.0f}"
    return f"{value:.4e}"


def _format(value) -> str:
    array = np.asarray(value)
    if array.ndim == 0:
        return _format_number(array)
    return "[" + ", ".join(_format_number(v) for v in array.ravel()[:8]) + (", …]" if array.size > 8 else "]")


def _unit_label(display: str) -> str:
    return display.replace("**", "^").replace("um", "µm").replace("percent", "%") if display else "-"


def _roller_header(result) -> list[str]:
    from .roller_profile import profile_parameters

    scene, bearing, loading = result.model.scene, result.model.inputs.bearing, result.model.inputs.operating
    if bearing.kind == "tapered_roller":
        shape = (f"d = {float(bearing.small_diameter) * 1e3:.4g} mm to D = {float(bearing.large_diameter) * 1e3:.4g} mm, "
                 f"θ = {np.degrees(float(bearing.cone_half_angle)):.3g}°")
    else:
        shape = f"D = {float(bearing.small_diameter) * 1e3:.4g} mm"
    curvature = float(loading.raceway_curvature)
    raceway = ("flat raceway" if curvature == 0 else
               f"{'convex' if curvature > 0 else 'concave'} raceway, R = {abs(1 / curvature) * 1e3:.4g} mm at mid-length")
    units = {"flat_length": (1e3, "mm"), "crown_radius": (1e3, "mm"), "design_load": (1e-3, "kN"), "zm": (1e6, "µm"),
             "k1": (1, ""), "k2": (1, "")}
    parameters = ", ".join(f"{name} = {value * units[name][0]:.4g} {units[name][1]}".rstrip()
                           for name, value in profile_parameters(bearing.profile).items())
    material = bearing.material
    return [
        scene.title,
        f"scene: {scene.source}",
        "",
        f"Roller     {bearing.kind}, {shape}, effective length l = {float(bearing.length) * 1e3:.4g} mm",
        f"Profile    {bearing.profile.kind}" + (f" ({parameters})" if parameters else ""),
        f"Material   E = {float(material.elastic_modulus) / 1e9:.4g} GPa, ν = {float(material.poisson_ratio):.3g} "
        "(roller and raceway)",
        f"Contact    Q = {float(loading.load) / 1e3:.4g} kN, tilt {np.degrees(float(loading.tilt)) * 60:.4g} arcmin, {raceway}",
    ]


def _roller_pressure_lines(result) -> list[str]:
    if "contact.pressure" not in result.values:
        return []
    pressure, y = np.asarray(result.values["contact.pressure"]), np.asarray(result.values["contact.y"])
    along = pressure.max(axis=0)
    stations = np.unique(np.linspace(0, len(y) - 1, 9).round().astype(int))
    lines = ["", "Peak pressure across the contact along the roller (max over x; full map in --json / --plot)",
             "  y [mm]     " + "".join(f"{y[i] * 1e3:>9.3f}" for i in stations),
             "  p [GPa]    " + "".join(f"{along[i] / 1e9:>9.4f}" for i in stations)]
    nx, ny = pressure.shape
    lines.append(f"  grid {nx} × {ny} cells of {float(np.diff(result.values['contact.x'][:2])[0]) * 1e6:.3g} µm × "
                 f"{float(np.diff(y[:2])[0]) * 1e6:.3g} µm")
    if result.model.inputs.bearing.profile.kind == "straight" and "roller_contact_influence" in [
            b.name for b in result.model.blocks]:
        lines.append("  straight roller: the edge peak grows as the cells shrink (an edge singularity); "
                     "it is grid dependent, not a converged value")
    if "contact.converged" in result.values:
        converged = bool(result.values["contact.converged"])
        if "roller_contact_slices" in [b.name for b in result.model.blocks]:
            lines.append("  Hertz line-contact slices (Palmgren laminae, no interaction between slices): "
                         + ("approach converged" if converged else "approach DID NOT CONVERGE"))
        else:
            state = "converged" if converged else "DID NOT CONVERGE (or reached the grid edge)"
            lines.append(f"  influence coefficients (DC-FFT, Polonsky–Keer): {state}, "
                         f"{int(result.values['contact.iterations'])} iterations")
    return lines


def _header(result) -> list[str]:
    scene, inputs = result.model.scene, result.model.inputs
    if scene.bearing_type in ("cylindrical_roller", "tapered_roller"):
        return _roller_header(result)
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
    if not any(key.startswith("balls.") for key in result.values):
        return []
    keys = [key for key in outputs if key.startswith(("balls.", "film.")) and key in result.values]
    short = {"balls.azimuth": "ψ", "balls.inner.load": "Qi", "balls.inner.contact_angle": "αi",
             "balls.inner.max_pressure": "p0i", "balls.outer.load": "Qo", "balls.outer.contact_angle": "αo",
             "balls.outer.max_pressure": "p0o", "balls.orbital_speed": "ωm", "balls.centrifugal_force": "Fc",
             "balls.gyroscopic_moment": "Mg", "film.inner.central": "hc,i", "film.inner.minimum": "hmin,i",
             "film.outer.central": "hc,o", "film.outer.minimum": "hmin,o", "film.inner.film_parameter": "Λi",
             "film.outer.film_parameter": "Λo"}
    shown = [key for key in short if key in keys]
    header = "".join(f"{short[k] + ' [' + _unit_label(outputs[k].display) + ']':>12}" for k in shown)
    lines = ["", "Balls (load distribution; semi-axes and spin speed in --json; – where a ball carries no load)",
             "   #" + header]
    columns = [to_display(result.values[k], outputs[k].unit, outputs[k].display) for k in shown]
    for j in range(len(columns[0])):
        lines.append(f"  {j:>2}" + "".join(f"{'–' if np.isnan(c[j]) else _format_number(c[j]):>12}" for c in columns))
    return lines


# display units of swept keys, by schema dimension
SWEEP_DISPLAY = {"length": "mm", "angular_speed": "rpm", "force": "kN", "moment": "N*m", "angle": "deg",
                 "pressure": "GPa"}
SI_OF_DIMENSION = {"length": "m", "angular_speed": "rad/s", "force": "N", "moment": "N*m", "angle": "rad",
                   "pressure": "Pa"}


def _swept_cells(key, values) -> tuple[str, list[str]]:
    from .schema import lookup

    dimension = lookup(key).dimension
    display = SWEEP_DISPLAY.get(dimension)
    shown = to_display(values, SI_OF_DIMENSION[dimension], display) if display else np.asarray(values)
    cells = [("[" + ", ".join(_format_number(x) for x in np.ravel(v)) + "]") if np.ndim(v) else _format_number(v)
             for v in shown]
    return f"{key} [{_unit_label(display or '')}]", cells


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
    batch = ("mapped point by point (iterative EHL solver)" if any(b.sequential_sweep for b in result.model.blocks)
             else "one vmapped batch")
    lines += ["", f"Sweep over {grid}{int(np.prod(shape))} points ({', '.join(axes)}), {batch}"]
    grids = np.meshgrid(*[np.arange(n) for n in shape], indexing="ij")
    flat_index = [g.ravel() for g in grids]
    columns = []
    for k, (key, values) in enumerate(axes.items()):
        header, cells = _swept_cells(key, values)
        columns.append((header, [cells[i] for i in flat_index[k]]))
    values = {key: np.reshape(value, (-1,) + np.shape(value)[len(shape):]) for key, value in result.values.items()}
    if "converged" in values:
        columns.append(("converged", ["yes" if c else "NO" for c in values["converged"]]))
    if "stiffness" in values:
        for i, name in enumerate(("Kxx", "Kyy", "Kzz")):
            columns.append((f"{name} [N/µm]", [_format_number(k[i, i] * 1e-6) for k in values["stiffness"]]))
    if "displacement" in values:
        columns.append(("δz [µm]", [_format_number(d[2] * 1e6) for d in values["displacement"]]))
    if "balls.inner.max_pressure" in values:
        columns.append(("max p0i [GPa]", [_format_number(p.max() / 1e9) for p in values["balls.inner.max_pressure"]]))
    if "contact.max_pressure" in values:
        columns.append(("p_max [GPa]", [_format_number(p / 1e9) for p in values["contact.max_pressure"]]))
        columns.append(("δ [µm]", [_format_number(d * 1e6) for d in values["contact.approach"]]))
        columns.append(("contact", ["converged" if c else "NO" for c in values["contact.converged"]]))
    for prefix, name in (("film", "film"), ("starvation", "starved")):
        if f"{prefix}.central" in values and np.ndim(values[f"{prefix}.central"]) == 1:  # roller contacts
            columns.append((f"{name} h_c [µm]", [_format_number(h * 1e6) for h in values[f"{prefix}.central"]]))
            columns.append((f"{name} h_min [µm]", [_format_number(h * 1e6) for h in values[f"{prefix}.minimum"]]))
            if f"{prefix}.converged" in values:
                columns.append((name, ["converged" if c else "NO" for c in values[f"{prefix}.converged"]]))
    if "life.L10r" in values:
        columns.append(("L10r [1e6 rev]", [_format_number(x) for x in values["life.L10r"]]))
    widths = [max(len(h), *(len(c) for c in cells)) + 2 for h, cells in columns]
    lines.append("  " + "".join(f"{h:>{w}}" for (h, _), w in zip(columns, widths)))
    rows = len(columns[0][1])
    shown = list(range(rows)) if rows <= 40 else list(range(20)) + [None] + list(range(rows - 20, rows))
    for row in shown:
        if row is None:
            lines.append(f"  … {rows - 40} more rows in --json …")
            continue
        lines.append("  " + "".join(f"{cells[row]:>{w}}" for (_, cells), w in zip(columns, widths)))
    if "converged" in values and not np.all(values["converged"]):
        lines.append(f"  {int(np.sum(~values['converged'].astype(bool)))} points DID NOT CONVERGE")
    lines += _problem_lines(result, most=10)
    lines += ["", f"compile {result.compile_s:.2f} s, run {result.run_s:.3f} s for {rows} points "
              f"({result.run_s / rows * 1e3:.2f} ms per point, after compilation)"]
    return "\n".join(lines)


def format_report(result) -> str:
    """The text report of a run: header, aligned tables per output group, notes, timing."""
    if result.sweep_axes:
        return format_sweep_report(result)
    lines = _header(result)
    outputs = result.model.outputs
    values = result.values
    sections: dict[str, dict[str, dict]] = {}
    for key, out in outputs.items():
        per_ball = key.startswith("balls.") or (key.startswith("film.") and "balls.azimuth" in values)
        if key not in values or per_ball or not out.in_report or key in (
                "displacement", "force", "stiffness", "converged", "residual", "contact.converged", "contact.iterations",
                "film.converged", "starvation.converged"):
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
    lines += _roller_pressure_lines(result)
    if "film.y" in values:  # the finite line level
        level, grid = "finite line EHL", f"{len(values['film.x'])} × {len(values['film.y'])} half-domain grid"
        meniscus = "a meniscus per y cell by mass balance"
    else:
        level, grid, meniscus = "line EHL", f"{len(values.get('film.x', ()))} nodes", "meniscus by flux balance"
    for key, solve in (("film.converged", f"Newton, {grid}, fully flooded"),
                       ("starvation.converged", f"starved by the oil layer, {meniscus}")):
        if key in values:
            state = "converged" if bool(values[key]) else "DID NOT CONVERGE (values are the last iterate)"
            lines.append(f"  {level} ({solve}): {state}")
    if "force" in values and result.model.inputs.operating.axial_displacement is not None:
        lines.append(f"  axial preload force at the prescribed δz: Fz = {float(values['force'][2]) / 1e3:.4f} kN")
    if "stiffness" in values:
        lines += _stiffness_lines(values["stiffness"])
    lines += _ball_table_lines(result, outputs)
    if "converged" in values:
        state = ("converged" if bool(values["converged"]) else "DID NOT CONVERGE"
                 if float(values["residual"]) >= RESIDUAL_TOLERANCE else "converged to a state OUTSIDE THE MODEL")
        lines += ["", f"Equilibrium solver: {state} (largest scaled residual {float(values['residual']):.1e})"]
    lines += _problem_lines(result)
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
    document["not_computed"] = list(result.model.not_implemented)
    document["errors"], document["warnings"] = (list(found) for found in result.problems)
    return document


def write_json(result, path: str) -> None:
    with open(path, "w") as file:
        json.dump(json_document(result), file, indent=2)
        file.write("\n")
