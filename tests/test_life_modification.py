"""Modified life a_ISO (ISO 281:2007 §9.3, effect `life` with lubricant.cleanliness): ν₁, e_C and
C_u against MASTA's values, the Walther viscosity against SKF's calculator, the a_ISO curves'
continuity and limits, the modified lives through scenes, and the errors a user meets."""

import jax
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.film.viscosity_temperature import walther_viscosity
from diffbearing.ratings import life_modification

from .helpers import BEARING_6411E, central_difference_jvp, example_scene

RPM = np.pi / 30.0


def test_reference_viscosity_and_contamination_against_masta():
    """NSK HR30306J, n = 1500 r/min, D_pw = 51.56 mm, oil bath at −/15/12 (the values MASTA gives, as
    published beside an open ISO 281 implementation, github Rust 'TRB solver' theory document §10.13):
    ν₁ = 16.18 mm²/s, e_C = 0.8174 at κ = 3.413, C_u = C₀/8.2 = 7.317 kN for C₀ = 60 kN."""
    assert float(life_modification.reference_viscosity(1500 * RPM, 51.56e-3)) * 1e6 == pytest.approx(16.18, abs=0.005)
    constants = life_modification.CONTAMINATION_CONSTANTS["oil_bath"]["-/15/12"]
    assert float(life_modification.contamination_factor(3.413, 51.56e-3, constants)) == pytest.approx(0.8174, abs=1e-4)
    assert float(life_modification.fatigue_load_limit(60e3, 51.56e-3, "roller")) == pytest.approx(7317.0, abs=1.0)


def test_reference_viscosity_branches():
    """Eq. (28) below 1000 r/min, eq. (29) from it: 45000 n^−0.83 and 4500 n^−0.5 at D_pw = 100 mm."""
    assert float(life_modification.reference_viscosity(500 * RPM, 0.1)) * 1e6 == pytest.approx(4500 * 500**-0.83, rel=1e-12)
    assert float(life_modification.reference_viscosity(4000 * RPM, 0.1)) * 1e6 == pytest.approx(450 / 4000**0.5, rel=1e-12)
    assert np.isinf(float(life_modification.reference_viscosity(0.0, 0.1)))


def test_walther_viscosity():
    """The Walther line passes through ν₄₀ and ν₁₀₀ (1e-12); an oil of 120 and 12 mm²/s at 80 °C has
    21.6 mm²/s in SKF's Bearing Calculator (κ = 2.08 with ν₁ = 10.4 mm²/s, both rounded): within 1 %."""
    for temperature, want in ((313.15, 120e-6), (373.15, 12e-6)):
        assert float(walther_viscosity(120e-6, 12e-6, temperature)) == pytest.approx(want, rel=1e-12)
    assert float(walther_viscosity(120e-6, 12e-6, 353.15)) * 1e6 == pytest.approx(2.08 * 10.4, rel=0.01)
    nu = lambda point: walther_viscosity(point[0], point[1], point[2])  # noqa: E731
    point, direction = jax.numpy.array([120e-6, 12e-6, 353.15]), jax.numpy.array([5e-6, -1e-6, 10.0])
    _, tangent = jax.jvp(nu, (point,), (direction,))
    assert float(tangent) == pytest.approx(float(central_difference_jvp(nu, point, direction, 1e-4)), rel=1e-7)


def test_a_iso_of_the_krw_worked_example():
    """KRW catalogue's worked example (spherical roller bearing 23220EAS, D_pw = 140 mm, n = 500 r/min,
    ISO VG 100 at 70 °C read as ν = 27 mm²/s, e_C = 0.7, C_u = 57.1 kN, P = 90.2 kN, C = 466 kN):
    a_ISO = 1.7 and L_nm = 405·10⁶ rev, read by the catalogue from ISO 281's diagram, hence 3 %; ν₁ by
    eq. (28) (the catalogue reads 22 mm²/s off the diagram)."""
    nu1 = float(life_modification.reference_viscosity(500 * RPM, 140e-3))
    assert nu1 * 1e6 == pytest.approx(22.0, rel=0.01)
    a_iso = float(life_modification.life_modification_factor(27e-6 / nu1, 0.7 * 57.1 / 90.2, "roller"))
    assert a_iso == pytest.approx(1.7, rel=0.03)
    assert a_iso * (466 / 90.2) ** (10 / 3) == pytest.approx(405.0, rel=0.03)


@pytest.mark.parametrize("element", ["ball", "roller"])
def test_a_iso_curves_are_continuous_and_limited(element):
    """a_ISO is continuous at κ = 1 (the same c on both sides, 1e-12) and at κ = 0.4 within the
    rounding of ISO 281's constants (0.1 %); it tends to 0.1 as e_C C_u/P → 0; κ above 4 counts as 4;
    it stops at 50."""
    a = life_modification.life_modification_factor
    below, above = (float(a(k, 0.5, element)) for k in (1.0 - 1e-13, 1.0))
    assert below == pytest.approx(above, rel=1e-10)
    below, above = (float(a(k, 0.2, element)) for k in (0.4 - 1e-13, 0.4))
    assert below == pytest.approx(above, rel=1e-3)
    assert float(a(2.0, 1e-12, element)) == pytest.approx(0.1, rel=1e-3)
    assert float(a(7.0, 0.3, element)) == float(a(4.0, 0.3, element))
    assert float(a(4.0, 5.0, element)) == 50.0


def test_a_iso_derivative():
    """d a_ISO / d(κ, e_C C_u/P) within a band against a central difference."""
    def factor(point):
        return life_modification.life_modification_factor(point[0], point[1], "ball")

    point, direction = jax.numpy.array([2.0, 0.1]), jax.numpy.array([1.0, 0.5])
    _, tangent = jax.jvp(factor, (point,), (direction,))
    assert float(tangent) == pytest.approx(float(central_difference_jvp(factor, point, direction, 1e-6)), rel=1e-7)


MODIFIED = BEARING_6411E + """bore = "55 mm"
outer_diameter = "140 mm"

[operating]
inner_speed = "3000 rpm"
force = ["10 kN", "0 N", "2 kN"]

[lubricant]
preset = "iso_vg_68"
temperature = "70 degC"
{cleanliness}

[effects]
life = true
"""


def _values(tmp_path, text):
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return run_model(build_model(load_scene(str(path))), progress=False).values


def test_modified_lives_through_a_scene(tmp_path):
    """κ = ν/ν₁ with ν on the VG 68 Walther line at 70 °C, e_C of circulating oil at −/17/14,
    C_u = C₀/22, L10m = a_ISO L10 and L10rm = a_ISO(P_ref) L10r with P_ref = C_r L10r^(−1/3)."""
    values = _values(tmp_path, MODIFIED.replace("{cleanliness}", 'cleanliness = "-/17/14"\nsupply = "circulating"'))
    nu = float(walther_viscosity(68e-6, 8.6e-6, 343.15))
    assert float(values["life.kinematic_viscosity"]) == pytest.approx(nu, rel=1e-12)
    nu1 = 4500 * 3000**-0.5 * 97.5**-0.5 * 1e-6
    kappa = nu / nu1
    assert float(values["life.viscosity_ratio"]) == pytest.approx(kappa, rel=1e-12)
    e_c = float(life_modification.contamination_factor(kappa, 97.5e-3, (0.0288, 1.6329)))
    assert float(values["life.contamination_factor"]) == pytest.approx(e_c, rel=1e-12)
    a_iso = float(values["life.a_iso"])
    want = float(life_modification.life_modification_factor(
        kappa, e_c * float(values["life.fatigue_load_limit"]) / float(values["life.equivalent_load"]), "ball"))
    assert a_iso == pytest.approx(want, rel=1e-12)
    assert float(values["life.L10m"]) == pytest.approx(a_iso * float(values["life.L10"]), rel=1e-12)
    reference = float(values["life.basic_dynamic_load_rating"]) * float(values["life.L10r"]) ** (-1 / 3)
    assert float(values["life.reference_equivalent_load"]) == pytest.approx(reference, rel=1e-12)
    assert float(values["life.L10rm"]) == pytest.approx(float(values["life.a_iso_reference"]) * float(values["life.L10r"]),
                                                        rel=1e-12)
    assert 0.1 < a_iso < 50


def test_without_cleanliness_no_a_iso_is_computed(tmp_path):
    """The same scene without lubricant.cleanliness runs no a_ISO (and its [lubricant] table, which
    nothing else reads, is refused)."""
    text = MODIFIED.replace("{cleanliness}", "")
    with pytest.raises(ValueError, match="'lubricant.preset', 'lubricant.temperature' not read"):
        _values(tmp_path, text)
    values = _values(tmp_path, text.split("[lubricant]")[0] + "[effects]\nlife = true\n")
    assert "life.L10r" in values and not any(key.startswith(("life.a_iso", "life.L10m", "life.L10rm")) for key in values)


def test_roller_bearing_a_iso_with_a_given_contamination_factor():
    """A cylindrical roller bearing, e_C given: C_u = C₀/8.2 and the roller's a_ISO."""
    values = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"), overrides=[
        "effects.stiffness=false", "operating.inner_speed=1500 rpm", "lubricant.preset=iso_vg_46",
        "lubricant.temperature=60 degC", "lubricant.cleanliness=custom", "lubricant.contamination_factor=0.5"])),
        progress=False).values
    assert float(values["life.contamination_factor"]) == 0.5
    kappa = float(values["life.viscosity_ratio"])
    x = 0.5 * float(values["life.fatigue_load_limit"]) / float(values["life.equivalent_load"])
    assert float(values["life.a_iso"]) == pytest.approx(float(life_modification.life_modification_factor(kappa, x, "roller")),
                                                        rel=1e-12)
    assert float(values["life.L10m"]) == pytest.approx(float(values["life.a_iso"]) * float(values["life.L10"]), rel=1e-12)


@pytest.mark.parametrize("cleanliness, message", [
    ('cleanliness = "-/17/14"', "lubricant.supply"),
    ('cleanliness = "custom"', "lubricant.contamination_factor"),
    ('cleanliness = "-/13/10"\nsupply = "oil_bath"', "lubricant.cleanliness"),
    ('cleanliness = "high"\ncontamination_factor = 0.5', "lubricant.contamination_factor"),
])
def test_bad_cleanliness_names_its_key(tmp_path, cleanliness, message):
    with pytest.raises(ValueError, match=message):
        _values(tmp_path, MODIFIED.replace("{cleanliness}", cleanliness))


def test_ep_additives_take_unit_kappa_below_one_capped_at_three():
    """ISO 281's rule for effective EP additives (DIN ISO 281 Bbl. 1; SKF, "Consideration of EP additives"):
    where κ < 1 and e_C ≥ 0.2, a_ISO at κ = 1, at most 3 and not below a_ISO at κ; elsewhere a_ISO."""
    x = np.array([0.05, 0.3, 1.0])
    # (κ = 1 raises a_ISO; the cap of 3 bites; a_ISO at κ already above 3 is kept): ball at x = 0.05,
    # 0.3, 1.0 (a_ISO 0.37, 1.23, 5.78 at κ = 0.5; 1.14, 15.6, 50 at κ = 1), roller at 0.05, 1.0, –
    for element, raised, capped, kept in (("ball", 0, 1, 2), ("roller", 0, 2, None)):
        plain = np.asarray(life_modification.life_modification_factor(0.5, x, element))
        unit = np.asarray(life_modification.life_modification_factor(1.0, x, element))
        with_ep = np.asarray(life_modification.life_modification_factor_ep(np.full(3, 0.5), x, 0.5, element))
        np.testing.assert_array_equal(with_ep, np.maximum(plain, np.minimum(unit, 3.0)))
        assert plain[raised] < with_ep[raised] == unit[raised] < 3.0
        assert plain[capped] < with_ep[capped] == 3.0 < unit[capped]
        if kept is not None:
            assert with_ep[kept] == plain[kept] > 3.0
        for kappa, factor in ((1.2, 0.5), (0.5, 0.19)):  # κ ≥ 1, or e_C < 0.2: a_ISO itself
            np.testing.assert_array_equal(
                life_modification.life_modification_factor_ep(np.full(3, kappa), x, factor, element),
                life_modification.life_modification_factor(kappa, x, element))


def test_ep_additives_through_a_scene():
    """The gearbox 6411E at 300 r/min (κ ≈ 0.55) in clean oil (−/13/10, e_C ≈ 0.6) with
    lubricant.ep_additives: a_ISO and L10m follow the EP rule at the scene's own κ, e_C, C_u and P,
    and exceed the plain oil's."""
    overrides = ["operating.inner_speed=300 rpm", 'lubricant.cleanliness="-/13/10"']
    plain = run_model(build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=overrides)),
                      progress=False).values
    values = run_model(build_model(load_scene(example_scene("gearbox_6411_ratings"),
                                              overrides=[*overrides, "lubricant.ep_additives=true"])),
                       progress=False).values
    kappa, factor = float(values["life.viscosity_ratio"]), float(values["life.contamination_factor"])
    assert kappa < 1.0 and factor >= 0.2
    ratio = factor * float(values["life.fatigue_load_limit"]) / float(values["life.equivalent_load"])
    want = float(life_modification.life_modification_factor_ep(kappa, ratio, factor, "ball"))
    assert float(values["life.a_iso"]) == pytest.approx(want, rel=1e-12)
    assert float(values["life.a_iso"]) > float(plain["life.a_iso"])
    assert float(values["life.L10m"]) == pytest.approx(want * float(values["life.L10"]), rel=1e-12)


def test_ep_additive_factor_derivative():
    """d a_ISO / d(κ, e_C C_u/P) with EP additives against a central difference, where a_ISO at κ = 1
    rules (x = 0.05: it depends on x alone) and where a_ISO at κ is kept (x = 1.0)."""
    def factor(point):
        return life_modification.life_modification_factor_ep(point[0], point[1], 0.5, "ball")

    direction = jax.numpy.array([0.1, 0.02])
    for point in (jax.numpy.array([0.5, 0.05]), jax.numpy.array([0.5, 1.0])):
        _, tangent = jax.jvp(factor, (point,), (direction,))
        assert float(tangent) != 0.0
        assert float(tangent) == pytest.approx(float(central_difference_jvp(factor, point, direction, 1e-6)), rel=1e-7)
