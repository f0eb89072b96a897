"""Test set-up: float64 for every test (DESIGN.md), and the shared scene folder."""

import os
import tempfile
from pathlib import Path

# Compiled XLA programs are cached on disk across the test processes (tests, notebook kernels,
# CLI subprocesses) of one run; set before JAX initialises its backends.
os.environ.setdefault("JAX_COMPILATION_CACHE_DIR", os.path.join(tempfile.gettempdir(), "diffbearing-jax-cache"))

import jax  # noqa: E402
import pytest  # noqa: E402

jax.config.update("jax_enable_x64", True)
jax.config.update("jax_compilation_cache_dir", os.environ["JAX_COMPILATION_CACHE_DIR"])

SHARED_SCENES = Path(__file__).resolve().parents[2] / "shared" / "scenes"


@pytest.fixture(scope="session")
def shared_scenes() -> Path:
    """../shared/scenes beside the checkout (CI clones main with shared/ beside it)."""
    if not SHARED_SCENES.is_dir():
        pytest.skip("../shared/scenes is not beside this checkout")
    return SHARED_SCENES
