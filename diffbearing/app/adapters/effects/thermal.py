"""The thermal–mechanical steady state (`effects.thermal = true`, `diffbearing.thermal`) of a single
ball bearing, a preloaded pair or the bearings on a shaft (rigid or flexible) in their mounting: a thermal network
of the rings, the lubricant, the shaft and the housing (on a shaft, at each bearing's seat; paths
from their geometry, `thermal.mounting_paths`), heated by the friction the scene's `effects.friction`
names at the state the temperatures give — SKF's four components with "skf" (`thermal.skf_heat`),
else Palmgren's moments (ISO 15312's friction model) — solved as one fixed point
(`bearing_thermal.solve_thermal`).

The effect sets what the scene's mounting and lubricant would otherwise take as given: the
[mounting] table's fits at the solved ring, shaft and housing temperatures are the `mounting` input
(the clearance the equilibrium, the set and every effect after them run at), and the oil at the
solved lubricant temperature on its Walther line is the `lubricant` input (the film, the friction
and a_ISO's κ). On a shaft the [mounting] table's fits apply to every bearing (`mounting.shaft_mountings`)
and the one lubricant its friction and life read is at the hottest bearing's lubricant temperature
(a warning says so where they differ). It needs `effects.mounting` (the fits) and the oil's Walther
line; the temperatures it sets are refused as scene keys."""

import equinox as eqx
import jax.numpy as jnp
import numpy as np

from ....params import BALL_BEARING_KINDS, check_range, radial_clearance, with_radial_clearance
from ....systems.bearing_set import preload_offset
from ....systems.shaft_equilibrium import ShaftLoads
from ....thermal import bearing_thermal
from ....thermal.bearing_thermal import PATH_NAMES
from ....thermal.mounting_paths import CONDUCTIVITIES, Cooling, MountingGeometry, mounting_paths, shaft_paths
from ....thermal.pair_thermal import MountedBallPair
from ....thermal.shaft_thermal import MountedShaft, shaft_factors
from ....thermal.skf_heat import SkfHeat
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register
from ..bearings.ball import ball_model, catalogue_bearing
from ..lubricant import lubricant_at, lubricant_input, walther_line
from ..materials import material
from ..systems.mounting import (
    TEMPERATURES,
    clearance_change,
    mounted_layout,
    mounting_input,
    scene_mounting,
    shaft_input,
    shaft_mountings,
)
from ..systems.shaft_layout import layout_supports, shaft_layout
from .friction import friction_kinds, palmgren_f0, scene_skf_bearing, shaft_skf_bearings

EFFECT_ON = "effects.thermal"
SINGLE, PAIR = (EFFECT_ON, "!bearing.arrangement"), (EFFECT_ON, "bearing.arrangement")
TEMPERATURE_RANGE = (253.15, 473.15)  # K: the scene's ambient and oil inlet, −20 °C to 200 °C
COEFFICIENT_RANGE = (1.0, 1e5)  # W/(m²·K): still air to a water-cooled jacket
NODE_NAMES = ("inner_ring", "outer_ring", "lubricant", "shaft", "housing")


def _settings(v) -> dict:
    """The effects and fidelity tables from the scene's dotted keys (the model options of the
    equilibrium the fixed point solves)."""
    tables: dict = {"effects": {}, "fidelity": {}}
    for key in v:
        table, _, name = key.partition(".")
        if table in tables:
            tables[table][name] = v[key]
    return tables


def _geometry(v, width) -> MountingGeometry:
    """The scene's bearing in its shaft and housing (`_seat_geometry`)."""
    pitch, ball = v["bearing.pitch_diameter"], v["bearing.ball_diameter"]
    return _seat_geometry(v, v["bearing.bore"], v["bearing.outer_diameter"], pitch - ball, pitch + ball, width,
                          2.0 * v["bearing.outer_diameter"])


def _seat_geometry(v, bore, outside, inner_raceway, outer_raceway, width, housing_default) -> MountingGeometry:
    """A bearing of bore, outside, raceway diameters and width [m] in the shaft and the housing the
    scene's thermal and mounting keys give (the housing's outer diameter `housing_default` where
    neither gives it)."""
    housing_diameter = v.get("thermal.housing_outer_diameter", v.get("mounting.housing_outer_diameter", housing_default))
    check_range("thermal.housing_outer_diameter", housing_diameter, low=outside, unit=" m",
                why="a housing around the bearings' outer diameter")
    housing_length = v.get("thermal.housing_length", 2.0 * width)
    check_range("thermal.housing_length", housing_length, low=0.0, unit=" m")
    shaft_length = v.get("thermal.shaft_length", 2.0 * bore)
    check_range("thermal.shaft_length", shaft_length, low=0.0, unit=" m", why="the shaft beyond the bearing, each side")
    return MountingGeometry(
        bore=bore, outer_diameter=outside, width=width, inner_raceway_diameter=inner_raceway,
        outer_raceway_diameter=outer_raceway, shaft_bore=v.get("mounting.shaft_bore", 0.0), shaft_length=shaft_length,
        housing_outer_diameter=housing_diameter, housing_length=housing_length,
        ring_conductivity=CONDUCTIVITIES["bearing_steel"],
        shaft_conductivity=CONDUCTIVITIES[v.get("mounting.shaft_material", "steel")],
        housing_conductivity=CONDUCTIVITIES[v.get("mounting.housing_material", "steel")])


def _cooling(v, line) -> Cooling:
    ambient = v.get("thermal.ambient_temperature", 293.15)
    inlet = v.get("thermal.oil_inlet_temperature", ambient)
    for key, value in (("thermal.ambient_temperature", ambient), ("thermal.oil_inlet_temperature", inlet)):
        check_range(key, value, low=TEMPERATURE_RANGE[0], high=TEMPERATURE_RANGE[1], unit=" K", why="−20 °C to 200 °C")
    flow = v.get("thermal.oil_flow", 0.0)
    check_range("thermal.oil_flow", flow, low=0.0, high=1e-3, low_open=False, unit=" m³/s", why="up to 60 l/min")
    coefficients = {}
    for name in ("housing", "shaft", "oil"):
        key = f"thermal.{name}_heat_transfer_coefficient"
        coefficients[name] = v.get(key, 10.0 if name == "housing" else None)
        check_range(key, coefficients[name], low=COEFFICIENT_RANGE[0], high=COEFFICIENT_RANGE[1], unit=" W/(m²·K)",
                    why="still air to a water-cooled jacket")
    speed = jnp.abs(v.get("operating.inner_speed", 0.0) - v.get("operating.outer_speed", 0.0))
    return Cooling(ambient, inlet, flow, coefficients["housing"], speed, bearing_thermal.WaltherLine(*line),
                   coefficients["shaft"], coefficients["oil"])


def _scene_line(v) -> tuple:
    """The oil's Walther line, the scene's keys checked: effects.mounting on, no temperature the
    network sets given."""
    if v.get("effects.mounting", False) is not True:
        raise ValueError("effects.thermal needs effects.mounting (the fits and the rings' expansion that turn the "
                         "temperatures into the operating clearance)")
    for part in TEMPERATURES:
        if f"mounting.{part}_temperature" in v:
            raise ValueError(f"mounting.{part}_temperature: set by effects.thermal (the network's), not given")
    lubricant_at(v, 293.15)  # a ValueError naming the key where the scene's oil has no Walther line
    return walther_line(v)


def _skf(v) -> bool:
    """Whether the heat is SKF's four components (`effects.friction = "skf"`), else Palmgren's."""
    return v.get("effects.friction") == "skf"


def _common(v):
    """(the bearing as the scene gives it, its `Mounting` without temperatures, the Walther line,
    its friction model's heat, the model options), each scene key checked."""
    line = _scene_line(v)
    bearing = catalogue_bearing(v, material(v))
    heat = SkfHeat(scene_skf_bearing(v, {"bearing": bearing})["skf_bearing"]) if _skf(v) else \
        bearing_thermal.PalmgrenFactors.of_kind(bearing.kind, palmgren_f0(v, bearing.kind))
    return bearing, scene_mounting(v), line, heat, ball_model(_settings(v))


def _shaft_heat(v, layout, supports) -> tuple:
    """Each of the shaft's bearings' friction model's heat (SKF's rows, or Palmgren's factors of its
    friction kind); ValueError naming the bearing the model does not cover."""
    if _skf(v):
        return tuple(SkfHeat(bearing) for bearing in shaft_skf_bearings(v, {"shaft": layout})["skf_bearing"])
    return shaft_factors(supports, [palmgren_f0(v, kind) for kind in friction_kinds(layout, supports, "palmgren",
                                                                                     EFFECT_ON)])


def _inputs(v, heated, paths, mounting) -> dict:
    """The `mounting`, `lubricant` and `thermal` inputs at the state `heated` solves to."""
    state = bearing_thermal.solve_thermal(heated, paths)
    warm = bearing_thermal.mounted_at(mounting, state.temperatures)
    return {"mounting": clearance_change(v, warm), "lubricant": lubricant_at(v, state.temperatures[2]),
            "thermal": {"state": state, "paths": paths, "heated": heated}}


def _plain(v, built) -> dict:
    """With `effects.thermal = false`: the scene's own mounting and lubricant."""
    return mounting_input(v, built) | lubricant_input(v, built) | {"thermal": None}


def _single(v, built) -> dict:
    if v[EFFECT_ON] is not True:
        return _plain(v, built)
    bearing, mounting, line, heat, model = _common(v)
    width = v.get("bearing.width")
    if width is None:
        raise ValueError("bearing.width is needed by effects.thermal (the rings' and the housing's conduction paths)")
    paths = mounting_paths(_geometry(v, width), _cooling(v, line))
    heated = bearing_thermal.MountedBallBearing(bearing, mounting, built["operating"], bearing_thermal.WaltherLine(*line),
                                                heat, model)
    return _inputs(v, heated, paths, mounting)


def _pair(v, built) -> dict:
    if v[EFFECT_ON] is not True:
        return _plain(v, built)
    bearing, mounting, line, heat, model = _common(v)
    layout = built["bearing_set"]
    matched = with_radial_clearance(bearing, layout.matched_clearance)
    offset = preload_offset(matched, layout.preload, model) if layout.preload is not None else \
        jnp.asarray(0.0 if layout.offset is None else layout.offset)
    paths = mounting_paths(_geometry(v, 2.0 * v["bearing.width"]), _cooling(v, line))
    heated = MountedBallPair(matched, mounting, built["operating"], bearing_thermal.WaltherLine(*line), heat,
                             layout.spacing, offset, layout.arrangement, model)
    return _inputs(v, heated, paths, mounting)


def _shaft_geometry(v, layout, supports) -> tuple[MountingGeometry, ...]:
    """Each of the shaft's bearings' `MountingGeometry` (its own d, D, width and raceways; the
    housing's outside diameter the scene's, else twice the largest D)."""
    largest = 2.0 * max(float(outside) for _, outside in layout.envelopes)
    found = []
    for number, (support, (bore, outside), width) in enumerate(zip(supports, layout.envelopes, layout.widths)):
        if width is None:
            raise ValueError(f"bearings[{number}]: width is needed by effects.thermal (the rings' and the housing's "
                             "conduction paths)")
        check_range(f"bearings[{number}].width", width, low=0.0, high=outside, unit=" m",
                    why="positive, below the outer diameter")
        rings = support.ring_section()
        found.append(_seat_geometry(v, bore, outside, rings.inner_raceway_diameter, rings.outer_raceway_diameter, width,
                                    largest))
    return tuple(found)


def _shaft(v, built) -> dict:
    """A shaft's layout, its bearings as mounted at the solved temperatures (`mounting.mounted_layout`),
    the lubricant at the hottest bearing's lubricant temperature (the one oil the shaft's friction
    and life read), and the state."""
    if v[EFFECT_ON] is not True:
        return shaft_input(v, built) | lubricant_input(v, built) | {"thermal": None}
    line = _scene_line(v)
    layout = shaft_layout(v, built)["shaft"]
    mountings = shaft_mountings(v, layout)
    supports = layout_supports(layout, _settings(v))
    heat = _shaft_heat(v, layout, supports)
    oil = bearing_thermal.WaltherLine(*line)
    cooling = eqx.tree_at(lambda c: c.speed, _cooling(v, line), jnp.abs(layout.speed))
    paths = shaft_paths(_shaft_geometry(v, layout, supports), layout.positions, cooling)
    heated = MountedShaft(supports, mountings, jnp.stack([jnp.asarray(bore, float) for bore, _ in layout.envelopes]),
                          jnp.stack([jnp.asarray(outside, float) for _, outside in layout.envelopes]),
                          heat, layout.loads, layout.speed, oil, layout.sections, layout.stiffness_at, layout.mesh)
    state = bearing_thermal.solve_thermal(heated, paths)
    moved, changes = mounted_layout(v, layout, heated.mountings_at(state.temperatures))
    lubricant = jnp.max(bearing_thermal.seat_temperatures(state.temperatures, len(supports))[:, 2])
    return {"shaft": moved, "mounting": changes, "lubricant": lubricant_at(v, lubricant),
            "thermal": {"state": state, "paths": paths, "heated": heated}}


def _outputs(inputs: dict, settings: dict, results: dict) -> dict:
    state, paths = inputs["thermal"]["state"], inputs["thermal"]["paths"]
    out = {f"thermal.{name}_temperature": state.temperatures[number] for number, name in enumerate(NODE_NAMES)}
    return out | {
        "thermal.clearance": state.clearance,
        "thermal.lubricant_power": state.lubricant_power, "thermal.ring_power": state.ring_power,
        "thermal.power": state.lubricant_power + state.ring_power,
        "thermal.heat_to_ambient": state.boundary_heat[0], "thermal.heat_to_oil": state.boundary_heat[1],
        "thermal.residual": state.residual, "thermal.converged": state.converged,
        "thermal.conductances": jnp.stack([jnp.asarray(getattr(paths, name), float) for name in PATH_NAMES]),
    }


def _ball_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    """The state, and the identity that holds it together: the equilibrium's clearance is the state's."""
    return _outputs(inputs, settings, results) | {"thermal.equilibrium_clearance": radial_clearance(inputs["bearing"])}


def _set_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    """The state, and the preload the warm pair carries: each bearing's axial load at the solved
    clearance without the external load."""
    thermal = inputs["thermal"]
    state = thermal["state"]
    return _outputs(inputs, settings, results) | {
        "thermal.operating_preload": thermal["heated"].preload_at(state.temperatures),
        "thermal.bearing_axial_loads": jnp.stack([force[2] for force in state.mechanics.bearing_forces])}


def _shaft_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    """Each bearing's seat (K,), the shaft's totals, and the identity that holds it together: each
    bearing's clearance as the shaft runs it is the state's."""
    state, paths, layout = inputs["thermal"]["state"], inputs["thermal"]["paths"], inputs["shaft"]
    seats = len(layout.kinds)
    temperatures = bearing_thermal.seat_temperatures(state.temperatures, seats)
    out = {f"bearings.thermal.{name}_temperature": temperatures[:, number] for number, name in enumerate(NODE_NAMES)}
    supports = layout_supports(layout, settings)
    running = [support.ring_section().clearance for support in supports]
    loads = layout.loads  # at the same points (a flexible shaft's mesh has nodes there), none of them
    unloaded = inputs["thermal"]["heated"].equilibrium(supports, ShaftLoads(
        loads.positions, jnp.zeros_like(loads.forces), jnp.zeros_like(loads.moments)))
    return out | {
        "bearings.thermal.operating_preload": jnp.stack([jnp.abs(force[2]) for force in unloaded.bearing_forces]),
        "bearings.thermal.clearance": state.clearance,
        "bearings.thermal.equilibrium_clearance": jnp.stack(running),
        "bearings.thermal.lubricant_power": state.lubricant_power, "bearings.thermal.ring_power": state.ring_power,
        "bearings.thermal.power": state.lubricant_power + state.ring_power,
        "shaft.thermal.power": jnp.sum(state.lubricant_power + state.ring_power),
        "shaft.thermal.heat_to_ambient": state.boundary_heat[0], "shaft.thermal.heat_to_oil": state.boundary_heat[1],
        "shaft.thermal.residual": state.residual, "shaft.thermal.converged": state.converged,
        "bearings.thermal.conductances": jnp.stack([jnp.broadcast_to(jnp.asarray(getattr(paths, name), float), (seats,))
                                                    for name in PATH_NAMES], axis=1),
    }


def _shaft_checks(values: dict) -> tuple[list[str], list[str]]:
    """As `_checks`, over the shaft's bearings; a warning that the shaft's friction and life read one
    lubricant, the hottest bearing's."""
    lubricant = np.asarray(values["bearings.thermal.lubricant_temperature"])
    if not bool(values["shaft.thermal.converged"]):
        hottest = max(float(np.max(values[f"bearings.thermal.{name}_temperature"])) for name in NODE_NAMES)
        return [_runaway(float(values["shaft.thermal.residual"]), hottest)], []
    if not (TEMPERATURE_RANGE[0] <= lubricant.min() and lubricant.max() <= TEMPERATURE_RANGE[1]):
        return [f"thermal: a lubricant temperature ({', '.join(f'{t - 273.15:.4g}' for t in lubricant)} °C) is "
                "outside its Walther line's −20 … 200 °C"], []
    if len(lubricant) > 1 and float(lubricant.max() - lubricant.min()) > 1.0:
        return [], [f"thermal: the shaft's friction and life read one lubricant, at the hottest bearing's "
                    f"{lubricant.max() - 273.15:.1f} °C (bearings {lubricant.min() - 273.15:.1f} … "
                    f"{lubricant.max() - 273.15:.1f} °C): the others' films are thicker"]
    return [], []


def _runaway(residual: float, hottest: float) -> str:
    return (f"thermal: no steady state found (largest residual {residual:.3g} K, hottest node {hottest - 273.15:.4g} °C): "
            "the friction heat outgrows what the paths carry away (thermal runaway), or the temperatures leave the "
            "model's −60 … 250 °C")


def _checks(values: dict) -> tuple[list[str], list[str]]:
    """No steady state inside the model is an error (thermal runaway, or temperatures outside the
    mounting model's −60 … 250 °C or the oil's −20 … 200 °C)."""
    lubricant = float(values["thermal.lubricant_temperature"])
    if not bool(values["thermal.converged"]):
        hottest = max(float(values[f"thermal.{name}_temperature"]) for name in NODE_NAMES)
        return [_runaway(float(values["thermal.residual"]), hottest)], []
    if not TEMPERATURE_RANGE[0] <= lubricant <= TEMPERATURE_RANGE[1]:
        return [f"thermal: the lubricant's temperature {lubricant - 273.15:.4g} °C is outside its Walther line's "
                "−20 … 200 °C"], []
    return [], []


OUTPUTS = (
    *(Output(f"thermal.{name}_temperature", "K", "degC", f"{name.replace('_', ' ')} temperature") for name in NODE_NAMES),
    Output("thermal.clearance", "m", "um", "operating diametral clearance at the solved temperatures"),
    Output("thermal.power", "W", "W", "friction heat M ω (Palmgren's; SKF's with effects.friction = \"skf\")"),
    Output("thermal.lubricant_power", "W", "W", "of it into the lubricant (Palmgren's viscous M₀ ω; SKF's drag)"),
    Output("thermal.ring_power", "W", "W", "of it into the rings (Palmgren's M₁ ω; SKF's rolling, sliding, seals)"),
    Output("thermal.heat_to_ambient", "W", "W", "heat to the ambient (shaft and housing)"),
    Output("thermal.heat_to_oil", "W", "W", "heat carried away by the circulating oil"),
    Output("thermal.residual", "K", "K", "largest residual of the fixed point", in_report=False),
    Output("thermal.converged", "", "", "the fixed point converged inside the model", in_report=False),
    Output("thermal.conductances", "W/K", "W/K", "the paths' conductances (" + ", ".join(PATH_NAMES) + ")",
           in_report=False),
)


SHAFT_OUTPUTS = (
    *(Output(f"bearings.thermal.{name}_temperature", "K", "degC", f"each bearing's {name.replace('_', ' ')} temperature",
             in_report=False) for name in NODE_NAMES),
    Output("bearings.thermal.clearance", "m", "um", "each bearing's operating diametral clearance at the solved "
                                                    "temperatures", in_report=False),
    Output("bearings.thermal.equilibrium_clearance", "m", "um", "each bearing's clearance as the shaft runs it (the "
                                                                "state's)", in_report=False),
    Output("bearings.thermal.operating_preload", "N", "kN", "each bearing's axial load without the external loads, at "
                                                            "the solved clearances (its operating preload)",
           in_report=False),
    Output("bearings.thermal.power", "W", "W", "each bearing's friction heat", in_report=False),
    Output("bearings.thermal.lubricant_power", "W", "W", "of it into the lubricant", in_report=False),
    Output("bearings.thermal.ring_power", "W", "W", "of it into the rings", in_report=False),
    Output("shaft.thermal.power", "W", "W", "friction heat of the shaft's bearings (Palmgren's; SKF's with "
                                            "effects.friction = \"skf\")"),
    Output("shaft.thermal.heat_to_ambient", "W", "W", "heat to the ambient (shaft ends and housing)"),
    Output("shaft.thermal.heat_to_oil", "W", "W", "heat carried away by the circulating oil"),
    Output("shaft.thermal.residual", "K", "K", "largest residual of the fixed point", in_report=False),
    Output("shaft.thermal.converged", "", "", "the fixed point converged inside the model", in_report=False),
    Output("bearings.thermal.conductances", "W/K", "W/K", "each seat's paths' conductances (" + ", ".join(PATH_NAMES)
           + ")", in_report=False),
)


def _shaft_report(values) -> list[str]:
    lines = ["", "Thermal network of the shaft (each bearing's seat; °C, µm, W; docs/theory.md §Thermal network)",
             f"  {'#':<4}{'inner':>8}{'outer':>8}{'lubricant':>11}{'shaft':>8}{'housing':>9}{'clearance':>11}"
             f"{'preload [kN]':>14}{'heat':>8}"]
    for number in range(len(values["bearings.thermal.power"])):
        temperatures = [float(values[f"bearings.thermal.{name}_temperature"][number]) - 273.15 for name in NODE_NAMES]
        lines.append(f"  {number:<4}" + "".join(f"{t:>{w}.1f}" for t, w in zip(temperatures, (8, 8, 11, 8, 9)))
                     + f"{float(values['bearings.thermal.clearance'][number]) * 1e6:>11.2f}"
                     + f"{float(values['bearings.thermal.operating_preload'][number]) / 1e3:>14.3f}"
                     + f"{float(values['bearings.thermal.power'][number]):>8.1f}")
    state = "converged" if bool(values["shaft.thermal.converged"]) else "DID NOT CONVERGE"
    return lines + [f"  fixed point of temperatures, clearances and heat: {state} (largest residual "
                    f"{float(values['shaft.thermal.residual']):.1e} K)"]


def _report(result) -> list[str]:
    values = result.values
    if "bearings.thermal.power" in values and np.ndim(values["bearings.thermal.power"]) == 1:
        return _shaft_report(values)
    if "thermal.conductances" not in values or np.ndim(values["thermal.conductances"]) != 1:
        return []
    lines = ["", "Thermal network (conductances [W/K]; paths from the parts' geometry, docs/theory.md §Thermal network)"]
    for name, value in zip(PATH_NAMES, np.asarray(values["thermal.conductances"])):
        lines.append(f"  {name.replace('_', ' '):<24}{value:>10.4g}")
    state = "converged" if bool(values["thermal.converged"]) else "DID NOT CONVERGE"
    return lines + [f"  fixed point of temperatures, clearance and heat: {state} (largest residual "
                    f"{float(values['thermal.residual']):.1e} K)"]


KEYS = {
    EFFECT_ON: Key("boolean", doc="the steady temperatures of the rings, lubricant, shaft and housing (on a shaft: at "
                                  "each bearing's seat), solved with the clearance and the friction heat (needs "
                                  "effects.mounting); they set the mounting's temperatures and the lubricant's"),
    "thermal.ambient_temperature": quantity("temperature", "the air's (default 20 °C)"),
    "thermal.oil_inlet_temperature": quantity("temperature", "the circulating oil's at the inlet (default: the ambient)"),
    "thermal.oil_flow": quantity("volume_flow", "circulating oil through the bearing (\"2 l/min\"; default 0: a bath, "
                                                "oil mist or grease)"),
    "thermal.housing_heat_transfer_coefficient": quantity("heat_transfer_coefficient", "the housing's outside "
                                                          "(default 10 W/(m²·K): still air; a cooling jacket 500–3000)"),
    "thermal.shaft_heat_transfer_coefficient": quantity("heat_transfer_coefficient", "the shaft's ends in air (default: "
                                                        "a turning cylinder's correlation)"),
    "thermal.oil_heat_transfer_coefficient": quantity("heat_transfer_coefficient", "rings to oil (default: a turning "
                                                      "cylinder's correlation at half the ring speed)"),
    "thermal.housing_outer_diameter": quantity("length", "the housing's outer diameter (default: "
                                                         "mounting.housing_outer_diameter, else 2 D)"),
    "thermal.housing_length": quantity("length", "the housing's length (on a shaft: around each bearing; default "
                                                 "twice the bearings' width)"),
    "thermal.shaft_length": quantity("length", "the shaft's length beyond the bearing (on a shaft: beyond the outermost "
                                               "bearings), each side (default 2 d)"),
    "bearing.width": quantity("length", "bearing width B"),
}

ADAPTER = register(Adapter(
    name="thermal",
    bearing_types=BALL_BEARING_KINDS + SHAFT,
    keys=KEYS,
    inputs=(InputBuilder(("mounting", "lubricant", "thermal"), BALL_BEARING_KINDS, _single, after=("operating",),
                         scene_keys=SINGLE),
            InputBuilder(("mounting", "lubricant", "thermal"), BALL_BEARING_KINDS, _pair,
                         after=("operating", "bearing_set"), scene_keys=PAIR),
            InputBuilder(("shaft", "mounting", "lubricant", "thermal"), SHAFT, _shaft, scene_keys=(EFFECT_ON,))),
    blocks=(Block(name="thermal", bearing_types=BALL_BEARING_KINDS, enabled_by=("thermal", True), requires=("equilibrium",),
                  inputs=("thermal", "bearing"), outputs=(*OUTPUTS, Output(
                      "thermal.equilibrium_clearance", "m", "um", "the equilibrium's clearance (the state's)",
                      in_report=False)), compute=_ball_outputs, checks=_checks, scene_keys=SINGLE),
            Block(name="set_thermal", bearing_types=BALL_BEARING_KINDS, enabled_by=("thermal", True),
                  requires=("bearing_set",), inputs=("thermal",), outputs=(*OUTPUTS, Output(
                      "thermal.operating_preload", "N", "kN", "operating preload (without the external load)"), Output(
                      "thermal.bearing_axial_loads", "N", "kN", "each bearing's axial load in the fixed point's "
                      "equilibrium", in_report=False)), compute=_set_outputs, checks=_checks,
                  scene_keys=PAIR),
            Block(name="shaft_thermal", bearing_types=SHAFT, enabled_by=("thermal", True), requires=("shaft",),
                  inputs=("thermal", "shaft"), outputs=SHAFT_OUTPUTS, compute=_shaft_outputs, checks=_shaft_checks)),
    report=_report,
))
