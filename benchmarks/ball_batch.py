"""Batch against single call: per-case time of `solve_equilibrium` under jit(vmap) and under jit.

    python benchmarks/ball_batch.py [--static-cases 10000] [--speed-cases 1000] [--repeats 3]

Two bearings, in one process, after compilation (median of `repeats` batches; single calls: median over
the `check` loads compared below of each one's median of 5 calls):
  * MASTA-style deep-groove bearing: 7 balls of D_w = 11.5 mm on d_m = 43.5 mm, f_i = 0.52,
    f_o = 0.53, diametral clearance 10 µm; static; radial 100–3000 N and axial 0–2000 N (random);
  * the aero-engine bearing of the stiffness paper (Z = 28) at 1500 r/min with centrifugal and
    gyroscopic effects, equilibrium + 5×5 stiffness; Fx, Fy, Fz swept as in
    benchmarks/ball_bearing.py.
The batch answers are compared with single calls on a subset (largest relative difference of Δ
and K). Targets: static ≤ 50 µs/case in a 10 000-case batch, the aero-engine bearing ≤ 200
µs/case, batch below single call for both. Writes benchmarks/results/ball_batch.md.

Where the time goes (jit(vmap), 2 cores). 7-ball static: the static start (regularized Newton
on the elastic energy, ≤ 9 steps) and the ring Newton (3 steps, Jacobian with the Hertz constants
held, 5 tangents). The aero-engine bearing with speed effects: a stage of per-ball 2×2 Newton
steps with the ring held, then four speed stages of the joint ring-and-ball Newton, every step
one linearisation of the balls (4 tangents: each ball's groove centre and centre) and the 5×5
Schur complement (`ball_equilibrium.condensed_balls`); the vmapped loops run as many steps as
the slowest case of the batch needs (a lightly loaded ball whose inner contact is open at the
start overshoots and comes back slowly on Hertz's δ^{3/2}). The stiffness is one exact
linearisation at the solved balls.
"""

import argparse
import platform
import resource
import statistics
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from timing import median_time  # noqa: E402

from diffbearing import build_model, load_scene  # noqa: E402
from diffbearing.bearings.ball.ball_equilibrium import BallModel, solve_equilibrium, stiffness_matrix  # noqa: E402
from diffbearing.params import Operating, ball_bearing  # noqa: E402

RESULTS = Path(__file__).parent / "results"
SPEED = 1500 * np.pi / 30


def masta_bearing():
    return ball_bearing(ball_diameter=11.5e-3, pitch_diameter=43.5e-3, balls=7, kind="deep_groove_ball",
                        inner_groove_ratio=0.52, outer_groove_ratio=0.53, radial_clearance=10e-6)


def measure(name, case, loads, repeats, check):
    """(row dict): single-call and per-case batch times [s], compile times [s], agreement [-]."""
    start = time.perf_counter()
    single = jax.jit(case).lower(loads[0]).compile()
    compile_single = time.perf_counter() - start
    checked = np.linspace(0, len(loads) - 1, check).astype(int)
    # single-call time: the median over the checked loads of each one's median of 5 calls
    single_s = statistics.median(median_time(lambda: single(loads[index]), 5) for index in checked)
    batched = jax.jit(jax.vmap(case))
    start = time.perf_counter()
    executable = batched.lower(loads).compile()
    compile_batch = time.perf_counter() - start
    batch_s = statistics.median(
        [_timed(lambda: jax.block_until_ready(executable(loads))) for _ in range(repeats)])
    out = executable(loads)
    difference = 0.0
    for index in checked:
        reference = single(loads[index])
        for batch_value, value in zip(out[:-1], reference[:-1]):
            value = np.asarray(value)
            scale = np.max(np.abs(value)) or 1.0
            difference = max(difference, float(np.max(np.abs(np.asarray(batch_value)[index] - value)) / scale))
    return dict(name=name, cases=len(loads), single=single_s, per_case=batch_s / len(loads),
                compile_single=compile_single, compile_batch=compile_batch, difference=difference,
                converged=int(np.sum(np.asarray(out[-1]))))


def _timed(function):
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--static-cases", type=int, default=10000)
    parser.add_argument("--speed-cases", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--check", type=int, default=20, help="single calls compared with the batch")
    args = parser.parse_args()

    masta = masta_bearing()
    static = BallModel()
    rng = np.random.default_rng(0)
    count = args.static_cases
    static_loads = jnp.asarray(np.stack([rng.uniform(100.0, 3000.0, count), np.zeros(count),
                                         rng.uniform(0.0, 2000.0, count)], axis=1))

    def static_case(force):
        solution = solve_equilibrium(masta, Operating(0.0, 0.0, force, jnp.zeros(2)), static)
        return solution.displacement, solution.converged

    seed = build_model(load_scene()).inputs["bearing"]
    moment = build_model(load_scene()).inputs["operating"].moment
    speed = BallModel(centrifugal=True, gyroscopic=True)
    scale = np.linspace(0.2, 2.0, args.speed_cases)
    speed_loads = jnp.asarray(np.stack([15e3 * scale, 18e3 * scale[::-1], 35e3 * np.sqrt(scale)], axis=1))

    def speed_case(force):
        operating = Operating(SPEED, 0.0, force, moment)
        solution = solve_equilibrium(seed, operating, speed)
        return (solution.displacement, stiffness_matrix(solution.displacement, seed, operating, speed, solution.ball_centres),
                solution.converged)

    rows = [measure("7-ball deep groove, static (Δ)", static_case, static_loads, args.repeats, args.check),
            measure("aero-engine bearing, 1500 r/min, speed effects (Δ + 5×5 K)", speed_case, speed_loads, args.repeats,
                    args.check)]
    targets = (50e-6, 200e-6)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    machine = f"{platform.machine()}, {jax.devices()[0].platform.upper()} ×{len(jax.devices())}, jax {jax.__version__}"
    lines = [f"`solve_equilibrium` single call (jit) against batch (jit(vmap)), one process ({machine}); "
             f"single: median over {args.check} loads of the batch of each one's median of 5 calls; "
             f"batch: median of {args.repeats}.", "",
             "| bearing | cases | single call | batch per case | batch/single | target | met | compile single / batch "
             "| max rel. diff. batch vs single | converged |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for row, target in zip(rows, targets):
        met = row["per_case"] <= target and row["per_case"] < row["single"] and row["difference"] <= 1e-10
        miss = "yes" if met else f"no ({row['per_case'] / target:.1f}× the target)"
        lines.append(f"| {row['name']} | {row['cases']} | {row['single'] * 1e6:.0f} µs | {row['per_case'] * 1e6:.0f} µs "
                     f"| {row['per_case'] / row['single']:.2f} | ≤ {target * 1e6:.0f} µs | {miss} "
                     f"| {row['compile_single']:.1f} s / {row['compile_batch']:.1f} s | {row['difference']:.1e} "
                     f"| {row['converged']} of {row['cases']} |")
    lines += ["", f"Peak resident memory of the process: {peak:.0f} MiB.", "",
              "Measured by `python benchmarks/ball_batch.py`."]
    table = "\n".join(lines)
    print(table)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "ball_batch.md").write_text(table + "\n")


if __name__ == "__main__":
    main()
