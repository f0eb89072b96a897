"""Timing and memory helpers shared by the benchmarks."""

import json
import os
import platform
import resource
import statistics
import time
import tracemalloc

import jax
import numpy as np

# compile times are measured from scratch: `run_model` and `run_sweep` keep no programs between a
# benchmark's runs (diffbearing/app/compilation_cache.py), unless the caller set DIFFBEARING_CACHE
os.environ.setdefault("DIFFBEARING_CACHE", "off")


def median_time(function, repeats):
    """Median wall time [s] of `repeats` calls of `function()` (JAX work awaited)."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        jax.block_until_ready(function())
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def compiled_with_time(function, *args):
    """(compiled executable, compile time [s]) of `jax.jit(function)` for `args` (lowering included)."""
    start = time.perf_counter()
    compiled = jax.jit(function).lower(*args).compile()
    return compiled, time.perf_counter() - start


def xla_memory_mib(compiled):
    """XLA's memory of one call of a compiled executable [MiB]: arguments + outputs + temporaries
    (`compiled.memory_analysis()`); None where the backend does not say."""
    stats = compiled.memory_analysis()
    if stats is None:
        return None
    return (stats.argument_size_in_bytes + stats.output_size_in_bytes + stats.temp_size_in_bytes) / 2**20


def traced_peak_mib(function):
    """Peak Python/NumPy heap [MiB] while `function()` runs (tracemalloc; NumPy reports its arrays)."""
    tracemalloc.start()
    try:
        function()
        return tracemalloc.get_traced_memory()[1] / 2**20
    finally:
        tracemalloc.stop()


def peak_rss_mib():
    """Peak resident memory of this process so far [MiB] (Linux ru_maxrss is in KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def machine():
    """One line: architecture, JAX backend × devices, JAX version, CPU cores."""
    return (f"{platform.machine()}, {os.cpu_count()} cores, {jax.devices()[0].platform.upper()} ×{len(jax.devices())}, "
            f"jax {jax.__version__}")


def timed_cases(make_case, counts, argument, repeats):
    """{count: dict(out, run_s, compile_s)} for each of `counts`: `make_case(count)` compiled for
    `argument`, its outputs (as NumPy) and the median of `repeats` calls after compilation."""
    rows = {}
    for count in counts:
        compiled, compile_s = compiled_with_time(make_case(count), argument)
        out = jax.block_until_ready(compiled(argument))
        run_s = median_time(lambda: compiled(argument), repeats)
        rows[count] = dict(out=[np.asarray(x) for x in out], run_s=run_s, compile_s=compile_s)
        print(count, f"{run_s * 1e3:.3f} ms", flush=True)
    return rows


def write_results(results, name, text, document):
    """Print `text` and write it to results/NAME.md, `document` to results/NAME.json."""
    print(text)
    results.mkdir(exist_ok=True)
    (results / f"{name}.md").write_text(text + "\n")
    (results / f"{name}.json").write_text(json.dumps(document, indent=1) + "\n")
