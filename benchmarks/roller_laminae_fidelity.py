"""Roller bearing laminae: accuracy against time, with the influence-coefficient contact as reference.

    python benchmarks/roller_laminae_fidelity.py [--bearing tapered|needle] [--laminae 10 20 30 50 100] [--repeats 15]

tapered (default): seed 004's tapered bearing (roller d/D = 7.0/8.0 mm, l = 12 mm, θ = 2.4°, Johns–Gohar
at 1 kN, E = 207 GPa, ν = 0.29; Z = 18, cup angle 15°, d_m = 50.7 mm, zero clearance), static, Fr = 4 kN
and Fa = 2 kN with the inner ring's misalignment imposed: [0, 0.5 mrad] (misaligned) and [0, 0] (aligned).
needle: the needle_roller_shaft example's needle roller bearing (26 needles of 3 × 13 mm, circular crown
flat 9 mm, Rc = 0.5 m, d_m = 33 mm, 15 µm clearance), Fr = 3.35 kN (its load in the example), misalignment
[0, 2′] (its permissible tilt) and [0, 0].
For each laminae count n the whole bearing is solved (equilibrium, 5×5 stiffness, per-roller results)
under jit; the time is the median of `repeats` calls after compilation (compile apart).

Reference: at the 100-lamina load distribution, the most loaded roller's inner contact (load and
tilt from `roller_contact_loadings`) re-solved by influence coefficients (`roller_contact`,
"influence", which has the edge peaks a lamina model smooths over) on the grids of GRIDS, the finest
the reference (the coarser ones show its grid convergence). Errors:
  * peak pressure of that contact: the laminae' largest Hertz line pressure against the reference;
  * that roller's inner load and the 5×5 stiffness (scaled to N/m) against 100 laminae.
Writes benchmarks/results/roller_laminae_fidelity.{json,md,png} (the needle's: roller_laminae_fidelity_needle.*).
"""

import argparse
import json
import sys
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from roller_bearing import tapered  # noqa: E402
from timing import compiled_with_time, machine, median_time  # noqa: E402

from diffbearing import needle_roller_bearing, needle_roller_raceways, roller_profile  # noqa: E402
from diffbearing.bearings.roller.needle_roller import PERMISSIBLE_MISALIGNMENT  # noqa: E402
from diffbearing.bearings.roller.roller_contact import roller_contact  # noqa: E402
from diffbearing.bearings.roller.roller_equilibrium import (  # noqa: E402
    RollerModel,
    RollerOperating,
    roller_contact_loadings,
    roller_results,
    roller_stiffness_matrix,
    solve_roller_equilibrium,
)

RESULTS = Path(__file__).resolve().parent / "results"
GRIDS = [(16, 128), (32, 256), (32, 512), (64, 1024), (128, 2048)]



def needle():
    """The needle_roller_shaft example's needle roller bearing and its case."""
    length = 13e-3
    bearing = needle_roller_bearing(roller_diameter=3e-3, roller_length=length, rollers=26,
                                    profile=roller_profile("circular", length=length, flat_length=9e-3, crown_radius=0.5))
    return dict(bearing=bearing, raceways=needle_roller_raceways(bearing, pitch_diameter=33e-3, diametral_clearance=15e-6),
                force=[3.35e3, 0.0, 0.0], cases={"misaligned": [0.0, PERMISSIBLE_MISALIGNMENT], "aligned": [0.0, 0.0]},
                label="the needle_roller_shaft example's needle roller bearing, Z = 26, 3 × 13 mm, d_m = 33 mm, 15 µm "
                      "clearance, static, Fr 3.35 kN", title="Needle roller bearing (Z = 26, 3 × 13 mm), Fr 3.35 kN",
                suffix="_needle")


def tapered_case():
    return dict(**{key: tapered()[key] for key in ("bearing", "raceways")}, force=[4e3, 0.0, 2e3],
                cases={"misaligned": [0.0, 5e-4], "aligned": [0.0, 0.0]},
                label="Seed 004's tapered bearing, Z = 18, α_o = 15°, d_m = 50.7 mm, static, Fr 4 kN, Fa 2 kN",
                title="Tapered roller bearing (seed 004, Z = 18), Fr 4 kN, Fa 2 kN", suffix="")


SETUPS = {"tapered": tapered_case, "needle": needle}


def bearing_case(laminae, bearing, raceways):
    model = RollerModel(laminae=laminae)

    def case(force, misalignment):
        operating = RollerOperating(force=force, moment=jnp.zeros(2), misalignment=misalignment)
        solution = solve_roller_equilibrium(bearing, raceways, operating, model)
        stiffness = roller_stiffness_matrix(solution.displacement, bearing, raceways, operating, model)
        results = roller_results(solution.displacement, bearing, raceways, operating, model)
        return (solution.displacement, solution.converged, stiffness, results.inner_load, results.inner_max_pressure,
                results.inner_lamina_load)

    return case, model


def bin_loads(pressure, x, y, length, bins):
    """Load [N] of `bins` equal lengths along the roller from an influence pressure field (nx, ny):
    Σ_x p Δx Δy per cell column, accumulated along y and cut at the bin edges (linear inside a cell)."""
    pressure, x, y = (np.asarray(a) for a in (pressure, x, y))
    dy = y[1] - y[0]
    column = pressure.sum(axis=0) * (x[1] - x[0]) * dy
    edges = np.concatenate([[y[0] - 0.5 * dy], y + 0.5 * dy])
    cumulative = np.concatenate([[0.0], np.cumsum(column)])
    cuts = np.linspace(-0.5 * length, 0.5 * length, bins + 1)
    return np.diff(np.interp(cuts, edges, cumulative))


def distribution_error(loads, reference):
    """Largest difference of two load distributions over the same bins, against the reference's largest bin."""
    return float(np.max(np.abs(np.asarray(loads) - reference)) / np.max(reference))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bearing", choices=tuple(SETUPS), default="tapered")
    parser.add_argument("--laminae", type=int, nargs="+", default=[10, 20, 30, 50, 100])
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args()
    finest = max(args.laminae)
    setup = SETUPS[args.bearing]()
    bearing, raceways = setup["bearing"], setup["raceways"]
    force = jnp.asarray(setup["force"])
    scale = np.diag([1.0, 1.0, 1.0, 2.0 / float(raceways.pitch_diameter), 2.0 / float(raceways.pitch_diameter)])
    document = {"machine": machine(), "force": setup["force"], "grids": GRIDS, "cases": {}, "title": setup["title"]}
    command = "python benchmarks/roller_laminae_fidelity.py" + ("" if args.bearing == "tapered" else f" --bearing {args.bearing}")
    lines = ["# Roller bearing laminae: accuracy against time", "",
             f"`{command}` ({machine()}). {setup['label']}, misalignment imposed. Time: equilibrium + 5×5 stiffness + "
             f"per-roller results under jit, median of {args.repeats} after compilation. Reference: the most loaded "
             f"roller's inner contact at the {finest}-lamina load distribution, re-solved by influence coefficients on "
             f"{GRIDS[-1][0]} × {GRIDS[-1][1]}."]
    for name, misalignment in setup["cases"].items():
        misalignment = jnp.asarray(misalignment)
        rows = {}
        for laminae in sorted(args.laminae):
            case, model = bearing_case(laminae, bearing, raceways)
            compiled, compile_s = compiled_with_time(case, force, misalignment)
            out = jax.block_until_ready(compiled(force, misalignment))
            run_s = median_time(lambda: compiled(force, misalignment), args.repeats)
            rows[laminae] = dict(model=model, out=out, run_s=run_s, compile_s=compile_s)
            print(name, laminae, f"{run_s * 1e3:.2f} ms", bool(out[1]), flush=True)
        best = rows[finest]
        roller = int(np.argmax(np.asarray(best["out"][3])))
        operating = RollerOperating(force=force, moment=jnp.zeros(2), misalignment=misalignment)
        inner, _ = roller_contact_loadings(best["out"][0], roller, bearing, raceways, operating, best["model"])
        influence, fields = [], []
        length = float(bearing.length)
        for grid in GRIDS:
            compiled, compile_s = compiled_with_time(lambda b, l: roller_contact(b, l, grid, "influence"), bearing, inner)
            result = jax.block_until_ready(compiled(bearing, inner))
            repeats = 5 if grid[0] * grid[1] <= 64 * 1024 else 3
            run_s = median_time(lambda: compiled(bearing, inner), repeats)
            influence.append(dict(grid=list(grid), run_s=run_s, compile_s=compile_s,
                                  max_pressure=float(result.max_pressure), approach=float(result.approach),
                                  converged=bool(result.converged), iterations=int(result.iterations)))
            fields.append((result.pressure, result.x, result.y))
            print(name, grid, f"{run_s * 1e3:.1f} ms", influence[-1], flush=True)
        reference = influence[-1]["max_pressure"]
        finest_bins = bin_loads(*fields[-1], length, finest)
        for entry, field in zip(influence, fields):
            entry["error_vs_finest"] = abs(entry["max_pressure"] / reference - 1)
            entry["distribution_error_vs_finest"] = distribution_error(bin_loads(*field, length, finest), finest_bins)
        k_best = scale @ np.asarray(best["out"][2]) @ scale
        q_best = float(best["out"][3][roller])
        table = []
        for laminae, row in rows.items():
            d, converged, k, q, p, line = row["out"]
            k = scale @ np.asarray(k) @ scale
            lamina_bins = np.asarray(line[roller]) * length / laminae
            table.append(dict(
                laminae=laminae, run_s=row["run_s"], compile_s=row["compile_s"], converged=bool(converged),
                max_pressure=float(p[roller]), error_pressure=abs(float(p[roller]) / reference - 1),
                roller_load=float(q[roller]), error_roller_load=abs(float(q[roller]) / q_best - 1),
                error_stiffness=float(np.max(np.abs(k - k_best)) / np.max(np.abs(k_best))),
                error_distribution=distribution_error(lamina_bins, bin_loads(*fields[-1], length, laminae)),
                displacement=np.asarray(d).tolist()))
        document["cases"][name] = dict(misalignment=np.asarray(misalignment).tolist(), roller=roller,
                                       roller_load=q_best, roller_tilt_inner=float(inner.tilt), laminae=table,
                                       influence=influence)
        lines += ["", f"## {name}: misalignment [{float(misalignment[0]) * 1e3:g}, {float(misalignment[1]) * 1e3:g}] mrad",
                  "", f"Most loaded roller: {roller} (ψ = {360 * roller / bearing.roller_count:.0f}°), inner load "
                  f"{q_best:.1f} N, tilt against the inner raceway {float(inner.tilt) * 1e3:.3f} mrad; influence peak pressure "
                  f"{reference / 1e9:.4f} GPa.", "",
                  "| model | time | compile | peak pressure | error vs influence | lamina loads vs influence | roller load "
                  f"error vs {finest} | stiffness change vs {finest} |", "|---|---|---|---|---|---|---|---|"]
        for row in table:
            lines.append(f"| {row['laminae']} laminae | {row['run_s'] * 1e3:.2f} ms | {row['compile_s']:.1f} s | "
                         f"{row['max_pressure'] / 1e9:.4f} GPa | {row['error_pressure']:.1%} | {row['error_distribution']:.1%} | "
                         f"{row['error_roller_load']:.1e} | "
                         f"{row['error_stiffness']:.1e} |")
        for entry in influence:
            lines.append(f"| influence {entry['grid'][0]}×{entry['grid'][1]} (one contact) | {entry['run_s'] * 1e3:.1f} ms | "
                         f"{entry['compile_s']:.1f} s | {entry['max_pressure'] / 1e9:.4f} GPa | "
                         f"{entry['error_vs_finest']:.2%} (vs finest grid) | {entry['distribution_error_vs_finest']:.2%} "
                         f"({finest} bins, vs finest grid) | – | – |")
    plot(document, setup["suffix"])
    table = "\n".join(lines)
    print(table)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / f"roller_laminae_fidelity{setup['suffix']}.md").write_text(table + "\n")
    (RESULTS / f"roller_laminae_fidelity{setup['suffix']}.json").write_text(json.dumps(document, indent=1) + "\n")


def plot(document, suffix):
    figure, axes = plt.subplots(1, len(document["cases"]), figsize=(12, 4.8), sharey=True)
    for axis, (name, case) in zip(np.atleast_1d(axes), document["cases"].items()):
        rows = case["laminae"]
        finest = max(r["laminae"] for r in rows)
        times = [r["run_s"] * 1e3 for r in rows]
        axis.loglog(times, [r["error_pressure"] for r in rows], "o-", label="laminae: peak pressure vs influence")
        axis.loglog(times, [r["error_distribution"] for r in rows], "v-", label="laminae: lamina loads vs influence")
        partial = [r for r in rows if r["laminae"] != finest]
        axis.loglog([r["run_s"] * 1e3 for r in partial], [max(r["error_roller_load"], 1e-12) for r in partial], "s-",
                    label=f"laminae: roller load vs {finest}")
        axis.loglog([r["run_s"] * 1e3 for r in partial], [max(r["error_stiffness"], 1e-12) for r in partial], "^-",
                    label=f"laminae: stiffness vs {finest}")
        for i, r in enumerate(rows):
            axis.annotate(f"n={r['laminae']}", (r["run_s"] * 1e3, r["error_pressure"]), textcoords="offset points",
                          xytext=(-8, 7 if i % 2 == 0 else -13), fontsize=8)
        grids = case["influence"][:-1]
        axis.loglog([g["run_s"] * 1e3 for g in grids], [max(g["error_vs_finest"], 1e-12) for g in grids], "d--",
                    label="influence (one contact): peak pressure vs finest grid")
        axis.loglog([g["run_s"] * 1e3 for g in grids], [max(g["distribution_error_vs_finest"], 1e-12) for g in grids], "x--",
                    label=f"influence (one contact): {finest}-bin loads vs finest grid")
        for g in grids:
            axis.annotate(f"{g['grid'][0]}×{g['grid'][1]}", (g["run_s"] * 1e3, max(g["error_vs_finest"], 1e-12)),
                          textcoords="offset points", xytext=(4, -10), fontsize=8)
        misalignment = case["misalignment"]
        axis.set_title(f"{name}: misalignment [{misalignment[0] * 1e3:g}, {misalignment[1] * 1e3:g}] mrad")
        axis.set_xlabel("wall time per solve [ms] (jitted, after compilation)")
        axis.grid(True, which="both", alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel("relative error [-]")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    figure.suptitle(f"{document['title']}: laminae against influence coefficients")
    figure.tight_layout()
    figure.savefig(RESULTS / f"roller_laminae_fidelity{suffix}.png", dpi=120)


if __name__ == "__main__":
    main()
