"""Effect `safety`: ISO 76 C₀ and P₀ against the standard's tables and catalogue ratings, the safety
of the computed pressure against ISO 76's definition of C₀, and the minimum-load warning."""

import equinox as eqx
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import (
    Material,
    Operating,
    ball_bearing,
    ball_results,
    build_model,
    load_scene,
    run_model,
    solve_equilibrium,
)
from diffbearing.app.adapters.bearings.ball import ball_model
from diffbearing.bearings.ball import raceway_contact
from diffbearing.contact import hertz
from diffbearing.ratings import static_safety

from .helpers import assert_jvp_matches_central_difference, example_scene

ISO_STEEL = Material(207e9, 0.3, 7830.0, name="iso_76_steel")  # ISO/TR 10657's E and ν


def hertz_f0(gamma):
    """f₀ = 0.2 Q_max / D_w² [N/mm²] rebuilt from Hertz (ISO/TR 10657 §4.2.1): Q_max the ball load
    that brings the more stressed raceway of r_i = 0.52 D_w, r_e = 0.53 D_w to 4 200 MPa."""
    ball = 10e-3
    bearing = ball_bearing(ball_diameter=ball, pitch_diameter=ball / gamma, balls=6, kind="deep_groove_ball",
                           inner_groove_ratio=0.52, outer_groove_ratio=0.53, contact_angle=0.0,
                           ball_material=ISO_STEEL, ring_material=ISO_STEEL)
    modulus = hertz.effective_modulus(207e9, 0.3, 207e9, 0.3)
    loads = []
    for curvature in (raceway_contact.inner_curvature, raceway_contact.outer_curvature):
        unit = hertz.point_contact(1.0, *curvature(bearing, 0.0), modulus)
        loads.append((4.2e9 / float(unit.max_pressure)) ** 3)
    return 0.2 * min(loads) / (ball * 1e3) ** 2


def test_f0_table_is_the_hertz_load_at_4200_mpa():
    """ISO 76 Table 1 is Hertz at 4 200 MPa rounded to 0.1: every row from γ = 0.01 to 0.40 within
    0.06 (largest measured 0.053; the outer raceway governs to γ = 0.09, the inner beyond, hence the
    table's peak)."""
    for gamma, table in zip(static_safety.F0_RATIO[1:], static_safety.F0_VALUE[1:]):
        assert table == pytest.approx(hertz_f0(gamma), abs=0.06), gamma


@pytest.mark.parametrize("name, balls, ball, pitch, catalogue", [
    ("6206", 9, 9.525e-3, 46.0e-3, 11.3e3),   # NSK Rolling Bearings: C0r 11.3 kN, f0 13.8 (SKF: 11.2 kN, f0 14)
    ("6208", 9, 11.906e-3, 60.0e-3, 17.9e3),  # NSK: C0r 17.9 kN, f0 14.0 (NTN CAT.2203 Example 2: 17.8 kN, f0 14.0)
])
def test_static_rating_of_catalogue_bearings(name, balls, ball, pitch, catalogue):
    """C₀r of two deep-groove bearings within 1 % of their catalogue ratings, from the usual internal
    geometry (9 balls of 3/8 in and 15/32 in; the catalogues give no internal geometry, d_m is the
    mean of bore and outside diameter)."""
    assert float(static_safety.ball_static_load_rating(balls, ball, pitch, 0.0)) == pytest.approx(catalogue, rel=0.01)


def test_equivalent_static_loads():
    """ISO 76 Table 2: radial-contact X₀ 0.6, Y₀ 0.5; 40° X₀ 0.5, Y₀ 0.26 (P₀ = 0.5·1000 + 0.26·10 000
    = 3100 N); P₀ never below F_r; Y₀ 0.40 at 22.5°; tapered rollers 0.22 cot α; cylindrical F_r."""
    ball = static_safety.ball_equivalent_static_load
    assert float(ball(jnp.array([1000.0, 0.0, 1000.0]), 0.0, radial_contact=True)) == pytest.approx(1100.0, rel=1e-14)
    assert float(ball(jnp.array([1000.0, 0.0, 100.0]), 0.0, radial_contact=True)) == pytest.approx(1000.0, rel=1e-14)
    forty = np.radians(40.0)
    assert float(ball(jnp.array([0.0, 1000.0, 10000.0]), forty, radial_contact=False)) == pytest.approx(3100.0, rel=1e-12)
    assert float(ball(jnp.array([0.0, 0.0, 500.0]), forty, radial_contact=False)) == pytest.approx(130.0, rel=1e-12)
    assert float(ball(jnp.array([0.0, 0.0, 1.0]), np.radians(22.5), radial_contact=False)) == pytest.approx(0.40)
    assert np.isnan(float(ball(jnp.array([0.0, 0.0, 1.0]), np.radians(2.0), radial_contact=False)))
    roller = static_safety.roller_equivalent_static_load
    fifteen = np.radians(15.0)
    assert float(roller(jnp.array([1000.0, 0.0, 5000.0]), fifteen)) == pytest.approx(500 + 0.22 / np.tan(fifteen) * 5000)
    assert float(roller(jnp.array([3000.0, 4000.0, 5000.0]), 0.0)) == pytest.approx(5000.0, rel=1e-14)


def test_double_row_equivalent_static_loads():
    """ISO 76 Table 2's double-row column, X₀ = 1 and Y₀ twice the single row's: P₀ = F_r + 0.92,
    0.76, 0.66, 0.52 F_a at 15°, 25°, 30°, 40° (the values LYC prints for pairs back to back and SKF
    for its 32 A series, 0.66), never below F_r, NaN outside 5°…45°."""
    double = static_safety.double_row_equivalent_static_load
    for angle, y0 in ((15.0, 0.92), (25.0, 0.76), (30.0, 0.66), (40.0, 0.52)):
        assert float(double(jnp.array([600.0, 800.0, 2000.0]), np.radians(angle))) == pytest.approx(1000.0 + y0 * 2000.0,
                                                                                                  rel=1e-12)
    assert float(double(jnp.array([3000.0, 0.0, 0.0]), np.radians(30.0))) == pytest.approx(3000.0, rel=1e-15)
    assert np.isnan(float(double(jnp.array([0.0, 0.0, 1.0]), np.radians(50.0))))


def test_pressure_safety_at_the_static_rating():
    """A zero-clearance deep-groove bearing of ISO 76's conformity under F_r = C₀r: ISO 76 takes
    Q_max = 5 F_r / Z, the rigid rings give Q_max = F_r / Σ cos^{5/2} ψ_j (4.386 F_r / Z for 9
    balls), so the pressure safety is 5 Σ cos^{5/2} ψ / Z = 1.140 (within the table's rounding, 0.5 %)."""
    bearing = ball_bearing(ball_diameter=11.906e-3, pitch_diameter=60e-3, balls=9, kind="deep_groove_ball",
                           inner_groove_ratio=0.52, outer_groove_ratio=0.53, radial_clearance=0.0,
                           ball_material=ISO_STEEL, ring_material=ISO_STEEL)
    rating = static_safety.ball_static_load_rating(9, 11.906e-3, 60e-3, 0.0)
    operating = Operating(0.0, 0.0, jnp.array([float(rating), 0.0, 0.0]), jnp.zeros(2))
    model = ball_model({"effects": {}, "fidelity": {}})
    solution = solve_equilibrium(bearing, operating, model)
    balls = ball_results(solution.displacement, bearing, operating, model)
    pressure = jnp.maximum(balls.inner_max_pressure.max(), balls.outer_max_pressure.max())
    safety = float(static_safety.pressure_safety(pressure, 4.2e9, 3.0))
    cosines = np.cos(2 * np.pi * np.arange(9) / 9)
    expected = 5 * np.sum(np.clip(cosines, 0, None) ** 2.5) / 9
    assert expected == pytest.approx(1.140, abs=1e-3)
    assert safety == pytest.approx(expected, rel=0.005)


ROLLER_AT_RATING = """
title = "cylindrical roller bearing at its static rating"
[bearing]
type = "cylindrical_roller"
roller_diameter = "25.4 mm"
roller_length = "14.7 mm"
pitch_diameter = "106.6 mm"
rollers = 12
radial_clearance = "0 um"
[profile]
kind = "straight"
[material]
elastic_modulus = "207 GPa"
poisson_ratio = 0.3
[operating]
force = ["{force} N", "0 kN", "0 kN"]
[effects]
contact = "slices"
safety = true
[fidelity]
laminae = 10
"""


def test_roller_pressure_safety_at_the_static_rating(tmp_path):
    """Straight cylindrical rollers, zero clearance, F_r = C₀r = 44 (1 − γ) Z L D: ISO 76's
    Q_max = 5 F_r/Z against the laminae's F_r/Σ cos^{19/9} ψ_j (q ∝ δ^{10/9}, ISO/TS 16281) gives
    the line-contact safety (4000/p_max)² = 5 Σ cos^{19/9} ψ / Z × 44.19/44 (the factor 44 rounds
    the Hertz 44.19 of E = 207 GPa, ν = 0.3), within 0.5 %."""
    rating = float(static_safety.roller_static_load_rating(12, 25.4e-3, 14.7e-3, 106.6e-3, 0.0))
    path = tmp_path / "roller.toml"
    path.write_text(ROLLER_AT_RATING.replace("{force}", repr(rating)))
    values = run_model(build_model(load_scene(str(path))), progress=False).values
    assert float(values["safety.static_load_rating"]) == pytest.approx(rating, rel=1e-14)
    assert float(values["safety.iso76"]) == pytest.approx(1.0, rel=1e-12)
    cosines = np.cos(2 * np.pi * np.arange(12) / 12)
    expected = 5 * np.sum(np.clip(cosines, 0, None) ** (19 / 9)) / 12 * 44.19 / 44.0
    assert float(values["safety.static"]) == pytest.approx(expected, rel=0.005)


@pytest.mark.parametrize("speed, warned", [("3000 rpm", True), ("0 rpm", False)])
def test_minimum_load_warns_only_when_turning(speed, warned):
    """2.04 kN on a cylindrical roller bearing of C_r = 162 kN (below 0.02 C_r): a warning at speed."""
    result = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"), overrides=[
        "effects.safety=true", "effects.stiffness=false", f"operating.inner_speed={speed}"])), progress=False)
    errors, warnings = result.problems
    assert not errors
    assert any("below the minimum load" in line for line in warnings) == warned
    assert float(result.values["safety.minimum_load"]) == pytest.approx(
        0.02 * float(result.values["life.basic_dynamic_load_rating"]), rel=1e-14)


def test_static_safety_derivatives():
    """d(C₀, P₀, pressure safety)/d(force, pitch diameter, p_max) of a 40° bearing against a central
    difference, forward and reverse."""
    bearing = ball_bearing(ball_diameter=11.906e-3, pitch_diameter=60e-3, balls=9, inner_groove_ratio=0.52,
                           outer_groove_ratio=0.53, contact_angle=np.radians(40.0))

    def safety(point):
        force, pitch, pressure = point
        return static_safety.bearing_static_safety(eqx.tree_at(lambda b: b.pitch_diameter, bearing, pitch), None,
                                                   force, pressure)

    point = (jnp.array([1000.0, 300.0, 2000.0]), jnp.asarray(60e-3), jnp.asarray(2.5e9))
    direction = (jnp.array([50.0, -20.0, 80.0]), jnp.asarray(1e-3), jnp.asarray(1e8))
    assert_jvp_matches_central_difference(safety, point, direction, 1e-3, rtol=1e-6)


def test_hybrid_bearing_is_rated_as_all_steel_and_says_so():
    """Silicon nitride balls (E 310 GPa): the same ISO 76 C₀ as the all-steel bearing, a higher
    computed pressure (E' up, so p_max ∝ E'^{2/3} at nearly the same ball load), and a warning that
    the ratings are the all-steel ones; none for steel balls."""
    runs = {}
    for preset in ("bearing_steel", "silicon_nitride"):
        result = run_model(build_model(load_scene(example_scene("deep_groove_6411"), overrides=[
            "effects.safety=true", "effects.stiffness=false", f"material.ball_preset={preset}"])), progress=False)
        runs[preset] = (result.values, result.problems[1])
    (steel, steel_warnings), (hybrid, hybrid_warnings) = runs["bearing_steel"], runs["silicon_nitride"]
    assert not any("hybrid" in line for line in steel_warnings)
    assert any("hybrid bearing" in line for line in hybrid_warnings)
    assert float(hybrid["safety.hybrid"]) == 1.0 and float(steel["safety.hybrid"]) == 0.0
    assert float(hybrid["safety.static_load_rating"]) == float(steel["safety.static_load_rating"])
    assert float(hybrid["safety.max_pressure"]) > 1.05 * float(steel["safety.max_pressure"])
    assert float(hybrid["safety.static"]) < float(steel["safety.static"])
