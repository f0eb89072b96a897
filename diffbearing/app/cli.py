"""The `diffbearing` command.

    diffbearing examples
    diffbearing bearings [PATTERN]
    diffbearing run [SCENE] [--set dotted.key=VALUE ...] [--json FILE] [--plot FILE] [--report FILE.html]
                    [--distributed [--coordinator HOST:PORT --processes N --process-id I]]

SCENE is a scene file or the name of a packaged example (`diffbearing examples` lists them; the
default is the aero-engine angular-contact ball bearing).

With --distributed the run is one of several processes under `jax.distributed` (one per host; a
sweep splits its grid over them, docs/distributed_sweeps.md); without --coordinator JAX finds the
cluster itself (SLURM, Open MPI). Only process 0 prints the report and writes files.

Compiled models are kept in a persistent cache, so that running the same scene again starts in
seconds: by default in ~/.cache/diffbearing/jax; DIFFBEARING_CACHE names another folder, and
DIFFBEARING_CACHE=off switches the cache off.

Bad input (unknown key, wrong dimension, missing key, out-of-range value, an output file in a
folder that does not exist) prints one line naming the problem and exits with code 2, before any
computation. A result outside the model (e.g. a ball pushed through its raceway) or a solver that
did not converge prints the report, then one line naming the limit, and exits with code 3.
"""

import argparse
import sys
from pathlib import Path


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="diffbearing", description="Differentiable rolling-bearing model (JAX).")
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("examples", help="list the packaged example scenes")
    listing = commands.add_parser("bearings", help="list the designations whose boundary dimensions diffbearing knows")
    listing.add_argument("pattern", nargs="?", default="*", help="shell pattern of designations, e.g. '62*' (default: all)")
    run = commands.add_parser("run", help="run a scene file or a packaged example and print a report")
    run.add_argument("scene", nargs="?",
                     help="scene TOML file or example name (default: aero_angular_contact; see `diffbearing examples`)")
    run.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                     help='override a scene value, e.g. --set operating.inner_speed="3000 rpm"')
    run.add_argument("--json", metavar="FILE", help="write results (SI units) as JSON")
    run.add_argument("--plot", metavar="FILE", help="save the scene's plot (PNG, PDF, SVG)")
    run.add_argument("--report", metavar="FILE.html", help="write a self-contained HTML report to hand on (inputs, "
                     "results, checks, the figure, versions and this command)")
    run.add_argument("--distributed", action="store_true", help="one process of a jax.distributed run")
    run.add_argument("--coordinator", metavar="HOST:PORT", help="address of process 0 (with --distributed)")
    run.add_argument("--processes", type=int, metavar="N", help="number of processes (with --coordinator)")
    run.add_argument("--process-id", type=int, metavar="I", help="this process's index, 0…N−1 (with --coordinator)")
    return parser


def _check_output_files(arguments) -> None:
    """ValueError for an output file whose folder does not exist (before the computation)."""
    for option in ("json", "plot", "report"):
        path = getattr(arguments, option)
        if path is not None and not Path(path).resolve().parent.is_dir():
            raise ValueError(f"--{option} {path}: folder {str(Path(path).resolve().parent)!r} does not exist")


def _examples() -> int:
    from .scene import DEFAULT_EXAMPLE, examples

    listed = examples()
    width = max(len(name) for name in listed)
    for name, description in listed.items():
        marker = " (default)" if name == DEFAULT_EXAMPLE else ""
        print(f"{name:<{width}}  {description}{marker}")
    print("\nrun one: diffbearing run NAME")
    return 0


def _bearings(pattern: str) -> int:
    """Print the designations matching `pattern` with d × D × B [mm], r_s min and the source; exit 2 if none."""
    from ..catalog.designations import SOURCES, designations, series

    found = designations(pattern)
    if not found:
        print(f"diffbearing: error: no designation matches {pattern!r} (series {', '.join(sorted(series()))})",
              file=sys.stderr)
        return 2
    kind = max(len("type"), *(len(entry.bearing_type) for entry in found)) + 2
    print(f"{'designation':<12}{'type':<{kind}}{'d [mm]':>8}{'D [mm]':>8}{'B [mm]':>8}{'T [mm]':>8}{'r_s min [mm]':>14}"
          "  source (B: a thrust bearing's height H; T: a tapered bearing's total width)")
    for entry in found:
        chamfer, total = ("" if value is None else f"{value * 1e3:g}" for value in (entry.chamfer, entry.total_width))
        print(f"{entry.designation:<12}{entry.bearing_type:<{kind}}{entry.bore * 1e3:>8g}"
              f"{entry.outside_diameter * 1e3:>8g}{entry.width * 1e3:>8g}{total:>8}{chamfer:>14}  {entry.source}")
    print(f"\n{len(found)} bearings; in a scene: bearing.designation = \"{found[0].designation}\" sets bore, outer_diameter "
          "and width")
    print("Sources: " + "; ".join(text for name, text in SOURCES.items() if any(name in entry.source for entry in found)))
    return 0


def main(argv=None) -> int:
    arguments = _parser().parse_args(argv)
    if arguments.command == "examples":
        return _examples()
    if arguments.command == "bearings":
        return _bearings(arguments.pattern)
    try:
        _check_output_files(arguments)
    except ValueError as error:
        print(f"diffbearing: error: {error}", file=sys.stderr)
        return 2
    import jax

    jax.config.update("jax_enable_x64", True)
    if arguments.distributed:
        jax.config.update("jax_cpu_collectives_implementation", "gloo")  # CPU processes gather through gloo
        jax.distributed.initialize(arguments.coordinator, arguments.processes, arguments.process_id)
    writes = jax.process_index() == 0
    from .model import build_model, run_model
    from .report import format_report, write_json
    from .scene import load_scene

    try:
        model = build_model(load_scene(arguments.scene, arguments.overrides))
    except ValueError as error:
        print(f"diffbearing: error: {error}", file=sys.stderr)
        return 2
    result = run_model(model, progress=writes)
    if not writes:
        return 0
    print(format_report(result))
    if arguments.json:
        write_json(result, arguments.json)
        print(f"\nJSON written to {arguments.json}")
    if arguments.plot:
        from .plots import save_plot

        try:
            save_plot(result, arguments.plot)
        except ValueError as error:
            print(f"diffbearing: error: {error}", file=sys.stderr)
            return 2
        print(f"plot written to {arguments.plot}")
    if arguments.report:
        from .html_report import write_html

        write_html(result, arguments.report, " ".join(["diffbearing", *(sys.argv[1:] if argv is None else argv)]))
        print(f"report written to {arguments.report}")
    errors, _ = result.problems
    if errors:
        more = f" (and {len(errors) - 1} more)" if len(errors) > 1 else ""
        print(f"diffbearing: error: {errors[0]}{more}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
