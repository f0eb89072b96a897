"""The report to hand on: one self-contained HTML file of a run (`diffbearing run ... --report
FILE.html`): the scene's inputs with their units, the results (every scalar output with its unit,
the text report as printed), the errors and warnings of the envelope checks, the figure as an
embedded PNG, the diffbearing and JAX versions, the command and the time. No external files,
scripts or fonts: it opens offline, reads on a phone (the tables scroll sideways) and prints."""

import base64
import datetime
import html
import io
import platform
from importlib.metadata import version

import jax
import numpy as np

from .duty_cycle import describe
from .formatting import format_value, swept_display, to_display, unit_label
from .report import format_report
from .scene import derived_values
from .schema import lookup

STYLE = """
body { font-family: system-ui, sans-serif; margin: 0 auto; max-width: 70rem; padding: 0.8rem; color: #111; }
h1 { font-size: 1.35rem; } h2 { font-size: 1.1rem; border-bottom: 1px solid #bbb; margin-top: 1.6rem; }
.scroll { overflow-x: auto; }
table { border-collapse: collapse; font-size: 0.9rem; }
td, th { border: 1px solid #ccc; padding: 0.2rem 0.45rem; text-align: left; vertical-align: top; }
td.number { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
pre { font-size: 0.78rem; background: #f6f6f6; padding: 0.6rem; overflow-x: auto; }
.error { color: #a00; font-weight: bold; } .warning { color: #8a5a00; }
img { max-width: 100%; height: auto; }
@media print { .scroll, pre { overflow: visible; white-space: pre-wrap; } body { max-width: none; } }
"""


def _input_rows(scene) -> list[tuple[str, str, str, str]]:
    """(key, value, unit, from) of each scene input, in its display unit; tables of entries
    ([[bearings]], [[loads]]) as their entries' SI values, then a row for each value of an entry the
    scene did not write; "from" the source of a value the scene did not write itself
    (`Scene.derived`), else "scene"."""
    rows = []
    for key, value in scene.values.items():
        source = scene.derived.get(key, "scene")
        try:
            dimension = lookup(key).dimension
        except ValueError:
            dimension = "dimensionless"
        if isinstance(value, (str, bool)) or value is None:
            rows.append((key, str(value), "", source))
            continue
        if isinstance(value, list) and value and isinstance(value[0], dict):
            rows.append((key, "; ".join(str(entry) for entry in value), "SI", source))
            continue
        shown, display = swept_display(np.asarray(value, float), dimension)
        rows.append((key, format_value(shown, most=None), unit_label(display) if display else "", source))
    for key, value, schema_key in derived_values(scene):  # a [[bearings]] entry's, within its table above
        if key not in scene.values:
            shown, display = swept_display(np.asarray(value, float), lookup(schema_key).dimension)
            rows.append((key, format_value(shown, most=None), unit_label(display) if display else "", scene.derived[key]))
    return rows


def _output_rows(result) -> list[tuple[str, str, str, str]]:
    """(key, description, value, unit) of each output with a value, in its display unit; arrays as lists
    (the first 12 elements)."""
    rows = []
    for key, out in result.model.outputs.items():
        if key not in result.values:
            continue
        shown = np.asarray(to_display(result.values[key], out.unit, out.display))
        if shown.dtype.kind not in "fiub":
            continue
        rows.append((key, out.description, format_value(shown, most=12), unit_label(out.display)))
    for key in sorted(key for key in result.values if key.startswith("duty.")):  # the cycle's values
        description, unit, display = describe(key, result.model.outputs)
        value = to_display(result.values[key], unit, display)
        rows.append((key, description, format_value(value, most=None), unit_label(display)))
    return rows


def _table(header: tuple[str, ...], rows, numeric_column: int | None = None) -> str:
    head = "".join(f"<th>{html.escape(name)}</th>" for name in header)
    number = ' class="number"'

    def cell(index, value):
        return f"<td{number if index == numeric_column else ''}>{html.escape(str(value))}</td>"

    body = "".join("<tr>" + "".join(cell(index, value) for index, value in enumerate(row)) + "</tr>" for row in rows)
    return f'<div class="scroll"><table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>'


def _figure(result) -> str:
    """The run's figure as an embedded PNG, or "" where it has none."""
    from .plots import has_plot, save_plot

    if not has_plot(result):
        return ""
    buffer = io.BytesIO()
    save_plot(result, buffer)
    encoded = base64.b64encode(buffer.getvalue()).decode("ascii")
    return f'<h2>Figure</h2><img alt="the run\'s figure" src="data:image/png;base64,{encoded}">'


def html_document(result, command: str) -> str:
    """The self-contained HTML report of a run (module docstring); `command` the command line that ran it."""
    scene = result.model.scene
    errors, warnings = result.problems
    checks = "".join(f'<li class="error">{html.escape(line)}</li>' for line in errors)
    checks += "".join(f'<li class="warning">{html.escape(line)}</li>' for line in warnings)
    clean = "<p>No errors, no warnings: every input and solved state within the model's envelope.</p>"
    checks = f"<ul>{checks}</ul>" if checks else clean
    when = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    return "\n".join([
        "<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(scene.title)} — diffbearing</title>", f"<style>{STYLE}</style>", "</head>", "<body>",
        f"<h1>{html.escape(scene.title)}</h1>",
        f"<p>Scene: {html.escape(scene.source)}<br>Command: <code>{html.escape(command)}</code><br>"
        f"diffbearing {html.escape(version('diffbearing'))}, JAX {html.escape(jax.__version__)}, "
        f"Python {platform.python_version()}, {when}<br>"
        f"Compile {result.compile_s:.2f} s, run {result.run_s:.4f} s (after compilation).</p>",
        "<h2>Errors and warnings (envelope checks)</h2>", checks,
        "<h2>Inputs</h2>", _table(("key", "value", "unit", "from"), _input_rows(scene),
                                  numeric_column=1),
        "<h2>Results</h2>", _table(("key", "quantity", "value", "unit"), _output_rows(result), numeric_column=2),
        _figure(result),
        "<h2>Report as printed</h2>", f"<pre>{html.escape(format_report(result))}</pre>",
        "</body>", "</html>"])


def write_html(result, path: str, command: str) -> None:
    with open(path, "w", encoding="utf-8") as file:
        file.write(html_document(result, command))
