"""Bearings as mounted (effect `mounting`, [mounting] table): the operating clearance left by the
fits, the temperatures and the rings' speed (`operating_clearance`), which the equilibrium then
uses in place of the bearing's own clearance."""

import jax

from ...operating_clearance import RING_EXPANSION, SEAT_MATERIALS, Mounting, operating_clearance_change
from ...params import BALL_BEARING_KINDS, radial_clearance
from ...roller_geometry import ROLLER_KINDS
from ..registry import Adapter, Block, InputBuilder, Key, Output, quantity, register

TEMPERATURES = ("inner_ring", "outer_ring", "shaft", "housing")
ROUGHNESSES = ("shaft", "inner_ring", "outer_ring", "housing")  # Rz of the shaft seat, ring bore, ring outside, housing bore
EFFECT_ON = "effects.mounting"
WHOLE_BEARING = ("operating.force",)  # a whole roller bearing's layout (as adapters/roller_bearing.py)


def _mounting(v, built) -> dict:
    """The Mounting of the scene's [mounting] table, or None without `effects.mounting`."""
    if v.get(EFFECT_ON, False) is not True:
        return {"mounting": None}
    shaft, shaft_expansion = SEAT_MATERIALS[v.get("mounting.shaft_material", "steel")]
    housing, housing_expansion = SEAT_MATERIALS[v.get("mounting.housing_material", "steel")]
    reference = v.get("mounting.reference_temperature", 293.15)
    return {"mounting": Mounting(
        shaft_interference=v.get("mounting.shaft_interference", 0.0),
        housing_interference=v.get("mounting.housing_interference", 0.0),
        shaft_bore=v.get("mounting.shaft_bore", 0.0),
        housing_outer_diameter=v.get("mounting.housing_outer_diameter"),
        roughness=tuple(v.get(f"mounting.{part}_roughness", 0.0) for part in ROUGHNESSES),
        **{f"{part}_temperature": v.get(f"mounting.{part}_temperature", reference) for part in TEMPERATURES},
        reference_temperature=reference,
        ring_expansion=RING_EXPANSION, element_expansion=RING_EXPANSION,
        shaft_expansion=v.get("mounting.shaft_expansion", shaft_expansion),
        housing_expansion=v.get("mounting.housing_expansion", housing_expansion),
        shaft=shaft, housing=housing,
    )}


def _seat_diameters(v):
    """(bore, outside diameter) [m] of the bearing; ValueError where the scene lacks them."""
    if "bearing.bore" not in v or "bearing.outer_diameter" not in v:
        raise ValueError("effects.mounting needs bearing.bore and bearing.outer_diameter (the rings' thickness "
                         "for the fits)")
    return v["bearing.bore"], v["bearing.outer_diameter"]


def clearance_change(v, mounting: Mounting, pitch, element, material, inner_speed, outer_speed):
    """`operating_clearance_change` of a bearing whose rings run from the bore to d_m − D and from
    d_m + D to the outside (D the ball, or the cylindrical roller, diameter)."""
    bore, outside = _seat_diameters(v)
    return operating_clearance_change(mounting, bore, pitch - element, pitch + element, outside, element, material,
                                      inner_speed, outer_speed)


def _speeds(v):
    return v.get("operating.inner_speed", 0.0), v.get("operating.outer_speed", 0.0)


def ball_operating_clearance(v, bearing, mounting: Mounting):
    """The diametral clearance [m] a ball bearing runs with: its own changed by the mounting;
    ValueError where the fits and temperatures close it below zero (the ball model takes G_r ≥ 0)."""
    own = radial_clearance(bearing)
    change = clearance_change(v, mounting, bearing.pitch_diameter, bearing.ball_diameter, bearing.ring_material,
                              *_speeds(v)).change
    running = own + change
    if not isinstance(running, jax.core.Tracer) and float(running) < 0.0:  # a sweep's tracers are not checked
        raise ValueError(f"[mounting]: the operating clearance is {float(running) * 1e6:.3g} µm (the bearing's "
                         f"{float(own) * 1e6:.3g} µm changed by {float(change) * 1e6:.3g} µm): the ball model takes "
                         f"clearances ≥ 0; loosen the fits or give the bearing more clearance")
    return running


def roller_operating_clearance(v, bearing, clearance, mounting: Mounting):
    """The diametral clearance [m] a cylindrical roller bearing runs with: `clearance` changed by
    the mounting (negative: preloaded); ValueError for a tapered roller bearing, whose clearance
    is its axial setting."""
    if bearing.kind != "cylindrical_roller":
        raise ValueError("effects.mounting: ball and cylindrical roller bearings (a tapered roller bearing's clearance "
                         "is its axial setting)")
    return clearance + clearance_change(v, mounting, v["bearing.pitch_diameter"], bearing.large_diameter,
                                        bearing.material, *_speeds(v)).change


def _outputs(change, running) -> dict:
    return {
        "mounting.clearance_change": change.change,
        "mounting.operating_clearance": running,
        "mounting.bearing_clearance": running - change.change,
        "mounting.shaft_fit": change.shaft_fit,
        "mounting.housing_fit": change.housing_fit,
        "mounting.thermal": change.thermal,
        "mounting.centrifugal": change.centrifugal,
        "mounting.fit_pressure_inner": change.fit_pressure_inner,
        "mounting.fit_pressure_outer": change.fit_pressure_outer,
        "mounting.hoop_stress_inner": change.hoop_stress_inner,
    }


def _ball_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, mounting, operating = inputs["bearing"], inputs["mounting"], inputs["operating"]
    change = operating_clearance_change(
        mounting, bearing.bore, bearing.pitch_diameter - bearing.ball_diameter,
        bearing.pitch_diameter + bearing.ball_diameter, bearing.outer_diameter, bearing.ball_diameter,
        bearing.ring_material, operating.inner_speed, operating.outer_speed)
    return _outputs(change, radial_clearance(bearing))


def _roller_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, raceways, operating, seats = inputs["bearing"], inputs["raceways"], inputs["operating"], inputs["seats"]
    pitch, roller = raceways.pitch_diameter, bearing.large_diameter
    change = operating_clearance_change(inputs["mounting"], seats[0], pitch - roller, pitch + roller, seats[1], roller,
                                        bearing.material, operating.inner_speed, operating.outer_speed)
    return _outputs(change, raceways.diametral_clearance)


def _seats(v, built) -> dict:
    """(bore, outside diameter) [m] of a roller bearing with `effects.mounting`."""
    return {"seats": None if built["mounting"] is None else _seat_diameters(v)}


def _checks(values: dict) -> tuple[list[str], list[str]]:
    running = float(values["mounting.operating_clearance"])
    return [], ([f"the operating clearance is {running * 1e6:.3g} µm: the fits and temperatures leave no clearance "
                 f"(the bearing runs preloaded)"] if running <= 0.0 else [])


OUTPUTS = (
    Output("mounting.clearance_change", "m", "um", "change of the diametral clearance by the mounting"),
    Output("mounting.operating_clearance", "m", "um", "operating diametral clearance (the equilibrium's)"),
    Output("mounting.bearing_clearance", "m", "um", "the bearing's diametral clearance before mounting"),
    Output("mounting.shaft_fit", "m", "um", "clearance change by the shaft fit"),
    Output("mounting.housing_fit", "m", "um", "clearance change by the housing fit"),
    Output("mounting.thermal", "m", "um", "clearance change by the temperatures"),
    Output("mounting.centrifugal", "m", "um", "clearance change by the rings' speed"),
    Output("mounting.fit_pressure_inner", "Pa", "MPa", "fit pressure, inner ring on the shaft"),
    Output("mounting.fit_pressure_outer", "Pa", "MPa", "fit pressure, outer ring in the housing"),
    Output("mounting.hoop_stress_inner", "Pa", "MPa", "hoop stress at the inner ring's bore"),
)


ADAPTER = register(Adapter(
    name="mounting",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={
        EFFECT_ON: Key("boolean", doc="operating clearance from the [mounting] table"),
        "bearing.bore": quantity("length"),
        "bearing.outer_diameter": quantity("length"),
        "mounting.shaft_interference": quantity("length", "diametral interference of the inner ring on the shaft "
                                                          "(negative: a loose fit)"),
        "mounting.housing_interference": quantity("length", "diametral interference of the outer ring in the housing "
                                                            "(negative: a loose fit)"),
        "mounting.shaft_bore": quantity("length", "bore of a hollow shaft (default 0: solid)"),
        "mounting.housing_outer_diameter": quantity("length", "outside diameter of the housing (default: a large "
                                                              "housing)"),
        **{f"mounting.{part}_roughness": quantity("length", f"Rz of the {part.replace('_', ' ')} fit surface: the fit "
                                                            "loses 0.4 Rz per surface on the radius (DIN 7190)")
           for part in ROUGHNESSES},
        **{f"mounting.{part}_temperature": quantity("temperature", f"{part.replace('_', ' ')} temperature (default: "
                                                                  "the reference)") for part in TEMPERATURES},
        "mounting.reference_temperature": quantity("temperature", "temperature of the fits and clearance as given "
                                                                  "(default 20 °C)"),
        "mounting.shaft_material": Key("choice", choices=tuple(SEAT_MATERIALS), doc="default steel"),
        "mounting.housing_material": Key("choice", choices=tuple(SEAT_MATERIALS), doc="default steel"),
        "mounting.shaft_expansion": quantity("thermal_expansion", "linear expansion coefficient (default: the "
                                                                  "material's)"),
        "mounting.housing_expansion": quantity("thermal_expansion", "linear expansion coefficient (default: the "
                                                                    "material's)"),
    },
    inputs=(InputBuilder(("mounting",), BALL_BEARING_KINDS + ROLLER_KINDS, _mounting),
            InputBuilder(("seats",), ROLLER_KINDS, _seats, after=("mounting",), scene_keys=WHOLE_BEARING)),
    blocks=(Block(
        name="mounting",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("mounting", True),
        requires=(),
        inputs=("bearing", "mounting", "operating"),
        outputs=OUTPUTS,
        compute=_ball_outputs,
        checks=_checks,
    ), Block(
        name="roller_mounting",
        bearing_types=ROLLER_KINDS,
        enabled_by=("mounting", True),
        requires=(),
        inputs=("bearing", "raceways", "mounting", "operating", "seats"),
        outputs=OUTPUTS,
        compute=_roller_outputs,
        checks=_checks,
        scene_keys=WHOLE_BEARING,
    )),
))

