"""Display of SI values: unit conversion (pint) and number formatting for reports and plots."""

import numpy as np

from .units import SI_UNITS, registry

# display units of swept keys, by schema dimension
SWEEP_DISPLAY = {"length": "mm", "angular_speed": "rpm", "force": "kN", "moment": "N*m", "angle": "deg",
                 "pressure": "GPa"}


def to_display(value, unit: str, display: str):
    """Convert an SI value (scalar or array) from `unit` to the `display` unit."""
    if unit == display or not display:
        return np.asarray(value)
    return np.asarray(registry().Quantity(np.asarray(value, dtype=float), unit).to(display).magnitude)


def swept_display(values, dimension: str) -> tuple[np.ndarray, str]:
    """(swept SI values in the display unit of their dimension, that unit; "" where there is none)."""
    display = SWEEP_DISPLAY.get(dimension, "")
    return (to_display(values, SI_UNITS[dimension], display) if display else np.asarray(values)), display


def format_number(value) -> str:
    value = float(value)
    if value == 0 or 1e-3 <= abs(value) < 1e3:
        return f"{value:.5g}"
    if 1e3 <= abs(value) < 1e6:
        return f"{value:.1f}" if abs(value) < 1e4 else f"{value:.0f}"
    return f"{value:.4e}"


def format_value(value) -> str:
    array = np.asarray(value)
    if array.ndim == 0:
        return format_number(array)
    return "[" + ", ".join(format_number(v) for v in array.ravel()[:8]) + (", …]" if array.size > 8 else "]")


def unit_label(display: str) -> str:
    return display.replace("**", "^").replace("um", "µm").replace("percent", "%") if display else "-"


def column(name: str, values, scale: float = 1.0) -> tuple[str, list[str]]:
    """A sweep-report column: (header, one formatted cell per point)."""
    return name, [format_number(value * scale) for value in values]


def state_column(name: str, flags, ok: str = "converged") -> tuple[str, list[str]]:
    """A sweep-report column of yes/no flags ("NO" where false)."""
    return name, [ok if flag else "NO" for flag in flags]
