"""Whole roller bearings: diffbearing (JAX) against the classical NumPy/SciPy solution.

    python benchmarks/roller_bearing.py [--cases 1000] [--scipy-cases 50] [--repeats 15]
                                        [--bearings tapered cylindrical] [--centrifugal-sweep map|vmap]

Two bearings, 30 laminae per roller, each without and with centrifugal force:
  * tapered: seed 004's roller (d/D = 7.0/8.0 mm, l = 12 mm, θ = 2.4°, Johns–Gohar at 1 kN, E = 207 GPa,
    ν = 0.29), Z = 18, cup angle 15°, d_m = 50.7 mm, zero clearance; moments free (5 unknowns);
    centrifugal force at 6000 r/min of the inner ring (at 10 000 r/min the lightest sweep loads,
    Fr 0.5 kN with Fa/Fr = 0.5, have no equilibrium with free moments: the tilt runs away, in both codes);
  * cylindrical: seed 003's 14 rollers of D = 25.4 mm, l = 14.7 mm (circular crown: flat 12.7 mm,
    Rc = 200 mm), d_m = 106.6 mm, 20 µm diametral clearance (4 unknowns); 6000 r/min.
Measured in one run on one machine:
  (a) one case (tapered: Fr 4 kN, Fa 2 kN; cylindrical: Fr 4 kN, My 5 N·m): equilibrium + 5×5 stiffness +
      roller loads, jitted (compile apart, median of `repeats`) against the SciPy baseline
      (benchmarks/scipy_roller_bearing.py), and the largest differences of Δ, roller loads and K;
  (b) a `cases`-point load sweep with stiffness (tapered: Fr 0.5…10 kN × Fa/Fr 0.5…2; cylindrical:
      Fr 0.5…10 kN × My/Fr 0…2 mm). JAX: one compile of jit(vmap(case)), median of 3 runs. SciPy: a
      loop over `scipy-cases` evenly spread sweep points, its total scaled to `cases` (an
      extrapolation, said so in the output). With centrifugal force diffbearing's solve does not
      finish under vmap (see docs/benchmarks.md, §Roller bearings), so by default the JAX sweep is
      jit(lax.map(case)) — one compile, cases one after another — timed on the SciPy subset and
      scaled the same way; `--centrifugal-sweep vmap` tries vmap (it hangs with the current solver).
Memory: XLA's buffers of one call of each executable (arguments + outputs + temporaries), the SciPy
case's peak NumPy heap (tracemalloc), and the process's peak resident memory.
Writes benchmarks/results/roller_bearing.{json,md}.
"""

import argparse
import json
import sys
import time
import warnings
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from scipy_roller_bearing import ClassicalRollerBearing  # noqa: E402
from timing import compiled_with_time, machine, median_time, peak_rss_mib, traced_peak_mib, xla_memory_mib  # noqa: E402

from diffbearing.bearings.roller.roller_equilibrium import (  # noqa: E402
    RollerModel,
    RollerOperating,
    roller_raceways,
    roller_results,
    roller_stiffness_matrix,
    solve_roller_equilibrium,
)
from diffbearing.bearings.roller.roller_geometry import roller_bearing  # noqa: E402
from diffbearing.bearings.roller.roller_profile import roller_profile  # noqa: E402
from diffbearing.params import Material  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
GCR15 = Material(207e9, 0.29, 7830.0)
LAMINAE = 30
RPM = np.pi / 30.0


def tapered():
    """Seed 004's tapered roller in an 18-roller bearing: (bearing, raceways, speed [rad/s], case, sweep)."""
    length = 12e-3
    bearing = roller_bearing(kind="tapered_roller", length=length, small_diameter=7e-3, large_diameter=8e-3,
                             cone_half_angle=np.radians(2.4), material=GCR15, roller_count=18,
                             profile=roller_profile("johns_gohar", length=length, design_load=1000.0))
    raceways = roller_raceways(bearing, pitch_diameter=50.7e-3, diametral_clearance=0.0, cup_angle=np.radians(15.0))
    radial, ratio = np.meshgrid(np.linspace(500.0, 10e3, 40), np.linspace(0.5, 2.0, 25), indexing="ij")
    forces = np.stack([radial.ravel(), 0 * radial.ravel(), (radial * ratio).ravel()], axis=1)
    return dict(bearing=bearing, raceways=raceways, speed=6000 * RPM, force=[4e3, 0.0, 2e3], moment=[0.0, 0.0],
                sweep_force=forces, sweep_moment=np.zeros((len(forces), 2)),
                label="tapered, Z = 18, seed 004 roller, α_o = 15°, d_m = 50.7 mm, zero clearance",
                case_label="Fr 4 kN, Fa 2 kN", sweep_label="Fr 0.5…10 kN (40) × Fa/Fr 0.5…2 (25)")


def cylindrical():
    """Seed 003's cylindrical roller bearing, 14 rollers, 20 µm clearance."""
    length = 14.7e-3
    bearing = roller_bearing(kind="cylindrical_roller", length=length, diameter=25.4e-3, material=GCR15, roller_count=14,
                             profile=roller_profile("circular", length=length, flat_length=12.7e-3, crown_radius=0.2))
    raceways = roller_raceways(bearing, pitch_diameter=106.6e-3, diametral_clearance=20e-6)
    radial, arm = np.meshgrid(np.linspace(500.0, 10e3, 40), np.linspace(0.0, 2e-3, 25), indexing="ij")
    forces = np.stack([radial.ravel(), 0 * radial.ravel(), 0 * radial.ravel()], axis=1)
    moments = np.stack([0 * radial.ravel(), (radial * arm).ravel()], axis=1)
    return dict(bearing=bearing, raceways=raceways, speed=6000 * RPM, force=[4e3, 0.0, 0.0], moment=[0.0, 5.0],
                sweep_force=forces, sweep_moment=moments,
                label="cylindrical, Z = 14, D = 25.4 mm, l = 14.7 mm, d_m = 106.6 mm, P_d = 20 µm",
                case_label="Fr 4 kN, My 5 N·m", sweep_label="Fr 0.5…10 kN (40) × My/Fr 0…2 mm (25)")


BEARINGS = {"tapered": tapered, "cylindrical": cylindrical}


def jax_case(setup, model):
    """case(force, moment) → (Δ, K, inner roller loads, converged), closed over the bearing."""
    bearing, raceways, speed = setup["bearing"], setup["raceways"], setup["speed"]

    def case(force, moment):
        operating = RollerOperating(force=force, moment=moment, inner_speed=speed)
        solution = solve_roller_equilibrium(bearing, raceways, operating, model)
        stiffness = roller_stiffness_matrix(solution.displacement, bearing, raceways, operating, model)
        loads = roller_results(solution.displacement, bearing, raceways, operating, model).inner_load
        return solution.displacement, stiffness, loads, solution.converged

    return case


def scipy_case(classical, guess):
    def case(force, moment):
        displacement, ok = classical.solve(np.asarray(force), np.asarray(moment), guess)
        stiffness = classical.stiffness(displacement)
        inner, _, _, _ = classical.results(displacement)
        return displacement, stiffness, inner, ok

    return case


def differences(scipy_out, jax_out, pitch_diameter):
    """Largest relative differences (Δ, roller loads, K): Δ with tilts × d_m/2 against its largest
    component, loads against the largest load, K scaled to N/m everywhere against its largest entry."""
    w = np.array([1.0, 1.0, 1.0, 0.5 * pitch_diameter, 0.5 * pitch_diameter])
    d_s, k_s, q_s = (np.asarray(a) for a in scipy_out[:3])
    d_j, k_j, q_j = (np.asarray(a) for a in jax_out[:3])
    scale = np.diag(1.0 / w)
    k_s, k_j = scale @ k_s @ scale, scale @ k_j @ scale
    return (float(np.max(np.abs((d_s - d_j) * w)) / np.max(np.abs(d_j * w))),
            float(np.max(np.abs(q_s - q_j)) / np.max(np.abs(q_j))),
            float(np.max(np.abs(k_s - k_j)) / np.max(np.abs(k_j))))


def measure(name, setup, centrifugal, args):
    model = RollerModel(laminae=LAMINAE, centrifugal=centrifugal)
    case = jax_case(setup, model)
    force, moment = jnp.asarray(setup["force"]), jnp.asarray(setup["moment"])
    report = {"bearing": name, "centrifugal": centrifugal, "speed_rpm": setup["speed"] / RPM if centrifugal else 0.0}

    # (a) one case
    compiled, compile_single = compiled_with_time(case, force, moment)
    repeats = args.repeats if not centrifugal else max(3, args.repeats // 3)
    jax_single = median_time(lambda: compiled(force, moment), repeats)
    jax_out = jax.block_until_ready(compiled(force, moment))

    classical = ClassicalRollerBearing.from_diffbearing(setup["bearing"], setup["raceways"], LAMINAE, setup["speed"],
                                                        centrifugal)
    guess = np.array([0.5 * float(setup["raceways"].diametral_clearance) + 1e-5, 0.0, 1e-5, 0.0, 0.0])
    reference = scipy_case(classical, guess)
    scipy_out = reference(setup["force"], setup["moment"])
    scipy_single = median_time(lambda: reference(setup["force"], setup["moment"]), repeats)
    scipy_memory = traced_peak_mib(lambda: reference(setup["force"], setup["moment"]))
    d_diff, q_diff, k_diff = differences(scipy_out, jax_out, float(setup["raceways"].pitch_diameter))
    report["single"] = dict(load=setup["case_label"], jax_s=jax_single, jax_compile_s=compile_single, scipy_s=scipy_single,
                            ratio=scipy_single / jax_single, jax_xla_memory_mib=xla_memory_mib(compiled),
                            scipy_peak_heap_mib=scipy_memory, jax_converged=bool(jax_out[3]), scipy_converged=bool(scipy_out[3]),
                            displacement=np.asarray(jax_out[0]).tolist(), stiffness=np.asarray(jax_out[1]).tolist(),
                            difference_displacement=d_diff, difference_roller_load=q_diff, difference_stiffness=k_diff)
    print(name, "centrifugal" if centrifugal else "static", report["single"], flush=True)

    # (b) the sweep
    forces, moments = setup["sweep_force"][:args.cases], setup["sweep_moment"][:args.cases]
    subset = np.unique(np.linspace(0, len(forces) - 1, args.scipy_cases).round().astype(int))
    batched = (jax.vmap(case) if not centrifugal or args.centrifugal_sweep == "vmap"
               else lambda f, m: jax.lax.map(lambda fm: case(*fm), (f, m)))
    jax_forces, jax_moments = (forces, moments) if not centrifugal or args.centrifugal_sweep == "vmap" else \
        (forces[subset], moments[subset])
    sweep_compiled, compile_sweep = compiled_with_time(batched, jax_forces, jax_moments)
    sweep_out = jax.block_until_ready(sweep_compiled(jax_forces, jax_moments))
    sweep_repeats = 3 if not centrifugal else 1
    jax_run = median_time(lambda: sweep_compiled(jax_forces, jax_moments), sweep_repeats)
    jax_cases = len(jax_forces)
    jax_sweep = jax_run * len(forces) / jax_cases

    times, diffs, failures, residuals = [], [], 0, [0.0]
    classical.roller_calls = classical.roller_flags = 0
    classical.roller_residual_max = 0.0
    for position, index in enumerate(subset):
        start = time.perf_counter()
        out = reference(forces[index], moments[index])
        times.append(time.perf_counter() - start)
        failures += not out[3]
        flags = (classical.roller_calls, classical.roller_flags, classical.roller_residual_max)
        if centrifugal:  # the rollers' balance at the solution (untimed; the flag counters restored)
            residuals.append(classical.max_roller_residual(out[0]))
            classical.roller_calls, classical.roller_flags, classical.roller_residual_max = flags
        row = position if jax_cases < len(forces) else index
        if out[3]:
            diffs.append(differences(out, [a[row] for a in sweep_out], float(setup["raceways"].pitch_diameter)))
    scipy_sweep = sum(times) / len(times) * len(forces)
    diffs = np.array(diffs) if diffs else np.full((1, 3), np.nan)
    report["sweep"] = dict(
        cases=len(forces), loads=setup["sweep_label"],
        jax_method="jit(vmap)" if jax_cases == len(forces) else f"jit(lax.map) on {jax_cases} cases, scaled to {len(forces)}",
        jax_s=jax_sweep, jax_measured_s=jax_run, jax_measured_cases=jax_cases, jax_repeats=sweep_repeats,
        jax_compile_s=compile_sweep, jax_xla_memory_mib=xla_memory_mib(sweep_compiled),
        jax_converged=int(np.sum(np.asarray(sweep_out[3]))),
        scipy_s=scipy_sweep, scipy_measured_s=float(sum(times)), scipy_measured_cases=len(subset),
        scipy_failures=failures, ratio=scipy_sweep / jax_sweep,
        scipy_roller_solves=classical.roller_calls, scipy_roller_solves_flagged=classical.roller_flags,
        scipy_roller_flagged_residual_max=classical.roller_residual_max, scipy_roller_residual_at_solution=max(residuals),
        difference_displacement=float(np.nanmax(diffs[:, 0])), difference_roller_load=float(np.nanmax(diffs[:, 1])),
        difference_stiffness=float(np.nanmax(diffs[:, 2])))
    print(name, "centrifugal" if centrifugal else "static", report["sweep"], flush=True)
    return report


def markdown(reports, args):
    lines = ["# Roller bearings against the SciPy baseline", "",
             f"`python benchmarks/roller_bearing.py` ({machine()}; {LAMINAE} laminae per roller). Single case: median of "
             f"{args.repeats} runs (static) or {max(3, args.repeats // 3)} (centrifugal) after compilation; sweep: "
             "median of 3 runs (static) or one run (centrifugal). SciPy's sweep time is its loop over "
             f"{args.scipy_cases} evenly spread sweep points scaled to the sweep: an extrapolation.", "",
             "| bearing | effects | measurement | diffbearing (JAX) | compile | NumPy/SciPy | ratio |",
             "|---|---|---|---|---|---|---|"]
    for r in reports:
        s, w = r["single"], r["sweep"]
        effect = f"centrifugal ({r['speed_rpm']:.0f} r/min)" if r["centrifugal"] else "static"
        lines.append(f"| {r['bearing']} | {effect} | one case ({s['load']}): Δ + K + roller loads | "
                     f"{s['jax_s'] * 1e3:.2f} ms | {s['jax_compile_s']:.1f} s | {s['scipy_s'] * 1e3:.1f} ms | "
                     f"{s['ratio']:.1f}× |")
        jax_note = "" if w["jax_measured_cases"] == w["cases"] else f" (lax.map, from {w['jax_measured_cases']} cases)"
        lines.append(f"| {r['bearing']} | {effect} | {w['cases']}-case sweep with K{jax_note} | {w['jax_s']:.2f} s "
                     f"({w['jax_s'] / w['cases'] * 1e3:.2f} ms/case) | {w['jax_compile_s']:.1f} s | {w['scipy_s']:.1f} s "
                     f"(from {w['scipy_measured_cases']} cases) | {w['ratio']:.1f}× |")
    lines += ["", "Same answers (largest relative difference; Δ with tilts × d_m/2, K scaled to N/m, each against its "
              "largest entry; the baseline's K is a central difference at h = 1e-11 m):", "",
              "| bearing | effects | one case: Δ / roller loads / K | sweep subset: Δ / roller loads / K | "
              "converged JAX / SciPy (sweep) | SciPy roller solves (flagged by MINPACK; worst scaled residual flagged / at the "
              "solutions) |", "|---|---|---|---|---|---|"]
    for r in reports:
        s, w = r["single"], r["sweep"]
        effect = "centrifugal" if r["centrifugal"] else "static"
        lines.append(f"| {r['bearing']} | {effect} | {s['difference_displacement']:.1e} / {s['difference_roller_load']:.1e} / "
                     f"{s['difference_stiffness']:.1e} | {w['difference_displacement']:.1e} / {w['difference_roller_load']:.1e}"
                     f" / {w['difference_stiffness']:.1e} | {w['jax_converged']}/{w['jax_measured_cases']} / "
                     f"{w['scipy_measured_cases'] - w['scipy_failures']}/{w['scipy_measured_cases']} | "
                     f"{w['scipy_roller_solves']} ({w['scipy_roller_solves_flagged']}; "
                     f"{w['scipy_roller_flagged_residual_max']:.0e} / {w['scipy_roller_residual_at_solution']:.0e}) |")
    lines += ["", "Memory: XLA buffers of one call (arguments + outputs + temporaries) against the SciPy case's peak "
              "NumPy heap (tracemalloc):", "", "| bearing | effects | JAX one case | JAX sweep executable | SciPy one case |",
              "|---|---|---|---|---|"]
    for r in reports:
        s, w = r["single"], r["sweep"]
        lines.append(f"| {r['bearing']} | {'centrifugal' if r['centrifugal'] else 'static'} | "
                     f"{s['jax_xla_memory_mib']:.2f} MiB | {w['jax_xla_memory_mib']:.1f} MiB ({w['jax_measured_cases']} cases) | "
                     f"{s['scipy_peak_heap_mib']:.2f} MiB |")
    lines += ["", f"Peak resident memory of the benchmark process: {peak_rss_mib():.0f} MiB."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", type=int, default=1000)
    parser.add_argument("--scipy-cases", type=int, default=50)
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--bearings", nargs="+", choices=list(BEARINGS), default=list(BEARINGS))
    parser.add_argument("--centrifugal-sweep", choices=["map", "vmap"], default="map")
    parser.add_argument("--static-only", action="store_true", help="skip the centrifugal runs")
    args = parser.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)  # MINPACK's "not making good progress": counted instead
    start = time.perf_counter()
    reports = []
    for name in args.bearings:
        setup = BEARINGS[name]()
        for centrifugal in (False,) if args.static_only else (False, True):
            reports.append(measure(name, setup, centrifugal, args))
    table = markdown(reports, args)
    print(table)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "roller_bearing.md").write_text(table + "\n")
    document = dict(machine=machine(), laminae=LAMINAE, arguments=vars(args), peak_rss_mib=peak_rss_mib(),
                    total_s=time.perf_counter() - start, reports=reports)
    (RESULTS / "roller_bearing.json").write_text(json.dumps(document, indent=1) + "\n")


if __name__ == "__main__":
    main()
