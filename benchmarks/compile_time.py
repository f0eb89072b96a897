"""Compile time: what the first answer costs, per packaged example and for the README's gradient.

    python benchmarks/compile_time.py [--examples NAME ...] [--films]

With --examples, the named examples' rows (and the gradient's) are measured and the others kept
from the last table written.

For every packaged example (the 2-D EHL example `starved_roller` only with `--films`: minutes of
compiling and running its numerical films), each in fresh processes:

  * the CLI cold and warm: `diffbearing run NAME` with an empty compilation cache folder
    (`DIFFBEARING_CACHE`), then again with the cache it left (wall time of the whole command,
    interpreter start and imports included; the program's own compile and run time as the JSON
    reports them);
  * the model's one program (`jax.jit(model.function())`, all blocks as one program, as a sweep
    compiles them; the CLI compiles the numerical films apart) traced, lowered and compiled without
    a cache: trace and lower time, StableHLO lines, XLA compile time with XLA's defaults and with
    the single run's quick settings (`registry.QUICK_COMPILE`), and the run time under each.

The README's gradient (`jax.grad` of K_zz of the default scene through `model.function()`) is
measured the same way in a fresh process. Writes benchmarks/results/compile_time.md.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
FILMS = ("starved_roller",)

# Run in a fresh interpreter: trace, lower and compile one program both ways, run each (median of 5).
PROGRAM = r"""
import json, statistics, sys, time
import jax
jax.config.update("jax_enable_x64", True)
from diffbearing import build_model, load_scene
from diffbearing.app.registry import QUICK_COMPILE
name, gradient = sys.argv[1], sys.argv[2] == "gradient"
model = build_model(load_scene(name))
function = model.function()
if gradient:
    function = jax.grad(lambda inputs, f=model.function(): f(inputs)["stiffness"][2, 2])
start = time.perf_counter(); traced = jax.jit(function).trace(model.inputs); traced_at = time.perf_counter()
lowered = traced.lower(); lowered_at = time.perf_counter()
out = {"trace_s": traced_at - start, "lower_s": lowered_at - traced_at, "lines": lowered.as_text().count("\n")}
for label, options in (("default", None), ("quick", QUICK_COMPILE)):
    start = time.perf_counter(); executable = lowered.compile(options); out[f"compile_{label}_s"] = time.perf_counter() - start
    times = []
    for _ in range(5):
        start = time.perf_counter(); jax.block_until_ready(executable(model.inputs)); times.append(time.perf_counter() - start)
    out[f"run_{label}_s"] = statistics.median(times)
print(json.dumps(out))
"""


# Run in a fresh interpreter: the program's StableHLO lines with the model's first k blocks, k = 1 … n
# (a block's share: the lines it adds to those before it, which it reads).
BLOCKS = r"""
import json, sys
import jax
jax.config.update("jax_enable_x64", True)
from diffbearing import build_model, load_scene
from diffbearing.app.registry import evaluate
model = build_model(load_scene(sys.argv[1]))
shares, before = [], 0
for k in range(1, len(model.blocks) + 1):
    lines = jax.jit(evaluate(model.blocks[:k], model.settings)).trace(model.inputs).lower().as_text().count("\n")
    shares.append([model.blocks[k - 1].name, lines - before])
    before = lines
print(json.dumps(shares))
"""


def _without_jax_cache(**settings) -> dict:
    """This process's environment without a JAX cache folder of the caller's, with `settings`."""
    return {key: value for key, value in os.environ.items() if key != "JAX_COMPILATION_CACHE_DIR"} | settings


def cli_run(name: str, cache: str) -> tuple[float, dict]:
    """(wall time [s], the JSON's timing) of `diffbearing run NAME` with the cache folder `cache`."""
    with tempfile.TemporaryDirectory() as folder:
        output = Path(folder) / "out.json"
        start = time.perf_counter()
        done = subprocess.run([sys.executable, "-m", "diffbearing.app.cli", "run", name, "--json", str(output)],
                              env=_without_jax_cache(DIFFBEARING_CACHE=cache), capture_output=True, text=True)
        wall = time.perf_counter() - start
        if done.returncode not in (0, 3):
            raise RuntimeError(f"{name}: exit {done.returncode}: {done.stderr[-500:]}")
        return wall, json.loads(output.read_text())["timing"]


def program(name: str, gradient: bool = False) -> dict:
    """The one program's trace, lower, compile and run times and HLO lines (fresh process, no cache)."""
    done = subprocess.run([sys.executable, "-c", PROGRAM, name, "gradient" if gradient else "value"],
                          env=_without_jax_cache(JAX_ENABLE_COMPILATION_CACHE="false"), capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{name}: {done.stderr[-800:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def block_shares(name: str) -> list:
    """[block, StableHLO lines it adds] of the example's program, block by block (fresh process)."""
    done = subprocess.run([sys.executable, "-c", BLOCKS, name], env=_without_jax_cache(), capture_output=True,
                          text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{name}: {done.stderr[-800:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def _table_rows() -> list[str]:
    """The example rows of the last written table (the gradient's row left out)."""
    path = RESULTS / "compile_time.md"
    if not path.is_file():
        return []
    examples_part = path.read_text().split("block by block")[0]  # not the block table's rows
    return [line for line in examples_part.splitlines()
            if line.startswith("| ") and not line.startswith(("| example", "| README")) and "---" not in line]


def main() -> None:
    from timing import machine

    from diffbearing.app.scene import examples

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--examples", nargs="*", help="example names (default: every packaged example)")
    parser.add_argument("--films", action="store_true", help="include the 2-D EHL examples")
    options = parser.parse_args()
    names = options.examples or [name for name in examples() if options.films or name not in FILMS]
    rows = []
    for name in names:
        with tempfile.TemporaryDirectory() as cache:
            cold, cold_timing = cli_run(name, cache)
            warm, warm_timing = cli_run(name, cache)
        measured = program(name)
        rows.append((name, cold, cold_timing, warm, measured))
        print(name, f"cold {cold:.1f} s, warm {warm:.1f} s", measured, flush=True)
    gradient = program("aero_angular_contact", gradient=True)
    print("gradient", gradient, flush=True)

    lines = ["# Compile time: the first answer", "", f"Machine: {machine()}. `python benchmarks/compile_time.py`.", "",
             "CLI: `diffbearing run NAME` in a fresh process, wall time with an empty cache folder (cold) and with the",
             "cache it left (warm); its program's compile and run time as the JSON reports them (cold run).",
             "One program: all blocks of the model jitted as one, no cache: trace + lower time, StableHLO lines,",
             "XLA compile and run time with XLA's defaults and with the single run's quick settings.", "",
             "| example | CLI cold [s] | compile [s] | run [ms] | CLI warm [s] | trace + lower [s] | HLO lines "
             "| compile default / quick [s] | run default / quick [ms] |",
             "|---|---|---|---|---|---|---|---|---|"]

    def program_cells(m):
        return (f"{m['trace_s'] + m['lower_s']:.1f} | {m['lines']} | {m['compile_default_s']:.1f} / "
                f"{m['compile_quick_s']:.1f} | {1e3 * m['run_default_s']:.2f} / {1e3 * m['run_quick_s']:.2f}")

    measured_rows = {name: f"| {name} | {cold:.1f} | {timing['compile_s']:.1f} | {1e3 * timing['run_s']:.1f} | "
                           f"{warm:.1f} | " + program_cells(measured) + " |"
                     for name, cold, timing, warm, measured in rows}
    gradient_row = "| README's `jax.grad` of K_zz | | | | | " + program_cells(gradient) + " |"
    # with --examples, the other examples' rows stay as the last full run left them
    kept = {line.split(" | ")[0][2:]: line for line in _table_rows()} if options.examples else {}
    for name in sorted(set(kept) | set(measured_rows)):
        lines.append(measured_rows[name] if name in measured_rows else kept[name])
    lines.append(gradient_row)
    shares = block_shares("aero_angular_contact")
    total = sum(count for _, count in shares)
    lines += ["", "The default scene's program block by block (the StableHLO lines each block adds to those before it, "
              "which it reads):", "", "| block | HLO lines | share |", "|---|---|---|"]
    lines += [f"| {block} | {count} | {100 * count / total:.0f} % |" for block, count in shares]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "compile_time.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).parent))
    main()
