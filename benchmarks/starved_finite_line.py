"""The starved-EHL paper's roller at its own grid, fully flooded and starved by 0.8 µm (the θ-model).

    python benchmarks/starved_finite_line.py [--grids 65 129 257] [--loads 1028 1607 2471]

The roller and oil layer of the public scene `diffbearing/scenes/starved_roller.toml`, read from it
(seed 003: crown radius 10 mm with the raceway's 100 mm edge radius, `with_raceway_edge`; 0.8 µm;
lubricant and speed as `benchmarks/line_ehl.py`) on grid × grid (half domain; 257 is the paper's
257 × 513). Each solve, flooded (`finite_line_film_krylov`) and starved (`starved_finite_line_film`),
runs in its own process on the machine's cores, compiled with `newton_krylov.COMPILER_OPTIONS` as the
CLI compiles it: compile time, run time, and the peak resident memory of compiling and of running
apart (the high-water mark is reset between them through /proc/self/clear_refs). Then the grid study:
central and roller-end minimum films against grid with the observed order (Richardson, the three
finest grids, where all three converged). Prints Markdown tables.
"""

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

from line_ehl import LUBRICANT, RADIUS, SPEED  # noqa: E402
from timing import machine  # noqa: E402

from diffbearing.app.scene import load_scene  # noqa: E402
from diffbearing.app.stored_models import release_memory  # noqa: E402
from diffbearing.bearings.roller.roller_profile import roller_profile, with_raceway_edge  # noqa: E402
from diffbearing.film.finite_line_krylov import finite_line_film_krylov  # noqa: E402
from diffbearing.film.starved_finite_line import starved_finite_line_film  # noqa: E402
from diffbearing.newton_krylov import COMPILER_OPTIONS  # noqa: E402

SCENE = load_scene("starved_roller").values  # the public scene: its roller and oil layer
PAPER_MINIMUM = {1028.0: 0.319, 1607.0: 0.215, 2471.0: 0.159}  # µm, starved by 0.8 µm (physics.md, seed 003)


def resident_peak_mib():
    """This process's resident high-water mark since the last reset [MiB] (VmHWM)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    return math.nan


def reset_resident_peak():
    """Release the compiler's leftovers as the CLI does (`stored_models.release_memory`) and reset
    VmHWM to the present resident size (Linux: '5' into /proc/self/clear_refs)."""
    release_memory()
    Path("/proc/self/clear_refs").write_text("5")


def one_solve(grid, load, model):
    """Compile and run one solve here; a dict of the films [µm], times [s] and peaks [MiB]."""
    length, flat_length = SCENE["bearing.roller_length"], SCENE["profile.flat_length"]
    profile = with_raceway_edge(roller_profile(SCENE["profile.kind"], length=length, flat_length=flat_length,
                                               crown_radius=SCENE["profile.crown_radius"]),
                                SCENE["contact.raceway_edge_radius"])
    case = (RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"], LUBRICANT["effective_modulus"],
            profile, length, flat_length)

    def solve(w):
        if model == "flooded":
            return finite_line_film_krylov(w, *case, grid=(grid, grid))
        return starved_finite_line_film(w, *case, SCENE["operating.oil_layer"], grid=(grid, grid))

    start = time.perf_counter()
    compiled = jax.jit(solve).lower(load).compile(COMPILER_OPTIONS)
    compile_s = time.perf_counter() - start
    compile_peak = resident_peak_mib()
    reset_resident_peak()
    start = time.perf_counter()
    film = jax.block_until_ready(compiled(load))
    return dict(central=float(film.central) * 1e6, minimum=float(film.minimum) * 1e6,
                converged=bool(film.converged), compile_s=compile_s, run_s=time.perf_counter() - start,
                compile_peak=compile_peak, run_peak=resident_peak_mib())


def observed_order(coarse, middle, fine):
    """(order, extrapolated value) of three values on grids halving their spacing; NaN where the
    changes do not shrink with the spacing (not in the asymptotic range)."""
    if (middle - coarse) * (fine - middle) <= 0 or abs(middle - coarse) <= abs(fine - middle):
        return math.nan, math.nan
    ratio = (middle - coarse) / (fine - middle)
    order = math.log2(ratio)
    return order, fine + (fine - middle) / (ratio - 1.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[65, 129, 257])
    parser.add_argument("--loads", type=float, nargs="+", default=[1028.0, 1607.0, 2471.0])
    parser.add_argument("--one", nargs=3, metavar=("GRID", "LOAD", "MODEL"), help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.one:
        grid, load, model = arguments.one
        print(json.dumps(one_solve(int(grid), float(load), model)))
        return
    print(f"`python benchmarks/starved_finite_line.py` on {machine()}; each solve in its own process, "
          "compiled with XLA's loop emitters (`newton_krylov.COMPILER_OPTIONS`)\n")
    print("| grid (half domain) | load | lubrication | h_c | h_min | converged | compile | run | peak compiling | "
          "peak running |\n|---|---|---|---|---|---|---|---|---|---|")
    films = {}
    for grid in arguments.grids:
        for load in arguments.loads:
            for model in ("flooded", "theta"):
                child = subprocess.run([sys.executable, __file__, "--one", str(grid), str(load), model],
                                       capture_output=True, text=True, check=True, cwd=Path(__file__).parent)
                row = json.loads(child.stdout.strip().splitlines()[-1])
                films[grid, load, model] = row
                print(f"| {grid} × {grid} | {load:g} N | {'flooded' if model == 'flooded' else 'starved 0.8 µm'} | "
                      f"{row['central']:.4f} µm | {row['minimum']:.4f} µm | {'yes' if row['converged'] else 'no'} | "
                      f"{row['compile_s']:.0f} s | {row['run_s']:.0f} s | {row['compile_peak'] / 1024:.2f} GiB | "
                      f"{row['run_peak'] / 1024:.2f} GiB |", flush=True)
    if len(arguments.grids) < 3:
        return
    print("\nGrid study (Richardson on the three finest grids where all three converged: observed order p, "
          "extrapolated value, – where the changes do not shrink with the spacing; the paper's starved minimum beside)\n")
    print("| load | lubrication | film | " + " | ".join(f"{g}²" for g in arguments.grids)
          + " | p | extrapolated | paper |\n|---|---|---|" + "---|" * (len(arguments.grids) + 3))
    for load in arguments.loads:
        for model in ("flooded", "theta"):
            for film in ("central", "minimum"):
                values = [films[g, load, model][film] for g in arguments.grids]
                converged = all(films[g, load, model]["converged"] for g in arguments.grids[-3:])
                order, extrapolated = observed_order(*values[-3:]) if converged else (math.nan, math.nan)
                paper = PAPER_MINIMUM.get(load) if (model, film) == ("theta", "minimum") else None
                lubrication = "flooded" if model == "flooded" else "starved"
                print(f"| {load:g} N | {lubrication} | h_{'c' if film == 'central' else 'min'} | "
                      + " | ".join(f"{v:.4f} µm" for v in values)
                      + (" | – | – |" if math.isnan(order) else f" | {order:.2f} | {extrapolated:.4f} µm |")
                      + f" {'' if paper is None else f'{paper} µm'} |")


if __name__ == "__main__":
    main()
