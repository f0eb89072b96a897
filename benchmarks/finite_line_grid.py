"""The starved-EHL paper's roller-end minimum film against the 2-D grid: how far it is from converged.

    python benchmarks/finite_line_grid.py

The roller contact of `finite_line_ehl.py` (1028 N, 1000 r/min), flooded and starved by
h_oil = 0.8 µm, on two refinement ladders of the half domain, each halving the spacing twice:
- along the roller, ny = 32, 64, 128 cells at nx = 33 (the fine cells over the flat's end and the
  crown halve with them: a quarter of the cells always covers the middle);
- along rolling, nx = 17, 33, 65 nodes at ny = 64.
For each ladder, Richardson's observed order p = log2(|h₁ − h₂| / |h₂ − h₃|) and the extrapolated
film h₃ + (h₃ − h₂)/(2^p − 1), where the differences keep their sign and shrink; where they do
not, the ladder's spread instead; a film whose solve did not converge is left out of its ladder.
The paper's heavier loads, 1607 and 2471 N starved, on the two coarser grids of the ladder along
the roller (through the load continuation where Newton at the load fails; 33 × 128 at 1607 N ran
past 10 minutes).

Then the same contact on cells clustered at the flat's end by one smooth map
(`finite_line_film(..., axial_clustering=8.0)`, `finite_line_ehl.axial_cells`), every cell halving:
ny = 16, 32, 64 at nx = 33 flooded and starved at 1028 N; 32, 48, 64 starved at 1607 N; 32 and
48 at 2471 N through finer load stages (CLUSTERED_LOAD_PATH; 33 × 64 at 2471 N did not converge
through them in a scratch run of 808 s, so it is left out).
Writes benchmarks/results/finite_line_grid.{md,png}.
One run of each solve on this 2-core machine; compile time separately.
"""

import math

import jax

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from finite_line_ehl import OIL_LAYER, PAPER_MINIMUM, RESULTS, ROLLER_LOAD, finite_line_solver, timed  # noqa: E402
from tqdm import tqdm  # noqa: E402

ALONG_ROLLER = ((33, 32), (33, 64), (33, 128))  # (nx, ny) on the half domain
ALONG_ROLLING = ((17, 64), (33, 64), (65, 64))
HEAVIER_LOADS = (1607.0, 2471.0)  # [N], starved, on the two coarser grids along the roller
HEAVIER_GRIDS = ALONG_ROLLER[:2]  # 33 × 128 at 1607 N ran past 10 minutes (one run, stopped)
CLUSTERING = 8.0  # β of `axial_cells`
CLUSTERED_LOAD_PATH = (0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 1.0)  # 2471 N on 33 × 48 fails through LOAD_PATH
CLUSTERED_LADDERS = {1028.0: ((33, 16), (33, 32), (33, 64)), 1607.0: ((33, 32), (33, 48), (33, 64)),
                     2471.0: ((33, 32), (33, 48))}  # starved; 1028 N flooded too


def richardson(films):
    """(observed order p, extrapolated film [m]) of three films on grids halving the spacing, or
    (nan, nan) where the differences change sign or grow (not in the asymptotic range)."""
    first, second = films[1] - films[0], films[2] - films[1]
    if first * second <= 0 or abs(second) >= abs(first):
        return math.nan, math.nan
    order = math.log2(first / second)
    return order, films[2] + second / (2**order - 1)


def solve_all():
    """{(grid, oil layer or None, load [N], clustering or None): (central [m], minimum [m], its y [m],
    converged, run [s], compile [s])}."""
    cases = [(grid, layer, ROLLER_LOAD, None) for grid in dict.fromkeys(ALONG_ROLLER + ALONG_ROLLING)
             for layer in (None, OIL_LAYER)]
    cases += [(grid, OIL_LAYER, load, None) for load in HEAVIER_LOADS for grid in HEAVIER_GRIDS]
    cases += [(grid, None, ROLLER_LOAD, CLUSTERING) for grid in CLUSTERED_LADDERS[1028.0]]
    cases += [(grid, OIL_LAYER, load, CLUSTERING) for load, ladder in CLUSTERED_LADDERS.items() for grid in ladder]
    results = {}
    for grid, layer, load, clustering in tqdm(cases, desc="2-D solves", unit="solve"):
        options = {} if clustering is None else {"axial_clustering": clustering, "load_path": CLUSTERED_LOAD_PATH}
        solve, compile_s = finite_line_solver(grid, layer, **options)
        film, run = timed(solve, load)
        results[grid, layer, load, clustering] = (float(film.central), float(film.minimum),
                                                  float(film.minimum_position), bool(film.converged), run, compile_s)
        tqdm.write(f"{grid[0]} × {grid[1]}{'' if clustering is None else ' clustered'}, {load:.0f} N, "
                   f"{'flooded' if layer is None else 'starved'}: h_c "
                   f"{float(film.central) * 1e6:.4f} µm, h_min {float(film.minimum) * 1e6:.4f} µm at y = "
                   f"{float(film.minimum_position) * 1e3:.3f} mm, converged {bool(film.converged)}, {run:.1f} s")
    return results


def ladder_line(direction, solved, halving=True):
    """A Markdown line on one refinement ladder's minimum films, of the solves (`solve_all` rows)
    that converged, and the extrapolated film [m] (nan if none; Richardson only where three
    converged grids halve the spacing)."""
    films = [row[1] for row in solved if row[3]]
    left_out = sum(not row[3] for row in solved)
    text = (f"- {direction}: h_min {', '.join(f'{f * 1e6:.4f}' for f in films)} µm"
            f"{f' ({left_out} not converged, left out)' if left_out else ''}; ")
    if len(films) < 2:
        return text + "fewer than two converged grids", math.nan
    if len(films) < 3 or not halving:
        changes = ", ".join(f"{(fine / coarse - 1) * 100:+.1f} %" for coarse, fine in zip(films, films[1:]))
        return text + f"change from each grid to the next finer: {changes}", math.nan
    order, extrapolated = richardson(films)
    if math.isnan(extrapolated):
        spread = (max(films) - min(films)) / (0.5 * (max(films) + min(films)))
        return text + f"the differences change sign or grow: no extrapolation, spread {spread * 100:.1f} %", extrapolated
    return text + (f"observed order p = {order:.2f}, extrapolated **{extrapolated * 1e6:.4f} µm** "
                   f"(the finest grid {(films[-1] / extrapolated - 1) * 100:+.1f} % from it)"), extrapolated


def table(results, keys):
    lines = ["| grid | load | h_c | h_min (at y) | converged | run | compile |", "|---|---|---|---|---|---|---|"]
    for key in keys:
        grid, load = key[0], key[2]
        central, minimum, position, converged, run, compile_s = results[key]
        lines.append(f"| {grid[0]} × {grid[1]} | {load:.0f} N | {central * 1e6:.4f} µm | "
                     f"{minimum * 1e6:.4f} µm ({position * 1e3:.3f} mm) | {'yes' if converged else 'NO'} | "
                     f"{run:.1f} s | {compile_s:.0f} s |")
    return lines + [""]



def paper_line(direction, load, solved, halving=True):
    """`ladder_line` with the paper's starved minimum film at that load beside it."""
    line, extrapolated = ladder_line(direction, solved, halving)
    converged = [row[1] for row in solved if row[3]] or [math.nan]
    best = converged[-1] if math.isnan(extrapolated) else extrapolated
    return line + (f"; the paper {PAPER_MINIMUM[round(load)] * 1e6:.3f} µm: the "
                   f"{'finest converged grid' if math.isnan(extrapolated) else 'extrapolated film'} "
                   f"{(best / PAPER_MINIMUM[round(load)] - 1) * 100:+.1f} %")


def main():
    results = solve_all()
    lines = ["# The starved-EHL paper: the roller-end minimum film against the 2-D grid", "",
             "1000 r/min; grids nx × ny of the half domain (nodes along rolling × cells along the half",
             "roller); `python benchmarks/finite_line_grid.py`, one run of each solve.", ""]
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    for layer, name in ((None, "fully flooded"), (OIL_LAYER, "starved, h_oil = 0.8 µm")):
        lines += [f"## 1028 N, {name}", ""]
        lines += table(results, [(grid, layer, ROLLER_LOAD, None)
                                 for grid in dict.fromkeys(ALONG_ROLLER + ALONG_ROLLING)])
        for ladder, direction, axis in ((ALONG_ROLLER, "along the roller (ny, nx = 33)", axes[0]),
                                        (ALONG_ROLLING, "along rolling (nx, ny = 64)", axes[1])):
            solved = [results[grid, layer, ROLLER_LOAD, None] for grid in ladder]
            films = [row[1] for row in solved]
            line, extrapolated = ladder_line(direction, solved)
            lines.append(line)
            counts = [grid[1] if ladder is ALONG_ROLLER else grid[0] for grid in ladder]
            axis.semilogx(counts, [f * 1e6 for f in films], "o-", base=2, label=f"1028 N, {name}")
            if not math.isnan(extrapolated):
                axis.axhline(extrapolated * 1e6, ls=":", color=axis.lines[-1].get_color())
        lines.append("")
    lines += ["## Starved by 0.8 µm at the paper's loads, along the roller", ""]
    lines += table(results, [(grid, OIL_LAYER, load, None) for load in HEAVIER_LOADS for grid in HEAVIER_GRIDS])
    for load in (ROLLER_LOAD, *HEAVIER_LOADS):
        solved = [results[grid, OIL_LAYER, load, None] for grid in (ALONG_ROLLER if load == ROLLER_LOAD else HEAVIER_GRIDS)]
        lines.append(paper_line(f"{load:.0f} N", load, solved))
        if load != ROLLER_LOAD:
            axes[0].semilogx([grid[1] for grid in HEAVIER_GRIDS], [row[1] * 1e6 if row[3] else math.nan for row in solved],
                             "s--", base=2, label=f"{load:.0f} N, starved")
    lines += ["", f"## Cells clustered at the flat's end (axial_clustering = {CLUSTERING:g}), along the roller (nx = 33)", ""]
    keys = [(grid, None, ROLLER_LOAD, CLUSTERING) for grid in CLUSTERED_LADDERS[1028.0]]
    keys += [(grid, OIL_LAYER, load, CLUSTERING) for load, ladder in CLUSTERED_LADDERS.items() for grid in ladder]
    lines += table(results, keys)
    flooded = [results[key] for key in keys[:3]]
    lines.append(ladder_line("1028 N, flooded", flooded)[0])
    for load, ladder in CLUSTERED_LADDERS.items():
        solved = [results[grid, OIL_LAYER, load, CLUSTERING] for grid in ladder]
        lines.append(paper_line(f"{load:.0f} N, starved", load, solved, halving=load == ROLLER_LOAD))
        axes[0].semilogx([grid[1] for grid in ladder], [row[1] * 1e6 if row[3] else math.nan for row in solved],
                         "^-.", base=2, label=f"{load:.0f} N, starved, clustered")
    axes[0].semilogx([grid[1] for grid in CLUSTERED_LADDERS[1028.0]], [row[1] * 1e6 for row in flooded], "^-.",
                     base=2, label="1028 N, flooded, clustered")
    for load in PAPER_MINIMUM:
        axes[0].axhline(PAPER_MINIMUM[load] * 1e6, color="k", lw=0.6)
    axes[1].axhline(PAPER_MINIMUM[1028.0] * 1e6, color="k", lw=0.6)
    for axis, label in zip(axes, ("cells along the half roller ny (nx = 33)", "nodes along rolling nx (ny = 64)")):
        axis.set(xlabel=label, ylabel="roller-end minimum film [µm]")
        axis.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    figure.suptitle("The starved-EHL paper: the minimum film against the grid (dotted: Richardson; black: the paper, starved)")
    RESULTS.mkdir(exist_ok=True)
    figure.savefig(RESULTS / "finite_line_grid.png", dpi=120)
    (RESULTS / "finite_line_grid.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
