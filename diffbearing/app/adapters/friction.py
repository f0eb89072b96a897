"""Friction torque and power loss (effect friction = "palmgren"): Palmgren's viscous and
load-dependent moments (`diffbearing.friction_torque`) from the loads the elements carry, the
lubricant's viscosity at its temperature and the speed."""

import jax.numpy as jnp

from ... import friction_torque, static_safety
from ...params import BALL_BEARING_KINDS, check_range
from ...roller_geometry import ROLLER_KINDS
from ..registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, register
from .bearing_set import SET, SET_SIZE
from .life import SUPPLY_KEY
from .roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING

FRICTION_MODELS = ("palmgren",)
DEFAULT_SUPPLY = "oil_bath"


def _f0(v, kind: str):
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
    return {"friction_constants": {"f0": _f0(v, built["bearing"].kind), "f1": _f1(v)}}


def _kind(bearing) -> str:
    """The kind of a shaft layout's bearing (a BallBearing, or a (RollerBearing, RollerRaceways) pair)."""
    return bearing[0].kind if isinstance(bearing, tuple) else bearing.kind


def _shaft_constants(v, built) -> dict:
    """f₀ of each of the shaft's bearings (a tuple), the scene's f₁ or None."""
    return {"friction_constants": {"f0": tuple(_f0(v, _kind(bearing)) for bearing in built["shaft"].bearings),
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


def _ball_torques(bearing, f0, f1, lubricant, speed, force):
    """`_torques` of a ball bearing under [Fx, Fy, Fz] [N] (P₀, C₀ of ISO 76)."""
    return _torques(bearing.kind, f0, f1, lubricant, speed, bearing.pitch_diameter, *_split(force),
                    static_safety.ball_bearing_equivalent_static_load(bearing, force),
                    static_safety.ball_bearing_static_load_rating(bearing))


def _roller_torques(bearing, raceways, f0, f1, lubricant, speed, force):
    """`_torques` of a roller bearing under [Fx, Fy, Fz] [N]."""
    return _torques(bearing.kind, f0, f1, lubricant, speed, raceways.pitch_diameter, *_split(force), None, None,
                    raceways.cup_angle)


def _speed(operating):
    return operating.inner_speed - operating.outer_speed


def _ball_friction(inputs: dict, settings: dict, results: dict) -> dict:
    constants = inputs["friction_constants"]
    return _ball_torques(inputs["bearing"], constants["f0"], constants["f1"], inputs["lubricant"],
                         _speed(inputs["operating"]), results["force"][:3])


def _roller_friction(inputs: dict, settings: dict, results: dict) -> dict:
    constants = inputs["friction_constants"]
    return _roller_torques(inputs["bearing"], inputs["raceways"], constants["f0"], constants["f1"], inputs["lubricant"],
                           _speed(inputs["operating"]), results["force"][:3])


def _set_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each bearing's Palmgren torque from its own load, and the set's together."""
    constants, speed = inputs["friction_constants"], _speed(inputs["operating"])
    torques = [_ball_torques(inputs["bearing"], constants["f0"], constants["f1"], inputs["lubricant"], speed,
                             results[f"set.bearings.{number}.force"][:3])["friction.torque"] for number in range(SET_SIZE)]
    return ({f"set.bearings.{number}.friction.torque": torque for number, torque in enumerate(torques)}
            | {"set.friction.torque": sum(torques), "set.friction.power": friction_torque.friction_power(sum(torques), speed)})


def _shaft_friction(inputs: dict, settings: dict, results: dict) -> dict:
    """Each of the shaft's bearings' Palmgren torque from its own load, and the shaft's together."""
    layout, constants, lubricant = inputs["shaft"], inputs["friction_constants"], inputs["lubricant"]
    torques = []
    for number, (bearing, f0) in enumerate(zip(layout.bearings, constants["f0"])):
        force = results["bearings.force"][number][:3]
        found = (_roller_torques(*bearing, f0, constants["f1"], lubricant, layout.speed, force)
                 if isinstance(bearing, tuple) else
                 _ball_torques(bearing, f0, constants["f1"], lubricant, layout.speed, force))
        torques.append(found["friction.torque"])
    return {"bearings.friction.torque": jnp.stack(torques), "shaft.friction.torque": sum(torques),
            "shaft.friction.power": friction_torque.friction_power(sum(torques), layout.speed)}


OUTPUTS = (
    Output("friction.torque", "N*m", "N*mm", "friction torque M = M0 + M1 (Palmgren)"),
    Output("friction.viscous_torque", "N*m", "N*mm", "viscous moment M0"),
    Output("friction.load_torque", "N*m", "N*mm", "load-dependent moment M1 = f1 P1 dm"),
    Output("friction.power", "W", "W", "power loss M ω"),
    Output("friction.f0", "", "", "Palmgren f0 (the scene's, else HR 1's)"),
    Output("friction.f1", "", "", "Palmgren f1 (the scene's, else HR 1's)"),
    Output("friction.load", "N", "kN", "load P1 of the moment M1"),
)

ADAPTER = register(Adapter(
    name="friction",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"effects.friction": Key("choice", choices=FRICTION_MODELS, doc="friction torque and power loss"),
          "friction.f0": Key("number", doc="Palmgren's f0 of the bearing's series and lubrication (default: HR 1's "
                                           "62 / 72-B / 2..-E / 302 series)"),
          "friction.f1": Key("number", doc="Palmgren's f1 (default: HR 1's, a (P0/C0)^b for ball bearings)"),
          "lubricant.supply": SUPPLY_KEY},
    inputs=(InputBuilder(("friction_constants",), BALL_BEARING_KINDS + ROLLER_KINDS, _constants, after=("bearing",)),
            InputBuilder(("friction_constants",), SHAFT, _shaft_constants, after=("shaft",))),
    blocks=(Block(
        name="friction",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("friction", "palmgren"),
        requires=("equilibrium",),
        inputs=("bearing", "operating", "lubricant", "friction_constants"),
        outputs=OUTPUTS,
        compute=_ball_friction,
    ), Block(
        name="roller_friction",
        bearing_types=ROLLER_KINDS,
        enabled_by=("friction", "palmgren"),
        requires=(EQUILIBRIUM_BLOCK,),
        inputs=("bearing", "raceways", "operating", "lubricant", "friction_constants"),
        outputs=OUTPUTS,
        compute=_roller_friction,
        scene_keys=WHOLE_BEARING,
    ), Block(
        name="set_friction",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("friction", "palmgren"),
        requires=("bearing_set",),
        inputs=("bearing", "operating", "lubricant", "friction_constants"),
        outputs=(*(Output(f"set.bearings.{number}.friction.torque", "N*m", "N*mm",
                          f"bearing {number}: friction torque M0 + M1") for number in range(SET_SIZE)),
                 Output("set.friction.torque", "N*m", "N*mm", "friction torque of the set"),
                 Output("set.friction.power", "W", "W", "power loss of the set")),
        compute=_set_friction,
        scene_keys=SET,
    ), Block(
        name="shaft_friction",
        bearing_types=SHAFT,
        enabled_by=("friction", "palmgren"),
        requires=("shaft",),
        inputs=("shaft", "lubricant", "friction_constants"),
        outputs=(Output("bearings.friction.torque", "N*m", "N*mm", "each bearing's friction torque M0 + M1",
                        in_report=False),
                 Output("shaft.friction.torque", "N*m", "N*mm", "friction torque of the shaft's bearings"),
                 Output("shaft.friction.power", "W", "W", "power loss of the shaft's bearings")),
        compute=_shaft_friction,
    )),
))
