"""The `diffbearing` command.

    diffbearing run [SCENE] [--set dotted.key=VALUE ...] [--json FILE] [--plot FILE]
                    [--distributed [--coordinator HOST:PORT --processes N --process-id I]]

With --distributed the run is one of several processes under `jax.distributed` (one per host; a
sweep splits its grid over them, docs/distributed_sweeps.md); without --coordinator JAX finds the
cluster itself (SLURM, Open MPI). Only process 0 prints the report and writes files.

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
    run.add_argument("--distributed", action="store_true", help="one process of a jax.distributed run")
    run.add_argument("--coordinator", metavar="HOST:PORT", help="address of process 0 (with --distributed)")
    run.add_argument("--processes", type=int, metavar="N", help="number of processes (with --coordinator)")
    run.add_argument("--process-id", type=int, metavar="I", help="this process's index, 0…N−1 (with --coordinator)")
    return parser


def main(argv=None) -> int:
    arguments = _parser().parse_args(argv)
    import os

    import jax

    jax.config.update("jax_enable_x64", True)
    # compiled models persist between runs (a second run of the same scene skips compilation)
    cache = os.environ.get("JAX_COMPILATION_CACHE_DIR", os.path.join(os.path.expanduser("~"), ".cache", "diffbearing"))
    jax.config.update("jax_compilation_cache_dir", cache)
    if arguments.distributed:
        jax.config.update("jax_cpu_collectives_implementation", "gloo")  # CPU processes gather through gloo
        jax.distributed.initialize(arguments.coordinator, arguments.processes, arguments.process_id)
    writes = jax.process_index() == 0
    from .report import format_report, write_json
    from .scene import build_model, load_scene, run_model

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
    errors, _ = result.problems
    if errors:
        more = f" (and {len(errors) - 1} more)" if len(errors) > 1 else ""
        print(f"diffbearing: error: {errors[0]}{more}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main())
