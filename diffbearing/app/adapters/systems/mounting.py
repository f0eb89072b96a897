"""Bearings as mounted (effect `mounting`, [mounting] table): the operating clearance left by the
fits, the temperatures and the rings' speed (`operating_clearance`), which the equilibrium then
uses in place of the bearing's own clearance (negative: a preloaded bearing). On a shaft the table
applies to every bearing (a fit class at each bearing's own d and D), whose types take a mounting
(`AbstractSupport.ring_section`), and the shaft and its effects run at those clearances."""

import dataclasses

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....params import BALL_BEARING_KINDS, check_range, radial_clearance
from ....systems import bearing_fits
from ....systems.operating_clearance import (
    RING_EXPANSION,
    SEAT_MATERIALS,
    Mounting,
    OperatingClearance,
    mounted_clearance_change,
    operating_clearance_change,
)
from ....thermal.axial_growth import mounted_axial_growth
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register
from ..materials import material
from .shaft_layout import ShaftLayout, layout_supports, shaft_layout

TEMPERATURES = ("inner_ring", "outer_ring", "shaft", "housing")
ROUGHNESSES = ("shaft", "inner_ring", "outer_ring", "housing")  # Rz of the shaft seat, ring bore, ring outside, housing bore
EFFECT_ON = "effects.mounting"
# The envelope of the fit and temperature model (docs/theory.md §Envelopes): linear expansion and
# elastic rings hold for through-hardened bearing steel from −60 °C to +250 °C (its dimensional
# stabilisation classes end at 250 °C, SN at 120 °C); an interference above 1 % of the fit diameter
# lies beyond every ISO 286 fit and the rings' elastic range; expansion coefficients of engineering
# metals and filled polymers lie in (0, 1e-4) 1/K.
TEMPERATURE_RANGE = (213.15, 523.15)  # K
INTERFERENCE_SHARE = 0.01  # of the fit diameter
EXPANSION_LIMIT = 1e-4  # 1/K
OPERATING_CLEARANCE_FLOOR = 0.01  # of d_m: −G_r above that is outside the preloaded bearing's model
WHOLE_BEARING = ("operating.force",)  # a whole roller bearing's layout (as adapters/roller_bearing.py)
SHAFT_LAYOUT = (EFFECT_ON, "!effects.thermal")  # a shaft's layout built here (the shaft's own without effects.mounting)


def mounting_input(v, built) -> dict:
    """The change of clearance (`OperatingClearance`) of the scene's [mounting] table, or None
    without `effects.mounting`: computed once here, added to the clearance by the bearing's own
    builder and reported by the blocks below."""
    if v.get(EFFECT_ON, False) is not True:
        return {"mounting": None}
    return {"mounting": clearance_change(v, scene_mounting(v))}


def scene_mounting(v, diameters=None, where: str = "bearing") -> Mounting:
    """The [mounting] table's fits, seats and temperatures as a `Mounting` (checked: `_check_envelope`)
    of the bearing of bore and outside diameter `diameters` [m] (default: the scene's bearing.bore
    and bearing.outer_diameter; `where` names a shaft's bearing, "bearings[k]", in the messages)."""
    if diameters is None:
        if "bearing.bore" not in v or "bearing.outer_diameter" not in v:
            raise ValueError("effects.mounting needs bearing.bore and bearing.outer_diameter (the rings' thickness "
                             "for the fits)")
        diameters = (v["bearing.bore"], v["bearing.outer_diameter"])
    bore, outside = diameters
    _check_envelope(v, bore, outside, where)
    shaft, shaft_expansion = SEAT_MATERIALS[v.get("mounting.shaft_material", "steel")]
    housing, housing_expansion = SEAT_MATERIALS[v.get("mounting.housing_material", "steel")]
    reference = v.get("mounting.reference_temperature", 293.15)
    return Mounting(
        shaft_interference=_interference(v, "shaft", bore, bearing_fits.shaft_interference),
        housing_interference=_interference(v, "housing", outside, bearing_fits.housing_interference),
        shaft_bore=v.get("mounting.shaft_bore", 0.0),
        housing_outer_diameter=v.get("mounting.housing_outer_diameter"),
        roughness=tuple(v.get(f"mounting.{part}_roughness", 0.0) for part in ROUGHNESSES),
        **{f"{part}_temperature": v.get(f"mounting.{part}_temperature", reference) for part in TEMPERATURES},
        reference_temperature=reference,
        ring_expansion=RING_EXPANSION, element_expansion=RING_EXPANSION,
        shaft_expansion=v.get("mounting.shaft_expansion", shaft_expansion),
        housing_expansion=v.get("mounting.housing_expansion", housing_expansion),
        shaft=shaft, housing=housing,
    )


def clearance_change(v, mounting: Mounting) -> OperatingClearance:
    """The change of clearance `mounting` makes to the scene's bearing at its speed."""
    # the rings run from the bore to d_m − D and from d_m + D to the outside (D the ball, or the
    # cylindrical roller, diameter)
    pitch = v["bearing.pitch_diameter"]
    element = v["bearing.ball_diameter"] if "bearing.ball_diameter" in v else v["bearing.roller_diameter"]
    return operating_clearance_change(
        mounting, v["bearing.bore"], pitch - element, pitch + element, v["bearing.outer_diameter"], element,
        material(v), v.get("operating.inner_speed", 0.0), v.get("operating.outer_speed", 0.0))


def shaft_mountings(v, layout: ShaftLayout) -> tuple[Mounting, ...]:
    """The [mounting] table as each of a shaft's bearings' `Mounting`: the same fits (a class's
    interference at each bearing's own d and D), seats and temperatures. ValueError names the
    [[bearings]] entry whose type takes no mounting or that gives no bore or outer_diameter."""
    found = []
    for number, (support, diameters, kind) in enumerate(zip(layout_supports(layout), layout.envelopes, layout.kinds)):
        if support.ring_section() is None:
            raise ValueError(f"bearings[{number}].type: a {kind} bearing takes no mounting (effects.mounting: ball "
                             "and cylindrical roller bearings; a tapered one's clearance is its axial setting)")
        if any(diameter is None for diameter in diameters):
            raise ValueError(f"bearings[{number}]: bore and outer_diameter are needed by effects.mounting (the rings' "
                             "thickness for the fits)")
        found.append(scene_mounting(v, diameters, f"bearings[{number}]"))
    return tuple(found)


def mounted_layout(v, layout: ShaftLayout, mountings) -> tuple[ShaftLayout, tuple[OperatingClearance, ...]]:
    """(the layout with each bearing's clearance change by its `mountings` entry at the shaft's speed
    and the shaft's and housing's axial growth between the bearings at their temperatures
    (`axial_growth.mounted_axial_growth`), those changes). ValueError names the scene key behind a
    clearance closed below the model's floor (`operating_clearance`), prefixed by its [[bearings]] entry."""
    changes = []
    for number, (support, mounting, (bore, outside)) in enumerate(zip(layout_supports(layout), mountings,
                                                                      layout.envelopes)):
        change = mounted_clearance_change(support, mounting, bore, outside, layout.speed)
        try:
            operating_clearance(support.ring_section().clearance, change, 2.0 * support.pitch_radius(), v)
        except ValueError as error:
            raise ValueError(f"bearings[{number}]: {error}") from None
        changes.append(change)
    moved = eqx.tree_at(lambda shaft: (shaft.clearance_changes, shaft.axial_growth), layout,
                        (jnp.stack([change.change for change in changes]),
                         mounted_axial_growth(layout.positions, tuple(mountings))),
                        is_leaf=lambda node: node is None)
    return moved, tuple(changes)


def shaft_input(v, built) -> dict:
    """The shaft's layout (`shaft.shaft_layout`) and, with `effects.mounting`, each bearing's
    clearance change by the [mounting] table at its temperatures (the `mounting` input, a tuple)."""
    layout = shaft_layout(v, built)["shaft"]
    if v[EFFECT_ON] is not True:
        return {"shaft": layout, "mounting": None}
    moved, changes = mounted_layout(v, layout, shaft_mountings(v, layout))
    return {"shaft": moved, "mounting": changes}


def _check_envelope(v, bore, outside, where: str) -> None:
    """The [mounting] table inside the model's envelope (the constants above) for a bearing of bore
    and outside diameter `bore`, `outside` [m] (named `where`.bore, `where`.outer_diameter);
    ValueError names the key."""
    for name in ("reference", *TEMPERATURES):
        check_range(f"mounting.{name}_temperature", v.get(f"mounting.{name}_temperature"), low=TEMPERATURE_RANGE[0],
                    high=TEMPERATURE_RANGE[1], low_open=False, high_open=False, unit=" K", why="−60 °C to 250 °C")
    for name in ("shaft_expansion", "housing_expansion"):
        check_range(f"mounting.{name}", v.get(f"mounting.{name}"), low=0.0, high=EXPANSION_LIMIT, unit=" 1/K")
    for seat, name, diameter in (("shaft", "bore", bore), ("housing", "outer_diameter", outside)):
        limit = INTERFERENCE_SHARE * diameter
        check_range(f"mounting.{seat}_interference", v.get(f"mounting.{seat}_interference"), low=-limit, high=limit,
                    low_open=False, high_open=False, unit=" m", why=f"±1 % of {where}.{name}")
    check_range("mounting.shaft_bore", v.get("mounting.shaft_bore"), low=0.0, high=bore, low_open=False,
                unit=" m", why=f"a hollow shaft's bore inside {where}.bore")
    check_range("mounting.housing_outer_diameter", v.get("mounting.housing_outer_diameter"),
                low=outside, unit=" m", why=f"a housing around {where}.outer_diameter")


def operating_clearance(own, change: OperatingClearance, pitch, v):
    """The operating diametral clearance [m]: the bearing's own `own` changed by its mounting. Where it
    falls below −1 % of d_m (`pitch` [m]), ValueError names the scene key behind the largest closing
    contribution (the fit's interference or class, the temperatures, the speed) rather than the
    bearing's clearance, which the user did not set wrong."""
    running = own + change.change
    if not any(isinstance(x, jax.core.Tracer) for x in (running, pitch)):  # a sweep's corners were checked
        floor = -OPERATING_CLEARANCE_FLOOR * float(pitch)
        if float(running) < floor:
            given = lambda seat: f"mounting.{seat}_tolerance" if f"mounting.{seat}_tolerance" in v \
                else f"mounting.{seat}_interference"
            culprits = {"shaft_fit": given("shaft"), "housing_fit": given("housing"),
                        "thermal": "mounting.inner_ring_temperature",
                        "centrifugal": "operating.inner_speed"}
            largest = min(culprits, key=lambda name: float(getattr(change, name)))
            raise ValueError(f"{culprits[largest]}: the mounting closes the clearance to {float(running) * 1e6:.4g} µm "
                             f"({largest.replace('_', ' ')} {float(getattr(change, largest)) * 1e6:.4g} µm), below the "
                             f"model's floor of −1 % of d_m ({floor * 1e6:.4g} µm)")
    return running


def _interference(v, seat: str, diameter, from_class):
    """The scene's diametral interference of the `seat` ("shaft", "housing") [m]: given, or from
    its ISO 286 class at the fit's `diameter` [m] and `mounting.fit_value` (`bearing_fits`), or 0."""
    given, tolerance = f"mounting.{seat}_interference", f"mounting.{seat}_tolerance"
    if given in v and tolerance in v:
        raise ValueError(f"[mounting]: give {given} or {tolerance}, not both")
    if tolerance in v:
        return from_class(v[tolerance], diameter, v.get("mounting.fit_value", "probable"))
    return v.get(given, 0.0)


def _outputs(change: OperatingClearance, running) -> dict:
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
        "mounting.effective_shaft_interference": change.shaft_interference,
        "mounting.effective_housing_interference": change.housing_interference,
    }


def _ball_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    return _outputs(inputs["mounting"], radial_clearance(inputs["bearing"]))


def _shaft_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    """Each bearing's `_outputs` (K,), its operating clearance that of its support as the shaft runs it."""
    running = [support.ring_section().clearance for support in layout_supports(inputs["shaft"], settings)]
    each = [_outputs(change, clearance) for change, clearance in zip(inputs["mounting"], running)]
    return ({f"bearings.{key}": jnp.stack([own[key] for own in each]) for key in each[0]}
            | {"bearings.mounting.axial_growth": inputs["shaft"].axial_growth})


def _roller_outputs(inputs: dict, settings: dict, results: dict) -> dict:
    return _outputs(inputs["mounting"], inputs["raceways"].diametral_clearance)


def _checks(values: dict) -> tuple[list[str], list[str]]:
    running = float(values["mounting.operating_clearance"])
    return [], ([f"the operating clearance is {running * 1e6:.3g} µm: the fits and temperatures leave no clearance "
                 f"(the bearing runs preloaded)"] if running <= 0.0 else [])


def _shaft_checks(values: dict) -> tuple[list[str], list[str]]:
    return [], [f"bearings[{number}]: the operating clearance is {float(running) * 1e6:.3g} µm: the fits and "
                "temperatures leave no clearance (the bearing runs preloaded)"
                for number, running in enumerate(np.asarray(values["bearings.mounting.operating_clearance"]))
                if running <= 0.0]


def _report(result) -> list[str]:
    """A shaft's bearings' clearances (a single bearing's are in the output table)."""
    values = result.values
    key = "bearings.mounting.operating_clearance"
    if key not in values or np.ndim(values[key]) != 1:
        return []
    lines = ["", "Operating clearance of each bearing, as mounted (diametral, µm; the [mounting] table's fits at "
                 "each bearing's d and D)",
             f"  {'#':<4}{'as given':>10}{'shaft fit':>11}{'housing fit':>13}{'thermal':>9}{'speed':>8}{'operating':>11}"
             f"{'axial growth':>14}"]
    for number in range(len(values[key])):
        row = [values[f"bearings.mounting.{name}"][number] * 1e6 for name in (
            "bearing_clearance", "shaft_fit", "housing_fit", "thermal", "centrifugal", "operating_clearance",
            "axial_growth")]
        lines.append(f"  {number:<4}" + "".join(f"{value:>{width}.2f}"
                                                for value, width in zip(row, (10, 11, 13, 9, 8, 11, 14))))
    return lines + ["  axial growth: the inner ring's axial shift against the outer ring by the shaft's and the "
                    "housing's growth between the bearings, about their mean (each locating bearing's offset "
                    "moves by it; a common shift is the shaft's own)"]


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
    Output("mounting.effective_shaft_interference", "m", "um", "effective shaft interference (smoothed, at temperature)"),
    Output("mounting.effective_housing_interference", "m", "um", "effective housing interference (smoothed, at temperature)"),
)


ADAPTER = register(Adapter(
    name="mounting",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={
        EFFECT_ON: Key("boolean", doc="operating clearance from the [mounting] table"),
        "bearing.bore": quantity("length"),
        "bearing.outer_diameter": quantity("length"),
        "mounting.shaft_interference": quantity("length", "diametral interference of the inner ring on the shaft "
                                                          "(negative: a loose fit)"),
        "mounting.housing_interference": quantity("length", "diametral interference of the outer ring in the housing "
                                                            "(negative: a loose fit)"),
        "mounting.shaft_tolerance": Key("text", doc="ISO 286 class of the shaft seat (g, h, j, js, k, m, n, p; grades 5–7), "
                                                    "instead of shaft_interference; with the ring's ISO 492 Normal bore"),
        "mounting.housing_tolerance": Key("text", doc="ISO 286 class of the housing seat (G, H, J, JS, K, M, N, P; grades 6, "
                                                      "7), instead of housing_interference; with the ring's ISO 492 "
                                                      "Normal outside"),
        "mounting.fit_value": Key("choice", choices=bearing_fits.FIT_VALUES,
                                  doc="which interference of the classes: probable (the mean, default), max or min"),
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
    # a ball bearing's with effects.thermal: the thermal effect's, at the temperatures it solves
    inputs=(InputBuilder(("mounting",), BALL_BEARING_KINDS, mounting_input, scene_keys=("!effects.thermal",)),
            InputBuilder(("mounting",), ROLLER_KINDS, mounting_input),
            # a shaft's layout with its bearings as mounted (with effects.thermal: the thermal effect's)
            InputBuilder(("shaft", "mounting"), SHAFT, shaft_input, scene_keys=SHAFT_LAYOUT)),
    blocks=(Block(
        name="mounting",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("mounting", True),
        requires=(),
        inputs=("bearing", "mounting"),
        outputs=OUTPUTS,
        compute=_ball_outputs,
        checks=_checks,
    ), Block(
        name="roller_mounting",
        bearing_types=ROLLER_KINDS,
        enabled_by=("mounting", True),
        requires=(),
        inputs=("raceways", "mounting"),
        outputs=OUTPUTS,
        compute=_roller_outputs,
        checks=_checks,
        scene_keys=WHOLE_BEARING,
    ), Block(
        name="shaft_mounting",
        bearing_types=SHAFT,
        enabled_by=("mounting", True),
        requires=(),
        inputs=("shaft", "mounting"),
        outputs=tuple(dataclasses.replace(output, key=f"bearings.{output.key}", in_report=False) for output in OUTPUTS)
        + (Output("bearings.mounting.axial_growth", "m", "um", "each bearing's inner ring's axial shift against its outer "
                  "ring by the shaft's and the housing's growth between the bearings (about their mean)",
                  in_report=False),),
        compute=_shaft_outputs,
        checks=_shaft_checks,
    )),
    report=_report,
))

