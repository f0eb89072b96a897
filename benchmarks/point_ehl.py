"""The numerical point contact against Hamrock–Dowson, and its films against the grid.

    python benchmarks/point_ehl.py [--grids 65 129] [--refinement 65 129 257]

Cases: circular contacts and elliptical ones (κ ≈ 3, 6 and 9) over a range of loads and speeds
(Moes M from 40 to 3500, L from 14 to 25, as the table prints them; steel, η₀ 0.08 Pa·s,
α 2.2e-8 1/Pa, Roelands, Dowson–Higginson); each solved on the half-domain grids nx × nx/2, in its own process
(time and peak memory its own). The refinement study takes one case through every grid of
`--refinement` and gives the observed order p = log₂(|f₁ − f₂| / |f₂ − f₃|) of the last three.
Writes benchmarks/results/point_ehl.md and point_ehl.png.
"""

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"
OIL = dict(viscosity=0.08, pressure_viscosity=2.2e-8, effective_modulus=2.26e11)
# (name, load [N], Rx [m], Ry [m], u [m/s])
CASES = (
    ("circle, light", 50.0, 10e-3, 10e-3, 1.0),
    ("circle, fast", 50.0, 10e-3, 10e-3, 3.0),
    ("κ ≈ 3, medium", 300.0, 8e-3, 40e-3, 2.0),
    ("κ ≈ 9, medium", 500.0, 5.4e-3, 0.165, 5.0),
    ("κ ≈ 9, heavy", 3000.0, 5.4e-3, 0.165, 5.0),
    ("κ ≈ 6, outer race", 5500.0, 17.23e-3, 0.2826, 7.07),
)
REFINEMENT_CASE = 3


def moes(load, radius, speed):
    """(M, L) of Moes for the point contact: M = W (2U)^(−3/4), L = G (2U)^(1/4), U = η₀u/(E'Rx),
    W = Q/(E'Rx²), G = αE' (Venner & Lubrecht, Multilevel Methods in Lubrication, 2000)."""
    modulus = OIL["effective_modulus"]
    speed_group = OIL["viscosity"] * speed / (modulus * radius)
    return (load / (modulus * radius**2) * (2 * speed_group) ** -0.75,
            OIL["pressure_viscosity"] * modulus * (2 * speed_group) ** 0.25)


def one_case(index, nx):
    """Runs in a child process: one compiled solve, printed as one JSON line."""
    import jax

    jax.config.update("jax_enable_x64", True)
    from timing import compiled_with_time, peak_rss_mib

    from diffbearing.contact.hertz import point_contact
    from diffbearing.film.film_formulas import hamrock_dowson_point
    from diffbearing.film.point_ehl import point_film

    _, load, rx, ry, speed = CASES[index]
    compiled, compile_time = compiled_with_time(
        lambda q: point_film(q, rx, ry, speed, **OIL, grid=(nx, (nx - 1) // 2)), load)
    start = time.perf_counter()
    film = jax.block_until_ready(compiled(load))
    run = time.perf_counter() - start
    curvature_sum = 1 / rx + 1 / ry
    contact = point_contact(load, curvature_sum, (1 / rx - 1 / ry) / curvature_sum, OIL["effective_modulus"])
    central, minimum = hamrock_dowson_point(load, rx, contact.ellipticity, speed, **OIL)
    print(json.dumps(dict(case=index, nx=nx, ny=(nx - 1) // 2, central=float(film.central) * 1e6,
                          minimum=float(film.minimum) * 1e6, hd_central=float(central) * 1e6,
                          hd_minimum=float(minimum) * 1e6, kappa=float(contact.ellipticity),
                          pressure=float(contact.max_pressure) / 1e9, converged=bool(film.converged), run=run,
                          compile=compile_time, peak=peak_rss_mib())))


def solve(index, nx):
    output = subprocess.run([sys.executable, __file__, "--case", str(index), str(nx)], capture_output=True, text=True,
                            check=True).stdout
    row = json.loads(output.strip().splitlines()[-1])
    print(row, flush=True)
    return row


def order(values):
    """Observed order of convergence of the last three values on grids halved in spacing."""
    first, second, third = values[-3:]
    return math.log2(abs(first - second) / abs(second - third)) if abs(second - third) > 0 else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[65, 129])
    parser.add_argument("--refinement", type=int, nargs="+", default=[65, 129, 257])
    parser.add_argument("--case", type=int, nargs=2, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.case:
        return one_case(*arguments.case)
    from timing import machine

    rows = [solve(index, nx) for index in range(len(CASES)) for nx in arguments.grids]
    refinement = [next((r for r in rows if r["case"] == REFINEMENT_CASE and r["nx"] == nx), None)
                  or solve(REFINEMENT_CASE, nx) for nx in arguments.refinement]
    lines = ["# Point contact EHL against Hamrock–Dowson", "",
             f"`python benchmarks/point_ehl.py` on {machine()}: each solve in its own process; peak memory is the "
             "process's resident peak, compilation included. Grid: nx nodes along rolling × ny cells on the half "
             "domain. HD: Hamrock & Dowson (1977) at the same κ.", "",
             "| case | M | L | κ | p₀ | grid | h_c | h_c / HD | h_min | h_min / HD | converged | run | compile | peak |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        name, load, rx, _, speed = CASES[row["case"]]
        m, l = moes(load, rx, speed)
        lines.append(f"| {name} | {m:.0f} | {l:.1f} | {row['kappa']:.2f} | {row['pressure']:.2f} GPa | "
                     f"{row['nx']} × {row['ny']} | {row['central']:.4f} µm | {row['central'] / row['hd_central']:.3f} | "
                     f"{row['minimum']:.4f} µm | {row['minimum'] / row['hd_minimum']:.3f} | "
                     f"{'yes' if row['converged'] else 'no'} | {row['run']:.1f} s | {row['compile']:.1f} s | "
                     f"{row['peak'] / 1024:.2f} GiB |")
    name = CASES[REFINEMENT_CASE][0]
    lines += ["", f"## Against the grid: {name}", "",
              "| grid | h_c | h_min | run | peak |", "|---|---|---|---|---|"]
    for row in refinement:
        lines.append(f"| {row['nx']} × {row['ny']} | {row['central']:.4f} µm | {row['minimum']:.4f} µm | "
                     f"{row['run']:.1f} s | {row['peak'] / 1024:.2f} GiB |")
    if len(refinement) >= 3:
        lines += ["", f"Observed order: h_c {order([r['central'] for r in refinement]):.2f}, "
                      f"h_min {order([r['minimum'] for r in refinement]):.2f}."]
    (RESULTS / "point_ehl.md").write_text("\n".join(lines) + "\n")
    plot(rows, refinement)


def plot(rows, refinement):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (ratio_axis, grid_axis) = plt.subplots(1, 2, figsize=(11, 4.2))
    for nx, marker in zip(sorted({r["nx"] for r in rows}), "os^v"):
        chosen = [r for r in rows if r["nx"] == nx]
        ms = [moes(*CASES[r["case"]][1:3], CASES[r["case"]][4])[0] for r in chosen]
        ratio_axis.scatter(ms, [r["central"] / r["hd_central"] for r in chosen], marker=marker,
                           label=f"h_c, {nx} × {(nx - 1) // 2}")
        ratio_axis.scatter(ms, [r["minimum"] / r["hd_minimum"] for r in chosen], marker=marker, facecolors="none",
                           edgecolors="k", label=f"h_min, {nx} × {(nx - 1) // 2}")
    failed = [r for r in rows if not r["converged"]]
    if failed:
        ms = [moes(*CASES[r["case"]][1:3], CASES[r["case"]][4])[0] for r in failed]
        ratio_axis.scatter(ms + ms, [r["central"] / r["hd_central"] for r in failed]
                           + [r["minimum"] / r["hd_minimum"] for r in failed], marker="x", s=90, color="red",
                           label="not converged (last iterate)")
    for level in (0.9, 1.1):
        ratio_axis.axhline(level, color="grey", ls="--", lw=0.8)
    ratio_axis.set(xscale="log", xlabel="Moes M", ylabel="numerical / Hamrock–Dowson",
                   title="flooded films against Hamrock–Dowson")
    ratio_axis.legend(fontsize=8)
    spacing = [6.0 / (r["nx"] - 1) for r in refinement]
    grid_axis.plot(spacing, [r["central"] for r in refinement], "o-", label="h_c")
    grid_axis.plot(spacing, [r["minimum"] for r in refinement], "s-", label="h_min")
    grid_axis.set(xscale="log", xlabel="Δx / b_r", ylabel="film [µm]", title=f"{CASES[REFINEMENT_CASE][0]}: grid")
    grid_axis.legend()
    for axis in (ratio_axis, grid_axis):
        axis.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(RESULTS / "point_ehl.png", dpi=110)


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    main()
