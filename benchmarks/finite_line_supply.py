"""The starved-EHL paper, starved: the oil supply that the paper's starvation criterion implies,
and the roller-end minimum films at that supply.

    python benchmarks/finite_line_supply.py

The paper (docs/papers.md, §The starved-EHL paper) reports at 1028 N a flooded central film of
1.207 µm, Er < 1 % at h_oil = 2.0 µm and Er > 1 % at 1.8 µm. By mass conservation a contact starves only once the supply
falls below the flux its flooded film carries, ρ̄h_c at the pressure plateau: about 1.39 µm from
the paper's own film and the Dowson–Higginson density at p_h. So a mass-conserving solver gives
Er > 1 % at 1.8 µm only if the supply it applied was smaller than the layer stated.

1. How much smaller: on the 1-D line contact (513 nodes; it is the roller's mid-length, where side
   flow is nil: the 2-D 65 × 65 central film is within 0.03 % of it) Brent's method finds the
   layer h₁ where Er = 1 %. The paper's two statements both hold for an applied supply k times
   the stated layer with h₁/2.0 µm < k < h₁/1.8 µm.
2. What that supply does to the paper's other numbers, the starved minimum films at the roller
   end (0.319 / 0.215 / 0.159 µm at 1028 / 1607 / 2471 N, stated for h_oil = 0.8 µm): 2-D, 33 × 48
   cells clustered at the flat's end (β = 8, where the 1607 N minimum is resolved along both
   directions: `finite_line_grid.py`), and 33 × 64 at 1028 N, where 48 cells are not enough.
   The layer is lowered from 0.8 µm to 0.8·k µm over the window in steps of 0.02 µm, each Newton
   from the previous solution (`start=`), the step halved where Newton fails. The first solve
   at 0.8 µm is `finite_line_grid.py`'s: from the 1-D start, through its finer load stages where
   Newton at the load fails (2471 N needs them).

Writes benchmarks/results/finite_line_supply.{md,png}. One run of each solve on this 2-core
machine; every solve compiles anew (the start changes the traced function), so the 2-D times
include compilation (and the caches are cleared after each: kept, about 25 compiled solves ended
a first run with "LLVM compilation error: Cannot allocate memory").
"""

import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from tqdm import tqdm  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from finite_line_ehl import FLAT_LENGTH, LUBRICANT, OIL_LAYER, PAPER_MINIMUM, PROFILE, RADIUS, RESULTS, SPEED  # noqa: E402
from finite_line_grid import CLUSTERED_LOAD_PATH, CLUSTERING  # noqa: E402
from line_ehl import PAPER_CENTRAL  # noqa: E402

from diffbearing.contact.hertz import line_contact  # noqa: E402
from diffbearing.film.finite_line_ehl import finite_line_film  # noqa: E402
from diffbearing.film.line_ehl import density_ratio, line_film  # noqa: E402

PAPER_CRITERION = (1.8e-6, 2.0e-6)  # Er > 1 % at the first layer, < 1 % at the second [m]
CRITERION_LOAD = 1028.0  # [N]
LINE_NODES = 513
SERIES = ((1028.0, (33, 48)), (1607.0, (33, 48)), (2471.0, (33, 48)), (1028.0, (33, 64)))  # load [N], half grid
RESOLVED = {(1028.0, (33, 48)): "rising with the cells: 0.338 / 0.345 / 0.354 µm on 32 / 48 / 64 at 0.8 µm",
            (1607.0, (33, 48)): "resolved: 0.2817 / 0.2809 µm on 48 / 64 cells, 0.2834 µm on 65 × 48",
            (2471.0, (33, 48)): "not resolved: 0.097 / 0.209 µm on 32 / 48 cells, 64 does not converge",
            (1028.0, (33, 64)): "the finest converged along the roller at 1028 N"}
LAYER_STEP = 0.02e-6  # [m]
SMALLEST_STEP = 0.0025e-6  # [m]
TOLERANCE = 0.15  # the tolerance held against the paper's minimum films


def line_central(oil_layer=None):
    """1-D central film [m] at 1028 N, flooded or starved by `oil_layer` [m]."""
    film = line_film(CRITERION_LOAD / FLAT_LENGTH, RADIUS, SPEED, **LUBRICANT, nodes=LINE_NODES, oil_layer=oil_layer)
    if not bool(film.converged):
        raise RuntimeError(f"1-D line film did not converge at oil_layer = {oil_layer}")
    return float(film.central)


def supply_window():
    """(flooded h_c [m], layer h₁ [m] where Er = 1 %, k_low, k_high, paper's flooded flux [m])."""
    flooded = line_central()
    layer = brentq(lambda h: 1.0 - line_central(h) / flooded - 0.01, 1.30e-6, 1.38e-6, xtol=1e-10)
    hertz_pressure = line_contact(CRITERION_LOAD / FLAT_LENGTH, RADIUS, LUBRICANT["effective_modulus"]).max_pressure
    paper_flux = float(density_ratio(hertz_pressure)) * PAPER_CENTRAL
    return flooded, layer, layer / PAPER_CRITERION[1], layer / PAPER_CRITERION[0], paper_flux


def solve(load, grid, oil_layer, start=None):
    """(FiniteLineFilm, wall time [s] with compilation)."""
    begin = time.perf_counter()
    stages = {"load_path": CLUSTERED_LOAD_PATH} if start is None else {"start": start, "load_path": (1.0,)}
    film = finite_line_film(load, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
                            LUBRICANT["effective_modulus"], PROFILE, 14.7e-3, FLAT_LENGTH, grid=grid,
                            oil_layer=oil_layer, axial_clustering=CLUSTERING, **stages)
    film = jax.block_until_ready(film)
    seconds = time.perf_counter() - begin
    jax.clear_caches()  # each solve compiles anew; kept, some 25 executables exhaust LLVM's memory maps
    return film, seconds


def layers_down_to(lowest, marks):
    """The layers [m] from 0.8 µm down to `lowest` in steps of LAYER_STEP, with `marks` added."""
    steps = np.arange(OIL_LAYER, lowest, -LAYER_STEP)
    return sorted({round(float(h), 12) for h in (*steps, lowest, *marks)}, reverse=True)


def continuation(load, grid, layers, progress):
    """Rows (layer [m], FiniteLineFilm, time [s] with its failed tries) of the converged solves
    down the `layers`, until one does not converge with the step at SMALLEST_STEP."""
    film, seconds = solve(load, grid, OIL_LAYER)
    progress.update()
    if not bool(film.converged):
        return []
    rows, current = [(OIL_LAYER, film, seconds)], OIL_LAYER
    for target in layers[1:]:
        step, seconds = current - target, 0.0
        while current > target:
            trial_layer = target if current - step < target + 1e-15 else current - step
            trial, more = solve(load, grid, trial_layer, start=film)
            seconds += more
            if bool(trial.converged):
                film, current = trial, trial_layer
            elif step / 2 >= SMALLEST_STEP:
                step /= 2
            else:
                return rows
        rows.append((current, film, seconds))
        progress.update()
    return rows


def at_layer(rows, layer):
    """The converged film at `layer` [m] among `rows`, or None."""
    return next((film for h, film, _ in rows if abs(h - layer) < 1e-12), None)  # layers are rounded to 1e-12 m


def main():
    RESULTS.mkdir(exist_ok=True)
    begin = time.perf_counter()
    flooded, layer_1, k_low, k_high, paper_flux = supply_window()
    window_seconds = time.perf_counter() - begin
    marks = (OIL_LAYER * k_high, OIL_LAYER * k_low)
    layers = layers_down_to(OIL_LAYER * k_low, marks)
    results = {}
    with tqdm(total=len(SERIES) * len(layers), desc="oil-layer continuation") as progress:
        for load, grid in SERIES:
            results[load, grid] = continuation(load, grid, layers, progress)

    def cell(load, grid, layer):
        film = at_layer(results[load, grid], layer)
        if film is None:
            return "not converged"
        minimum = float(film.minimum)
        return f"{minimum * 1e6:.4f} µm ({100 * (minimum / PAPER_MINIMUM[load] - 1):+.1f} %)"

    lines = ["# The starved-EHL paper, starved: the supply the paper's criterion implies", "",
             "`python benchmarks/finite_line_supply.py`", "",
             "## 1. The starvation criterion (1-D line contact, 1028 N)", "",
             f"- Flooded central film: {flooded * 1e6:.4f} µm ({LINE_NODES} nodes; paper's 2-D: "
             f"{PAPER_CENTRAL * 1e6:.3f} µm).",
             f"- Flux the paper's flooded film carries, ρ̄(p_h)·h_c: {paper_flux * 1e6:.3f} µm, less than the 1.8 µm "
             "at which the paper finds the contact starved.",
             f"- Layer where Er = 1 %: h₁ = {layer_1 * 1e6:.4f} µm (Brent's method).",
             f"- The paper's Er > 1 % at {PAPER_CRITERION[0] * 1e6:.1f} µm and Er < 1 % at "
             f"{PAPER_CRITERION[1] * 1e6:.1f} µm both hold for an applied supply k × the stated layer with "
             f"**{k_low:.3f} < k < {k_high:.3f}**.",
             f"- {window_seconds:.0f} s for the 1-D solves, compilation included.", "",
             f"## 2. Roller-end minimum film at the supply k × {OIL_LAYER * 1e6:.1f} µm", "",
             f"2-D, nx × ny on the half domain, cells clustered at the flat's end (β = {CLUSTERING:g}); "
             "the layer lowered from 0.8 µm, each Newton from the previous solution. In brackets: against the "
             f"paper's minimum film (tolerance ±{100 * TOLERANCE:.0f} %).", "",
             f"| load | grid | paper | k = 1 ({OIL_LAYER * 1e6:.3f} µm) | k = {k_high:.3f} ({marks[0] * 1e6:.3f} µm) | "
             f"k = {k_low:.3f} ({marks[1] * 1e6:.3f} µm) | on this grid |", "|---|---|---|---|---|---|---|"]
    for load, grid in SERIES:
        lines.append(f"| {load:.0f} N | {grid[0]} × {grid[1]} | {PAPER_MINIMUM[load] * 1e6:.3f} µm | "
                     f"{cell(load, grid, OIL_LAYER)} | {cell(load, grid, marks[0])} | {cell(load, grid, marks[1])} | "
                     f"{RESOLVED[load, grid]} |")
    lines += ["", "Every converged step (layer [µm]: h_c, h_min [µm], time [s] with compilation):", ""]
    for load, grid in SERIES:
        steps = ", ".join(f"{h * 1e6:.3f}: {float(f.central) * 1e6:.4f}, {float(f.minimum) * 1e6:.4f}, {s:.0f}"
                          for h, f, s in results[load, grid])
        lines.append(f"- {load:.0f} N, {grid[0]} × {grid[1]}: {steps}")

    figure, axis = plt.subplots(figsize=(7, 4.5))
    colors = {1028.0: "C0", 1607.0: "C1", 2471.0: "C2"}
    for load, grid in SERIES:
        rows, color = results[load, grid], colors[load]
        axis.plot([h / OIL_LAYER for h, _, _ in rows], [float(f.minimum) * 1e6 for _, f, _ in rows],
                  "o-" if grid[1] == 48 else "s--", color=color, ms=3,
                  label=f"{load:.0f} N, {grid[0]} × {grid[1]}" + (" (not grid-resolved)" if load == 2471.0 else ""))
    for load, color in colors.items():
        paper = PAPER_MINIMUM[load] * 1e6
        axis.axhspan(paper * (1 - TOLERANCE), paper * (1 + TOLERANCE), color=color, alpha=0.12)
        axis.axhline(paper, color=color, ls=":")
    axis.axvspan(k_low, k_high, color="0.5", alpha=0.2, label="supply window of the paper's Er criterion")
    axis.set(xlabel=f"supply k = h_oil / {OIL_LAYER * 1e6:.1f} µm", ylabel="roller-end minimum film [µm]",
             title="The starved-EHL paper, starved, clustered cells: paper's minima (dotted) ±15 %")
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(RESULTS / "finite_line_supply.png", dpi=120)
    (RESULTS / "finite_line_supply.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
