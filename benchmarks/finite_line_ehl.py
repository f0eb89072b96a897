"""Seed 003's flooded finite line contact (2-D, half domain, dense Newton): films and time.

    python benchmarks/finite_line_ehl.py

Roller with a 12.7 mm flat and 10 mm crown radius, 14.7 mm long, on the outer raceway at
1000 r/min; loads 1028, 1607 and 2471 N on a 33 × 48 grid, and 1028 N on 25 × 48 and 41 × 48.
Writes benchmarks/results/finite_line_ehl.md.
"""

import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

import numpy as np  # noqa: E402

from diffbearing.finite_line_ehl import finite_line_film  # noqa: E402
from diffbearing.roller_profile import roller_profile  # noqa: E402

RADIUS = 1 / (1 / 12.7e-3 - 1 / 66e-3)
SPEED = 106.6e-3 / 4 * (1 - (25.4 / 106.6) ** 2) * 1000 * np.pi / 30
PROFILE = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)


def main():
    lines = ["# Seed 003 flooded finite line contact (2-D, dense Newton)", "",
             "| load | grid | central film (y = 0) | minimum film | at y | p_max | converged | run | compile |",
             "|---|---|---|---|---|---|---|---|---|"]
    for grid, loads in (((25, 48), (1028.0,)), ((33, 48), (1028.0, 1607.0, 2471.0)), ((41, 48), (1028.0,))):
        start = time.perf_counter()
        solve = jax.jit(lambda w, g=grid: finite_line_film(w, RADIUS, SPEED, 0.08, 2.2e-8, 2.26e11, PROFILE, 14.7e-3,
                                                           12.7e-3, grid=g)).lower(loads[0]).compile()
        compile_s = time.perf_counter() - start
        for load in loads:
            start = time.perf_counter()
            result = jax.block_until_ready(solve(load))
            run = time.perf_counter() - start
            lines.append(f"| {load:.0f} N | {grid[0]} × {grid[1]} | {float(result.central) * 1e6:.4f} µm | "
                         f"{float(result.minimum) * 1e6:.4f} µm | {float(result.minimum_position) * 1e3:.3f} mm | "
                         f"{float(np.max(result.pressure)) / 1e9:.3f} GPa | {'yes' if bool(result.converged) else 'no'} | "
                         f"{run:.1f} s | {compile_s:.1f} s |")
            print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    (Path(__file__).resolve().parent / "results" / "finite_line_ehl.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
