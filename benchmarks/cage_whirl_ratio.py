"""Cage whirl against the ratio of pocket clearance to guide clearance (the cage paper, §4).

    python benchmarks/cage_whirl_ratio.py [--revolutions 10] [--repeats 3]

The cage paper's B7005-class bearing (diffbearing/scenes/cage_b7005.toml: F = [1120, 0, 400] N,
outer-lock pockets, guide clearance 0.24 mm diametral, m = 3 pushing and n = 4 resisting balls for
the quasi-static equilibrium), pocket clearance c_p = ratio × 0.24 mm for ratio 0.6 … 1.6, at 1800
and 20000 r/min. For each: the simulated orbit (`simulate_cage`, from ε = 0.8 at 240°, over
`revolutions` cage revolutions; whirl radius, mean offset, decay rate, dominant frequency over the
second half) and the linear whirl decay rate σ at the quasi-static equilibrium
(`cage_stability`). Also the integrator choice of cage_dynamics.py: Tsit5 against Kvaerno5 over
5 ms at 20000 r/min (ratio 1.083), median of `repeats` runs, compile time apart; and central
differences of the whirl radius over 0.3 s at 1800 r/min for shrinking steps.
Writes benchmarks/results/cage_whirl_ratio.{md,png}.
"""

import argparse
import platform
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import diffrax  # noqa: E402
import jax.numpy as jnp  # noqa: E402
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402
from tqdm import tqdm  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from timing import median_time  # noqa: E402

from diffbearing.cage import cage_dynamics  # noqa: E402
from diffbearing.cage.cage_dynamics import simulate_cage  # noqa: E402
from diffbearing.cage.cage_forces import epicyclic_cage_speed  # noqa: E402
from diffbearing.cage.cage_stability import cage_stability  # noqa: E402
from diffbearing.params import Lubricant, Operating, ball_bearing, ball_cage  # noqa: E402

B7005 = ball_bearing(ball_diameter=5.556e-3, pitch_diameter=36e-3, balls=17, inner_groove_ratio=0.52,
                     outer_groove_ratio=0.53, contact_angle=np.radians(15.0))
OIL = Lubricant(0.01, 2e-8, 870.0)
GUIDE = 0.24e-3
START = 0.8 * 0.5 * GUIDE * jnp.array([np.cos(np.radians(240.0)), np.sin(np.radians(240.0))])
RATIOS = np.round(np.arange(0.6, 1.601, 0.1), 2)
SPEEDS = (1800.0, 20000.0)


def case(ratio, rpm):
    cage = ball_cage(B7005, pocket="outer_lock", pocket_clearance=ratio * GUIDE, guide_clearance=GUIDE,
                     land_width=2e-3, pushing_balls=3, resisting_balls=4)
    return cage, Operating(rpm * np.pi / 30.0, 0.0, [1120.0, 0.0, 400.0], [0.0, 0.0])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--revolutions", type=float, default=10.0)
    parser.add_argument("--repeats", type=int, default=3)
    options = parser.parse_args()

    @jax.jit
    def study(ratio, rpm, duration):
        cage, operating = case(ratio, rpm)
        return (simulate_cage(cage, B7005, operating, OIL, START, duration, 1024),
                cage_stability(cage, B7005, operating, OIL))

    rows, orbits = [], {}
    for rpm in SPEEDS:
        _, operating = case(1.0, rpm)
        duration = options.revolutions * 2 * np.pi / float(epicyclic_cage_speed(B7005, operating))
        for ratio in tqdm(RATIOS, desc=f"{rpm:.0f} r/min"):
            start = time.perf_counter()
            orbit, stability = jax.block_until_ready(study(ratio, rpm, duration))
            wall = time.perf_counter() - start
            orbits[(rpm, ratio)] = orbit
            rows.append((rpm, ratio, orbit, stability, wall))

    # is the long-run whirl radius differentiable? central differences in the ratio at 1800 r/min, 0.3 s
    whirl_of = jax.jit(lambda ratio: study(ratio, 1800.0, 0.3)[0].whirl_radius)
    differences = [(step, float(whirl_of(1.083 + step) - whirl_of(1.083 - step)) / (2 * step))
                   for step in (1e-3, 1e-4, 1e-5, 1e-6)]

    # integrator choice: Tsit5 against Kvaerno5 on the same case
    solver_rows = []
    for solver in (diffrax.Tsit5(), diffrax.Kvaerno5()):
        cage_dynamics.SOLVER = solver
        cage, operating = case(1.083, 20000.0)
        run = jax.jit(lambda: simulate_cage(cage, B7005, operating, OIL, START, 5e-3, 512).whirl_radius)
        start = time.perf_counter()
        whirl = float(jax.block_until_ready(run()))
        first = time.perf_counter() - start
        seconds = median_time(run, repeats=options.repeats)
        solver_rows.append((type(solver).__name__, whirl, first - seconds, seconds))
    cage_dynamics.SOLVER = diffrax.Tsit5()

    lines = [
        "# Cage whirl against pocket / guide clearance (the cage paper, B7005-class)",
        "",
        "Command: `python benchmarks/cage_whirl_ratio.py` "
        f"(--revolutions {options.revolutions:g}, --repeats {options.repeats}). "
        f"Machine: {platform.machine()}, {platform.processor() or 'cpu'}, CPU only, JAX {jax.__version__}.",
        "",
        "F = [1120, 0, 400] N, outer-lock pockets, guide clearance 0.24 mm, start ε = 0.8 at 240°. Orbit measures "
        "over the second half of the run; σ is the linear whirl decay rate at the quasi-static equilibrium "
        "(m = 3 pushing, n = 4 resisting balls). Wall time: one call per case, orbit and stability together; "
        "the first row includes compilation.",
        "",
        "| speed | c_p/c_g | whirl radius | mean offset | decay rate | whirl frequency | σ (linear) | "
        "equilibrium ε | converged | wall time |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for rpm, ratio, orbit, stability, wall in rows:
        lines.append(
            f"| {rpm:.0f} r/min | {ratio:.1f} | {float(orbit.whirl_radius) * 1e6:.2f} µm | "
            f"{float(orbit.mean_offset) * 1e6:.1f} µm | {float(orbit.decay_rate):.1f} 1/s | "
            f"{float(orbit.whirl_frequency):.0f} Hz | {float(stability.decay_rate):.1f} 1/s | "
            f"{float(stability.eccentricity):.3f} | {bool(orbit.converged)} | {wall:.2f} s |")
    lines += ["", "Central differences of the whirl radius in the ratio (1800 r/min, 0.3 s, ratio 1.083): they do "
              "not converge as the step shrinks, so the long-run whirl has no useful derivative:", "",
              "| step | d(whirl radius)/d(ratio) |", "|---|---|"]
    lines += [f"| {step:g} | {value * 1e6:.5g} µm |" for step, value in differences]
    lines += ["", "Integrator (20000 r/min, ratio 1.083, 5 ms):", "",
              "| solver | whirl radius | compile | run (median) |", "|---|---|---|---|"]
    for name, whirl, compile_s, seconds in solver_rows:
        lines.append(f"| {name} | {whirl * 1e6:.6f} µm | {compile_s:.1f} s | {seconds:.2f} s |")
    results = Path(__file__).parent / "results"
    (results / "cage_whirl_ratio.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))

    figure, axes = plt.subplots(1, 3, figsize=(15, 4.5), layout="constrained")
    for rpm, style in zip(SPEEDS, ("o-", "s--")):
        chosen = [r for r in rows if r[0] == rpm]
        axes[0].plot(RATIOS, [float(r[2].whirl_radius) * 1e6 for r in chosen], style, label=f"{rpm:.0f} r/min")
        axes[1].plot(RATIOS, [float(r[3].decay_rate) for r in chosen], style, label=f"{rpm:.0f} r/min")
    axes[0].set(xlabel="pocket clearance / guide clearance", ylabel="whirl radius (RMS of |c − c̄|) [µm]",
                title="simulated whirl (second half)")
    axes[1].set(xlabel="pocket clearance / guide clearance", ylabel="σ [1/s]", yscale="log",
                title="linear whirl decay rate at the equilibrium")
    circle = np.linspace(0, 2 * np.pi, 200)
    axes[2].plot(120 * np.cos(circle), 120 * np.sin(circle), color="grey", lw=0.8)
    for ratio, colour in ((0.6, "tab:blue"), (1.0, "tab:green"), (1.6, "tab:red")):
        centre = np.asarray(orbits[(1800.0, ratio)].centre) * 1e6
        axes[2].plot(centre[512:, 0], centre[512:, 1], color=colour, lw=0.8, label=f"ratio {ratio:.1f}")
    axes[2].set(aspect="equal", xlabel="x [µm]", ylabel="y [µm]", title="orbits at 1800 r/min (second half)")
    for axis in axes:
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.savefig(results / "cage_whirl_ratio.png", dpi=110)


if __name__ == "__main__":
    main()
