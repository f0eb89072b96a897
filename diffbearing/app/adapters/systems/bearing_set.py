"""Matched pairs of angular-contact ball bearings (`bearing.arrangement`, `bearing.set_size = 2`):
back-to-back, face-to-face or tandem on one rigid shaft, preloaded by an axial offset or a
preload force (`bearing_set`, `shaft_equilibrium`). A scene with `bearing.arrangement` is a set:
the single bearing's equilibrium (and what builds on it) does not run; `operating.force` and
`operating.moment` act on the shaft at the middle of the set."""

import dataclasses

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.ball import ball_validity
from ....bearings.ball.ball_equilibrium import ball_results
from ....params import BALL_BEARING_KINDS, _as_float, _is_concrete, check_range, radial_clearance, with_radial_clearance
from ....systems.bearing_set import ARRANGEMENTS, bearing_set, clamped_offset, preload_force, preload_offset
from ....systems.shaft_equilibrium import RESIDUAL_TOLERANCE, Shaft, ShaftLoads, shaft_stiffness, solve_shaft
from ....thermal.axial_growth import grown_supports, pair_growth
from ...formatting import format_number, stiffness_lines, swept_display
from ...registry import Adapter, Block, InputBuilder, Key, Output, all_keys, quantity, register
from ..bearings.ball import ADAPTER as BALL_ADAPTER
from ..bearings.ball import (
    ISO76_BALL_PRESSURE_LIMIT,
    PARTNER_AXIAL_FACTOR,
    ball_model,
    catalogue_bearing,
    light_at_speed,
    low_shoulder_angle,
    shoulder_checks,
    shoulder_outputs,
    validity_errors,
)
from ..materials import material

SET = ("bearing.arrangement",)  # the set's layout
SET_SIZE = 2
SIDES = ("inner", "outer")
BALL_FIELDS = ("load", "contact_angle", "max_pressure")


class SetLayout(eqx.Module):
    """The set as the scene gives it: arrangement, centre distance of the two bearings [m], preload
    as a force [N] or an offset [m] (one of them, or neither), and the diametral clearance [m] the
    bearings were matched with (before any mounting changed it)."""

    spacing: jax.Array = eqx.field(converter=_as_float)
    matched_clearance: jax.Array = eqx.field(converter=_as_float)
    preload: jax.Array | None = None
    offset: jax.Array | None = None
    arrangement: str = eqx.field(static=True, default="back_to_back")


def _layout(v, built) -> dict:
    if v.get("bearing.set_size", SET_SIZE) != SET_SIZE:
        raise ValueError(f"bearing.set_size: sets of {SET_SIZE} bearings are modelled, got {v['bearing.set_size']!r}")
    if "bearing.width" not in v:
        raise ValueError("bearing.arrangement needs bearing.width (the two bearings' centres are a width apart, plus "
                         "bearing.spacer)")
    if _is_concrete(v["bearing.ball_diameter"]):
        check_range("bearing.width", v["bearing.width"], low=float(v["bearing.ball_diameter"]), unit=" m",
                    why="bearing.ball_diameter: a ring holds its ball")
    check_range("bearing.spacer", v.get("bearing.spacer"), low=0.0, low_open=False, unit=" m")
    check_range("operating.preload", v.get("operating.preload"), low=0.0, low_open=False, unit=" N",
                why="a set with end play: a negative operating.preload_offset")
    for key in ("operating.axial_displacement", "operating.outer_speed"):
        if v.get(key, 0.0) not in (0.0, None):
            raise ValueError(f"{key}: not with a bearing set (its preload is operating.preload or "
                             "operating.preload_offset; the outer rings stand still in the housing)")
    for key in ("operating.misalignment", "operating.radial_displacement"):
        if v.get(key) is not None:
            raise ValueError(f"{key}: not with a bearing set (the set's inner rings move together under "
                             "operating.force and operating.moment)")
    preload, offset = v.get("operating.preload"), v.get("operating.preload_offset")
    if preload is not None and offset is not None:
        raise ValueError("operating: give one of preload and preload_offset, not both")
    if v["bearing.arrangement"] == "tandem" and (preload is not None or offset is not None):
        raise ValueError("operating.preload: a tandem pair cannot be preloaded by itself (both bearings face the same "
                         "way); use back_to_back or face_to_face")
    matched = radial_clearance(catalogue_bearing(v, material(v)))
    return {"bearing_set": SetLayout(v["bearing.width"] + v.get("bearing.spacer", 0.0), matched, preload, offset,
                                     v["bearing.arrangement"])}


def _offsets(bearing, layout: SetLayout, model):
    """(offset as matched [m], offset in the running bearing's own reference [m] (`clamped_offset`:
    a mounting may have moved its free contact angle), preload at standstill [N])."""
    matched = with_radial_clearance(bearing, layout.matched_clearance)
    if layout.preload is not None:
        offset, preload = preload_offset(matched, layout.preload, model), layout.preload
    else:
        offset = jnp.asarray(0.0 if layout.offset is None else layout.offset)
        preload = preload_force(matched, offset, model)
    return offset, clamped_offset(matched, bearing, offset), preload


def centrifugal_ratio(balls, force, preload) -> jax.Array:
    """The set's balls' largest centrifugal force over the load per ball, (|F| + 2 P) / 2Z [-] (0
    without the centrifugal effect): far above 1 the speed lifts the balls off the inner raceways
    (`balls`: both bearings' `BallResults`; P the preload at standstill [N])."""
    if balls[0].centrifugal_force is None:
        return jnp.zeros(())
    per_ball = (jnp.linalg.norm(force) + 2.0 * preload) / (2 * balls[0].centrifugal_force.shape[-1])
    largest = jnp.max(jnp.stack([jnp.max(b.centrifugal_force) for b in balls]))
    return jax.lax.stop_gradient(largest / jnp.maximum(per_ball, 1e-300))


def tandem_missing_axial_load(bearing, force, moment, spacing, arrangement: str) -> jax.Array:
    """max(0, 1.25 (F_r + 2|M|/s) tan α₀ − F_z) [N] of a tandem pair (0 for the others): each of its
    bearings carries F_z/2 and F_r/2 ± |M|/s radially (s the centre distance), and one of them runs
    only against a partner below 1.25 tan α₀ times its radial load (`ball.missing_axial_load`)."""
    if arrangement != "tandem":
        return jnp.zeros(())
    radial = jnp.linalg.norm(force[:2]) + 2.0 * jnp.linalg.norm(moment) / spacing
    return jax.lax.stop_gradient(jnp.maximum(
        PARTNER_AXIAL_FACTOR * radial * jnp.tan(bearing.free_contact_angle) - force[2], 0.0))


def _set(inputs: dict, settings: dict, results: dict) -> dict:
    model = ball_model(settings)
    bearing, operating, layout = inputs["bearing"], inputs["operating"], inputs["bearing_set"]
    offset, running_offset, preload = _offsets(bearing, layout, model)
    supports = bearing_set(bearing, layout.arrangement, spacing=layout.spacing, offset=running_offset, model=model)
    strain = 0.0 if inputs["mounting"] is None else inputs["mounting"].axial_strain
    if inputs["mounting"] is not None:  # the stacks' growth at the mounting's ring temperatures
        supports = grown_supports(supports, pair_growth(layout.spacing, strain))
    shaft = Shaft(supports, ShaftLoads(jnp.zeros(1), operating.force[None], operating.moment[None]),
                  operating.inner_speed)
    solution = solve_shaft(shaft)
    out = {"set.displacement": solution.displacement, "set.converged": solution.converged,
           "set.residual": solution.residual, "set.preload_force": preload, "set.preload_offset": offset,
           "set.axial_growth": layout.spacing * strain}
    approach, angle, lowest, every = [], [], [], []
    for number, (support, local, force, centres, table) in enumerate(zip(
            supports, solution.bearing_displacements, solution.bearing_forces, solution.elements,
            solution.constants)):
        balls = ball_results(local, bearing, operating, model, centres, table)
        every.append(balls)
        prefix = f"set.bearings.{number}."
        azimuth = balls.azimuth if support.orientation > 0 else jnp.mod(-balls.azimuth, 2.0 * jnp.pi)
        out |= {prefix + "displacement": local, prefix + "force": force, prefix + "balls.azimuth": azimuth,
                prefix + "balls.orbital_speed": balls.orbital_speed}
        for side in SIDES:
            out |= {f"{prefix}balls.{side}.{field}": getattr(balls, f"{side}_{field}") for field in BALL_FIELDS}
        approach.append(ball_validity.largest_approach_ratio(balls.inner_approach, balls.outer_approach,
                                                             bearing.ball_diameter))
        angle.append(ball_validity.largest_contact_angle(balls.inner_contact_angle, balls.outer_contact_angle,
                                                       balls.inner_load, balls.outer_load))
        lowest.append(low_shoulder_angle(bearing, balls))
        if inputs.get("shoulders") is not None:
            out |= {prefix + key: value for key, value in shoulder_outputs(bearing, balls, inputs["shoulders"]).items()}
    out["set.validity.approach_ratio"] = jax.lax.stop_gradient(jnp.max(jnp.stack(approach)))
    out["set.validity.lowest_contact_angle"] = jnp.min(jnp.stack(lowest))
    out["set.validity.contact_angle"] = jax.lax.stop_gradient(jnp.max(jnp.stack(angle)))
    out["set.validity.centrifugal_ratio"] = centrifugal_ratio(every, operating.force, preload)
    out["set.validity.missing_axial_load"] = tandem_missing_axial_load(bearing, operating.force, operating.moment,
                                                                       layout.spacing, layout.arrangement)
    if settings["effects"].get("stiffness", False) is True:
        out["set.stiffness"] = shaft_stiffness(solution.displacement, shaft, elements=solution.elements,
                                               constants=solution.constants)
    return out


def _checks(values: dict) -> tuple[list[str], list[str]]:
    """Errors: a state outside the ball model (a loaded contact past its shoulder edge among them) or a
    shaft solve that did not converge; warnings: a peak pressure above the ISO 76 limit, a contact
    ellipse truncated by a shoulder, a bearing of a preloaded pair that has lost its load."""
    warnings = []
    errors = validity_errors(values["set.validity.approach_ratio"], values["set.validity.contact_angle"], "set",
                             values["set.validity.lowest_contact_angle"])
    if not errors and not bool(values["set.converged"]):
        missing = float(values["set.validity.missing_axial_load"])
        reason = light_at_speed({"validity.centrifugal_ratio": values["set.validity.centrifugal_ratio"]}) or (
            f": the axial load is {missing:.4g} N short of 1.25 (F_r + 2|M|/s) tan α₀, below which one bearing of a "
            "tandem pair runs only against a partner — a third bearing or a back_to_back pair"
            if missing > 0.0 else "")
        errors.append(f"shaft equilibrium of the set did not converge: largest scaled residual "
                      f"{float(values['set.residual']):.1e} (tolerance {RESIDUAL_TOLERANCE:g})" + reason)
    for number in range(SET_SIZE):
        prefix = f"set.bearings.{number}."
        if prefix + "validity.shoulder_overrun" in values:
            shoulder_errors, shoulder_warnings = shoulder_checks(values, f"bearing {number}", prefix)
            errors += shoulder_errors
            warnings += shoulder_warnings
        for side in SIDES:
            pressure = np.asarray(values[f"set.bearings.{number}.balls.{side}.max_pressure"])
            if pressure.max() > ISO76_BALL_PRESSURE_LIMIT:
                warnings.append(f"bearing {number}: peak contact pressure {pressure.max() / 1e9:.3g} GPa ({side} "
                                f"raceway) exceeds the ISO 76 static limit {ISO76_BALL_PRESSURE_LIMIT / 1e9:g} GPa")
        inner = np.asarray(values[f"set.bearings.{number}.balls.inner.load"])
        if float(values["set.preload_force"]) > 0.0 and not np.any(inner > 0.0):
            warnings.append(f"bearing {number} carries no load: the load has taken away its preload")
    return errors, warnings


def _bearing_outputs(number: int):
    prefix = f"set.bearings.{number}."
    return (
        Output(prefix + "displacement", "m, rad", "", f"bearing {number}: inner-ring displacement in its own frame "
               "[δx, δy, δz, θx, θy] (δz from the balls touching at α0)", in_report=False),
        Output(prefix + "force", "N, N*m", "", f"bearing {number}: load it carries, its own frame [Fx, Fy, Fz, Mx, My]",
               in_report=False),
        Output(prefix + "balls.azimuth", "rad", "deg", f"bearing {number}: ball azimuth ψ from +x (shaft frame)",
               in_report=False),
        Output(prefix + "balls.orbital_speed", "rad/s", "rpm", f"bearing {number}: orbital speed ω_m", in_report=False),
        *(Output(f"{prefix}balls.{side}.{field}", unit, display, f"bearing {number}: {name}, {side}", in_report=False)
          for side in SIDES
          for field, unit, display, name in (("load", "N", "kN", "contact load Q"),
                                             ("contact_angle", "rad", "deg", "contact angle α"),
                                             ("max_pressure", "Pa", "GPa", "peak Hertz pressure p0"))),
        Output(prefix + "validity.shoulder_overrun", "rad", "deg", f"bearing {number}: largest angle by which a loaded "
               "contact's centre lies past its shoulder edge (with the shoulder diameters; model limit 0)",
               in_report=False),
        *(Output(f"{prefix}balls.{side}.shoulder_share", "", "", f"bearing {number}: share of the {side} contact's "
                 "load beyond the shoulder edge (with the shoulder diameters)", in_report=False) for side in SIDES),
    )


def _plot(result, figure):
    """Ball loads and contact angles of both bearings around the shaft (shaft-frame azimuth)."""
    values = result.values
    load_axis, angle_axis = figure.subplots(1, 2)
    for number, style in zip(range(SET_SIZE), ("o-", "s--")):
        prefix = f"set.bearings.{number}.balls."
        order = np.argsort(np.asarray(values[prefix + "azimuth"]))
        azimuth = np.degrees(np.asarray(values[prefix + "azimuth"]))[order]
        load_axis.plot(azimuth, np.asarray(values[prefix + "inner.load"])[order] / 1e3, style, ms=4,
                       label=f"bearing {number}")
        angle_axis.plot(azimuth, np.degrees(np.asarray(values[prefix + "inner.contact_angle"]))[order], style, ms=4,
                        label=f"bearing {number}")
    load_axis.set(ylabel="inner contact load Q [kN]", title="load distribution")
    angle_axis.set(ylabel="inner contact angle α [deg]", title="contact angles")
    for axis in (load_axis, angle_axis):
        axis.set(xlabel="ball azimuth ψ [deg] (shaft frame, from +x towards +y)", xticks=np.arange(0, 361, 60))
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.suptitle(f"{result.model.scene.title}: {result.model.inputs['bearing_set'].arrangement.replace('_', '-')} pair")


def _preload_against_sweep(result, figure):
    """Each bearing's axial load against the first swept quantity (scalar sweeps) or the point index."""
    key, swept = next(iter(result.sweep_axes.items()))
    shown, display = swept_display(swept, all_keys()[key].dimension)
    x, label = (shown, f"{key} [{display}]") if np.ndim(swept) == 1 and display else (np.arange(len(swept)),
                                                                                       f"{key} (point)")
    axis = figure.subplots(1, 1)
    for number in range(SET_SIZE):
        axial = np.asarray(result.values[f"set.bearings.{number}.force"]).reshape((len(swept), -1, 5))[:, 0, 2]
        axis.plot(x, axial / 1e3, "o-", ms=4, label=f"bearing {number}")
    axis.set(xlabel=label, ylabel="axial load Fz [kN]", title="axial load of each bearing")
    axis.grid(alpha=0.3)
    axis.legend()
    figure.suptitle(result.model.scene.title)


SET_BLOCK = Block(
    name="bearing_set",
    bearing_types=BALL_BEARING_KINDS,  # a deep-groove set is refused by `_layout` with its reason
    enabled_by=None,
    requires=("raceway_contact",),
    inputs=("bearing", "operating", "bearing_set", "shoulders", "mounting"),
    uses=("centrifugal", "gyroscopic", "stiffness"),
    outputs=(
        Output("set.preload_force", "N", "kN", "preload: each bearing's axial load, unloaded at standstill"),
        Output("set.preload_offset", "m", "um", "preload offset: each inner ring's axial push as matched"),
        Output("set.axial_growth", "m", "um", "inner rings' and spacer's axial growth over the outer ones' (mounting)"),
        Output("set.displacement", "m, rad", "", "shaft displacement at the middle of the set [ux, uy, uz, θx, θy]",
               in_report=False),
        Output("set.converged", "", "", "the shaft equilibrium converged", in_report=False),
        Output("set.residual", "", "", "largest scaled residual of the shaft equilibrium", in_report=False),
        Output("set.validity.approach_ratio", "", "", "largest contact approach δ / Dw in the set", in_report=False),
        Output("set.validity.contact_angle", "rad", "deg", "largest |contact angle| in the set", in_report=False),
        Output("set.validity.lowest_contact_angle", "rad", "deg", "lowest loaded contact angle in the set (model "
                                                                  "limit 0: the low shoulder)", in_report=False),
        Output("set.validity.centrifugal_ratio", "", "", "largest ball centrifugal force over the load per ball "
               "(|F| + 2 preload) / 2Z (0 without the centrifugal effect)", in_report=False),
        Output("set.validity.missing_axial_load", "N", "N", "axial load a tandem pair lacks: max(0, 1.25 (F_r + 2|M|/s) "
               "tan α₀ − F_z) (0 for the other arrangements)", in_report=False),
        Output("set.stiffness", "N/m, N/rad, N*m/m, N*m/rad", "", "5×5 stiffness of the set at its middle (exact)",
               effect="stiffness", in_report=False),
        *(output for number in range(SET_SIZE) for output in _bearing_outputs(number)),
    ),
    compute=_set,
    checks=_checks,
    plot=_plot,
    sweep_plot=_preload_against_sweep,
    scene_keys=SET,
)


def _report(result) -> list[str]:
    values = result.values
    u = np.asarray(values["set.displacement"])
    layout = result.model.inputs["bearing_set"]
    lines = ["", f"Set: {layout.arrangement.replace('_', '-')} pair, bearing centres {float(layout.spacing) * 1e3:.2f} mm "
                 "apart (bearing 0 at −, bearing 1 at + half of it)",
             f"  shaft at the middle: ux = {u[0] * 1e6:.3f} µm, uy = {u[1] * 1e6:.3f} µm, uz = {u[2] * 1e6:.3f} µm, "
             f"θx = {u[3] * 1e3:.4f} mrad, θy = {u[4] * 1e3:.4f} mrad",
             f"  {'bearing':<9}{'Fr [kN]':>10}{'Fa [kN]':>10}{'M [N·m]':>10}{'Qmax i [kN]':>13}{'p0max i [GPa]':>15}"
             f"{'αi [deg]':>16}"]
    for number in range(SET_SIZE):
        prefix = f"set.bearings.{number}."
        force = np.asarray(values[prefix + "force"])
        load = np.asarray(values[prefix + "balls.inner.load"])
        angle = np.degrees(np.asarray(values[prefix + "balls.inner.contact_angle"])[load > 0])
        angles = f"{angle.min():.1f}–{angle.max():.1f}" if angle.size else "–"
        lines.append(f"  {number:<9}{np.hypot(force[0], force[1]) / 1e3:>10.4f}{force[2] / 1e3:>10.4f}"
                     f"{np.hypot(force[3], force[4]):>10.2f}{load.max() / 1e3:>13.4f}"
                     f"{np.asarray(values[prefix + 'balls.inner.max_pressure']).max() / 1e9:>15.4f}{angles:>16}")
    if "set.stiffness" in values:
        lines += stiffness_lines(values["set.stiffness"], "balls of both bearings")
    residual = float(values["set.residual"])
    state = "converged" if bool(values["set.converged"]) else "DID NOT CONVERGE"
    return lines + ["", f"Shaft equilibrium of the set: {state} (largest scaled residual {residual:.1e})"]


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    columns = [("set", ["converged" if flag else "NO" for flag in values["set.converged"]])]
    for number in range(SET_SIZE):
        columns.append((f"Fa{number} [kN]", [format_number(f[2] / 1e3) for f in values[f"set.bearings.{number}.force"]]))
    if "set.stiffness" in values:
        columns += [(f"{name} [N/µm]", [format_number(k[i, i] * 1e-6) for k in values["set.stiffness"]])
                    for i, name in ((0, "Kxx"), (2, "Kzz"))]
        columns.append(("Kθθ [N·m/mrad]", [format_number(k[3, 3] * 1e-3) for k in values["set.stiffness"]]))
    return columns


ADAPTER = register(Adapter(
    name="bearing_set",
    bearing_types=BALL_BEARING_KINDS,
    keys={
        "bearing.arrangement": Key("choice", choices=tuple(ARRANGEMENTS),
                                   doc="a matched pair on one shaft: back_to_back (DB), face_to_face (DF), tandem (DT)"),
        "bearing.set_size": Key("integer", doc="bearings in the set (2)"),
        "bearing.width": quantity("length", "bearing width B: the set's bearing centres are B (+ spacer) apart"),
        "bearing.spacer": quantity("length", "spacer between the two bearings of a set (default 0)"),
        "operating.preload": quantity("force", "a set's preload: each bearing's axial load, unloaded at standstill "
                                               "(turned into an axial offset, which the set then holds)"),
        "operating.preload_offset": quantity("length", "a set's preload as the axial push of each inner ring against "
                                                       "its outer ring (the pair's face offset is twice it)"),
        # the ball model's [fidelity] keys, read by the set's block for both bearings
        **{key: dataclasses.replace(BALL_ADAPTER.keys[key], read_by=("bearing_set",))
           for key in ("fidelity.hertz", "fidelity.race_control", "fidelity.hertz_constants")},
    },
    inputs=(InputBuilder(("bearing_set",), BALL_BEARING_KINDS, _layout, scene_keys=SET),),
    blocks=(SET_BLOCK,),
    report=_report,
    sweep_columns=_sweep_columns,
))
