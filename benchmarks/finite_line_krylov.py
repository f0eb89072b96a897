"""The starved-EHL paper's finite line contact by matrix-free Newton–Krylov on fine grids: time,
compile time and peak memory of each solve, and the films.

    python benchmarks/finite_line_krylov.py [--grids 129 257] [--loads 1028 1607 2471] [--layers 0 0.8]
        [--timeout SECONDS] [--results finite_line_krylov]

Each case (grid nx × ny on the half domain, load, flooded or starved by an oil layer [µm]; 0 means
flooded) runs in its own process, so that its peak resident memory is its own: the process's
peak (ru_maxrss: compilation included), the peak while the compiled solve runs (VmHWM reset after
compilation) and XLA's buffers of one call (arguments, outputs, temporaries); on a GPU the
device's peak (XLA's allocator) is given beside them. A case that
outlasts `--timeout` is reported as not finished. Writes benchmarks/results/<results>.md, after
each case. The grid 257 × 257 on the half domain is the paper's 257 × 513 over the whole roller.
"""

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"


def one_case(nx, ny, load, layer_um):
    """Runs in a child process: one compiled solve, printed as one JSON line."""
    import jax

    jax.config.update("jax_enable_x64", True)
    from line_ehl import FLAT_LENGTH, LUBRICANT, RADIUS, SPEED
    from timing import compiled_with_time, machine, peak_rss_mib, reset_peak_rss, resident_peak_mib, xla_memory_mib

    from diffbearing.finite_line_krylov import finite_line_film_krylov
    from diffbearing.roller_profile import roller_profile

    profile = roller_profile("circular", length=14.7e-3, flat_length=FLAT_LENGTH, crown_radius=10e-3)
    layer = layer_um * 1e-6 if layer_um > 0 else None
    compiled, compile_time = compiled_with_time(
        lambda w: finite_line_film_krylov(w, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
                                          LUBRICANT["effective_modulus"], profile, 14.7e-3, FLAT_LENGTH, grid=(nx, ny),
                                          oil_layer=layer), load)
    compile_peak = peak_rss_mib()
    reset_peak_rss()
    start = time.perf_counter()
    film = jax.block_until_ready(compiled(load))
    run = time.perf_counter() - start
    solve_peak = resident_peak_mib()
    device = jax.devices()[0]
    device_peak = (device.memory_stats() or {}).get("peak_bytes_in_use") if device.platform != "cpu" else None
    print(json.dumps(dict(grid=f"{nx} × {ny}", load=load, layer=layer_um, central=float(film.central) * 1e6,
                          minimum=float(film.minimum) * 1e6, at=float(film.minimum_position) * 1e3,
                          converged=bool(film.converged), residual=float(film.residual), run=run,
                          compile=compile_time, peak=peak_rss_mib(), compile_peak=compile_peak,
                          solve_peak=solve_peak, xla=xla_memory_mib(compiled),
                          device_peak=device_peak and device_peak / 2**20, dtype=str(film.central.dtype),
                          machine=f"{machine()} ({device.device_kind})")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[129, 257])
    parser.add_argument("--loads", type=float, nargs="+", default=[1028.0, 1607.0, 2471.0])
    parser.add_argument("--layers", type=float, nargs="+", default=[0.0, 0.8])
    parser.add_argument("--timeout", type=float, help="seconds a case may take before it is reported as not finished")
    parser.add_argument("--results", default="finite_line_krylov", help="name of the file written in benchmarks/results")
    parser.add_argument("--case", type=float, nargs=4, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.case:
        nx, ny, load, layer = arguments.case
        return one_case(int(nx), int(ny), load, layer)
    rows = []
    for grid in arguments.grids:
        for layer in arguments.layers:
            for load in arguments.loads:
                try:
                    output = subprocess.run([sys.executable, __file__, "--case", str(grid), str(grid), str(load),
                                             str(layer)], capture_output=True, text=True, check=True,
                                            timeout=arguments.timeout).stdout
                    row = json.loads(output.strip().splitlines()[-1])
                except subprocess.TimeoutExpired:
                    row = dict(grid=f"{grid} × {grid}", load=load, layer=layer, timeout=arguments.timeout)
                except subprocess.CalledProcessError as error:
                    sys.exit(f"case {grid} × {grid}, {load} N, {layer} µm failed:\n{error.stderr[-4000:]}")
                rows.append(row)
                print(row, flush=True)
                write(rows, arguments.results)


def write(rows, name):
    """The table of the cases run so far, in benchmarks/results/<name>.md."""
    machine = next((row["machine"] for row in rows if "machine" in row), "?")
    lines = ["# The starved-EHL paper's finite line contact by Newton–Krylov", "",
             f"`python benchmarks/finite_line_krylov.py` on {machine}: one run per case, each in its own process; "
             "peak memory: the process's resident peak, compilation included (and the GPU's peak, where one ran); "
             "solve peak: the resident peak while the compiled solve runs; XLA: its buffers of one call.",
             "", "| grid (half domain) | load | oil layer | central film | minimum film | at y | converged | run | compile "
             "| peak memory | solve peak | XLA |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        layer = "flooded" if row["layer"] == 0 else f"{row['layer']:.2g} µm"
        if "timeout" in row:
            lines.append(f"| {row['grid']} | {row['load']:.0f} N | {layer} | – | – | – | not finished in "
                         f"{row['timeout']:.0f} s | – | – | – | – | – |")
            continue
        device = f" (GPU {row['device_peak'] / 1024:.2f} GiB)" if row.get("device_peak") else ""
        xla = f"{row['xla'] / 1024:.2f} GiB" if row.get("xla") is not None else "–"
        lines.append(f"| {row['grid']} | {row['load']:.0f} N | {layer} | {row['central']:.4f} µm | {row['minimum']:.4f} µm | "
                     f"{row['at']:.3f} mm | {'yes' if row['converged'] else 'no'} | {row['run']:.1f} s | "
                     f"{row['compile']:.1f} s | {row['peak'] / 1024:.2f} GiB{device} | {row['solve_peak'] / 1024:.2f} GiB | "
                     f"{xla} |")
    (RESULTS / f"{name}.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    main()
