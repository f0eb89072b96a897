"""Thermal speed ratings (`effects.thermal_speed = true`, `diffbearing.thermal.thermal_speed`) of a
single ball or whole roller bearing, of each bearing of a matched pair and of each on a shaft: ISO 15312's thermal reference
speed n_θr under the standard's reference conditions (thrust bearings' for the thrust kinds), and,
for a single bearing with the mounting's heat transfer coefficient
`thermal_speed.heat_transfer_coefficient`, DIN 732's thermally safe operating speed n_θ at the solved
load and the scene's lubricant, both from Palmgren's moments (ISO 15312's friction model) with the
bearing kind's factors of HR 1 (`friction_torque.PALMGREN_CONSTANTS`) or the scene's."""

import jax.numpy as jnp

from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....friction import friction_torque
from ....params import BALL_BEARING_KINDS, check_range
from ....ratings import static_safety
from ....thermal import thermal_speed
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register
from ..bearings.roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING
from ..systems.shaft_layout import check_static_ratings, layout_supports
from .friction import ball_torques, palmgren_f0, roller_torques

MOUNTING = ("thermal_speed.heat_transfer_coefficient",)  # the scenes DIN 732's rating runs in
TEMPERATURE_RANGE = (253.15, 473.15)  # K: −20 °C to 200 °C, the lubricant's range
HEAT_TRANSFER_RANGE = (10.0, 1e5)  # W/(m²·K): still air to a water-cooled housing (HR 1: 200–1000 for seats)


def _reference(v, built) -> dict:
    """ISO 15312's inputs: d, D, the total width W (`bearing.total_width`, else `bearing.width`), the
    factors f₀r (oil) and f₁r of the bearing's kind or the scene's."""
    for key in ("bearing.bore", "bearing.outer_diameter"):
        if key not in v:
            raise ValueError(f"{key} is needed by effects.thermal_speed (ISO 15312's reference surface)")
    width_key = "bearing.total_width" if "bearing.total_width" in v else "bearing.width"
    if width_key not in v:
        raise ValueError("bearing.width is needed by effects.thermal_speed (ISO 15312's reference surface π B (D + d); "
                         "a tapered bearing's total width T as bearing.total_width)")
    check_range(width_key, v[width_key], low=0.0, high=v["bearing.outer_diameter"], unit=" m",
                why="positive, below the outer diameter")
    _, f0_oil, coefficient, exponent = friction_torque.PALMGREN_CONSTANTS[built["bearing"].kind]
    f0 = v.get("thermal_speed.f0r", f0_oil)
    check_range("thermal_speed.f0r", f0, low=0.0, high=100.0, why="Palmgren's f0 of catalogues, about 1 to 15")
    f1 = v.get("thermal_speed.f1r", thermal_speed.reference_friction_factor(coefficient, exponent))
    check_range("thermal_speed.f1r", f1, low=0.0, high=0.01, why="Palmgren's f1 of catalogues, about 1e-4 to 1e-3")
    return {"thermal_reference": {"f0": f0, "f1": f1, "bore": v["bearing.bore"], "outside": v["bearing.outer_diameter"],
                                  "width": v[width_key]}}


def _shaft_reference(v, built) -> dict:
    """ISO 15312's inputs of each of the shaft's bearings (`thermal_reference`, a tuple): its friction
    kind's (`AbstractSupport.friction_kind`) oil f₀ and f₁ at the reference load, arrangement, d, D and
    total width from its [[bearings]] entry; a single bearing's factor keys are refused."""
    for key in ("thermal_speed.f0r", "thermal_speed.f1r"):
        if key in v:
            raise ValueError(f"{key}: a single bearing's key, not taken on a shaft (its bearings are of several kinds)")
    layout = built["shaft"]
    found = []
    for number, (support, (bore, outside), width) in enumerate(zip(layout_supports(layout), layout.envelopes,
                                                                  layout.widths)):
        kind = support.friction_kind("palmgren")
        if kind is None:
            raise ValueError(f"effects.thermal_speed: bearings[{number}] ({layout.kinds[number]}) has no Palmgren factors")
        arrangement = thermal_speed.reference_arrangement(kind)
        for name, value in (("bore", bore), ("outer_diameter", outside), ("width", width)):
            if value is None and (name != "width" or arrangement == "radial"):
                raise ValueError(f"bearings[{number}]: {name} is needed by effects.thermal_speed (ISO 15312's "
                                 "reference surface)")
        if arrangement == "radial":
            check_range(f"bearings[{number}].width", width, low=0.0, high=outside, unit=" m",
                        why="positive, below the outer diameter (a tapered bearing's total width T as total_width)")
        _, f0, coefficient, exponent = friction_torque.PALMGREN_CONSTANTS[kind]
        found.append({"f0": f0, "f1": thermal_speed.reference_friction_factor(coefficient, exponent, arrangement),
                      "bore": bore, "outside": outside, "width": width if width is not None else 0.0})
    return {"thermal_reference": tuple(found)}


def _shaft_reference_speeds(inputs: dict, settings: dict, results: dict) -> dict:
    speeds, flows, ratings, converged = [], [], [], []
    for support, reference in zip(layout_supports(inputs["shaft"], settings), inputs["thermal_reference"]):
        rating = support.static_load_rating()
        arrangement = thermal_speed.reference_arrangement(support.friction_kind("palmgren"))
        found = thermal_speed.thermal_reference_speed(reference["f0"], reference["f1"], rating, reference["bore"],
                                                      reference["outside"], reference["width"], arrangement)
        speeds.append(found.speed)
        flows.append(found.heat_flow)
        ratings.append(rating)
        converged.append(found.converged)
    return {"bearings.thermal_speed.reference_speed": jnp.stack(speeds),
            "bearings.thermal_speed.reference_heat_flow": jnp.stack(flows),
            "bearings.thermal_speed.static_load_rating": jnp.stack(ratings),
            "bearings.thermal_speed.reference_converged": jnp.stack(converged)}


def _shaft_checks(values: dict) -> tuple[list[str], list[str]]:
    failed = [number for number, ok in enumerate(values["bearings.thermal_speed.reference_converged"]) if not bool(ok)]
    return ([f"thermal_speed: ISO 15312's heat balance of bearings[{number}] did not converge" for number in failed],
            [])


def _report(result) -> list[str]:
    """Each of a shaft's bearings' thermal reference speed (a single bearing's are in the output table)."""
    values = result.values
    key = "bearings.thermal_speed.reference_speed"
    if key not in values or jnp.ndim(values[key]) != 1:
        return []
    lines = ["", "Thermal reference speeds (ISO 15312, Palmgren's moments; each bearing's kind's HR 1 factors)",
             f"  {'#':<4}{'type':<34}{'n_θr [rpm]':>12}{'q_r A_r [W]':>13}{'C0 [kN]':>10}"]
    for number, kind in enumerate(result.model.inputs["shaft"].kinds):
        lines.append(f"  {number:<4}{kind:<34}{float(values[key][number]) * 30 / jnp.pi:>12.5g}"
                     f"{float(values['bearings.thermal_speed.reference_heat_flow'][number]):>13.4g}"
                     f"{float(values['bearings.thermal_speed.static_load_rating'][number]) / 1e3:>10.4g}")
    return lines


def _mounting(v, built) -> dict:
    """DIN 732's heat flow Φ = k_q A_r ΔT_A + ρc V̇ ΔT_L and the f₀ of the scene's lubrication."""
    coefficient = v["thermal_speed.heat_transfer_coefficient"]
    check_range("thermal_speed.heat_transfer_coefficient", coefficient, low=HEAT_TRANSFER_RANGE[0],
                high=HEAT_TRANSFER_RANGE[1], unit=" W/(m²·K)", why="still air to a water-cooled housing")
    temperatures = {}
    for name, default in (("bearing_temperature", thermal_speed.REFERENCE_OUTER_RING_TEMPERATURE),
                          ("ambient_temperature", thermal_speed.REFERENCE_AMBIENT_TEMPERATURE)):
        temperatures[name] = v.get(f"thermal_speed.{name}", default)
        check_range(f"thermal_speed.{name}", temperatures[name], low=TEMPERATURE_RANGE[0], high=TEMPERATURE_RANGE[1],
                    unit=" K", why="−20 °C to 200 °C")
    keys = ("thermal_speed.oil_flow", "thermal_speed.oil_temperature_rise")
    if (keys[0] in v) != (keys[1] in v):
        given, missing = keys if keys[0] in v else keys[::-1]
        raise ValueError(f"{missing}: give it with {given} (the oil's heat flow ρc V̇ ΔT_L needs both)")
    flow, rise = v.get(keys[0], 0.0), v.get(keys[1], 0.0)
    if keys[0] in v:
        check_range(keys[0], flow, low=0.0, high=1e-3, unit=" m³/s", why="up to 60 l/min")
        check_range(keys[1], rise, low=0.0, high=100.0, unit=" K", why="outlet over inlet")
    reference = built["thermal_reference"]
    area = thermal_speed.reference_surface(reference["bore"], reference["outside"], reference["width"])
    seats = thermal_speed.seat_heat_flow(coefficient, area, temperatures["bearing_temperature"]
                                         - temperatures["ambient_temperature"])
    oil = thermal_speed.oil_heat_flow(flow, rise)
    return {"thermal_mounting": {"heat_flow": seats + oil, "seat_heat_flow": seats, "oil_heat_flow": oil,
                                 "f0": palmgren_f0(v, built["bearing"].kind)}}


def _reference_outputs(reference, static_rating) -> dict:
    rating = thermal_speed.thermal_reference_speed(reference["f0"], reference["f1"], static_rating, reference["bore"],
                                                   reference["outside"], reference["width"])
    return {"thermal_speed.reference_speed": rating.speed, "thermal_speed.reference_heat_flow": rating.heat_flow,
            "thermal_speed.f0r": jnp.asarray(reference["f0"], float), "thermal_speed.f1r": jnp.asarray(reference["f1"], float),
            "thermal_speed.static_load_rating": static_rating, "thermal_speed.reference_converged": rating.converged}


def _ball_reference(inputs: dict, settings: dict, results: dict) -> dict:
    bearing = inputs["bearing"]
    return _reference_outputs(inputs["thermal_reference"], static_safety.ball_bearing_static_load_rating(bearing))


def _roller_reference(inputs: dict, settings: dict, results: dict) -> dict:
    rating = static_safety.roller_bearing_static_load_rating(inputs["bearing"], inputs["raceways"])
    return _reference_outputs(inputs["thermal_reference"], rating)


def _safe_outputs(torques, mounting, lubricant, pitch, operating) -> dict:
    """DIN 732's n_θ from the solved load's P₁ and f₁ (`friction.ball_torques`), ν of the lubricant."""
    rating = thermal_speed.thermally_safe_speed(mounting["f0"], torques["friction.f1"], torques["friction.load"],
                                                lubricant.viscosity / lubricant.density, pitch, mounting["heat_flow"])
    return {"thermal_speed.safe_speed": rating.speed, "thermal_speed.heat_flow": rating.heat_flow,
            "thermal_speed.seat_heat_flow": mounting["seat_heat_flow"], "thermal_speed.oil_heat_flow": mounting["oil_heat_flow"],
            "thermal_speed.operating_speed": jnp.abs(operating.inner_speed - operating.outer_speed),
            "thermal_speed.safe_converged": rating.converged}


def _ball_safe(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, operating = inputs["bearing"], inputs["operating"]
    torques = ball_torques(bearing, inputs["thermal_mounting"]["f0"], None, inputs["lubricant"],
                           operating.inner_speed - operating.outer_speed, results["force"][:3])
    return _safe_outputs(torques, inputs["thermal_mounting"], inputs["lubricant"], bearing.pitch_diameter, operating)


def _roller_safe(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, raceways, operating = inputs["bearing"], inputs["raceways"], inputs["operating"]
    torques = roller_torques(bearing, raceways, inputs["thermal_mounting"]["f0"], None, inputs["lubricant"],
                             operating.inner_speed - operating.outer_speed, results["force"][:3])
    return _safe_outputs(torques, inputs["thermal_mounting"], inputs["lubricant"], raceways.pitch_diameter, operating)


def _reference_checks(values: dict) -> tuple[list[str], list[str]]:
    if not bool(values["thermal_speed.reference_converged"]):
        return ["thermal_speed: ISO 15312's heat balance did not converge"], []
    return [], []


def _safe_checks(values: dict) -> tuple[list[str], list[str]]:
    """Φ ≤ 0 has no thermally safe speed (an error); running above n_θ is a warning."""
    flow = float(values["thermal_speed.heat_flow"])
    if flow <= 0.0:
        return [f"thermal_speed: the mounting carries no heat away (Φ = {flow:.4g} W): no thermally safe speed "
                "(DIN 732)"], []
    if not bool(values["thermal_speed.safe_converged"]):
        return ["thermal_speed: DIN 732's heat balance did not converge"], []
    safe, running = float(values["thermal_speed.safe_speed"]), float(values["thermal_speed.operating_speed"])
    if running > safe:
        return [], [f"thermal_speed: the bearing runs at {running * 30 / jnp.pi:.5g} r/min, above its thermally safe "
                    f"speed n_θ = {safe * 30 / jnp.pi:.5g} r/min (DIN 732): it runs hotter than "
                    "thermal_speed.bearing_temperature"]
    return [], []


REFERENCE_OUTPUTS = (
    Output("thermal_speed.reference_speed", "rad/s", "rpm", "thermal reference speed n_θr (ISO 15312)"),
    Output("thermal_speed.reference_heat_flow", "W", "W", "reference heat flow q_r A_r (ISO 15312)"),
    Output("thermal_speed.f0r", "", "", "reference factor f0r (oil)"),
    Output("thermal_speed.f1r", "", "", "reference factor f1r at P0 = 0.05 C0"),
    Output("thermal_speed.static_load_rating", "N", "kN", "C0 of the reference load (ISO 76)"),
    Output("thermal_speed.reference_converged", "", "", "ISO 15312's heat balance converged", in_report=False),
)
SAFE_OUTPUTS = (
    Output("thermal_speed.safe_speed", "rad/s", "rpm", "thermally safe operating speed n_θ (DIN 732)"),
    Output("thermal_speed.heat_flow", "W", "W", "heat flow carried away Φ = Φ_S + Φ_L (DIN 732)"),
    Output("thermal_speed.seat_heat_flow", "W", "W", "through the seats Φ_S = k_q A_r ΔT_A"),
    Output("thermal_speed.oil_heat_flow", "W", "W", "by the circulating oil Φ_L = ρc V̇ ΔT_L"),
    Output("thermal_speed.operating_speed", "rad/s", "rpm", "the relative ring speed", in_report=False),
    Output("thermal_speed.safe_converged", "", "", "DIN 732's heat balance converged", in_report=False),
)


SHAFT_OUTPUTS = (
    Output("bearings.thermal_speed.reference_speed", "rad/s", "rpm", "each bearing's thermal reference speed n_θr "
                                                                      "(ISO 15312)", in_report=False),
    Output("bearings.thermal_speed.reference_heat_flow", "W", "W", "each bearing's q_r A_r (ISO 15312)", in_report=False),
    Output("bearings.thermal_speed.static_load_rating", "N", "kN", "each bearing's C0 of the reference load",
           in_report=False),
    Output("bearings.thermal_speed.reference_converged", "", "", "each bearing's heat balance converged",
           in_report=False),
)


def _blocks(prefix: str, types, requires, extra_inputs, reference, safe, scene_keys=()) -> tuple[Block, Block]:
    return (Block(name=f"{prefix}thermal_reference_speed", bearing_types=types, enabled_by=("thermal_speed", True),
                  requires=requires, inputs=("bearing", *extra_inputs, "thermal_reference"), outputs=REFERENCE_OUTPUTS,
                  compute=reference, checks=_reference_checks, scene_keys=scene_keys),
            Block(name=f"{prefix}thermally_safe_speed", bearing_types=types, enabled_by=("thermal_speed", True),
                  requires=requires, inputs=("bearing", *extra_inputs, "operating", "lubricant", "thermal_mounting"),
                  outputs=SAFE_OUTPUTS, compute=safe, checks=_safe_checks, scene_keys=scene_keys + MOUNTING))


ADAPTER = register(Adapter(
    name="thermal_speed",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"effects.thermal_speed": Key("boolean", doc="thermal speed ratings: ISO 15312's thermal reference speed; "
                                                      "with thermal_speed.heat_transfer_coefficient DIN 732's "
                                                      "thermally safe operating speed"),
          "thermal_speed.f0r": Key("number", doc="ISO 15312's f0r (default: the kind's oil-lubricated f0 of HR 1, "
                                                 "62 / 72-B / 2..-E / 302 series)"),
          "thermal_speed.f1r": Key("number", doc="ISO 15312's f1r (default: the kind's HR 1 f1 at P0 = 0.05 C0)"),
          "thermal_speed.heat_transfer_coefficient": quantity("heat_transfer_coefficient",
                                                              "DIN 732's k_q of the seats (HR 1: 200–1000 W/(m²·K))"),
          "thermal_speed.bearing_temperature": quantity("temperature", "DIN 732's permitted mean bearing temperature "
                                                                       "(default 70 °C)"),
          "thermal_speed.ambient_temperature": quantity("temperature", "DIN 732's ambient temperature (default 20 °C)"),
          "thermal_speed.oil_flow": quantity("volume_flow", "DIN 732's circulating oil flow V̇ (\"2 l/min\")"),
          "thermal_speed.oil_temperature_rise": quantity("temperature_difference", "DIN 732's ΔT_L of the oil, outlet "
                                                                                   "over inlet (\"10 K\")"),
          "bearing.bore": quantity("length"),
          "bearing.outer_diameter": quantity("length"),
          "bearing.width": quantity("length", "bearing width B"),
          "bearing.total_width": quantity("length", "a tapered bearing's total width T (ISO 15312's reference "
                                                    "surface; set by its designation)")},
    inputs=(InputBuilder(("thermal_reference",), BALL_BEARING_KINDS + ROLLER_KINDS, _reference, after=("bearing",)),
            InputBuilder(("thermal_reference",), SHAFT, _shaft_reference, after=("shaft",)),
            InputBuilder(("thermal_mounting",), BALL_BEARING_KINDS + ROLLER_KINDS, _mounting,
                         after=("bearing", "thermal_reference"), scene_keys=MOUNTING)),
    blocks=(*_blocks("", BALL_BEARING_KINDS, ("equilibrium",), (), _ball_reference, _ball_safe),
            *_blocks("roller_", ROLLER_KINDS, (EQUILIBRIUM_BLOCK,), ("raceways",), _roller_reference, _roller_safe,
                     WHOLE_BEARING),
            Block(name="set_thermal_reference_speed", bearing_types=BALL_BEARING_KINDS, enabled_by=("thermal_speed", True),
                  requires=("bearing_set",), inputs=("bearing", "thermal_reference"), outputs=REFERENCE_OUTPUTS,
                  compute=_ball_reference, checks=_reference_checks, scene_keys=("bearing.arrangement",)),
            Block(name="shaft_thermal_reference_speed", bearing_types=SHAFT, enabled_by=("thermal_speed", True),
                  requires=("shaft",), inputs=("shaft", "thermal_reference"), outputs=SHAFT_OUTPUTS,
                  compute=_shaft_reference_speeds, checks=_shaft_checks, validate=check_static_ratings)),
    report=_report,
))
