"""The spherical roller bearing through the bearing interface: the self-aligning identities of its
first-order model (no moment about the centre, no change with the tilt), the rows alike under a
radial load and one row unloaded under an axial one, the contacts' statics against the ring force,
its ISO 281 (e, Y₁, Y₂ of double-row roller bearings) and ISO 76 ratings, its stiffness against
central differences, random states, the example's shaft as a simply supported beam, and its scene
entry's checks."""

import importlib.resources

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import (
    RollerModel,
    build_model,
    load_scene,
    run_model,
    spherical_roller,
    spherical_roller_raceways,
    spherical_roller_support,
)
from diffbearing.bearings.roller import spherical_roller as srb
from diffbearing.app.adapters.systems.shaft import pressure_warnings
from diffbearing.friction import skf_friction

from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference

SCENE = importlib.resources.files("diffbearing.scenes") / "spherical_roller_shaft.toml"

# The spherical_roller_shaft example's bearing (22220 E size, illustrative internals): 2 × 19 rollers
# of 22 × 19 mm, barrel radius 76 mm, inner raceways 79 mm, d_m = 140 mm, α = 10°, 60 µm clearance.
DIAMETER, LENGTH, ROLLERS, PITCH, ANGLE, CLEARANCE = 22e-3, 19e-3, 19, 140e-3, np.radians(10.0), 60e-6
ROLLER = spherical_roller(roller_diameter=DIAMETER, roller_length=LENGTH, rollers=ROLLERS, profile_radius=76e-3)
RACEWAYS = spherical_roller_raceways(ROLLER, pitch_diameter=PITCH, contact_angle=ANGLE, inner_profile_radius=79e-3,
                                     diametral_clearance=CLEARANCE)
MODEL = RollerModel(laminae=20)
SUPPORT = spherical_roller_support(ROLLER, RACEWAYS, 0.0, model=MODEL)


@jax.jit
def _full(displacement):
    return srb.full_ring_force(displacement, ROLLER, RACEWAYS, MODEL)


@jax.jit
def _full_stiffness(displacement):
    return jax.jacfwd(srb.full_ring_force)(displacement, ROLLER, RACEWAYS, MODEL)


@jax.jit
def _contacts(displacement):
    return SUPPORT.contacts(displacement, 0.0, None)


@hypothesis.settings(max_examples=6, deadline=None)
@hypothesis.given(radial=st.floats(35e-6, 90e-6), axial=st.floats(-40e-6, 40e-6), tilt_x=st.floats(-2e-3, 2e-3),
                  tilt_y=st.floats(-2e-3, 2e-3))
def test_the_first_order_model_is_self_aligning(radial, axial, tilt_x, tilt_y):
    """At random loaded states, tilted or not, the full model's moments about the centre vanish
    and its force and stiffness do not change with the tilt (a rotation of the inner ring and its
    rollers about O moves no contact): |M| < 1e-6 of F d_m/2, ∂F/∂θ < 1e-6 of the translational
    stiffness × d_m/2, F(θ) = F(0) to 1e-6. The support, which drops the tilt, rests on these."""
    translation = jnp.array([radial, 0.3 * radial, axial, 0.0, 0.0])
    tilted = translation.at[3].set(tilt_x).at[4].set(tilt_y)
    force, stiffness = np.asarray(_full(tilted)), np.asarray(_full_stiffness(tilted))
    size = np.abs(force[:3]).max()
    assert size > 0.0
    np.testing.assert_allclose(force[3:], 0.0, atol=1e-6 * size * PITCH / 2)
    np.testing.assert_allclose(force, np.asarray(_full(translation)), rtol=0, atol=1e-6 * size)
    np.testing.assert_allclose(stiffness[:, 3:], 0.0, atol=1e-6 * np.abs(stiffness[:3, :3]).max() * PITCH / 2)
    np.testing.assert_allclose(np.asarray(SUPPORT.ring_force(tilted, 0.0, None)), force * srb.TRANSLATION,
                               rtol=0, atol=1e-6 * size)


def test_a_radial_load_loads_both_rows_alike_and_an_axial_one_a_single_row():
    """Δ = [60 µm, 0, 0, 0, 0]: the rows' rollers alike (1e-9), no axial force (1e-9 of F_x). Δ along
    +z alone loads row 1 only (row 2 open: a hard case the rollers' Newton meets), every roller of it
    alike, and its contacts' axial components, Σ q (sin α − (y/R_i) cos α), make the ring's F_z (1e-9)."""
    radial = _contacts(jnp.array([60e-6, 0.0, 0.0, 0.0, 0.0]))
    load = np.asarray(radial.load)
    np.testing.assert_allclose(load[:, 0], load[:, 2], rtol=1e-9, atol=1e-9 * load.max())
    np.testing.assert_allclose(load[:, 1], load[:, 3], rtol=1e-9, atol=1e-9 * load.max())
    force = np.asarray(SUPPORT.ring_force(jnp.array([60e-6, 0.0, 0.0, 0.0, 0.0]), 0.0, None))
    np.testing.assert_allclose(force[2], 0.0, atol=1e-9 * force[0])
    displacement = jnp.array([0.0, 0.0, 300e-6, 0.0, 0.0])  # past the normal play P_d cos α / 2 over sin α
    axial = _contacts(displacement)
    load = np.asarray(axial.load)
    assert load[:, 2:].max() == 0.0 and load[:, :2].min() > 0.0
    np.testing.assert_allclose(load[:, 0], load[0, 0], rtol=1e-9)
    setup = srb.spherical_setup(ROLLER, RACEWAYS, MODEL.laminae)
    laminae = np.asarray(axial.lamina_load[:, 0, :])
    y = np.asarray(setup.y)
    components = laminae * (np.sin(ANGLE) - y / float(RACEWAYS.inner_profile_radius) * np.cos(ANGLE))
    ring = np.asarray(SUPPORT.ring_force(displacement, 0.0, None))
    np.testing.assert_allclose(components.sum(), ring[2], rtol=1e-9)


def test_its_ratings_are_iso_281_and_iso_76_of_double_row_roller_bearings():
    """C_r = 1.15 f_c (2 L_we cos α)^{7/9} Z^{3/4} D_we^{29/27} (f_c of ISO/TR 1281-1's closed form,
    1e-3); C₀r = 44 (1 − γ) 2 Z L_we D_we cos α (exact); P = F_r + 0.45 cot α F_a up to e = 1.5 tan α,
    0.67 F_r + 0.67 cot α F_a above, continuous at e (1.675 F_r either way); P₀ = F_r + 0.44 cot α F_a."""
    gamma = DIAMETER * np.cos(ANGLE) / PITCH
    fc = (207.9 * 0.83 * gamma ** (2 / 9) * (1 - gamma) ** (29 / 27) * (1 + gamma) ** -0.25
          * (1 + (1.04 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)) ** 4.5) ** (-2 / 9))
    expected = 1.15 * fc * (2 * 19 * np.cos(ANGLE)) ** (7 / 9) * ROLLERS ** 0.75 * 22 ** (29 / 27)
    np.testing.assert_allclose(SUPPORT.dynamic_load_rating(), expected, rtol=1e-3)
    np.testing.assert_allclose(SUPPORT.static_load_rating(), 44 * (1 - gamma) * 2 * ROLLERS * 19 * 22 * np.cos(ANGLE),
                               rtol=1e-12)
    cot, e = 1 / np.tan(ANGLE), 1.5 * np.tan(ANGLE)
    for radial, axial, want in ((10e3, 1e3, 10e3 + 0.45 * cot * 1e3), (10e3, 5e3, 0.67 * 10e3 + 0.67 * cot * 5e3)):
        np.testing.assert_allclose(SUPPORT.equivalent_dynamic_load(jnp.array([radial, 0.0, axial])), want, rtol=1e-12)
        np.testing.assert_allclose(SUPPORT.equivalent_static_load(jnp.array([0.0, radial, -axial])),
                                   radial + 0.44 * cot * axial, rtol=1e-12)
    at_e = [float(SUPPORT.equivalent_dynamic_load(jnp.array([10e3, 0.0, e * 10e3 * (1 + s)]))) for s in (-1e-12, 1e-12)]
    np.testing.assert_allclose(at_e, 1.675 * 10e3, rtol=1e-9)


def test_its_stiffness_is_the_ring_forces_derivative():
    """The support's ring stiffness (rollers re-equilibrated through their implicit derivative) along a
    translation against central differences (1e-6), zero in θ."""
    point = jnp.array([55e-6, 10e-6, 20e-6, 0.0, 0.0])
    direction = jnp.array([1e-6, -1e-6, 2e-6, 0.0, 0.0])
    assert_jvp_matches_central_difference(lambda d: SUPPORT.ring_force(d, 0.0, None), point, direction, 1e-2, rtol=1e-6,
                                          atol=1e-8 * 3e4)
    stiffness = np.asarray(SUPPORT.ring_stiffness(point, 0.0, None))
    np.testing.assert_allclose(stiffness[3:], 0.0, atol=0.0)
    np.testing.assert_allclose(stiffness[:, 3:], 0.0, atol=0.0)


@pytest.mark.slow
@hypothesis.settings(max_examples=8, deadline=None)
@hypothesis.given(radial=st.floats(-100e-6, 100e-6), axial=st.floats(-150e-6, 150e-6))
def test_random_states_are_finite_balanced_and_the_energys_gradient(radial, axial):
    """Random translations (all rollers open, one row, both): a finite ring force, equal to the static
    energy's total derivative to 1e-6 of itself or 1e-9 of the load scale (the ring force is the
    contacts' partial derivative at the rollers' minimum: the two agree where the centring spring,
    `spherical_roller.CENTRING`, leaves the minimum alone; this walk found the radial rollers' spring
    moving it by 2e-6 and more), the rollers balanced (`balance_residual` < 1e-9) and a finite
    stiffness."""
    displacement = jnp.array([radial, -0.5 * radial, axial, 0.0, 0.0])
    force = np.asarray(SUPPORT.ring_force(displacement, 0.0, None))
    gradient = np.asarray(jax.grad(SUPPORT.static_energy)(displacement, None))
    assert np.all(np.isfinite(force))
    scale = float(SUPPORT.characteristic_load(None, None))
    np.testing.assert_allclose(force, gradient, rtol=1e-6, atol=1e-9 * scale)
    assert float(SUPPORT.balance_residual(displacement, 0.0, None, scale)) < 1e-9
    assert np.all(np.isfinite(np.asarray(SUPPORT.ring_stiffness(displacement, 0.0, None))))


@pytest.mark.parametrize("keys, named", [
    (dict(profile_radius=10e-3), "bearing.roller_profile_radius"),
    (dict(profile_radius=90e-3, inner_profile_radius=95e-3), "bearing.roller_profile_radius must be below the outer"),
    (dict(inner_profile_radius=70e-3), "bearing.inner_profile_radius"),
    (dict(contact_angle=np.radians(25.0)), "bearing.contact_angle"),
    (dict(rollers=22), "bearing.rollers: 22 rollers"),
])
def test_bad_geometry_names_its_key(keys, named):
    roller_keys = dict(roller_diameter=DIAMETER, roller_length=LENGTH, rollers=keys.get("rollers", ROLLERS),
                       profile_radius=keys.get("profile_radius", 76e-3))
    with pytest.raises(ValueError, match=named):
        roller = spherical_roller(**roller_keys)
        spherical_roller_raceways(roller, pitch_diameter=PITCH, contact_angle=keys.get("contact_angle", ANGLE),
                                  inner_profile_radius=keys.get("inner_profile_radius", 79e-3))


@pytest.mark.parametrize("change, named", [
    (('inner_profile_radius = "79 mm"', 'inner_profile_radius = "75 mm"'), "bearings[0]: inner_profile_radius"),
    (('rollers = 19                       # a row', 'rollers = 19\nballs = 19'), "bearings[0]: key 'balls' is not read"),
    (('stiffness = true', 'stiffness = true\ncentrifugal = true'), "effects.centrifugal"),
    (('friction = "skf"', 'friction = "skf"\n[friction]\nseries = "213"'), "friction.series"),
])
def test_a_bad_spherical_roller_entry_exits_2_naming_its_key(capsys, tmp_path, change, named):
    """The example with one bad key: exit 2, one line naming it."""
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.read_text().replace(*change, 1))
    assert_exits_2_naming(capsys, ["run", str(path)], named)


@pytest.mark.slow
def test_the_example_shaft_is_a_simply_supported_beam_on_its_spherical_roller_bearings():
    """The spherical_roller_shaft example: converged, no problems; neither bearing carries a moment, so
    the shaft is a simply supported beam: each bearing takes half the 60 kN and its rings tilt by the
    beam's section rotation at a support, F L²/(16 E I) = 2.362 mrad (8.1′), within 1e-6. Each
    bearing's SKF moment is the catalogue model's spherical roller row (series 222E; the model itself
    checked against the catalogue's 22208 E example in test_skf_friction.py) at the load it carries,
    d = 100 and D = 180 mm, ν of ISO VG 68 at 60 °C, to 1e-12."""
    model = build_model(load_scene(str(SCENE)))
    result = run_model(model, progress=False)
    assert bool(result.values["shaft.converged"]) and not any(result.problems), result.problems
    forces = np.asarray(result.values["bearings.force"])
    np.testing.assert_allclose(forces[:, 0], 30e3, rtol=1e-9)
    np.testing.assert_allclose(forces[:, 3:], 0.0, atol=1e-9 * 30e3 * PITCH / 2)
    tilts = np.abs(np.asarray(result.values["bearings.displacement"])[:, 4])
    inertia = np.pi * 0.1**4 / 64
    np.testing.assert_allclose(tilts, 60e3 * 0.8**2 / (16 * 207e9 * inertia), rtol=1e-6)
    lubricant = model.inputs["lubricant"]
    for number, force in enumerate(forces):
        moment = skf_friction.frictional_moment("spherical_roller", "222E", np.hypot(force[0], force[1]), abs(force[2]),
                                                600 * np.pi / 30, lubricant.viscosity / lubricant.density, 0.1, 0.18,
                                                supply="oil_bath")
        assert float(result.values["bearings.friction.torque"][number]) == pytest.approx(float(moment.total), rel=1e-12)


def test_a_shaft_warns_of_pressure_past_its_bearings_own_iso_76_limit():
    """ISO 76's permissible pressure is the type's: 4.1 GPa passes a roller bearing's 4 000 MPa,
    s(p) = (4.0/4.1)² (1e-12), and the shaft warns of it; the same pressure under a ball bearing's
    4 200 MPa, s(p) = (4.2/4.1)³, gives no warning."""
    roller = float(SUPPORT.pressure_safety(4.1e9))
    assert roller == pytest.approx((4.0 / 4.1) ** 2, rel=1e-12)
    ball = (4.2 / 4.1) ** 3
    (warning,) = pressure_warnings([4.1e9, 4.1e9], [roller, ball])
    assert warning.startswith("bearing 0: peak contact pressure 4.1 GPa exceeds ISO 76's permissible pressure")
