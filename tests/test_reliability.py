"""Lives at another reliability (`life.reliability`): ISO 281 Table 12's a₁ against the Weibull form
it is printed from, its derivative, a random walk of its range, and every life of a bearing, a
shaft, a set and a roller bearing scaled by it; bad reliabilities exit 2 naming the key."""

import hypothesis
import hypothesis.strategies as st
import jax
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.ratings import reliability

from .helpers import assert_jvp_matches_central_difference, example_scene


def _a1(percent):
    """a₁ written out: 0.95 (ln(100/R)/ln(100/90))^{2/3} + 0.05."""
    return 0.95 * (np.log(100.0 / percent) / np.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05


@pytest.mark.parametrize("percent, printed", reliability.TABLE_12)
def test_table_12_is_the_weibull_form_to_its_rounding(percent, printed):
    """ISO 281:2007 Table 12 (GOST 18855-2013): each printed a₁ is the form's value rounded to the
    digits printed (0.64, 0.093: half a unit of the last digit); 1 at 90 % exactly."""
    digits = len(f"{printed:g}".split(".")[1]) if printed != 1.0 else 0
    value = float(reliability.reliability_factor(percent))
    assert abs(value - printed) <= 0.5 * 10.0**-digits + 1e-15
    assert value == pytest.approx(_a1(percent), rel=1e-15)
    if percent == 90.0:
        assert value == 1.0


@hypothesis.settings(max_examples=30, deadline=None)
@hypothesis.given(low=st.floats(90.0, 99.95), high=st.floats(90.0, 99.95))
def test_a1_falls_with_the_reliability_over_the_tables_range(low, high):
    """Random reliabilities in 90–99.95 %: a₁ within [a₁(99.95 %), 1] and never rising with R."""
    low, high = sorted((low, high))
    a_low, a_high = float(reliability.reliability_factor(low)), float(reliability.reliability_factor(high))
    assert _a1(99.95) - 1e-15 <= a_high <= a_low <= 1.0 + 1e-15


@pytest.mark.parametrize("percent", [89.9, 99.96, 100.0, float("nan")])
def test_a_reliability_outside_table_12_is_refused_naming_its_key(percent):
    with pytest.raises(ValueError, match="life.reliability"):
        reliability.reliability_factor(percent)


@pytest.mark.parametrize("percent", [92.5, 99.5])
def test_a1_derivative_matches_central_differences(percent):
    assert_jvp_matches_central_difference(jax.jit(reliability.reliability_factor), np.array(percent), np.array(1.0),
                                          1e-4, rtol=1e-7)


def _lives(name: str, percent, *overrides):
    scene = load_scene(example_scene(name), overrides=[f"life.reliability={percent}", "effects.life=true", *overrides])
    return run_model(build_model(scene), progress=False).values


def test_a_bearings_and_a_shafts_lives_at_99_percent_are_a1_times_theirs():
    """gearbox_6411_ratings (a ball bearing with its oil: L10, L10r, L10m, L10rm) and gearbox_shaft (two
    bearings: each one's L10, L10r and the system's L10r) at R = 99 %: every L_n is a₁(99 %) = 0.2483
    times its L10 (1e-12); a₁ reported."""
    factor = _a1(99.0)
    single = _lives("gearbox_6411_ratings", 99)
    assert float(single["life.a1"]) == pytest.approx(factor, rel=1e-14)
    for at_90, at_r in [("L10", "Ln"), ("L10r", "Lnr"), ("L10m", "Lnm"), ("L10rm", "Lnrm")]:
        assert float(single[f"life.{at_r}"]) == pytest.approx(factor * float(single[f"life.{at_90}"]), rel=1e-12)
    shaft = _lives("gearbox_shaft", 99)
    for at_90, at_r in [("bearings.L10", "bearings.Ln"), ("bearings.L10r", "bearings.Lnr"), ("shaft.L10r", "shaft.Lnr")]:
        np.testing.assert_allclose(np.asarray(shaft[at_r]), factor * np.asarray(shaft[at_90]), rtol=1e-12)


@pytest.mark.slow
def test_a_sets_and_a_roller_bearings_lives_at_95_percent_are_a1_times_theirs():
    """spindle_pair (each bearing's L10r and the set's) and cylindrical_roller_bearing (L10, L10r) at
    R = 95 %: a₁ = 0.6379 (Table 12: 0.64) times each, 1e-12."""
    factor = _a1(95.0)
    pair = _lives("spindle_pair", 95)
    for key in ("set.bearings.0.L10r", "set.bearings.1.L10r", "set.L10r"):
        assert float(pair[key.replace("L10r", "Lnr")]) == pytest.approx(factor * float(pair[key]), rel=1e-12)
    roller = _lives("cylindrical_roller_bearing", 95)
    for at_90, at_r in [("life.L10", "life.Ln"), ("life.L10r", "life.Lnr")]:
        assert float(roller[at_r]) == pytest.approx(factor * float(roller[at_90]), rel=1e-12)


@pytest.mark.parametrize("percent", ["80", "99.99"])
def test_a_bad_reliability_in_a_scene_exits_2_naming_it(capsys, percent):
    code = cli.main(["run", example_scene("gearbox_6411_ratings"), "--set", f"life.reliability={percent}"])
    err = capsys.readouterr().err
    assert code == 2 and "life.reliability" in err and len(err.strip().splitlines()) == 1, err
