"""The `diffbearing` command.

    diffbearing run [SCENE] [--set dotted.key=VALUE ...] [--json FILE] [--plot FILE]

Bad input (unknown key, wrong dimension, missing key, out-of-range value) prints one line
naming the key and exits with code 2. A result outside the model (e.g. a ball pushed through its
raceway) or a solver that did not converge prints the report, then one line naming the limit, and
exits with code 3.
"""

import argparse
import sys


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="diffbearing", description="Differentiable rolling-bearing model (JAX).")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="run a scene file and print a report")
    run.add_argument("scene", nargs="?", help="scene TOML file (default: the built-in seed 001 example)")
    run.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                     help='override a scene value, e.g. --set operating.inner_speed="3000 rpm"')
    run.add_argument("--json", metavar="FILE", help="write results (SI units) as JSON")
    run.add_argument("--plot", metavar="FILE", help="save the scene's plot (PNG, PDF, SVG)")
    return parser


def main(argv=None) -> int:
    arguments = _parser().parse_args(argv)
    import os

    import jax

    jax.config.update("jax_enable_x64", True)
    # compiled models persist between runs (a second run of the same scene skips compilation)
    cache = os.environ.get("JAX_COMPILATION_CACHE_DIR", os.path.join(os.path.expanduser("~"), ".cache", "diffbearing"))
    jax.config.update("jax_compilation_cache_dir", cache)
    from .report import format_report, write_json
    from .scene import build_model, load_scene, run_model

    try:
        model = build_model(load_scene(arguments.scene, arguments.overrides))
    except ValueError as error:
        print(f"diffbearing: error: {error}", file=sys.stderr)
        return 2
    result = run_model(model)
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
    errors, _ = result.problems
    if errors:
        more = f" (and {len(errors) - 1} more)" if len(errors) > 1 else ""
        print(f"diffbearing: error: {errors[0]}{more}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
