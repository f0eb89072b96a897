"""Test set-up: float64 for every test (docs/conventions.md, §Units and precision) and a compilation
cache shared by the run's processes."""

import os
import tempfile

# Compiled XLA programs are cached on disk across the test processes (tests, notebook kernels,
# CLI subprocesses) of one run; set before JAX initialises its backends.
os.environ.setdefault("JAX_COMPILATION_CACHE_DIR", os.path.join(tempfile.gettempdir(), "diffbearing-jax-cache"))

import jax  # noqa: E402

jax.config.update("jax_enable_x64", True)
jax.config.update("jax_compilation_cache_dir", os.environ["JAX_COMPILATION_CACHE_DIR"])
