"""The starved-EHL paper's roller starved by 0.8 µm, by the θ-model (`starved_finite_line_film`).

    python benchmarks/starved_finite_line.py [--grid 257] [--loads 1028 1607 2471]

The roller of `benchmarks/line_ehl.py` on grid × grid (half domain; 257 is the paper's 257 × 513),
one process, 2 cores: each load compiled and run once (the wall time of the whole solve, the flooded
start and the march included), the process's peak resident memory at the end. Prints a Markdown table.
"""

import argparse
import time

import jax

jax.config.update("jax_enable_x64", True)

from line_ehl import FLAT_LENGTH, LUBRICANT, RADIUS, SPEED  # noqa: E402
from timing import machine, peak_rss_mib  # noqa: E402

from diffbearing.roller_profile import roller_profile  # noqa: E402
from diffbearing.starved_finite_line import starved_finite_line_film  # noqa: E402

LENGTH = 14.7e-3


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", type=int, default=257)
    parser.add_argument("--loads", type=float, nargs="+", default=[1028.0, 1607.0, 2471.0])
    arguments = parser.parse_args()
    profile = roller_profile("circular", length=LENGTH, flat_length=FLAT_LENGTH, crown_radius=10e-3)
    print(f"`python benchmarks/starved_finite_line.py --grid {arguments.grid}` on {machine()}\n")
    print("| grid | load | h_c | h_min | converged | wall (compile included) |\n|---|---|---|---|---|---|")
    for load in arguments.loads:
        start = time.perf_counter()
        film = jax.block_until_ready(jax.jit(lambda w: starved_finite_line_film(
            w, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"], LUBRICANT["effective_modulus"],
            profile, LENGTH, FLAT_LENGTH, 0.8e-6, grid=(arguments.grid, arguments.grid)))(load))
        print(f"| {arguments.grid} × {arguments.grid} | {load:g} N | {float(film.central) * 1e6:.4f} µm | "
              f"{float(film.minimum) * 1e6:.4f} µm | {'yes' if bool(film.converged) else 'no'} | "
              f"{time.perf_counter() - start:.0f} s |", flush=True)
    print(f"\npeak resident memory {peak_rss_mib() / 1024:.2f} GiB")


if __name__ == "__main__":
    main()
