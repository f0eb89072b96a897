"""The static capacity curve of a four-point-contact slewing ring (axial load against tilting
moment at ISO 76's 4 200 MPa), for three radial clearances, beside the rigid-ring line of the
4.37 rule, and what the curve costs.

    python benchmarks/slewing_capacity.py [--rays 13]

The ring is the example scene's (diffbearing/scenes/slewing_ring.toml: 137 balls of 20 mm on a
1094 mm raceway diameter, 45° arches, f = 0.535). Each point solves the ring alone on a ray of
loads until its largest contact pressure is the limit (`systems.static_capacity`); the first point
of a clearance compiles the solve. Writes benchmarks/results/slewing_capacity.md and .png.
"""

import argparse
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import machine, peak_rss_mib  # noqa: E402

from diffbearing.bearings.ball.four_point import FourPointSupport, axial_clearance  # noqa: E402
from diffbearing.bearings.ball.raceway_contact import ball_raceway_modulus, both_curvatures  # noqa: E402
from diffbearing.contact import hertz  # noqa: E402
from diffbearing.params import ball_bearing  # noqa: E402
from diffbearing.ratings.static_safety import BALL_PRESSURE_LIMIT  # noqa: E402
from diffbearing.systems.static_capacity import capacity_point, rigid_ring_line  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
ANGLE = np.radians(45.0)
RING = ball_bearing(ball_diameter=20e-3, pitch_diameter=1.094, balls=137, inner_groove_ratio=0.535,
                    outer_groove_ratio=0.535, contact_angle=ANGLE)
CLEARANCES = (0.0, 100e-6, 300e-6)  # m, diametral
AXIAL_REFERENCE, MOMENT_REFERENCE = 3.0e6, 0.75e6  # N, N·m: the rays' directions


def limit_load():
    """Q_lim [N]: the ball load whose Hertz pressure at α₀ (the more curved, inner contact) is the limit."""
    sums, differences = both_curvatures(RING, ANGLE, ANGLE)
    unit = hertz.point_contact(np.ones(2), sums, differences, ball_raceway_modulus(RING))
    return float((BALL_PRESSURE_LIMIT / np.max(np.asarray(unit.max_pressure))) ** 3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rays", type=int, default=13)
    arguments = parser.parse_args()
    angles = np.linspace(0.0, 0.5 * np.pi, arguments.rays)
    axial_end, moment_end = rigid_ring_line(RING.ball_count, 1.094, ANGLE, limit_load())
    lines = ["# Static capacity curve of a four-point-contact slewing ring", "", f"Machine: {machine()}.",
             f"Command: `python benchmarks/slewing_capacity.py --rays {arguments.rays}`", "",
             f"137 balls of 20 mm on d_m = 1094 mm, 45° arches, f_i = f_o = 0.535, p_lim = "
             f"{BALL_PRESSURE_LIMIT / 1e6:.0f} MPa. Rigid rings without clearance (4.37 rule, Q_lim = "
             f"{limit_load() / 1e3:.2f} kN at α₀): F_a = {axial_end / 1e3:.0f} kN at M = 0, M = {moment_end / 1e3:.0f} "
             "kN·m at F_a = 0.", "",
             "| radial clearance [µm] | axial play [µm] | F_a at M = 0 [kN] | M at F_a = 0 [kN·m] | all converged | "
             "first point (compile) [s] | each further point [s] | solves a point |", "|---|---|---|---|---|---|---|---|"]
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    axes.plot([0.0, axial_end / 1e3], [moment_end / 1e3, 0.0], "k--", lw=1, label="rigid rings, 4.37 rule")
    table = ["", "| φ [°] | " + " | ".join(f"F_a, M at {c * 1e6:.0f} µm" for c in CLEARANCES) + " |",
             "|---|" + "---|" * len(CLEARANCES)]
    columns = []
    for clearance in CLEARANCES:
        support = FourPointSupport(RING, 0.0, clearance)
        times, points = [], []
        for angle in angles:
            start = time.perf_counter()
            points.append(capacity_point(support, np.cos(angle) * AXIAL_REFERENCE, np.sin(angle) * MOMENT_REFERENCE,
                                         BALL_PRESSURE_LIMIT))
            times.append(time.perf_counter() - start)
        axial = np.array([point.axial_load for point in points]) / 1e3
        moment = np.array([point.moment for point in points]) / 1e3
        columns.append([f"{a:.0f} kN, {m:.0f} kN·m" for a, m in zip(axial, moment)])
        axes.plot(axial, moment, "o-", ms=3, label=f"G_r = {clearance * 1e6:.0f} µm")
        lines.append(f"| {clearance * 1e6:.0f} | {float(axial_clearance(support)) * 1e6:.1f} | {axial[0]:.0f} | "
                     f"{moment[-1]:.0f} | {all(point.converged for point in points)} | {times[0]:.2f} | "
                     f"{np.median(times[1:]):.3f} | {min(p.solves for p in points)}–{max(p.solves for p in points)} |")
        print(lines[-1], flush=True)
    table += [f"| {np.degrees(angle):.1f} | " + " | ".join(column[row] for column in columns) + " |"
              for row, angle in enumerate(angles)]
    axes.set_xlabel("axial load F_a [kN]")
    axes.set_ylabel("tilting moment M [kN·m]")
    axes.set_title("Static capacity at 4200 MPa, four-point slewing ring")
    axes.set_xlim(left=0.0)
    axes.set_ylim(bottom=0.0)
    axes.grid(alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(RESULTS / "slewing_capacity.png", dpi=120)
    lines += table + ["", f"Peak memory {peak_rss_mib():.0f} MiB (resident)."]
    (RESULTS / "slewing_capacity.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
