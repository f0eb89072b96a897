"""Effect friction = "palmgren": Palmgren's moments in their catalogue units, the default constants
against the Timken Engineering Manual's table, the power loss against Schaeffler's, KRW's worked
example, the loads P₁ of HR 1 through scenes, and derivatives of the torque through the solved
bearing."""

import equinox as eqx
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.friction import friction_torque
from diffbearing.ratings import static_safety

from .helpers import BEARING_6208, assert_jvp_matches_central_difference, example_scene

RPM = np.pi / 30.0


@pytest.mark.parametrize("viscosity, rpm", [(20.0, 3000.0), (20.0, 50.0)])
def test_viscous_moment_in_catalogue_units(viscosity, rpm):
    """M₀ = 10⁻⁷ f₀ (ν n)^{2/3} d_m³ N·mm for ν n ≥ 2000, 160·10⁻⁷ f₀ d_m³ below (ν mm²/s, n r/min,
    d_m mm; Schaeffler HR 1, Timken Engineering Manual p. 184): 66.209 N·mm and 6.912 N·mm for f₀ = 2,
    d_m = 60 mm."""
    torque = float(friction_torque.viscous_torque(2.0, viscosity * 1e-6, rpm * RPM, 60e-3)) * 1e3
    product = viscosity * rpm
    want = 1e-7 * 2.0 * product ** (2 / 3) * 60.0**3 if product >= 2000 else 160e-7 * 2.0 * 60.0**3
    assert torque == pytest.approx(want, rel=1e-12)
    assert torque == pytest.approx(66.209 if product >= 2000 else 6.912, abs=1e-3)


def test_default_constants_are_timkens_reference_values():
    """Timken's Table 114 gives f₀ and f₁ at ISO 15312's reference conditions (oil, P₀ = 0.05 C₀):
    deep groove 02 series f₀ 2, f₁ 0.00020; cylindrical 02 series f₀ 2, f₁ 0.0003 — HR 1's oil-bath
    f₀ and its f₁ = 0.0009 (P₀/C₀)^0.5 at 0.05, within Timken's rounding (1 %)."""
    f0_grease, f0_oil, a, b = friction_torque.PALMGREN_CONSTANTS["deep_groove_ball"]
    assert f0_oil == 2.0 and friction_torque.speed_factor(a, b, 0.05, 1.0) == pytest.approx(0.00020, rel=0.01)
    _, f0_oil, a, b = friction_torque.PALMGREN_CONSTANTS["cylindrical_roller"]
    assert f0_oil == 2.0 and friction_torque.speed_factor(a, b, 0.05, 1.0) == pytest.approx(0.0003, rel=1e-12)


def test_power_is_schaeffers():
    """N = M ω equals HR 1's N_R = M_R n / 9550 [W, N·mm, r/min] within the rounding of 9550 (1e-4)."""
    assert float(friction_torque.friction_power(0.1, 3000 * RPM)) == pytest.approx(100.0 * 3000 / 9550, rel=1e-4)


# KRW's worked example (KRW Wälzlager, Bearings Delivery Programme 2006, "Reibung", pp. 52–57): a
# 6220 (d 100, D 180 mm, d_m 140 mm, C₀ 93 kN) at 2200 r/min under F_r 20 kN, F_a 6 kN in oil
# (f₀ 2); its table of ν [mm²/s] at 40…80 °C against M₀ [N·mm] and the friction power [W], and M₁.
KRW_VISCOSITY = np.array([100.0, 60.0, 39.0, 26.0, 19.0])
KRW_VISCOUS_TORQUE = np.array([2000.0, 1423.0, 1062.0, 824.0, 660.0])
KRW_POWER = np.array([725.0, 592.0, 509.0, 454.0, 417.0])
KRW_LOAD_TORQUE = 1148.0


def test_krw_worked_example_6220():
    """KRW's 6220 (constants above): f₁ = 0.00089 (P₀/C₀)^0.5 with P₀ = F_r = 20 kN (ISO 76: 0.6 F_r
    + 0.5 F_a = 15 kN is less) is 0.000413, printed 0.00041; P₁ = F_r (F_a/F_r below HR 1's and
    KRW's limit); M₁ = f₁ P₁ d_m = 1148 N·mm at the printed f₁ (exact); M₀ at every tabulated ν
    within the rounding of the printed ν and M₀ (0.9–1.8 %; off by 1.1 % at most, at ν = 26) and
    N = (M₀ + M₁) ω within 1 % (0.4 % at most). The table's 30 °C row
    (ν 183, M₀ 2318 N·mm, 954 W) is left out: its power needs M₀ ≈ 2990 N·mm, which the formula
    gives (2992), so its printed M₀ is a misprint."""
    speed = 2200.0 * RPM
    f1 = friction_torque.speed_factor(0.00089, 0.5, 20e3, 93e3)
    assert float(f1) == pytest.approx(0.00041, abs=5e-6)
    load = friction_torque.friction_load("deep_groove_ball", 20e3, 6e3)
    assert float(load) == 20e3
    assert float(friction_torque.load_torque(0.00041, load, 0.14)) * 1e3 == pytest.approx(KRW_LOAD_TORQUE, rel=1e-12)
    viscous = np.array([float(friction_torque.viscous_torque(2.0, nu * 1e-6, speed, 0.14)) for nu in KRW_VISCOSITY])
    # ν printed to ±0.5 mm²/s moves M₀ ∝ ν^{2/3} by (2/3)(0.5/ν), M₀ printed to ±0.5 N·mm
    rounding = (2.0 / 3.0) * 0.5 / KRW_VISCOSITY + 0.5 / KRW_VISCOUS_TORQUE
    assert np.all(np.abs(viscous * 1e3 / KRW_VISCOUS_TORQUE - 1.0) <= rounding)
    power = np.array([float(friction_torque.friction_power(m + KRW_LOAD_TORQUE * 1e-3, speed)) for m in viscous])
    np.testing.assert_allclose(power, KRW_POWER, rtol=0.01)


SCENE = 'title = "6208 friction"' + BEARING_6208 + """radial_clearance = "10 um"
[operating]
inner_speed = "3000 rpm"
force = ["2000 N", "0 N", "{axial} N"]
[lubricant]
kinematic_viscosity_40 = "20 mm^2/s"
kinematic_viscosity_100 = "4 mm^2/s"
temperature = "40 degC"
{supply}
[effects]
friction = "palmgren"
"""


def _model(tmp_path, axial=0.0, supply=""):
    path = tmp_path / "scene.toml"
    path.write_text(SCENE.replace("{axial}", repr(axial)).replace("{supply}", supply))
    return build_model(load_scene(str(path)))


@pytest.mark.parametrize("axial, supply, f0", [(0.0, "", 2.0), (1500.0, 'supply = "grease"', 1.3)])
def test_torque_of_a_6208(tmp_path, axial, supply, f0):
    """6208 at 3000 r/min in 20 mm²/s oil: M₀ = 66.209 N·mm (oil bath f₀ = 2; grease 1.3), M₁ = f₁ P₁ d_m
    with f₁ = 0.0009 (P₀/C₀)^0.5 and P₁ = max(3.3 F_a − 0.1 F_r, F_r) (HR 1)."""
    values = run_model(_model(tmp_path, axial, supply), progress=False).values
    assert float(values["friction.f0"]) == f0
    assert float(values["friction.viscous_torque"]) * 1e3 == pytest.approx(66.209 * f0 / 2.0, rel=1e-4)
    force = jnp.array([2000.0, 0.0, axial])
    c0 = static_safety.ball_static_load_rating(9, 11.906e-3, 60e-3, 0.0)
    p0 = static_safety.ball_equivalent_static_load(force, 0.0, radial_contact=True)
    f1 = 0.0009 * float(p0 / c0) ** 0.5
    p1 = max(3.3 * axial - 0.1 * 2000.0, 2000.0)
    assert float(values["friction.load"]) == pytest.approx(p1, rel=1e-9)
    assert float(values["friction.load_torque"]) == pytest.approx(f1 * p1 * 0.06, rel=1e-9)
    assert float(values["friction.power"]) == pytest.approx(float(values["friction.torque"]) * 3000 * RPM, rel=1e-12)


@pytest.mark.slow
def test_torque_derivatives_through_the_solved_bearing(tmp_path):
    """d M / d(applied force, viscosity) through the ball equilibrium against a central difference,
    forward and reverse."""
    model = _model(tmp_path, axial=1500.0)
    function = model.function()

    def torque(point):
        inputs = eqx.tree_at(lambda i: (i["operating"].force, i["lubricant"].viscosity), model.inputs, point)
        return function(inputs)["friction.torque"]

    point = (jnp.array([2000.0, 300.0, 1500.0]), jnp.asarray(model.inputs["lubricant"].viscosity))
    direction = (jnp.array([100.0, -50.0, 80.0]), 0.1 * point[1])
    assert_jvp_matches_central_difference(torque, point, direction, 1e-4, rtol=1e-6)


def test_cylindrical_roller_bearing_friction():
    """The cylindrical roller example at 1500 r/min in VG 46 at 60 °C: P₁ = F_r, f₁ = 0.0003 (HR 1, 2..-E)."""
    values = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"), overrides=[
        "effects.stiffness=false", "effects.life=false", "effects.friction=palmgren", "operating.inner_speed=1500 rpm",
        "lubricant.preset=iso_vg_46", "lubricant.temperature=60 degC"])), progress=False).values
    assert float(values["friction.load"]) == pytest.approx(2040.0, rel=1e-9)
    assert float(values["friction.load_torque"]) == pytest.approx(0.0003 * 2040.0 * 0.1066, rel=1e-9)


@pytest.mark.parametrize("ratio", [0.0, 0.05, 0.2, 0.2635, 0.3, 2.0])
def test_spherical_roller_friction_load_is_hr1s(ratio):
    """P₁ of a spherical roller bearing (HR 1, "Friction and increases in temperature"; KRW's p. 118
    alike), α = 10°, e = 1.5 tan α = 0.2645: F_r (1 + 0.6 (F_a/(e F_r))³) up to e, 1.6 F_a/e past it,
    written out here (1e-14); never below F_r."""
    radial, angle = 10e3, np.radians(10.0)
    axial = ratio * radial
    e = 1.5 * np.tan(angle)
    expected = radial * (1 + 0.6 * (ratio / e) ** 3) if ratio <= e else 1.6 * axial / e
    load = float(friction_torque.friction_load("spherical_roller", radial, axial, angle))
    assert load == pytest.approx(max(expected, radial), rel=1e-14)


def test_spherical_roller_friction_load_is_continuous_at_e_and_finite_unloaded():
    """At F_a = e F_r both forms give 1.6 F_r (1e-12 either side of e); an unloaded bearing gives 0 and a
    finite gradient (the light branch's F_a/F_r kept away from 0/0)."""
    import jax

    angle = np.radians(10.0)
    e = 1.5 * np.tan(angle)
    for side in (1 - 1e-13, 1 + 1e-13):
        assert float(friction_torque.friction_load("spherical_roller", 1e4, side * e * 1e4, angle)) == pytest.approx(
            1.6e4, rel=1e-12)
    gradient = jax.grad(lambda f: friction_torque.friction_load("spherical_roller", f[0], f[1], angle))(jnp.zeros(2))
    assert float(friction_torque.friction_load("spherical_roller", 0.0, 0.0, angle)) == 0.0
    assert np.all(np.isfinite(np.asarray(gradient)))


@pytest.mark.parametrize("kind, radial, axial, load", [
    ("needle_roller", 3e3, 0.0, 3e3), ("thrust_ball", 0.0, 6e3, 6e3), ("cylindrical_roller_thrust", 0.0, 30e3, 30e3)])
def test_needle_and_thrust_bearings_load_their_moment_with_fr_or_fa(kind, radial, axial, load):
    """HR 1: M₁ = f₁ F d_m with F the radial load of a needle roller bearing, the axial load of an axial
    bearing; its rows f₀ 4 / 5.5 and f₁ 0.0005 (NA49), 1 / 1.5 and 0.0012 (F_a/C₀a)^0.33 (511–514),
    2 / 3 and 0.0015 (811)."""
    assert float(friction_torque.friction_load(kind, radial, axial)) == load
    expected = {"needle_roller": (4.0, 5.5, 0.0005, 0.0), "thrust_ball": (1.0, 1.5, 0.0012, 0.33),
                "cylindrical_roller_thrust": (2.0, 3.0, 0.0015, 0.0)}
    assert friction_torque.PALMGREN_CONSTANTS[kind] == expected[kind]


@pytest.mark.parametrize("force", [[10e3, 1e3], [10e3, 5e3]])
def test_spherical_roller_friction_load_derivative_matches_central_differences(force):
    """dP₁/d(F_r, F_a) on either side of e (F_a/F_r = 0.1 and 0.5 at α = 10°) against central differences."""
    angle = np.radians(10.0)
    assert_jvp_matches_central_difference(lambda f: friction_torque.friction_load("spherical_roller", f[0], f[1], angle),
                                          jnp.asarray(force), jnp.array([1.0, 0.5]), 1.0, rtol=1e-7)
