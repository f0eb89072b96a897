"""The starved numerical point contact against Chevalier's starvation formula, grid by grid.

    python benchmarks/starved_point_ehl.py [--grids 65x32 129x64 257x128] [--layers 0.75 0.375 0.1875 0.09375]

A circular contact (Rx = Ry = 10 mm, 50 N, p₀ 1.07 GPa, u = 1 m/s; steel, η₀ 0.08 Pa·s,
α 2.2e-8 1/Pa, Roelands, Dowson–Higginson) starved by oil layers [µm] (by default about 2, 1, ½
and ¼ of its flooded central film; `starved_point_ehl.starved_point_film`), against Chevalier,
Lubrecht, Cann, Colin & Dalmaz (J. Tribol. 120, 1998): h/h_ff = r/(1 + r^γ)^{1/γ},
r = h_oil/(ρ̄ h_ff), γ = 2.5, ρ̄ the density ratio at p₀, h_ff the flooded central film of the
same grid. Each grid in its own process (its peak resident memory is that grid's): one compiled
solve, run once per layer (the time after compilation). Then the grid convergence of the flooded
and starved central films (Richardson, the three finest grids). Writes
benchmarks/results/starved_point_ehl.md and starved_point_ehl.png.
"""

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import jax
import numpy as np

jax.config.update("jax_enable_x64", True)

from timing import compiled_with_time, machine, peak_rss_mib  # noqa: E402

from diffbearing.film.film_formulas import starved_film  # noqa: E402
from diffbearing.film.line_ehl import density_ratio  # noqa: E402
from diffbearing.film.point_ehl import point_film  # noqa: E402
from diffbearing.film.starved_point_ehl import starved_point_film  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
OIL = dict(viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
CIRCLE = dict(radius_rolling=10e-3, radius_transverse=10e-3, speed=1.0)
LOAD, HERTZ_PRESSURE = 50.0, 1.07e9
SHARPNESS = 2.5


def one_grid(grid, layers):
    """{grid, flooded [m], compile [s], peak [MiB], rows: [{layer [m], central [m], minimum [m],
    converged, run [s]}]} of one grid (in this process)."""
    flooded = float(jax.jit(lambda q: point_film(q, **CIRCLE, **OIL, grid=grid).central)(LOAD))
    compiled, compile_time = compiled_with_time(
        lambda layer: starved_point_film(LOAD, **CIRCLE, **OIL, oil_layer=layer, grid=grid), flooded)
    rows = []
    for layer in layers:
        start = time.perf_counter()
        solved = jax.block_until_ready(compiled(1e-6 * layer))
        rows.append(dict(layer=1e-6 * layer, central=float(solved.film.central), minimum=float(solved.film.minimum),
                         converged=bool(solved.film.converged), run=time.perf_counter() - start))
    return dict(grid=list(grid), flooded=flooded, compile=compile_time, peak=peak_rss_mib(), rows=rows)


def richardson(values):
    """(observed order, extrapolated value) of a quantity on three grids, each twice as fine."""
    coarse, middle, fine = values
    if (middle - coarse) * (fine - middle) <= 0:
        return math.nan, math.nan
    order = math.log2(abs(middle - coarse) / abs(fine - middle))
    return order, fine + (fine - middle) / (2**order - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", nargs="+", default=["65x32", "129x64", "257x128"])
    parser.add_argument("--layers", type=float, nargs="+", default=[0.75, 0.375, 0.1875, 0.09375], help="µm")
    parser.add_argument("--one", help=argparse.SUPPRESS)  # a child process: one grid, JSON on stdout
    arguments = parser.parse_args()
    if arguments.one:
        print(json.dumps(one_grid(tuple(int(n) for n in arguments.one.split("x")), arguments.layers)))
        return
    grids = []
    for grid in arguments.grids:
        command = [sys.executable, __file__, "--one", grid, "--layers", *map(str, arguments.layers)]
        grids.append(json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout
                                .strip().splitlines()[-1]))
        print(grids[-1], flush=True)
    density = float(density_ratio(HERTZ_PRESSURE))
    lines = ["# Starved point contact against Chevalier, grid by grid", "",
             f"`python benchmarks/starved_point_ehl.py` on {machine()}: a circle, 50 N, 1 m/s; h_c,ff the flooded "
             "central film of the same grid; each grid in its own process (compile: the starved solve's, the "
             "flooded one before it not counted; peak: the process's resident peak). Grids on the half domain.", "",
             f"| grid | h_oil | h_oil / h_c,ff | h_c | h_c / h_c,ff | Chevalier (γ = {SHARPNESS}, ρ̄ = {density:.3f}) "
             "| difference | h_min | converged | run | compile | peak memory |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for result in grids:
        flooded = result["flooded"]
        for row in result["rows"]:
            ratio = row["central"] / flooded
            chevalier = float(starved_film(1.0, row["layer"] / flooded, density, SHARPNESS))
            lines.append(f"| {result['grid'][0]} × {result['grid'][1]} | {row['layer'] * 1e6:.4g} µm | "
                         f"{row['layer'] / flooded:.3f} | {row['central'] * 1e6:.4f} µm | {ratio:.4f} | {chevalier:.4f} | "
                         f"{100 * (ratio / chevalier - 1):+.1f} % | {row['minimum'] * 1e6:.4f} µm "
                         f"| {'yes' if row['converged'] else 'no'} | {row['run']:.1f} s | {result['compile']:.0f} s | "
                         f"{result['peak'] / 1024:.2f} GiB |")
    if len(grids) >= 3:
        last = grids[-3:]
        names = ", ".join(f"{g['grid'][0]} × {g['grid'][1]}" for g in last)
        lines += ["", f"Grid convergence (Richardson, {names}):", "",
                  "| quantity | values | observed order | extrapolated |", "|---|---|---|---|"]
        quantities = [("flooded h_c,ff [µm]", [g["flooded"] * 1e6 for g in last])]
        for index, layer in enumerate(arguments.layers):
            quantities.append((f"h_c [µm] at h_oil = {layer:g} µm", [g["rows"][index]["central"] * 1e6 for g in last]))
        for name, values in quantities:
            order, extrapolated = richardson(values)
            settled = "not monotone" if math.isnan(order) else f"{order:.2f}"
            lines.append(f"| {name} | {', '.join(f'{v:.4f}' for v in values)} | {settled} | "
                         f"{'–' if math.isnan(order) else f'{extrapolated:.4f}'} |")
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "starved_point_ehl.md").write_text("\n".join(lines) + "\n")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axis = plt.subplots(figsize=(6, 4))
    supply = np.geomspace(0.05, 10, 200)
    axis.plot(supply, [float(starved_film(1.0, r, density, SHARPNESS)) for r in supply], "k-",
              label=f"Chevalier, γ = {SHARPNESS}")
    for result, marker in zip(grids, "osd^v"):
        converged = [row for row in result["rows"] if row["converged"]]
        axis.plot([row["layer"] / result["flooded"] for row in converged],
                  [row["central"] / result["flooded"] for row in converged], marker, fillstyle="none",
                  label=f"θ-model, {result['grid'][0]} × {result['grid'][1]}")
    axis.set(xscale="log", xlabel="oil layer / flooded central film", ylabel="central film / flooded",
             title="starved circular contact, 50 N, 1 m/s")
    axis.grid(alpha=0.3)
    axis.legend()
    figure.tight_layout()
    figure.savefig(RESULTS / "starved_point_ehl.png", dpi=120)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
