"""The starved-EHL paper's finite line contact by matrix-free Newton–Krylov on fine grids: time,
compile time and peak memory of each solve, and the films.

    python benchmarks/finite_line_krylov.py [--grids 129 257] [--loads 1028 1607 2471] [--layers 0 0.8]
        [--timeout SECONDS] [--results finite_line_krylov]

Each case (grid nx × ny on the half domain, load, flooded or starved by an oil layer [µm]; 0 means
flooded) runs in its own process, so that its peak resident memory is its own (ru_maxrss:
compilation included), then once more in a fresh process that takes the executable from JAX's
persistent compilation cache (a temporary folder): its peak is what a solve costs without
compiling, as a second run of a scene does. XLA's buffers of one call (arguments, outputs,
temporaries) beside them; on a GPU the device's peak (XLA's allocator). Rows are kept in
benchmarks/results/<results>.json, so that a later run with other grids adds to the table. A case that
outlasts `--timeout` is reported as not finished. Writes benchmarks/results/<results>.md, after
each case. The grid 257 × 257 on the half domain is the paper's 257 × 513 over the whole roller.
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"


def one_case(nx, ny, load, layer_um, cache):
    """Runs in a child process: one compiled solve (the executable kept in the compilation cache folder
    `cache`), printed as one JSON line."""
    import jax

    jax.config.update("jax_enable_x64", True)
    jax.config.update("jax_compilation_cache_dir", cache)
    jax.config.update("jax_persistent_cache_min_compile_time_secs", 0.0)
    from line_ehl import FLAT_LENGTH, LUBRICANT, RADIUS, SPEED
    from timing import compiled_with_time, machine, peak_rss_mib, xla_memory_mib

    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_krylov import finite_line_film_krylov

    profile = roller_profile("circular", length=14.7e-3, flat_length=FLAT_LENGTH, crown_radius=10e-3)
    layer = layer_um * 1e-6 if layer_um > 0 else None
    compiled, compile_time = compiled_with_time(
        lambda w: finite_line_film_krylov(w, RADIUS, SPEED, LUBRICANT["viscosity"], LUBRICANT["pressure_viscosity"],
                                          LUBRICANT["effective_modulus"], profile, 14.7e-3, FLAT_LENGTH, grid=(nx, ny),
                                          oil_layer=layer), load)
    start = time.perf_counter()
    film = jax.block_until_ready(compiled(load))
    run = time.perf_counter() - start
    device = jax.devices()[0]
    device_peak = (device.memory_stats() or {}).get("peak_bytes_in_use") if device.platform != "cpu" else None
    print(json.dumps(dict(grid=f"{nx} × {ny}", load=load, layer=layer_um, central=float(film.central) * 1e6,
                          minimum=float(film.minimum) * 1e6, at=float(film.minimum_position) * 1e3,
                          converged=bool(film.converged), residual=float(film.residual), run=run,
                          compile=compile_time, peak=peak_rss_mib(), xla=xla_memory_mib(compiled),
                          device_peak=device_peak and device_peak / 2**20, dtype=str(film.central.dtype),
                          machine=f"{machine()} ({device.device_kind})")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[129, 257])
    parser.add_argument("--loads", type=float, nargs="+", default=[1028.0, 1607.0, 2471.0])
    parser.add_argument("--layers", type=float, nargs="+", default=[0.0, 0.8])
    parser.add_argument("--timeout", type=float, help="seconds a case may take before it is reported as not finished")
    parser.add_argument("--results", default="finite_line_krylov", help="name of the file written in benchmarks/results")
    parser.add_argument("--case", nargs=5, help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.case:
        nx, ny, load, layer, cache = arguments.case
        return one_case(int(nx), int(ny), float(load), float(layer), cache)
    kept = RESULTS / f"{arguments.results}.json"
    rows = json.loads(kept.read_text()) if kept.exists() else []
    for grid in arguments.grids:
        for layer in arguments.layers:
            for load in arguments.loads:
                row = dict(grid=f"{grid} × {grid}", load=load, layer=layer)
                try:
                    with tempfile.TemporaryDirectory() as cache:
                        command = [sys.executable, __file__, "--case", str(grid), str(grid), str(load), str(layer), cache]
                        runs = [json.loads(subprocess.run(command, capture_output=True, text=True, check=True,
                                                          timeout=arguments.timeout).stdout.strip().splitlines()[-1])
                                for _ in range(2)]  # compiling, then with the executable from the cache
                    row = runs[0] | dict(cached_peak=runs[1]["peak"], cached_compile=runs[1]["compile"])
                except subprocess.TimeoutExpired:
                    row |= dict(timeout=arguments.timeout)
                except subprocess.CalledProcessError as error:
                    sys.exit(f"case {grid} × {grid}, {load} N, {layer} µm failed:\n{error.stderr[-4000:]}")
                rows = [old for old in rows if (old["grid"], old["load"], old["layer"]) != (row["grid"], load, layer)]
                rows.append(row)
                print(row, flush=True)
                kept.write_text(json.dumps(rows, indent=1))
                write(rows, arguments.results)


def write(rows, name):
    """The table of the cases run so far, in benchmarks/results/<name>.md."""
    machine = next((row["machine"] for row in rows if "machine" in row), "?")
    lines = ["# The starved-EHL paper's finite line contact by Newton–Krylov", "",
             f"`python benchmarks/finite_line_krylov.py` on {machine}: one run per case, each in its own process; "
             "peak memory: the process's resident peak, compilation included (and the GPU's peak, where one ran); "
             "cached: the peak of a fresh process that takes the executable from the compilation cache (its "
             "tracing and loading time in brackets); XLA: the buffers of one call.",
             "", "| grid (half domain) | load | oil layer | central film | minimum film | at y | converged | run | compile "
             "| peak memory | cached | XLA |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in sorted(rows, key=lambda row: (int(row["grid"].split()[0]), row["layer"], row["load"])):
        layer = "flooded" if row["layer"] == 0 else f"{row['layer']:.2g} µm"
        if "timeout" in row:
            lines.append(f"| {row['grid']} | {row['load']:.0f} N | {layer} | – | – | – | not finished in "
                         f"{row['timeout']:.0f} s | – | – | – | – | – |")
            continue
        device = f" (GPU {row['device_peak'] / 1024:.2f} GiB)" if row.get("device_peak") else ""
        xla = f"{row['xla'] / 1024:.2f} GiB" if row.get("xla") is not None else "–"
        cached = f"{row['cached_peak'] / 1024:.2f} GiB ({row['cached_compile']:.0f} s)" if "cached_peak" in row else "–"
        lines.append(f"| {row['grid']} | {row['load']:.0f} N | {layer} | {row['central']:.4f} µm | {row['minimum']:.4f} µm | "
                     f"{row['at']:.3f} mm | {'yes' if row['converged'] else 'no'} | {row['run']:.1f} s | "
                     f"{row['compile']:.1f} s | {row['peak'] / 1024:.2f} GiB{device} | {cached} | "
                     f"{xla} |")
    lines += grid_ladders(rows)
    (RESULTS / f"{name}.md").write_text("\n".join(lines) + "\n")


def grid_ladders(rows):
    """Lines of a table: for each load and oil layer solved on three grids, each halving the spacing
    (e.g. 65, 129, 257) and all converged, Richardson's observed order p = log2(|h₁ − h₂| / |h₂ − h₃|)
    of the central and the minimum film and the extrapolated h₃ + (h₃ − h₂)/(2^p − 1)."""
    lines = []
    cases = {}
    for row in rows:
        if row.get("converged"):
            cases.setdefault((row["load"], row["layer"]), {})[int(row["grid"].split()[0])] = row
    for (load, layer), by_grid in cases.items():
        grids = sorted(by_grid)
        for coarse, middle, fine in zip(grids, grids[1:], grids[2:]):
            if (middle - 1) != 2 * (coarse - 1) or (fine - 1) != 2 * (middle - 1):
                continue
            if not lines:
                lines = ["", "Grid convergence (Richardson, from the converged rows above):", "",
                         "| load | oil layer | grids | film | values | observed order | extrapolated |",
                         "|---|---|---|---|---|---|---|"]
            for film in ("central", "minimum"):
                h1, h2, h3 = (by_grid[grid][film] for grid in (coarse, middle, fine))
                ratio = (h1 - h2) / (h2 - h3) if h2 != h3 else float("nan")
                order = math.log2(ratio) if ratio > 1 else float("nan")
                extrapolated = h3 + (h3 - h2) / (2**order - 1) if math.isfinite(order) else float("nan")
                layer_text = "flooded" if layer == 0 else f"{layer:.2g} µm"
                lines.append(f"| {load:.0f} N | {layer_text} | {coarse}, {middle}, {fine} | {film} | "
                             f"{h1:.4f}, {h2:.4f}, {h3:.4f} µm | {order:.2f} | {extrapolated:.4f} µm |")
    return lines


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    main()
