"""Spherical roller bearing laminae: accuracy against time.

    python benchmarks/spherical_roller_laminae.py [--laminae 4 6 10 20 30 50 100] [--repeats 15]

The spherical_roller_shaft example's bearing (22220 E size: 2 × 19 barrel rollers of 22 × 19 mm,
barrel radius R_r = 76 mm, inner raceways R_i = 79 mm, d_m = 140 mm, α = 10°, 60 µm clearance),
static, under each of its bearings' loads in the example, F_r = 30 kN and F_a = 2.5 kN: for each
laminae count n the inner ring's translation that carries the load (Newton on the three
translations; each roller's (u, w, φ) by its own Newton inside), the translational stiffness, the
contacts, ISO/TS 16281's L10r and the peak pressure under jit; the time is the median of `repeats`
calls after compilation (compile apart). Errors against n = 200. Writes
benchmarks/results/spherical_roller_laminae.{json,md}.
"""

import argparse
import sys
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import machine, timed_cases, write_results  # noqa: E402

from diffbearing import RollerModel, spherical_roller, spherical_roller_raceways, spherical_roller_support  # noqa: E402
from diffbearing.ratings.reference_life import contact_reference_life  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
REFERENCE = 200
LOAD = np.array([30e3, 0.0, 2.5e3])
PITCH = 140e-3
ROLLER = spherical_roller(roller_diameter=22e-3, roller_length=19e-3, rollers=19, profile_radius=76e-3)
RACEWAYS = spherical_roller_raceways(ROLLER, pitch_diameter=PITCH, contact_angle=np.radians(10.0),
                                     inner_profile_radius=79e-3, diametral_clearance=60e-6)
NEWTON_STEPS = 25


def case(laminae):
    support = spherical_roller_support(ROLLER, RACEWAYS, 0.0, model=RollerModel(laminae=laminae))

    def solve(load):
        def step(translation, _):
            displacement = jnp.concatenate([translation, jnp.zeros(2)])
            force = support.ring_force(displacement, 0.0, None)[:3]
            stiffness = support.ring_stiffness(displacement, 0.0, None)[:3, :3]
            return translation - jnp.linalg.solve(stiffness, force - load), None

        translation, _ = jax.lax.scan(step, jnp.array([60e-6, 0.0, 20e-6]), None, length=NEWTON_STEPS)
        displacement = jnp.concatenate([translation, jnp.zeros(2)])
        residual = support.ring_force(displacement, 0.0, None)[:3] - load
        stiffness = support.ring_stiffness(displacement, 0.0, None)[:3, :3]
        contacts = support.contacts(displacement, 0.0, None)
        life = contact_reference_life(contacts, support.contact_ratings(support.dynamic_load_rating(), contacts))
        return translation, stiffness, life, jnp.max(contacts.max_pressure), jnp.max(jnp.abs(residual))

    return solve


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--laminae", type=int, nargs="+", default=[4, 6, 10, 20, 30, 50, 100])
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args()
    load = jnp.asarray(LOAD)
    rows = timed_cases(case, sorted(set(args.laminae) | {REFERENCE}), load, args.repeats)
    best = rows[REFERENCE]["out"]
    table = []
    for laminae, row in rows.items():
        translation, k, life, pressure, residual = row["out"]
        table.append(dict(laminae=laminae, run_s=row["run_s"], compile_s=row["compile_s"], life=float(life),
                          pressure=float(pressure), translation=translation.tolist(), residual=float(residual),
                          error_life=abs(float(life) / float(best[2]) - 1),
                          error_pressure=abs(float(pressure) / float(best[3]) - 1),
                          error_radial=abs(float(translation[0]) / float(best[0][0]) - 1),
                          error_stiffness=float(np.max(np.abs(k - best[1])) / np.max(np.abs(best[1])))))
    lines = ["# Spherical roller bearing laminae: accuracy against time", "",
             f"`python benchmarks/spherical_roller_laminae.py` ({machine()}). The spherical_roller_shaft example's "
             "bearing (2 × 19 barrel rollers of 22 × 19 mm, R_r = 76 mm, R_i = 79 mm, d_m = 140 mm, α = 10°, 60 µm "
             f"clearance), static, F_r = {LOAD[0] / 1e3:g} kN, F_a = {LOAD[2] / 1e3:g} kN. Time: the inner ring's translation "
             f"({NEWTON_STEPS} Newton steps, each roller's Newton inside), 3×3 translational stiffness, contacts, L10r and "
             f"peak pressure under jit, median of {args.repeats} after compilation. Errors against {REFERENCE} laminae.", "",
             "| laminae | time | compile | residual [N] | radial approach [µm] | error | L10r [10⁶ rev] | error | "
             "peak pressure [GPa] | error | stiffness change |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in table:
        lines.append(f"| {row['laminae']} | {row['run_s'] * 1e3:.2f} ms | {row['compile_s']:.2f} s | {row['residual']:.1e} | "
                     f"{row['translation'][0] * 1e6:.3f} | {row['error_radial']:.1e} | {row['life']:.1f} | "
                     f"{row['error_life']:.1e} | {row['pressure'] / 1e9:.4f} | {row['error_pressure']:.1e} | "
                     f"{row['error_stiffness']:.1e} |")
    write_results(RESULTS, "spherical_roller_laminae", "\n".join(lines), dict(machine=machine(), rows=table))


if __name__ == "__main__":
    main()
