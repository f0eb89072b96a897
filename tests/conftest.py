"""Test set-up: float64 for every test (DESIGN.md), and the shared scene folder."""

from pathlib import Path

import jax
import pytest

jax.config.update("jax_enable_x64", True)

SHARED_SCENES = Path(__file__).resolve().parents[2] / "shared" / "scenes"


@pytest.fixture(scope="session")
def shared_scenes() -> Path:
    """../shared/scenes beside the checkout (CI clones main with shared/ beside it)."""
    if not SHARED_SCENES.is_dir():
        pytest.skip("../shared/scenes is not beside this checkout")
    return SHARED_SCENES
