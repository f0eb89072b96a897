"""The starved numerical point contact against Chevalier's starvation formula.

    python benchmarks/starved_point_ehl.py [--grid 65 32] [--layers 2 1 0.5 0.25]

A circular contact (Rx = Ry = 10 mm, 50 N, p₀ 1.07 GPa, u = 1 m/s; steel, η₀ 0.08 Pa·s,
α 2.2e-8 1/Pa, Roelands, Dowson–Higginson) starved by oil layers of the given multiples of its
flooded central film on the same grid (`starved_point_ehl.starved_point_film`), against
Chevalier, Lubrecht, Cann, Colin & Dalmaz (J. Tribol. 120, 1998):
h/h_ff = r/(1 + r^γ)^{1/γ}, r = h_oil/(ρ̄ h_ff), γ = 2.5, ρ̄ the density ratio at p₀.
One compiled solve, run once per layer (the time after compilation). Writes
benchmarks/results/starved_point_ehl.md and starved_point_ehl.png.
"""

import argparse
import time
from pathlib import Path

import jax
import numpy as np

jax.config.update("jax_enable_x64", True)

from timing import compiled_with_time, machine, peak_rss_mib  # noqa: E402

from diffbearing.film_formulas import starved_film  # noqa: E402
from diffbearing.line_ehl import density_ratio  # noqa: E402
from diffbearing.point_ehl import point_film  # noqa: E402
from diffbearing.starved_point_ehl import starved_point_film  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
OIL = dict(viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
CIRCLE = dict(radius_rolling=10e-3, radius_transverse=10e-3, speed=1.0)
LOAD, HERTZ_PRESSURE = 50.0, 1.07e9
SHARPNESS = 2.5


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", type=int, nargs=2, default=[65, 32])
    parser.add_argument("--layers", type=float, nargs="+", default=[2.0, 1.0, 0.5, 0.25])
    arguments = parser.parse_args()
    grid = tuple(arguments.grid)
    flooded = float(jax.jit(lambda q: point_film(q, **CIRCLE, **OIL, grid=grid).central)(LOAD))
    compiled, compile_time = compiled_with_time(
        lambda layer: starved_point_film(LOAD, **CIRCLE, **OIL, oil_layer=layer, grid=grid), flooded)
    density = float(density_ratio(HERTZ_PRESSURE))
    rows = []
    for ratio in arguments.layers:
        start = time.perf_counter()
        solved = jax.block_until_ready(compiled(ratio * flooded))
        run = time.perf_counter() - start
        chevalier = float(starved_film(flooded, ratio * flooded, density, SHARPNESS)) / flooded
        rows.append(dict(ratio=ratio, central=float(solved.film.central) / flooded, chevalier=chevalier,
                         minimum=float(solved.film.minimum) * 1e6, converged=bool(solved.film.converged), run=run))
        print(rows[-1], flush=True)
    lines = ["# Starved point contact against Chevalier", "",
             f"`python benchmarks/starved_point_ehl.py --grid {grid[0]} {grid[1]}` on {machine()}: a circle, 50 N, "
             f"1 m/s; flooded central film {flooded * 1e6:.4f} µm on {grid[0]} × {grid[1]} (half domain); "
             f"compile {compile_time:.0f} s, peak resident memory {peak_rss_mib():.0f} MiB.", "",
             f"| h_oil / h_c,ff | h_c / h_c,ff | Chevalier (γ = {SHARPNESS}, ρ̄ = {density:.3f}) | difference | h_min "
             "| converged | run |", "|---|---|---|---|---|---|---|"]
    for row in rows:
        lines.append(f"| {row['ratio']:g} | {row['central']:.4f} | {row['chevalier']:.4f} | "
                     f"{100 * (row['central'] / row['chevalier'] - 1):+.1f} % | {row['minimum']:.4f} µm | "
                     f"{'yes' if row['converged'] else 'no'} | {row['run']:.0f} s |")
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "starved_point_ehl.md").write_text("\n".join(lines) + "\n")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axis = plt.subplots(figsize=(6, 4))
    supply = np.geomspace(0.05, 10, 200)
    axis.plot(supply, [float(starved_film(1.0, r, density, SHARPNESS)) for r in supply],
              label=f"Chevalier, γ = {SHARPNESS}")
    converged = [row for row in rows if row["converged"]]
    axis.plot([row["ratio"] for row in converged], [row["central"] for row in converged], "o",
              label=f"θ-model, {grid[0]} × {grid[1]}")
    axis.set(xscale="log", xlabel="oil layer / flooded central film", ylabel="central film / flooded",
             title="starved circular contact, 50 N, 1 m/s")
    axis.grid(alpha=0.3)
    axis.legend()
    figure.tight_layout()
    figure.savefig(RESULTS / "starved_point_ehl.png", dpi=120)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
