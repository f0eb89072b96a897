"""Seed 003's roller-end minimum film against the 2-D grid: how far it is from converged.

    python benchmarks/finite_line_grid.py

The roller contact of `finite_line_ehl.py` (1028 N, 1000 r/min), flooded and starved by
h_oil = 0.8 µm, on two refinement ladders of the half domain, each halving the spacing twice:
- along the roller, ny = 32, 64, 128 cells at nx = 33 (the fine cells over the flat's end and the
  crown halve with them: a quarter of the cells always covers the middle);
- along rolling, nx = 17, 33, 65 nodes at ny = 64.
For each ladder, Richardson's observed order p = log2(|h₁ − h₂| / |h₂ − h₃|) and the extrapolated
film h₃ + (h₃ − h₂)/(2^p − 1), where the differences keep their sign and shrink; where they do
not, the ladder's spread instead. The paper's heavier loads, 1607 and 2471 N starved, on the two
coarser grids of the ladder along the roller (through the load continuation where Newton at the
load fails; 33 × 128 at 1607 N ran past 10 minutes).
Writes benchmarks/results/finite_line_grid.{md,png}.
One run of each solve on this 2-core machine; compile time separately.
"""

import math
import time

import jax

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from tqdm import tqdm  # noqa: E402

from finite_line_ehl import OIL_LAYER, PAPER_MINIMUM, RESULTS, ROLLER_LOAD, finite_line_solver, timed  # noqa: E402

ALONG_ROLLER = ((33, 32), (33, 64), (33, 128))  # (nx, ny) on the half domain
ALONG_ROLLING = ((17, 64), (33, 64), (65, 64))
HEAVIER_LOADS = (1607.0, 2471.0)  # [N], starved, on the two coarser grids along the roller
HEAVIER_GRIDS = ALONG_ROLLER[:2]  # 33 × 128 at 1607 N ran past 10 minutes (one run, stopped)


def richardson(films):
    """(observed order p, extrapolated film [m]) of three films on grids halving the spacing, or
    (nan, nan) where the differences change sign or grow (not in the asymptotic range)."""
    first, second = films[1] - films[0], films[2] - films[1]
    if first * second <= 0 or abs(second) >= abs(first):
        return math.nan, math.nan
    order = math.log2(first / second)
    return order, films[2] + second / (2**order - 1)


def solve_all():
    """{(grid, oil layer or None, load [N]): (central [m], minimum [m], its y [m], converged, run [s], compile [s])}."""
    cases = [(grid, layer, ROLLER_LOAD) for grid in dict.fromkeys(ALONG_ROLLER + ALONG_ROLLING)
             for layer in (None, OIL_LAYER)]
    cases += [(grid, OIL_LAYER, load) for load in HEAVIER_LOADS for grid in HEAVIER_GRIDS]
    results = {}
    for grid, layer, load in tqdm(cases, desc="2-D solves", unit="solve"):
        solve, compile_s = finite_line_solver(grid, layer)
        film, run = timed(solve, load)
        results[grid, layer, load] = (float(film.central), float(film.minimum), float(film.minimum_position),
                                      bool(film.converged), run, compile_s)
        tqdm.write(f"{grid[0]} × {grid[1]}, {load:.0f} N, {'flooded' if layer is None else 'starved'}: h_c "
                   f"{float(film.central) * 1e6:.4f} µm, h_min {float(film.minimum) * 1e6:.4f} µm at y = "
                   f"{float(film.minimum_position) * 1e3:.3f} mm, converged {bool(film.converged)}, {run:.1f} s")
    return results


def ladder_line(direction, films):
    """A Markdown line on one refinement ladder's minimum films, and the extrapolated film [m] (nan if none)."""
    text = f"- {direction}: h_min {', '.join(f'{f * 1e6:.4f}' for f in films)} µm; "
    if len(films) < 3:
        return text + f"two grids: {(films[-1] / films[0] - 1) * 100:+.1f} % from the coarser", math.nan
    order, extrapolated = richardson(films)
    if math.isnan(extrapolated):
        spread = (max(films) - min(films)) / (0.5 * (max(films) + min(films)))
        return text + f"the differences change sign or grow: no extrapolation, spread {spread * 100:.1f} %", extrapolated
    return text + (f"observed order p = {order:.2f}, extrapolated **{extrapolated * 1e6:.4f} µm** "
                   f"(the finest grid {(films[-1] / extrapolated - 1) * 100:+.1f} % from it)"), extrapolated


def table(results, keys):
    lines = ["| grid | load | h_c | h_min (at y) | converged | run | compile |", "|---|---|---|---|---|---|---|"]
    for grid, layer, load in keys:
        central, minimum, position, converged, run, compile_s = results[grid, layer, load]
        lines.append(f"| {grid[0]} × {grid[1]} | {load:.0f} N | {central * 1e6:.4f} µm | "
                     f"{minimum * 1e6:.4f} µm ({position * 1e3:.3f} mm) | {'yes' if converged else 'NO'} | "
                     f"{run:.1f} s | {compile_s:.0f} s |")
    return lines + [""]



def main():
    results = solve_all()
    lines = ["# Seed 003: the roller-end minimum film against the 2-D grid", "",
             "1000 r/min; grids nx × ny of the half domain (nodes along rolling × cells along the half",
             "roller); `python benchmarks/finite_line_grid.py`, one run of each solve.", ""]
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    for layer, name in ((None, "fully flooded"), (OIL_LAYER, "starved, h_oil = 0.8 µm")):
        lines += [f"## 1028 N, {name}", ""]
        lines += table(results, [(grid, layer, ROLLER_LOAD) for grid in dict.fromkeys(ALONG_ROLLER + ALONG_ROLLING)])
        for ladder, direction, axis in ((ALONG_ROLLER, "along the roller (ny, nx = 33)", axes[0]),
                                        (ALONG_ROLLING, "along rolling (nx, ny = 64)", axes[1])):
            films = [results[grid, layer, ROLLER_LOAD][1] for grid in ladder]
            line, extrapolated = ladder_line(direction, films)
            lines.append(line)
            counts = [grid[1] if ladder is ALONG_ROLLER else grid[0] for grid in ladder]
            axis.semilogx(counts, [f * 1e6 for f in films], "o-", base=2, label=f"1028 N, {name}")
            if not math.isnan(extrapolated):
                axis.axhline(extrapolated * 1e6, ls=":", color=axis.lines[-1].get_color())
        lines.append("")
    lines += ["## Starved by 0.8 µm at the paper's loads, along the roller", ""]
    lines += table(results, [(grid, OIL_LAYER, load) for load in HEAVIER_LOADS for grid in HEAVIER_GRIDS])
    for load in (ROLLER_LOAD, *HEAVIER_LOADS):
        films = [results[grid, OIL_LAYER, load][1] for grid in (ALONG_ROLLER if load == ROLLER_LOAD else HEAVIER_GRIDS)]
        line, extrapolated = ladder_line(f"{load:.0f} N", films)
        best = films[-1] if math.isnan(extrapolated) else extrapolated
        lines.append(line + f"; the paper {PAPER_MINIMUM[round(load)] * 1e6:.3f} µm: the "
                     f"{'finest grid' if math.isnan(extrapolated) else 'extrapolated film'} "
                     f"{(best / PAPER_MINIMUM[round(load)] - 1) * 100:+.1f} %")
        if load != ROLLER_LOAD:
            axes[0].semilogx([grid[1] for grid in HEAVIER_GRIDS], [f * 1e6 for f in films], "s--", base=2,
                             label=f"{load:.0f} N, starved")
    for load in PAPER_MINIMUM:
        axes[0].axhline(PAPER_MINIMUM[load] * 1e6, color="k", lw=0.6)
    axes[1].axhline(PAPER_MINIMUM[1028.0] * 1e6, color="k", lw=0.6)
    for axis, label in zip(axes, ("cells along the half roller ny (nx = 33)", "nodes along rolling nx (ny = 64)")):
        axis.set(xlabel=label, ylabel="roller-end minimum film [µm]")
        axis.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    figure.suptitle("Seed 003: the minimum film against the grid (dotted: Richardson; black: the paper, starved)")
    RESULTS.mkdir(exist_ok=True)
    figure.savefig(RESULTS / "finite_line_grid.png", dpi=120)
    (RESULTS / "finite_line_grid.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
