"""Scene quantities and their display: speeds as engineers write them (docs/scenes.md §Scene files) — a bare frequency
counts revolutions, an angle per time converts as written, a bare number is SI."""

import math

import numpy as np
import pytest

from diffbearing.app.formatting import stiffness_lines
from diffbearing.app.units import to_si

THREE_THOUSAND_RPM = 3000.0 * 2.0 * math.pi / 60.0  # rad/s


@pytest.mark.parametrize("written", ["3000 r/min", "3000 rpm", "3000 rev/min", "3000 1/min", "3000 min⁻¹",
                                     "3000 min^-1", "50 Hz", "50 1/s", "50 rps", "0.05 kHz"])
def test_every_spelling_of_a_shaft_speed_is_revolutions(written):
    assert to_si(written, "angular_speed", "operating.inner_speed") == pytest.approx(THREE_THOUSAND_RPM, rel=1e-15)


@pytest.mark.parametrize("written, expected", [("50 rad/s", 50.0), (50, 50.0), ("18000 deg/s", THREE_THOUSAND_RPM)])
def test_angles_per_time_and_bare_numbers_convert_as_written(written, expected):
    assert to_si(written, "angular_speed", "operating.inner_speed") == pytest.approx(expected, rel=1e-15)


def test_a_speed_with_the_wrong_dimension_names_its_key():
    with pytest.raises(ValueError, match=r"shaft.speed: '3 N' is not an angular speed"):
        to_si("3 N", "angular_speed", "shaft.speed")


def test_stiffness_round_off_prints_as_zero():
    """A coupling of 1e-15 N/m beside diagonals of 1e9 N/m is rounding noise: the report shows 0; a
    real coupling (a tenth of the diagonals) is printed."""
    matrix = np.diag([1e9, 1e9, 2e8, 3e5, 3e5])
    matrix[0, 1] = matrix[1, 0] = 1e-15
    matrix[2, 4] = 1e6
    rows = stiffness_lines(matrix, "balls")[3:]
    assert rows[0].split() == ["Fx", "1000", "0", "0", "0", "0"]
    assert rows[2].split()[-1] == "1000"


def test_the_unit_registry_keeps_its_parsed_definitions_in_the_cache_folder_and_survives_a_broken_one(
        monkeypatch, tmp_path):
    """pint's parsed definitions go to the "pint" folder of the cache in use: JAX's folder where one
    is set (the tests set one), else DIFFBEARING_CACHE's; a half-written file is parsed around and
    the folder removed, to be written anew; with neither folder there is no cache."""
    import jax

    from diffbearing.app.units import registry

    build = registry.__wrapped__  # the registry itself is built once per process
    before = jax.config.jax_compilation_cache_dir
    try:
        jax.config.update("jax_compilation_cache_dir", str(tmp_path / "jax"))
        monkeypatch.setenv("DIFFBEARING_CACHE", str(tmp_path / "ours"))
        assert build().Quantity("1500 r/min").to("rad/s").magnitude == pytest.approx(50.0 * math.pi, rel=1e-15)
        stored = sorted((tmp_path / "jax" / "pint").glob("*.pickle"))
        assert stored and not (tmp_path / "ours").exists()
        for path in stored:  # as another process would leave a file it is still writing
            path.write_bytes(path.read_bytes()[:10])
        assert build().Quantity("60 degC").to("K").magnitude == pytest.approx(333.15, rel=1e-15)
        assert not (tmp_path / "jax" / "pint").exists(), "the broken cache is removed"
        build()
        assert sorted((tmp_path / "jax" / "pint").glob("*.pickle")), "and written anew by the next process"
        jax.config.update("jax_compilation_cache_dir", None)
        build()
        assert sorted((tmp_path / "ours" / "pint").glob("*.pickle")), "without JAX's folder, in DIFFBEARING_CACHE"
        monkeypatch.setenv("DIFFBEARING_CACHE", "off")
        assert build().cache_folder is None
    finally:
        jax.config.update("jax_compilation_cache_dir", before)
