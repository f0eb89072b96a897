"""SKF's four-component frictional moment (SKF General Catalogue 6000, "Friction"): the catalogue's
worked example for a 22208 E, the exact reductions of Table 2's forms, the sliding coefficient's
blending, derivatives against a central difference, and the refusal of bad input."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.friction import friction_torque, skf_friction
from diffbearing.ratings import static_safety

from .helpers import assert_jvp_matches_central_difference, example_scene

RPM = np.pi / 30.0

# The catalogue's example: spherical roller bearing 22208 E (d 40, D 80, B 23 mm, d_m 60 mm), 3500 r/min,
# F_r = 2990 N, F_a = 100 N, oil bath at H = 2.5 mm (V_M ≈ 0.3·10⁻⁴ at H/d_m = 0.041), mineral oil of
# ν = 68 mm²/s, full film (μ_sl = 0.05).
EXAMPLE = dict(kind="spherical_roller", constants="222E", radial=2990.0, axial=100.0, speed=3500 * RPM,
               kinematic_viscosity=68e-6, bore=40e-3, outside_diameter=80e-3)


def _example():
    return skf_friction.frictional_moment(**EXAMPLE, supply="oil_bath", sliding_friction_coefficient=0.05,
                                          drag_loss_factor=0.3e-4, inner_ring_width=23e-3)


def test_catalogue_worked_example_22208_e():
    """Each of the catalogue's printed intermediates within its rounding: G_rr.e = 0.26, G_rr.l = 0.436,
    G_sl.e = 434, G_sl.l = 1236.6, M_rr = 437 N·mm (from the rounded G_rr = 0.26), M_sl = 21.7 N·mm,
    φ_ish ≈ 0.85, φ_rs ≈ 0.8, K_roll = 13.2·10⁻¹², M_drag = 14.5 N·mm; the total 334 N·mm within 1 %
    (331.1 N·mm unrounded: the catalogue multiplies its rounded factors)."""
    rolling_e, rolling_l, sliding_e, sliding_l = skf_friction.spherical_roller_variables(
        skf_friction.SPHERICAL_ROLLER_CONSTANTS["222E"], 2990.0, 100.0, 60e-3)
    assert float(rolling_e) == pytest.approx(0.26, abs=0.005)
    assert float(rolling_l) == pytest.approx(0.436, abs=0.0005)
    assert float(sliding_e) == pytest.approx(434.0, abs=0.5)
    assert float(sliding_l) == pytest.approx(1236.6, abs=0.1)

    result = _example()
    assert float(result.rolling_variable) == float(rolling_e)  # G_rr.e < G_rr.l: the .e pair
    assert float(result.sliding_variable) == float(sliding_e)
    assert float(skf_friction.rolling_moment(0.26, 68e-6, 3500 * RPM)) * 1e3 == pytest.approx(437.0, abs=0.5)
    assert float(result.rolling) * 1e3 == pytest.approx(434.9, abs=0.05)
    assert float(result.sliding) * 1e3 == pytest.approx(21.7, abs=0.05)
    assert float(result.inlet_shear) == pytest.approx(0.85, abs=0.005)
    assert float(result.replenishment) == pytest.approx(0.8, abs=0.005)
    assert skf_friction.roller_drag_constant(5.5, 0.8, 40e-3, 80e-3) == pytest.approx(13.2e-12, rel=1e-12)
    assert float(result.drag) * 1e3 == pytest.approx(14.5, abs=0.05)
    assert float(result.seal) == 0.0
    assert float(result.total) * 1e3 == pytest.approx(334.0, rel=0.01)
    assert float(result.total) * 1e3 == pytest.approx(331.1, abs=0.05)


def test_sliding_coefficient_blends_boundary_and_full_film():
    """φ_bl = 1 at standstill, so μ_sl = μ_bl = 0.15; at 3500 r/min in 68 mm²/s oil φ_bl ≈ 10⁻²³ and
    μ_sl = μ_EHL; in between the formula φ_bl = exp(−2.6·10⁻⁸ (n ν)^1.4 d_m)."""
    assert float(skf_friction.sliding_coefficient(68e-6, 0.0, 60e-3, 0.05)) == pytest.approx(0.15, rel=1e-15)
    assert float(skf_friction.sliding_coefficient(68e-6, 3500 * RPM, 60e-3, 0.05)) == pytest.approx(0.05, rel=1e-12)
    weighting = np.exp(-2.6e-8 * (50.0 * 10.0) ** 1.4 * 60.0)
    blended = skf_friction.sliding_coefficient(10e-6, 50 * RPM, 60e-3, 0.05)
    assert float(blended) == pytest.approx(weighting * 0.15 + (1 - weighting) * 0.05, rel=1e-12)
    assert 0.05 < float(blended) < 0.15


def test_deep_groove_forms_without_axial_load():
    """At F_a = 0 Table 2's own forms, G_rr = R1 d_m^1.96 F_r^0.54 and G_sl = S1 d_m^−0.26 F_r^{5/3}; as
    F_a → 0⁺ the loaded G_rr tends to the same value but the loaded G_sl to S1 d_m^−0.145 F_r^{5/3}, the
    catalogue's jump; the gradient in F_a stays finite at F_a = 0."""
    r1, _, s1, _ = skf_friction.DEEP_GROOVE_BALL_CONSTANTS["62"]
    rolling, sliding = skf_friction.deep_groove_ball_variables((r1, 1.7, s1, 36.5), 3000.0, 0.0, 60e-3, 19e3)
    assert float(rolling) == pytest.approx(r1 * 60.0**1.96 * 3000.0**0.54, rel=1e-12)
    assert float(sliding) == pytest.approx(s1 * 60.0**-0.26 * 3000.0 ** (5 / 3), rel=1e-12)
    rolling, sliding = skf_friction.deep_groove_ball_variables((r1, 1.7, s1, 36.5), 3000.0, 1e-6, 60e-3, 19e3)
    assert float(rolling) == pytest.approx(r1 * 60.0**1.96 * 3000.0**0.54, rel=1e-6)
    assert float(sliding) == pytest.approx(s1 * 60.0**-0.145 * 3000.0 ** (5 / 3), rel=1e-12)
    gradient = jax.grad(lambda fa: sum(skf_friction.deep_groove_ball_variables((r1, 1.7, s1, 36.5), 3000.0, fa,
                                                                              60e-3, 19e3)))(0.0)
    assert np.isfinite(float(gradient))


def test_angular_contact_at_standstill_and_power():
    """At n = 0 the centrifugal term vanishes: G_rr = R1 d_m^1.97 (F_r + R2 F_a)^0.54 (Table 2) to 1e-12;
    the power is N = M ω."""
    r1, r2, *_ = skf_friction.ANGULAR_CONTACT_BALL_CONSTANTS["single_row"]
    rolling, _ = skf_friction.frictional_variables("angular_contact_ball", "single_row", 2000.0, 1500.0, 0.0, 65e-3)
    assert float(rolling) == pytest.approx(r1 * 65.0**1.97 * (2000.0 + r2 * 1500.0) ** 0.54, rel=1e-12)
    result = _example()
    assert float(result.power) == pytest.approx(float(result.total) * 3500 * RPM, rel=1e-14)
    assert float(friction_torque.friction_power(0.1, -3000 * RPM)) == pytest.approx(0.1 * 3000 * RPM, rel=1e-14)


def test_seal_moment():
    """M_seal = K_S1 d_s^β + K_S2 for two seals, half for one: a 6208-2RS1 (D = 80 mm) on d_s = 52 mm adds
    0.018 · 52^2.25 + 20 N·mm to the moment of the open bearing."""
    beta, k1, k2 = skf_friction.SEAL_CONSTANTS["deep_groove_ball.RS1.62<D<=80"]
    want = k1 * 52.0**beta + k2
    assert float(skf_friction.seal_moment(k1, beta, k2, 52e-3)) * 1e3 == pytest.approx(want, rel=1e-13)
    assert float(skf_friction.seal_moment(k1, beta, k2, 52e-3, seals=1)) * 1e3 == pytest.approx(want / 2, rel=1e-13)
    arguments = ("deep_groove_ball", "62", 3000.0, 500.0, 3000 * RPM, 20e-6, 40e-3, 80e-3)
    open_bearing = skf_friction.frictional_moment(*arguments, supply="grease", static_load_rating=19e3)
    sealed = skf_friction.frictional_moment(*arguments, supply="grease", static_load_rating=19e3,
                                            seal="deep_groove_ball.RS1.62<D<=80", counterface_diameter=52e-3)
    assert float(sealed.total - open_bearing.total) * 1e3 == pytest.approx(want, rel=1e-12)


def test_derivatives_of_a_6208():
    """d M/d F_r and d M/d ν of a 6208 (series 62, C₀ = 19 kN) at F_r = 3 kN, F_a = 500 N, 3000 r/min,
    ν = 20 mm²/s in an oil bath, against a central difference: the unknowns in kN and mm²/s (scale ~10),
    so h = 1e-5 (≈ 6e-6 × scale, tests/helpers.py)."""
    def total(point):
        radial, viscosity = point[0] * 1e3, point[1] * 1e-6
        return skf_friction.frictional_moment("deep_groove_ball", "62", radial, 500.0, 3000 * RPM, viscosity, 40e-3,
                                              80e-3, supply="oil_bath", static_load_rating=19e3,
                                              drag_loss_factor=1e-4).total

    point = jnp.array([3.0, 20.0])
    for direction in (jnp.array([1.0, 0.0]), jnp.array([0.0, 1.0])):
        assert_jvp_matches_central_difference(total, point, direction, step=1e-5, rtol=1e-7)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match=r"constants: the deep_groove_ball series must be one of .*'62'.*got '99'"):
        skf_friction.frictional_moment("deep_groove_ball", "99", 3000.0, 0.0, 300.0, 20e-6, 40e-3, 80e-3,
                                       supply="oil_bath", static_load_rating=19e3)
    with pytest.raises(ValueError, match="kinematic_viscosity must be > 0"):
        skf_friction.frictional_moment("deep_groove_ball", "62", 3000.0, 0.0, 300.0, -20e-6, 40e-3, 80e-3,
                                       supply="oil_bath", static_load_rating=19e3)
    with pytest.raises(ValueError, match=r"kind must be one of \('deep_groove_ball'"):
        skf_friction.frictional_moment("needle_roller", "62", 3000.0, 0.0, 300.0, 20e-6, 40e-3, 80e-3, supply="grease")
    with pytest.raises(ValueError, match=r"supply must be one of \('oil_bath'"):
        skf_friction.frictional_moment("deep_groove_ball", "62", 3000.0, 0.0, 300.0, 20e-6, 40e-3, 80e-3, supply="mist",
                                       static_load_rating=19e3)
    with pytest.raises(ValueError, match="outside_diameter must be larger than the bore"):
        skf_friction.frictional_moment("cylindrical_roller", "2", 3000.0, 0.0, 300.0, 20e-6, 80e-3, 40e-3, supply="grease")


def test_scene_runs_skfs_model_at_the_carried_load():
    """effects.friction = "skf" on the gearbox 6411E (series 64, circulating oil: K_rs of an oil jet) gives
    the physics function's moment at the load the solved bearing carries (1e-12); a drag loss needs an oil
    bath, the series must be one of Table 3's, and the key is refused where the effect is Palmgren's."""
    model = build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=[
        "effects.friction=skf", 'friction.series="64"']))
    values = run_model(model, progress=False).values
    force = values["force"][:3]
    lubricant = model.inputs["lubricant"]
    want = skf_friction.frictional_moment(
        "deep_groove_ball", "64", float(np.hypot(force[0], force[1])), abs(float(force[2])), 3000 * RPM,
        lubricant.viscosity / lubricant.density, 55e-3, 140e-3, supply="oil_jet",
        static_load_rating=static_safety.ball_bearing_static_load_rating(model.inputs["bearing"]))
    assert float(values["friction.torque"]) == pytest.approx(float(want.total), rel=1e-12)
    assert float(values["friction.replenishment_factor"]) == pytest.approx(float(want.replenishment), rel=1e-12)
    assert float(values["friction.drag_torque"]) == 0.0

    with pytest.raises(ValueError, match="friction.drag_loss_factor: the drag loss is an oil bath's"):
        build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=[
            "effects.friction=skf", "friction.drag_loss_factor=3e-5"]))
    with pytest.raises(ValueError, match=r"friction.series: the deep_groove_ball series .* got '6'"):
        build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=[
            "effects.friction=skf", 'friction.series="6"']))
    with pytest.raises(ValueError, match="'friction.series' not read by anything"):
        build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=['friction.series="62"']))


def test_tapered_roller_scene_uses_its_axial_load_factor():
    """A tapered roller bearing through a scene: SKF's moment at its carried load with Y = 0.4 cot α of the
    cup (ISO 281), series 320 X, 1500 r/min in VG 68 (1e-12)."""
    model = build_model(load_scene(example_scene("tapered_roller_bearing"), overrides=[
        "effects.friction=skf", 'friction.series="320X"', "operating.inner_speed=1500 rpm", "bearing.bore=40 mm",
        "bearing.outer_diameter=62 mm", "lubricant.preset=iso_vg_68"]))
    values = run_model(model, progress=False).values
    force, lubricant = values["force"][:3], model.inputs["lubricant"]
    want = skf_friction.frictional_moment(
        "tapered_roller", "320X", float(np.hypot(force[0], force[1])), abs(float(force[2])), 1500 * RPM,
        lubricant.viscosity / lubricant.density, 40e-3, 62e-3, supply="oil_bath",
        axial_load_factor=0.4 / np.tan(float(model.inputs["raceways"].cup_angle)))
    assert float(values["friction.torque"]) == pytest.approx(float(want.total), rel=1e-12)
    assert float(values["friction.sliding_coefficient"]) == pytest.approx(0.002, rel=1e-3)  # μ_EHL of tapered bearings


@pytest.mark.slow
def test_scene_torque_derivatives_through_the_solved_bearing():
    """d M_SKF / d(applied force, viscosity) through the 6411E's ball equilibrium against a central
    difference, forward and reverse."""
    import equinox as eqx

    model = build_model(load_scene(example_scene("gearbox_6411_ratings"), overrides=[
        "effects.friction=skf", 'friction.series="64"']))
    function = model.function()

    def torque(point):
        inputs = eqx.tree_at(lambda i: (i["operating"].force, i["lubricant"].viscosity), model.inputs, point)
        return function(inputs)["friction.torque"]

    point = (jnp.asarray(model.inputs["operating"].force), jnp.asarray(model.inputs["lubricant"].viscosity))
    direction = (jnp.array([100.0, -50.0, 80.0]), 0.1 * point[1])
    assert_jvp_matches_central_difference(torque, point, direction, 1e-4, rtol=1e-6)


def test_seal_rows_by_outside_diameter():
    """`seal_row` picks SKF's seal constants by the outside diameter's range (D ≤ 62 mm, 62 < D ≤ 80 mm for
    RS1 on deep groove ball bearings) and refuses a D that no row holds."""
    assert skf_friction.seal_row("deep_groove_ball", "RS1", 62e-3) == "deep_groove_ball.RS1.D<=62"
    assert skf_friction.seal_row("deep_groove_ball", "RS1", 62.5e-3) == "deep_groove_ball.RS1.62<D<=80"
    assert skf_friction.seal_row("cylindrical_roller", "LS", 400e-3) == "cylindrical_roller.LS"
    with pytest.raises(ValueError, match="not for D = 81 mm"):
        skf_friction.seal_row("deep_groove_ball", "RS1", 81e-3)
    with pytest.raises(ValueError, match="no LS seal on a deep_groove_ball bearing"):
        skf_friction.seal_row("deep_groove_ball", "LS", 50e-3)


def test_seal_moment_derivative():
    """d M_seal / d d_s of the RS1 seal (62 < D ≤ 80 mm) against a central difference."""
    beta, k1, k2 = skf_friction.SEAL_CONSTANTS["deep_groove_ball.RS1.62<D<=80"]
    assert_jvp_matches_central_difference(lambda d: skf_friction.seal_moment(k1, beta, k2, d), jnp.asarray(52e-3),
                                          jnp.asarray(1e-3), 1e-6, rtol=1e-8)


def test_scene_seals_add_skfs_seal_moment():
    """friction.seal = "LS" on the cylindrical roller bearing scene (d_s = 60 mm): the moment grows by
    M_seal = K_S1 d_s² + K_S2 = 0.032 · 60² + 50 N·mm for two seals (SKF seal constants), half for one;
    the seal keys are refused without a seal, without d_s and with 3 seals."""
    base = ["effects.friction=skf", "bearing.bore=50 mm", "bearing.outer_diameter=110 mm", "lubricant.preset=iso_vg_68"]
    sealed = ["friction.seal=LS", "friction.seal_counterface_diameter=60 mm"]

    def torque(*overrides):
        values = run_model(build_model(load_scene(example_scene("cylindrical_roller_bearing"),
                                                  overrides=base + list(overrides))), progress=False).values
        return float(values["friction.torque"]), float(values["friction.seal_torque"])

    open_torque, open_seal = torque()
    two, two_seal = torque(*sealed)
    one, one_seal = torque(*sealed, "friction.seals=1")
    want = (0.032 * 60.0**2 + 50.0) * 1e-3
    assert open_seal == 0.0
    assert two_seal == pytest.approx(want, rel=1e-13) and two - open_torque == pytest.approx(want, rel=1e-12)
    assert one_seal == pytest.approx(want / 2, rel=1e-13) and one - open_torque == pytest.approx(want / 2, rel=1e-12)
    for overrides, message in ((sealed[1:], "friction.seal_counterface_diameter needs friction.seal"),
                               (sealed[:1], "friction.seal needs friction.seal_counterface_diameter"),
                               ([*sealed, "friction.seals=3"], "friction.seals: 1 .* or 2, got 3"),
                               (["friction.seal=RS1", sealed[1]], "friction.seal: SKF's seal constants give no RS1")):
        with pytest.raises(ValueError, match=message):
            build_model(load_scene(example_scene("cylindrical_roller_bearing"), overrides=base + overrides))


def test_shaft_skf_friction_is_each_bearings_at_its_load():
    """effects.friction = "skf" on the gearbox shaft (two 6411, series 64, 3000 r/min, VG 68 oil bath): each
    bearing's moment is the physics function's at the load that bearing carries on the shaft (1e-12), the
    shaft's their sum; a series not of the bearings' kind and a single bearing's seal key are refused."""
    overrides = ["effects.friction=skf", 'friction.series="64"', "lubricant.preset=iso_vg_68"]
    model = build_model(load_scene(example_scene("gearbox_shaft"), overrides=overrides))
    values = run_model(model, progress=False).values
    lubricant = model.inputs["lubricant"]
    want = []
    for number, bearing in enumerate(model.inputs["shaft"].bearings):
        force = values["bearings.force"][number]
        want.append(float(skf_friction.frictional_moment(
            "deep_groove_ball", "64", float(np.hypot(force[0], force[1])), abs(float(force[2])), 3000 * RPM,
            lubricant.viscosity / lubricant.density, 55e-3, 140e-3, supply="oil_bath",
            static_load_rating=static_safety.ball_bearing_static_load_rating(bearing)).total))
    np.testing.assert_allclose(values["bearings.friction.torque"], want, rtol=1e-12)
    assert float(values["shaft.friction.torque"]) == pytest.approx(sum(want), rel=1e-12)
    assert float(values["shaft.friction.power"]) == pytest.approx(sum(want) * 3000 * RPM, rel=1e-12)
    for extra, message in (('friction.series="302"', "friction.series: a series of every bearing's kind"),
                           ("friction.seal=RS1", "friction.seal: a single bearing's key, not taken on a shaft")):
        with pytest.raises(ValueError, match=message):
            build_model(load_scene(example_scene("gearbox_shaft"), overrides=[*overrides, extra]))


@pytest.mark.slow
def test_shaft_skf_torque_derivatives_through_the_shaft():
    """d M_SKF (shaft total) / d(load on the shaft, viscosity) through the gearbox shaft's equilibrium
    against a central difference."""
    import equinox as eqx

    model = build_model(load_scene(example_scene("gearbox_shaft"), overrides=[
        "effects.friction=skf", 'friction.series="64"', "lubricant.preset=iso_vg_68"]))
    function = model.function()

    def torque(point):
        inputs = eqx.tree_at(lambda i: (i["shaft"].loads.forces, i["lubricant"].viscosity), model.inputs, point)
        return function(inputs)["shaft.friction.torque"]

    point = (jnp.asarray(model.inputs["shaft"].loads.forces), jnp.asarray(model.inputs["lubricant"].viscosity))
    direction = (jnp.array([[200.0, -100.0, 150.0]]), 0.1 * point[1])
    assert_jvp_matches_central_difference(torque, point, direction, 1e-4, rtol=1e-6)


@pytest.mark.parametrize("kind, series, rolling, sliding", [
    ("thrust_ball", "512", lambda dm, fa: 1.03e-6 * dm**1.83 * fa**0.54, lambda dm, fa: 1.6e-2 * dm**0.05 * fa ** (4 / 3)),
    ("cylindrical_roller_thrust", "812", lambda dm, fa: 2.25e-6 * dm**2.38 * fa**0.31, lambda dm, fa: 0.154 * dm**0.62 * fa),
])
def test_thrust_bearings_rows_are_table_2b_and_3(kind, series, rolling, sliding):
    """Thrust ball and cylindrical roller thrust bearings (SKF General Catalogue 6000, Friction, Tables 2b
    and 3, one row of constants for each type): G_rr, G_sl written out at d_m = 77.5 mm, F_a = 30 kN
    (1e-12); a radial load changes nothing; the replenishment reads K_Z = 3.8 and 4.4 (Table 5), and the
    whole moment of the thrust roller bearing at 300 r/min in ν = 30 mm²/s is its parts."""
    g_rr, g_sl = skf_friction.frictional_variables(kind, series, 0.0, 30e3, 0.0, 77.5e-3)
    assert float(g_rr) == pytest.approx(rolling(77.5, 30e3), rel=1e-12)
    assert float(g_sl) == pytest.approx(sliding(77.5, 30e3), rel=1e-12)
    loaded = skf_friction.frictional_variables(kind, series, 5e3, 30e3, 0.0, 77.5e-3)
    assert [float(x) for x in loaded] == [float(g_rr), float(g_sl)]
    assert skf_friction.bearing_type_constants(kind, series)[0] == {"thrust_ball": 3.8, "cylindrical_roller_thrust": 4.4}[kind]
    moment = skf_friction.frictional_moment(kind, series, 0.0, 30e3, 300 * RPM, 30e-6, 60e-3, 95e-3, supply="oil_bath")
    parts = float(moment.inlet_shear * moment.replenishment * moment.rolling + moment.sliding)
    assert float(moment.total) == pytest.approx(parts, rel=1e-12)
    assert float(moment.rolling) == pytest.approx(float(g_rr) * (30.0 * 300.0) ** 0.6 * 1e-3, rel=1e-12)


@pytest.mark.parametrize("kind, series", [("thrust_ball", "511"), ("cylindrical_roller_thrust", "811")])
def test_thrust_rows_moment_derivative_matches_central_differences(kind, series):
    """dM/d(F_a, n) of the thrust rows' SKF moment (30 kN, 300 r/min, ν = 30 mm²/s) against central differences."""
    def moment(x):
        return skf_friction.frictional_moment(kind, series, 0.0, x[0], x[1] * RPM, 30e-6, 60e-3, 95e-3,
                                              supply="oil_bath").total

    assert_jvp_matches_central_difference(moment, jnp.array([30e3, 300.0]), jnp.array([1.0, 1.0]), 1e-2, rtol=1e-6)
