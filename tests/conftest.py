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

# Slow cases CI leaves out (`extended`, besides those marked in place), node ids or their start:
# with an empty compilation cache CI cannot run every slow case in its time (docs/validation.md,
# §Tests and notebooks, has the measured times). Each repeats what a case
# CI runs checks more cheaply: the other arrangement, speed or load of a shaft or set, a derivative
# or hard case of a film whose values and hard cases CI checks, the same solve through the CLI.
# Run them with `pytest -m extended -o addopts= --nbmake -n auto tests notebooks` after a change
# to the films, shafts, sets or their adapters (docs/validation.md).
EXTENDED = (
    "tests/test_bearing_set_scene.py::test_preload_as_force_and_as_offset_agree",
    "tests/test_bearing_set_scene.py::test_pair_skf_friction_is_each_bearings_at_its_load",
    "tests/test_cli.py::test_every_example_runs_by_name[spindle_pair]",
    "tests/test_cli.py::test_every_example_runs_by_name[flexible_shaft]",
    "tests/test_film_formulas.py::test_starved_ehl_paper_finite_line_film_through_the_cli",
    "tests/test_finite_line_krylov.py::test_newton_krylov_hard_cases_say_whether_they_converged_and_stay_finite",
    "tests/test_flexible_shaft.py::test_the_rigid_shaft_is_the_limit_of_a_stiffening_one",
    "tests/test_point_ehl.py::test_flooded_film_within_ten_percent_of_hamrock_dowson[elliptical",
    "tests/test_point_ehl.py::test_point_film_derivatives_match_central_differences",
    "tests/test_point_ehl.py::test_very_low_speed_says_whether_it_converged_and_stays_finite",
    "tests/test_shaft_equilibrium.py::test_one_bearing_on_the_shaft_is_the_bearing_alone",
    "tests/test_shaft_equilibrium.py::test_preloaded_pair_under_axial_load_is_each_bearing_alone",
    "tests/test_shaft_equilibrium.py::test_tilt_stiffness_derivative_against_preload_offset",
    "tests/test_shaft_equilibrium.py::test_position_preload_rises_with_speed",
    "tests/test_shaft_scene.py::test_element_loads_derivatives_through_the_shaft",
    "tests/test_skf_friction.py::test_shaft_skf_torque_derivatives_through_the_shaft",
    "tests/test_starved_film.py::test_finite_line_derivatives_match_central_differences",
    "tests/test_starved_film.py::test_starved_finite_line_derivatives_match_central_differences",
    "tests/test_starved_film.py::test_finite_line_jacobian_assembly_equals_forward_mode[starved",
    "tests/test_starved_film.py::test_finite_line_warm_start_reaches_the_cold_solution_and_carries_no_derivative",
    "tests/test_starved_film.py::test_mass_conserving_meniscus_balance_keeps_mid_length_and_its_derivatives_are_implicit",
    "tests/test_starved_finite_line.py::test_the_papers_roller_starved_on_129_squared",
    "tests/test_starved_finite_line.py::test_starved_film_derivatives_match_central_differences",
    "tests/test_starved_point_ehl.py::test_starved_film_derivatives_match_central_differences",
    "tests/test_starved_point_ehl.py::test_a_ball_scene_starved_by_a_thick_layer_is_flooded",
    "tests/test_sweep.py::test_sweep_of_the_starved_line_film_equals_single_runs",
)


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.get_closest_marker("slow") and item.nodeid.startswith(EXTENDED):
            item.add_marker(pytest.mark.extended)


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
