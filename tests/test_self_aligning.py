"""The self-aligning ball bearing through the bearing interface: its rows' outer raceway one sphere
about the bearing's centre, its radial play, no moment and no tilt stiffness (a shaft on two of
them carries its load as a beam on two pivots), the rows' contact forces passing through the
sphere's centre, its ISO 281 and ISO 76 ratings written out, a derivative in the clearance."""

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import Shaft, ShaftLoads, solve_shaft
from diffbearing.bearings.ball.ball_equilibrium import BallModel, inner_groove_radius_of_centres
from diffbearing.bearings.ball.self_aligning import (
    SelfAligningSupport,
    axial_backoff,
    self_aligning_row,
    self_aligning_support,
)
from diffbearing.params import groove_curvature_centre_distance
from diffbearing.ratings import static_safety

from .helpers import assert_jvp_matches_central_difference

# a 1208-size bearing (illustrative internals): 2 × 15 balls of 9.525 mm on d_m = 60 mm, 12°, f_i = 0.53
ANGLE = np.radians(12.0)
GEOMETRY = dict(ball_diameter=9.525e-3, pitch_diameter=60e-3, balls=15, inner_groove_ratio=0.53, contact_angle=ANGLE)
CLEARANCE = 20e-6  # m, diametral


ROW = self_aligning_row(**GEOMETRY)


def _support(clearance=CLEARANCE, position=0.0, model=BallModel()) -> SelfAligningSupport:
    return self_aligning_support(ROW, clearance, position, model=model)


@jax.jit
def _ring_force(support, displacement):
    return support.ring_force(displacement, 0.0, support.constants())


@jax.jit
def _rows_force(support, displacement):
    return support.rows.ring_force(displacement, 0.0, support.constants())


def test_its_rows_share_one_sphere_about_the_centre():
    """f_o = d_m/(2 D_w cos α₀) + ½, and each row's outer "groove" centre — its inner groove centres'
    plane at z_r = ±B D_w sin α₀ less B D_w sin α₀ along its own axis, their radius R_i less
    B D_w cos α₀ — is the bearing's centre (1e-15 m)."""
    support = _support()
    row = support.rows.bearing
    np.testing.assert_allclose(row.outer_groove_ratio, 60.0 / (2 * 9.525 * np.cos(ANGLE)) + 0.5, rtol=1e-15)
    distance = float(groove_curvature_centre_distance(row))
    for single in support.rows.rows():
        axial = float(single.position) - single.orientation * distance * np.sin(ANGLE)
        assert abs(axial) < 1e-15
    assert abs(float(inner_groove_radius_of_centres(row)) - distance * np.cos(ANGLE)) < 1e-15


def test_its_radial_play_is_the_clearance():
    """No load while the inner ring moves radially less than G_r/2, a load beyond (the rows backed
    off by e = B D_w sin α₀ − √((B D_w)² − (B D_w cos α₀ + G_r/2)²))."""
    support = _support()
    below = _ring_force(support, jnp.array([0.5 * CLEARANCE - 0.05e-6, 0.0, 0.0, 0.0, 0.0]))
    above = _ring_force(support, jnp.array([0.5 * CLEARANCE + 0.05e-6, 0.0, 0.0, 0.0, 0.0]))
    assert np.all(np.asarray(below) == 0.0)
    assert float(above[0]) > 1e-3
    distance = float(groove_curvature_centre_distance(support.rows.bearing))
    np.testing.assert_allclose(float(axial_backoff(support.rows.bearing, CLEARANCE)),
                               distance * np.sin(ANGLE) - np.sqrt(distance**2 - (distance * np.cos(ANGLE)
                                                                                  + 0.5 * CLEARANCE) ** 2), rtol=1e-14)


@hypothesis.settings(max_examples=15, deadline=None)
@hypothesis.given(st.floats(-60e-6, 60e-6), st.floats(-60e-6, 60e-6), st.floats(-80e-6, 80e-6),
                  st.floats(-0.04, 0.04), st.floats(-0.04, 0.04), st.floats(-5e-6, 40e-6))
@hypothesis.example(0.0, 1.678e-5, 1.400e-5, 0.0, 0.0, 3.755e-5)  # light load, wide clearance: the back-off's share
def test_a_tilt_loads_nothing_and_carries_no_moment(dx, dy, dz, tx, ty, clearance):
    """Over random translations, tilts up to 0.04 rad (past the catalogues' 2.5°) and clearances
    (preloaded to 40 µm): F(δ, θ) = F(δ, 0) exactly, no moment, finite; and the rows' own moment
    about the sphere's centre at the translation is no larger than (|δ| + |e|) |F|, e the rows'
    back-off (each contact force passes through the centre: what is left is the small-displacement
    model's moment about the rows' moved rings, not about the centre), where B D_w |F| would be a
    force off the centre."""
    support = _support(clearance)
    translation = jnp.array([dx, dy, dz, 0.0, 0.0])
    force = _ring_force(support, jnp.array([dx, dy, dz, tx, ty]))
    assert np.all(np.isfinite(np.asarray(force)))
    np.testing.assert_array_equal(force, _ring_force(support, translation))
    assert np.all(np.asarray(force[3:]) == 0.0)
    rows = _rows_force(support, translation)
    np.testing.assert_allclose(rows[:3], force[:3], rtol=1e-14, atol=1e-12)
    moved = float(jnp.linalg.norm(translation[:3])) + abs(float(axial_backoff(ROW, clearance)))
    assert float(jnp.linalg.norm(rows[3:])) <= moved * float(jnp.linalg.norm(rows[:3])) + 1e-9


def test_its_stiffness_has_no_tilt_rows_and_is_the_force_derivative():
    """dF/dΔ: zero in the tilt rows and columns; its translation block the central difference of
    the force; the derivative in the clearance (a design parameter) against central differences."""
    support = _support()
    displacement = jnp.array([25e-6, -4e-6, 6e-6, 1e-3, 0.0])
    stiffness = jax.jit(lambda d: support.ring_stiffness(d, 0.0, support.constants()))(displacement)
    assert np.all(np.asarray(stiffness[3:, :]) == 0.0) and np.all(np.asarray(stiffness[:, 3:]) == 0.0)
    assert float(stiffness[0, 0]) > 1e7
    assert_jvp_matches_central_difference(lambda d: _ring_force(support, d), displacement,
                                          jnp.array([1.0, 0.5, -1.0, 0.0, 0.0]) * 1e-6, 1e-3, rtol=1e-6)
    assert_jvp_matches_central_difference(lambda c: _ring_force(_support(c), displacement), jnp.asarray(CLEARANCE),
                                          jnp.asarray(1e-6), 1e-3, rtol=1e-6)


def test_a_shaft_on_two_is_a_beam_on_two_pivots():
    """A rigid shaft on two self-aligning bearings 200 mm apart, a radial load 50 mm from the first:
    the reactions of statics, F (L − a)/L and F a/L (1e-9), the shaft tilting freely."""
    bearings = (_support(position=0.0), _support(position=0.2))
    load = ShaftLoads(np.array([0.05]), np.array([[4000.0, 0.0, 0.0]]), np.zeros((1, 2)))
    solution = solve_shaft(Shaft(bearings, load))
    assert bool(solution.converged)
    np.testing.assert_allclose([solution.bearing_forces[0][0], solution.bearing_forces[1][0]], [3000.0, 1000.0],
                               rtol=1e-9)
    assert abs(float(solution.displacement[4])) > 1e-5  # the shaft tilts: the bearings deflect unequally


def test_its_ratings_are_iso_281_and_iso_76s_for_self_aligning_bearings():
    """C_r = b_m f_c (2 cos α)^0.7 Z^{2/3} D_w^1.8 with f_c of ISO 281 Table 2's self-aligning column
    at γ = 9.525 cos 12° / 60 = 0.1553 (between 28.7 at 0.15 and 29.7 at 0.16); C₀r = f₀ · 2 Z D_w²
    cos α with f₀ of ISO 76 Table 1's (2.6 at 0.15 and 0.16); P₀r = F_r + 0.44 cot α F_a; pressure
    safety (4 600 MPa / p)³; ISO 281 P of Table 3's double-row self-aligning row (1e-12)."""
    support = _support()
    gamma = 9.525 * np.cos(ANGLE) / 60.0
    fc = 28.7 + (29.7 - 28.7) * (gamma - 0.15) / 0.01
    rating = 1.3 * fc * (2 * np.cos(ANGLE)) ** 0.7 * 15 ** (2 / 3) * 9.525**1.8
    np.testing.assert_allclose(support.dynamic_load_rating(), rating, rtol=1e-12)
    np.testing.assert_allclose(support.static_load_rating(), 2.6 * 2 * 15 * 9.525**2 * np.cos(ANGLE), rtol=1e-12)
    np.testing.assert_allclose(support.equivalent_static_load(jnp.array([600.0, 800.0, 300.0])),
                               1000.0 + 0.44 / np.tan(ANGLE) * 300.0, rtol=1e-12)
    np.testing.assert_allclose(support.pressure_safety(2.3e9), 8.0, rtol=1e-12)
    # ISO 281 Table 3, double row: X = 1, Y = 0.42 cot α to e = 1.5 tan α = 0.319, then 0.65, 0.65 cot α
    np.testing.assert_allclose(support.equivalent_dynamic_load(jnp.array([1000.0, 0.0, 300.0])),
                               1000.0 + 0.42 / np.tan(ANGLE) * 300.0, rtol=1e-12)
    np.testing.assert_allclose(support.equivalent_dynamic_load(jnp.array([1000.0, 0.0, 330.0])),
                               650.0 + 0.65 / np.tan(ANGLE) * 330.0, rtol=1e-12)
    assert static_safety.SELF_ALIGNING_PRESSURE_LIMIT == 4.6e9


def test_bad_geometry_names_its_key():
    with pytest.raises(ValueError, match="bearing.radial_clearance"):
        _support(2e-3)  # beyond 2 B D_w (1 − cos α₀) = 1.35 mm
    with pytest.raises(ValueError, match="static"):
        _support(model=BallModel(centrifugal=True))
