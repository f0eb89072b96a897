"""Effect `frequencies`: overrolling frequencies at the solved contact angles against the textbook
closed forms (Harris & Kotzalas vol. 1, §8), for a turning inner or outer ring, ball and roller
bearings, orders at standstill, and the shift at speed."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, overrolling, run_model
from diffbearing.app.report import format_report

from .helpers import BEARING_6411E, central_difference_jvp, example_scene

FIELDS = ("cage", "ball_pass_outer", "ball_pass_inner", "ball_spin")


def textbook(inner_hz, outer_hz, count, diameter, pitch, angle):
    """FTF, BPFO, BPFI, BSF [Hz] written out (Harris & Kotzalas vol. 1, §8; rings at f_i, f_o)."""
    gamma = diameter * np.cos(angle) / pitch
    relative = abs(inner_hz - outer_hz)
    return {"cage": 0.5 * (inner_hz * (1 - gamma) + outer_hz * (1 + gamma)),
            "ball_pass_outer": 0.5 * count * relative * (1 - gamma),
            "ball_pass_inner": 0.5 * count * relative * (1 + gamma),
            "ball_spin": pitch / (2 * diameter) * relative * (1 - gamma**2)}


def _run(tmp_path, text):
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return run_model(build_model(load_scene(str(path))), progress=False).values


def _ball_scene(inner, outer, speed_effects):
    return BEARING_6411E + f"""
[operating]
inner_speed = "{inner} rpm"
outer_speed = "{outer} rpm"
force = ["0 N", "0 N", "10 kN"]

[effects]
frequencies = true
centrifugal = {str(speed_effects).lower()}
gyroscopic = {str(speed_effects).lower()}
"""


@pytest.mark.parametrize("inner, outer", [(6000.0, 0.0), (0.0, 6000.0), (4000.0, -1500.0)])
def test_ball_frequencies_are_the_closed_forms_at_the_solved_angle(tmp_path, inner, outer):
    """Without speed effects every ball of an axially loaded bearing sits at one contact angle α:
    the frequencies are the textbook ones at that α to 1e-12, for any turning ring."""
    values = _run(tmp_path, _ball_scene(inner, outer, speed_effects=False))
    angle = np.asarray(values["balls.inner.contact_angle"])
    assert np.ptp(angle) < 1e-12 and np.allclose(values["balls.outer.contact_angle"], angle, rtol=0, atol=1e-12)
    want = textbook(inner / 60, outer / 60, 7, 26.9875e-3, 97.5e-3, angle[0])
    for field in FIELDS:
        assert float(values[f"frequencies.{field}"]) == pytest.approx(want[field], rel=1e-12), field
        assert float(values[f"frequencies.orders.{field}"]) == pytest.approx(
            want[field] / abs(inner - outer) * 60, rel=1e-12), field
    free = textbook(inner / 60, outer / 60, 7, 26.9875e-3, 97.5e-3, 0.0)  # a deep-groove bearing's nominal angle
    for field in FIELDS:
        assert float(values[f"frequencies.nominal.{field}"]) == pytest.approx(free[field], rel=1e-12), field


def test_orders_at_standstill_are_those_of_the_turning_bearing(tmp_path):
    """Orders depend on the contact angles only: at standstill they are those of 6000 r/min."""
    still = _run(tmp_path, _ball_scene(0.0, 0.0, speed_effects=False))
    turning = _run(tmp_path, _ball_scene(6000.0, 0.0, speed_effects=False))
    for field in FIELDS:
        assert float(still[f"frequencies.{field}"]) == 0.0
        assert float(still[f"frequencies.orders.{field}"]) == pytest.approx(
            float(turning[f"frequencies.orders.{field}"]), rel=1e-12)


def test_speed_effects_shift_the_frequencies_from_the_nominal(tmp_path):
    """At 6000 r/min centrifugal force opens the inner and closes the outer contact angle; the
    passes still add up to Z per relative revolution (BPFO + BPFI = Z |f_i − f_o|, exact), and the
    cage stays within 5 % of the textbook value at the mean angle (Harris's order of the shift)."""
    values = _run(tmp_path, _ball_scene(6000.0, 0.0, speed_effects=True))
    inner_angle, outer_angle = (np.asarray(values[f"balls.{side}.contact_angle"]) for side in ("inner", "outer"))
    assert np.all(inner_angle > outer_angle + 1e-3)
    total = float(values["frequencies.ball_pass_outer"]) + float(values["frequencies.ball_pass_inner"])
    assert total == pytest.approx(7 * 100.0, rel=1e-12)
    mean = textbook(100.0, 0.0, 7, 26.9875e-3, 97.5e-3, 0.5 * (inner_angle.mean() + outer_angle.mean()))
    assert float(values["frequencies.cage"]) == pytest.approx(mean["cage"], rel=0.05)
    assert float(values["frequencies.cage"]) != pytest.approx(float(values["frequencies.nominal.cage"]), rel=1e-3)


def test_cylindrical_roller_frequencies_are_the_closed_forms(tmp_path):
    """A cylindrical roller bearing (α = 0) at 3000 r/min: the textbook forms to 1e-12; its report
    names rollers, not balls."""
    result = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"), overrides=[
        "effects.frequencies=true", "effects.stiffness=false", "effects.life=false",
        "operating.inner_speed=3000 rpm"])), progress=False)
    values = result.values
    want = textbook(50.0, 0.0, 12, 25.4e-3, 106.6e-3, 0.0)
    for field in FIELDS:
        assert float(values[f"frequencies.{field}"]) == pytest.approx(want[field], rel=1e-12), field
    report = format_report(result)
    assert "roller pass, outer raceway BPFO" in report and "roller spin BSF" in report and "ball" not in report


def test_tapered_roller_rolls_on_both_raceways():
    """A tapered roller (cone 10.2°, cup 15°) in pure rolling: the roller's surface speed relative
    to the cage is the same at the cone and the cup, ω_c (R_i + R_o) = ω_i R_i + ω_o R_o (exact)."""
    diameter, pitch, cone, cup = 7.5e-3, 50.686e-3, np.radians(10.2), np.radians(15.0)
    frequencies = overrolling.roller_bearing_frequencies(2 * np.pi * 50.0, 2 * np.pi * 5.0, 18, diameter, pitch, cone, cup)
    inner_radius, outer_radius = 0.5 * (pitch - diameter * np.cos(cone)), 0.5 * (pitch + diameter * np.cos(cup))
    cage = float(frequencies.cage)
    assert (50.0 - cage) * inner_radius == pytest.approx((cage - 5.0) * outer_radius, rel=1e-12)
    assert float(frequencies.ball_spin) == pytest.approx((50.0 - cage) * 2 * inner_radius / diameter, rel=1e-12)


def test_frequencies_derivative_in_the_contact_angles():
    """d(BPFI)/d(α_i, α_o, loads) of the ball formula against a central difference (the load-weighted
    cage), and finite at zero load."""
    def bpfi(angles):
        inner, outer, load = angles
        return overrolling.ball_bearing_frequencies(600.0, 0.0, 3, 0.01, 0.05, inner, outer, load).ball_pass_inner

    point = (jnp.array([0.3, 0.35, 0.4]), jnp.array([0.28, 0.3, 0.33]), jnp.array([100.0, 50.0, 0.0]))
    direction = (jnp.array([1.0, -0.5, 0.2]), jnp.array([0.3, 0.1, -1.0]), jnp.array([10.0, -20.0, 5.0]))
    _, tangent = jax.jvp(bpfi, (point,), (direction,))
    assert float(tangent) == pytest.approx(float(central_difference_jvp(bpfi, point, direction, 1e-6)), rel=1e-7)
    unloaded = (point[0], point[1], jnp.zeros(3))
    gradient = jax.grad(bpfi)(unloaded)
    assert all(np.all(np.isfinite(g)) for g in gradient)
