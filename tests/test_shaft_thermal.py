"""The bearings on a shaft in the thermal–mechanical fixed point (`diffbearing.thermal.shaft_thermal`)
and mounted on it (`effects.mounting` on a shaft): a support's clearance moved by a mounting's
change, the seats' paths against the single bearing's and closed forms, the network of several
seats balanced, the packaged spindle shaft holding one state (its clearances, loads and heat), the
fixed point's identities and derivatives against central differences; bad inputs exit 2 naming
their key."""

import dataclasses

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.bearings.ball.ball_support import BallSupport
from diffbearing.bearings.roller.roller_equilibrium import roller_raceways
from diffbearing.bearings.roller.roller_geometry import roller_bearing
from diffbearing.bearings.roller.roller_profile import roller_profile
from diffbearing.bearings.roller.roller_support import RollerSupport
from diffbearing.film.viscosity_temperature import walther_viscosity
from diffbearing.params import BEARING_STEEL, ISO_VG_VISCOSITY_100, radial_clearance
from diffbearing.ratings.life_modification import reference_viscosity
from diffbearing.systems import bearing_fits
from diffbearing.systems.bearing_set import bearing_set, preload_offset
from diffbearing.systems.flexible_shaft import shaft_mesh
from diffbearing.systems.operating_clearance import SEAT_MATERIALS, Mounting, mounted_clearance_change, operating_clearance_change
from diffbearing.systems.shaft_beam import ShaftSections
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, solve_shaft
from diffbearing.thermal import bearing_thermal as bt
from diffbearing.thermal.mounting_paths import CONDUCTIVITIES, Cooling, MountingGeometry, mounting_paths, shaft_paths
from diffbearing.thermal.shaft_thermal import MountedShaft, shaft_factors
from diffbearing.thermal.thermal_network import boundary_heat_flows, node_temperatures

from .helpers import SPINDLE_7014C, assert_exits_2_naming, assert_jvp_matches_central_difference, example_scene

AMBIENT = 293.15
BEARING = SPINDLE_7014C
MOUNTING = Mounting(shaft_interference=5e-6, housing_interference=-2e-6, reference_temperature=AMBIENT)
OIL = bt.WaltherLine(32e-6, 5.4e-6)  # ISO VG 32
SEAT = MountingGeometry(bore=70e-3, outer_diameter=110e-3, width=20e-3, inner_raceway_diameter=90e-3 - 11.112e-3,
                        outer_raceway_diameter=90e-3 + 11.112e-3, shaft_bore=0.0, shaft_length=0.15,
                        housing_outer_diameter=0.18, housing_length=0.04, ring_conductivity=CONDUCTIVITIES["bearing_steel"],
                        shaft_conductivity=CONDUCTIVITIES["steel"], housing_conductivity=CONDUCTIVITIES["cast_iron"])
SPEED = 6000.0 * np.pi / 30


def _cooling(speed=SPEED):
    return Cooling(AMBIENT, AMBIENT, 0.0, 500.0, speed, OIL)


def _cylindrical(clearance=20e-6):
    length = 11e-3
    profile = roller_profile("circular", length=length, flat_length=9e-3, crown_radius=50e-3)
    bearing = roller_bearing(kind="cylindrical_roller", length=length, diameter=11e-3, profile=profile, roller_count=20)
    return RollerSupport(bearing, roller_raceways(bearing, pitch_diameter=90e-3, diametral_clearance=clearance), 0.3)


def test_a_support_moves_its_clearance_by_the_change():
    """`with_clearance_change(δ)`: the ring section's clearance is the old one plus δ (1e-18 m), a ball
    bearing's free contact angle kept; a mounting's change through the support is
    `operating_clearance_change` of its raceways (exact); a tapered roller bearing takes none."""
    change = -7.3e-6
    for support in (BallSupport(BEARING, 0.0), _cylindrical()):
        moved = support.with_clearance_change(change)
        assert float(moved.ring_section().clearance) == pytest.approx(float(support.ring_section().clearance) + change,
                                                                     abs=1e-18)
    ball = BallSupport(BEARING, 0.0).with_clearance_change(change)
    assert float(ball.bearing.free_contact_angle) == float(BEARING.free_contact_angle)
    assert float(radial_clearance(ball.bearing)) == pytest.approx(float(radial_clearance(BEARING)) + change, abs=1e-18)
    warm = dataclasses.replace(MOUNTING, inner_ring_temperature=AMBIENT + 30.0, shaft_temperature=AMBIENT + 25.0)
    got = mounted_clearance_change(BallSupport(BEARING, 0.0), warm, 70e-3, 110e-3, SPEED).change
    want = operating_clearance_change(warm, 70e-3, 90e-3 - 11.112e-3, 90e-3 + 11.112e-3, 110e-3, 11.112e-3, BEARING_STEEL,
                                      SPEED).change
    assert float(got) == float(want)
    profile = roller_profile("circular", length=11e-3, flat_length=9e-3, crown_radius=50e-3)
    tapered = roller_bearing(kind="tapered_roller", length=11e-3, small_diameter=10e-3, large_diameter=12e-3,
                             cone_half_angle=np.radians(2.0), profile=profile, roller_count=20)
    cone = RollerSupport(tapered, roller_raceways(tapered, pitch_diameter=90e-3, cup_angle=np.radians(15.0)), 0.0)
    assert cone.ring_section() is None
    with pytest.raises(NotImplementedError):
        cone.with_clearance_change(change)


def test_one_seat_has_the_single_bearing_paths_and_two_join_by_conduction():
    """`shaft_paths` of one seat is `mounting_paths` (exact); of two seats 300 mm apart: each seat one
    shaft end fin (half the single's), the housing's outside less one end face, and the shaft and the
    housing wall joined by k A / L (1e-14)."""
    single = mounting_paths(SEAT, _cooling())
    one = shaft_paths((SEAT,), [0.0], _cooling())
    for name in bt.PATH_NAMES:
        np.testing.assert_array_equal(np.ravel(getattr(one, name)), np.ravel(getattr(single, name)), err_msg=name)
    two = shaft_paths((SEAT, SEAT), [0.25, -0.05], _cooling())
    assert two.axial_pairs == ((1, 0),)
    for name in ("inner_ring_shaft", "outer_ring_housing", "inner_ring_lubricant", "outer_ring_lubricant", "oil_flow"):
        np.testing.assert_array_equal(getattr(two, name), [float(getattr(single, name))] * 2)
    np.testing.assert_allclose(two.shaft_ambient, [0.5 * float(single.shaft_ambient)] * 2, rtol=1e-14)
    face = 500.0 * 0.25 * np.pi * (0.18 ** 2 - 0.11 ** 2)
    np.testing.assert_allclose(two.housing_ambient, [float(single.housing_ambient) - face] * 2, rtol=1e-14)
    assert float(two.shaft_axial[0]) == pytest.approx(42.3 * 0.25 * np.pi * 0.07 ** 2 / 0.3, rel=1e-14)
    assert float(two.housing_axial[0]) == pytest.approx(50.0 * 0.25 * np.pi * (0.18 ** 2 - 0.11 ** 2) / 0.3, rel=1e-14)


def test_a_network_of_seats_carries_one_seats_heat_through_the_other():
    """Heat at seat 0 only: the heat leaving is the heat generated (1e-12), seat 1 warms only through
    the shaft and the housing between them; with those two conductances 0 it stays at the ambient
    (1e-12 K)."""
    paths = shaft_paths((SEAT, SEAT), [0.0, 0.3], _cooling())
    sources = jnp.zeros(12).at[0].set(60.0).at[1].set(60.0).at[2].set(40.0)
    network = bt.bearing_network(paths)
    assert network.names[5] == "inner_ring_1" and network.names[10:] == ("ambient", "oil_inlet")
    temperatures = node_temperatures(network, sources)
    assert float(jnp.sum(boundary_heat_flows(network, temperatures, sources))) == pytest.approx(160.0, rel=1e-12)
    assert float(jnp.min(temperatures[5:10])) > AMBIENT
    cut = dataclasses.replace(paths, shaft_axial=jnp.zeros(1), housing_axial=jnp.zeros(1))
    np.testing.assert_allclose(node_temperatures(bt.bearing_network(cut), sources)[5:10], AMBIENT, atol=1e-12)


OFFSET = float(preload_offset(BEARING, 500.0))


def _spindle(offset=OFFSET, speed=SPEED):
    """The front pair (40 mm apart) and a cylindrical roller bearing 300 mm behind, a cutting force at
    the nose, as `MountedShaft`, with its paths."""
    pair = bearing_set(BEARING, "back_to_back", spacing=0.04, offset=offset)  # at z = ∓20 mm
    supports = (*pair, _cylindrical(30e-6))  # at z = 300 mm
    loads = ShaftLoads(jnp.array([-0.12]), jnp.array([[1.5e3, 0.0, 1e3]]), jnp.zeros((1, 2)))
    shaft = MountedShaft(supports, (MOUNTING,) * 3, jnp.full(3, 70e-3), jnp.full(3, 110e-3),
                         shaft_factors(supports, [1.0] * 3), loads, speed, OIL)
    seats = tuple(dataclasses.replace(SEAT, inner_raceway_diameter=s.ring_section().inner_raceway_diameter,
                                      outer_raceway_diameter=s.ring_section().outer_raceway_diameter)
                  for s in supports)
    return shaft, shaft_paths(seats, [-0.02, 0.02, 0.3], _cooling(speed))


solve = jax.jit(bt.solve_thermal)


@pytest.mark.slow
def test_the_warm_shaft_is_its_networks_and_its_mountings_state():
    """A spindle (front pair, rear cylindrical roller bearing) at 6000 r/min: converged; the heat
    leaving is the friction heat (1e-10); the temperatures are the network's for their heat (1e-8 K);
    each bearing's clearance is its cold one changed by `operating_clearance_change` at its seat's
    temperatures (1e-15 m); the loads are the shaft's equilibrium at those clearances and the offsets
    the shaft's axial growth against the housing's leaves, solved apart (1e-8); the pair's preload
    rises above the matched 500 N; the seats' temperatures differ."""
    shaft, paths = _spindle()
    state = solve(shaft, paths)
    assert bool(state.converged)
    assert float(jnp.sum(state.boundary_heat)) == pytest.approx(float(jnp.sum(state.lubricant_power + state.ring_power)),
                                                                rel=1e-10)
    sources = jax.jit(lambda s, t: s.heat(t).sources)(shaft, state.temperatures)
    np.testing.assert_allclose(node_temperatures(bt.bearing_network(paths), sources)[:15], state.temperatures[:15],
                               atol=1e-8)
    warm = []
    for seat, support in enumerate(shaft.supports):
        rings = support.ring_section()
        change = operating_clearance_change(bt.mounted_at(MOUNTING, state.temperatures, seat), 70e-3,
                                            rings.inner_raceway_diameter, rings.outer_raceway_diameter, 110e-3,
                                            rings.element_diameter, rings.material, SPEED).change
        assert float(state.clearance[seat]) == pytest.approx(float(rings.clearance + change), abs=1e-15)
        warm.append(support.with_clearance_change(change))
    # the shaft's growth against the housing's along z = −20, 20, 300 mm (the trapezoid rule over each
    # span, both of steel), about the mean; the two angular contact bearings' offsets move by o_k u_k,
    # the floating cylindrical roller bearing's rings slide
    shaft_side, housing_side = state.temperatures[jnp.array([3, 8, 13])], state.temperatures[jnp.array([4, 9, 14])]
    spans = jnp.array([0.04, 0.28])

    def grown(side):
        return jnp.concatenate([jnp.zeros(1), jnp.cumsum(MOUNTING.shaft_expansion * spans
                                                         * (0.5 * (side[1:] + side[:-1]) - AMBIENT))])

    growth = grown(shaft_side) - grown(housing_side)
    growth = growth - jnp.mean(growth)
    warm = [dataclasses.replace(support, offset=support.offset + support.orientation * growth[k]) if k < 2 else support
            for k, support in enumerate(warm)]
    apart = solve_shaft(Shaft(tuple(warm), shaft.loads, SPEED))
    for got, want in zip(state.mechanics.bearing_forces, apart.bearing_forces):
        np.testing.assert_allclose(got, want, rtol=1e-8, atol=1e-6)
    assert min(float(state.mechanics.bearing_forces[number][2]) for number in range(2)) > 500.0  # each its own frame
    inner = state.temperatures[jnp.array([0, 5, 10])]
    assert float(jnp.max(inner) - jnp.min(inner)) > 5.0


@pytest.mark.slow
def test_the_warm_shaft_is_differentiable():
    """∂(front inner ring temperature, rear bearing temperature, front bearing's axial load)/∂(preload
    offset, speed) through the fixed point against central differences (1e-5)."""
    def outputs(x):
        shaft, paths = _spindle(x[0] * 1e-6, x[1] * np.pi / 30)
        state = bt.solve_thermal(shaft, paths)
        return jnp.stack([state.temperatures[0], state.temperatures[10], state.mechanics.bearing_forces[0][2] / 1e3])

    point = jnp.array([OFFSET * 1e6, 6000.0])
    for direction, step in ((jnp.array([1.0, 0.0]), 0.05), (jnp.array([0.0, 1.0]), 20.0)):
        assert_jvp_matches_central_difference(outputs, point, direction, step, rtol=1e-5)


@pytest.mark.slow
def test_the_warm_flexible_shaft_is_differentiable():
    """The spindle on a Timoshenko beam (70 mm at the pair, a 50/20 mm tube to the rear bearing):
    ∂(front inner ring temperature, rear bearing's radial load, front bearing's axial load)/∂(the
    tube's outside diameter, speed) through the fixed point and the beam's condensed equilibrium
    against central differences (1e-5). A stiffer tube moves the loads between the bearings, and
    with them the heat."""
    rigid, paths = _spindle()
    mesh = shaft_mesh(_spindle_sections(0.05), [s.position for s in rigid.supports], rigid.loads.positions)

    def outputs(x):
        shaft, paths = _spindle(speed=x[1] * np.pi / 30)
        flexible = dataclasses.replace(shaft, sections=_spindle_sections(x[0] * 1e-3), mesh=mesh)
        state = bt.solve_thermal(flexible, paths)
        forces = state.mechanics.bearing_forces
        return jnp.stack([state.temperatures[0], jnp.hypot(forces[2][0], forces[2][1]) / 1e3, forces[0][2] / 1e3,
                          jnp.where(state.converged, 0.0, jnp.nan)])

    point = jnp.array([50.0, 6000.0])
    for direction, step in ((jnp.array([1.0, 0.0]), 1e-2), (jnp.array([0.0, 1.0]), 20.0)):
        assert_jvp_matches_central_difference(outputs, point, direction, step, rtol=1e-5)


def _spindle_sections(tube_diameter):
    """70 mm solid from the nose to behind the pair, a tube of `tube_diameter` [m] with a 20 mm bore
    to beyond the rear bearing."""
    return ShaftSections([-0.15, 0.04], [0.04, 0.35], jnp.stack([jnp.asarray(0.07), jnp.asarray(tube_diameter)]),
                         [0.0, 0.02], SEAT_MATERIALS["steel"][0])


@pytest.mark.slow
def test_a_mounted_shaft_is_differentiable():
    """`effects.mounting` on a shaft (each bearing's clearance changed by `mounted_clearance_change`
    at its fits and ring temperatures, then the shaft's equilibrium): ∂(each clearance change, the
    front bearing's axial load, the rear bearing's radial load)/∂(shaft interference, inner rings'
    temperature) against central differences (1e-6)."""
    pair = bearing_set(BEARING, "back_to_back", spacing=0.04, offset=OFFSET)
    supports = (*pair, _cylindrical(30e-6))
    loads = ShaftLoads(jnp.array([-0.12]), jnp.array([[1.5e3, 0.0, 1e3]]), jnp.zeros((1, 2)))

    def outputs(x):
        mounting = dataclasses.replace(MOUNTING, shaft_interference=x[0] * 1e-6, inner_ring_temperature=x[1],
                                       outer_ring_temperature=AMBIENT + 10.0, shaft_temperature=x[1] - 2.0,
                                       housing_temperature=AMBIENT + 8.0)
        changes = jnp.stack([mounted_clearance_change(support, mounting, 70e-3, 110e-3, SPEED).change
                             for support in supports])
        solution = solve_shaft(Shaft(tuple(s.with_clearance_change(c) for s, c in zip(supports, changes)), loads, SPEED))
        forces = solution.bearing_forces
        return jnp.concatenate([changes * 1e6, jnp.stack([forces[0][2] / 1e3, jnp.hypot(forces[2][0], forces[2][1]) / 1e3,
                                                          jnp.where(solution.converged, 0.0, jnp.nan)])])

    point = jnp.array([5.0, AMBIENT + 20.0])
    for direction, step in ((jnp.array([1.0, 0.0]), 1e-2), (jnp.array([0.0, 1.0]), 1e-2)):
        assert_jvp_matches_central_difference(outputs, point, direction, step, rtol=1e-6)


def _run(path, overrides=()):
    return run_model(build_model(load_scene(str(path), overrides=list(overrides))), progress=False)


@pytest.mark.slow
def test_the_spindle_shaft_example_holds_one_state():
    """spindle_shaft_thermal: no error; each bearing's clearance as the shaft runs it, as the mounting
    reports it and as the fixed point solved it are one (1e-15 m); the shaft's loads are the fixed
    point's (1e-8); the heat leaving is the friction heat (1e-10); the front pair's operating preload
    exceeds its matched 500 N, the rear bearing carries none; ISO 15312's n_θr beside it; a_ISO's κ is
    ν/ν₁ with ν at the hottest bearing's lubricant temperature (1e-12)."""
    result = _run(example_scene("spindle_shaft_thermal"))
    values = result.values
    assert result.problems[0] == []
    np.testing.assert_allclose(values["bearings.thermal.equilibrium_clearance"], values["bearings.thermal.clearance"],
                               atol=1e-15)
    np.testing.assert_allclose(values["bearings.mounting.operating_clearance"], values["bearings.thermal.clearance"],
                               atol=1e-15)
    state = result.model.inputs["thermal"]["state"]
    for got, want in zip(state.mechanics.bearing_forces, values["bearings.force"]):
        np.testing.assert_allclose(got, want, rtol=1e-8, atol=1e-6)
    assert float(values["shaft.thermal.heat_to_ambient"] + values["shaft.thermal.heat_to_oil"]) == pytest.approx(
        float(values["shaft.thermal.power"]), rel=1e-10)
    preload = np.asarray(values["bearings.thermal.operating_preload"])
    assert preload[0] == pytest.approx(preload[1], rel=1e-6) and preload[0] > 500.0 and preload[2] == 0.0
    assert np.all(np.asarray(values["bearings.thermal_speed.reference_speed"]) > 0.0)
    # a_ISO's κ at the hottest bearing's lubricant temperature on ISO VG 32's Walther line
    hottest = float(np.max(values["bearings.thermal.lubricant_temperature"]))
    viscosity = walther_viscosity(32e-6, ISO_VG_VISCOSITY_100[32] * 1e-6, hottest)
    np.testing.assert_allclose(values["bearings.viscosity_ratio"],
                               float(viscosity / reference_viscosity(6000.0 * np.pi / 30, 90e-3)), rtol=1e-12)


GEARBOX = open(example_scene("gearbox_shaft")).read()


def test_a_shaft_mounts_each_bearing_with_the_mounting_table(tmp_path):
    """gearbox_shaft with effects.mounting and k5/J6: each 6411's change is `operating_clearance_change`
    of its own rings at the classes' interferences at d and D and the shaft's speed (exact), its
    operating clearance the given 28 µm plus it (1e-15 m), which the shaft then runs at."""
    path = tmp_path / "shaft.toml"
    path.write_text(GEARBOX.replace("[effects]", '[mounting]\nshaft_tolerance = "k5"\nhousing_tolerance = "J6"\n\n'
                                                 "[effects]\nmounting = true"))
    values = _run(path).values
    steel, expansion = SEAT_MATERIALS["steel"]
    mounting = Mounting(shaft_interference=bearing_fits.shaft_interference("k5", 55e-3),
                        housing_interference=bearing_fits.housing_interference("J6", 140e-3), shaft=steel, housing=steel,
                        shaft_expansion=expansion, housing_expansion=expansion)
    want = operating_clearance_change(mounting, 55e-3, 97.5e-3 - 26.9875e-3, 97.5e-3 + 26.9875e-3, 140e-3, 26.9875e-3,
                                      BEARING_STEEL, 3000.0 * np.pi / 30).change
    np.testing.assert_array_equal(values["bearings.mounting.clearance_change"], [float(want)] * 2)
    np.testing.assert_allclose(values["bearings.mounting.operating_clearance"], 28e-6 + float(want), atol=1e-15)
    np.testing.assert_array_equal(values["bearings.mounting.axial_growth"], [0.0, 0.0])  # all at the reference


def test_a_warm_shaft_grows_against_its_housing(tmp_path):
    """gearbox_shaft (6411s at z = ∓100 mm) with effects.mounting, the shaft at 60 °C in a cast-iron
    housing at 40 °C: each inner ring shifts against its outer ring by ∓(L/2)(α_s 40 K − α_h 20 K),
    L = 200 mm (1e-18 m)."""
    path = tmp_path / "shaft.toml"
    path.write_text(GEARBOX.replace("[effects]", '[mounting]\nshaft_temperature = "60 degC"\nhousing_temperature = '
                                                 '"40 degC"\nhousing_material = "cast_iron"\n\n[effects]\nmounting = true'))
    values = _run(path).values
    steel, cast_iron = SEAT_MATERIALS["steel"][1], SEAT_MATERIALS["cast_iron"][1]
    half = 0.5 * 0.2 * (steel * 40.0 - cast_iron * 20.0)
    np.testing.assert_allclose(values["bearings.mounting.axial_growth"], [-half, half], rtol=0, atol=1e-18)


THERMAL_GEARBOX = GEARBOX.replace('radial_clearance = "0.028 mm"\n', 'radial_clearance = "0.028 mm"\nwidth = "33 mm"\n') \
    .replace("[effects]", '[lubricant]\npreset = "iso_vg_68"\n\n[mounting]\nshaft_tolerance = "k5"\n\n'
                          "[effects]\nmounting = true\nthermal = true")


@pytest.mark.parametrize("override, named", [
    ("effects.mounting=false", "effects.mounting"),
    ('mounting.shaft_temperature="60 degC"', "mounting.shaft_temperature"),
    ('thermal.oil_flow="-1 l/min"', "thermal.oil_flow"),
    ('thermal.housing_outer_diameter="120 mm"', "thermal.housing_outer_diameter"),
])
def test_bad_shaft_thermal_inputs_exit_2_naming_their_key(capsys, tmp_path, override, named):
    path = tmp_path / "shaft.toml"
    path.write_text(THERMAL_GEARBOX)
    assert_exits_2_naming(capsys, ["run", str(path), "--set", override], named)


def test_a_bearing_without_its_width_exits_2(capsys, tmp_path):
    """A bearing without its width (the network's conduction paths), or with one outside (0, D):
    exit 2 naming bearings[0]."""
    path = tmp_path / "shaft.toml"
    path.write_text(THERMAL_GEARBOX.replace('width = "33 mm"\n', "", 1))
    assert_exits_2_naming(capsys, ["run", str(path)], "bearings[0]: width")
    for width in ("-33 mm", "300 mm"):
        path.write_text(THERMAL_GEARBOX.replace('width = "33 mm"', f'width = "{width}"', 1))
        assert_exits_2_naming(capsys, ["run", str(path)], "bearings[0].width")


@pytest.mark.slow
def test_a_flexible_shaft_holds_one_state(tmp_path):
    """The gearbox shaft as a 55 mm Timoshenko beam: converged; each bearing's clearance as the shaft
    runs it is the state's (1e-15 m); the flexible shaft's loads are the fixed point's (1e-8); the
    heat balance closes (1e-10)."""
    path = tmp_path / "shaft.toml"
    path.write_text(THERMAL_GEARBOX + '\n[[shaft.sections]]\nfrom = "-150 mm"\nto = "150 mm"\nouter_diameter = "55 mm"\n')
    result = _run(path)
    values = result.values
    assert result.problems[0] == [] and bool(values["shaft.thermal.converged"])
    np.testing.assert_allclose(values["bearings.thermal.equilibrium_clearance"], values["bearings.thermal.clearance"],
                               atol=1e-15)
    for got, want in zip(result.model.inputs["thermal"]["state"].mechanics.bearing_forces, values["bearings.force"]):
        np.testing.assert_allclose(got, want, rtol=1e-8, atol=1e-6)
    assert float(values["shaft.thermal.heat_to_ambient"] + values["shaft.thermal.heat_to_oil"]) == pytest.approx(
        float(values["shaft.thermal.power"]), rel=1e-10)
