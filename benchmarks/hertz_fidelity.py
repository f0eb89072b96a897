"""Hertz point contact: accuracy against wall time for each fidelity level.

    python benchmarks/hertz_fidelity.py [--contacts 10000] [--repeats 7]

Levels: "exact" (ellipticity solve + AGM elliptic integrals), "brewe_hamrock" (1977 curve fits),
"hamrock_brewe" (1983 closed forms), each jit-compiled and vmapped over a batch of contacts with
ellipticity 1 ≤ κ ≤ 20, against the classical way: a Python loop of scipy.optimize.brentq on the
ellipticity equation with scipy.special.ellipk/ellipe per contact. Error: maximum relative error
against that SciPy solution, on every tenth contact of the batch. Times: median of `repeats` runs,
compile time apart. Writes benchmarks/results/hertz_fidelity.{md,png}.
"""

import argparse
import platform
import statistics
import sys
import time
from pathlib import Path

import jax

jax.config.update("jax_enable_x64", True)
import jax.numpy as jnp  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import ellipe, ellipk  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from timing import median_time  # noqa: E402

from diffbearing.contact import hertz  # noqa: E402

RESULTS = Path(__file__).parent / "results"
MODULUS = float(hertz.effective_modulus(208e9, 0.3, 208e9, 0.3))
FIELDS = ("semi_major_axis", "semi_minor_axis", "approach", "max_pressure")


def scipy_point_contact(load, curvature_sum, difference):
    """The classical route: root-bracket κ, then the closed forms (Harris eqs. 6.36–6.41)."""
    def residual(kappa):
        m = 1 - 1 / kappa**2
        return ((kappa**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((kappa**2 - 1) * ellipe(m)) - difference

    kappa = 1.0 if difference < 1e-12 else brentq(residual, 1.0 + 1e-12, 1e3, xtol=1e-14, rtol=1e-15)
    m = 1 - 1 / kappa**2
    k_int, e_int = ellipk(m), ellipe(m)
    radius = 1 / curvature_sum
    a = (6 * kappa**2 * e_int * load * radius / (np.pi * MODULUS)) ** (1 / 3)
    b = (6 * e_int * load * radius / (np.pi * kappa * MODULUS)) ** (1 / 3)
    approach = k_int * (9 / (2 * e_int * radius) * (load / (np.pi * kappa * MODULUS)) ** 2) ** (1 / 3)
    return a, b, approach, 3 * load / (2 * np.pi * a * b)



def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--contacts", type=int, default=10000)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()

    kappa = jnp.linspace(1.0, 20.0, args.contacts)
    difference = hertz.curvature_difference_of_ellipticity(kappa)
    loads = jnp.full_like(kappa, 2e3)
    curvature_sum = jnp.full_like(kappa, 150.0)

    stride = 10  # the SciPy loop runs on every tenth contact; its time is scaled to the full batch
    host = np.asarray(difference)[::stride]
    scipy_times = []
    for _ in range(3):
        start = time.perf_counter()
        reference = np.array([scipy_point_contact(2e3, 150.0, f) for f in host]).T
        scipy_times.append((time.perf_counter() - start) * stride)
    scipy_s = statistics.median(scipy_times)

    rows = []
    for method in ("exact", "brewe_hamrock", "hamrock_brewe"):
        function = jax.jit(jax.vmap(lambda q, s, f: hertz.point_contact(q, s, f, MODULUS, method)))
        start = time.perf_counter()
        compiled = function.lower(loads, curvature_sum, difference).compile()
        compile_s = time.perf_counter() - start
        run_s = median_time(lambda: compiled(loads, curvature_sum, difference), args.repeats)
        contact = compiled(loads, curvature_sum, difference)
        fields = np.stack([np.asarray(getattr(contact, name))[::stride] for name in FIELDS])
        rows.append((method, run_s, compile_s, np.max(np.abs(fields / reference - 1), axis=1)))
    rows.append(("scipy brentq loop (classical, reference)", scipy_s, 0.0, np.zeros(len(FIELDS))))

    header = (f"Hertz point contact, {args.contacts} contacts with 1 ≤ κ ≤ 20, median of {args.repeats} runs "
              f"({platform.processor() or platform.machine()}, {jax.devices()[0].platform.upper()}, jax {jax.__version__})")
    lines = [header, "",
             "| level | time per batch | per contact | compile | speed-up vs SciPy | max rel. error a | b | δ | p0 |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, run_s, compile_s, errors in rows:
        lines.append(f"| {name} | {run_s * 1e3:.2f} ms | {run_s / args.contacts * 1e9:.0f} ns | "
                     f"{compile_s:.2f} s | {scipy_s / run_s:.0f}× | " + " | ".join(f"{e:.1e}" for e in errors) + " |")
    table = "\n".join(lines)
    print(table)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "hertz_fidelity.md").write_text(table + "\n\nMeasured by `python benchmarks/hertz_fidelity.py`.\n")

    figure, axis = plt.subplots(figsize=(6.5, 4.2), layout="constrained")
    for name, run_s, _, errors in rows[:-1]:
        error = max(float(np.max(errors)), 1e-16)
        axis.scatter(run_s / args.contacts * 1e9, error, s=50)
        axis.annotate(name, (run_s / args.contacts * 1e9, error), textcoords="offset points", xytext=(6, 4), fontsize=8)
    axis.set(xscale="log", yscale="log", xlabel="wall time per contact [ns]",
             ylabel="max relative error of a, b, δ, p0 (vs SciPy)", title="Hertz point contact: accuracy against time")
    axis.grid(alpha=0.3, which="both")
    figure.savefig(RESULTS / "hertz_fidelity.png", dpi=120)


if __name__ == "__main__":
    main()
