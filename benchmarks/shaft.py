"""Shafts and preloaded pairs: compile time, time per solve and per case of a batch, peak memory.

    python benchmarks/shaft.py [--cases 1000] [--repeats 5]

Three cases, one process, times after compilation (medians of `repeats`):
  * the packaged `gearbox_shaft` scene through the scene layer (two 6411E, static, stiffness and life);
  * its shaft alone (`solve_shaft` + `shaft_stiffness`), one call under jit and `cases` gear loads
    under jit(vmap) (radial 1–10 kN, axial 0–3 kN, random);
  * the packaged `spindle_pair` scene (a DB pair at 8000 r/min with centrifugal force and
    gyroscopic moment, stiffness).
No SciPy baseline is timed for the shaft (benchmarks/ball_bearing.py times the classical
solution of one bearing). Writes benchmarks/results/shaft.md.
"""

import argparse
import sys
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import compiled_with_time, machine, median_time, peak_rss_mib  # noqa: E402

from diffbearing import build_model, load_scene, run_model  # noqa: E402
from diffbearing.app.registry import compiled as compiled_model  # noqa: E402
from diffbearing.bearings.ball.ball_equilibrium import BallModel  # noqa: E402
from diffbearing.bearings.ball.ball_support import BallSupport  # noqa: E402
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, shaft_stiffness, solve_shaft  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"


def scene_case(name, repeats):
    """(compile [s], run [s]) of a packaged scene through the scene layer."""
    model = build_model(load_scene(name))
    result = run_model(model, progress=False)
    executable, _ = compiled_model(model.blocks, model.settings, model.inputs)
    return result.compile_s, median_time(lambda: executable(model.inputs), repeats)


def shaft_of(layout, force):
    supports = tuple(BallSupport(bearing, position, offset, model=BallModel(), orientation=orientation)
                     for bearing, position, offset, orientation in zip(layout.bearings, layout.positions,
                                                                       layout.offsets, layout.orientations))
    loads = ShaftLoads(layout.loads.positions, force[None], layout.loads.moments)
    return Shaft(supports, loads, layout.speed)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=5)
    arguments = parser.parse_args()
    rows = []
    compile_s, run_s = scene_case("gearbox_shaft", arguments.repeats)
    rows.append(("`gearbox_shaft` scene (2 bearings, static; stiffness, life)", 1, run_s, compile_s))

    layout = build_model(load_scene("gearbox_shaft")).inputs["shaft"]

    def one(force):
        shaft = shaft_of(layout, force)
        solution = solve_shaft(shaft)
        return solution.displacement, shaft_stiffness(solution.displacement, shaft), solution.converged

    force = jnp.array([6e3, 2e3, 1.5e3])
    single, single_compile = compiled_with_time(one, force)
    rows.append(("gearbox shaft alone: `solve_shaft` + `shaft_stiffness`, single call", 1,
                 median_time(lambda: single(force), arguments.repeats), single_compile))
    generator = np.random.default_rng(0)
    forces = jnp.asarray(np.column_stack([generator.uniform(1e3, 10e3, arguments.cases),
                                          generator.uniform(0.0, 3e3, arguments.cases),
                                          generator.uniform(0.0, 3e3, arguments.cases)]))
    batch, batch_compile = compiled_with_time(jax.vmap(one), forces)
    batch_time = median_time(lambda: batch(forces), arguments.repeats)
    converged = int(np.sum(np.asarray(batch(forces)[2])))
    rows.append((f"the same under jit(vmap), {arguments.cases} gear loads ({converged} converged)", arguments.cases,
                 batch_time, batch_compile))

    compile_s, run_s = scene_case("spindle_pair", arguments.repeats)
    rows.append(("`spindle_pair` scene (DB pair, 8000 r/min, speed effects, stiffness)", 1, run_s, compile_s))

    lines = ["# Shafts and preloaded pairs", "",
             f"`python benchmarks/shaft.py` on {machine()}; times after compilation, medians of {arguments.repeats}; "
             "compile times apart (lowering and XLA compilation).", "",
             "| case | cases | time per case | compile |", "|---|---|---|---|"]
    for name, cases, seconds, compile_time in rows:
        lines.append(f"| {name} | {cases} | {seconds / cases * 1e3:.3f} ms | {compile_time:.1f} s |")
    lines += ["", f"Peak resident memory of the process: {peak_rss_mib():.0f} MiB.", ""]
    RESULTS.joinpath("shaft.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
