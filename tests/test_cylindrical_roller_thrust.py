"""The cylindrical roller thrust bearing through the bearing interface: equal roller loads under a
pure axial load, the lamina law along each roller in closed form, the tilt stiffness of rigid washers,
the floating housing washer, the sliding along the rollers and its loss in closed form, its ISO 281,
ISO/TS 16281 and ISO 76 ratings, derivatives against central differences, random states, and its
scene entry's checks."""

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
    cylindrical_roller_thrust_bearing,
    cylindrical_roller_thrust_support,
    load_scene,
    roller_profile,
    run_model,
)
from diffbearing.bearings.roller import cylindrical_roller_thrust as crtb
from diffbearing.bearings.roller.roller_contact import PALMGREN_STEEL_MODULUS
from diffbearing.bearings.roller.roller_equilibrium import lamina_positions
from diffbearing.bearings.roller.roller_geometry import roller_modulus
from diffbearing.ratings import reference_life, roller_life

from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference, palmgren_moment

SCENE = importlib.resources.files("diffbearing.scenes") / "thrust_roller_shaft.toml"

# The thrust_roller_shaft example's bearing (81212 size, illustrative internals): 16 rollers of
# 11 × 11 mm on d_m = 77.5 mm.
DIAMETER, LENGTH, ROLLERS, PITCH, LAMINAE = 11e-3, 11e-3, 16, 77.5e-3, 20
STRAIGHT = cylindrical_roller_thrust_bearing(roller_diameter=DIAMETER, roller_length=LENGTH, rollers=ROLLERS)
CROWNED = cylindrical_roller_thrust_bearing(
    roller_diameter=DIAMETER, roller_length=LENGTH, rollers=ROLLERS,
    profile=roller_profile("circular", length=LENGTH, flat_length=8e-3, crown_radius=0.3))
MODEL = RollerModel(laminae=LAMINAE)


def _support(bearing=STRAIGHT):
    return cylindrical_roller_thrust_support(bearing, PITCH, 0.0, model=MODEL)


@jax.jit
def _force(support, displacement):
    return support.ring_force(displacement, 0.0, None)


@jax.jit
def _stiffness(support, displacement):
    return support.ring_stiffness(displacement, 0.0, None)


@jax.jit
def _contacts(support, displacement):
    return support.contacts(displacement, 0.0, None)


def _under_axial_load(support, axial_load, steps=60):
    """Δ = [0, 0, δz, 0, 0] with F_z = `axial_load` [N] (Newton on δz)."""
    displacement = jnp.zeros(5).at[2].set(2e-6)
    for _ in range(steps):
        step = (float(_force(support, displacement)[2]) - axial_load) / float(_stiffness(support, displacement)[2, 2])
        displacement = displacement.at[2].add(-step)
        if abs(step) < 1e-16:
            break
    return displacement


@hypothesis.settings(max_examples=6, deadline=None)
@hypothesis.given(axial_load=st.floats(500.0, 300e3))
def test_a_pure_axial_load_loads_every_roller_and_lamina_alike(axial_load):
    """Straight rollers under F_a: every roller carries F_a/Z on both washers, every lamina F_a/(Z n),
    at the approach that ISO/TS 16281's lamina law gives for it (1e-10); no radial force or moment."""
    support = _support()
    displacement = _under_axial_load(support, axial_load)
    contacts = _contacts(support, displacement)
    np.testing.assert_allclose(contacts.load, axial_load / ROLLERS, rtol=1e-10)
    np.testing.assert_allclose(contacts.lamina_load, axial_load / (ROLLERS * LAMINAE), rtol=1e-10)
    scale = float(roller_modulus(STRAIGHT)) / PALMGREN_STEEL_MODULUS
    per_contact = scale * float(roller_life.lamina_load(jnp.asarray(displacement[2] / 2), LENGTH / LAMINAE, LENGTH))
    np.testing.assert_allclose(per_contact, axial_load / (ROLLERS * LAMINAE), rtol=1e-10)
    force = np.asarray(_force(support, displacement))
    np.testing.assert_allclose(force[[0, 1, 3, 4]], 0.0, atol=1e-9 * axial_load)


def test_the_laminae_follow_the_tilted_washer_in_closed_form():
    """Crowned rollers at Δ = [3 µm, −2 µm, 12 µm, 2e-4, −1e-4]: lamina k of roller j carries
    q((δz − θ_t,j r_k − 2 z(y_k))/2), θ_t = θy cos ψ − θx sin ψ, r_k = d_m/2 + y_k (1e-12): the
    radial displacement changes nothing (flat washers)."""
    support = _support(CROWNED)
    displacement = jnp.array([3e-6, -2e-6, 12e-6, 2e-4, -1e-4])
    contacts = _contacts(support, displacement)
    psi = 2 * np.pi * np.arange(ROLLERS) / ROLLERS
    y = np.asarray(lamina_positions(CROWNED, LAMINAE)[0])
    tilt = -1e-4 * np.cos(psi) - 2e-4 * np.sin(psi)
    beyond = np.maximum(np.abs(y) - 4e-3, 0.0)
    drop = beyond**2 / (0.3 + np.sqrt(0.3**2 - beyond**2))
    total = 12e-6 - tilt[:, None] * (PITCH / 2 + y)[None, :] - 2 * drop[None, :]
    scale = float(roller_modulus(CROWNED)) / PALMGREN_STEEL_MODULUS
    expected = scale * np.asarray(roller_life.lamina_load(jnp.asarray(total / 2), LENGTH / LAMINAE, LENGTH))
    for column in (0, 1):
        np.testing.assert_allclose(contacts.lamina_load[:, column, :], expected, rtol=1e-12, atol=1e-12 * expected.max())
    moved = np.asarray(_force(support, displacement.at[:2].set(0.0)))
    np.testing.assert_allclose(np.asarray(_force(support, displacement)), moved, rtol=1e-14, atol=1e-12)


def test_its_tilt_stiffness_is_its_axial_stiffness_times_half_the_mean_square_radius():
    """Straight rollers under 50 kN: K_θθ = K_zz ⟨r_k²⟩/2 with ⟨r_k²⟩ = (d_m/2)² + ⟨y_k²⟩ (Σ cos² ψ_j
    = Z/2, every lamina alike; 1e-10); no coupling of δz and θ, zero rows in δx, δy."""
    support = _support()
    displacement = _under_axial_load(support, 50e3)
    stiffness = np.asarray(_stiffness(support, displacement))
    y = np.asarray(lamina_positions(STRAIGHT, LAMINAE)[0])
    mean_square = (PITCH / 2) ** 2 + np.mean(y**2)
    np.testing.assert_allclose(stiffness[3, 3], stiffness[2, 2] * mean_square / 2, rtol=1e-10)
    np.testing.assert_allclose(stiffness[4, 4], stiffness[2, 2] * mean_square / 2, rtol=1e-10)
    np.testing.assert_allclose(stiffness[:2], 0.0, atol=0.0)
    np.testing.assert_allclose(stiffness[2, 3:], 0.0, atol=1e-9 * stiffness[2, 2])


def test_its_rollers_slide_along_their_length_and_lose_mu_fa_omega_l_over_4():
    """v_s(y) = ω |y|/2 on either washer (pure rolling at the pitch radius), ω L_we/4 at the ends; the
    loss of straight rollers under F_a, μ = 0.05, 1000 r/min: μ F_a ω L_we/4 (n even: ⟨|y_k|⟩ = L/4
    exactly; 1e-10)."""
    support = _support()
    speed = 1000 * np.pi / 30
    speeds = np.asarray(crtb.sliding_speeds(STRAIGHT, PITCH, speed, LAMINAE))
    y = np.asarray(lamina_positions(STRAIGHT, LAMINAE)[0])
    np.testing.assert_allclose(speeds, speed * np.abs(y) / 2, rtol=1e-15)
    contacts = _contacts(support, _under_axial_load(support, 20e3))
    power = float(crtb.sliding_power(contacts, STRAIGHT, PITCH, speed, 0.05))
    np.testing.assert_allclose(power, 0.05 * 20e3 * speed * LENGTH / 4, rtol=1e-10)
    with pytest.raises(ValueError, match="friction_coefficient"):
        crtb.sliding_power(contacts, STRAIGHT, PITCH, speed, 1.5)


def test_its_stiffness_and_sliding_power_are_derivatives_that_match_central_differences():
    """The ring stiffness (the energy's Hessian) along a direction in δz and both tilts, and the sliding
    power in the roller length, against central differences (1e-6)."""
    support = _support(CROWNED)
    point = jnp.array([0.0, 0.0, 10e-6, 1e-4, -5e-5])
    direction = jnp.array([0.0, 0.0, 1e-6, 1e-5, 2e-5])
    assert_jvp_matches_central_difference(lambda d: support.ring_force(d, 0.0, None), point, direction, 1e-2, rtol=1e-6,
                                          atol=1e-8 * 1e5)
    stiffness = support.ring_stiffness(point, 0.0, None)
    np.testing.assert_allclose(stiffness @ direction, jax.jvp(lambda d: support.ring_force(d, 0.0, None), (point,),
                                                              (direction,))[1], rtol=1e-12, atol=1e-9)

    def power(length):
        bearing = cylindrical_roller_thrust_bearing(roller_diameter=DIAMETER, roller_length=length, rollers=ROLLERS)
        moved = cylindrical_roller_thrust_support(bearing, PITCH, 0.0, model=MODEL)
        return crtb.sliding_power(moved.contacts(jnp.array([0.0, 0.0, 8e-6, 1e-4, 0.0]), 0.0, None), bearing, PITCH,
                                  100.0, 0.05)

    assert_jvp_matches_central_difference(power, jnp.asarray(LENGTH), jnp.asarray(1e-3), 1e-3, rtol=1e-6)


def test_its_ratings_are_iso_281_iso_76_and_iso_ts_16281_at_90_degrees():
    """Table 10's α = 90° column against 293.16 γ^{2/9}, Lundberg–Palmgren's form at 90° (every row to
    its rounding, 0.05); C_a = f_c L_we^{7/9} Z^{3/4} D_we^{29/27} (b_m = 1.0) and C₀a = 220 Z L_we D_we
    [N, mm] written out; P_a = P₀a = F_a; under a pure axial load on straight rollers ISO/TS 16281's
    L10r = (C_a / (0.73 F_a))⁴ exactly (every lamina alike; 1e-10)."""
    from diffbearing.ratings import thrust_roller_ratings as ratings

    np.testing.assert_allclose(ratings.FC_AXIAL, 293.16 * ratings.FC_RATIO ** (2 / 9), atol=0.05 + 1e-9)
    support = _support()
    gamma = DIAMETER / PITCH
    factor = np.interp(gamma, ratings.FC_RATIO, ratings.FC_AXIAL)
    rating = float(support.dynamic_load_rating())
    np.testing.assert_allclose(rating, factor * 11 ** (7 / 9) * ROLLERS ** 0.75 * 11 ** (29 / 27), rtol=1e-12)
    np.testing.assert_allclose(support.static_load_rating(), 220 * ROLLERS * 11 * 11, rtol=1e-12)
    for load in (support.equivalent_dynamic_load, support.equivalent_static_load):
        np.testing.assert_allclose(load(jnp.array([0.0, 0.0, -7e3])), 7e3, rtol=1e-15)
    assert np.isnan(float(ratings.thrust_roller_factor(0.35, 1.0)))
    contacts = _contacts(support, _under_axial_load(support, 40e3))
    life = float(reference_life.contact_reference_life(contacts, support.contact_ratings(rating, contacts)))
    np.testing.assert_allclose(life, (rating / (0.73 * 40e3)) ** 4, rtol=1e-10)


@hypothesis.settings(max_examples=10, deadline=None)
@hypothesis.given(axial=st.floats(-5e-6, 30e-6), tilt_x=st.floats(-5e-4, 5e-4), tilt_y=st.floats(-5e-4, 5e-4),
                  radial=st.floats(-50e-6, 50e-6))
def test_random_states_give_finite_loads_and_the_energys_gradient(axial, tilt_x, tilt_y, radial):
    """Random axial approaches (some or all rollers open), tilts and radial shifts: the ring force is
    finite, with no radial component, equal to the static energy's gradient (the interface's start),
    and its stiffness finite."""
    support = _support(CROWNED)
    displacement = jnp.array([radial, -radial, axial, tilt_x, tilt_y])
    force = np.asarray(_force(support, displacement))
    gradient = np.asarray(jax.grad(support.static_energy)(displacement, None))
    assert np.all(np.isfinite(force)) and np.all(force[:2] == 0.0) and force[2] >= 0.0
    np.testing.assert_allclose(force, gradient, rtol=1e-12, atol=1e-12 * (1 + np.abs(force).max()))
    assert np.all(np.isfinite(np.asarray(_stiffness(support, displacement))))


@pytest.mark.parametrize("keys, named", [
    (dict(pitch_diameter=10e-3), "bearing.pitch_diameter must exceed the roller length"),
    (dict(rollers=40), "bearing.rollers: 40 rollers"),
    (dict(rollers=4, pitch_diameter=30e-3), "bearing.roller_diameter must be ≥ 0.0003 m and ≤ 0.009 m"),
])
def test_bad_geometry_names_its_key(keys, named):
    with pytest.raises(ValueError, match=named):
        cylindrical_roller_thrust_support(STRAIGHT if "rollers" not in keys else cylindrical_roller_thrust_bearing(
            roller_diameter=DIAMETER, roller_length=LENGTH, rollers=keys["rollers"]), keys.get("pitch_diameter", PITCH),
            0.0)


@pytest.mark.parametrize("change, named", [
    (('designation = "81212"', 'designation = "81212"\nbore = "70 mm"'), "bearings[2]: bore: the rollers' inner ends lie at"),
    (('designation = "81212"', 'designation = "81212"\nouter_diameter = "85 mm"'),
     "bearings[2]: outer_diameter: the rollers' outer ends"),
    (('rollers = 16', 'rollers = 16\nradial_clearance = "20 um"'), "bearings[2]: key 'radial_clearance' is not read"),
    (('rollers = 16', 'rollers = 30'), "bearings[2]: rollers: 30 rollers of 11 mm do not fit"),
])
def test_a_bad_thrust_roller_entry_exits_2_naming_its_key(capsys, tmp_path, change, named):
    """The example with one bad key in its thrust bearing's entry: exit 2, one line naming it."""
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.read_text().replace(*change))
    assert_exits_2_naming(capsys, ["run", str(path)], named)


@pytest.mark.slow
def test_the_example_carries_its_thrust_on_the_thrust_bearing():
    """The thrust_roller_shaft example: converged, no problems; the cylindrical roller bearings carry no
    axial load, the thrust bearing all 30 kN and no radial load, the radial bearings the gear's
    4 kN half each (the layout symmetric; 1e-9); every thrust roller alike, 30 kN / 16. The thrust
    bearing's Palmgren moment is HR 1's 811 row written out (f₀ 3 in oil, f₁ 0.0015, M₁ = f₁ F_a d_m),
    1e-12."""
    model = build_model(load_scene(str(SCENE)))
    result = run_model(model, progress=False)
    assert bool(result.values["shaft.converged"]) and not any(result.problems), result.problems
    forces = np.asarray(result.values["bearings.force"])
    np.testing.assert_allclose(forces[:2, 2], 0.0, atol=1e-9)
    np.testing.assert_allclose(forces[2, :2], 0.0, atol=1e-9)
    np.testing.assert_allclose(forces[2, 2], 30e3, rtol=1e-9)
    np.testing.assert_allclose(forces[:2, 0], 2000.0, rtol=1e-9)
    np.testing.assert_allclose(result.values["bearings.elements.inner_load"][2, :ROLLERS], 30e3 / ROLLERS, rtol=1e-9)
    lubricant = model.inputs["lubricant"]
    thrust = palmgren_moment(3.0, 0.0015, 30e3, lubricant.viscosity / lubricant.density, 300.0, 77.5e-3)
    assert float(result.values["bearings.friction.torque"][2]) == pytest.approx(thrust, rel=1e-12)
