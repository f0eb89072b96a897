"""The thermal–mechanical fixed point: diffbearing (JAX) against the classical NumPy/SciPy solution.

    python benchmarks/thermal.py [--repeats 5]

A mounted 6411 (the mounted_6411 example's bearing; a line fit on the shaft, a loose cast-iron housing)
under 8 kN radial and 1 kN axial at 1500 r/min in ISO VG 68, cooled by fixed conductances
(tests/test_bearing_thermal.py's paths): the five temperatures where the friction heat, the
clearance the fits and temperatures leave, the ball loads and the network agree.

  * diffbearing: `solve_thermal` (damped Newton on the five temperatures, the ball equilibrium
    inside each residual, implicit derivatives), compile time and the median run after
    compilation; ∂(inner ring temperature)/∂(speed, housing conductance) by forward-mode autodiff
    through the fixed point, compile and run;
  * classical: `scipy.optimize.root` (MINPACK hybr) on the same five temperatures, each residual
    solving the ball bearing the classical way (benchmarks/scipy_ball_bearing.py: hybr on 5 + 2Z
    unknowns) at the contact angle its clearance gives, Palmgren's moments and the network in
    NumPy, the clearance change by the same closed form (`operating_clearance_change`, evaluated
    eagerly); the two derivatives by central differences (four more solves);
  * the same answers: the largest temperature difference and the derivatives' relative differences;
  * the pair and the three-bearing spindle shaft of tests/test_pair_thermal.py and
    tests/test_shaft_thermal.py: compile and run (no classical baseline).
Writes benchmarks/results/thermal.md.
"""

import argparse
import dataclasses
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import root  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from scipy_ball_bearing import ClassicalBallBearing  # noqa: E402
from timing import machine, median_time, peak_rss_mib  # noqa: E402

from diffbearing.params import BEARING_STEEL, Operating, ball_bearing, groove_curvature_centre_distance  # noqa: E402
from diffbearing.ratings.static_safety import ball_bearing_static_load_rating  # noqa: E402
from diffbearing.systems.operating_clearance import SEAT_MATERIALS, Mounting, operating_clearance_change  # noqa: E402
from diffbearing.thermal import bearing_thermal as bt  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
AMBIENT = 293.15
BEARING = ball_bearing(kind="deep_groove_ball", ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7,
                       inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=28e-6, bore=55e-3,
                       outer_diameter=140e-3, ball_material=BEARING_STEEL, ring_material=BEARING_STEEL)
MOUNTING = Mounting(shaft_interference=0.0, housing_interference=-5e-6, reference_temperature=AMBIENT,
                    housing=SEAT_MATERIALS["cast_iron"][0], housing_expansion=SEAT_MATERIALS["cast_iron"][1])
OIL = bt.WaltherLine(68e-6, 8.6e-6)  # ISO VG 68
F0, COEFFICIENT, EXPONENT = 2.0, 0.0009, 0.5  # HR 1's 62 series, oil
FORCE = np.array([8e3, 0.0, 1e3])
RPM = 1500.0
HOUSING = 2.0  # W/K, housing – ambient


def paths(housing=HOUSING):
    return bt.ThermalPaths(inner_ring_shaft=5.0, outer_ring_housing=8.0, inner_ring_lubricant=1.0,
                           outer_ring_lubricant=1.0, shaft_ambient=0.8, housing_ambient=housing, oil_flow=0.5,
                           ambient_temperature=AMBIENT, inlet_temperature=AMBIENT + 20.0)


def heated(rpm=RPM):
    operating = Operating(rpm * jnp.pi / 30, 0.0, jnp.asarray(FORCE), jnp.zeros(2))
    return bt.MountedBallBearing(BEARING, MOUNTING, operating, OIL, bt.PalmgrenFactors(F0, COEFFICIENT, EXPONENT))


# ---- the classical solution ------------------------------------------------------------------------

def walther(temperature):
    """ν [m²/s] on ISO VG 68's Walther line (ASTM D341), NumPy."""
    loglog = lambda nu: np.log10(np.log10(nu * 1e6 + 0.7))
    low, high = np.log10(313.15), np.log10(373.15)
    slope = (loglog(68e-6) - loglog(8.6e-6)) / (high - low)
    return (10.0 ** (10.0 ** (loglog(68e-6) - slope * (np.log10(temperature) - low))) - 0.7) * 1e-6


class ClassicalFixedPoint:
    """The same equations, solved the usual way (module docstring)."""

    def __init__(self):
        self.rating = float(ball_bearing_static_load_rating(BEARING))
        self.distance = float(groove_curvature_centre_distance(BEARING))
        self.clearance = 28e-6
        material = BEARING_STEEL
        self.modulus = material.elastic_modulus / (1 - material.poisson_ratio ** 2)
        self.guess = np.array([1e-5, 1e-5, 2e-5, 0.0, 0.0])

    def network(self, housing):
        """(L_ff, L_fb T_b) of the five free nodes."""
        p = paths(housing)
        edges = ((0, 3), (1, 4), (0, 2), (1, 2), (3, 5), (4, 5), (2, 6))
        values = [float(getattr(p, name)) for name in bt.PATH_NAMES]
        matrix = np.zeros((7, 7))
        for (i, j), g in zip(edges, values):
            matrix[i, i] += g
            matrix[j, j] += g
            matrix[i, j] -= g
            matrix[j, i] -= g
        held = np.array([AMBIENT, AMBIENT + 20.0])
        return matrix[:5, :5], matrix[:5, 5:] @ held

    def heat(self, temperatures, rpm):
        """Sources [W] at the five free nodes."""
        speed = rpm * np.pi / 30
        warm = dataclasses.replace(MOUNTING, inner_ring_temperature=temperatures[0],
                                   outer_ring_temperature=temperatures[1], shaft_temperature=temperatures[3],
                                   housing_temperature=temperatures[4])
        pitch, ball = 97.5e-3, 26.9875e-3
        change = float(operating_clearance_change(warm, 55e-3, pitch - ball, pitch + ball, 140e-3, ball, BEARING_STEEL,
                                                  speed).change)
        clearance = self.clearance + change  # stays positive here: the contact angle of the clearance
        angle = np.arccos(1.0 - clearance / (2.0 * self.distance))
        bearing = ClassicalBallBearing(ball, pitch, 7, float(BEARING.inner_groove_ratio),
                                       float(BEARING.outer_groove_ratio), angle, self.modulus,
                                       BEARING_STEEL.density, speed, centrifugal=False, gyroscopic=False)
        displacement, *_ = bearing.solve(np.concatenate([FORCE, np.zeros(2)]), self.guess)
        self.guess = displacement
        radial, axial = np.hypot(FORCE[0], FORCE[1]), abs(FORCE[2])
        static = max(0.6 * radial + 0.5 * axial, radial)
        f1 = COEFFICIENT * (static / self.rating) ** EXPONENT
        load = f1 * max(3.3 * axial - 0.1 * radial, radial) * pitch * speed
        product = walther(temperatures[2]) * 1e6 * rpm
        viscous = 1e-7 * F0 * product ** (2 / 3) * (pitch * 1e3) ** 3 * 1e-3 * speed
        return np.array([0.5 * load, 0.5 * load, viscous, 0.0, 0.0])

    def solve(self, rpm=RPM, housing=HOUSING):
        matrix, held = self.network(housing)
        start = np.linalg.solve(matrix, self.heat(np.full(5, AMBIENT), rpm) - held)
        found = root(lambda t: t - np.linalg.solve(matrix, self.heat(t, rpm) - held), start, method="hybr", tol=1e-12)
        return found.x, found.success


# ---- the runs --------------------------------------------------------------------------------------

def diffbearing_case(repeats):
    solve = jax.jit(lambda h, p: bt.solve_thermal(h, p).temperatures)
    start = time.perf_counter()
    temperatures = np.asarray(jax.block_until_ready(solve(heated(), paths())))
    compile_s = time.perf_counter() - start
    run_s = median_time(lambda: solve(heated(), paths()), repeats)

    def inner(x):
        return bt.solve_thermal(heated(x[0]), paths(x[1])).temperatures[0]

    derivative = jax.jit(jax.jacfwd(inner))
    point = jnp.array([RPM, HOUSING])
    start = time.perf_counter()
    gradient = np.asarray(jax.block_until_ready(derivative(point)))
    derivative_compile_s = time.perf_counter() - start
    derivative_s = median_time(lambda: derivative(point), repeats)
    return temperatures, compile_s, run_s, gradient, derivative_compile_s, derivative_s


def classical_case(repeats):
    classical = ClassicalFixedPoint()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        temperatures, success = classical.solve()
        times.append(time.perf_counter() - start)
    start = time.perf_counter()
    steps = (10.0, 0.02)  # r/min, W/K
    gradient = []
    for index, step in enumerate(steps):
        plus = classical.solve(RPM + step * (index == 0), HOUSING + step * (index == 1))[0][0]
        minus = classical.solve(RPM - step * (index == 0), HOUSING - step * (index == 1))[0][0]
        gradient.append((plus - minus) / (2 * step))
    derivative_s = time.perf_counter() - start
    return temperatures, bool(success), float(np.median(times)), np.array(gradient), derivative_s


def system_cases(repeats):
    """(name, compile [s], run [s]) of the pair and the spindle shaft of the tests."""
    from tests import test_pair_thermal, test_shaft_thermal

    found = []
    for name, make in (("matched pair (tests/test_pair_thermal.py, 4000 r/min)",
                        lambda: (test_pair_thermal._pair(), test_pair_thermal.PATHS)),
                       ("spindle shaft, 3 bearings (tests/test_shaft_thermal.py, 6000 r/min)", test_shaft_thermal._spindle)):
        system, system_paths = make()
        solve = jax.jit(lambda h, p: bt.solve_thermal(h, p).temperatures)
        start = time.perf_counter()
        jax.block_until_ready(solve(system, system_paths))
        compile_s = time.perf_counter() - start
        found.append((name, compile_s, median_time(lambda: solve(system, system_paths), repeats)))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    arguments = parser.parse_args()
    ours, compile_s, run_s, gradient, derivative_compile_s, derivative_s = diffbearing_case(arguments.repeats)
    theirs, success, classical_s, classical_gradient, classical_derivative_s = classical_case(arguments.repeats)
    systems = system_cases(arguments.repeats)
    difference = float(np.max(np.abs(ours[:5] - theirs)))
    relative = np.abs(gradient - classical_gradient) / np.abs(gradient)
    lines = [
        "# The thermal–mechanical fixed point", "", f"Machine: {machine()}.",
        f"Command: `python benchmarks/thermal.py --repeats {arguments.repeats}` (medians of {arguments.repeats}).", "",
        "A mounted 6411 at 1500 r/min, 8 kN radial and 1 kN axial (module docstring): inner ring "
        f"{ours[0] - 273.15:.2f} °C, outer ring {ours[1] - 273.15:.2f} °C, lubricant {ours[2] - 273.15:.2f} °C.", "",
        "| | diffbearing | classical (SciPy) | ratio |", "|---|---|---|---|",
        f"| solve, after compilation [ms] | {run_s * 1e3:.1f} | {classical_s * 1e3:.1f} | {classical_s / run_s:.1f} |",
        f"| solve, compile [s] | {compile_s:.2f} | – | |",
        f"| ∂T_inner/∂(speed, housing G), after compilation [ms] | {derivative_s * 1e3:.1f} | "
        f"{classical_derivative_s * 1e3:.1f} (4 solves) | {classical_derivative_s / derivative_s:.1f} |",
        f"| ∂T_inner/∂(speed, housing G), compile [s] | {derivative_compile_s:.2f} | – | |", "",
        f"The same answers: largest temperature difference {difference:.2e} K (classical converged: {success}); "
        f"∂T_inner/∂n = {gradient[0] * 1e3:.4f} K per 1000 r/min against {classical_gradient[0] * 1e3:.4f} "
        f"(relative {relative[0]:.1e}), ∂T_inner/∂G_housing = {gradient[1]:.4f} K/(W/K) against "
        f"{classical_gradient[1]:.4f} ({relative[1]:.1e}).", "",
        f"Compile time is the user's time too: one solve costs {compile_s + run_s:.1f} s here against "
        f"{classical_s:.1f} s classically; diffbearing is ahead from "
        f"{int(np.ceil(compile_s / (classical_s - run_s)))} solves of one compiled program (a sweep, a design "
        "loop). For one bearing Palmgren's heat reads the external load, so the ball equilibrium inside "
        "each residual delivers the state reported, not the heat; for the pair and the shaft below it sets "
        "the preload and so the heat.", "",
        "| system (diffbearing) | compile [s] | solve after compilation [ms] |", "|---|---|---|",
        *(f"| {name} | {c:.2f} | {r * 1e3:.1f} |" for name, c, r in systems), "",
        f"Peak resident memory of the run: {peak_rss_mib():.0f} MiB.",
    ]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "thermal.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
