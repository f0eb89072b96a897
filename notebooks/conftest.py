"""The design notebooks that take longest run with the slow cases (`pytest -m slow`, which CI
runs with --nbmake over tests and notebooks); the rest run in the default `pytest`."""

import pytest

# with a cold compilation cache on 2 cores: 79 s, 39 s, 27 s, 55 s, 195 s, 27 s, 89 s
SLOW_NOTEBOOKS = ("ball_bearing_stiffness_design.ipynb", "cage_pocket_clearance_design.ipynb",
                  "roller_crowning_design.ipynb", "roller_bearing_crowning_design.ipynb",
                  "spindle_preload_design.ipynb", "rotor_critical_speeds.ipynb", "spindle_thermal_preload.ipynb")


# of those, CI leaves out (the `extended` cases, pyproject.toml): 833 s with a cold cache
EXTENDED_NOTEBOOKS = ("spindle_preload_design.ipynb",)


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.path.name in SLOW_NOTEBOOKS:
            item.add_marker(pytest.mark.slow)
        if item.path.name in EXTENDED_NOTEBOOKS:
            item.add_marker(pytest.mark.extended)
