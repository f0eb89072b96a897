"""Friction torque and power loss: effect friction = "palmgren" (Palmgren's viscous and
load-dependent moments, `diffbearing.friction.friction_torque`) or "skf" (SKF's rolling, sliding and drag
moments, `diffbearing.friction.skf_friction`), from the loads the bearing carries, the lubricant's viscosity
at its temperature and the speed."""

import jax.numpy as jnp

from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....friction import friction_torque, skf_friction
from ....friction.skf_friction import SkfBearing
from ....params import BALL_BEARING_KINDS, check_range
from ....ratings import static_safety
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register
from ..systems.bearing_set import SET, SET_SIZE
from .life import SUPPLY_KEY
from ..bearings.roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING
from ..systems.shaft_layout import check_static_ratings, layout_supports

FRICTION_MODELS = ("palmgren", "skf")
DEFAULT_SUPPLY = "oil_bath"
# lubricant.supply → SKF's lubrication of K_rs: circulating oil is fed as a jet, the bath is a low-level one
SKF_SUPPLY = {"circulating": "oil_jet", "oil_bath": "oil_bath", "grease": "grease"}


def palmgren_f0(v, kind: str):
    """f₀ of a bearing kind and the scene's lubrication, or the scene's `friction.f0`."""
    f0_grease, f0_oil, _, _ = friction_torque.PALMGREN_CONSTANTS[kind]
    supply = v.get("lubricant.supply", DEFAULT_SUPPLY)
    f0 = v.get("friction.f0", f0_grease if supply == "grease" else f0_oil)
    check_range("friction.f0", f0, low=0.0, high=100.0, why="Palmgren's f0 of catalogues, about 1 to 15")
    return f0


def _f1(v):
    f1 = v.get("friction.f1")
    if f1 is not None:
        check_range("friction.f1", f1, low=0.0, high=0.01, why="Palmgren's f1 of catalogues, about 1e-4 to 1e-3")
    return f1


def _constants(v, built) -> dict:
    """f₀ of the bearing's kind and lubrication, or the scene's; the scene's f₁ or None."""
    return {"friction_constants": {"f0": palmgren_f0(v, built["bearing"].kind), "f1": _f1(v)}}


def scene_skf_bearing(v, built) -> dict:
    """The scene's SKF series (default `skf_friction.DEFAULT_SERIES`), lubrication, d, D and drag inputs."""
    kind = built["bearing"].kind
    series = v.get("friction.series", skf_friction.DEFAULT_SERIES[kind])
    table = skf_friction.SERIES_CONSTANTS[kind]
    if series not in table:
        raise ValueError(f"friction.series: the {kind} series of SKF's friction model, one of {tuple(table)}, "
                         f"got {series!r}")
    for key in ("bearing.bore", "bearing.outer_diameter"):
        if key not in v:
            raise ValueError(f"{key} is needed by effects.friction = 'skf' (SKF's model reads d and D)")
    supply = v.get("lubricant.supply", DEFAULT_SUPPLY)
    drag = v.get("friction.drag_loss_factor")
    width = None
    if drag is not None:
        check_range("friction.drag_loss_factor", drag, low=0.0, low_open=False, high=0.01,
                    why="V_M read off SKF's diagram against the oil level H/d_m, of order 1e-5 to 1e-3")
        if supply != "oil_bath":
            raise ValueError(f"friction.drag_loss_factor: the drag loss is an oil bath's (lubricant.supply = "
                             f"'oil_bath'), got lubricant.supply = {supply!r}")
        if kind in skf_friction.ROLLER_LENGTH_KINDS:  # the model's roller drag reads the inner ring's width
            if "bearing.width" not in v:
                raise ValueError("bearing.width is needed by friction.drag_loss_factor on a roller bearing "
                                 "(SKF's roller drag reads the inner ring width B)")
            width = v["bearing.width"]
    return {"skf_bearing": SkfBearing(series, SKF_SUPPLY[supply], v["bearing.bore"], v["bearing.outer_diameter"],
                                      drag, width, *_seals(v, kind))}


def _seals(v, kind: str) -> tuple:
    """(row of SKF's seal constants or None, d_s [m] or None, seals) from friction.seal,
    friction.seal_counterface_diameter and friction.seals."""
    seal = v.get("friction.seal")
    keys = ("friction.seal_counterface_diameter", "friction.seals")
    if seal is None:
        given = [key for key in keys if key in v]
        if given:
            raise ValueError(f"{given[0]} needs friction.seal (the seal designation, one of {skf_friction.SEALS})")
        return None, None, 2
    if keys[0] not in v:
        raise ValueError(f"friction.seal needs {keys[0]} (d_s, the seal's counterface diameter: the inner ring "
                         "shoulder diameter of the bearing tables)")
    counterface = v[keys[0]]
    check_range(keys[0], counterface, low=0.0, high=v["bearing.outer_diameter"], unit=" m",
                why="between 0 and the bearing's outer diameter")
    seals = v.get("friction.seals", 2)
    if seals not in (1, 2):
        raise ValueError(f"friction.seals: 1 (sealed on one side) or 2, got {seals}")
    try:
        row = skf_friction.seal_row(kind, seal, v["bearing.outer_diameter"])
    except ValueError as error:
        raise ValueError(f"friction.{error}") from None
    return row, counterface, seals


def friction_kinds(layout, supports, model: str, effect: str = "effects.friction") -> list[str]:
    """Each of the shaft's bearings' (`supports`) kind in the friction model `model`
    (`AbstractSupport.friction_kind`); ValueError naming the `effect` and the bearing a model does not cover."""
    kinds = []
    for number, support in enumerate(supports):
        kind = support.friction_kind(model)
        if kind is None:
            raise ValueError(f"{effect}: bearings[{number}] ({layout.kinds[number]}) is not covered by the "
                             f"{model!r} friction model" + (" (try \"skf\")" if model == "palmgren" else ""))
        kinds.append(kind)
    return kinds


def shaft_skf_bearings(v, built) -> dict:
    """Each of the shaft's bearings' SKF inputs (a tuple): its type's series where its design fixes
    one, else the scene's friction.series where it is one of every bearing's kind's, else each kind's
    default; d and D from each [[bearings]] entry. The oil bath's drag and seals are a single
    bearing's keys (a shaft's bearings have their own)."""
    layout, supply = built["shaft"], v.get("lubricant.supply", DEFAULT_SUPPLY)
    for key in ("friction.drag_loss_factor", "friction.seal"):
        if key in v:
            raise ValueError(f"{key}: a single bearing's key, not taken on a shaft (its bearings each have their own)")
    series = v.get("friction.series")
    bearings = []
    supports = layout_supports(layout)
    for number, (support, kind, (bore, outside)) in enumerate(zip(supports, friction_kinds(layout, supports, "skf"),
                                                                  layout.envelopes)):
        own = support.friction_series()
        if series is not None and own is None and series not in skf_friction.SERIES_CONSTANTS[kind]:
            raise ValueError(f"friction.series: a series of every bearing's kind in SKF's friction model; bearings[{number}] "
                             f"is {kind}, whose series are {tuple(skf_friction.SERIES_CONSTANTS[kind])}, got {series!r}")
        if bore is None or outside is None:
            raise ValueError(f"bearings[{number}]: bore and outer_diameter are needed by effects.friction = 'skf' "
                             "(SKF's model reads d and D)")
        bearings.append(SkfBearing(own or series or skf_friction.DEFAULT_SERIES[kind], SKF_SUPPLY[supply], bore, outside, None,
                                   None))
    return {"skf_bearing": tuple(bearings)}


def _shaft_constants(v, built) -> dict:
    """f₀ of each of the shaft's bearings (a tuple), the scene's f₁ or None."""
    return {"friction_constants": {"f0": tuple(palmgren_f0(v, kind) for kind in friction_kinds(
        built["shaft"], layout_supports(built["shaft"]), "palmgren")),
                                   "f1": _f1(v)}}


def _torques(kind, f0, f1, lubricant, speed, pitch, radial, axial, static_load, static_rating, angle=0.0):
    """Palmgren's moments [N·m] and power [W] of one bearing: f₁ the scene's, or of its kind from
    P₀/C₀; `speed` the relative ring speed [rad/s]."""
    if f1 is None:
        _, _, coefficient, exponent = friction_torque.PALMGREN_CONSTANTS[kind]
        f1 = friction_torque.speed_factor(coefficient, exponent, static_load, static_rating)
    load = friction_torque.friction_load(kind, radial, axial, angle)
    viscous = friction_torque.viscous_torque(f0, lubricant.viscosity / lubricant.density, speed, pitch)
    loaded = friction_torque.load_torque(f1, load, pitch)
    return {"friction.f0": jnp.asarray(f0, float), "friction.f1": jnp.asarray(f1, float),
            "friction.load": load, "friction.viscous_torque": viscous, "friction.load_torque": loaded,
            "friction.torque": viscous + loaded, "friction.power": friction_torque.friction_power(viscous + loaded, speed)}


def _split(force):
    return jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])


def ball_torques(bearing, f0, f1, lubricant, speed, force):
    """`_torques` of a ball bearing under [Fx, Fy, Fz] [N] (P₀, C₀ of ISO 76)."""
    return _torques(bearing.kind, f0, f1, lubricant, speed, bearing.pitch_diameter, *_split(force),
                    static_safety.ball_bearing_equivalent_static_load(bearing, force),
                    static_safety.ball_bearing_static_load_rating(bearing))


def roller_torques(bearing, raceways, f0, f1, lubricant, speed, force):
    """`_torques` of a roller bearing under [Fx, Fy, Fz] [N]."""
    return _torques(bearing.kind, f0, f1, lubricant, speed, raceways.pitch_diameter, *_split(force), None, None,
                    raceways.cup_angle)


def _speed(operating):
    return operating.inner_speed - operating.outer_speed


def _ball_friction(inputs: dict, settings: dict, results: dict) -> dict:
    constants = inputs["friction_constants"]
    return ball_torques(inputs["bearing"], constants["f0"], constants["f1"], inputs["lubricant"],
                         _speed(inputs["operating"]), results["force"][:3])


def _roller_friction(inputs: dict, settings: dict, results: dict) -> dict:
    constants = inputs["friction_constants"]
    return roller_torques(inputs["bearing"], inputs["raceways"], constants["f0"], constants["f1"], inputs["lubricant"],
                           _speed(inputs["operating"]), results["force"][:3])


def _skf_outputs(moment: skf_friction.FrictionalMoment) -> dict:
    return {"friction.torque": moment.total, "friction.power": moment.power,
            "friction.rolling_torque": moment.inlet_shear * moment.replenishment * moment.rolling,
            "friction.sliding_torque": moment.sliding, "friction.drag_torque": moment.drag,
            "friction.seal_torque": moment.seal,
            "friction.inlet_shear_factor": moment.inlet_shear, "friction.replenishment_factor": moment.replenishment,
            "friction.sliding_coefficient": moment.sliding_coefficient}


def _skf_moment(kind, static_rating, angle, skf: SkfBearing, lubricant, speed, force) -> skf_friction.FrictionalMoment:
    """`skf_friction.bearing_moment` in the scene's `lubricant`."""
    return skf_friction.bearing_moment(kind, static_rating, angle, skf, lubricant.viscosity / lubricant.density, speed,
                                       force)


def _ball_skf_moment(bearing, skf, lubricant, speed, force):
    return _skf_moment(bearing.kind, static_safety.ball_bearing_static_load_rating(bearing), None, skf, lubricant,
                       speed, force)


def _roller_skf_moment(bearing, raceways, skf, lubricant, speed, force):
    return _skf_moment(bearing.kind, None, raceways.cup_angle, skf, lubricant, speed, force)


def _ball_skf_friction(inputs: dict, settings: dict, results: dict) -> dict:
    return _skf_outputs(_ball_skf_moment(inputs["bearing"], inputs["skf_bearing"], inputs["lubricant"],
                                         _speed(inputs["operating"]), results["force"][:3]))


def _set_skf_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each bearing's SKF moment from its own load, and the set's together."""
    speed = _speed(inputs["operating"])
    torques = [_ball_skf_moment(inputs["bearing"], inputs["skf_bearing"], inputs["lubricant"], speed,
                                results[f"set.bearings.{number}.force"][:3]).total for number in range(SET_SIZE)]
    return _set_totals(torques, speed)


def _set_totals(torques, speed) -> dict:
    return ({f"set.bearings.{number}.friction.torque": torque for number, torque in enumerate(torques)}
            | {"set.friction.torque": sum(torques), "set.friction.power": friction_torque.friction_power(sum(torques), speed)})


def _roller_skf_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """SKF's moments of a roller bearing from its carried load."""
    return _skf_outputs(_roller_skf_moment(inputs["bearing"], inputs["raceways"], inputs["skf_bearing"],
                                           inputs["lubricant"], _speed(inputs["operating"]), results["force"][:3]))


def _shaft_skf_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each of the shaft's bearings' SKF moment from its own load, and the shaft's together."""
    layout = inputs["shaft"]
    supports = layout_supports(layout, settings)
    torques = [_skf_moment(support.friction_kind("skf"), support.static_load_rating(), support.nominal_contact_angle(),
                           skf, inputs["lubricant"], layout.speed, results["bearings.force"][number][:3]).total
               for number, (support, skf) in enumerate(zip(supports, inputs["skf_bearing"]))]
    return _shaft_totals(torques, layout.speed)


def _shaft_totals(torques, speed) -> dict:
    return {"bearings.friction.torque": jnp.stack(torques), "shaft.friction.torque": sum(torques),
            "shaft.friction.power": friction_torque.friction_power(sum(torques), speed)}


def _set_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each bearing's Palmgren torque from its own load, and the set's together."""
    constants, speed = inputs["friction_constants"], _speed(inputs["operating"])
    torques = [ball_torques(inputs["bearing"], constants["f0"], constants["f1"], inputs["lubricant"], speed,
                             results[f"set.bearings.{number}.force"][:3])["friction.torque"] for number in range(SET_SIZE)]
    return _set_totals(torques, speed)


def _shaft_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each of the shaft's bearings' Palmgren torque from its own load (its P₀, C₀ and contact angle
    as its type rates them), and the shaft's together."""
    layout, constants, lubricant = inputs["shaft"], inputs["friction_constants"], inputs["lubricant"]
    torques = []
    for number, (support, f0) in enumerate(zip(layout_supports(layout, settings), constants["f0"])):
        force = results["bearings.force"][number][:3]
        found = _torques(support.friction_kind("palmgren"), f0, constants["f1"], lubricant, layout.speed,
                         2.0 * support.pitch_radius(), *_split(force), support.equivalent_static_load(force),
                         support.static_load_rating(), support.nominal_contact_angle())
        torques.append(found["friction.torque"])
    return _shaft_totals(torques, layout.speed)


TORQUE_AND_POWER = (
    Output("friction.torque", "N*m", "N*mm", "friction torque M"),
    Output("friction.power", "W", "W", "power loss M ω"),
)
OUTPUTS = (
    *TORQUE_AND_POWER,
    Output("friction.viscous_torque", "N*m", "N*mm", "viscous moment M0"),
    Output("friction.load_torque", "N*m", "N*mm", "load-dependent moment M1 = f1 P1 dm"),
    Output("friction.f0", "", "", "Palmgren f0 (the scene's, else HR 1's)"),
    Output("friction.f1", "", "", "Palmgren f1 (the scene's, else HR 1's)"),
    Output("friction.load", "N", "kN", "load P1 of the moment M1"),
)

SKF_OUTPUTS = (
    *TORQUE_AND_POWER,
    Output("friction.rolling_torque", "N*m", "N*mm", "rolling moment φ_ish φ_rs M_rr (SKF)"),
    Output("friction.sliding_torque", "N*m", "N*mm", "sliding moment M_sl = G_sl μ_sl (SKF)"),
    Output("friction.drag_torque", "N*m", "N*mm", "drag moment in the oil bath M_drag (SKF)"),
    Output("friction.seal_torque", "N*m", "N*mm", "seals' moment M_seal (SKF)"),
    Output("friction.inlet_shear_factor", "", "", "inlet shear heating factor φ_ish (SKF)"),
    Output("friction.replenishment_factor", "", "", "kinematic replenishment factor φ_rs (SKF)"),
    Output("friction.sliding_coefficient", "", "", "sliding friction coefficient μ_sl (SKF)"),
)

def _single_bearing_blocks(model: str, constants: str, outputs, ball_compute, roller_compute) -> tuple[Block, Block]:
    """The blocks of a single ball and a whole roller bearing for `effects.friction = model`, reading
    the input `constants`."""
    prefix = "" if model == "palmgren" else f"{model}_"
    return (Block(name=f"{prefix}friction", bearing_types=BALL_BEARING_KINDS, enabled_by=("friction", model),
                  requires=("equilibrium",), inputs=("bearing", "operating", "lubricant", constants), outputs=outputs,
                  compute=ball_compute),
            Block(name=f"roller_{prefix}friction", bearing_types=ROLLER_KINDS, enabled_by=("friction", model),
                  requires=(EQUILIBRIUM_BLOCK,), inputs=("bearing", "raceways", "operating", "lubricant", constants),
                  outputs=outputs, compute=roller_compute, scene_keys=WHOLE_BEARING))


def _set_block(model: str, constants: str, compute) -> Block:
    """The block of a bearing set for `effects.friction = model`, reading the input `constants`."""
    prefix = "" if model == "palmgren" else f"{model}_"
    return Block(name=f"set_{prefix}friction", bearing_types=BALL_BEARING_KINDS, enabled_by=("friction", model),
                 requires=("bearing_set",), inputs=("bearing", "operating", "lubricant", constants), outputs=SET_OUTPUTS,
                 compute=compute, scene_keys=SET)


def _shaft_outputs(model: str) -> tuple[Output, ...]:
    return (Output("bearings.friction.torque", "N*m", "N*mm", f"each bearing's friction torque {model}", in_report=False),
            Output("shaft.friction.torque", "N*m", "N*mm", "friction torque of the shaft's bearings"),
            Output("shaft.friction.power", "W", "W", "power loss of the shaft's bearings"))


SET_OUTPUTS = (*(Output(f"set.bearings.{number}.friction.torque", "N*m", "N*mm", f"bearing {number}: friction torque")
                  for number in range(SET_SIZE)),
               Output("set.friction.torque", "N*m", "N*mm", "friction torque of the set"),
               Output("set.friction.power", "W", "W", "power loss of the set"))

ADAPTER = register(Adapter(
    name="friction",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"effects.friction": Key("choice", choices=FRICTION_MODELS, doc="friction torque and power loss"),
          "friction.f0": Key("number", doc="Palmgren's f0 of the bearing's series and lubrication (default: HR 1's "
                                           "62 / 72-B / 2..-E / 302 series)"),
          "friction.f1": Key("number", doc="Palmgren's f1 (default: HR 1's, a (P0/C0)^b for ball bearings)"),
          "friction.series": Key("text", doc="the bearing's series in SKF's friction model (Table 3: e.g. 62, 63 "
                                             "deep groove; single_row, double_row, four_point angular contact; 2, "
                                             "22 cylindrical; 302, 322 tapered; default 62 / single_row / 2 / 302)"),
          "friction.drag_loss_factor": Key("number", doc="SKF's V_M read off its diagram against the oil level "
                                                         "H/d_m (oil bath only; default: no drag loss)"),
          "friction.seal": Key("choice", choices=skf_friction.SEALS,
                               doc="the bearing's contact seals in SKF's model (RS1, RSH deep groove; RS1 angular "
                                   "contact; LS cylindrical roller; default: open)"),
          "friction.seal_counterface_diameter": quantity("length", "d_s, the seal's counterface diameter (SKF)"),
          "friction.seals": Key("integer", doc="seals on the bearing, 1 or 2 (default 2; SKF)"),
          "bearing.bore": quantity("length"),
          "bearing.outer_diameter": quantity("length"),
          "bearing.width": quantity("length", "bearing width B"),
          "lubricant.supply": SUPPLY_KEY},
    inputs=(InputBuilder(("friction_constants",), BALL_BEARING_KINDS + ROLLER_KINDS, _constants, after=("bearing",)),
            InputBuilder(("skf_bearing",), BALL_BEARING_KINDS + ROLLER_KINDS, scene_skf_bearing, after=("bearing",)),
            InputBuilder(("friction_constants",), SHAFT, _shaft_constants, after=("shaft",)),
            InputBuilder(("skf_bearing",), SHAFT, shaft_skf_bearings, after=("shaft",))),
    blocks=(*_single_bearing_blocks("palmgren", "friction_constants", OUTPUTS, _ball_friction, _roller_friction),
            *_single_bearing_blocks("skf", "skf_bearing", SKF_OUTPUTS, _ball_skf_friction, _roller_skf_friction),
            _set_block("palmgren", "friction_constants", _set_friction),
            _set_block("skf", "skf_bearing", _set_skf_friction),
            Block(name="shaft_friction", bearing_types=SHAFT, enabled_by=("friction", "palmgren"), requires=("shaft",),
                  inputs=("shaft", "lubricant", "friction_constants"), outputs=_shaft_outputs("M0 + M1"),
                  compute=_shaft_friction, validate=check_static_ratings),
            Block(name="shaft_skf_friction", bearing_types=SHAFT, enabled_by=("friction", "skf"), requires=("shaft",),
                  inputs=("shaft", "lubricant", "skf_bearing"), outputs=_shaft_outputs("(SKF)"),
                  compute=_shaft_skf_friction)),
))
