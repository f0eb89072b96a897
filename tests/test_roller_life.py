"""Roller-bearing life: ISO 281 C_r from geometry, the ISO/TS 16281 lamina law and ratings, L10r and its derivative."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from scipy.optimize import brentq

from diffbearing.ratings import roller_life

from .helpers import assert_jvp_matches_central_difference

# Test geometry (chosen, not a catalogue bearing): a single-row cylindrical roller bearing with straight
# rollers, Z = 14, D_we = 10 mm, L_we = 9.6 mm, D_pw = 65 mm, α = 0 (about 209 size).
Z, DIAMETER, LENGTH, PITCH = 14, 10e-3, 9.6e-3, 65e-3


def iso_tr_1281_fc(gamma, coefficient):
    """f_c of radial roller bearings in closed form (ISO/TR 1281-1), λν = 0.83."""
    shape = gamma ** (2 / 9) * (1 - gamma) ** (29 / 27) / (1 + gamma) ** 0.25
    ratio = 1.04 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)
    return coefficient * 0.83 * shape * (1 + ratio**4.5) ** (-2 / 9)


def test_table7_is_the_closed_form_it_tabulates():
    """ISO 281 Table 7 against ISO/TR 1281-1's closed form, as restated with 551.13373 N × 0.377 in AxisForge's
    core/machine_elements/bearings/capacity.py: all 30 entries within 0.13 % (measured 0.122 %, at γ = 0.03).
    With the coefficient 207.9 the closed form rounded to 0.1 is every entry exactly."""
    np.testing.assert_allclose(roller_life.FC_VALUE, iso_tr_1281_fc(roller_life.FC_RATIO, 551.13373 * 0.377), rtol=1.3e-3)
    np.testing.assert_array_equal(np.round(iso_tr_1281_fc(roller_life.FC_RATIO, 207.9), 1), roller_life.FC_VALUE)


def test_rating_from_geometry():
    """ISO 281's C_r in mm at a tabulated γ = 0.10 (f_c = 84.2, no interpolation), the row exponent 7/9 and cos α.
    No public source giving Z, D_we, L_we, D_pw and the catalogue C_r of one bearing was found, so this checks
    the formula, not a catalogue value."""
    pitch = 100e-3
    expected = 1.1 * 84.2 * 9.6 ** (7 / 9) * 14**0.75 * 10 ** (29 / 27)  # 46.17 kN
    np.testing.assert_allclose(roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, pitch), expected, rtol=1e-12)
    two_rows = roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, pitch, rows=2)
    np.testing.assert_allclose(two_rows / expected, 2 ** (7 / 9), rtol=1e-12)
    angle = np.radians(12.0)  # tapered: γ = D cos α / D_pw interpolated, (L cos α)^{7/9}
    fc = np.interp(DIAMETER * np.cos(angle) / PITCH, roller_life.FC_RATIO, roller_life.FC_VALUE)
    tapered = 1.1 * fc * (9.6 * np.cos(angle)) ** (7 / 9) * 14**0.75 * 10 ** (29 / 27)
    np.testing.assert_allclose(roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, angle, PITCH), tapered, rtol=1e-12)


def test_lamina_ratings_are_lundberg_palmgren_line_contact_ratings():
    """With C_r from ISO 281, eqs. (47)–(57) are 552 b_m (1∓γ)^{29/27}(1±γ)^{−1/4} γ^{2/9} D^{29/27} (L/n_s)^{7/9}
    Z^{−1/4} [N, mm]: λν cancels; 0.378·552 vs 207.9 and 1.038 vs 1.04 leave 0.43 % (inner), 0.39 % (outer)."""
    laminae = 30
    rating = roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, PITCH)
    inner, outer = roller_life.lamina_ratings(rating, Z, DIAMETER, 0.0, PITCH, laminae)
    gamma = DIAMETER / PITCH
    common = 1.1 * 552 * gamma ** (2 / 9) * 10 ** (29 / 27) * (9.6 / laminae) ** (7 / 9) * Z**-0.25
    np.testing.assert_allclose(inner, common * (1 - gamma) ** (29 / 27) * (1 + gamma) ** -0.25, rtol=5e-3)
    np.testing.assert_allclose(outer, common * (1 + gamma) ** (29 / 27) * (1 - gamma) ** -0.25, rtol=5e-3)


@pytest.mark.parametrize("laminae", [1, 7, 30])
def test_lamina_law_sums_to_the_roller_law(laminae):
    """n_s laminae at one contact approach a carry 35948 L_we^{8/9} (2a)^{10/9} [N, mm] together (eqs. (34)–(37))."""
    approach = 3e-6
    total = laminae * roller_life.lamina_load(approach, LENGTH / laminae, LENGTH)
    np.testing.assert_allclose(total, 35948 * 9.6 ** (8 / 9) * (2 * 3e-3) ** (10 / 9), rtol=1e-12)


def test_lamina_law_opens_with_finite_gradient():
    load, slope = jax.value_and_grad(roller_life.lamina_load)(-1e-6, LENGTH / 30, LENGTH)
    assert float(load) == 0.0 and float(slope) == 0.0


def radial_lamina_loads(force, laminae=30):
    """(Z, n_s) lamina forces of straight rollers between rigid rings, zero clearance, pure radial force [N].

    Roller j at ψ_j = 2πj/Z has approach δ_r cos ψ_j, half at each contact; each lamina carries
    `lamina_load` of that approach; δ_r solves Σ_j cos ψ_j Σ_k q_jk = F_r (brentq)."""
    psi = 2 * np.pi * np.arange(Z) / Z

    def loads(shift):
        per_lamina = np.asarray(roller_life.lamina_load(jnp.asarray(shift * np.cos(psi) / 2), LENGTH / laminae, LENGTH))
        return np.repeat(per_lamina[:, None], laminae, axis=1)

    shift = brentq(lambda s: np.sum(np.cos(psi) * loads(s).sum(axis=1)) - force, 1e-9, 1e-3, xtol=1e-18, rtol=1e-14)
    return jnp.asarray(loads(shift))


def reference_life(rating, inner, outer=None):
    outer = inner if outer is None else outer
    return roller_life.roller_reference_rating_life(rating, Z, DIAMETER, 0.0, PITCH, inner, outer)


@pytest.mark.parametrize("load_ratio", [0.05, 0.3])
def test_reference_life_for_the_iso281_reference_case(load_ratio):
    """Pure radial load, zero clearance, rigid rings, straight rollers, no edge-stress factors (eq. (60)).

    L10r does NOT come out as ISO 281's (C_r/F_r)^{10/3}: eqs. (47)–(48) divide λν = 0.83 out of C_r
    (the lamina model is to carry the edge stresses itself) and the lamina sums give line contact's life
    exponent 4. Measured L10r / (C_r/F_r)^{10/3} = 15.26 at F_r = 0.05 C_r, 9.61 at 0.1 C_r, 4.62 at
    0.3 C_r, 2.07 at C_r. What the calibration does make true (0.378, 0.364 are the load-zone integrals at
    ε = 0.5): L10r = K (C_r / (λν F_r))⁴, measured K = 0.9828 at every load (bound 3 %), and the same for
    any number of laminae (uniform laminae: exact)."""
    rating = roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, PITCH)
    force = load_ratio * float(rating)
    life = reference_life(rating, radial_lamina_loads(force))
    np.testing.assert_allclose(life, (rating / (roller_life.LAMBDA_NU * force)) ** 4, rtol=0.03)
    np.testing.assert_allclose(life / (rating / force) ** (10 / 3),
                               0.9828 * roller_life.LAMBDA_NU**-4 * load_ratio ** (-2 / 3), rtol=1e-3)
    np.testing.assert_allclose(reference_life(rating, radial_lamina_loads(force, laminae=7)), life, rtol=1e-9)


def test_reference_life_derivative():
    """d L10r along a uniform scale and along a random direction of the loaded laminae, inner and outer loads apart."""
    rating = roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, PITCH)
    loads = radial_lamina_loads(0.1 * float(rating))
    loaded = (loads > 0).astype(float)
    direction = jnp.asarray(np.random.default_rng(0).uniform(-1, 1, (2, *loads.shape))) * loaded

    def relative_life(t):  # t[0] scales the inner, t[1] the outer lamina loads (relative)
        return reference_life(rating, loads * (1 + t[0]), loads * (1 + t[1])) / 1e4

    assert_jvp_matches_central_difference(relative_life, jnp.zeros((2, *loads.shape)), direction, step=1e-6, rtol=1e-6)
    for scale in (jnp.ones((2, *loads.shape)), jnp.zeros((2, *loads.shape)).at[1].set(1.0)):
        assert_jvp_matches_central_difference(relative_life, jnp.zeros((2, *loads.shape)), scale, step=1e-6, rtol=1e-6)


def test_zero_loads_have_finite_gradients():
    """No load: L10r = +inf, gradients zero (not NaN); a half-unloaded set: finite gradient, zero on the unloaded laminae."""
    rating = roller_life.roller_dynamic_load_rating(Z, DIAMETER, LENGTH, 0.0, PITCH)
    zeros = jnp.zeros((Z, 30))
    life, (d_rating, d_loads) = jax.value_and_grad(lambda c, q: reference_life(c, q), argnums=(0, 1))(rating, zeros)
    assert np.isposinf(life) and float(d_rating) == 0.0 and np.all(np.asarray(d_loads) == 0.0)
    loads = radial_lamina_loads(0.1 * float(rating))
    gradient = jax.grad(lambda q: reference_life(rating, q))(loads)
    assert np.all(np.isfinite(gradient)) and np.all(np.asarray(gradient)[np.asarray(loads) == 0] == 0.0)
    assert np.all(np.asarray(gradient)[np.asarray(loads) > 0] < 0.0)


def test_equivalent_load_of_roller_bearings():
    """ISO 281 Table 8: a cylindrical bearing (α = 0) takes P = F_r; a tapered one P = F_r while
    F_a/F_r ≤ e = 1.5 tan α, else P = 0.4 F_r + 0.4 cot α F_a; L10 = (C/P)^{10/3}."""
    alpha = np.radians(15.0)
    np.testing.assert_allclose(roller_life.roller_equivalent_dynamic_load(jnp.array([3e3, 4e3, 0.0]), 0.0), 5e3, rtol=1e-15)
    light = jnp.array([4e3, 0.0, 1.5 * np.tan(alpha) * 4e3 * 0.99])
    np.testing.assert_allclose(roller_life.roller_equivalent_dynamic_load(light, alpha), 4e3, rtol=1e-15)
    heavy = jnp.array([4e3, 0.0, 2e3])
    np.testing.assert_allclose(roller_life.roller_equivalent_dynamic_load(heavy, alpha), 0.4 * 4e3 + 0.4 / np.tan(alpha) * 2e3,
                               rtol=1e-14)
    np.testing.assert_allclose(roller_life.roller_basic_rating_life(50e3, 5e3), 10.0 ** (10.0 / 3.0), rtol=1e-14)
