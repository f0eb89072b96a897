"""Whole roller bearings, cylindrical and tapered: the quasi-static 5-DOF equilibrium with the load
distribution over the rollers and along each roller (ISO/TS 16281 laminae), roller tilt and rib
force (always), the 5×5 stiffness (effect `stiffness`), and the rollers' contacts re-solved by
influence coefficients at the converged load distribution (effect contact = "influence").

These blocks run where the scene gives `operating.force` (`WHOLE_BEARING`, the registry's
layouts); a roller scene with `contact.load` is one roller–raceway contact (roller.py), which
builds the roller (input `bearing`) for both layouts.
"""

import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.roller.roller_contact import roller_contact
from ....bearings.roller.roller_equilibrium import (
    MAX_APPROACH_FRACTION,
    RESIDUAL_TOLERANCE,
    RollerModel,
    RollerOperating,
    RollerRaceways,
    check_axial_displacement,
    prescribed_coordinates,
    roller_contact_loadings,
    roller_raceways,
    roller_results,
    roller_stiffness_matrix,
    solve_roller_equilibrium,
    tapered_axial_load_needed,
)
from ....bearings.roller.roller_geometry import ROLLER_KINDS, mean_roller_diameter
from ....bearings.roller.roller_support import RollerSupport
from ....params import check_axial_force_free, check_radial_force_free, check_range
from ...formatting import element_table_lines, format_number, state_column, stiffness_lines, swept_display, to_display
from ...registry import (
    Adapter,
    Block,
    InputBuilder,
    Key,
    Mounting,
    Output,
    all_keys,
    convergence_checks,
    quantity,
    register,
)
from .ball import AXIAL_DISPLACEMENT_KEY, SPEED_FACTOR_WARNING, check_speed_factor, speed_factor, stiffness_against_sweep
from ..systems.mounting import operating_clearance
from .roller import contact_settings, profile_line, scene_roller_bearing

WHOLE_BEARING = ("operating.force",)  # the scene key of this layout (registry: a whole roller bearing)
INFLUENCE_ROLLERS = ("most_loaded", "all")
# ISO 76:2006, 7.1: contact stress limit at the basic static load rating of roller bearings.
ISO76_ROLLER_PRESSURE_LIMIT = 4.0e9  # Pa
# n·d_m [mm·r/min]: the ball bearings' warning (ball.SPEED_FACTOR_WARNING, 1e6) over each type's
# bearing factor b_f, the factor by which the catalogues scale a ball bearing's speed factor A = n·d_m
# to a roller bearing's (SKF Rolling bearings catalogue, "Relubrication intervals", bearing factors
# b_f: 1.5 a cylindrical roller bearing as non-locating bearing, 2 a tapered roller bearing — the
# rollers' ends sliding on a rib). Above it standard bearings of the type stop.
BEARING_FACTORS = {"cylindrical_roller": 1.5, "tapered_roller": 2.0}
MAX_MISALIGNMENT = 0.05  # rad: the small-angle bound of a roller's tilt against its raceway (roller_geometry)

EQUILIBRIUM_BLOCK, STIFFNESS_BLOCK, INFLUENCE_BLOCK = ("roller_bearing_equilibrium", "roller_bearing_stiffness",
                                                       "roller_bearing_influence")


def roller_model(settings: dict) -> RollerModel:
    """The static model options a scene's effects and fidelity tables select (ValueError for a bad
    `fidelity.laminae`)."""
    return RollerModel(laminae=settings["fidelity"].get("laminae", 30),
                       centrifugal=settings["effects"].get("centrifugal", False) is True)


class InfluenceRollers(eqx.Module):
    """Which rollers' contacts the influence-coefficient solve re-solves (static): the most loaded
    roller's ("most_loaded") or every roller's ("all")."""

    rollers: str = eqx.field(static=True, default="most_loaded")


def _traced(value) -> bool:
    return isinstance(value, jax.core.Tracer)


def scene_raceways(v, built) -> dict:
    """{"raceways": RollerRaceways} of a whole roller bearing (`built` holds its "bearing" and
    "mounting"); ValueError names a missing or bad key."""
    bearing = built["bearing"]
    if "bearing.pitch_diameter" not in v:
        raise ValueError("missing required key 'bearing.pitch_diameter' (the pitch diameter d_m of a roller bearing)")
    if bearing.kind == "tapered_roller" and "bearing.contact_angle" not in v:
        raise ValueError("missing required key 'bearing.contact_angle' (the cup angle α_o of a tapered roller bearing)")
    pitch, clearance, cup = (v["bearing.pitch_diameter"], v.get("bearing.radial_clearance", 0.0),
                             v.get("bearing.contact_angle", 0.0))
    if built["mounting"] is not None:  # effects.mounting: the operating clearance
        clearance = operating_clearance(clearance, built["mounting"], pitch, v)
    if any(_traced(x) for x in (pitch, clearance, cup, bearing.cone_half_angle, bearing.large_diameter)):
        # a sweep's point: its corners were validated with concrete values (sweep.check_corners),
        # and `roller_raceways` writes bounds made of these values into its messages with float()
        raceways = RollerRaceways(pitch, clearance, cup)
    else:
        raceways = roller_raceways(bearing, pitch_diameter=pitch, diametral_clearance=clearance, cup_angle=cup)
    mean = 0.5 * (bearing.small_diameter + bearing.large_diameter)
    if not any(_traced(x) for x in (pitch, mean)):
        room = float(pitch) * math.sin(math.pi / bearing.roller_count)
        if float(mean) > room:
            size = f"{float(mean) * 1e3:.4g} mm" + (" (mean diameter)" if bearing.kind == "tapered_roller" else "")
            raise ValueError(f"bearing.rollers: {bearing.roller_count} rollers of {size} do not fit on the "
                             f"{float(pitch) * 1e3:.4g} mm pitch circle: that needs D ≤ d_m sin(π/Z) = {room * 1e3:.4g} mm")
    return {"raceways": raceways}


def _operating(v, built) -> dict:
    bearing = built["bearing"]
    check_speed_factor(v)
    force = v["operating.force"]
    misalignment = v.get("operating.misalignment")
    if misalignment is not None and "operating.moment" in v:
        raise ValueError("operating.moment: with operating.misalignment the inner ring's tilt is imposed and the "
                         "moments are outputs; give one of the two")
    if misalignment is not None:
        check_range("operating.misalignment", misalignment, low=-MAX_MISALIGNMENT, high=MAX_MISALIGNMENT, unit=" rad",
                    why="small-angle misalignment, |θ| < 0.05 rad ≈ 2.9°")
    radial_displacement = v.get("operating.radial_displacement")
    check_radial_force_free(force, radial_displacement)
    axial = force[2]
    if bearing.kind == "cylindrical_roller" and not _traced(axial) and float(axial) != 0.0:
        raise ValueError(f"operating.force: a cylindrical roller bearing without ribs carries no axial load; "
                         f"Fz must be 0, got {float(axial):g} N")
    axial_displacement = v.get("operating.axial_displacement")
    check_axial_force_free(force, axial_displacement)
    if axial_displacement is None and bearing.kind == "tapered_roller":
        _check_tapered_load(force, v.get("bearing.contact_angle", 0.0))
    operating = RollerOperating(force=force, moment=v.get("operating.moment", [0.0, 0.0]),
                                inner_speed=v.get("operating.inner_speed", 0.0),
                                outer_speed=v.get("operating.outer_speed", 0.0), misalignment=misalignment,
                                radial_displacement=radial_displacement, axial_displacement=axial_displacement)
    check_axial_displacement(bearing, operating)
    return {"operating": operating}


def _check_tapered_load(force, cup_angle) -> None:
    """ValueError naming operating.force unless Fz > Fr tan α_o: the cup has no rib, so it pushes
    each roller along its contact normal at α_o, and the applied load balances the sum of those
    pushes: Fz = Σ Q sin α_o and Fr = |Σ Q cos α_o (cos ψ, sin ψ)| ≤ Σ Q cos α_o = Fz / tan α_o,
    equal only with a single roller loaded. Below it no equilibrium exists."""
    if any(_traced(x) for x in (*force, cup_angle)):
        return
    radial, axial = math.hypot(float(force[0]), float(force[1])), float(force[2])
    needed = radial * math.tan(float(cup_angle))
    if (radial > 0.0 or axial != 0.0) and axial <= needed:
        raise ValueError(f"operating.force: a tapered roller bearing takes Fr = {radial:.4g} N only with an axial load "
                         f"Fz > Fr tan α_o = {needed:.4g} N pushing the cone into the cup (+z), got Fz = {axial:.4g} N "
                         "(its cup pushes the rollers along α_o = "
                         f"{math.degrees(float(cup_angle)):.3g}°; a radially loaded tapered bearing is held axially by "
                         "its partner: mount the pair on a shaft, [[bearings]])")


def _influence_rollers(v, built) -> dict:
    return {"influence_rollers": InfluenceRollers(v.get("contact.rollers", "most_loaded"))}


# --- the equilibrium and its load distribution ------------------------------------------------

def approach_ratio(bearing, rollers):
    """The largest lamina approach / mean roller diameter [-] (limit `MAX_APPROACH_FRACTION`)."""
    return rollers.largest_approach / mean_roller_diameter(bearing)


def _equilibrium(inputs: dict, settings: dict, results: dict) -> dict:
    model = roller_model(settings)
    bearing, raceways, operating = inputs["bearing"], inputs["raceways"], inputs["operating"]
    solution = solve_roller_equilibrium(bearing, raceways, operating, model)
    rollers = roller_results(solution.displacement, bearing, raceways, operating, model)
    out = {"displacement": solution.displacement, "force": solution.force, "converged": solution.converged,
           "residual": solution.residual, "rollers.azimuth": rollers.azimuth, "rollers.tilt": rollers.tilt,
           "rollers.shift": rollers.shift, "rollers.lamina_position": rollers.lamina_y,
           "validity.approach_ratio": approach_ratio(bearing, rollers),
           "validity.speed_factor": jax.lax.stop_gradient(speed_factor(operating.inner_speed - operating.outer_speed,
                                                                       raceways.pitch_diameter)),
           "validity.bearing_factor": jnp.asarray(BEARING_FACTORS[bearing.kind]),
           "validity.missing_axial_load": jax.lax.stop_gradient(missing_axial_load(bearing, raceways, operating, model))}
    for side in ("inner", "outer"):
        out |= {f"rollers.{side}.load": getattr(rollers, f"{side}_load"),
                f"rollers.{side}.lamina_load": getattr(rollers, f"{side}_lamina_load"),
                f"rollers.{side}.max_pressure": getattr(rollers, f"{side}_max_pressure")}
    if bearing.kind == "tapered_roller":
        out["rollers.rib.load"] = rollers.rib_load
    if model.centrifugal:
        out["rollers.centrifugal_force"] = rollers.centrifugal_force
    return out


def missing_axial_load(bearing, raceways, operating, model):
    """max(0, F_r tan α_o + Z F_c sin α_o cos α_m / cos θ − F_z) [N]: the axial load a tapered
    roller bearing lacks for any equilibrium to exist (`tapered_axial_load_needed`; at speed the
    rollers' centrifugal force, which the cup takes, raises it); 0 for a cylindrical bearing and
    under operating.axial_displacement (Fz an output)."""
    if operating.axial_displacement is not None:
        return jnp.asarray(0.0)
    return jnp.maximum(tapered_axial_load_needed(bearing, raceways, operating, model) - operating.force[2], 0.0)


def _equilibrium_checks(values: dict) -> tuple[list[str], list[str]]:
    """Errors: a tapered bearing short of the axial load any equilibrium needs at its speed, a
    solver that did not converge, a lamina approach beyond the model; warnings: a peak pressure
    above the ISO 76 static limit, a speed above the type's n·d_m (`BEARING_FACTORS`)."""
    errors, warnings = [], []
    factor, limit = float(values["validity.speed_factor"]), SPEED_FACTOR_WARNING / float(values["validity.bearing_factor"])
    if factor > limit:
        warnings.append(f"n·d_m = {factor:.3g} mm·r/min is above {limit:.3g}, where standard bearings of this type stop "
                        f"(a ball bearing's {SPEED_FACTOR_WARNING:.0e} over its bearing factor "
                        f"{float(values['validity.bearing_factor']):g}; the rib, cage and lubrication, not modelled "
                        "here, set the limit)")
    missing = float(values["validity.missing_axial_load"])
    if missing > 0.0:
        errors.append(f"no equilibrium exists: the axial load is {missing:.4g} N short of F_r tan α_o + Z F_c sin α_o "
                      "cos α_m / cos θ, what a tapered roller bearing needs at this speed (each roller's centrifugal "
                      "force F_c presses it on the cup, whose axial push the cone must take besides the radial load's; "
                      "raise Fz or set the bearing by operating.axial_displacement)")
    elif not bool(values["converged"]):
        errors.append(f"roller bearing equilibrium solver did not converge: largest scaled residual "
                      f"{float(values['residual']):.1e} (tolerance {RESIDUAL_TOLERANCE:g})")
    elif float(values["validity.approach_ratio"]) > MAX_APPROACH_FRACTION:
        errors.append(f"equilibrium outside the model: a lamina approach of {float(values['validity.approach_ratio']) * 100:.3g} "
                      f"% of the roller diameter passes the limit of {MAX_APPROACH_FRACTION * 100:g} % (Hertz line "
                      "contacts small against the roller)")
    for side in ("inner", "outer"):
        pressure = np.asarray(values[f"rollers.{side}.max_pressure"])
        roller = int(np.argmax(pressure))
        if pressure[roller] > ISO76_ROLLER_PRESSURE_LIMIT:
            warnings.append(f"peak contact pressure {pressure[roller] / 1e9:.3g} GPa ({side} raceway, roller {roller}) "
                            f"exceeds the ISO 76 static limit {ISO76_ROLLER_PRESSURE_LIMIT / 1e9:g} GPa of roller "
                            "bearings")
    return errors, warnings


def _side_outputs(side: str):
    short = side[0]
    return (
        Output(f"rollers.{side}.load", "N", "N", f"roller load Q, {side} raceway", column=f"Q{short}"),
        Output(f"rollers.{side}.lamina_load", "N/m", "N/mm",
               f"load per unit length of each lamina q_k (rollers × laminae), {side} raceway", in_report=False),
    )


def _pressure_output(side: str, how: str):
    return Output(f"rollers.{side}.max_pressure", "Pa", "GPa", f"peak contact pressure p_max, {side} raceway ({how})",
                  column=f"p{side[0]}")


def _azimuth_plot(result, figure):
    """Roller loads and peak pressures around the azimuth, and the inner lamina loads as a map over
    rollers and laminae."""
    values = result.values
    azimuth = np.degrees(np.asarray(values["rollers.azimuth"]))
    load_axis, pressure_axis, map_axis = figure.subplots(1, 3, width_ratios=[1, 1, 1.25])
    for side, style in (("inner", "o-"), ("outer", "s--")):
        load_axis.plot(azimuth, np.asarray(values[f"rollers.{side}.load"]), style, ms=4, label=f"Q, {side} raceway")
        pressure_axis.plot(azimuth, np.asarray(values[f"rollers.{side}.max_pressure"]) / 1e9, style, ms=4,
                           label=f"{side} raceway")
    if "rollers.rib.load" in values:
        load_axis.plot(azimuth, np.asarray(values["rollers.rib.load"]), "^:", ms=4, label="rib force Q_f")
    pressure_axis.axhline(ISO76_ROLLER_PRESSURE_LIMIT / 1e9, color="tab:red", lw=0.8)
    pressure_axis.text(2.0, ISO76_ROLLER_PRESSURE_LIMIT / 1e9 * 1.01, "ISO 76 limit 4.0 GPa", fontsize=8, color="tab:red")
    load_axis.set(ylabel="roller load [N]", title="load distribution")
    pressure_axis.set(ylabel="peak pressure p_max [GPa]", title="peak contact pressure",
                      ylim=(0, 1.1 * max(ISO76_ROLLER_PRESSURE_LIMIT / 1e9,
                                         float(np.nanmax(values["rollers.inner.max_pressure"])) / 1e9,
                                         float(np.nanmax(values["rollers.outer.max_pressure"])) / 1e9)))
    for axis in (load_axis, pressure_axis):
        axis.set(xlabel="roller azimuth ψ [deg] (from +x towards +y)", xticks=np.arange(0, 361, 60))
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    y = np.asarray(values["rollers.lamina_position"]) * 1e3
    loads = np.asarray(values["rollers.inner.lamina_load"]) / 1e3
    shown = map_axis.pcolormesh(y, azimuth, loads, shading="nearest", cmap="viridis")
    figure.colorbar(shown, ax=map_axis, label="lamina load q, inner raceway [N/mm]")
    tapered = result.model.inputs["bearing"].kind == "tapered_roller"
    map_axis.set(xlabel="y along the roller [mm]" + (" (+: large end)" if tapered else ""), ylabel="roller azimuth ψ [deg]",
                 title=f"inner lamina loads, {loads.shape[0]} rollers × {loads.shape[1]} laminae")
    figure.suptitle(f"{result.model.scene.title}: rollers around the bearing")


def sweep_abscissa(result):
    """(x values, axis label) of a sweep's plots: the first swept quantity where it is a scalar
    with a display unit, else the point index."""
    key, values = next(iter(result.sweep_axes.items()))
    shown, display = swept_display(values, all_keys()[key].dimension)
    if np.ndim(values) == 1 and display:
        return shown, f"{key} [{display}]"
    return np.arange(len(values)), f"{key} (point)"


def _against_sweep(result, figure):
    """The largest roller load and the peak pressure against the first swept quantity (or the point)."""
    x, label = sweep_abscissa(result)
    values = result.values
    count = len(x)
    load_axis, pressure_axis = figure.subplots(1, 2)
    for side, style in (("inner", "-"), ("outer", "--")):
        loads = np.asarray(values[f"rollers.{side}.load"]).reshape((count, -1, np.shape(values[f"rollers.{side}.load"])[-1]))
        pressures = np.asarray(values[f"rollers.{side}.max_pressure"]).reshape(loads.shape)
        load_axis.plot(x, loads[:, 0].max(axis=-1), style, label=f"{side} raceway")
        pressure_axis.plot(x, pressures[:, 0].max(axis=-1) / 1e9, style, label=f"{side} raceway")
    load_axis.set(xlabel=label, ylabel="largest roller load Q_max [N]", title="most loaded roller")
    pressure_axis.set(xlabel=label, ylabel="peak contact pressure [GPa]", title="peak pressure")
    for axis in (load_axis, pressure_axis):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(result.model.scene.title)


EQUILIBRIUM = Block(
    name=EQUILIBRIUM_BLOCK,
    bearing_types=ROLLER_KINDS,
    enabled_by=None,
    requires=(),
    inputs=("bearing", "raceways", "operating"),
    uses=("centrifugal", "contact"),
    scene_keys=WHOLE_BEARING,
    outputs=(
        Output("displacement", "m, rad", "", "inner-ring displacement [δx, δy, δz, θx, θy]", in_report=False),
        Output("force", "N, N*m", "", "load the rollers carry [Fx, Fy, Fz, Mx, My] (Fx, Fy follow under "
                                      "radial_displacement, Fz under axial_displacement, Mx, My under misalignment)",
               in_report=False),
        Output("converged", "", "", "the equilibrium solver converged", in_report=False),
        Output("residual", "", "", "largest scaled residual of ring and roller equations", in_report=False),
        Output("validity.approach_ratio", "", "", "largest lamina approach / mean roller diameter (model limit "
                                                  f"{MAX_APPROACH_FRACTION:g})", in_report=False),
        Output("validity.speed_factor", "", "", "n·d_m of the relative ring speed [mm·r/min]", in_report=False),
        Output("validity.bearing_factor", "", "", "the type's bearing factor b_f: its n·d_m warning is 1e6 / b_f",
               in_report=False),
        Output("validity.missing_axial_load", "N", "N", "axial load a tapered bearing lacks for any equilibrium: "
                                                        "max(0, Fr tan α_o + Z F_c sin α_o cos α_m / cos θ − Fz)",
               in_report=False),
        Output("rollers.azimuth", "rad", "deg", "roller azimuth ψ from +x", column="ψ"),
        *_side_outputs("inner"),
        *_side_outputs("outer"),
        Output("rollers.rib.load", "N", "N", "rib force Q_f along the roller axis (tapered rollers only)", column="Qrib"),
        Output("rollers.tilt", "rad", "mrad", "roller tilt φ in its axial plane", column="φ"),
        _pressure_output("inner", "largest Hertz line pressure of its laminae"),
        _pressure_output("outer", "largest Hertz line pressure of its laminae"),
        Output("rollers.shift", "m", "um", "roller displacement u across its axis, towards the cup", in_report=False),
        Output("rollers.lamina_position", "m", "mm", "lamina centres y_k along the roller from its middle "
                                                      "(+ towards the large end)", in_report=False),
        Output("rollers.centrifugal_force", "N", "N", "centrifugal force F_c of each roller", effect="centrifugal"),
    ),
    compute=_equilibrium,
    checks=_equilibrium_checks,
    validate=lambda settings, inputs: roller_model(settings),
    plot=_azimuth_plot,
    sweep_plot=_against_sweep,
)


# --- stiffness ---------------------------------------------------------------------------------

def _stiffness(inputs: dict, settings: dict, results: dict) -> dict:
    return {"stiffness": roller_stiffness_matrix(results["displacement"], inputs["bearing"], inputs["raceways"],
                                                 inputs["operating"], roller_model(settings))}


STIFFNESS = Block(
    name=STIFFNESS_BLOCK,
    bearing_types=ROLLER_KINDS,
    enabled_by=("stiffness", True),
    requires=(EQUILIBRIUM_BLOCK,),
    inputs=("bearing", "raceways", "operating"),
    scene_keys=WHOLE_BEARING,
    outputs=(Output("stiffness", "N/m, N/rad, N*m/m, N*m/rad", "",
                    "5×5 stiffness K = dF/dΔ, rollers re-equilibrated (jacfwd)", in_report=False),),
    compute=_stiffness,
    sweep_plot=stiffness_against_sweep,
)


# --- the rollers' contacts by influence coefficients ---------------------------------------

def _influence(inputs: dict, settings: dict, results: dict) -> dict:
    """Re-solve the contacts of the most loaded roller (largest inner load), or of every roller, by
    influence coefficients at the converged displacement: one `jax.lax.map` over the 2n contacts
    (inner ones first), an unloaded contact skipped by `jax.lax.cond`."""
    grid, tolerance = contact_settings(settings)
    model = roller_model(settings)
    bearing, raceways, operating = inputs["bearing"], inputs["raceways"], inputs["operating"]
    displacement = results["displacement"]
    most = jnp.argmax(results["rollers.inner.load"])
    every = inputs["influence_rollers"].rollers == "all"
    chosen = jnp.arange(bearing.roller_count) if every else most[None]
    inner, outer = jax.vmap(lambda j: roller_contact_loadings(displacement, j, bearing, raceways, operating, model))(chosen)
    loadings = jax.tree.map(lambda a, b: jnp.concatenate([a, b]), inner, outer)

    def solve(loading):
        return roller_contact(bearing, loading, grid, "influence", tolerance)

    def unloaded(loading):
        shape = jax.eval_shape(solve, loading)
        empty = jax.tree.map(lambda s: jnp.zeros(s.shape, s.dtype), shape)
        return eqx.tree_at(lambda c: c.converged, empty, jnp.asarray(True))

    contacts = jax.lax.map(lambda loading: jax.lax.cond(loading.load > 0, solve, unloaded, loading), loadings)
    count = chosen.shape[0]
    shown = most if every else 0  # the most loaded roller's place among the solved ones
    out = {"rollers.influence.roller": most, "rollers.influence.rollers": chosen,
           "rollers.influence.converged": jnp.all(contacts.converged),
           "rollers.influence.iterations": jnp.max(contacts.iterations),
           "rollers.influence.y": contacts.y[shown]}
    for offset, side in ((0, "inner"), (count, "outer")):
        laminae = results[f"rollers.{side}.max_pressure"]
        out |= {f"rollers.{side}.lamina_max_pressure": laminae,
                f"rollers.{side}.max_pressure": laminae.at[chosen].set(contacts.max_pressure[offset:offset + count]),
                f"rollers.influence.{side}.pressure": contacts.pressure[offset + shown],
                f"rollers.influence.{side}.x": contacts.x[offset + shown]}
    return out


def _influence_plot(result, figure):
    """Pressure maps of the most loaded roller's inner and outer contacts and their peaks along the roller."""
    values = result.values
    roller = int(values["rollers.influence.roller"])
    y = np.asarray(values["rollers.influence.y"]) * 1e3
    inner_axis, outer_axis, line_axis = figure.subplots(1, 3, width_ratios=[1.2, 1.2, 1])
    for axis, side in ((inner_axis, "inner"), (outer_axis, "outer")):
        pressure = np.asarray(values[f"rollers.influence.{side}.pressure"]) / 1e9
        x = np.asarray(values[f"rollers.influence.{side}.x"]) * 1e6
        shown = axis.pcolormesh(y, x, pressure, shading="nearest", cmap="viridis")
        figure.colorbar(shown, ax=axis, label="pressure [GPa]")
        axis.set(xlabel="y along the roller [mm]", ylabel="x, rolling direction [µm]",
                 title=f"{side} raceway, Q = {float(values[f'rollers.{side}.load'][roller]):.4g} N")
        line_axis.plot(y, pressure.max(axis=0), "-" if side == "inner" else "--", label=f"{side}: max over x")
        line_axis.axhline(float(values[f"rollers.{side}.lamina_max_pressure"][roller]) / 1e9, lw=0.8, ls=":",
                          color="tab:blue" if side == "inner" else "tab:orange", label=f"{side}: laminae' peak (Hertz)")
    line_axis.set(xlabel="y along the roller [mm]", ylabel="pressure [GPa]", title="peak pressure along the roller",
                  ylim=(0, None))
    line_axis.grid(alpha=0.3)
    line_axis.legend(fontsize=8)
    psi = np.degrees(float(values["rollers.azimuth"][roller]))
    figure.suptitle(f"{result.model.scene.title}: roller {roller} (ψ = {psi:.4g}°), influence coefficients")


def _influence_outputs():
    how = "influence coefficients, edge peaks included, where re-solved; its laminae elsewhere"
    return (
        _pressure_output("inner", how),
        _pressure_output("outer", how),
        Output("rollers.inner.lamina_max_pressure", "Pa", "GPa", "largest Hertz line pressure of the laminae, inner "
                                                                 "raceway (before the re-solve)", in_report=False),
        Output("rollers.outer.lamina_max_pressure", "Pa", "GPa", "largest Hertz line pressure of the laminae, outer "
                                                                 "raceway (before the re-solve)", in_report=False),
        Output("rollers.influence.roller", "", "", "index of the most loaded roller (largest inner load), whose "
                                                   "pressure maps are given", in_report=False),
        Output("rollers.influence.rollers", "", "", "indices of the rollers re-solved", in_report=False),
        Output("rollers.influence.converged", "", "", "every re-solved contact converged inside its grid", in_report=False),
        Output("rollers.influence.iterations", "", "", "largest conjugate-gradient iteration count", in_report=False),
        Output("rollers.influence.inner.pressure", "Pa", "GPa", "pressure map p[x, y] of the most loaded roller, inner "
                                                                "raceway (nx × ny)", in_report=False),
        Output("rollers.influence.outer.pressure", "Pa", "GPa", "pressure map p[x, y] of the most loaded roller, outer "
                                                                "raceway (nx × ny)", in_report=False),
        Output("rollers.influence.inner.x", "m", "mm", "cell centres along rolling (x), inner map", in_report=False),
        Output("rollers.influence.outer.x", "m", "mm", "cell centres along rolling (x), outer map", in_report=False),
        Output("rollers.influence.y", "m", "mm", "cell centres along the roller axis (y) of both maps", in_report=False),
    )


INFLUENCE = Block(
    name=INFLUENCE_BLOCK,
    bearing_types=ROLLER_KINDS,
    enabled_by=("contact", "influence"),
    requires=(EQUILIBRIUM_BLOCK,),
    inputs=("bearing", "raceways", "operating", "influence_rollers"),
    scene_keys=WHOLE_BEARING,
    # iterative contact solves: a sweep maps its points one after another rather than vmapping them
    sequential_sweep=True,
    outputs=_influence_outputs(),
    compute=_influence,
    checks=convergence_checks(("rollers.influence.converged", "the influence-coefficient contact solution of the "
                                                              "rollers (or its loaded zone reached the grid's edge)")),
    validate=lambda settings, inputs: contact_settings(settings),
    plot=_influence_plot,
)


# --- report --------------------------------------------------------------------------------------

def _header(result) -> list[str]:
    scene, inputs, values = result.model.scene, result.model.inputs, result.values
    bearing, raceways, operating = inputs["bearing"], inputs["raceways"], inputs["operating"]
    model = roller_model(result.model.settings)
    if bearing.kind == "tapered_roller":
        half = float(bearing.cone_half_angle)
        cup = float(raceways.cup_angle)
        shape = (f"d = {float(bearing.small_diameter) * 1e3:.4g} mm to D = {float(bearing.large_diameter) * 1e3:.4g} mm, "
                 f"cone half angle θ = {np.degrees(half):.4g}°")
        angles = f"cup angle αo = {np.degrees(cup):.4g}°, cone angle αi = αo − 2θ = {np.degrees(cup - 2 * half):.4g}°"
    else:
        shape = f"D = {float(bearing.small_diameter) * 1e3:.4g} mm"
        angles = "contact angle 0°, no ribs (no axial load)"
    material = bearing.material
    speeds = [float(to_display(s, "rad/s", "rpm")) for s in (operating.inner_speed, operating.outer_speed)]
    force = to_display(operating.force, "N", "kN")
    load = f"F = [{', '.join(f'{f:.4g}' for f in force)}] kN"
    if operating.misalignment is None:
        load += f"; M = [{', '.join(f'{m:.4g}' for m in np.asarray(operating.moment))}] N·m"
    else:
        tilt = np.asarray(operating.misalignment) * 1e3
        load += (f"; inner-ring misalignment imposed, [θx, θy] = [{', '.join(f'{t:.4g}' for t in tilt)}] mrad "
                 "(the moments are outputs)")
    if operating.radial_displacement is not None:
        shift = np.asarray(operating.radial_displacement) * 1e6
        load += (f"; radial displacement imposed, [δx, δy] = [{', '.join(f'{d:.4g}' for d in shift)}] µm "
                 "(Fx, Fy are outputs)")
    if operating.axial_displacement is not None:
        load += f"; axial displacement imposed, δz = {float(operating.axial_displacement) * 1e6:.4g} µm (Fz is an output)"
    centrifugal = "on" if model.centrifugal else "off"
    if model.centrifugal and not result.sweep_axes:
        centrifugal += f", F_c = {float(values['rollers.centrifugal_force']):.4g} N per roller"
    width = float(bearing.length) / model.laminae * 1e6
    return [
        scene.title,
        f"scene: {scene.source}",
        "",
        f"Bearing    {bearing.kind}, {bearing.roller_count} rollers, {shape}, effective length "
        f"l = {float(bearing.length) * 1e3:.4g} mm",
        f"           pitch diameter dm = {float(raceways.pitch_diameter) * 1e3:.5g} mm, {angles}, diametral clearance "
        f"Pd = {float(raceways.diametral_clearance) * 1e6:.4g} µm",
        profile_line(scene, bearing),
        f"Material   E = {float(material.elastic_modulus) / 1e9:.4g} GPa, ν = {float(material.poisson_ratio):.3g}, "
        f"ρ = {float(material.density):.4g} kg/m³ (rollers and rings)",
        f"Model      {model.laminae} laminae of {width:.4g} µm per roller (ISO/TS 16281), centrifugal force {centrifugal}",
        f"Operating  inner ring {speeds[0]:.1f} r/min, outer ring {speeds[1]:.1f} r/min; {load}",
    ]


def _influence_lines(result) -> list[str]:
    values = result.values
    if "rollers.influence.roller" not in values:
        return []
    roller = int(values["rollers.influence.roller"])
    pressure = values["rollers.influence.inner.pressure"]
    solved = np.asarray(values["rollers.influence.rollers"])
    which = (f"every roller's contacts ({len(solved)} × 2)" if len(solved) > 1
             else f"the most loaded roller's (#{roller}) two contacts")
    lines = ["", f"Influence coefficients (DC-FFT, Polonsky–Keer) at the load distribution: {which} on "
                 f"{pressure.shape[0]} × {pressure.shape[1]} cells replace the laminae's peak pressure"]
    for side in ("inner", "outer"):
        lines.append(f"  roller {roller}, {side}: Q = {format_number(values[f'rollers.{side}.load'][roller])} N, "
                     f"p_max = {values[f'rollers.{side}.max_pressure'][roller] / 1e9:.4g} GPa (laminae "
                     f"{values[f'rollers.{side}.lamina_max_pressure'][roller] / 1e9:.4g} GPa)")
    if result.model.inputs["bearing"].profile.kind == "straight":
        lines.append("  straight roller: the edge peak grows as the cells shrink (an edge singularity); it is grid "
                     "dependent, not a converged value")
    state = "converged" if bool(values["rollers.influence.converged"]) else "DID NOT CONVERGE (or reached the grid edge)"
    lines.append(f"  {state}, at most {int(values['rollers.influence.iterations'])} iterations; pressure maps in --json "
                 "and --plot")
    return lines


def _fixed(value, digits: int) -> str:
    """`value` with `digits` decimals, rounding noise (and −0) to 0."""
    return f"{round(float(value), digits) + 0.0:.{digits}f}"


def _report(result) -> list[str]:
    values, operating = result.values, result.model.inputs["operating"]
    d = np.asarray(values["displacement"])
    lines = ["", "Inner-ring displacement (from the concentric, aligned position)",
             f"  δx = {_fixed(d[0] * 1e6, 3)} µm, δy = {_fixed(d[1] * 1e6, 3)} µm, δz = {_fixed(d[2] * 1e6, 3)} µm, "
             f"θx = {_fixed(d[3] * 1e3, 4)} mrad, θy = {_fixed(d[4] * 1e3, 4)} mrad"]
    if operating.radial_displacement is not None:
        radial = np.asarray(values["force"])[:2] / 1e3
        lines.append(f"  radial force at the prescribed δx, δy: Fx = {_fixed(radial[0], 4)} kN, "
                     f"Fy = {_fixed(radial[1], 4)} kN")
    if operating.axial_displacement is not None:
        lines.append(f"  axial force at the prescribed δz: Fz = {_fixed(np.asarray(values['force'])[2] / 1e3, 4)} kN")
    if operating.misalignment is not None:
        moment = np.asarray(values["force"])[3:]
        lines.append(f"  moments at the imposed misalignment: Mx = {_fixed(moment[0], 3)} N·m, "
                     f"My = {_fixed(moment[1], 3)} N·m")
    names = np.array(["δx", "δy", "δz", "θx", "θy"])
    held = np.asarray(prescribed_coordinates(result.model.inputs["bearing"], operating)) > 0
    modelled = np.arange(5) != 2 if result.model.inputs["bearing"].kind == "cylindrical_roller" else np.ones(5, bool)
    lines.append(f"  free (from the load): {', '.join(names[~held & modelled]) or 'none'}; prescribed (load an output): "
                 f"{', '.join(names[held & modelled]) or 'none'}" + ("" if modelled[2] else "; δz: no ribs, no axial load"))
    if "stiffness" in values:
        lines += stiffness_lines(values["stiffness"], "rollers")
    rib = "Qrib on the cone's rib, " if "rollers.rib.load" in values else ""
    lines += element_table_lines(result, f"Rollers (ψ from +x towards +y; Q per raceway contact, {rib}φ tilt in the axial "
                                         "plane; lamina loads in --json)")
    inner = np.asarray(values["rollers.inner.load"])
    most = int(np.argmax(inner))
    lines.append(f"  {int(np.sum(inner > 0))} of {len(inner)} rollers loaded; the most loaded, #{most} at "
                 f"ψ = {np.degrees(values['rollers.azimuth'][most]):.4g}°, carries Qi = {format_number(inner[most])} N")
    lines += _influence_lines(result)
    residual = float(values["residual"])
    state = "converged" if bool(values["converged"]) else "DID NOT CONVERGE"
    return lines + ["", f"Equilibrium solver: {state} (largest scaled residual {residual:.1e})"]


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    if "rollers.inner.load" not in values:
        return []
    columns = [state_column("converged", values["converged"], ok="yes")]
    if "stiffness" in values:
        columns += [(f"{name} [N/µm]", [format_number(k[i, i] * 1e-6) for k in values["stiffness"]])
                    for i, name in enumerate(("Kxx", "Kyy", "Kzz"))]
    columns.append(("δx [µm]", [format_number(d[0] * 1e6) for d in values["displacement"]]))
    columns.append(("δz [µm]", [format_number(d[2] * 1e6) for d in values["displacement"]]))
    columns.append(("Qi max [N]", [format_number(q.max()) for q in values["rollers.inner.load"]]))
    columns.append(("p_max [GPa]", [format_number(max(p.max(), o.max()) / 1e9) for p, o in
                                    zip(values["rollers.inner.max_pressure"], values["rollers.outer.max_pressure"])]))
    if "rollers.influence.converged" in values:
        columns.append(state_column("influence", values["rollers.influence.converged"]))
    return columns


_GRID_READERS = (INFLUENCE_BLOCK,)


def _mounted_parameters(reads):
    """A [[bearings]] entry's roller bearing and raceways (no mounting of its own: the shaft's)."""
    roller = scene_roller_bearing(reads, {})["bearing"]
    return roller, scene_raceways(reads, {"bearing": roller, "mounting": None})["raceways"]


def _describe(parameters) -> str:
    roller, raceways = parameters
    return (f"{roller.kind}, {roller.roller_count} rollers of {float(roller.large_diameter) * 1e3:.4g} × "
            f"{float(roller.length) * 1e3:.4g} mm, dm = {float(raceways.pitch_diameter) * 1e3:.4g} mm")


MOUNTING = Mounting(
    parameters=_mounted_parameters,
    support=lambda parameters, position, offset, orientation, settings: RollerSupport(
        *parameters, position, offset, model=roller_model(settings), orientation=orientation),
    describe=_describe,
)

ADAPTER = register(Adapter(
    name="roller_bearing",
    bearing_types=ROLLER_KINDS,
    refused={("tapered_roller", "effects.mounting"): "ball and cylindrical roller bearings (a tapered roller "
                                                     "bearing's clearance is its axial setting)"},
    keys={
        "bearing.rollers": Key("integer"),
        "bearing.pitch_diameter": quantity("length"),
        "bearing.radial_clearance": quantity("length", "diametral"),
        "bearing.contact_angle": quantity("angle"),
        "operating.force": Key("quantities", "force", length=3, doc="[Fx, Fy, Fz] on the inner ring"),
        "operating.moment": Key("quantities", "moment", length=2, doc="[Mx, My] on the inner ring"),
        "operating.misalignment": Key("quantities", "angle", length=2,
                                      doc="imposed inner-ring tilt [θx, θy] (ball and roller bearings): the ring held "
                                          "by its shaft; the moments are then outputs (give no operating.moment)"),
        "operating.radial_displacement": Key("quantities", "length", length=2,
                                             doc="imposed radial displacement [δx, δy] of the inner ring (ball and roller "
                                                 "bearings): Fx, Fy must be 0; the radial force is then an output"),
        "operating.axial_displacement": AXIAL_DISPLACEMENT_KEY,
        "operating.inner_speed": quantity("angular_speed"),
        "operating.outer_speed": quantity("angular_speed"),
        "effects.centrifugal": Key("boolean"),
        "effects.stiffness": Key("boolean"),
        "effects.contact": Key("choice", choices=("slices", "influence")),
        "contact.rollers": Key("choice", choices=INFLUENCE_ROLLERS,
                               doc='whole roller bearing with contact = "influence": re-solve the most loaded '
                                   "roller's contacts or every roller's"),
        "fidelity.laminae": Key("integer", read_by=(EQUILIBRIUM_BLOCK, STIFFNESS_BLOCK, INFLUENCE_BLOCK),
                                doc="laminae (slices) per roller of a whole roller bearing, ISO/TS 16281 (default 30)"),
        "fidelity.grid": Key("integers", length=2, read_by=_GRID_READERS),
        "fidelity.tolerance": Key("number", read_by=_GRID_READERS),
    },
    # one contact (roller.py) or the whole bearing: the scene says which by giving one of these
    required={kind: (("contact.load", "operating.force"),) for kind in ROLLER_KINDS},
    inputs=(InputBuilder(("raceways",), ROLLER_KINDS, scene_raceways, after=("bearing", "mounting"), scene_keys=WHOLE_BEARING),
            InputBuilder(("operating",), ROLLER_KINDS, _operating, after=("bearing",), scene_keys=WHOLE_BEARING),
            InputBuilder(("influence_rollers",), ROLLER_KINDS, _influence_rollers, scene_keys=WHOLE_BEARING)),
    blocks=(EQUILIBRIUM, STIFFNESS, INFLUENCE),
    header=_header,
    report=_report,
    sweep_columns=_sweep_columns,
    mounting=MOUNTING,
))
