"""The needle roller bearing through the bearing interface: the laminae of long rollers under tilt
against their closed form (where one end of a roller lifts off), its ISO 281 rating with the
type's b_m (machined rings, drawn cup) and its ISO 76 rating against the standards' formulas, the
crowning design of the whole-bearing notebook on it (the life's gradient in the crown against
central differences), its stiffness as the force's derivative, the 2′ tilt past which a shaft
warns, random geometries, and its scene entry's checks."""

import importlib.resources

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import (
    RollerModel,
    RollerOperating,
    build_model,
    load_scene,
    needle_roller_bearing,
    needle_roller_raceways,
    needle_roller_support,
    roller_profile,
    roller_results,
    run_model,
    solve_roller_equilibrium,
)
from diffbearing.app.adapters.systems.shaft import end_lamina_share, misalignment_warnings
from diffbearing.bearings.interface import ContactLoads
from diffbearing.bearings.roller import roller_equilibrium
from diffbearing.bearings.roller.needle_roller import PERMISSIBLE_MISALIGNMENT
from diffbearing.bearings.roller.roller_contact import PALMGREN_STEEL_MODULUS
from diffbearing.bearings.roller.roller_geometry import roller_modulus
from diffbearing.ratings import roller_life

from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference, palmgren_moment

SCENE = importlib.resources.files("diffbearing.scenes") / "needle_roller_shaft.toml"

# The needle_roller_shaft example's bearing (RNA 4905 size, illustrative internals): 26 needles of
# 3 × 13 mm on d_m = 33 mm, 15 µm diametral clearance.
DIAMETER, LENGTH, ROLLERS, PITCH, CLEARANCE = 3e-3, 13e-3, 26, 33e-3, 15e-6
LAMINAE = 20
STRAIGHT = needle_roller_bearing(roller_diameter=DIAMETER, roller_length=LENGTH, rollers=ROLLERS)
RACEWAYS = needle_roller_raceways(STRAIGHT, pitch_diameter=PITCH, diametral_clearance=CLEARANCE)
MODEL = RollerModel(laminae=LAMINAE)


@jax.jit
def _contacts(support, displacement):
    return support.contacts(displacement, 0.0, support.constants())


def _lamina_centres():
    return np.asarray(roller_equilibrium.lamina_positions(STRAIGHT, LAMINAE)[0])


@pytest.mark.parametrize("tilt", [0.0, 2e-4, 1.2e-3])
def test_the_laminae_of_a_tilted_needle_follow_the_gap_in_closed_form(tilt):
    """Δ = [δ, 0, 0, 0, θ] on straight needles at standstill: roller j at ψ_j has the total approach
    δ_jk = δ cos ψ_j − θ cos ψ_j y_k − P_d/2 at lamina k, shared equally by its two contacts, each
    lamina carrying ISO/TS 16281's q(δ_jk/2) scaled by E'/E'_steel (1e-12). At θ = 1.2 mrad (4′) the +y end of the most
    loaded roller is open — past θ_lift = 2(δ − P_d/2)/(L − L/n) for the lamina centres — while
    its −y end carries more than the aligned roller: the edge load of a long tilted roller."""
    support = needle_roller_support(STRAIGHT, RACEWAYS, 0.0, model=MODEL)
    approach = 20e-6
    contacts = _contacts(support, jnp.array([approach, 0.0, 0.0, 0.0, tilt]))
    psi = 2 * np.pi * np.arange(ROLLERS) / ROLLERS
    y = _lamina_centres()
    total = approach * np.cos(psi)[:, None] - tilt * np.cos(psi)[:, None] * y[None, :] - 0.5 * CLEARANCE
    scale = float(roller_modulus(STRAIGHT)) / PALMGREN_STEEL_MODULUS
    expected = scale * np.asarray(roller_life.lamina_load(jnp.asarray(total / 2), LENGTH / LAMINAE, LENGTH))
    for column in (0, 1):
        np.testing.assert_allclose(contacts.lamina_load[:, column, :], expected, rtol=1e-12, atol=1e-12 * expected.max())
    lift = 2 * (approach - 0.5 * CLEARANCE) / (LENGTH - LENGTH / LAMINAE)
    most = np.asarray(contacts.lamina_load[0, 0])
    assert (most[-1] == 0.0) == (tilt > lift), (tilt, lift)
    if tilt > lift:
        aligned = np.asarray(_contacts(support, jnp.array([approach, 0.0, 0.0, 0.0, 0.0])).lamina_load[0, 0])
        assert most[0] > 1.5 * aligned[0]


def test_its_ratings_are_iso_281_and_iso_76_with_its_own_factors():
    """C_r = b_m f_c L_we^{7/9} Z^{3/4} D_we^{29/27} [N, mm] with b_m = 1.1 (machined rings) and 1.0
    (drawn cup) of ISO 281 Table 1 and f_c of ISO/TR 1281-1's closed form at γ = D/d_m (its table
    rounds to 0.1: 1e-3); C₀r = 44 (1 − γ) Z L_we D_we (ISO 76, radial roller bearings, exact); the
    radial roller bearing's P = F_r."""
    gamma = DIAMETER / PITCH
    fc = (207.9 * 0.83 * gamma ** (2 / 9) * (1 - gamma) ** (29 / 27) * (1 + gamma) ** -0.25
          * (1 + (1.04 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)) ** 4.5) ** (-2 / 9))
    closed_form = fc * (LENGTH * 1e3) ** (7 / 9) * ROLLERS ** 0.75 * (DIAMETER * 1e3) ** (29 / 27)
    for ring, factor in (("machined", 1.1), ("drawn_cup", 1.0)):
        support = needle_roller_support(STRAIGHT, RACEWAYS, 0.0, outer_ring=ring)
        np.testing.assert_allclose(support.dynamic_load_rating(), factor * closed_form, rtol=1e-3)
        np.testing.assert_allclose(support.static_load_rating(), 44 * (1 - gamma) * ROLLERS * 13 * 3, rtol=1e-12)
        np.testing.assert_allclose(support.equivalent_dynamic_load(jnp.array([3e3, 4e3, 0.0])), 5e3, rtol=1e-15)
    drawn = needle_roller_support(STRAIGHT, RACEWAYS, 0.0, outer_ring="drawn_cup").dynamic_load_rating()
    machined = needle_roller_support(STRAIGHT, RACEWAYS, 0.0).dynamic_load_rating()
    np.testing.assert_allclose(drawn / machined, 1.0 / 1.1, rtol=1e-15)


def _crowned(crown_radius):
    return needle_roller_bearing(roller_diameter=DIAMETER, roller_length=LENGTH, rollers=ROLLERS,
                                 profile=roller_profile("circular", length=LENGTH, flat_length=9e-3,
                                                        crown_radius=crown_radius))


def _life_at_tilt(crown_radius, tilt):
    """ISO/TS 16281 L10r [10⁶ rev] of the bearing under F_r = 3 kN at an imposed tilt θy [rad], as the
    crowning notebook computes it."""
    bearing = _crowned(crown_radius)
    operating = RollerOperating(force=jnp.array([3e3, 0.0, 0.0]), moment=jnp.zeros(2),
                                misalignment=jnp.stack([0.0, tilt]))
    solution = solve_roller_equilibrium(bearing, RACEWAYS, operating, MODEL)
    rollers = roller_results(solution.displacement, bearing, RACEWAYS, operating, MODEL)
    width = LENGTH / LAMINAE
    rating = roller_life.roller_dynamic_load_rating(ROLLERS, DIAMETER, LENGTH, 0.0, PITCH)
    return roller_life.roller_reference_rating_life(rating, ROLLERS, DIAMETER, 0.0, PITCH, rollers.inner_lamina_load * width,
                                                    rollers.outer_lamina_load * width)


def test_the_crowning_design_of_the_notebook_runs_on_it():
    """The whole-bearing crowning design (notebooks/roller_bearing_crowning_design.ipynb: equilibrium,
    lamina loads, ISO/TS 16281 L10r) on the needle bearing, unchanged: at 2′ of tilt a crown (flat
    9 mm, R = 1.5 m) keeps more life than straight needles, whose loaded end takes the tilt; the
    gradient of ln L10r in the crown radius at 2′ against a central difference (1e-6)."""
    tilt = PERMISSIBLE_MISALIGNMENT
    crowned = float(_life_at_tilt(1.5, tilt))
    straight_bearing = needle_roller_support(STRAIGHT, RACEWAYS, 0.0)
    assert straight_bearing.bearing.profile.kind == "straight"
    huge = float(_life_at_tilt(1e6, tilt))  # R = 1000 km: the drop at the ends 0.1 nm, straight needles
    assert crowned > 1.2 * huge, (crowned, huge)
    assert_jvp_matches_central_difference(lambda r: jnp.log(_life_at_tilt(r, tilt)), jnp.asarray(1.5), jnp.asarray(1.0),
                                          1e-3, rtol=1e-6)


def test_its_stiffness_is_the_ring_forces_derivative():
    """dF/dΔ of the crowned needle bearing at a tilted, partly open state against central differences
    of its ring force along a direction in all five components (1e-6 of the largest: the laminae
    that open and close give the differences' truncation error its kinks)."""
    support = needle_roller_support(_crowned(1.5), RACEWAYS, 0.0, model=MODEL)
    point = jnp.array([18e-6, -4e-6, 0.0, 1e-4, 3e-4])
    direction = jnp.array([1e-6, 1e-6, 0.0, 1e-5, -1e-5])
    assert_jvp_matches_central_difference(lambda d: support.ring_force(d, 0.0, None), point, direction, 1e-2, rtol=1e-6,
                                          atol=1e-8 * 1.2e3)
    stiffness = support.ring_stiffness(point, 0.0, None)
    np.testing.assert_allclose(stiffness @ direction, jax.jvp(lambda d: support.ring_force(d, 0.0, None), (point,),
                                                              (direction,))[1], rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(stiffness[2], 0.0, atol=0.0)  # no ribs: no axial force, whatever the state


def test_past_two_minutes_of_tilt_a_shaft_warns_of_the_needles_and_not_of_a_ball_bearing():
    """1 mrad (3.4′) on a needle bearing (limit 2′) and on a ball bearing (10′): one warning, the needle's."""
    needle = needle_roller_support(STRAIGHT, RACEWAYS, 0.0)
    limits = [needle.permissible_misalignment(), np.radians(10 / 60)]
    warnings = misalignment_warnings(np.array([[0, 0, 0, 0, 1e-3]] * 2), limits)
    assert len(warnings) == 1 and warnings[0].startswith("bearing 0:") and "2′" in warnings[0], warnings


def test_the_end_lamina_share_flags_a_contact_that_reaches_the_rollers_end():
    """`end_lamina_share`: straight needles, aligned or tilted, load their end laminae as much as any
    (1, exactly); crowned ones (flat 9 mm, Rc = 0.5 m: 2.8 µm of drop at the end laminae' centres)
    at a 10 µm radial approach in 15 µm of clearance leave them free (0) while the middle carries
    load; point contacts give 0."""
    approach = jnp.array([10e-6, 0.0, 0.0, 0.0, 0.0])
    for tilt in (0.0, 5e-4):
        straight = _contacts(needle_roller_support(STRAIGHT, RACEWAYS, 0.0, model=MODEL), approach.at[4].set(tilt))
        np.testing.assert_allclose(end_lamina_share(straight), 1.0, rtol=1e-12)
    crowned = _contacts(needle_roller_support(_crowned(0.5), RACEWAYS, 0.0, model=MODEL), approach)
    assert float(end_lamina_share(crowned)) == 0.0 and float(jnp.max(crowned.lamina_load)) > 0.0
    points = ContactLoads(crowned.azimuth, crowned.load, crowned.load[..., None], crowned.max_pressure,
                         jnp.zeros_like(crowned.load), crowned.approach, crowned.raceways, "point")
    assert float(end_lamina_share(points)) == 0.0


@hypothesis.settings(max_examples=12, deadline=None)
@hypothesis.given(diameter=st.floats(1.5e-3, 6e-3), slenderness=st.floats(2.55, 10.0), rollers=st.integers(8, 60),
                  room=st.floats(1.05, 2.0), radial=st.floats(-5e-6, 40e-6), tilt=st.floats(-1e-3, 1e-3))
def test_random_needle_bearings_give_finite_loads_or_name_their_key(diameter, slenderness, rollers, room, radial, tilt):
    """Random needles (D_w 1.5–6 mm, L/D 2.55–10, Z 8–60) on a pitch circle `room` × the smallest
    that holds them: the builders accept them, and at random states (open rollers, tilts) the ring
    force is finite with no axial component; the same rollers shorter than 2.5 D_w, or on a circle
    too small, are refused naming their key."""
    length = slenderness * diameter
    pitch = room * diameter / np.sin(np.pi / rollers)
    bearing = needle_roller_bearing(roller_diameter=diameter, roller_length=length, rollers=rollers)
    raceways = needle_roller_raceways(bearing, pitch_diameter=pitch, diametral_clearance=5e-6)
    support = needle_roller_support(bearing, raceways, 0.0, model=RollerModel(laminae=10))
    force = np.asarray(support.ring_force(jnp.array([radial, 0.0, 0.0, 0.0, tilt]), 0.0, None))
    assert np.all(np.isfinite(force)) and force[2] == 0.0
    if radial > 0.0 and tilt == 0.0:
        assert force[0] > 0.0
    with pytest.raises(ValueError, match="bearing.roller_length"):
        needle_roller_bearing(roller_diameter=diameter, roller_length=2.5 * diameter, rollers=rollers)
    with pytest.raises(ValueError, match="bearing.rollers"):
        needle_roller_raceways(bearing, pitch_diameter=0.98 * diameter / np.sin(np.pi / rollers))


def test_an_axial_offset_is_refused():
    with pytest.raises(ValueError, match="offset"):
        needle_roller_support(STRAIGHT, RACEWAYS, 0.0, 1e-6)


@pytest.mark.parametrize("change, named", [
    (('roller_diameter = "3 mm"', 'roller_diameter = "5.5 mm"'), "bearings[1]: roller_length: a needle roller is longer"),
    (('bore = "30 mm"', 'bore = "31 mm"'), "bearings[1]: bore: without an inner ring"),
    (('inner_ring = false', 'inner_ring = true'), "bearings[1]: bore: the inner ring's bore lies below"),
    (('outer_ring = "machined"', 'outer_ring = "drawn"'), "outer_ring"),
    (('rollers = 26', 'rollers = 26\ncontact_angle = "10 deg"'), "bearings[1]: key 'contact_angle' is not read"),
    (('rollers = 26', 'rollers = 36'), "bearings[1]: rollers: 36 rollers of 3 mm do not fit"),
    (('position = "60 mm"', 'position = "60 mm"\noffset = "5 um"'), "offset"),
    (('friction = "palmgren"', 'friction = "skf"'), "bearings[1] (needle_roller) is not covered by the 'skf' friction model"),
])
def test_a_bad_needle_entry_exits_2_naming_its_key(capsys, tmp_path, change, named):
    """The example with one bad key in its needle bearing's entry: exit 2, one line naming it."""
    path = tmp_path / "bad.toml"
    path.write_text(SCENE.read_text().replace(*change))
    assert_exits_2_naming(capsys, ["run", str(path)], named)


@pytest.mark.slow
def test_a_shallow_crown_warns_of_edge_load_at_the_needles_ends():
    """The example with a 5 m crown (0.4 µm of drop at the ends, less than the needles' approach):
    one warning, bearing 1's, that its rollers' end laminae carry load; none with the example's
    0.5 m crown (`test_the_example_carries_the_axial_load_on_its_ball_bearing`)."""
    scene = load_scene(str(SCENE))
    scene.values["bearings"][1]["profile.crown_radius"] = 5.0
    result = run_model(build_model(scene), progress=False)
    errors, warnings = result.problems
    assert not errors and len(warnings) == 1 and warnings[0].startswith("bearing 1: a roller's end lamina"), warnings
    assert 0.5 < float(result.values["bearings.end_lamina_share"][1]) <= 1.0


@pytest.mark.slow
def test_the_example_carries_the_axial_load_on_its_ball_bearing():
    """The needle_roller_shaft example: converged, no problems; the needle bearing carries no axial
    load, the ball bearing all 0.8 kN; the radial loads balance the gear's 4 kN (1e-9). The needle
    bearing's Palmgren moment is HR 1's NA49 row written out (f₀ 5.5 in oil, f₁ 0.0005, M₁ = f₁ F_r
    d_m), 1e-12."""
    model = build_model(load_scene(str(SCENE)))
    result = run_model(model, progress=False)
    assert bool(result.values["shaft.converged"]) and not any(result.problems)
    forces = np.asarray(result.values["bearings.force"])
    np.testing.assert_allclose(forces[1, 2], 0.0, atol=1e-9)
    np.testing.assert_allclose(forces[0, 2], 800.0, rtol=1e-9)
    np.testing.assert_allclose(forces[:, 0].sum(), 4000.0, rtol=1e-9)
    lubricant = model.inputs["lubricant"]
    needle = palmgren_moment(5.5, 0.0005, forces[1, 0], lubricant.viscosity / lubricant.density, 1500.0, 33e-3)
    assert float(result.values["bearings.friction.torque"][1]) == pytest.approx(needle, rel=1e-12)
