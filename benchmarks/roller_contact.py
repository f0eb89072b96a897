"""Roller contact: accuracy against time for every fidelity level, and the speed ratio against the
dense active-set method of the crowning paper.

    python benchmarks/roller_contact.py            # everything (the 64×512 dense solve takes minutes)
    python benchmarks/roller_contact.py --quick    # skip the 64×512 dense solve

1. A fully crowned roller (flat length 0, Rc = 100 mm, D = 10 mm, l = 12 mm, flat raceway, 1 kN,
   E = 207 GPa, ν = 0.29) is an exact Hertz point contact: error of peak pressure and approach
   against Hertz, per grid, and for the Hertz-slice level.
2. The crowning paper's tapered roller with the Johns–Gohar profile (no closed form): error against the
   finest grid (256 × 2048).
3. The crowning paper's method — a dense influence matrix with an active set, NumPy/LAPACK
   (`dense_roller_contact.py`) — against the DC-FFT Polonsky–Keer solver at 32 × 256 and 64 × 512
   on the same grid: wall times, ratio, and the largest pressure difference.

Times are medians of repeated runs after compilation; compile times apart. Writes
benchmarks/results/roller_contact.md and roller_contact.png.
"""

import argparse
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from dense_roller_contact import solve_dense_active_set  # noqa: E402
from timing import median_time  # noqa: E402

from diffbearing.bearings.roller.roller_contact import contact_grid, roller_contact  # noqa: E402
from diffbearing.bearings.roller.roller_geometry import RollerLoading, initial_gap, roller_bearing, roller_modulus  # noqa: E402
from diffbearing.bearings.roller.roller_profile import roller_profile  # noqa: E402
from diffbearing.contact import hertz  # noqa: E402
from diffbearing.params import Material  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
GCR15 = Material(207e9, 0.29, 7830.0)
GRIDS = [(8, 32), (16, 64), (32, 128), (32, 256), (64, 256), (64, 512), (128, 512), (128, 1024)]
FINEST = (256, 2048)


def timed_solve(bearing, loading, grid, method, repeats):
    """(result, compile [s], median run [s])."""
    start = time.perf_counter()
    compiled = jax.jit(lambda b, l: roller_contact(b, l, grid, method)).lower(bearing, loading).compile()
    compile_s = time.perf_counter() - start
    result = jax.block_until_ready(compiled(bearing, loading))
    return result, compile_s, median_time(lambda: compiled(bearing, loading), repeats)


def crowned_roller():
    length = 12e-3
    bearing = roller_bearing(kind="cylindrical_roller", length=length, diameter=10e-3, material=GCR15,
                             profile=roller_profile("circular", length=length, flat_length=0.0, crown_radius=0.1))
    loading = RollerLoading(1000.0, 0.0, 0.0)
    rx, ry = 5e-3, 0.1
    exact = hertz.point_contact(1000.0, 1 / rx + 1 / ry, (1 / rx - 1 / ry) / (1 / rx + 1 / ry), roller_modulus(bearing))
    return bearing, loading, float(exact.max_pressure), float(exact.approach)


def crowning_paper_roller():
    length = 12e-3
    bearing = roller_bearing(kind="tapered_roller", length=length, small_diameter=7e-3, large_diameter=8e-3,
                             cone_half_angle=np.radians(2.4), material=GCR15,
                             profile=roller_profile("johns_gohar", length=length, design_load=1000.0))
    return bearing, RollerLoading(1000.0, 0.0, 1 / 22e-3)


def accuracy_table(bearing, loading, reference_pressure, reference_approach, grids):
    rows = []
    for grid in grids:
        repeats = 9 if grid[0] * grid[1] <= 64 * 512 else 3
        result, compile_s, run_s = timed_solve(bearing, loading, grid, "influence", repeats)
        rows.append((f"influence {grid[0]}×{grid[1]}", run_s, compile_s,
                     abs(float(result.max_pressure) / reference_pressure - 1),
                     abs(float(result.approach) / reference_approach - 1), int(result.iterations)))
        print(rows[-1], flush=True)
    result, compile_s, run_s = timed_solve(bearing, loading, (32, 256), "slices", 21)
    rows.append(("slices 256 laminae", run_s, compile_s, abs(float(result.max_pressure) / reference_pressure - 1),
                 abs(float(result.approach) / reference_approach - 1), 0))
    print(rows[-1], flush=True)
    return rows


def dense_comparison(grids, first_round_only):
    """Rows per grid; for grids in `first_round_only` only the first dense solve is timed (a
    lower bound on the dense method's time: it needs several such solves)."""
    bearing, loading = crowning_paper_roller()
    rows = []
    for grid in grids:
        partial = grid in first_round_only
        result, compile_s, run_s = timed_solve(bearing, loading, grid, "influence", 9)
        x, y, _ = contact_grid(bearing, loading, *grid)
        gap = np.asarray(initial_gap(bearing, loading, x, y))
        cell_x, cell_y = float(x[1] - x[0]), float(y[1] - y[0])
        slices = np.asarray(roller_contact(bearing, loading, grid, "slices").pressure) > 0
        start = time.perf_counter()
        pressure, dense_approach, rounds = solve_dense_active_set(gap, 1000.0, cell_x, cell_y,
                                                                  float(roller_modulus(bearing)), slices,
                                                                  max_rounds=1 if partial else 50)
        dense_s = time.perf_counter() - start
        if pressure is None:
            difference = approach_difference = None
        else:
            difference = np.abs(pressure - np.asarray(result.pressure)).max() / float(result.max_pressure)
            approach_difference = abs(dense_approach / float(result.approach) - 1)
        rows.append((grid, run_s, compile_s, dense_s, rounds, difference, approach_difference, partial))
        print(rows[-1], flush=True)
    return rows


def accuracy_lines(title, note, rows):
    """Markdown section: one row per fidelity level."""
    return ["", f"## {title}", "", note, "", "| level | run | compile | error p_max | error δ | iterations |",
            "|---|---|---|---|---|---|"] + [f"| {name} | {run * 1e3:.2f} ms | {comp:.2f} s | {ep:.2e} | {ed:.2e} | {it} |"
                                            for name, run, comp, ep, ed, it in rows]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="skip the 64×512 dense solve (minutes)")
    parser.add_argument("--dense-64x512-full", action="store_true",
                        help="run the whole dense active-set iteration at 64×512 (tens of minutes), "
                             "not only its first solve")
    arguments = parser.parse_args()
    RESULTS.mkdir(exist_ok=True)

    bearing, loading, p0, delta = crowned_roller()
    hertz_rows = accuracy_table(bearing, loading, p0, delta, GRIDS)
    bearing, loading = crowning_paper_roller()
    finest = jax.jit(lambda b, l: roller_contact(b, l, FINEST))(bearing, loading)
    seed_rows = accuracy_table(bearing, loading, float(finest.max_pressure), float(finest.approach), GRIDS)
    dense_rows = dense_comparison([(32, 256)] + ([] if arguments.quick else [(64, 512)]),
                                  first_round_only=[] if arguments.dense_64x512_full else [(64, 512)])

    lines = ["# Roller contact: accuracy against time", "",
             "`python benchmarks/roller_contact.py` on the project's 2-core CPU machine (JAX CPU; medians of",
             "repeated runs after compilation, compile time apart)."]
    lines += accuracy_lines(
        "Fully crowned roller against the exact Hertz point contact",
        f"D = 10 mm, l = 12 mm, flat length 0, Rc = 100 mm, flat raceway, Q = 1 kN: Hertz p0 = {p0 / 1e9:.4f} GPa, "
        f"δ = {delta * 1e6:.4f} µm.", hertz_rows)
    lines += accuracy_lines(
        "The crowning paper's tapered roller, Johns–Gohar profile, against the finest grid",
        f"Finest grid {FINEST[0]}×{FINEST[1]}: p_max = {float(finest.max_pressure) / 1e9:.4f} GPa, "
        f"δ = {float(finest.approach) * 1e6:.4f} µm.", seed_rows)
    lines += ["", "## Against the crowning paper's method: dense influence matrix with an active set (NumPy/LAPACK)", "",
              "| grid | DC-FFT + preconditioned PK (JAX) | compile | dense active set (NumPy) | dense solves | ratio |"
              " max pressure difference / p_max | approach difference |",
              "|---|---|---|---|---|---|---|---|"]
    for g, run, comp, dense, rounds, diff, dapp, partial in dense_rows:
        if partial:
            lines.append(f"| {g[0]}×{g[1]} | {run * 1e3:.1f} ms | {comp:.2f} s | > {dense:.0f} s (first of several "
                         f"dense solves) | ≥ 1 | > {dense / run:.0f}× | – | – |")
        else:
            lines.append(f"| {g[0]}×{g[1]} | {run * 1e3:.1f} ms | {comp:.2f} s | {dense:.1f} s | {rounds} | "
                         f"{dense / run:.0f}× | {diff:.1e} | {dapp:.1e} |")
    complete = [row for row in dense_rows if not row[-1]]
    if any(row[-1] for row in dense_rows):
        lines += ["", "At 64×512 only the first dense solve (LU of the bordered matrix on the starting contact set)",
                  "is timed: the whole iteration repeats it until no pressure is negative "
                  f"({complete[0][4]} solves at {complete[0][0][0]}×{complete[0][0][1]}), so",
                  "the ratio is a lower bound. `--dense-64x512-full` runs it to the end."]
    (RESULTS / "roller_contact.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))

    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
    for axis, rows, title in ((axes[0], hertz_rows, "fully crowned roller vs exact Hertz"),
                              (axes[1], seed_rows, "crowning paper, Johns–Gohar vs 256×2048")):
        numeric = [r for r in rows if r[0].startswith("influence")]
        times = [r[1] * 1e3 for r in numeric]
        axis.loglog(times, [max(r[3], 1e-7) for r in numeric], "o-", label="influence: peak pressure")
        axis.loglog(times, [max(r[4], 1e-7) for r in numeric], "s--", label="influence: approach")
        for r in numeric:
            axis.annotate(r[0].split()[1], (r[1] * 1e3, max(r[3], 1e-7)), fontsize=7, xytext=(3, 3),
                          textcoords="offset points")
        fast = rows[-1]
        axis.loglog([fast[1] * 1e3], [fast[3]], "r^", label="slices: peak pressure")
        axis.loglog([fast[1] * 1e3], [fast[4]], "rv", label="slices: approach")
        axis.set(xlabel="wall time after compilation [ms]", ylabel="relative error", title=title)
        axis.grid(alpha=0.3, which="both")
        axis.legend(fontsize=8)
    figure.savefig(RESULTS / "roller_contact.png", dpi=120)


if __name__ == "__main__":
    main()
