"""Cage forces of the cage paper: its figures, and the cost of a force map (JAX against NumPy/SciPy).

    python benchmarks/cage_forces.py [--positions 100000] [--scipy-positions 200] [--repeats 5]

B7005-class bearing of the packaged example diffbearing/scenes/cage_b7005.toml (cage geometry a scene leaves out:
`ball_cage` defaults). Measured in one run on one machine:
  * Fig. 9 of Liu et al. 2020: f_inv against the offset angle, outer-lock and cylindrical pockets
    (20000 r/min, m = 4, n = 2, ε = 0.8), and the fraction of angles where outer-lock wins;
  * Fig. 10: f_inv against ε at 240° (m = 3, n = 4) at 20000 and 60000 r/min, both pockets;
  * time of f_inv and the resultant over `positions` random cage positions (ε ≤ 1.2) in one
    jit(vmap) call, median of `repeats`, compile time apart; against a classical NumPy/SciPy
    evaluation of the same equations (a loop over positions and balls, `scipy.optimize.brentq`
    seating each ball), timed on `scipy-positions` of them and scaled, with the largest difference.
Writes benchmarks/results/cage_forces.{md,png}.
"""

import argparse
import platform
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import matplotlib  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from timing import median_time  # noqa: E402

from diffbearing.cage.cage_forces import ball_roles, cage_forces  # noqa: E402
from diffbearing.cage.cage_pocket import pocket_stiffness  # noqa: E402
from diffbearing.params import Lubricant, Operating, ball_bearing, ball_cage  # noqa: E402

RESULTS = Path(__file__).parent / "results"
BEARING = ball_bearing(ball_diameter=5.556e-3, pitch_diameter=36e-3, balls=17, inner_groove_ratio=0.52,
                       outer_groove_ratio=0.53, contact_angle=np.radians(15.0))
OIL = Lubricant(0.01, 2e-8, 870.0)
CLEARANCE = 0.12e-3  # radial guide clearance [m]
FORCE = [1120.0, 0.0, 400.0]


def cage(pocket, pushing, resisting):
    return ball_cage(BEARING, pocket=pocket, pocket_clearance=0.26e-3, guide_clearance=0.24e-3, land_width=2e-3,
                     pushing_balls=pushing, resisting_balls=resisting)


def restoring_map(pocket, rpm, pushing, resisting):
    """jit(vmap) of (x, y) [m] → (f_inv, Fx, Fy) [N]."""
    operating = Operating(rpm * np.pi / 30.0, 0.0, FORCE, [0.0, 0.0])
    the_cage = cage(pocket, pushing, resisting)

    def one(offset):
        solved = cage_forces(the_cage, BEARING, operating, OIL, offset)
        return jnp.stack([solved.restoring_force, solved.force[0], solved.force[1]])

    return jax.jit(jax.vmap(one))


def offsets(eccentricity, degrees):
    angle = np.radians(degrees)
    return np.stack([eccentricity * CLEARANCE * np.cos(angle), eccentricity * CLEARANCE * np.sin(angle)], axis=-1)


class ClassicalCage:
    """The same quasi-static equations in NumPy, one position and one ball at a time, each ball
    seated by `scipy.optimize.brentq` on its circumferential force (the usual way)."""

    def __init__(self, pocket, rpm, pushing, resisting):
        self.pocket, self.m, self.n = pocket, pushing, resisting
        d, dm, alpha = 5.556e-3, 36e-3, np.radians(15.0)
        self.rb, self.rp, self.rpok = d / 2, dm / 2, d / 2 + 0.13e-3
        self.play = self.rpok - self.rb
        omega = rpm * np.pi / 30.0
        self.wc = 0.5 * omega * (1 - d * np.cos(alpha) / dm)
        ratio = d * np.cos(alpha) / dm
        self.spin = dm / (2 * d) * (1 - ratio**2) * omega * np.array([-np.sin(alpha), 0.0, -np.cos(alpha)])
        v = self.wc * self.rp
        reynolds = 870 * v * d / 0.01
        self.drag = max(3 * np.pi * 0.01 * d * v * (1 + 0.15 * reynolds**0.687), 0.055 * np.pi * 870 * v**2 * d**2)
        self.k = float(pocket_stiffness(self.rb, self.rpok, 208e9, 0.3, 13e9, 0.4, pocket))
        roles = ball_roles(17, pushing, resisting)
        self.push_w, self.resist_w = np.asarray(roles[0]), np.asarray(roles[1])
        self.psi = 2 * np.pi * np.arange(17) / 17
        self.radius = (dm + 0.8 * d - 0.24e-3) / 2
        self.spacing = d + 2e-3

    def land(self, e):
        eps = np.hypot(*e) / CLEARANCE
        limit = 1 - 1e-6 / CLEARANCE
        film = min(eps, limit)
        scale = 0.01 * self.radius * self.wc * (2e-3) ** 3 / CLEARANCE**2
        held = limit / eps if eps > limit else 1.0
        metal = 3e7 * CLEARANCE * max(eps - limit, 0.0)
        unit = e / CLEARANCE
        normal = scale * film / (1 - film**2) ** 2 * held + (metal / eps if eps > 0 else 0.0)
        tangential = scale * 0.25 * np.pi / (1 - film**2) ** 1.5 * held - 0.1 * metal / max(eps, 1e-300)
        torque = -2 * np.pi * 0.01 * self.radius**3 * 2e-3 * self.wc / (CLEARANCE * np.sqrt(1 - film**2)) \
            - 0.1 * metal * self.radius
        return -normal * unit + tangential * np.array([-unit[1], unit[0]]), torque

    def forces(self, offset):
        lands = [self.land(offset), self.land(offset)]
        torque = lands[0][1] + lands[1][1]
        push = (self.n * self.drag * self.rp - torque) / (self.m * self.rp)
        total = lands[0][0] + lands[1][0]
        for j, psi in enumerate(self.psi):
            weight = self.push_w[j] + self.resist_w[j]
            if weight == 0:
                continue
            target = push if self.push_w[j] > 0 else -self.drag
            er, et = np.array([np.cos(psi), np.sin(psi)]), np.array([-np.sin(psi), np.cos(psi)])
            xb = -er @ offset
            xs = max(xb, 0.0) if self.pocket == "outer_lock" else 0.0
            low = max(xs - self.play, 0.0)

            def carried(delta):
                dist = self.play + delta
                return self.k * delta**1.5 * np.sqrt(max(dist**2 - xs**2, 0.0)) / dist - abs(target)

            high = low + max(max(xs, self.play), (2 * abs(target) / self.k) ** (2 / 3))
            delta = brentq(carried, low, high, xtol=1e-22, rtol=1e-15)
            dist = self.play + delta
            normal = np.array([xs, np.sign(target) * np.sqrt(dist**2 - xs**2), 0.0]) / dist
            load = self.k * delta**1.5
            sliding = np.cross(self.spin, self.rb * normal)
            f = load * normal + 0.1 * load * sliding / np.linalg.norm(sliding)
            total = total + weight * (f[0] * er + f[1] * et)
        direction = offset / np.hypot(*offset)
        return np.array([-(total @ direction), total[0], total[1]])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--positions", type=int, default=100_000)
    parser.add_argument("--scipy-positions", type=int, default=200)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    RESULTS.mkdir(exist_ok=True)
    lines = ["# Cage forces, the cage paper (B7005-class, outer-ring guided cage)", "",
             f"Machine: {platform.processor() or platform.machine()}, {jax.device_count()} JAX device(s) "
             f"({jax.default_backend()}), JAX {jax.__version__}. Command: `python benchmarks/cage_forces.py`.", ""]

    # Fig. 9: f_inv against the offset angle
    angles = np.arange(0.0, 360.0, 5.0)
    fig9 = {pocket: np.asarray(restoring_map(pocket, 20000.0, 4, 2)(offsets(0.8, angles)))[:, 0]
            for pocket in ("outer_lock", "cylindrical")}
    wins = float(np.mean(fig9["outer_lock"] > fig9["cylindrical"]))
    lines += ["## Fig. 9: f_inv against the offset angle (20000 r/min, m = 4, n = 2, ε = 0.8)", "",
              f"Outer-lock f_inv exceeds the cylindrical pocket's at {wins * 100:.0f} % of {len(angles)} angles "
              "(the paper: \"at most angles\"). Largest f_inv: outer-lock "
              f"{fig9['outer_lock'].max():.3g} N at {angles[np.argmax(fig9['outer_lock'])]:.0f}°, cylindrical "
              f"{fig9['cylindrical'].max():.3g} N at {angles[np.argmax(fig9['cylindrical'])]:.0f}°. f_inv < 0 (the "
              f"balls' net push drives the cage outward) for the outer-lock cage at "
              f"{np.mean(fig9['outer_lock'] < 0) * 100:.0f} % of the angles.", ""]

    # Fig. 10: f_inv against ε at 240°
    eccentricities = np.linspace(0.05, 0.95, 19)
    fig10 = {(pocket, rpm): np.asarray(restoring_map(pocket, rpm, 3, 4)(offsets(eccentricities, 240.0)))[:, 0]
             for pocket in ("outer_lock", "cylindrical") for rpm in (20000.0, 60000.0)}
    lines += ["## Fig. 10: f_inv against relative eccentricity (240°, m = 3, n = 4)", "",
              "| ε | outer-lock 20000 r/min [N] | cylindrical 20000 r/min [N] | outer-lock 60000 r/min [N] | "
              "cylindrical 60000 r/min [N] |", "|---|---|---|---|---|"]
    for i in range(1, len(eccentricities), 3):
        lines.append(f"| {eccentricities[i]:.2f} | " + " | ".join(
            f"{fig10[(p, r)][i]:.4g}" for r in (20000.0, 60000.0) for p in ("outer_lock", "cylindrical")) + " |")
    lines.append("")

    # cost of a force map: JAX vmap against the NumPy/SciPy loop
    rng = np.random.default_rng(0)
    count = args.positions
    points = offsets(rng.uniform(0.01, 1.2, count), rng.uniform(0.0, 360.0, count))
    evaluate = restoring_map("outer_lock", 20000.0, 3, 4)
    start = time.perf_counter()
    compiled = evaluate.lower(jnp.asarray(points)).compile()
    compile_s = time.perf_counter() - start
    batch = jnp.asarray(points)
    run_s = median_time(lambda: compiled(batch), args.repeats)
    values = np.asarray(compiled(batch))
    classical = ClassicalCage("outer_lock", 20000.0, 3, 4)
    subset = points[: args.scipy_positions]
    start = time.perf_counter()
    reference = np.array([classical.forces(p) for p in subset])
    scipy_s = (time.perf_counter() - start) / len(subset) * count
    difference = np.max(np.abs(reference - values[: len(subset)]) / np.maximum(np.abs(reference), 1e-3))
    lines += [f"## Cost of a force map: {count:,} cage positions (ε ≤ 1.2, outer-lock, 20000 r/min)", "",
              "| method | time | per position |", "|---|---|---|",
              f"| diffbearing jit(vmap), after compilation (median of {args.repeats}) | {run_s:.3g} s | "
              f"{run_s / count * 1e6:.3g} µs |",
              f"| diffbearing compilation | {compile_s:.3g} s | |",
              f"| NumPy/SciPy loop (brentq per ball), {len(subset)} positions scaled to {count:,} | {scipy_s:.3g} s | "
              f"{scipy_s / count * 1e6:.3g} µs |", "",
              f"Speed-up {scipy_s / run_s:.0f}× after compilation. Largest relative difference of (f_inv, Fx, Fy) "
              f"between the two: {difference:.1e}.", ""]

    figure, (angle_axis, eccentricity_axis) = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
    angle_axis.plot(angles, fig9["outer_lock"], label="outer-lock pocket")
    angle_axis.plot(angles, fig9["cylindrical"], "--", label="cylindrical pocket")
    angle_axis.axhline(0.0, color="grey", lw=0.8)
    angle_axis.set(xlabel="offset angle from the radial load [deg]", ylabel="f_inv [N]",
                   title="Fig. 9: 20000 r/min, m = 4, n = 2, ε = 0.8")
    for (pocket, rpm), forces in fig10.items():
        eccentricity_axis.plot(eccentricities, forces, "-" if pocket == "outer_lock" else "--",
                               color="tab:blue" if rpm == 20000.0 else "tab:red",
                               label=f"{pocket.replace('_', '-')}, {rpm:.0f} r/min")
    eccentricity_axis.set(xlabel="relative eccentricity ε", ylabel="f_inv [N]", title="Fig. 10: 240°, m = 3, n = 4",
                          yscale="log")
    for axis in (angle_axis, eccentricity_axis):
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.suptitle("Restoring force of the B7005-class cage (the cage paper)")
    figure.savefig(RESULTS / "cage_forces.png", dpi=120)
    lines += ["![f_inv against offset angle and eccentricity](cage_forces.png)", ""]
    (RESULTS / "cage_forces.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
