"""Seed 003's fully flooded contact as a line contact: film against grid size and wall time.

    python benchmarks/line_ehl.py

Pan–Hamrock (formula) and the numerical 1-D line EHL (Roelands, Dowson–Higginson; Newton with
continuation and nested grids) at 129 … 1025 nodes; error against the paper's 2-D numerical
central film (1.207 µm) and against the finest 1-D grid. Medians of 5 runs after compilation.
Then a heavy-load case (10× the load at 1/100 the speed, Moes M ≈ 209) on 257 … 1025 nodes
against Pan–Hamrock, to show the grid such a load needs. Writes benchmarks/results/line_ehl.md.
"""

import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import median_time  # noqa: E402

from diffbearing.film_formulas import pan_hamrock_line  # noqa: E402
from diffbearing.line_ehl import line_film, moes_load_parameter  # noqa: E402

RADIUS = 1 / (1 / 12.7e-3 - 1 / 66e-3)
LOAD = 1028.0 / 12.7e-3
SPEED = 106.6e-3 / 4 * (1 - (25.4 / 106.6) ** 2) * 1000 * np.pi / 30
LUBRICANT = dict(viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
PAPER_CENTRAL = 1.207e-6


def main():
    rows = []
    formula = jax.jit(lambda w: pan_hamrock_line(w, RADIUS, SPEED, **LUBRICANT))
    central, minimum = formula(LOAD)
    rows.append(("Pan–Hamrock formula", float(central), float(minimum), median_time(lambda: formula(LOAD), 21), 0.0))
    for nodes in (129, 257, 513, 1025):
        start = time.perf_counter()
        solve = jax.jit(lambda w, n=nodes: line_film(w, RADIUS, SPEED, nodes=n, **LUBRICANT)).lower(LOAD).compile()
        compile_s = time.perf_counter() - start
        result = solve(LOAD)
        assert bool(result.converged)
        rows.append((f"line EHL, {nodes} nodes", float(result.central), float(result.minimum),
                     median_time(lambda: solve(LOAD), 5), compile_s))
        print(rows[-1], flush=True)
    finest = rows[-1]
    lines = ["# Seed 003 flooded contact as a 1-D line contact: film against time", "",
             f"W = 1028 N on 12.7 mm, u = {SPEED:.3f} m/s, R = {RADIUS * 1e3:.2f} mm, η0 = 0.08 Pa·s, α = 2.2e-8 1/Pa, "
             "E' = 2.26e11 Pa; paper (2-D numerical): central film 1.207 µm.", "",
             "| level | central film | minimum film | vs paper (central) | vs 1025 nodes (central, minimum) | run | compile |",
             "|---|---|---|---|---|---|---|"]
    for name, central, minimum, run, compile_s in rows:
        lines.append(f"| {name} | {central * 1e6:.4f} µm | {minimum * 1e6:.4f} µm | "
                     f"{(central / PAPER_CENTRAL - 1) * 100:+.1f} % | {(central / finest[1] - 1) * 100:+.2f} %, "
                     f"{(minimum / finest[2] - 1) * 100:+.2f} % | {run * 1e3:.2f} ms | {compile_s:.1f} s |")
    heavy_load, slow = 10 * LOAD, SPEED / 100
    formula_central = float(pan_hamrock_line(heavy_load, RADIUS, slow, **LUBRICANT)[0])
    moes = float(moes_load_parameter(heavy_load, RADIUS, slow, LUBRICANT["viscosity"], LUBRICANT["effective_modulus"]))
    lines += ["", f"Heavy load: w = {heavy_load / 1e3:.1f} N/mm, u = {slow:.4f} m/s (Moes M = {moes:.0f}); "
              f"Pan–Hamrock central film {formula_central * 1e9:.1f} nm.", "",
              "| nodes | central film | minimum film | converged | vs Pan–Hamrock |", "|---|---|---|---|---|"]
    for nodes in (129, 257, 513, 1025):
        result = jax.jit(lambda w, n=nodes: line_film(w, RADIUS, slow, nodes=n, **LUBRICANT))(heavy_load)
        lines.append(f"| {nodes} | {float(result.central) * 1e9:.1f} nm | {float(result.minimum) * 1e9:.1f} nm | "
                     f"{'yes' if bool(result.converged) else 'no (negative film)'} | "
                     f"{(float(result.central) / formula_central - 1) * 100:+.0f} % |")
        print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    (Path(__file__).resolve().parent / "results" / "line_ehl.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
