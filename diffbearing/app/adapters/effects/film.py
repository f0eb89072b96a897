"""Lubricant films (effect `film`) and starvation (effect `starvation`).

Ball bearings: Hamrock–Dowson point-contact films at every loaded ball (film = "hamrock_dowson"),
or the numerical point contact (film = "point") at the most loaded ball of each raceway.
Rollers, fully flooded and in pure rolling: Pan–Hamrock (film = "formula"), the numerical line
contact at mid-length ("line") or the 2-D finite line contact over the whole roller
("finite_line"). Starvation (with operating.oil_layer): the film of the same level with the inlet
supplied by an oil layer only, and Er = (h_c,ff − h_c)/h_c,ff against the flooded film (starved
when Er > 1 %); for ball bearings with film = "point" only (the θ-model, `starved_point_ehl`).
"""

import os

import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.ball.kinematics import raceway_entrainment_speed
from ....bearings.ball.raceway_contact import (
    ball_raceway_modulus,
    diameter_ratio,
    inner_curvature,
    outer_curvature,
    rolling_radius,
)
from ....bearings.roller.roller_geometry import ROLLER_KINDS, equivalent_radius, film_length, roller_modulus
from ....contact import hertz
from ....film import film_formulas
from ....film.finite_line_ehl import MAX_UNKNOWNS, finite_line_film, half_domain_grid
from ....film.finite_line_krylov import finite_line_film_krylov
from ....film.line_ehl import check_nodes, density_ratio, line_film
from ....film.nested_krylov import krylov_levels, preconditioner_bytes
from ....film.point_ehl import FEWEST_CELLS, grid_change, point_film
from ....film.starved_finite_line import starved_finite_line_film
from ....film.starved_point_ehl import march_grid, starved_point_film
from ....newton_krylov import COMPILER_OPTIONS
from ....params import BALL_BEARING_KINDS, _as_float, check_range
from ...formatting import column, state_column
from ...registry import Adapter, Block, InputBuilder, Key, Output, convergence_checks, quantity, register

DEFAULT_LINE_NODES = 513
# The finite line level (film = "finite_line"): the 2-D EHL of the whole roller length, half
# domain, on fidelity.grid = [nx, ny]: nx nodes along rolling by ny cells along the whole roller,
# of which the ⌈ny/2⌉ on y ≥ 0 are solved (`finite_line_ehl.half_domain_grid`).
DEFAULT_FINITE_LINE_GRID = (33, 96)
# Its solver (fidelity.solver): "dense", the dense Newton on cells clustered at the roller end,
# or "krylov", the matrix-free Newton–Krylov on uniform cells (`finite_line_krylov`); by default
# the dense one where the half grid fits it, else Newton–Krylov.
FINITE_LINE_SOLVERS = ("dense", "krylov")
# The point contact level (film = "point"): fidelity.grid = [nx, ny], nx nodes along rolling by
# ny cells across the whole contact, of which the ⌈ny/2⌉ on y ≥ 0 are solved; on 129 × 64 the
# central film is 1.5 % below its grid-extrapolated value for a ball in its groove
# (docs/validation/lubricant_film.md §The point contact).
DEFAULT_POINT_GRID = (129, 128)
# [-] the point contact's central film changed by more than this from the next coarser grid: the
# report warns that the grid does not resolve the film (its own error, at the observed order
# 1.7–2, about half the change: `point_ehl.grid_change`). The catalogue-load cases of
# docs/validation/lubricant_film.md change by 4.5–14 % from 65 × 32 to 129 × 64, the groove at
# 3 kN by 24 %, the 209 bearing at 8.9 kN by 42 and 50 % (its films 18–22 % below the resolved ones).
GRID_CHANGE_WARNING = 0.15
# Chevalier's γ for a line contact: no side flow, so the film follows the supply until it meets
# the flooded one; γ = 20 matches the 1-D numerical starved films (`benchmarks/line_ehl.py`).
LINE_STARVATION_SHARPNESS = 20.0


def _oil_layer(v, built) -> dict:
    if "operating.oil_layer" not in v:
        raise ValueError("effects.starvation needs operating.oil_layer (the inlet oil supply layer, e.g. \"0.8 um\")")
    layer = v["operating.oil_layer"]
    check_range("operating.oil_layer", layer, low=1e-9, high=1e-3, unit=" m",
                why="a layer between 1 nm and 1 mm; omit it for a fully flooded inlet")
    return {"oil_layer": _as_float(layer)}


# --- ball bearings: Hamrock–Dowson at every ball ----------------------------------------------

def _film_hamrock_dowson(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, operating, lubricant = inputs["bearing"], inputs["operating"], inputs["lubricant"]
    modulus = ball_raceway_modulus(bearing)
    orbital = results["balls.orbital_speed"]
    out = {}
    for side, curvature, ring_speed in (("inner", inner_curvature, operating.inner_speed),
                                        ("outer", outer_curvature, operating.outer_speed)):
        load, angle = results[f"balls.{side}.load"], results[f"balls.{side}.contact_angle"]
        radius = rolling_radius(bearing, angle, side)
        speed = raceway_entrainment_speed(ring_speed, orbital, bearing.pitch_diameter, diameter_ratio(bearing, angle),
                                          side)
        ellipticity = hertz.ellipticity(curvature(bearing, angle)[1])
        loaded = load > 0
        central, minimum = film_formulas.hamrock_dowson_point(
            jnp.where(loaded, load, 1.0), radius, ellipticity, speed, lubricant.viscosity,
            lubricant.pressure_viscosity, modulus)
        out |= {f"film.{side}.central": jnp.where(loaded, central, jnp.nan),
                f"film.{side}.minimum": jnp.where(loaded, minimum, jnp.nan),
                f"film.{side}.entrainment_speed": speed}
        if inputs["roughness"] is not None:
            out[f"film.{side}.film_parameter"] = jnp.where(
                loaded, film_formulas.film_parameter(minimum, inputs["roughness"]), jnp.nan)
    return out


def _ball_film_outputs(side):
    short = side[0]
    return (
        Output(f"film.{side}.central", "m", "um", f"central film h_c (Hamrock–Dowson), {side}", column=f"hc,{short}"),
        Output(f"film.{side}.minimum", "m", "um", f"minimum film h_min (Hamrock–Dowson), {side}",
               column=f"hmin,{short}"),
        Output(f"film.{side}.entrainment_speed", "m/s", "m/s", f"mean entrainment speed u, {side}", in_report=False),
        Output(f"film.{side}.film_parameter", "", "", f"film parameter Λ = h_min/σ, {side}", column=f"Λ{short}"),
    )


# --- ball bearings: the numerical point contact at the most loaded ball ------------------------

# Newton–Krylov holds its column preconditioner (`nested_krylov.preconditioner_bytes`) twice at
# once, the iteration's and the implicit derivative's; a grid whose two copies need more than half
# the machine's memory is refused before it compiles.
PRECONDITIONER_COPIES = 2
MEMORY_SHARE = 0.5


def machine_memory() -> int:
    """This machine's physical memory [B]."""
    return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")


def check_grid_memory(grid, starved: bool = False) -> None:
    """ValueError naming fidelity.grid where the Newton–Krylov solve on the half-domain `grid` would
    not fit in `MEMORY_SHARE` of this machine's memory (its estimate in the message)."""
    estimate = PRECONDITIONER_COPIES * preconditioner_bytes(grid, starved)
    if estimate > MEMORY_SHARE * machine_memory():
        raise ValueError(f"fidelity.grid: the {grid[0]} × {grid[1]} half-domain grid needs about "
                         f"{estimate / 2**30:.3g} GiB ({grid[1]} dense column blocks of {grid[0] - 2}² in float64, held "
                         f"twice), more than half of this machine's {machine_memory() / 2**30:.3g} GiB: take a coarser grid")


def point_grid(settings: dict) -> tuple[int, int]:
    """(nx, ny on the half domain) of the point contact level from fidelity.grid (default
    [129, 128]); ValueError naming the key for a grid the solver does not take or the machine
    cannot hold (`check_grid_memory`)."""
    nx, ny = (int(n) for n in settings["fidelity"].get("grid", DEFAULT_POINT_GRID))
    half = (ny + 1) // 2
    try:
        krylov_levels((nx, half), FEWEST_CELLS)
    except ValueError as error:
        raise ValueError(f"fidelity.grid = [nx, ny] with effects.film = \"point\" (ny across the whole contact, "
                         f"half solved): {str(error).removeprefix('grid: ')}") from None
    check_grid_memory((nx, half), starved=settings["effects"].get("starvation", False) is True)
    return nx, half


def _point_settings(settings: dict, inputs: dict) -> None:
    """ValueError for a grid the point contact does not take, or rings that do not roll (no
    entrainment: the Reynolds equation has no film to carry the load)."""
    point_grid(settings)
    operating = inputs["operating"]
    relative = operating.inner_speed - operating.outer_speed
    if not isinstance(relative, jax.core.Tracer) and float(relative) == 0.0:
        raise ValueError("operating.inner_speed: effects.film = \"point\" needs rolling (inner_speed ≠ outer_speed); "
                         "at standstill no lubricant film forms")


_POINT_FIELDS = ("central", "minimum", "converged", "x", "y", "pressure", "thickness")


def _point_case(inputs: dict, results: dict, side: str) -> dict:
    """The contact of the most loaded ball on the `side` raceway: its index, load [N], radii Rx, Ry
    [m], curvature difference [-] and entrainment speed [m/s]; an unloaded raceway is solved at 1 N."""
    bearing, operating = inputs["bearing"], inputs["operating"]
    curvature, ring_speed = ((inner_curvature, operating.inner_speed) if side == "inner"
                             else (outer_curvature, operating.outer_speed))
    loads = results[f"balls.{side}.load"]
    ball = jnp.argmax(loads)
    load, angle = loads[ball], results[f"balls.{side}.contact_angle"][ball]
    curvature_sum, difference = curvature(bearing, angle)
    radius_rolling = rolling_radius(bearing, angle, side)
    speed = raceway_entrainment_speed(ring_speed, results["balls.orbital_speed"][ball], bearing.pitch_diameter,
                                      diameter_ratio(bearing, angle), side)
    return dict(ball=ball, load=load, solved_load=jnp.where(load > 0, load, 1.0), radius_rolling=radius_rolling,
                radius_transverse=1.0 / (curvature_sum - 1.0 / radius_rolling), difference=difference, speed=speed)


def _film_point(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, lubricant = inputs["bearing"], inputs["lubricant"]
    modulus = ball_raceway_modulus(bearing)
    out = {}
    for side in ("inner", "outer"):
        case = _point_case(inputs, results, side)
        loaded = case["load"] > 0  # an unloaded raceway has no film: null values (NaN), solved at 1 N
        solved = point_film(case["solved_load"], case["radius_rolling"], case["radius_transverse"], case["speed"],
                            lubricant.viscosity, lubricant.pressure_viscosity, modulus, grid=point_grid(settings),
                            viscosity_law=lubricant.viscosity_law, density_law=lubricant.density_law)
        central, minimum = film_formulas.hamrock_dowson_point(
            case["solved_load"], case["radius_rolling"], hertz.ellipticity(case["difference"]), case["speed"],
            lubricant.viscosity, lubricant.pressure_viscosity, modulus)
        films = {"central": solved.central, "minimum": solved.minimum, "hamrock_dowson_central": central,
                 "hamrock_dowson_minimum": minimum, "grid_change": grid_change(solved)}
        out |= {f"film.{side}.ball": case["ball"], f"film.{side}.load": case["load"],
                f"film.{side}.entrainment_speed": case["speed"],
                **{f"film.{side}.{name}": getattr(solved, name) for name in _POINT_FIELDS},
                **{f"film.{side}.{name}": jnp.where(loaded, value, jnp.nan) for name, value in films.items()}}
        if inputs["roughness"] is not None:
            out[f"film.{side}.film_parameter"] = film_formulas.film_parameter(out[f"film.{side}.minimum"],
                                                                              inputs["roughness"])
    return out


_POINT_CONVERGENCE = convergence_checks(("film.inner.converged", "the point contact EHL (inner raceway)"),
                                        ("film.outer.converged", "the point contact EHL (outer raceway)"))


def _point_checks(values: dict) -> tuple[list[str], list[str]]:
    """Each solve's convergence (an error where it did not), and a warning where a converged film
    changed by more than GRID_CHANGE_WARNING from the next coarser grid."""
    errors, warnings = _POINT_CONVERGENCE(values)
    for side in ("inner", "outer"):
        change = float(values[f"film.{side}.grid_change"])
        if bool(values[f"film.{side}.converged"]) and change > GRID_CHANGE_WARNING:  # NaN: unloaded
            warnings.append(f"film.{side}.central changed by {100 * change:.3g} % from the next coarser grid: this grid "
                            f"does not resolve the film (its own error is about half that); refine fidelity.grid")
    return errors, warnings


def _starvation_point(inputs: dict, settings: dict, results: dict) -> dict:
    """The starved films of the same two contacts as `_film_point` (`starved_point_ehl`)."""
    bearing, lubricant, oil_layer = inputs["bearing"], inputs["lubricant"], inputs["oil_layer"]
    modulus = ball_raceway_modulus(bearing)
    out = {"starvation.oil_layer": oil_layer}
    for side in ("inner", "outer"):
        case = _point_case(inputs, results, side)
        solved = starved_point_film(case["solved_load"], case["radius_rolling"], case["radius_transverse"],
                                    case["speed"], lubricant.viscosity, lubricant.pressure_viscosity, modulus, oil_layer,
                                    grid=point_grid(settings), viscosity_law=lubricant.viscosity_law,
                                    density_law=lubricant.density_law)
        loaded = case["load"] > 0
        central = jnp.where(loaded, solved.film.central, jnp.nan)
        out |= {f"starvation.{side}.central": central,
                f"starvation.{side}.minimum": jnp.where(loaded, solved.film.minimum, jnp.nan),
                f"starvation.{side}.relative_error": 1.0 - central / results[f"film.{side}.central"],
                f"starvation.{side}.converged": solved.film.converged,
                f"starvation.{side}.pressure": solved.film.pressure, f"starvation.{side}.thickness": solved.film.thickness,
                f"starvation.{side}.fill": solved.fill}
    return out


def _starved_point_outputs(side):
    return (
        Output(f"starvation.{side}.central", "m", "um", f"starved central film h_c at the most loaded ball, {side}"),
        Output(f"starvation.{side}.minimum", "m", "um", f"starved minimum film h_min, {side}"),
        Output(f"starvation.{side}.relative_error", "", "percent",
               f"Er = (h_c,ff − h_c)/h_c,ff (starved if > 1 %), {side}"),
        Output(f"starvation.{side}.converged", "", "", f"the starved point contact EHL converged, {side}",
               in_report=False),
        Output(f"starvation.{side}.pressure", "Pa", "GPa", f"starved film pressure p[x, y], {side}", in_report=False),
        Output(f"starvation.{side}.thickness", "m", "um", f"starved film thickness h[x, y], {side}", in_report=False),
        Output(f"starvation.{side}.fill", "", "", f"oil fill θ[x, y] of the gap (1: full film), {side}",
               in_report=False),
    )


def _point_outputs(side):
    return (
        Output(f"film.{side}.ball", "", "", f"most loaded ball (index), where solved, {side}"),
        Output(f"film.{side}.load", "N", "N", f"its contact load Q, {side}"),
        Output(f"film.{side}.central", "m", "um", f"central film h_c (numerical point contact), {side}"),
        Output(f"film.{side}.minimum", "m", "um", f"minimum film h_min (numerical point contact), {side}"),
        Output(f"film.{side}.hamrock_dowson_central", "m", "um", f"Hamrock–Dowson h_c at that ball, {side}"),
        Output(f"film.{side}.hamrock_dowson_minimum", "m", "um", f"Hamrock–Dowson h_min at that ball, {side}"),
        Output(f"film.{side}.film_parameter", "", "", f"film parameter Λ = h_min/σ, {side}"),
        Output(f"film.{side}.grid_change", "", "percent",
               f"change of h_c from the next coarser grid (about twice the grid's own error), {side}"),
        Output(f"film.{side}.entrainment_speed", "m/s", "m/s", f"mean entrainment speed u, {side}", in_report=False),
        Output(f"film.{side}.converged", "", "", f"the {side} point contact EHL converged", in_report=False),
        Output(f"film.{side}.x", "m", "mm", "nodes along rolling (x)", in_report=False),
        Output(f"film.{side}.y", "m", "mm", "cell centres across rolling from the rolling plane (y ≥ 0)",
               in_report=False),
        Output(f"film.{side}.pressure", "Pa", "GPa", f"film pressure p[x, y], {side}", in_report=False),
        Output(f"film.{side}.thickness", "m", "um", f"film thickness h[x, y], {side}", in_report=False),
    )


def _point_film_plot(result, figure):
    """Pressure and film maps of the inner and outer contacts of the most loaded balls, mirrored
    to the whole contact."""
    values = result.values
    axes = figure.subplots(2, 2)
    for row, side in enumerate(("inner", "outer")):
        x = np.asarray(values[f"film.{side}.x"]) * 1e3
        y = np.asarray(values[f"film.{side}.y"]) * 1e3
        whole_y = np.concatenate([-y[::-1], y])

        def whole(field):
            field = np.asarray(field)
            return np.concatenate([field[:, ::-1], field], axis=1)

        central = float(values[f"film.{side}.central"]) * 1e6
        for axis, field, scale, cmap, label, limit in (
                (axes[row, 0], values[f"film.{side}.pressure"], 1e-9, "viridis", "pressure [GPa]", None),
                (axes[row, 1], values[f"film.{side}.thickness"], 1e6, "magma", "film thickness [µm]", 3 * central)):
            shown = axis.pcolormesh(whole_y, x, whole(field) * scale, shading="nearest", cmap=cmap, vmax=limit)
            figure.colorbar(shown, ax=axis, label=label)
            axis.set(xlabel="y across rolling [mm]", ylabel="x, rolling [mm]", aspect="equal",
                     title=f"{side}, ball {int(values[f'film.{side}.ball'])}: {label.split(' [')[0]}")
    figure.suptitle(f"{result.model.scene.title}: point contact EHL, {len(x)} × {len(y)} half-domain grid")


def _starved_point_plot(result, figure):
    """The film along rolling on the rolling plane (y's first cell), flooded and starved, and the
    oil fill θ there, at the inner and outer contacts."""
    values = result.values
    layer = float(values["starvation.oil_layer"]) * 1e6
    for axis, side in zip(figure.subplots(1, 2), ("inner", "outer")):
        x = np.asarray(values[f"film.{side}.x"]) * 1e3
        axis.plot(x, np.asarray(values[f"film.{side}.thickness"])[:, 0] * 1e6, label="fully flooded")
        axis.plot(x, np.asarray(values[f"starvation.{side}.thickness"])[:, 0] * 1e6, label=f"starved, h_oil = {layer:.3g} µm")
        axis.axhline(layer, color="grey", lw=0.8, ls="--", label="oil layer")
        fill = axis.twinx()
        fill.plot(x, np.asarray(values[f"starvation.{side}.fill"])[:, 0], color="tab:green", lw=0.8)
        fill.set(ylabel="oil fill θ (green)", ylim=(0, 1.05))
        central = float(values[f"film.{side}.central"]) * 1e6
        axis.set(xlabel="x, rolling [mm]", ylabel="film thickness [µm]", ylim=(0, 4 * central),
                 title=f"{side}, ball {int(values[f'film.{side}.ball'])}")
        axis.grid(alpha=0.3)
        axis.legend(fontsize="small")
    figure.suptitle(f"{result.model.scene.title}: starved point contact EHL on the rolling plane")


# --- rollers: fully flooded -------------------------------------------------------------------

def _entrainment(settings: dict, inputs: dict) -> None:
    """ValueError for a roller scene without entrainment speed."""
    speed = inputs["operating"].entrainment_speed
    if not isinstance(speed, jax.core.Tracer) and float(speed) <= 0:
        raise ValueError("effects.film needs an entrainment speed: give operating.inner_speed (or outer_speed) "
                         "and bearing.pitch_diameter (cylindrical roller)")


def _line_settings(settings: dict, inputs: dict) -> None:
    """ValueError for a roller scene without entrainment speed or a bad line EHL grid."""
    _entrainment(settings, inputs)
    check_nodes(_line_nodes(settings))


def _finite_line_settings(settings: dict, inputs: dict) -> None:
    """ValueError for a roller scene without entrainment speed or a bad finite line grid."""
    _entrainment(settings, inputs)
    finite_line_settings(settings)


def _krylov_options(settings: dict) -> dict:
    """XLA's options for a program holding a Newton–Krylov finite line solve (`newton_krylov.COMPILER_OPTIONS`)."""
    return COMPILER_OPTIONS if finite_line_settings(settings)[1] == "krylov" else {}


def _starvation_model(settings: dict) -> str:
    """fidelity.starvation_model of the starved finite line contact (default: "meniscus" with the
    dense solver, "theta" with Newton–Krylov, where the meniscus model does not converge on the
    paper's grid); ValueError naming it where "theta" meets the dense solver (the θ-model runs on
    Newton–Krylov's uniform grids)."""
    solver = finite_line_settings(settings)[1]
    model = settings["fidelity"].get("starvation_model", "meniscus" if solver == "dense" else "theta")
    if model == "theta" and solver == "dense":
        raise ValueError("fidelity.starvation_model = \"theta\" runs on Newton–Krylov's uniform grids: set "
                         "fidelity.solver = \"krylov\" (and a fidelity.grid it takes, e.g. [129, 257])")
    return model


def _starved_finite_line_settings(settings: dict, inputs: dict) -> None:
    _starvation_model(settings)


def _line_nodes(settings: dict) -> int:
    """Nodes of the line EHL level: fidelity.grid[0], default 513."""
    return settings["fidelity"].get("grid", [DEFAULT_LINE_NODES])[0]


def finite_line_settings(settings: dict) -> tuple[tuple[int, int], str]:
    """((nx, ny on the half domain), solver) of the finite line level from fidelity.grid (whole
    roller length, default [33, 96]) and fidelity.solver (default: "dense" where the half grid
    fits it, else "krylov"); ValueError naming the key for a grid the solver does not take or the
    machine cannot hold (`check_grid_memory`)."""
    fidelity = settings["fidelity"]
    nx, ny = (int(n) for n in fidelity.get("grid", DEFAULT_FINITE_LINE_GRID))
    half = (ny + 1) // 2
    solver = fidelity.get("solver", "dense" if (nx - 2) * half <= MAX_UNKNOWNS else "krylov")
    if solver == "dense":
        return half_domain_grid((nx, ny)), solver
    try:
        krylov_levels((nx, half))
    except ValueError as error:
        raise ValueError(f"fidelity.grid = [nx, ny] with fidelity.solver = \"krylov\" (half ⌈ny/2⌉ solved): "
                         f"{str(error).removeprefix('grid: ')}") from None
    check_grid_memory((nx, half), starved=settings["effects"].get("starvation", False) is True)
    return (nx, half), solver


def _roller_film_case(inputs: dict):
    bearing, loading, lubricant = inputs["bearing"], inputs["operating"], inputs["lubricant"]
    return (loading.load / film_length(bearing), equivalent_radius(bearing, loading, jnp.asarray(0.0)),
            loading.entrainment_speed, lubricant.viscosity, lubricant.pressure_viscosity, roller_modulus(bearing))


def _film_formula(inputs: dict, settings: dict, results: dict) -> dict:
    central, minimum = film_formulas.pan_hamrock_line(*_roller_film_case(inputs))
    return {"film.central": central, "film.minimum": minimum,
            "film.entrainment_speed": inputs["operating"].entrainment_speed}


def _line(inputs: dict, settings: dict, oil_layer=None):
    lubricant = inputs["lubricant"]
    return line_film(*_roller_film_case(inputs), nodes=_line_nodes(settings), oil_layer=oil_layer,
                     viscosity_law=lubricant.viscosity_law, density_law=lubricant.density_law)


def _film_line(inputs: dict, settings: dict, results: dict) -> dict:
    solved = _line(inputs, settings)
    return {"film.central": solved.central, "film.minimum": solved.minimum, "film.converged": solved.converged,
            "film.entrainment_speed": inputs["operating"].entrainment_speed, "film.x": solved.x,
            "film.pressure": solved.pressure, "film.thickness": solved.thickness}


def _finite_line(inputs: dict, settings: dict, oil_layer=None):
    bearing, lubricant = inputs["bearing"], inputs["lubricant"]
    _, radius, speed, viscosity, pressure_viscosity, modulus = _roller_film_case(inputs)
    grid, solver = finite_line_settings(settings)
    case = (inputs["operating"].load, radius, speed, viscosity, pressure_viscosity, modulus, bearing.profile,
            bearing.length, film_length(bearing))
    laws = dict(viscosity_law=lubricant.viscosity_law, density_law=lubricant.density_law)
    if oil_layer is not None and _starvation_model(settings) == "theta":
        return starved_finite_line_film(*case, oil_layer, grid=grid, **laws)
    solve = finite_line_film if solver == "dense" else finite_line_film_krylov
    return solve(*case, grid=grid, oil_layer=oil_layer, **laws)


_FINITE_LINE_FIELDS = ("central", "minimum", "minimum_position", "converged", "x", "y", "pressure", "thickness")


def _film_finite_line(inputs: dict, settings: dict, results: dict) -> dict:
    solved = _finite_line(inputs, settings)
    return {"film.entrainment_speed": inputs["operating"].entrainment_speed,
            **{f"film.{name}": getattr(solved, name) for name in _FINITE_LINE_FIELDS}}


_ROLLER_FILM_COMMON = (
    Output("film.central", "m", "um", "central film h_c at x = 0"),
    Output("film.minimum", "m", "um", "minimum film h_min"),
    Output("film.entrainment_speed", "m/s", "m/s", "mean entrainment speed u (pure rolling)"),
)


def _finite_line_outputs(prefix: str, case: str):
    return (
        Output(f"{prefix}.minimum_position", "m", "mm", f"where the {case} h_min is, y from mid-length"),
        Output(f"{prefix}.converged", "", "", f"the {case} finite line EHL Newton converged", in_report=False),
        Output(f"{prefix}.x", "m", "mm", "nodes along rolling (x), inlet at −4.5 b", in_report=False),
        Output(f"{prefix}.y", "m", "mm", "cell centres along the roller from mid-length (y ≥ 0)", in_report=False),
        Output(f"{prefix}.pressure", "Pa", "GPa", f"{case} film pressure p[x, y]", in_report=False),
        Output(f"{prefix}.thickness", "m", "um", f"{case} film thickness (the gap where dry) h[x, y]",
               in_report=False),
    )


# --- rollers: starved ----------------------------------------------------------------------------

def _starvation_formula(inputs: dict, settings: dict, results: dict) -> dict:
    oil_layer = inputs["oil_layer"]
    load_per_length, radius, _, _, _, modulus = _roller_film_case(inputs)
    density = density_ratio(hertz.line_contact(load_per_length, radius, modulus).max_pressure,
                            inputs["lubricant"].density_law)
    flooded_central, flooded_minimum = results["film.central"], results["film.minimum"]
    central = film_formulas.starved_film(flooded_central, oil_layer, density, LINE_STARVATION_SHARPNESS)
    minimum = flooded_minimum * central / flooded_central  # the flooded h_min/h_c ratio kept (an estimate)
    return {"starvation.oil_layer": oil_layer, "starvation.central": central, "starvation.minimum": minimum,
            "starvation.relative_error": 1.0 - central / flooded_central}


def _starvation_line(inputs: dict, settings: dict, results: dict) -> dict:
    oil_layer = inputs["oil_layer"]
    solved = _line(inputs, settings, oil_layer)
    return {"starvation.oil_layer": oil_layer, "starvation.central": solved.central, "starvation.minimum": solved.minimum,
            "starvation.relative_error": 1.0 - solved.central / results["film.central"],
            "starvation.meniscus": solved.meniscus, "starvation.converged": solved.converged,
            "starvation.x": solved.x, "starvation.pressure": solved.pressure, "starvation.thickness": solved.thickness}


def _starvation_finite_line(inputs: dict, settings: dict, results: dict) -> dict:
    solved = _finite_line(inputs, settings, oil_layer=inputs["oil_layer"])
    return {"starvation.oil_layer": inputs["oil_layer"],
            "starvation.relative_error": 1.0 - solved.central / results["film.central"],
            "starvation.meniscus": solved.meniscus,
            **{f"starvation.{name}": getattr(solved, name) for name in _FINITE_LINE_FIELDS}}


_STARVATION_COMMON = (
    Output("starvation.oil_layer", "m", "um", "inlet oil supply layer h_oil"),
    Output("starvation.central", "m", "um", "starved central film h_c"),
    Output("starvation.minimum", "m", "um", "starved minimum film h_min"),
    Output("starvation.relative_error", "", "percent", "Er = (h_c,ff − h_c)/h_c,ff (starved if > 1 %)"),
)


# --- plots ---------------------------------------------------------------------------------------

def _line_film_plot(result, figure):
    """Pressure and film thickness along the rolling direction of the line EHL solution, with the
    starved solution beside the flooded one when the scene names starvation."""
    values = result.values
    pressure_axis, film_axis = figure.subplots(1, 2)
    cases = [("film", "fully flooded")]
    if "starvation.x" in values:
        layer = float(values["starvation.oil_layer"]) * 1e6
        cases.append(("starvation", f"starved, h_oil = {layer:.3g} µm"))
    for prefix, label in cases:
        x = np.asarray(values[f"{prefix}.x"]) * 1e3
        pressure_axis.plot(x, np.asarray(values[f"{prefix}.pressure"]) / 1e9, label=label)
        film_axis.plot(x, np.asarray(values[f"{prefix}.thickness"]) * 1e6, label=label)
    film_axis.axhline(float(values["film.central"]) * 1e6, color="grey", lw=0.8, ls="--", label="flooded central film")
    pressure_axis.set(xlabel="x, rolling direction [mm]", ylabel="pressure [GPa]", title="film pressure")
    film_axis.set(xlabel="x, rolling direction [mm]", ylabel="film thickness [µm]", title="film thickness",
                  ylim=(0, 4 * float(values["film.central"]) * 1e6))
    for axis in (pressure_axis, film_axis):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(f"{result.model.scene.title}: line EHL")


def _finite_line_film_plot(result, figure):
    """Maps of the finite line EHL solution (the starved one when the scene names starvation) over
    the half roller, and the film along the roller through its minimum, flooded and starved."""
    values = result.values
    prefix = "starvation" if "starvation.pressure" in values else "film"
    x, y = np.asarray(values[f"{prefix}.x"]) * 1e3, np.asarray(values[f"{prefix}.y"]) * 1e3
    pressure_axis, film_axis, line_axis = figure.subplots(1, 3)
    shown = pressure_axis.pcolormesh(y, x, np.asarray(values[f"{prefix}.pressure"]) / 1e9, shading="nearest",
                                     cmap="viridis")
    figure.colorbar(shown, ax=pressure_axis, label="pressure [GPa]")
    thickness = np.asarray(values[f"{prefix}.thickness"]) * 1e6
    shown = film_axis.pcolormesh(y, x, thickness, shading="nearest", cmap="magma",
                                 vmax=3 * float(values["film.central"]) * 1e6)
    figure.colorbar(shown, ax=film_axis, label="film thickness [µm]")
    case = "starved" if prefix == "starvation" else "flooded"
    for axis, name in ((pressure_axis, "pressure"), (film_axis, "film")):
        axis.set(xlabel="y from mid-length [mm]", ylabel="x, rolling [mm]", title=f"{case} {name}")
    for name, label in (("film", "fully flooded"), ("starvation", "starved")):
        if f"{name}.thickness" in values:
            film = np.asarray(values[f"{name}.thickness"]) * 1e6
            row = np.unravel_index(np.argmin(film), film.shape)[0]
            line_axis.plot(np.asarray(values[f"{name}.y"]) * 1e3, film[row], label=f"{label}, at its h_min row")
    line_axis.set(xlabel="y from mid-length [mm]", ylabel="film thickness [µm]", title="film along the roller",
                  ylim=(0, 3 * float(values["film.central"]) * 1e6))
    line_axis.grid(alpha=0.3)
    line_axis.legend()
    figure.suptitle(f"{result.model.scene.title}: finite line EHL, {len(x)} × {len(y)} half-domain grid")


# --- report --------------------------------------------------------------------------------------

def _report(result) -> list[str]:
    values = result.values
    if "film.inner.pressure" in values:  # the point contact level
        lines = [f"  point contact EHL ({side}, Newton–Krylov, {len(values[f'film.{side}.x'])} × "
                 f"{len(values[f'film.{side}.y'])} half-domain grid): "
                 + ("converged" if bool(values[f"film.{side}.converged"]) else
                    "DID NOT CONVERGE (values are the last iterate)") for side in ("inner", "outer")]
        marched = march_grid(point_grid(result.model.settings))
        return lines + [f"  starved point contact EHL ({side}, θ-model, Newton–Krylov: a pseudo-time march on "
                        f"{marched[0]} × {marched[1]}, then grid by grid): "
                        + ("converged" if bool(values[f"starvation.{side}.converged"]) else
                           "DID NOT CONVERGE (values are the last iterate)")
                        for side in ("inner", "outer") if f"starvation.{side}.converged" in values]
    if "film.y" in values:  # the finite line level
        grid, chosen = finite_line_settings(result.model.settings)
        solver = "Newton–Krylov" if chosen == "krylov" and len(krylov_levels(grid)) > 1 else "Newton"
        level, grid = "finite line EHL", f"{solver}, {len(values['film.x'])} × {len(values['film.y'])} half-domain grid"
        meniscus = ("the mass-conserving θ-model" if _starvation_model(result.model.settings) == "theta"
                    else "a meniscus per y cell by mass balance")
    else:
        level, grid, meniscus = "line EHL", f"Newton, {len(values.get('film.x', ()))} nodes", "meniscus by flux balance"
    lines = []
    for key, solve in (("film.converged", f"{grid}, fully flooded"),
                       ("starvation.converged", f"starved by the oil layer, {meniscus}")):
        if key in values:
            state = "converged" if bool(values[key]) else "DID NOT CONVERGE (values are the last iterate)"
            lines.append(f"  {level} ({solve}): {state}")
    return lines


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    columns = []
    for prefix, name in (("film", "film"), ("starvation", "starved")):
        if f"{prefix}.central" in values and np.ndim(values[f"{prefix}.central"]) == 1:  # roller contacts
            columns.append(column(f"{name} h_c [µm]", values[f"{prefix}.central"], 1e6))
            columns.append(column(f"{name} h_min [µm]", values[f"{prefix}.minimum"], 1e6))
            if f"{prefix}.converged" in values:
                columns.append(state_column(name, values[f"{prefix}.converged"]))
    return columns


ROLLER_INPUTS = ("bearing", "operating", "lubricant")
_FILM_BLOCKS = ("film_line", "film_finite_line", "starvation_line", "starvation_finite_line", "film_point",
                "starvation_point")

ADAPTER = register(Adapter(
    name="film",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={
        "effects.film": Key("choice", choices=(False, "hamrock_dowson", "point", "formula", "line", "finite_line")),
        "effects.starvation": Key("boolean"),
        "operating.oil_layer": quantity("length", "inlet oil supply layer"),
        "fidelity.grid": Key("integers", length=2, read_by=_FILM_BLOCKS,
                             doc="[nx, ny] cells along rolling and along the whole roller (or across the whole "
                                 "point contact; 2-D EHL solves the half y ≥ 0)"),
        "fidelity.solver": Key("choice", choices=FINITE_LINE_SOLVERS,
                               read_by=("film_finite_line", "starvation_finite_line"),
                               doc="finite line EHL: dense Newton (clustered cells) or matrix-free Newton–Krylov "
                                   "(uniform cells); default dense where the grid fits it"),
        "fidelity.starvation_model": Key("choice", choices=("meniscus", "theta"), read_by=("starvation_finite_line",),
                                         doc="starved finite line EHL: a meniscus per y cell (the dense solver's "
                                             "default) or the mass-conserving θ-model (Newton–Krylov only, its "
                                             "default)"),
    },
    inputs=(InputBuilder(("oil_layer",), ROLLER_KINDS + BALL_BEARING_KINDS, _oil_layer),),
    blocks=(
        Block(name="film_hamrock_dowson", bearing_types=BALL_BEARING_KINDS, enabled_by=("film", "hamrock_dowson"),
              requires=("equilibrium",), inputs=("bearing", "operating", "lubricant", "roughness"),
              outputs=(*_ball_film_outputs("inner"), *_ball_film_outputs("outer")), compute=_film_hamrock_dowson),
        Block(name="film_point", sequential_sweep=True, bearing_types=BALL_BEARING_KINDS, enabled_by=("film", "point"),
              requires=("equilibrium",), inputs=("bearing", "operating", "lubricant", "roughness"),
              outputs=(*_point_outputs("inner"), *_point_outputs("outer")), compute=_film_point,
              validate=_point_settings, plot=_point_film_plot,
              compiler_options=lambda settings: COMPILER_OPTIONS, own_program=True,
              checks=_point_checks),
        Block(name="starvation_point", sequential_sweep=True, bearing_types=BALL_BEARING_KINDS,
              enabled_by=("starvation", True), only_with=("film", ("point",)), requires=("film_point",),
              inputs=("bearing", "operating", "lubricant", "oil_layer"),
              outputs=(Output("starvation.oil_layer", "m", "um", "inlet oil supply layer h_oil"),
                       *_starved_point_outputs("inner"), *_starved_point_outputs("outer")),
              compute=_starvation_point, validate=_point_settings, plot=_starved_point_plot,
              compiler_options=lambda settings: COMPILER_OPTIONS, own_program=True,
              checks=convergence_checks(("starvation.inner.converged", "the starved point contact EHL (inner raceway)"),
                                        ("starvation.outer.converged", "the starved point contact EHL (outer raceway)"))),
        Block(name="film_formula", bearing_types=ROLLER_KINDS, enabled_by=("film", "formula"),
              requires=("roller_geometry",), inputs=ROLLER_INPUTS, outputs=_ROLLER_FILM_COMMON,
              compute=_film_formula, validate=_entrainment),
        Block(name="film_line", sequential_sweep=True, bearing_types=ROLLER_KINDS, enabled_by=("film", "line"),
              requires=("roller_geometry",), inputs=ROLLER_INPUTS,
              outputs=(
                  *_ROLLER_FILM_COMMON,
                  Output("film.converged", "", "", "the line EHL Newton converged", in_report=False),
                  Output("film.x", "m", "mm", "nodes along rolling (x), inlet at −4.5 b", in_report=False),
                  Output("film.pressure", "Pa", "GPa", "film pressure p(x)", in_report=False),
                  Output("film.thickness", "m", "um", "film thickness h(x)", in_report=False),
              ),
              compute=_film_line, validate=_line_settings, plot=_line_film_plot,
              checks=convergence_checks(("film.converged", "the line EHL Newton (fully flooded film)"))),
        Block(name="film_finite_line", sequential_sweep=True, bearing_types=ROLLER_KINDS,
              enabled_by=("film", "finite_line"), requires=("roller_geometry",), inputs=ROLLER_INPUTS,
              outputs=(*_ROLLER_FILM_COMMON, *_finite_line_outputs("film", "flooded")),
              compute=_film_finite_line, validate=_finite_line_settings, plot=_finite_line_film_plot,
              compiler_options=_krylov_options, own_program=True,
              checks=convergence_checks(("film.converged", "the finite line EHL Newton (fully flooded film)"))),
        Block(name="starvation_formula", bearing_types=ROLLER_KINDS, enabled_by=("starvation", True),
              only_with=("film", ("formula",)), requires=("film_formula",), inputs=ROLLER_INPUTS + ("oil_layer",),
              outputs=_STARVATION_COMMON, compute=_starvation_formula),
        Block(name="starvation_line", sequential_sweep=True, bearing_types=ROLLER_KINDS,
              enabled_by=("starvation", True), only_with=("film", ("line",)), requires=("film_line",),
              inputs=ROLLER_INPUTS + ("oil_layer",),
              outputs=(
                  *_STARVATION_COMMON,
                  Output("starvation.meniscus", "m", "mm", "inlet meniscus x_m, where the pressure starts"),
                  Output("starvation.converged", "", "", "the starved line EHL Newton converged", in_report=False),
                  Output("starvation.x", "m", "mm", "nodes along rolling (x), from the meniscus", in_report=False),
                  Output("starvation.pressure", "Pa", "GPa", "starved film pressure p(x)", in_report=False),
                  Output("starvation.thickness", "m", "um", "starved film thickness h(x)", in_report=False),
              ),
              compute=_starvation_line, plot=_line_film_plot,
              checks=convergence_checks(("starvation.converged", "the line EHL Newton (starved film)"))),
        Block(name="starvation_finite_line", sequential_sweep=True, bearing_types=ROLLER_KINDS,
              enabled_by=("starvation", True), only_with=("film", ("finite_line",)), requires=("film_finite_line",),
              inputs=ROLLER_INPUTS + ("oil_layer",),
              outputs=(
                  *_STARVATION_COMMON,
                  Output("starvation.meniscus", "m", "mm", "inlet meniscus x_m per y cell, where the pressure starts",
                         in_report=False),
                  *_finite_line_outputs("starvation", "starved"),
              ),
              compute=_starvation_finite_line, validate=_starved_finite_line_settings, plot=_finite_line_film_plot,
              compiler_options=_krylov_options, own_program=True,
              checks=convergence_checks(("starvation.converged", "the finite line EHL Newton (starved film)"))),
    ),
    report=_report,
    sweep_columns=_sweep_columns,
))
