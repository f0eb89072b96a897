"""Cylindrical roller thrust bearing laminae: accuracy against time.

    python benchmarks/thrust_roller_laminae.py [--laminae 4 6 10 20 30 50 100] [--repeats 25]

The thrust_roller_shaft example's thrust bearing (16 rollers of 11 × 11 mm on d_m = 77.5 mm, crown
flat 8 mm, R_c = 0.1 m) at 300 r/min, its shaft washer under 30 kN and tilted by 0.3 mrad (the
tilt a shaft could give it): for each laminae count n the state (the axial approach that carries
30 kN at that tilt, by Newton), the 5×5 stiffness, the contacts, ISO/TS 16281's L10r and the
sliding loss (μ = 0.05) under jit; the time is the median of `repeats` calls after compilation
(compile apart). Errors against n = 400. Writes benchmarks/results/thrust_roller_laminae.{json,md}.
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

from diffbearing import RollerModel, cylindrical_roller_thrust_bearing, cylindrical_roller_thrust_support  # noqa: E402
from diffbearing import roller_profile  # noqa: E402
from diffbearing.bearings.roller import cylindrical_roller_thrust as crtb  # noqa: E402
from diffbearing.ratings.reference_life import contact_reference_life  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
REFERENCE = 400
AXIAL_LOAD, TILT, SPEED, FRICTION = 30e3, 3e-4, 300 * np.pi / 30, 0.05
LENGTH = 11e-3
BEARING = cylindrical_roller_thrust_bearing(
    roller_diameter=11e-3, roller_length=LENGTH, rollers=16,
    profile=roller_profile("circular", length=LENGTH, flat_length=8e-3, crown_radius=0.1))


def case(laminae):
    support = cylindrical_roller_thrust_support(BEARING, 77.5e-3, 0.0, model=RollerModel(laminae=laminae))

    def solve(axial_load):
        displacement = jnp.array([0.0, 0.0, 10e-6, 0.0, TILT])

        def step(displacement, _):
            force = support.ring_force(displacement, SPEED, None)
            stiffness = support.ring_stiffness(displacement, SPEED, None)
            return displacement.at[2].add(-(force[2] - axial_load) / stiffness[2, 2]), None

        displacement, _ = jax.lax.scan(step, displacement, None, length=30)
        stiffness = support.ring_stiffness(displacement, SPEED, None)
        contacts = support.contacts(displacement, SPEED, None)
        life = contact_reference_life(contacts, support.contact_ratings(support.dynamic_load_rating(), contacts))
        power = crtb.sliding_power(contacts, BEARING, 77.5e-3, SPEED, FRICTION)
        return displacement, stiffness, life, power, jnp.max(contacts.max_pressure)

    return solve


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--laminae", type=int, nargs="+", default=[4, 6, 10, 20, 30, 50, 100])
    parser.add_argument("--repeats", type=int, default=25)
    args = parser.parse_args()
    rows = timed_cases(case, sorted(set(args.laminae) | {REFERENCE}), AXIAL_LOAD, args.repeats)
    best = rows[REFERENCE]["out"]
    scale = np.diag([1.0, 1.0, 1.0, 2 / 77.5e-3, 2 / 77.5e-3])
    k_best = scale @ best[1] @ scale
    table = []
    for laminae, row in rows.items():
        d, k, life, power, pressure = row["out"]
        k = scale @ k @ scale
        table.append(dict(laminae=laminae, run_s=row["run_s"], compile_s=row["compile_s"], life=float(life),
                          power=float(power), pressure=float(pressure), approach=float(d[2]),
                          error_life=abs(float(life) / float(best[2]) - 1), error_power=abs(float(power) / float(best[3]) - 1),
                          error_pressure=abs(float(pressure) / float(best[4]) - 1),
                          error_stiffness=float(np.max(np.abs(k - k_best)) / np.max(np.abs(k_best)))))
    lines = ["# Cylindrical roller thrust bearing laminae: accuracy against time", "",
             f"`python benchmarks/thrust_roller_laminae.py` ({machine()}). The thrust_roller_shaft example's thrust bearing "
             f"(16 rollers of 11 × 11 mm, d_m = 77.5 mm, crown flat 8 mm, R_c = 0.1 m), {AXIAL_LOAD / 1e3:g} kN, shaft "
             f"washer tilted {TILT * 1e3:g} mrad, 300 r/min, μ = {FRICTION:g}. Time: the axial approach (30 Newton steps), "
             f"5×5 stiffness, contacts, L10r and sliding loss under jit, median of {args.repeats} after compilation. "
             f"Errors against {REFERENCE} laminae.", "",
             "| laminae | time | compile | L10r [10⁶ rev] | error | sliding loss [W] | error | peak pressure [GPa] | error | "
             "stiffness change |", "|---|---|---|---|---|---|---|---|---|---|"]
    for row in table:
        lines.append(f"| {row['laminae']} | {row['run_s'] * 1e3:.3f} ms | {row['compile_s']:.2f} s | {row['life']:.1f} | "
                     f"{row['error_life']:.1e} | {row['power']:.2f} | {row['error_power']:.1e} | {row['pressure'] / 1e9:.4f} | "
                     f"{row['error_pressure']:.1e} | {row['error_stiffness']:.1e} |")
    write_results(RESULTS, "thrust_roller_laminae", "\n".join(lines), dict(machine=machine(), rows=table))


if __name__ == "__main__":
    main()
