"""Grease life (`diffbearing.ratings.grease_life`, `effects.grease_life`): FYH's worked example,
NSK's and JTEKT's printed equations at their corners and floors, each method's envelope (an error
beyond its bounds, NSK's load guide a warning), derivatives against central differences, random
operating points; the packaged motor example, the thermal network's outer ring temperature read
with effects.thermal; bad inputs exit 2 naming their key, a state outside exits 3."""

import math

import hypothesis
import hypothesis.strategies as st
import jax.numpy as jnp
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.ratings.grease_life import CELSIUS_ZERO, GREASE_LIFE_METHODS, HOUR, envelope_problems

from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference, example_scene
from .test_thermal_effect import SINGLE

RPM = math.pi / 30
NSK_GENERAL, NSK_WIDE = GREASE_LIFE_METHODS["nsk_general_purpose"], GREASE_LIFE_METHODS["nsk_wide_range"]
JTEKT, FYH = GREASE_LIFE_METHODS["jtekt_sealed"], GREASE_LIFE_METHODS["fyh_bearing_unit"]


def _log_hours(found):
    return math.log10(float(found.life) / HOUR)


def test_fyh_worked_example():
    """FYH CAT. No. 3300, §4.3, example 8: a UCP204J unit (UC204: d = 20 mm, D = 47 mm) at 800 r/min
    under F_r = 1 kN with C_r/P_r = 12.8 at 40 °C — d_m n and T below their floors, taken as
    12.5·10⁴ and 50 °C: log L = 4.542, L ≈ 34 800 h (the catalogue's rounding: 5e-4, 50 h)."""
    found = FYH.grease_life(800 * RPM, None, 20e-3, 47e-3, 1e3, 12.8e3, 40.0 + CELSIUS_ZERO)
    assert _log_hours(found) == pytest.approx(4.542, abs=5e-4)
    assert float(found.life) / HOUR == pytest.approx(34_800, abs=50)
    assert float(found.speed_term) == 125e3 and float(found.temperature) == 50.0 + CELSIUS_ZERO


def test_nsk_equations_at_their_corners_and_floors():
    """NSK CAT. No. E1102 eqs. (12.1), (12.2) at n/N_max = 0.25 and 1, T = 70 °C and the upper bound:
    the printed coefficients' values (1e-12); below n/N_max = 0.25 and 70 °C the life is the floor's
    (exact); the life falls with speed and temperature."""
    def log_t(method, ratio, celsius):
        return _log_hours(method.grease_life(ratio * 10_000 * RPM, 10_000 * RPM, 0.0, 0.0, 1e3, 20e3,
                                             celsius + CELSIUS_ZERO))

    for method, (a, b, c, e), top in ((NSK_GENERAL, (6.54, 2.6, 0.025, 0.012), 110.0),
                                      (NSK_WIDE, (6.12, 1.4, 0.018, 0.006), 130.0)):
        for ratio in (0.25, 1.0):
            for celsius in (70.0, top):
                assert log_t(method, ratio, celsius) == pytest.approx(a - b * ratio - (c - e * ratio) * celsius,
                                                                      rel=1e-12)
        assert log_t(method, 0.1, 40.0) == log_t(method, 0.25, 70.0)
        assert log_t(method, 0.5, 90.0) < log_t(method, 0.4, 90.0) and log_t(method, 0.5, 95.0) < log_t(method, 0.5, 90.0)
    assert log_t(NSK_GENERAL, 0.25, 70.0) == pytest.approx(4.35, rel=1e-12)  # 22 400 h
    assert log_t(NSK_WIDE, 0.25, 70.0) == pytest.approx(4.615, rel=1e-12)  # the synthetic grease lasts longer


def test_jtekt_sealed_equation_and_floors():
    """JTEKT CAT. No. BS004 eq. (12-1) at d_m n = 300·10³, P_r/C_r = 0.1, 90 °C against the printed
    form (1e-12); below its floors (d_m n 125·10³, P_r/C_r 0.04, T 50 °C) the life is the floors'."""
    bore, outside = 40e-3, 80e-3  # d_m = 60 mm
    found = JTEKT.grease_life(5000 * RPM, None, bore, outside, 2e3, 20e3, 90.0 + CELSIUS_ZERO)
    want = 6.10 - 4.40e-6 * 300e3 - 3.125 * (0.1 - 0.04) - (0.021 - 1.80e-8 * 300e3) * 90.0
    assert _log_hours(found) == pytest.approx(want, rel=1e-12)
    low = JTEKT.grease_life(1000 * RPM, None, bore, outside, 0.2e3, 20e3, 30.0 + CELSIUS_ZERO)
    floor = JTEKT.grease_life(125e3 / 60 * RPM, None, bore, outside, 0.8e3, 20e3, 50.0 + CELSIUS_ZERO)
    assert _log_hours(low) == pytest.approx(_log_hours(floor), abs=1e-12)


def test_each_method_reports_its_bounds():
    """Beyond a method's temperature, speed or (JTEKT's, FYH's) load bound: an error naming the value
    and the bound; NSK's "about 1/10 of C_r" passed: a warning; inside: nothing."""
    inside = NSK_GENERAL.grease_life(5000 * RPM, 10_000 * RPM, 0.0, 0.0, 1e3, 20e3, 90.0 + CELSIUS_ZERO)
    assert envelope_problems(NSK_GENERAL, inside) == ([], [])
    hot = NSK_GENERAL.grease_life(5000 * RPM, 10_000 * RPM, 0.0, 0.0, 1e3, 20e3, 115.0 + CELSIUS_ZERO)
    assert "115 °C is above the method's 110 °C" in envelope_problems(NSK_GENERAL, hot)[0][0]
    assert envelope_problems(NSK_WIDE, hot) == ([], [])
    fast = NSK_GENERAL.grease_life(11_000 * RPM, 10_000 * RPM, 0.0, 0.0, 1e3, 20e3, 90.0 + CELSIUS_ZERO)
    assert "n/N_max = 1.1" in envelope_problems(NSK_GENERAL, fast)[0][0]
    loaded = NSK_GENERAL.grease_life(5000 * RPM, 10_000 * RPM, 0.0, 0.0, 3e3, 20e3, 90.0 + CELSIUS_ZERO)
    errors, warnings = envelope_problems(NSK_GENERAL, loaded)
    assert errors == [] and "P_r/C_r = 0.15" in warnings[0]
    errors, warnings = envelope_problems(JTEKT, JTEKT.grease_life(5000 * RPM, None, 40e-3, 80e-3, 3.4e3, 20e3, 360.0))
    assert warnings == [] and "P_r/C_r = 0.17 is above the method's 0.16" in errors[0]
    errors, _ = envelope_problems(FYH, FYH.grease_life(6000 * RPM, None, 40e-3, 80e-3, 1e3, 20e3, 350.0), "bearings[1]: ")
    assert errors == ["bearings[1]: grease_life: d_m n = 3.6e+05 mm·r/min is above the method's 3e+05 mm·r/min"]


def test_derivatives_are_central_differences():
    """∂ log₁₀ t/∂(speed, temperature, load) of each method above its floors against central
    differences (1e-7)."""
    def outputs(method, limiting):
        def log_life(x):
            found = method.grease_life(x[0] * RPM, limiting, 40e-3, 80e-3, x[2] * 1e3, 20e3, x[1])
            return jnp.log10(found.life / HOUR)[None]
        return log_life

    point = jnp.array([4000.0, 363.15, 2.0])
    for method in GREASE_LIFE_METHODS.values():
        for index, step in enumerate((1.0, 1e-3, 1e-4)):
            assert_jvp_matches_central_difference(outputs(method, 10_000 * RPM), point, jnp.zeros(3).at[index].set(1.0),
                                                  step, rtol=1e-7)


@hypothesis.settings(max_examples=60, deadline=None)
@hypothesis.given(method=st.sampled_from(sorted(GREASE_LIFE_METHODS)), rpm=st.floats(0.0, 40_000.0),
                  celsius=st.floats(-60.0, 250.0), load=st.floats(0.0, 10e3), bore=st.floats(5e-3, 200e-3))
def test_random_operating_points_give_a_life_or_say_why_not(method, rpm, celsius, load, bore):
    """Any operating point: a finite positive life; inside every bound no error, beyond one an error
    (or NSK's load warning) — never a silent number outside the method."""
    formula = GREASE_LIFE_METHODS[method]
    found = formula.grease_life(rpm * RPM, 12_000 * RPM, bore, 2 * bore, load, 20e3, celsius + CELSIUS_ZERO)
    assert math.isfinite(float(found.life)) and float(found.life) > 0.0
    errors, warnings = envelope_problems(formula, found)
    limits = formula.limits()
    beyond = (celsius + CELSIUS_ZERO > limits.temperature or float(found.speed_term) > limits.speed
              or (load / 20e3 > limits.load_ratio and not limits.load_is_guide))
    assert bool(errors) == beyond
    assert bool(warnings) == (limits.load_is_guide and load / 20e3 > limits.load_ratio)


MOTOR = open(example_scene("motor_6205_grease")).read()


def _run(path, overrides=()):
    return run_model(build_model(load_scene(str(path), overrides=list(overrides))), progress=False)


def test_the_motor_example_is_nsks_equation(tmp_path):
    """motor_6205_grease: no problem; the life is eq. (12.1) at n/N_max = 3000/13 000 → 0.25 (its
    floor) and 80 °C, log t = 6.54 − 0.65 − 0.022 · 80 = 4.13 (1e-12); P_r/C_r is ISO 281's P over
    the catalogue's 14 kN; with JTEKT's form the life reads d_m n (38.5 mm · 3000 r/min → its floor)."""
    result = _run(example_scene("motor_6205_grease"))
    values = result.values
    assert result.problems == ([], [])
    assert math.log10(float(values["grease_life.life"]) / HOUR) == pytest.approx(4.13, rel=1e-12)
    assert float(values["grease_life.speed_term"]) == 0.25
    assert float(values["grease_life.load_ratio"]) == pytest.approx(float(values["life.equivalent_load"]) / 14e3,
                                                                    rel=1e-12)
    path = tmp_path / "jtekt.toml"
    path.write_text(MOTOR.replace('grease_life = "nsk_general_purpose"', 'grease_life = "jtekt_sealed"').replace(
        'limiting_speed = "13000 rpm"', ""))
    jtekt = _run(path).values
    want = 6.10 - 4.40e-6 * 125e3 - 3.125 * (float(jtekt["grease_life.load_ratio"]) - 0.04) - (0.021 - 1.8e-8 * 125e3) * 80
    assert math.log10(float(jtekt["grease_life.life"]) / HOUR) == pytest.approx(want, rel=1e-12)


@pytest.mark.slow
def test_with_effects_thermal_the_life_is_at_the_networks_outer_ring(tmp_path):
    """The mounted 6411 in the thermal fixed point: the temperature the grease life reads is the
    network's outer ring's (exact), and the life is the formula's there."""
    path = tmp_path / "warm.toml"
    path.write_text(SINGLE.replace("life = true", 'life = true\ngrease_life = "jtekt_sealed"'))
    values = _run(path).values
    assert float(values["grease_life.temperature"]) == float(values["thermal.outer_ring_temperature"])
    found = JTEKT.grease_life(3000 * RPM, None, 55e-3, 140e-3, float(values["life.equivalent_load"]),
                              float(values["life.basic_dynamic_load_rating"]), float(values["thermal.outer_ring_temperature"]))
    assert float(values["grease_life.life"]) == pytest.approx(float(found.life), rel=1e-12)


@pytest.mark.parametrize("override, named", [
    ('grease_life.temperature="120 degC"', "grease_life.temperature"),
    ('effects.grease_life="jtekt_sealed"', "grease_life.limiting_speed"),
    ('effects.grease_life="lithium"', "effects.grease_life"),
    ('grease_life.limiting_speed="-1 rpm"', "grease_life.limiting_speed"),
])
def test_bad_grease_inputs_exit_2_naming_their_key(capsys, override, named):
    assert_exits_2_naming(capsys, ["run", "motor_6205_grease", "--set", override], named)


def test_a_grease_life_without_its_inputs_or_outside_its_scope_exits_2(capsys, tmp_path):
    """NSK's method without N_max; a bearing type the formulas do not cover (an angular contact
    bearing, a cylindrical roller bearing): exit 2 naming the key."""
    path = tmp_path / "motor.toml"
    path.write_text(MOTOR.replace('limiting_speed = "13000 rpm"', ""))
    assert_exits_2_naming(capsys, ["run", str(path)], "grease_life.limiting_speed")
    for scene in ("aero_angular_contact", "cylindrical_roller_bearing"):
        assert_exits_2_naming(capsys, ["run", scene, "--set", 'effects.grease_life="jtekt_sealed"'],
                              "effects.grease_life")


def test_a_given_temperature_with_the_network_exits_2(capsys, tmp_path):
    path = tmp_path / "warm.toml"
    path.write_text(SINGLE.replace("life = true", 'life = true\ngrease_life = "jtekt_sealed"')
                    + '\n[grease_life]\ntemperature = "70 degC"\n')
    assert_exits_2_naming(capsys, ["run", str(path)], "grease_life.temperature")


def test_a_speed_beyond_the_method_exits_3(capsys):
    """14 000 r/min on a 13 000 r/min N_max: the state is outside NSK's equation — exit 3, named."""
    from diffbearing.app import cli

    code = cli.main(["run", "motor_6205_grease", "--set", 'operating.inner_speed="14000 rpm"'])
    err = capsys.readouterr().err
    assert code == 3 and "n/N_max = 1.077 is above the method's 1" in err, err
