"""ISO 281 and ISO 76 ratings of thrust ball bearings (`ratings.thrust_ball_ratings`): the
standards' formulas written out at tabulated points, Table 5's closed forms against its printed
rows, interpolation between Table 4's columns, and NaN outside the tables."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.ratings import thrust_ball_ratings as thrust

from .helpers import assert_jvp_matches_central_difference

# ISO 281 Table 5 as printed (GOST 18855-2013): α → (single direction X; double, F_a/F_r ≤ e: X₁, Y₁; e)
TABLE_5 = {45: (0.66, 1.18, 0.59, 1.25), 50: (0.73, 1.37, 0.57, 1.49), 55: (0.81, 1.60, 0.56, 1.79),
           60: (0.92, 1.90, 0.55, 2.17), 65: (1.06, 2.30, 0.54, 2.68), 70: (1.28, 2.90, 0.53, 3.43),
           75: (1.66, 3.89, 0.52, 4.67), 80: (2.43, 5.86, 0.52, 7.09), 85: (4.80, 11.75, 0.51, 14.29)}


def test_an_axial_bearings_dynamic_rating_is_eq_5_with_table_4():
    """α = 90°, 15 balls of 12.7 mm on D_pw = 85 mm: D_w/D_pw = 0.1494, f_c between 81.1 (0.14) and
    82.7 (0.15); C_a = 1.3 f_c Z^{2/3} D_w^1.8 (1e-12); above 25.4 mm eq. (7), 3.647 … D_w^1.4."""
    fc = 81.1 + (82.7 - 81.1) * (12.7 / 85.0 - 0.14) / 0.01
    expected = 1.3 * fc * 15 ** (2 / 3) * 12.7**1.8
    np.testing.assert_allclose(thrust.thrust_ball_dynamic_load_rating(15, 12.7e-3, 85e-3, np.pi / 2), expected,
                               rtol=1e-12)
    fc = 88.8 + (90.2 - 88.8) * (30.0 / 155.0 - 0.19) / 0.01
    np.testing.assert_allclose(thrust.thrust_ball_dynamic_load_rating(16, 30e-3, 155e-3, np.pi / 2),
                               3.647 * 1.3 * fc * 16 ** (2 / 3) * 30.0**1.4, rtol=1e-12)


def test_an_angular_thrust_bearings_rating_interpolates_between_table_4s_columns():
    """At 60° (a column) eq. (6) with its f_c; at 52.5° (half way between 45° and 60°) the mean of
    the two columns at D_w cos α/D_pw; beyond 75° or past a column's last ratio, NaN."""
    angle = np.radians(60.0)
    ratio = 12.7e-3 * np.cos(angle) / 85e-3
    fc = 68.4 + (70.7 - 68.4) * (ratio - 0.07) / 0.01  # ratio 0.0747
    expected = 1.3 * fc * np.cos(angle) ** 0.7 * np.tan(angle) * 15 ** (2 / 3) * 12.7**1.8
    np.testing.assert_allclose(thrust.thrust_ball_dynamic_load_rating(15, 12.7e-3, 85e-3, angle), expected, rtol=1e-12)
    angle = np.radians(52.5)
    ratio = 12.7e-3 * np.cos(angle) / 85e-3  # 0.0910
    at_45 = 78.0 + (79.7 - 78.0) * (ratio - 0.09) / 0.01
    at_60 = 72.6 + (74.2 - 72.6) * (ratio - 0.09) / 0.01
    np.testing.assert_allclose(thrust.thrust_ball_factor(12.7e-3, 85e-3, angle), 0.5 * (at_45 + at_60), rtol=1e-12)
    assert np.isnan(float(thrust.thrust_ball_factor(12.7e-3, 85e-3, np.radians(80.0))))
    assert np.isnan(float(thrust.thrust_ball_factor(25e-3, 60e-3, np.radians(75.0))))  # 0.108 past 0.10


@pytest.mark.parametrize("degrees", sorted(TABLE_5))
def test_table_5s_closed_forms_give_its_printed_rows(degrees):
    """X = 1.25 tan α (1 − ⅔ sin α), X₁ = (20/13) tan α (1 − ⅓ sin α), Y₁ = (10/13) (1 − ⅓ sin α),
    e = 1.25 tan α against Table 5 as printed, each to its rounding (half a unit of its second
    decimal)."""
    e, x, y, x1, y1 = thrust.thrust_ball_load_factors(np.radians(degrees), double_direction=True)
    printed_x, printed_x1, printed_y1, printed_e = TABLE_5[degrees]
    np.testing.assert_allclose([x, x1, y1, e], [printed_x, printed_x1, printed_y1, printed_e], rtol=0, atol=0.005)
    assert y == 1.0


def test_equivalent_loads():
    """P_a = F_a and P₀a = F_a at 90°; at 60°, single direction P_a = X F_r + F_a, double direction
    below e X₁ F_r + Y₁ F_a; P₀a = 2.3 F_r tan α + F_a (1e-12)."""
    force = jnp.array([300.0, 400.0, 5000.0])
    assert float(thrust.thrust_ball_equivalent_dynamic_load(force, np.pi / 2)) == 5000.0
    assert float(thrust.thrust_ball_equivalent_static_load(force, np.pi / 2)) == 5000.0
    angle = np.radians(60.0)
    e, x, _, x1, y1 = thrust.thrust_ball_load_factors(angle, double_direction=True)
    np.testing.assert_allclose(thrust.thrust_ball_equivalent_dynamic_load(force, angle), x * 500.0 + 5000.0, rtol=1e-12)
    light = jnp.array([3000.0, 0.0, 2000.0])  # F_a/F_r = 0.67 < e = 2.17
    np.testing.assert_allclose(thrust.thrust_ball_equivalent_dynamic_load(light, angle, double_direction=True),
                               x1 * 3000.0 + y1 * 2000.0, rtol=1e-12)
    np.testing.assert_allclose(thrust.thrust_ball_equivalent_static_load(force, angle),
                               2.3 * 500.0 * np.tan(angle) + 5000.0, rtol=1e-12)


def test_static_rating_is_iso_76_eq_4():
    """C₀a = f₀ Z D_w² sin α: f₀ = 61.6 at α = 90° (D_w cos α = 0); at 60° with D_w cos α/D_pw =
    0.0747, between 55.9 (0.07) and 55.1 (0.08) (1e-12); C_a's derivative in α between Table 4's
    columns (at 52.5°, off the tables' kinks) against central differences."""
    np.testing.assert_allclose(thrust.thrust_ball_static_load_rating(15, 12.7e-3, 85e-3, np.pi / 2),
                               61.6 * 15 * 12.7**2, rtol=1e-12)
    angle = np.radians(60.0)
    ratio = 12.7 * np.cos(angle) / 85.0
    f0 = 55.9 + (55.1 - 55.9) * (ratio - 0.07) / 0.01
    np.testing.assert_allclose(thrust.thrust_ball_static_load_rating(15, 12.7e-3, 85e-3, angle),
                               f0 * 15 * 12.7**2 * np.sin(angle), rtol=1e-12)
    assert_jvp_matches_central_difference(
        jax.jit(lambda a: thrust.thrust_ball_dynamic_load_rating(15, 12.7e-3, 85e-3, a)), jnp.asarray(np.radians(52.5)),
        jnp.asarray(1.0), 1e-6, rtol=1e-6)
