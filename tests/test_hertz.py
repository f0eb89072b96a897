"""Hertz contact: published numbers, closed forms, approximation errors, derivatives."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from scipy.special import ellipe, ellipk

from diffbearing.bearings.ball.raceway_contact import ball_raceway_modulus, inner_curvature
from diffbearing.contact import hertz
from diffbearing.contact.elliptic import complete_elliptic_integrals, elliptic_integrals_and_difference
from diffbearing.params import BEARING_STEEL, ball_bearing

from .helpers import assert_jvp_matches_central_difference

STEEL_MODULUS = float(hertz.effective_modulus(208e9, 0.3, 208e9, 0.3))
FIELDS = ("semi_major_axis", "semi_minor_axis", "approach", "max_pressure", "ellipticity", "load_deflection_constant")


def test_elliptic_integrals_match_scipy():
    m = np.concatenate([[-0.5, 0.0, 1e-12, 1e-6], np.linspace(0.01, 0.99, 99), [1 - 1e-6, 1 - 1e-10]])
    elliptic_k, elliptic_e = complete_elliptic_integrals(jnp.asarray(m))
    np.testing.assert_allclose(elliptic_k, ellipk(m), rtol=1e-14)
    np.testing.assert_allclose(elliptic_e, ellipe(m), rtol=1e-14)


def test_elliptic_difference_is_stable_at_circle():
    # (K − E)/m → π/4 as m → 0 (series K − E = (π/4) m (1 + 3m/8 + …)); no 0/0 at m = 0.
    m = jnp.array([0.0, 1e-300, 1e-12, 1e-6])
    _, _, difference_over_m = elliptic_integrals_and_difference(m)
    np.testing.assert_allclose(difference_over_m, np.pi / 4 * (1 + 3 * np.asarray(m) / 8), rtol=1e-12)


def test_elliptic_derivative_matches_closed_form():
    # dK/dm = (E − (1−m) K) / (2 m (1−m)) (DLMF 19.4.1 in the parameter m), → π/8 at m = 0.
    m = jnp.array([1e-3, 0.3, 0.9, 0.999])
    derivative = jax.vmap(jax.grad(lambda x: complete_elliptic_integrals(x)[0]))(m)
    mm = np.asarray(m)
    np.testing.assert_allclose(derivative, (ellipe(mm) - (1 - mm) * ellipk(mm)) / (2 * mm * (1 - mm)), rtol=1e-9)
    np.testing.assert_allclose(jax.grad(lambda x: complete_elliptic_integrals(x)[0])(0.0), np.pi / 8, rtol=1e-14)


def test_ellipticity_solves_its_equation_over_the_range():
    # Stated range of the Newton solve: 0 ≤ F ≤ 0.9999 (κ up to about 350).
    difference = jnp.concatenate([jnp.array([0.0, 1e-12, 1e-6]), jnp.linspace(1e-3, 0.9999, 500)])
    kappa = hertz.ellipticity(difference)
    np.testing.assert_allclose(hertz.curvature_difference_of_ellipticity(kappa), difference, rtol=0, atol=2e-15)
    assert float(kappa[0]) == 1.0


def test_ellipticity_against_scipy_reference():
    # Independent check: F(κ) from scipy's K, E in Johnson's form (eq. 4.39), at κ = 1.5, 8, 20.
    for kappa in (1.5, 8.0, 20.0):
        m = 1 - 1 / kappa**2
        difference = ((kappa**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((kappa**2 - 1) * ellipe(m))
        np.testing.assert_allclose(hertz.ellipticity(difference), kappa, rtol=1e-12)


def test_chamfer_paper_inner_contact():
    """The 6411E chamfer paper: Σρ_i = 0.1040 1/mm, F(ρ_i) = 0.9583, a = 9.234 mm at Q = 72.14 kN.

    The paper read its Hertz coefficients off tables (docs/papers.md, §The 6411E chamfer paper):
    exact Hertz must land within 1 % of a. The paper's γ_i = 0.2726 is used as printed (α0 = 9.23° would give 0.2732).
    """
    ball_diameter, fi = 26.9875e-3, 13.9 / 26.9875
    gamma = 0.2726
    curvature_sum = (4 - 1 / fi + 2 * gamma / (1 - gamma)) / ball_diameter
    difference = (1 / fi + 2 * gamma / (1 - gamma)) / (4 - 1 / fi + 2 * gamma / (1 - gamma))
    np.testing.assert_allclose(curvature_sum * 1e-3, 0.1040, rtol=1e-3)  # printed to 4 digits
    np.testing.assert_allclose(difference, 0.9583, rtol=1e-4)
    contact = hertz.point_contact(72.14e3, curvature_sum, difference, STEEL_MODULUS)
    np.testing.assert_allclose(contact.semi_major_axis, 9.234e-3, rtol=0.01)


def test_chamfer_paper_geometry_through_the_bearing_model():
    # The same contact built from the bearing: α0 from the 28 µm clearance (paper: 9.23°).
    bearing = ball_bearing(ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7, kind="deep_groove_ball",
                           inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=0.028e-3)
    np.testing.assert_allclose(np.degrees(bearing.free_contact_angle), 9.23, atol=0.01)
    curvature_sum, difference = inner_curvature(bearing, bearing.free_contact_angle)
    np.testing.assert_allclose(curvature_sum * 1e-3, 0.1040, rtol=2e-3)
    np.testing.assert_allclose(difference, 0.9583, rtol=2e-4)
    contact = hertz.point_contact(72.14e3, curvature_sum, difference, ball_raceway_modulus(bearing))
    np.testing.assert_allclose(contact.semi_major_axis, 9.234e-3, rtol=0.01)


def test_sphere_on_flat_closed_form():
    # Johnson eqs. 4.22–4.23: a = (3QR/(4E*))^(1/3), p0 = 3Q/(2πa²), δ = a²/R, E* = E'/2.
    radius, load = 0.01, 500.0
    contact = hertz.point_contact(load, 2.0 / radius, 0.0, STEEL_MODULUS)
    reduced = STEEL_MODULUS / 2
    a = (3 * load * radius / (4 * reduced)) ** (1 / 3)
    np.testing.assert_allclose(contact.semi_major_axis, a, rtol=1e-13)
    np.testing.assert_allclose(contact.semi_minor_axis, a, rtol=1e-13)
    np.testing.assert_allclose(contact.max_pressure, 3 * load / (2 * np.pi * a**2), rtol=1e-13)
    np.testing.assert_allclose(contact.approach, a**2 / radius, rtol=1e-13)
    np.testing.assert_allclose(hertz.hertz_load(contact.approach, contact.load_deflection_constant), load, rtol=1e-13)


def test_line_contact_closed_form():
    # Johnson eq. 4.43 with E* = E'/2: b = √(4wR/(πE*)), p0 = 2w/(πb).
    load_per_length, radius = 1e5, 0.02
    contact = hertz.line_contact(load_per_length, radius, STEEL_MODULUS)
    b = np.sqrt(4 * load_per_length * radius / (np.pi * STEEL_MODULUS / 2))
    np.testing.assert_allclose(contact.half_width, b, rtol=1e-14)
    np.testing.assert_allclose(contact.max_pressure, 2 * load_per_length / (np.pi * b), rtol=1e-14)


# Measured maximum relative errors of the approximate levels over 1 ≤ κ ≤ 20
# (benchmarks/hertz_fidelity.py prints them); bounds are those values rounded up.
APPROXIMATION_BOUNDS = {
    "brewe_hamrock": {"ellipticity": 0.075, "semi_major_axis": 0.05, "semi_minor_axis": 0.025,
                      "approach": 0.056, "max_pressure": 0.025, "load_deflection_constant": 0.09},
    "hamrock_brewe": {"ellipticity": 0.042, "semi_major_axis": 0.028, "semi_minor_axis": 0.014,
                      "approach": 0.048, "max_pressure": 0.017, "load_deflection_constant": 0.075},
}


@pytest.mark.parametrize("method", list(APPROXIMATION_BOUNDS))
def test_approximation_error_bounds(method):
    kappa = jnp.linspace(1.0, 20.0, 400)
    difference = hertz.curvature_difference_of_ellipticity(kappa)
    exact = hertz.point_contact(1e3, 200.0, difference, STEEL_MODULUS)
    approximate = hertz.point_contact(1e3, 200.0, difference, STEEL_MODULUS, method=method)
    for field, bound in APPROXIMATION_BOUNDS[method].items():
        error = float(jnp.max(jnp.abs(getattr(approximate, field) / getattr(exact, field) - 1)))
        assert error < bound, (field, error)
        assert error > 0.3 * bound, (field, error)  # the bound is tight: a changed formula shows up


def _fields(contact):
    return jnp.stack([getattr(contact, name) for name in FIELDS])


@pytest.mark.parametrize("kappa", [1.0, 1.001, 8.0, 20.0])
@pytest.mark.parametrize("method", ["exact", "hamrock_brewe"])
def test_point_contact_derivatives(kappa, method):
    """d(outputs)/d(load, Σρ, F, E') against central differences at κ = 1, 1.001, 8, 20.

    Outputs are normalized by their value, inputs perturbed relatively (F absolutely, as F = 0 at
    κ = 1), so one tolerance fits all; step 1e-6 ≈ ε^(1/3)/6.
    """
    difference = float(hertz.curvature_difference_of_ellipticity(kappa))
    point = jnp.array([2e3, 150.0, difference, STEEL_MODULUS])
    reference = _fields(hertz.point_contact(*point, method=method))

    def normalized(t):
        x = point * (1 + t.at[2].set(0.0)) + jnp.zeros(4).at[2].set(t[2])
        return _fields(hertz.point_contact(*x, method=method)) / reference

    for index in range(4):
        direction = jnp.zeros(4).at[index].set(1.0)
        assert_jvp_matches_central_difference(normalized, jnp.zeros(4), direction, step=1e-6, rtol=2e-6, atol=2e-9)


def test_ellipticity_derivative_at_circle_is_four_thirds():
    # Near κ = 1: F ≈ 3(κ − 1)/4 (expansion of Johnson eq. 4.39), so dκ/dF = 4/3 exactly at F = 0.
    np.testing.assert_allclose(jax.grad(hertz.ellipticity)(0.0), 4 / 3, rtol=1e-14)
    np.testing.assert_allclose(jax.jacrev(hertz.ellipticity)(0.0), 4 / 3, rtol=1e-14)


def test_zero_load_gives_zeros_and_finite_gradients():
    contact = hertz.point_contact(0.0, 150.0, 0.9, STEEL_MODULUS)
    for name in ("semi_major_axis", "semi_minor_axis", "approach", "max_pressure"):
        assert float(getattr(contact, name)) == 0.0
    gradient = jax.grad(lambda q: hertz.point_contact(q, 150.0, 0.9, STEEL_MODULUS).max_pressure)(0.0)
    assert np.isfinite(gradient)
    # open contact: exact zero load, zero gradient
    assert float(hertz.hertz_load(-1e-6, 1e10)) == 0.0
    assert float(jax.grad(hertz.hertz_load)(-1e-6, 1e10)) == 0.0
    assert float(jax.grad(hertz.hertz_load)(0.0, 1e10)) == 0.0


def test_line_contact_derivatives():
    point = jnp.array([1e5, 0.02, STEEL_MODULUS])
    reference = hertz.line_contact(*point)

    def normalized(t):
        contact = hertz.line_contact(*(point * (1 + t)))
        length = 0.01 * (1 + t[0])
        return jnp.stack([contact.half_width / reference.half_width, contact.max_pressure / reference.max_pressure,
                          hertz.line_contact_approach_palmgren(1e3 * (1 + t[1]), length) / 3.047e-6])

    for index in range(3):
        assert_jvp_matches_central_difference(normalized, jnp.zeros(3), jnp.zeros(3).at[index].set(1.0),
                                              step=1e-6, rtol=1e-6, atol=1e-9)


def test_vmap_and_jit_agree_with_loop():
    difference = jnp.array([0.0, 0.5, 0.95])
    batched = jax.jit(jax.vmap(lambda f: _fields(hertz.point_contact(1e3, 150.0, f, STEEL_MODULUS))))(difference)
    for i, f in enumerate(difference):
        np.testing.assert_allclose(batched[i], _fields(hertz.point_contact(1e3, 150.0, f, STEEL_MODULUS)), rtol=1e-14)


def test_bearing_steel_preset():
    assert float(BEARING_STEEL.elastic_modulus) == 208e9 and float(BEARING_STEEL.poisson_ratio) == 0.3
