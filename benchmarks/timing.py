"""Timing helper shared by the benchmarks."""

import statistics
import time

import jax


def median_time(function, repeats):
    """Median wall time [s] of `repeats` calls of `function()` (JAX work awaited)."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        jax.block_until_ready(function())
        times.append(time.perf_counter() - start)
    return statistics.median(times)
