"""The starved-EHL paper, starved: what the side flow at the meniscus does to the roller-end minimum film.

    python benchmarks/finite_line_side_flow.py

The roller contact of `finite_line_ehl.py` starved by h_oil = 0.8 µm at 1028 and 1607 N, on
33 × 48 cells clustered at the flat's end (`axial_clustering=8.0`, where the 1607 N minimum is
resolved: `finite_line_grid.py`). The default meniscus balance of each column counts the oil
layer alone and drops the oil that a wetter neighbour's full film pushes sideways into the
column's partial film; `finite_line_film(..., side_inflow=γ)` counts the fraction γ of it, and
γ = 1 conserves mass across the meniscus.

First the column model (γ = 0) from the 1-D start, through the default load continuation (1607 N
needs it); then a continuation in γ by steps of 0.1, each Newton from the previous solution
(`start=`, with `load_path=(1.0,)`: where Newton from the start fails, its fallback is Newton from
the 1-D start at the load, menisci held first). Where that fails too, the first dry end column
(meniscus on its upper bound: no full film) is the one the side inflow must fill: its meniscus is
set to its inboard neighbour's and Newton is tried again, then the first two, up to three
(FILL_TRIES).

Writes benchmarks/results/finite_line_side_flow.{md,png}. One run of each solve on this 2-core
machine; every solve compiles anew (γ and the start change the traced function), so the times
include compilation.
"""

import time

import equinox as eqx
import jax
import jax.numpy as jnp

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from finite_line_ehl import FLAT_LENGTH, LUBRICANT, OIL_LAYER, PAPER_MINIMUM, PROFILE, RADIUS, RESULTS, SPEED  # noqa: E402
from tqdm import tqdm  # noqa: E402

from diffbearing.film.finite_line_ehl import finite_line_film  # noqa: E402

GRID = (33, 48)  # half domain
CLUSTERING = 8.0
LOADS = (1028.0, 1607.0)  # [N]
FRACTIONS = tuple(round(0.1 * k, 1) for k in range(1, 11))  # γ
FILL_TRIES = 3


def solve(load, side_inflow, start=None):
    """(FiniteLineFilm, wall time [s] with compilation): from the 1-D start through the default
    load continuation, or from `start` with Newton at the load only."""
    begin = time.perf_counter()
    film = finite_line_film(load, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
                            LUBRICANT["effective_modulus"], PROFILE, 14.7e-3, FLAT_LENGTH, grid=GRID,
                            oil_layer=OIL_LAYER, axial_clustering=CLUSTERING, side_inflow=side_inflow,
                            **({} if start is None else {"start": start, "load_path": (1.0,)}))
    return jax.block_until_ready(film), time.perf_counter() - begin


def dry_columns(film):
    """Indices of the y cells without a full film (meniscus on its upper bound, the largest)."""
    meniscus = np.asarray(film.meniscus)
    return np.nonzero(meniscus >= meniscus.max() - 1e-12)[0]


def with_columns_filled(film, count):
    """`film` as a start with its first `count` dry end columns' menisci set to the last wet one's."""
    meniscus = np.asarray(film.meniscus).copy()
    dry = dry_columns(film)
    meniscus[dry[:count]] = meniscus[dry[0] - 1]
    return eqx.tree_at(lambda solution: solution.meniscus, film, jnp.asarray(meniscus))


def continuation(load, progress):
    """Rows (γ, columns filled by hand, FiniteLineFilm, time [s]) from γ = 0 up, and the γ = 0
    and last converged films."""
    film, seconds = solve(load, 0.0)
    rows, first = [(0.0, 0, film, seconds)], film
    progress.update()
    if not bool(film.converged):
        return rows, first, film
    for fraction in FRACTIONS:
        trial, seconds = solve(load, fraction, start=film)
        filled = 0
        while not bool(trial.converged) and filled < FILL_TRIES:
            filled += 1
            trial, more = solve(load, fraction, start=with_columns_filled(film, filled))
            seconds += more
        rows.append((fraction, filled, trial, seconds))
        progress.update()
        if not bool(trial.converged):
            break
        film = trial
    return rows, first, film


def table(load, rows):
    reference = float(rows[0][2].minimum)
    lines = [f"## {load:.0f} N (paper's minimum film {PAPER_MINIMUM[load] * 1e6:.3f} µm)", "",
             "| γ | h_c [µm] | h_min [µm] (at y [mm]) | h_min against γ = 0 | against the paper | y cells with a full "
             "film | dry columns filled by hand | converged (residual) | time [s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for fraction, filled, film, seconds in rows:
        minimum = float(film.minimum)
        lines.append(f"| {fraction:.1f} | {float(film.central) * 1e6:.4f} | {minimum * 1e6:.4f} "
                     f"({float(film.minimum_position) * 1e3:.3f}) | {100 * (minimum / reference - 1):+.1f} % | "
                     f"{100 * (minimum / PAPER_MINIMUM[load] - 1):+.1f} % | {GRID[1] - dry_columns(film).size} of {GRID[1]} | "
                     f"{filled} | {bool(film.converged)} ({float(film.residual):.1e}) | {seconds:.1f} |")
    return lines


def main():
    RESULTS.mkdir(exist_ok=True)
    lines = ["# The starved-EHL paper, starved (0.8 µm): side flow in the meniscus balance", "",
             f"`python benchmarks/finite_line_side_flow.py`; grid {GRID[0]} × {GRID[1]} on the half domain, cells "
             f"clustered at the flat's end (β = {CLUSTERING:g}). γ = `side_inflow`, the fraction of the side inflow "
             "counted in each column's meniscus balance (1: mass conserving). Continuation in γ from the column "
             "model (γ = 0), each Newton from the previous solution; where it fails, the first dry end columns "
             "are filled by hand (their menisci set to the last wet one's). Times include compilation.", ""]
    figure, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=True)
    with tqdm(total=len(LOADS) * (len(FRACTIONS) + 1), desc="side-flow continuation") as progress:
        for axis, load in zip(axes, LOADS):
            rows, column_model, last = continuation(load, progress)
            lines += table(load, rows) + [""]
            for film, label in ((column_model, "γ = 0 (column model)"), (last, f"γ = {rows[-1][0]:.1f}")):
                axis.plot(np.asarray(film.y) * 1e3, np.asarray(film.thickness).min(axis=0) * 1e6, ".-", label=label)
            axis.axhline(PAPER_MINIMUM[load] * 1e6, color="k", ls=":", label="paper's minimum")
            axis.axvline(FLAT_LENGTH / 2 * 1e3, color="0.6", lw=0.8)
            axis.set(title=f"{load:.0f} N, h_oil = {OIL_LAYER * 1e6:.1f} µm", xlabel="y from mid-length [mm]",
                     xlim=(5.5, 7.0), ylim=(0.0, 1.2))
            axis.legend()
    axes[0].set_ylabel("smallest film in each y cell [µm]")
    figure.tight_layout()
    figure.savefig(RESULTS / "finite_line_side_flow.png", dpi=120)
    (RESULTS / "finite_line_side_flow.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
