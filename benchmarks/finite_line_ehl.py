"""The starved-EHL paper's finite line contact (2-D, half domain, dense Newton), flooded and
starved: films, accuracy against time of every fidelity level, and the paper's numbers.

    python benchmarks/finite_line_ehl.py

Roller with a 12.7 mm flat and 10 mm crown radius, 14.7 mm long, on the outer raceway at
1000 r/min (docs/papers.md, §The starved-EHL paper). Writes benchmarks/results/finite_line_ehl.{md,png}:

1. accuracy against time at 1028 N, flooded and starved by h_oil = 0.8 µm: the formulas, the 1-D
   line contact (129 and 513 nodes), the dense 2-D solver on 25, 33 and 41 × 48 and the public
   scene's grid [65, 129] (65 × 65 on the half domain, the finest it takes), and the matrix-free
   Newton–Krylov on uniform cells (starved: the meniscus model at 129 × 129, the mass-conserving
   θ-model at 129 × 129 and 257 × 257), each against the Newton–Krylov at the paper's grid
   (257 × 257 on the half domain): flooded, and starved by the θ-model;
2. the paper's minimum films at 0.8 µm for 1028 / 1607 / 2471 N (33 × 48; 65 × 65 without 2471 N),
   through the load continuation where Newton at the load fails;
3. the starvation criterion Er at h_oil = 1.8 and 2.0 µm (33 × 48): from the 1-D start, as the
   CLI runs it, and at 1.8 µm by a continuation in the oil layer from 2.0 µm (warm starts); the
   1-D line contact's Er alike, and the oil layer the flooded films carry.

2-D grids are named by the half domain they solve, nx × ⌈ny/2⌉: a scene's fidelity.grid [nx, ny]
counts the whole roller, so 33 × 48 here is [33, 96] and 65 × 65 is [65, 129].

Times: formulas and 1-D levels median of 5 runs after compilation, the 2-D solves one run each
(tens of seconds); compile separately. One CPU process.
"""

import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from line_ehl import FLAT_LENGTH, LOAD, LUBRICANT, RADIUS, SPEED, formula_rows  # noqa: E402
from timing import median_time  # noqa: E402

from diffbearing.bearings.roller.roller_profile import roller_profile  # noqa: E402
from diffbearing.film.finite_line_ehl import finite_line_film  # noqa: E402
from diffbearing.film.finite_line_krylov import finite_line_film_krylov  # noqa: E402
from diffbearing.film.line_ehl import density_ratio, line_film  # noqa: E402
from diffbearing.film.starved_finite_line import starved_finite_line_film  # noqa: E402
from diffbearing.newton_krylov import COMPILER_OPTIONS  # noqa: E402

PROFILE = roller_profile("circular", length=14.7e-3, flat_length=FLAT_LENGTH, crown_radius=10e-3)
ROLLER_LOAD = LOAD * FLAT_LENGTH
OIL_LAYER = 0.8e-6
GRIDS = ((25, 48), (33, 48), (41, 48))
REFERENCE_GRID = (65, 65)  # the public scene's [65, 129]
# Newton–Krylov levels by oil layer (name, solver, grid), the last the accuracy reference: the paper's grid
KRYLOV_LEVELS = {None: (("Newton–Krylov", finite_line_film_krylov, (129, 129)),
                        ("Newton–Krylov", finite_line_film_krylov, (257, 257))),
                 OIL_LAYER: (("Newton–Krylov, meniscus", finite_line_film_krylov, (129, 129)),
                             ("Newton–Krylov, θ-model", starved_finite_line_film, (129, 129)),
                             ("Newton–Krylov, θ-model", starved_finite_line_film, (257, 257)))}
# (grid, loads [N], oil layers [m]): on 65 × 65, 2471 N and the Er pair are left out of this run:
# 2471 N spent over 10 minutes in the continuation's first stage (1606 N) without converging
# (docs/validation/lubricant_film.md, §The paper's starved minimum films), and the Er pair's
# oil-layer continuation would take about 10 minutes there
PAPER_CASES = (((33, 48), (1028.0, 1607.0, 2471.0), (1.8e-6, 2.0e-6)),
               (REFERENCE_GRID, (1028.0, 1607.0), ()))
CONTINUATION_STEP = 0.02e-6  # the oil-layer continuation's step [m] (the Er pair)
PAPER_MINIMUM = {1028.0: 0.319e-6, 1607.0: 0.215e-6, 2471.0: 0.159e-6}
RESULTS = Path(__file__).resolve().parent / "results"


def finite_line_solver(grid, oil_layer, solver=finite_line_film, **options):
    """(compiled W → FiniteLineFilm, compile time [s]); `options` go to `solver`; a Newton–Krylov
    compiled with XLA's options for it (`newton_krylov.COMPILER_OPTIONS`), as the CLI does."""
    start = time.perf_counter()
    solve = jax.jit(lambda w: solver(w, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
                                     LUBRICANT["effective_modulus"], PROFILE, 14.7e-3, FLAT_LENGTH, grid=grid,
                                     oil_layer=oil_layer, **options))
    solve = solve.lower(ROLLER_LOAD).compile(None if solver is finite_line_film else COMPILER_OPTIONS)
    return solve, time.perf_counter() - start


def timed(solve, load):
    start = time.perf_counter()
    result = jax.block_until_ready(solve(load))
    return result, time.perf_counter() - start


def level_rows(oil_layer):
    """(level, central, minimum, converged, run [s], compile [s]) at 1028 N; the reference last."""
    rows = [(name, central, minimum, True, run, compile_s)
            for name, central, minimum, run, compile_s in formula_rows(oil_layer)]
    for nodes in (129, 513):
        start = time.perf_counter()
        solve = jax.jit(lambda w, n=nodes: line_film(w, RADIUS, SPEED, nodes=n, oil_layer=oil_layer, **LUBRICANT))
        solve = solve.lower(LOAD).compile()
        compile_s = time.perf_counter() - start
        result = solve(LOAD)
        rows.append((f"1-D line EHL, {nodes} nodes", float(result.central), float(result.minimum),
                     bool(result.converged), median_time(lambda: solve(LOAD), 5), compile_s))
        print(rows[-1], flush=True)
    for grid in (*GRIDS, REFERENCE_GRID):
        solve, compile_s = finite_line_solver(grid, oil_layer)
        result, run = timed(solve, ROLLER_LOAD)
        rows.append((f"2-D finite line, {grid[0]} × {grid[1]}", float(result.central), float(result.minimum),
                     bool(result.converged), run, compile_s))
        print(rows[-1], flush=True)
    for name, solver, grid in KRYLOV_LEVELS[oil_layer]:
        solve, compile_s = finite_line_solver(grid, oil_layer, solver=solver)
        result, run = timed(solve, ROLLER_LOAD)
        rows.append((f"2-D finite line, {name}, {grid[0]} × {grid[1]}", float(result.central),
                     float(result.minimum), bool(result.converged), run, compile_s))
        print(rows[-1], flush=True)
    return rows


def run_time(seconds):
    """A run time with its unit: seconds from 1 s up, milliseconds below."""
    return f"{seconds:.1f} s" if seconds >= 1.0 else f"{seconds * 1e3:.3g} ms"


def accuracy_table(title, rows):
    reference, reference_central, reference_minimum, *_ = rows[-1]
    lines = [f"### {title} (reference: {reference})", "",
             "| level | central film | minimum film | central vs reference | minimum vs reference | converged | run | compile |",
             "|---|---|---|---|---|---|---|---|"]
    for name, central, minimum, converged, run, compile_s in rows:
        minimum_text = "–" if np.isnan(minimum) else f"{minimum * 1e6:.4f} µm"
        minimum_error = "–" if np.isnan(minimum) else f"{(minimum / reference_minimum - 1) * 100:+.1f} %"
        lines.append(f"| {name} | {central * 1e6:.4f} µm | {minimum_text} | "
                     f"{(central / reference_central - 1) * 100:+.2f} % | {minimum_error} | "
                     f"{'yes' if converged else 'NO'} | {run_time(run)} | {compile_s:.1f} s |")
    return lines + [""]


def plot(flooded, starved, path):
    figure, axes = plt.subplots(1, 2, figsize=(13, 4.2), layout="constrained")
    for axis, (title, rows) in zip(axes, (("fully flooded", flooded), ("starved, h_oil = 0.8 µm", starved))):
        reference_name, reference_central, reference_minimum, *_ = rows[-1]
        for index, (name, central, minimum, _, run, _) in enumerate(rows[:-1]):
            for value, reference, marker in ((central, reference_central, "o"), (minimum, reference_minimum, "s")):
                if not np.isnan(value):
                    axis.loglog(run, abs(value / reference - 1) * 100, marker, color=f"C{index}",
                                label=name if marker == "o" else None)
        axis.set(xlabel="wall time per solve [s]", ylabel="error against the reference [%]",
                 title=f"{title}: ○ central film, □ minimum film\nreference: {reference_name.removeprefix('2-D finite line, ')}")
        axis.grid(alpha=0.3, which="both")
    figure.legend(*axes[0].get_legend_handles_labels(), loc="outside right upper", fontsize=7)  # flooded: every level
    figure.suptitle("The starved-EHL paper's roller contact at 1028 N: what accuracy costs in time")
    figure.savefig(path, dpi=120)
    plt.close(figure)


def oil_carried(film):
    """The oil layer [m] the film carries, ρ̄h at the pressure peak (∂p/∂x = 0) on y = 0: a
    mass-conserving contact supplied with more stays flooded there."""
    pressure, thickness = (np.asarray(a).reshape(a.shape[0], -1)[:, 0] for a in (film.pressure, film.thickness))
    peak = np.argmax(pressure)
    return float(density_ratio(pressure[peak])) * thickness[peak]


def starvation_criterion(grid, layers):
    """Markdown lines: Er = 1 − h_c/h_c,ff at 1028 N on `grid` for each oil layer, from the 1-D start
    (what the CLI runs) and, for the thinnest, by a continuation in the oil layer from the thickest
    (warm starts, `start=`); the 1-D line contact's Er alike; the oil the flooded films carry."""
    flooded = finite_line_solver(grid, None)[0](ROLLER_LOAD)
    flooded_line = line_film(LOAD, RADIUS, SPEED, nodes=129, **LUBRICANT)
    name = f"{grid[0]} × {grid[1]}"
    lines = ["", f"### Starvation criterion Er = 1 − h_c/h_c,ff at 1028 N, {name} (paper: < 1 % at 2.0 µm, "
             "> 1 % at 1.8 µm)", "",
             f"Oil carried by the flooded film, ρ̄h at the pressure peak on y = 0: 2-D {name} "
             f"{oil_carried(flooded) * 1e6:.3f} µm, 1-D 129 nodes {oil_carried(flooded_line) * 1e6:.3f} µm. Above it "
             "the centre stays flooded (Er = 0 there); only the crowned ends, whose gap is wider, starve.", "",
             "| level | h_oil | central film | Er | minimum film | flooded y cells | converged | run |",
             "|---|---|---|---|---|---|---|---|"]

    def row(level, layer, result, reference, run):
        flooded_cells = int(np.sum(np.asarray(result.meniscus) <= float(result.x[0]) + 1e-12)) \
            if np.ndim(result.meniscus) else "–"  # 2-D: menisci on the inlet
        lines.append(f"| {level} | {layer * 1e6:.2f} µm | {float(result.central) * 1e6:.4f} µm | "
                     f"{(1 - float(result.central) / float(reference.central)) * 100:.3f} % | "
                     f"{float(result.minimum) * 1e6:.4f} µm | {flooded_cells} | "
                     f"{'yes' if bool(result.converged) else 'NO'} | {'–' if np.isnan(run) else f'{run:.1f} s'} |")
        print(lines[-1], flush=True)

    from_line_start = {}
    for layer in layers:
        from_line_start[layer], run = timed(finite_line_solver(grid, layer)[0], ROLLER_LOAD)
        row(f"2-D {name}, from the 1-D start", layer, from_line_start[layer], flooded, run)
    warm = jax.jit(lambda layer, previous: finite_line_film(
        ROLLER_LOAD, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
        LUBRICANT["effective_modulus"], PROFILE, 14.7e-3, FLAT_LENGTH, grid=grid, oil_layer=layer, start=previous))
    start = time.perf_counter()
    result = from_line_start[max(layers)]
    for layer in np.arange(max(layers), min(layers) - 1e-9, -CONTINUATION_STEP)[1:]:
        result = jax.block_until_ready(warm(layer, result))
    row(f"2-D {name}, continued from {max(layers) * 1e6:.1f} µm (the row above) in steps of "
        f"{CONTINUATION_STEP * 1e6:.2f} µm, compile included",
        min(layers), result, flooded, time.perf_counter() - start)
    for layer in (1.35e-6, 1.38e-6, *layers):
        row("1-D line EHL, 129 nodes", layer, line_film(LOAD, RADIUS, SPEED, nodes=129, oil_layer=layer, **LUBRICANT),
            flooded_line, np.nan)
    return lines + [""]


def main():
    flooded, starved = level_rows(None), level_rows(OIL_LAYER)
    lines = ["# The starved-EHL paper's finite line contact (2-D): accuracy against time", "",
             "`python benchmarks/finite_line_ehl.py`: 1028 N, 1000 r/min, errors against the Newton–Krylov at the "
             "paper's grid (uniform cells, 257 × 257 on the half domain; starved: the mass-conserving θ-model, so a "
             "meniscus-model level's error is its model's and its grid's together); the dense Newton's 65 × 65 "
             "is the half domain of the public scene's grid [65, 129], the finest it takes. 2-D grids are "
             "named by the half domain solved. Formulas and 1-D: median of 5 runs; 2-D: one run. Formulas and 1-D at "
             "mid-length, load on the flat length; their minimum film is the one of the rolling direction (outlet "
             "constriction), not the roller-end one.", "",
             *accuracy_table("Fully flooded", flooded), *accuracy_table("Starved, h_oil = 0.8 µm", starved)]
    plot(flooded, starved, RESULTS / "finite_line_ehl.png")

    for grid, loads, layers in PAPER_CASES:
        name = f"{grid[0]} × {grid[1]}"
        solve, _ = finite_line_solver(grid, OIL_LAYER)
        lines += [f"### The paper's minimum films, h_oil = 0.8 µm, {name}", "",
                  "| load | starved central film | starved minimum film | at y | paper | difference | converged | run |",
                  "|---|---|---|---|---|---|---|---|"]
        for load in loads:
            paper = PAPER_MINIMUM[load]
            result, run = timed(solve, load)
            lines.append(f"| {load:.0f} N | {float(result.central) * 1e6:.4f} µm | {float(result.minimum) * 1e6:.4f} µm | "
                         f"{float(result.minimum_position) * 1e3:.3f} mm | {paper * 1e6:.3f} µm | "
                         f"{(float(result.minimum) / paper - 1) * 100:+.1f} % | "
                         f"{'yes' if bool(result.converged) else 'NO'} | {run:.1f} s |")
            print(lines[-1], flush=True)
        if not layers:
            continue
        lines += starvation_criterion(grid, layers)
        lines.append("")
    text = "\n".join(lines) + "\n"
    (RESULTS / "finite_line_ehl.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
