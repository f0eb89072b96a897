"""Test set-up: float64 for every test (docs/conventions.md, §Units and precision), a compilation
cache shared by the run's processes, and each module's compiled programs released after it."""

import gc
import os
import tempfile

import pytest

# Compiled XLA programs are cached on disk across the test processes (tests, notebook kernels,
# CLI subprocesses) of one run; set before JAX initialises its backends.
# Every program is kept, however quick its compilation (JAX's default keeps those over 1 s only):
# CI's slow suite and the README's `pytest` run side by side from this cache. JAX reads both from the environment.
os.environ.setdefault("JAX_COMPILATION_CACHE_DIR", os.path.join(tempfile.gettempdir(), "diffbearing-jax-cache"))
os.environ.setdefault("JAX_PERSISTENT_CACHE_MIN_COMPILE_TIME_SECS", "0")
os.environ.setdefault("JAX_PERSISTENT_CACHE_MIN_ENTRY_SIZE_BYTES", "0")

# The tests' programs compile with a single run's quick XLA settings (registry.QUICK_COMPILE; importing
# it initialises no backend), through XLA_FLAGS; the tests' time is compile time (docs/benchmarks.md,
# §Compile times). A flag the environment already sets is left as it is.
from diffbearing.app.registry import QUICK_COMPILE  # noqa: E402

os.environ["XLA_FLAGS"] = " ".join([os.environ.get("XLA_FLAGS", "")] + [
    f"--{flag}={str(value).lower()}" for flag, value in QUICK_COMPILE.items()
    if f"--{flag}" not in os.environ.get("XLA_FLAGS", "")]).strip()

import jax  # noqa: E402

jax.config.update("jax_enable_x64", True)
jax.config.update("jax_compilation_cache_dir", os.environ["JAX_COMPILATION_CACHE_DIR"])

from diffbearing.app import registry  # noqa: E402


@pytest.fixture(autouse=True, scope="module")
def release_compiled_programs():
    """After each test module, drop the compiled programs it left in this process (JAX's caches and
    the scene layer's compiled models): each loaded XLA program holds memory maps of its own, and
    one process running every module passed Linux's vm.max_map_count (65 530 maps) and crashed in
    XLA (segmentation fault while compiling). The persistent compilation cache keeps them on disk."""
    yield
    registry._COMPILED.clear()
    jax.clear_caches()
    gc.collect()
