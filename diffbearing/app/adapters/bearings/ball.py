"""Ball bearings: geometry, Hertz constants at the free contact angle, the quasi-static
equilibrium with its load distribution (always), the stiffness matrix (effect `stiffness`)."""

import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.ball import ball_equilibrium, ball_validity, groove_chamfer
from ....bearings.ball.ball_support import BallSupport
from ....bearings.ball.kinematics import RACE_CONTROLS
from ....bearings.ball.raceway_contact import ContactConstantTable, ball_raceway_modulus, both_curvatures, diameter_ratio
from ....contact import hertz
from ....params import (
    BALL_BEARING_KINDS,
    Operating,
    ball_bearing,
    groove_curvature_centre_distance,
    radial_clearance,
    with_radial_clearance,
)
from ...formatting import element_table_lines, format_number, state_column, stiffness_lines, swept_display, to_display
from ...registry import Adapter, Block, InputBuilder, Key, Mounting, Output, all_keys, quantity, register
from ..materials import material
from ..systems.mounting import operating_clearance

# ISO 76:2006, 7.1: contact stress limit at the basic static load rating of ball bearings.
ISO76_BALL_PRESSURE_LIMIT = 4.2e9  # Pa

BALL_KEYS = ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls",
             ("bearing.inner_groove_radius", "bearing.inner_groove_ratio"),
             ("bearing.outer_groove_radius", "bearing.outer_groove_ratio"),
             ("bearing.contact_angle", "bearing.radial_clearance"))


def _bearing(v, built) -> dict:
    """The bearing; with `effects.mounting`, at its operating clearance (`mounting.operating_clearance`)."""
    ring = material(v)
    bearing = catalogue_bearing(v, ring)
    if built["mounting"] is None:
        return {"bearing": bearing}
    return {"bearing": with_radial_clearance(bearing, operating_clearance(radial_clearance(bearing), built["mounting"],
                                                                          v["bearing.pitch_diameter"], v))}


def catalogue_bearing(v, ring, kind=None, clearance=True):
    """The scene's bearing as its [bearing] table gives it (SI values), rings of `ring`; `kind` for
    a row of another type's (default: the table's type), its clearance not read with `clearance`
    False (a type that takes the key itself)."""
    return ball_bearing(
        kind=kind or v["bearing.type"],
        ball_diameter=v["bearing.ball_diameter"], pitch_diameter=v["bearing.pitch_diameter"],
        balls=v["bearing.balls"],
        inner_groove_ratio=v.get("bearing.inner_groove_ratio"),
        outer_groove_ratio=v.get("bearing.outer_groove_ratio"),
        inner_groove_radius=v.get("bearing.inner_groove_radius"),
        outer_groove_radius=v.get("bearing.outer_groove_radius"),
        contact_angle=v.get("bearing.contact_angle"),
        radial_clearance=v.get("bearing.radial_clearance") if clearance else None,
        ball_material=material(v, "ball_", ring), ring_material=ring,
        bore=v.get("bearing.bore"), outer_diameter=v.get("bearing.outer_diameter"),
        dynamic_load_rating=v.get("bearing.dynamic_load_rating"),
    )


def require(v, keys) -> None:
    """ValueError naming the first of `keys` the scene's table (or a [[bearings]] entry) lacks."""
    for key in keys:
        if key not in v:
            raise ValueError(f"missing required key '{key}'")


# n·d_m [mm·r/min]: above the first, oil-lubricated ball bearings need special designs (the
# catalogues' limiting speeds of standard bearings stay below 1e6); beyond the second, far past any
# rolling bearing (aero-engine main-shaft bearings run at 2–3e6, test rigs have reached about 4e6;
# the aero paper's own speed sweep, aero_speed_sweep, ends at 5e6), the input is a slip of units.
SPEED_FACTOR_WARNING, SPEED_FACTOR_LIMIT = 1.0e6, 1.0e7
# shared with the tapered roller bearing (`roller_bearing`)
AXIAL_DISPLACEMENT_KEY = quantity("length", "imposed axial displacement δz of the inner ring (ball and tapered roller "
                                            "bearings; preload or setting by displacement): Fz must be 0, the axial "
                                            "force is then an output")


def speed_factor(speed, pitch_diameter):
    """n·d_m [mm·r/min] of a ring speed [rad/s] on a pitch diameter [m] (arrays, or floats on the host)."""
    return abs(speed) * 30.0 / np.pi * pitch_diameter * 1e3


def check_speed_factor(v, pitch_key: str = "bearing.pitch_diameter") -> None:
    """Refuse a ring speed beyond `SPEED_FACTOR_LIMIT` n·d_m (ValueError naming the speed key)."""
    pitch = v.get(pitch_key)
    for key in ("operating.inner_speed", "operating.outer_speed"):
        speed = v.get(key)
        if speed is None or pitch is None or isinstance(speed, jax.core.Tracer) or isinstance(pitch, jax.core.Tracer):
            continue
        factor = speed_factor(float(speed), float(pitch))
        if factor > SPEED_FACTOR_LIMIT:
            raise ValueError(f"{key}: n·d_m = {factor:.3g} mm·r/min is far beyond any rolling bearing (limit "
                             f"{SPEED_FACTOR_LIMIT:.0e}; {float(speed) * 30 / np.pi:.4g} r/min on d_m = {pitch * 1e3:.4g} mm)")


SHOULDER_KEYS = ("bearing.inner_shoulder_diameter", "bearing.outer_shoulder_diameter")


def scene_shoulders(v, bearing):
    """The high shoulders' depths [h_i, h_o] above the groove bottoms [m] from both shoulder diameters
    (`groove_chamfer.shoulder_depths`), or None where the scene gives neither (no shoulder check);
    ValueError naming the key for one diameter alone or one outside its groove."""
    given = [key for key in SHOULDER_KEYS if key in v]
    if not given:
        return None
    if len(given) == 1:
        missing = next(key for key in SHOULDER_KEYS if key not in given)
        raise ValueError(f"{missing}: give both shoulder diameters with {given[0]} (the contact ellipses are checked "
                         "against both rings' shoulders)")
    diameters = [v[key] for key in SHOULDER_KEYS]
    if not any(isinstance(x, jax.core.Tracer) for x in (*diameters, *jax.tree.leaves(bearing))):
        inner_bottom, outer_bottom = (float(d) for d in groove_chamfer.groove_bottom_diameters(bearing))
        inner_centre = inner_bottom + 2.0 * float(bearing.inner_groove_ratio * bearing.ball_diameter)
        outer_centre = outer_bottom - 2.0 * float(bearing.outer_groove_ratio * bearing.ball_diameter)
        for key, diameter, low, high in zip(SHOULDER_KEYS, diameters, (inner_bottom, outer_centre),
                                            (inner_centre, outer_bottom)):
            if not low < float(diameter) < high:
                raise ValueError(f"{key} must be between {low * 1e3:.4g} mm and {high * 1e3:.4g} mm (between its "
                                 f"groove bottom and the groove curvature centre's height), got {float(diameter) * 1e3:.4g} mm")
    return jnp.stack(groove_chamfer.shoulder_depths(bearing, *diameters))


def _shoulders(v, built) -> dict:
    return {"shoulders": scene_shoulders(v, built["bearing"])}


def _operating(v, built) -> dict:
    check_speed_factor(v)
    return {"operating": Operating(
        inner_speed=v.get("operating.inner_speed", 0.0), outer_speed=v.get("operating.outer_speed", 0.0),
        force=v.get("operating.force", [0.0, 0.0, 0.0]), moment=v.get("operating.moment", [0.0, 0.0]),
        axial_displacement=v.get("operating.axial_displacement"), misalignment=v.get("operating.misalignment"),
        radial_displacement=v.get("operating.radial_displacement"),
    )}


def ball_model(settings: dict) -> ball_equilibrium.BallModel:
    """The static model options a scene's effects and fidelity tables select."""
    effects, fidelity = settings["effects"], settings["fidelity"]
    return ball_equilibrium.BallModel(
        centrifugal=effects.get("centrifugal", False) is True,
        gyroscopic=effects.get("gyroscopic", False) is True,
        race_control=fidelity.get("race_control", "outer"),
        hertz_method=fidelity.get("hertz", "exact"),
        hertz_constants=fidelity.get("hertz_constants", "contact_angle"),
    )


# --- raceway contact geometry and Hertz constants at the free contact angle ------------------

def _raceway_contact(inputs: dict, settings: dict, results: dict) -> dict:
    bearing = inputs["bearing"]
    method = settings["fidelity"].get("hertz", "exact")
    angle = jnp.asarray(bearing.free_contact_angle)
    modulus = ball_raceway_modulus(bearing)
    out = {
        "geometry.free_contact_angle": angle,
        "geometry.radial_clearance": radial_clearance(bearing),
        "geometry.groove_centre_distance": groove_curvature_centre_distance(bearing),
        "geometry.diameter_ratio": diameter_ratio(bearing, angle),
        "geometry.effective_modulus": modulus,
    }
    sums, differences = both_curvatures(bearing, angle, angle)
    both = hertz.point_contact(1.0, sums, differences, modulus, method)
    # p₀ ∝ Q^{1/3}: the load that reaches the ISO 76 limit follows from p₀ at 1 N.
    limits = (ISO76_BALL_PRESSURE_LIMIT / both.max_pressure) ** 3
    for k, side in enumerate(("inner", "outer")):
        out |= {
            f"hertz.{side}.curvature_sum": sums[k],
            f"hertz.{side}.curvature_difference": differences[k],
            f"hertz.{side}.ellipticity": both.ellipticity[k],
            f"hertz.{side}.load_deflection_constant": both.load_deflection_constant[k],
            f"hertz.{side}.static_limit_load": limits[k],
        }
    out["hertz.combined_load_deflection_constant"] = hertz.combined_load_deflection_constant(
        *both.load_deflection_constant)
    return out


def _side_outputs(side):
    return (
        Output(f"hertz.{side}.curvature_sum", "1/m", "1/mm", f"curvature sum Σρ, {side}"),
        Output(f"hertz.{side}.curvature_difference", "", "", f"curvature difference F(ρ), {side}"),
        Output(f"hertz.{side}.ellipticity", "", "", f"ellipticity κ = a/b, {side}"),
        Output(f"hertz.{side}.load_deflection_constant", "N/m**1.5", "N/mm**1.5",
               f"load–deflection constant K (Q = K δ^1.5), {side}"),
        Output(f"hertz.{side}.static_limit_load", "N", "kN", f"ball load at p0 = 4.2 GPa (ISO 76), {side}"),
    )


RACEWAY_CONTACT = Block(
    name="raceway_contact",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=None,
    requires=(),
    inputs=("bearing",),
    outputs=(
        Output("geometry.free_contact_angle", "rad", "deg", "free contact angle α0"),
        Output("geometry.radial_clearance", "m", "um", "diametral radial clearance Gr"),
        Output("geometry.groove_centre_distance", "m", "mm", "groove curvature centre distance (fi+fo−1)Dw"),
        Output("geometry.diameter_ratio", "", "", "γ = Dw cos α0 / dm"),
        Output("geometry.effective_modulus", "Pa", "GPa", "effective modulus E' of ball and ring"),
        *_side_outputs("inner"),
        *_side_outputs("outer"),
        Output("hertz.combined_load_deflection_constant", "N/m**1.5", "N/mm**1.5",
               "combined constant Kn, inner and outer in series"),
    ),
    compute=_raceway_contact,
)


# --- quasi-static equilibrium and load distribution ------------------------------------------

_BALL_FIELDS = ("load", "contact_angle", "max_pressure", "semi_major_axis", "semi_minor_axis")


def _equilibrium(inputs: dict, settings: dict, results: dict) -> dict:
    model = ball_model(settings)
    bearing, operating = inputs["bearing"], inputs["operating"]
    solution, balls = ball_equilibrium.solve_with_balls(bearing, operating, model)
    out = {"balls.centre": balls.centre, "displacement": solution.displacement, "force": solution.force,
           "prescribed": ball_equilibrium.prescribed_coordinates(operating),
           "free_tilt": free_tilt(solution.displacement, operating), "converged": solution.converged,
           "residual": solution.residual, "validity.approach_ratio": solution.approach_ratio,
           "validity.contact_angle": solution.contact_angle,
           "validity.lowest_contact_angle": low_shoulder_angle(bearing, balls),
           "validity.centrifugal_ratio": jax.lax.stop_gradient(centrifugal_ratio(balls, operating)),
           "validity.missing_axial_load": jax.lax.stop_gradient(missing_axial_load(bearing, operating)),
           "validity.speed_factor": jax.lax.stop_gradient(speed_factor(operating.inner_speed - operating.outer_speed,
                                                                       bearing.pitch_diameter)),
           "balls.azimuth": balls.azimuth,
           "balls.orbital_speed": balls.orbital_speed, "balls.spin_speed": balls.spin_speed}
    for side in ("inner", "outer"):
        out |= {f"balls.{side}.{field}": getattr(balls, f"{side}_{field}") for field in _BALL_FIELDS}
    if model.centrifugal:
        out["balls.centrifugal_force"] = balls.centrifugal_force
    if model.gyroscopic:
        out["balls.gyroscopic_moment"] = balls.gyroscopic_moment
    if solution.constant_table is not None:
        out |= {f"hertz.constant_table.{side}": getattr(solution.constant_table, side) for side in ("inner", "outer")}
    if inputs.get("shoulders") is not None:
        out |= shoulder_outputs(bearing, balls, inputs["shoulders"])
    return out


def shoulder_outputs(bearing, balls, depths) -> dict:
    """Each ball's share of its contact load beyond the shoulder edge (`groove_chamfer.truncated_load_share`)
    per raceway, and the largest angle [rad] by which a loaded contact's centre lies past its
    shoulder edge (negative: every contact centre on the groove). An angular-contact bearing's
    high shoulders face its positive contact angles; a deep-groove bearing has one each side."""
    out, overrun = {}, []
    for side, depth, ratio in (("inner", depths[0], bearing.inner_groove_ratio),
                               ("outer", depths[1], bearing.outer_groove_ratio)):
        angle = getattr(balls, f"{side}_contact_angle")
        towards = angle if bearing.kind == "angular_contact_ball" else jnp.abs(angle)
        radius = ratio * bearing.ball_diameter
        out[f"balls.{side}.shoulder_share"] = groove_chamfer.truncated_load_share(
            towards, getattr(balls, f"{side}_semi_major_axis"), radius, depth)
        past = towards - groove_chamfer.shoulder_angle(depth, radius)
        overrun.append(jnp.max(jnp.where(getattr(balls, f"{side}_load") > 0.0, past, -0.5 * jnp.pi)))
    out["validity.shoulder_overrun"] = jax.lax.stop_gradient(jnp.max(jnp.stack(overrun)))
    return out


LOW_SHOULDER_ROUNDING = 1e-9  # rad: a ball at the groove bottom (α = 0 within rounding) is inside


def low_shoulder_angle(bearing, balls):
    """`ball_validity.low_shoulder_angle` of a bearing's balls (`BallResults`), without derivative."""
    return jax.lax.stop_gradient(ball_validity.low_shoulder_angle(bearing, balls.inner_load, balls.inner_contact_angle,
                                                                  balls.outer_load, balls.outer_contact_angle))


def validity_errors(approach, angle, subject: str, lowest=None) -> list[str]:
    """Errors for a ball state outside the model (`ball_validity`): the largest approach / D_w and
    |contact angle| [rad] of `subject` ("equilibrium", "bearing 1", ...), and its lowest loaded
    contact angle [rad] (`low_shoulder_angle`)."""
    errors = []
    if lowest is not None and float(lowest) < -LOW_SHOULDER_ROUNDING:
        errors.append(f"{subject} outside the model: a ball loaded at α = {np.degrees(float(lowest)):.1f}° past its "
                      "raceway's edge (an angular-contact bearing's low-shoulder side, where its axial load, −z, pushes "
                      "the inner ring towards the open side: reverse operating.force[2] or the bearing; a four-point "
                      "bearing's groove bottom, past which the other half takes the contact)")
    if float(approach) > ball_validity.MAX_APPROACH_FRACTION:
        errors.append(f"{subject} outside the model: a contact approach of {float(approach) * 100:.3g} % of Dw passes "
                      f"the limit of {ball_validity.MAX_APPROACH_FRACTION * 100:g} % of Dw (Hertz theory's small "
                      "contacts)")
    if float(angle) >= float(ball_validity.MAX_CONTACT_ANGLE):
        errors.append(f"{subject} outside the model: a contact angle |α| = {np.degrees(float(angle)):.1f}° leaves "
                      "(−90°, 90°) (a ball pushed through its raceway, or at speed lifted over the inner groove's edge by its "
                      "centrifugal force under too light an axial load)")
    return errors


STEEP_CONTACT = np.radians(75.0)  # rad: a loaded contact this steep may ride on a shoulder (not modelled)
FREE_TILT_WARNING = 0.5e-3  # rad: a free inner ring tilting more than this without a moment is worth a word


def free_tilt(displacement, operating):
    """The inner ring's tilt √(θx² + θy²) [rad] where nothing holds it: its tilts free and no moment
    applied (0 otherwise); a diagnostic, without derivative."""
    if operating.misalignment is not None:
        return jnp.zeros(())
    tilt = jax.lax.stop_gradient(jnp.linalg.norm(displacement[3:]))
    return jnp.where(jnp.any(operating.moment != 0.0), 0.0, tilt)


def free_tilt_warnings(tilt) -> list[str]:
    """A warning where the inner ring tilts by more than `FREE_TILT_WARNING` with nothing holding it
    (`free_tilt`): a single bearing under combined load tilts freely unless a shaft holds it, which
    a catalogue calculation or ISO/TS 16281 takes as a given misalignment."""
    if float(np.max(tilt)) > FREE_TILT_WARNING:
        return [f"the inner ring tilts freely by {float(np.max(tilt)) * 1e3:.3g} mrad (no moment given): a bearing on a "
                "shaft is held by it; set operating.misalignment = [\"0 mrad\", \"0 mrad\"] to hold it aligned, or "
                "mount it on a shaft ([[bearings]])"]
    return []


def centrifugal_ratio(balls, operating):
    """The balls' largest centrifugal force over the applied load per ball |F|/Z [-] (0 without
    the centrifugal effect): far above 1 the speed lifts the balls off the inner raceway."""
    if balls.centrifugal_force is None:
        return jnp.zeros(())
    per_ball = jnp.linalg.norm(operating.force) / balls.centrifugal_force.shape[-1]
    return jnp.max(balls.centrifugal_force) / jnp.maximum(per_ball, 1e-300)


# Fa/(Fr tan α₀) of a single-row angular-contact bearing with half its balls loaded (the Sjövall
# integrals at ε = 0.5, Harris & Kotzalas vol. 1, ch. 7): below it the radial load's own axial
# component is not taken up, and in an arrangement the partner bearing carries it (the catalogues'
# requisite axial load, Fa ≥ R Fr, R = 1.14 for 40° bearings, SKF Rolling bearings 2018).
PARTNER_AXIAL_FACTOR = 1.25


def missing_axial_load(bearing, operating):
    """max(0, 1.25 F_r tan α₀ − F_z) [N] of an angular-contact bearing (0 for a deep-groove one): the
    axial load it lacks to run with half its balls loaded without a partner."""
    if bearing.kind == "deep_groove_ball":
        return jnp.zeros(())
    radial = jnp.sqrt(operating.force[0] ** 2 + operating.force[1] ** 2)
    return jnp.maximum(PARTNER_AXIAL_FACTOR * radial * jnp.tan(bearing.free_contact_angle) - operating.force[2], 0.0)


def without_partner(values: dict) -> str:
    """The reason a solve did not converge where an angular-contact bearing lacks axial load."""
    missing = float(values.get("validity.missing_axial_load", 0.0))
    if missing <= 0.0:
        return ""
    return (f": the axial load is {missing:.4g} N short of 1.25 F_r tan α₀, below which a single angular-contact "
            "bearing runs only against its partner (its balls pressed towards the low shoulder) — mount the pair as a "
            "set ([set]) or on a shaft")


def light_at_speed(values: dict) -> str:
    """The reason a solve at speed did not converge where the centrifugal force outweighs the load."""
    ratio = float(values.get("validity.centrifugal_ratio", 0.0))
    if ratio <= 1.0:
        return ""
    return (f": each ball's centrifugal force is {ratio:.3g}× the applied load per ball — at this speed the load is "
            "below the bearing's minimum and the balls leave the inner raceway (no equilibrium inside the model)")


def shoulder_checks(values: dict, subject: str = "equilibrium", prefix: str = "") -> tuple[list[str], list[str]]:
    """An error where a loaded contact's centre lies past its shoulder edge; a warning with the
    largest share of a contact's load beyond the edge where only the ellipse is truncated (`values`
    holds `shoulder_outputs` under `prefix`; `subject` names the bearing in the messages)."""
    overrun = float(values[prefix + "validity.shoulder_overrun"])
    if overrun > 0.0:
        return [f"{subject} outside the model: a loaded contact lies {np.degrees(overrun):.2f}° past its shoulder edge "
                "(the ball rides on the shoulder: more axial load than these shoulders carry; check "
                "bearing.inner_shoulder_diameter and bearing.outer_shoulder_diameter)"], []
    warnings = []
    where = "" if subject == "equilibrium" else f"{subject}: "
    for side in ("inner", "outer"):
        share = np.asarray(values[f"{prefix}balls.{side}.shoulder_share"])
        ball = int(np.argmax(share))
        if share[ball] > 0.0:
            warnings.append(f"{where}the contact ellipse of ball {ball} passes the {side} ring's shoulder edge: "
                            f"{share[ball] * 100:.3g} % of its load lies beyond it (the ellipse is truncated; the edge "
                            "stress is not modelled)")
    return [], warnings


def _equilibrium_checks(values: dict) -> tuple[list[str], list[str]]:
    """Errors: a state outside the ball model (ball_validity) or a solver that did not converge;
    warnings: a peak pressure above the ISO 76 static limit."""
    warnings = []
    if float(values["residual"]) >= ball_equilibrium.RESIDUAL_TOLERANCE:
        errors = [f"equilibrium solver did not converge: largest scaled residual {float(values['residual']):.1e} "
                  f"(tolerance {ball_equilibrium.RESIDUAL_TOLERANCE:g})" + (light_at_speed(values) or without_partner(values))]
    else:
        errors = validity_errors(values["validity.approach_ratio"], values["validity.contact_angle"], "equilibrium",
                                 values["validity.lowest_contact_angle"])
    warnings += free_tilt_warnings(values["free_tilt"])
    steepest = float(values["validity.contact_angle"])
    if "validity.shoulder_overrun" in values:
        shoulder_errors, shoulder_warnings = shoulder_checks(values)
        errors += shoulder_errors
        warnings += shoulder_warnings
    elif steepest > STEEP_CONTACT:
        warnings.append(f"a loaded contact at |α| = {np.degrees(steepest):.1f}°: the groove's edge (shoulder) is not "
                        "modelled — check the contact ellipse against the shoulder height")
    factor = float(values["validity.speed_factor"])
    if factor > SPEED_FACTOR_WARNING:
        warnings.append(f"n·d_m = {factor:.3g} mm·r/min is above {SPEED_FACTOR_WARNING:.0e}, where standard ball "
                        "bearings stop (cage, lubrication and heat, not modelled here, set the limit)")
    for side in ("inner", "outer"):
        pressure = np.asarray(values[f"balls.{side}.max_pressure"])
        ball = int(np.argmax(pressure))
        if pressure[ball] > ISO76_BALL_PRESSURE_LIMIT:
            warnings.append(f"peak contact pressure {pressure[ball] / 1e9:.3g} GPa ({side} raceway, ball {ball}) "
                            f"exceeds the ISO 76 static limit {ISO76_BALL_PRESSURE_LIMIT / 1e9:g} GPa")
    return errors, warnings


def _ball_outputs(side):
    short = side[0]
    return (
        Output(f"balls.{side}.load", "N", "kN", f"contact load Q, {side}", column=f"Q{short}"),
        Output(f"balls.{side}.contact_angle", "rad", "deg", f"contact angle α, {side}", column=f"α{short}"),
        Output(f"balls.{side}.max_pressure", "Pa", "GPa", f"peak Hertz pressure p0, {side}", column=f"p0{short}"),
        Output(f"balls.{side}.semi_major_axis", "m", "mm", f"contact semi-major axis a, {side}", in_report=False),
        Output(f"balls.{side}.semi_minor_axis", "m", "mm", f"contact semi-minor axis b, {side}", in_report=False),
    )


def _azimuth_plot(result, figure):
    """Ball loads, contact angles and peak pressures around the azimuth, against the ISO 76 limit."""
    values = result.values
    azimuth = np.degrees(np.asarray(values["balls.azimuth"]))
    load_axis, angle_axis, pressure_axis = figure.subplots(1, 3)
    for side, style in (("inner", "o-"), ("outer", "s--")):
        load_axis.plot(azimuth, np.asarray(values[f"balls.{side}.load"]) / 1e3, style, ms=4, label=f"{side} raceway")
        angle_axis.plot(azimuth, np.degrees(np.asarray(values[f"balls.{side}.contact_angle"])), style, ms=4,
                        label=f"{side} raceway")
        pressure_axis.plot(azimuth, np.asarray(values[f"balls.{side}.max_pressure"]) / 1e9, style, ms=4,
                           label=f"{side} raceway")
    pressure_axis.axhline(ISO76_BALL_PRESSURE_LIMIT / 1e9, color="tab:red", lw=0.8)
    pressure_axis.text(2.0, ISO76_BALL_PRESSURE_LIMIT / 1e9 * 1.01, "ISO 76 limit 4.2 GPa", fontsize=8,
                       color="tab:red")
    load_axis.set(ylabel="ball load Q [kN]", title="load distribution")
    angle_axis.set(ylabel="contact angle α [deg]", title="contact angles")
    pressure_axis.set(ylabel="peak pressure p0 [GPa]", title="peak Hertz pressure",
                      ylim=(0, 1.1 * max(ISO76_BALL_PRESSURE_LIMIT / 1e9,
                                         float(np.nanmax(values["balls.inner.max_pressure"])) / 1e9,
                                         float(np.nanmax(values["balls.outer.max_pressure"])) / 1e9)))
    for axis in (load_axis, angle_axis, pressure_axis):
        axis.set(xlabel="ball azimuth ψ [deg] (from +x towards +y)", xticks=np.arange(0, 361, 60))
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.suptitle(f"{result.model.scene.title}: balls around the bearing")


EQUILIBRIUM = Block(
    name="equilibrium",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=None,
    requires=("raceway_contact",),
    inputs=("bearing", "operating", "shoulders"),
    uses=("centrifugal", "gyroscopic"),
    outputs=(
        Output("displacement", "m, rad", "", "inner-ring displacement [δx, δy, δz, θx, θy]", in_report=False),
        Output("force", "N, N*m", "", "load the balls carry [Fx, Fy, Fz, Mx, My] (Fx, Fy follow under "
                                      "radial_displacement, Fz under axial_displacement, Mx, My under misalignment)",
               in_report=False),
        Output("prescribed", "", "", "1 where [δx, δy, δz, θx, θy] was prescribed (its load an output), 0 where free",
               in_report=False),
        Output("free_tilt", "rad", "mrad", "inner-ring tilt √(θx² + θy²) with the tilts free and no moment applied (else 0)",
               in_report=False),
        Output("converged", "", "", "the equilibrium solver converged to a state within the model", in_report=False),
        Output("residual", "", "", "largest scaled residual of ring and ball equations", in_report=False),
        Output("validity.approach_ratio", "", "",
               f"largest contact approach δ / Dw (model limit {ball_validity.MAX_APPROACH_FRACTION:g})", in_report=False),
        Output("validity.contact_angle", "rad", "deg", "largest |contact angle| (model limit 90°)", in_report=False),
        Output("validity.lowest_contact_angle", "rad", "deg", "lowest loaded contact angle of an angular-contact "
                                                              "bearing (model limit 0: its low shoulder; 90° for deep "
                                                              "groove)", in_report=False),
        Output("validity.centrifugal_ratio", "", "", "largest ball centrifugal force over the applied load per ball "
                                                     "(0 without the centrifugal effect)", in_report=False),
        Output("validity.speed_factor", "", "", "n·d_m of the relative ring speed [mm·r/min]", in_report=False),
        Output("validity.shoulder_overrun", "rad", "deg", "largest angle by which a loaded contact's centre lies past "
               "its shoulder edge (with the shoulder diameters; model limit 0)", in_report=False),
        Output("balls.inner.shoulder_share", "", "", "share of the inner contact's load beyond the shoulder edge "
               "(with the shoulder diameters)", in_report=False),
        Output("balls.outer.shoulder_share", "", "", "share of the outer contact's load beyond the shoulder edge "
               "(with the shoulder diameters)", in_report=False),
        Output("validity.missing_axial_load", "N", "N", "axial load an angular-contact bearing lacks to run without a "
                                                        "partner: max(0, 1.25 Fr tan α₀ − Fz)", in_report=False),
        Output("balls.azimuth", "rad", "deg", "ball azimuth ψ from +x", column="ψ"),
        *_ball_outputs("inner"),
        *_ball_outputs("outer"),
        Output("balls.centre", "m", "mm", "ball centre (axial, radial) from the outer groove curvature centre, "
               "in the ball's azimuth plane", in_report=False),
        *(Output(f"hertz.constant_table.{side}", "N/m**1.5", "N/mm**1.5",
                 f"Chebyshev coefficients of the {side} Hertz constant K(α) in t = 2 cos α − 1, which the "
                 "equilibrium interpolates (with fidelity.hertz_constants = \"contact_angle\")", in_report=False)
          for side in ("inner", "outer")),
        Output("balls.orbital_speed", "rad/s", "rpm", "orbital (cage) speed ω_m", column="ωm"),
        Output("balls.spin_speed", "rad/s", "rpm", "ball spin speed ω_R about its own axis", in_report=False),
        Output("balls.centrifugal_force", "N", "N", "centrifugal force F_c", effect="centrifugal", column="Fc"),
        Output("balls.gyroscopic_moment", "N*m", "N*m",
               "gyroscopic moment M_g (dL/dt = M_g e_t, along the direction of increasing azimuth)",
               effect="gyroscopic", column="Mg"),
    ),
    compute=_equilibrium,
    checks=_equilibrium_checks,
    plot=_azimuth_plot,
    scene_keys=("!bearing.arrangement",),  # a matched set solves its own equilibrium (adapters/bearing_set.py)
)


# --- stiffness ---------------------------------------------------------------------------------

def _stiffness(inputs: dict, settings: dict, results: dict) -> dict:
    # at the equilibrium block's balls, which carry their implicit derivative, and with its table of
    # Hertz constants: no ball solve and no table again
    table = (ContactConstantTable(results["hertz.constant_table.inner"], results["hertz.constant_table.outer"])
             if "hertz.constant_table.inner" in results else None)
    matrix = ball_equilibrium.stiffness_at_balls(results["displacement"], results["balls.centre"], inputs["bearing"],
                                                 inputs["operating"], ball_model(settings), table)
    return {"stiffness": matrix}


def stiffness_against_sweep(result, figure):
    """Diagonal stiffness against the first swept quantity (scalar sweeps) or the point index."""
    key, values = next(iter(result.sweep_axes.items()))
    shown, display = swept_display(values, all_keys()[key].dimension)
    if np.ndim(values) == 1 and display:
        x, label = shown, f"{key} [{display}]"
    else:
        x, label = np.arange(len(values)), f"{key} (point)"
    stiffness = np.asarray(result.values["stiffness"]).reshape((len(values), -1, 5, 5))[:, 0]
    translation, rotation = figure.subplots(1, 2)
    for i, name in enumerate(("Kxx", "Kyy", "Kzz")):
        translation.plot(x, stiffness[:, i, i] * 1e-6, label=name)
    for i, name in ((3, "Kθxθx"), (4, "Kθyθy")):
        rotation.plot(x, stiffness[:, i, i] * 1e-3, label=name)
    translation.set(xlabel=label, ylabel="stiffness [N/µm]", title="translational stiffness")
    rotation.set(xlabel=label, ylabel="stiffness [N·m/mrad]", title="tilting stiffness")
    for axis in (translation, rotation):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(result.model.scene.title)


STIFFNESS = Block(
    name="stiffness",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=("stiffness", True),
    requires=("equilibrium",),
    inputs=("bearing", "operating"),
    outputs=(Output("stiffness", "N/m, N/rad, N*m/m, N*m/rad", "",
                    "5×5 stiffness K = dF/dΔ, balls re-equilibrated (jacfwd through the implicit solve)",
                    in_report=False),),
    compute=_stiffness,
    sweep_plot=stiffness_against_sweep,
)


# --- report ------------------------------------------------------------------------------------

def _header(result) -> list[str]:
    scene, inputs = result.model.scene, result.model.inputs
    bearing, operating = inputs["bearing"], inputs["operating"]
    force = to_display(operating.force, "N", "kN")
    moment = np.asarray(operating.moment)
    speeds = [to_display(s, "rad/s", "rpm") for s in (operating.inner_speed, operating.outer_speed)]
    return [
        scene.title,
        f"scene: {scene.source}",
        "",
        f"Bearing    {bearing.kind}, {bearing.ball_count} balls, Dw = {float(bearing.ball_diameter) * 1e3:.4f} mm, "
        f"dm = {float(bearing.pitch_diameter) * 1e3:.3f} mm, fi = {float(bearing.inner_groove_ratio):.4f}, "
        f"fo = {float(bearing.outer_groove_ratio):.4f}",
        f"Materials  rings {bearing.ring_material.name}, balls {bearing.ball_material.name}",
        f"Operating  inner ring {float(speeds[0]):.1f} r/min, outer ring {float(speeds[1]):.1f} r/min; "
        f"F = [{', '.join(f'{f:.3f}' for f in force)}] kN; " + (
            f"M = [{', '.join(f'{m:.1f}' for m in moment)}] N·m" if operating.misalignment is None else
            f"misalignment imposed [θx, θy] = [{', '.join(f'{t * 1e3:.4g}' for t in np.asarray(operating.misalignment))}] "
            "mrad") + (
            "" if operating.radial_displacement is None else
            f"; radial displacement imposed [δx, δy] = "
            f"[{', '.join(f'{d * 1e6:.4g}' for d in np.asarray(operating.radial_displacement))}] µm (Fx, Fy are outputs)"),
    ]


def _report(result) -> list[str]:
    values = result.values
    if "displacement" not in values:  # a set: adapters/bearing_set.py reports it
        return []
    d = np.asarray(values["displacement"])
    lines = ["", "Inner-ring displacement (from the just-touching position at the free contact angle)",
             f"  δx = {d[0] * 1e6:.3f} µm, δy = {d[1] * 1e6:.3f} µm, δz = {d[2] * 1e6:.3f} µm, "
             f"θx = {d[3] * 1e3:.4f} mrad, θy = {d[4] * 1e3:.4f} mrad"]
    if result.model.inputs["operating"].axial_displacement is not None:
        lines.append(f"  axial preload force at the prescribed δz: Fz = {float(values['force'][2]) / 1e3:.4f} kN")
    if result.model.inputs["operating"].radial_displacement is not None:
        lines.append(f"  radial force at the prescribed δx, δy: Fx = {float(values['force'][0]) / 1e3:.4f} kN, "
                     f"Fy = {float(values['force'][1]) / 1e3:.4f} kN")
    if result.model.inputs["operating"].misalignment is not None:
        lines.append(f"  moments at the imposed misalignment: Mx = {float(values['force'][3]):.4g} N·m, "
                     f"My = {float(values['force'][4]):.4g} N·m")
    names = np.array(["δx", "δy", "δz", "θx", "θy"])
    held = np.asarray(values["prescribed"]) > 0
    lines.append(f"  free (from the load): {', '.join(names[~held]) or 'none'}; prescribed (load an output): "
                 f"{', '.join(names[held]) or 'none'}")
    if "stiffness" in values:
        lines += stiffness_lines(values["stiffness"], "balls")
    lines += element_table_lines(result, "Balls (load distribution; semi-axes and spin speed in --json; "
                                         "– where a ball carries no load)")
    residual = float(values["residual"])
    outside = validity_errors(values["validity.approach_ratio"], values["validity.contact_angle"], "",
                              values["validity.lowest_contact_angle"])
    state = ("DID NOT CONVERGE" if residual >= ball_equilibrium.RESIDUAL_TOLERANCE
             else "converged to a state OUTSIDE THE MODEL" if outside or not bool(values["converged"]) else "converged")
    return lines + ["", f"Equilibrium solver: {state} (largest scaled residual {residual:.1e})"]


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    if "displacement" not in values:  # a set: adapters/bearing_set.py reports it
        return []
    columns = [state_column("converged", values["converged"], ok="yes")]
    if "stiffness" in values:
        columns += [(f"{name} [N/µm]", [format_number(k[i, i] * 1e-6) for k in values["stiffness"]])
                    for i, name in enumerate(("Kxx", "Kyy", "Kzz"))]
    columns.append(("δz [µm]", [format_number(d[2] * 1e6) for d in values["displacement"]]))
    columns.append(("max p0i [GPa]", [format_number(p.max() / 1e9) for p in values["balls.inner.max_pressure"]]))
    return columns


def _mounted_shoulder_outputs(support, displacement, speed, elements, constants, depths) -> dict:
    """`shoulder_outputs` of a ball bearing on a shaft, its balls at the shaft's solution."""
    balls = ball_equilibrium.ball_results(displacement, support.bearing,
                                          Operating(speed, 0.0, jnp.zeros(3), jnp.zeros(2)), support.model, elements,
                                          constants)
    return shoulder_outputs(support.bearing, balls, depths)


MOUNTING = Mounting(
    parameters=lambda reads: catalogue_bearing(reads, material(reads)),
    support=lambda bearing, position, offset, orientation, settings: BallSupport(
        bearing, position, offset, model=ball_model(settings), orientation=orientation),
    describe=lambda bearing: (f"{bearing.kind}, {bearing.ball_count} balls, Dw = {float(bearing.ball_diameter) * 1e3:.4f} "
                              f"mm, α0 = {np.degrees(float(bearing.free_contact_angle)):.2f}°"),
    shoulders=lambda reads, bearing: scene_shoulders(reads, bearing),
    shoulder_outputs=_mounted_shoulder_outputs,
)

ADAPTER = register(Adapter(
    name="ball",
    bearing_types=BALL_BEARING_KINDS,
    refused={("deep_groove_ball", "bearing.arrangement"): "sets are of angular_contact_ball bearings, got "
                                                          "'deep_groove_ball'"},
    keys={
        "bearing.bore": quantity("length"),
        "bearing.outer_diameter": quantity("length"),
        "bearing.ball_diameter": quantity("length"),
        "bearing.pitch_diameter": quantity("length"),
        "bearing.balls": Key("integer"),
        "bearing.inner_groove_radius": quantity("length"),
        "bearing.outer_groove_radius": quantity("length"),
        "bearing.inner_groove_ratio": Key("number"),
        "bearing.outer_groove_ratio": Key("number"),
        "bearing.contact_angle": quantity("angle", "ball bearings: the free contact angle; tapered roller bearings: "
                                                    "the cup angle α_o"),
        "bearing.radial_clearance": quantity("length", "diametral clearance (ball and roller bearings); negative: "
                                                       "preloaded, down to −1 % of d_m"),
        "bearing.dynamic_load_rating": quantity("force"),
        "bearing.inner_shoulder_diameter": quantity("length", "the inner ring's (high) shoulder diameter d₁: with "
                                                              "the outer one, each contact ellipse is checked against "
                                                              "its shoulder edge"),
        "bearing.outer_shoulder_diameter": quantity("length", "the outer ring's (high) shoulder diameter D₂"),
        "operating.inner_speed": quantity("angular_speed"),
        "operating.outer_speed": quantity("angular_speed"),
        "operating.force": Key("quantities", "force", length=3, doc="[Fx, Fy, Fz] on the inner ring"),
        "operating.moment": Key("quantities", "moment", length=2, doc="[Mx, My] on the inner ring"),
        "operating.axial_displacement": AXIAL_DISPLACEMENT_KEY,
        "operating.misalignment": Key("quantities", "angle", length=2,
                                      doc="imposed inner-ring tilt [θx, θy] (ball and roller bearings): the ring held "
                                          "by its shaft; the moments are then outputs (give no operating.moment)"),
        "operating.radial_displacement": Key("quantities", "length", length=2,
                                             doc="imposed radial displacement [δx, δy] of the inner ring (ball and roller "
                                                 "bearings): Fx, Fy must be 0; the radial force is then an output"),
        "effects.centrifugal": Key("boolean"),
        "effects.gyroscopic": Key("boolean"),
        "effects.stiffness": Key("boolean"),
        "fidelity.hertz": Key("choice", choices=hertz.POINT_CONTACT_METHODS,
                              read_by=("raceway_contact", "equilibrium")),
        "fidelity.race_control": Key("choice", choices=RACE_CONTROLS, read_by=("equilibrium",),
                                     doc="raceway control hypothesis of the ball kinematics"),
        "fidelity.hertz_constants": Key("choice", choices=("contact_angle", "free_contact_angle"),
                                        read_by=("equilibrium",),
                                        doc="Hertz constants of the ball contacts at their current angle or at α0"),
    },
    required={kind: BALL_KEYS for kind in BALL_BEARING_KINDS},
    inputs=(InputBuilder(("bearing",), BALL_BEARING_KINDS, _bearing, after=("mounting",)),
            InputBuilder(("shoulders",), BALL_BEARING_KINDS, _shoulders, after=("bearing",)),
            InputBuilder(("operating",), BALL_BEARING_KINDS, _operating)),
    blocks=(RACEWAY_CONTACT, EQUILIBRIUM, STIFFNESS),
    header=_header,
    report=_report,
    sweep_columns=_sweep_columns,
    mounting=MOUNTING,
))
