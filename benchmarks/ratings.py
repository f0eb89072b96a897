"""The rating checks and hand-offs: what each costs on top of the bearing solve, and the stiffness
sweep for rotor-dynamics codes.

    python benchmarks/ratings.py [--repeats 20] [--speeds 64]

The default scene (the aero-engine angular-contact bearing at speed, stiffness and life) run
through the scene layer alone and with each of the effects safety, frequencies, friction and a_ISO
(a [lubricant] with cleanliness): compile time and the median run time after compilation, so the
difference is each effect's own cost. Then `stiffness_over_speed` over `speeds` speeds (one vmapped
sweep, compile and run). No SciPy baseline: these are closed forms on the solved state. Writes
benchmarks/results/ratings.md.
"""

import argparse
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import machine, median_time, peak_rss_mib  # noqa: E402

from diffbearing import build_model, load_scene, run_model, stiffness_over_speed  # noqa: E402
from diffbearing.app.registry import compiled as compiled_model  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
LUBRICANT = ["lubricant.preset=iso_vg_68", "lubricant.temperature=70 degC"]
CASES = {
    "bearing (equilibrium, stiffness, life)": [],
    "+ safety": ["effects.safety=true"],
    "+ frequencies": ["effects.frequencies=true"],
    "+ friction (Palmgren)": ["effects.friction=palmgren", *LUBRICANT],
    "+ a_ISO (lubricant.cleanliness)": [*LUBRICANT, "lubricant.cleanliness=-/17/14", "lubricant.supply=circulating"],
}


def case(overrides, repeats):
    model = build_model(load_scene(overrides=overrides))
    result = run_model(model, progress=False)
    executable, _ = compiled_model(model.blocks, model.settings, model.inputs)
    return result.compile_s, median_time(lambda: executable(model.inputs), repeats)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--speeds", type=int, default=64)
    arguments = parser.parse_args()
    lines = ["# Rating checks and the rotor-dynamics hand-off", "", f"Machine: {machine()}.",
             f"Command: `python benchmarks/ratings.py --repeats {arguments.repeats} --speeds {arguments.speeds}`", "",
             "| scene | compile [s] | run [ms] |", "|---|---|---|"]
    for name, overrides in CASES.items():
        compile_s, run_s = case(overrides, arguments.repeats)
        lines.append(f"| {name} | {compile_s:.2f} | {run_s * 1e3:.3f} |")
        print(lines[-1], flush=True)
    speeds = np.linspace(0.0, 2000.0, arguments.speeds)
    table = stiffness_over_speed(load_scene(), speeds)  # compiles once
    start = time.perf_counter()
    table = stiffness_over_speed(load_scene(), speeds)
    sweep_s = time.perf_counter() - start
    lines += ["", f"`stiffness_over_speed` of the default scene over {len(speeds)} speeds (one vmapped sweep, "
                  f"compiled again by each call): {sweep_s:.2f} s a call, {table.stiffness.shape} matrices.",
              f"Peak resident memory of the process: {peak_rss_mib():.0f} MiB."]
    print("\n".join(lines[-2:]))
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "ratings.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
