"""Display of SI values: unit conversion (pint) and number formatting for reports and plots."""

import numpy as np

from .units import SI_UNITS, registry

# display units of swept keys, by schema dimension
SWEEP_DISPLAY = {"length": "mm", "angular_speed": "rpm", "force": "kN", "moment": "N*m", "angle": "deg",
                 "pressure": "GPa", "temperature": "degC", "volume_flow": "l/min"}


def to_display(value, unit: str, display: str):
    """Convert an SI value (scalar or array) from `unit` to the `display` unit."""
    if unit == display or not display:
        return np.asarray(value)
    return np.asarray(registry().Quantity(np.asarray(value, dtype=float), unit).to(display).magnitude)


def swept_display(values, dimension: str) -> tuple[np.ndarray, str]:
    """(swept SI values in the display unit of their dimension (its SI unit where `SWEEP_DISPLAY` names
    none), that unit; "" for a dimensionless one)."""
    display = SWEEP_DISPLAY.get(dimension, SI_UNITS[dimension])
    return (to_display(values, SI_UNITS[dimension], display) if display else np.asarray(values)), display


def format_number(value) -> str:
    value = float(value)
    if value == 0 or 1e-3 <= abs(value) < 1e3:
        return f"{value:.5g}"
    if 1e3 <= abs(value) < 1e6:
        return f"{value:.1f}" if abs(value) < 1e4 else f"{value:.0f}"
    return f"{value:.4e}"


def format_value(value, most: int | None = 8) -> str:
    """A number, or an array as "[a, b, …]" of its first `most` elements (None: all)."""
    array = np.asarray(value)
    if array.ndim == 0:
        return format_number(array)
    flat = array.ravel() if most is None else array.ravel()[:most]
    return "[" + ", ".join(format_number(v) for v in flat) + (", …]" if flat.size < array.size else "]")


def unit_label(display: str) -> str:
    return display.replace("**", "^").replace("um", "µm").replace("percent", "%") if display else "-"


def column(name: str, values, scale: float = 1.0) -> tuple[str, list[str]]:
    """A sweep-report column: (header, one formatted cell per point)."""
    return name, [format_number(value * scale) for value in values]


def state_column(name: str, flags, ok: str = "converged") -> tuple[str, list[str]]:
    """A sweep-report column of yes/no flags ("NO" where false)."""
    return name, [ok if flag else "NO" for flag in flags]


ROUND_OFF = 1e-9  # relative size below which a stiffness coupling is shown as 0


def stiffness_lines(matrix, elements: str) -> list[str]:
    """Report lines of a 5×5 stiffness K = dF/dΔ [N/m, N/rad; N·m/m, N·m/rad] in N/µm and N·m/mrad;
    `elements` names what was re-equilibrated ("balls", "rollers"). A coupling below 1e-9 of its
    diagonals' geometric mean √|K_ii K_jj| (the same units) is rounding noise and shows as 0."""
    k = np.asarray(matrix)
    diagonal = np.sqrt(np.abs(np.outer(np.diag(k), np.diag(k))))
    k = np.where(np.abs(k) < ROUND_OFF * diagonal, 0.0, k)
    names = ["x", "y", "z", "θx", "θy"]
    lines = ["", f"Stiffness K = dF/dΔ ({elements} re-equilibrated; rows F: N, M: N·m; columns δ: µm, θ: mrad)",
             "  " + " " * 6 + "".join(f"{'∂/∂' + n:>13}" for n in names)]
    scale = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # per µm and per mrad
    row_names = ["Fx", "Fy", "Fz", "Mx", "My"]
    for i in range(5):
        lines.append(f"  {row_names[i]:<6}" + "".join(f"{k[i, j] * scale[j]:>13.5g}" for j in range(5)))
    return lines


def element_table_lines(result, title: str) -> list[str]:
    """A table with one row per rolling element (ball or roller): the run's outputs that declare a
    `column`, in their display units; – for NaN (a quantity that does not exist for that element)."""
    outputs, values = result.model.outputs, result.values
    shown = [key for key, out in outputs.items() if out.column and key in values]
    header = "".join(f"{outputs[k].column + ' [' + unit_label(outputs[k].display) + ']':>12}" for k in shown)
    lines = ["", title, "   #" + header]
    columns = [to_display(values[k], outputs[k].unit, outputs[k].display) for k in shown]
    # rounding noise (a roller's tilt of 1e-18 mrad where it is zero by symmetry) shown as 0
    columns = [np.where(np.abs(c) < 1e-9, 0.0, c) for c in columns]
    for j in range(len(columns[0])):
        lines.append(f"  {j:>2}" + "".join(f"{'–' if np.isnan(c[j]) else format_number(c[j]):>12}" for c in columns))
    return lines
