"""Roller–raceway contact: roller geometry and the Hertz line-contact reference (always), the
pressure field by Hertz slices (effect contact = "slices") or influence coefficients ("influence").

These blocks model one contact: they run where the scene gives `contact.load` (`SINGLE_CONTACT`);
a scene with `operating.force` instead is a whole bearing (roller_bearing.py). The roller itself
(input `bearing`: diameters, length, profile, material, count) is built here for both."""

import math

import jax
import numpy as np

from ....bearings.roller.roller_contact import roller_contact
from ....bearings.roller.roller_geometry import (
    ROLLER_KINDS,
    RollerLoading,
    equivalent_radius,
    pure_rolling_entrainment_speed,
    raceway_curvature,
    raceway_radius_of_pitch,
    roller_bearing,
    roller_modulus,
)
from ....bearings.roller.roller_profile import PROFILE_KINDS, profile_parameters, roller_profile, with_raceway_edge
from ....contact import hertz
from ....params import check_range
from ...formatting import column, state_column
from ...registry import Adapter, Block, InputBuilder, Key, Output, convergence_checks, quantity, register
from ..materials import material

DEFAULT_CONTACT_GRID = (32, 256)
SINGLE_CONTACT = ("contact.load",)  # the scene key of this layout (registry: one roller–raceway contact)
DEFAULT_CONTACT_TOLERANCE = 1e-11


def scene_roller_profile(v):
    """The `RollerProfile` of a scene's [profile] values (SI; straight without them), for a roller
    of effective length bearing.roller_length."""
    kind = v.get("profile.kind", "straight")
    parameters = {name: v.get(f"profile.{name}") for name in ("flat_length", "crown_radius", "design_load", "k1", "k2", "zm")}
    if kind in ("straight", "circular"):
        parameters.pop("design_load")  # a design load belongs to the logarithmic kinds; others ignore it
    profile = roller_profile(kind, length=v["bearing.roller_length"], **parameters)
    if "contact.raceway_edge_radius" in v:
        profile = with_raceway_edge(profile, v["contact.raceway_edge_radius"])
    return profile


def scene_roller_bearing(v, built) -> dict:
    """{"bearing": the RollerBearing} of a scene's [bearing] and [profile] values (SI)."""
    length = v["bearing.roller_length"]
    profile = scene_roller_profile(v)
    return {"bearing": roller_bearing(kind=v["bearing.type"], length=length, diameter=v.get("bearing.roller_diameter"),
                                      small_diameter=v.get("bearing.roller_small_diameter"),
                                      large_diameter=v.get("bearing.roller_large_diameter"),
                                      cone_half_angle=v.get("bearing.cone_half_angle", 0.0), profile=profile,
                                      material=material(v), roller_count=v.get("bearing.rollers"))}


def _roller_count_text(scene, bearing) -> str:
    """", Z rollers", with a note where they would not fit on the pitch circle (D > d_m sin(π/Z))."""
    text = f", {bearing.roller_count} rollers"
    pitch = scene.values.get("bearing.pitch_diameter")
    if pitch is not None and float(bearing.large_diameter) > pitch * math.sin(math.pi / bearing.roller_count):
        text += (f" (which would not fit on the {pitch * 1e3:.4g} mm pitch circle: that needs D ≤ d_m sin(π/Z) = "
                 f"{pitch * math.sin(math.pi / bearing.roller_count) * 1e3:.4g} mm)")
    return text


def _raceway_curvature(v):
    """Signed raceway curvature [1/m] in the rolling direction: convex (inner) > 0, concave < 0."""
    raceway = v.get("contact.raceway", "inner")
    if "contact.raceway_radius" in v:
        radius = v["contact.raceway_radius"]
        if not isinstance(radius, jax.core.Tracer) and np.isposinf(radius):
            return 0.0  # "inf": a flat raceway
        check_range("contact.raceway_radius", radius, low=0.0, unit=" m", why='or "inf" for a flat raceway')
        return raceway_curvature(radius, raceway)
    if "bearing.pitch_diameter" in v and v["bearing.type"] == "cylindrical_roller":
        radius = raceway_radius_of_pitch(v["bearing.pitch_diameter"], v["bearing.roller_diameter"], raceway)
        check_range("bearing.pitch_diameter", radius, low=0.0, unit=" m",
                    why="the inner raceway radius (d_m − D)/2 must be positive")
        return raceway_curvature(radius, raceway)
    raise ValueError("missing required key: one of 'contact.raceway_radius', 'bearing.pitch_diameter' "
                     "(the latter for cylindrical rollers)")


def _entrainment_speed(v):
    """Pure-rolling entrainment speed [m/s] of a cylindrical roller; 0 without a pitch diameter."""
    if "bearing.pitch_diameter" not in v or v["bearing.type"] != "cylindrical_roller":
        return 0.0
    if not isinstance(v["bearing.roller_diameter"], jax.core.Tracer):
        check_range("bearing.pitch_diameter", v["bearing.pitch_diameter"], low=float(v["bearing.roller_diameter"]),
                    unit=" m", why="bearing.roller_diameter: the rollers lie between the raceways")
    return pure_rolling_entrainment_speed(v["bearing.pitch_diameter"], v["bearing.roller_diameter"],
                                          v.get("operating.inner_speed", 0.0), v.get("operating.outer_speed", 0.0))


def _loading(v, built) -> dict:
    return {"operating": RollerLoading(load=v["contact.load"], tilt=v.get("contact.tilt", 0.0),
                                       raceway_curvature=_raceway_curvature(v),
                                       entrainment_speed=_entrainment_speed(v))}


# --- geometry and the Hertz line-contact reference --------------------------------------------

def _roller_geometry(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, loading = inputs["bearing"], inputs["operating"]
    modulus = roller_modulus(bearing)
    radius = equivalent_radius(bearing, loading, np.asarray(0.0))
    line = hertz.line_contact(loading.load / bearing.length, radius, modulus)
    return {"geometry.effective_modulus": modulus, "geometry.equivalent_radius": radius,
            "hertz.line.max_pressure": line.max_pressure, "hertz.line.half_width": line.half_width}


ROLLER_GEOMETRY = Block(
    name="roller_geometry",
    bearing_types=ROLLER_KINDS,
    enabled_by=None,
    requires=(),
    inputs=("bearing", "operating"),
    scene_keys=SINGLE_CONTACT,
    outputs=(
        Output("geometry.effective_modulus", "Pa", "GPa", "effective modulus E' of roller and raceway"),
        Output("geometry.equivalent_radius", "m", "mm", "equivalent radius R in rolling, at mid-length"),
        Output("hertz.line.max_pressure", "Pa", "GPa", "Hertz line contact p0 at Q/l (reference)"),
        Output("hertz.line.half_width", "m", "um", "Hertz line contact half-width b at Q/l"),
    ),
    compute=_roller_geometry,
)


# --- the pressure field --------------------------------------------------------------------------

def contact_settings(settings: dict) -> tuple[tuple[int, int], float]:
    """(grid (nx, ny), solver tolerance) of a scene's fidelity table; ValueError if out of range."""
    fidelity = settings["fidelity"]
    grid = tuple(fidelity.get("grid", DEFAULT_CONTACT_GRID))
    tolerance = fidelity.get("tolerance", DEFAULT_CONTACT_TOLERANCE)
    if not all(4 <= n <= 4096 for n in grid):
        raise ValueError(f"fidelity.grid must have 4 to 4096 cells in each direction, got {list(grid)}")
    if not 0.0 < tolerance < 1.0:
        raise ValueError(f"fidelity.tolerance must be > 0 and < 1 (relative pressure change), got {tolerance:g}")
    return grid, tolerance


_CONTACT_FIELDS = ("max_pressure", "approach", "load", "contact_length", "max_half_width", "converged", "iterations",
                   "pressure", "x", "y")
_CONTACT_OUTPUTS = (
    Output("contact.max_pressure", "Pa", "GPa", "peak contact pressure p_max"),
    Output("contact.approach", "m", "um", "approach δ (from touching at mid-length)"),
    Output("contact.load", "N", "N", "load carried by the pressure field, ΔA Σp"),
    Output("contact.contact_length", "m", "mm", "length of the loaded zone along the roller"),
    Output("contact.max_half_width", "m", "um", "largest half-width of the loaded zone (rolling)"),
    Output("contact.converged", "", "", "the contact solution converged inside its grid", in_report=False),
    Output("contact.iterations", "", "", "conjugate-gradient iterations (0 for slices)", in_report=False),
    Output("contact.pressure", "Pa", "GPa", "pressure map p[x, y] on the nx × ny grid", in_report=False),
    Output("contact.x", "m", "mm", "cell centres along rolling (x)", in_report=False),
    Output("contact.y", "m", "mm", "cell centres along the roller axis (y)", in_report=False),
)


def _contact(method):
    def compute(inputs: dict, settings: dict, results: dict) -> dict:
        grid, tolerance = contact_settings(settings)
        solved = roller_contact(inputs["bearing"], inputs["operating"], grid, method, tolerance)
        return {f"contact.{name}": getattr(solved, name) for name in _CONTACT_FIELDS}

    return compute


def _contact_plot(result, figure):
    """Pressure map of a roller contact (x across, y along the roller) and the peak along y."""
    values = result.values
    pressure = np.asarray(values["contact.pressure"]) / 1e9
    x, y = np.asarray(values["contact.x"]) * 1e6, np.asarray(values["contact.y"]) * 1e3
    map_axis, line_axis = figure.subplots(1, 2, width_ratios=[1.6, 1])
    shown = map_axis.pcolormesh(y, x, pressure, shading="nearest", cmap="viridis")
    figure.colorbar(shown, ax=map_axis, label="pressure [GPa]")
    map_axis.set(xlabel="y along the roller [mm]", ylabel="x, rolling direction [µm]",
                 title=f"contact pressure, {pressure.shape[0]} × {pressure.shape[1]} cells")
    line_axis.plot(y, pressure.max(axis=0), label="max over x")
    line_axis.axhline(float(values["hertz.line.max_pressure"]) / 1e9, color="grey", lw=0.8, ls="--",
                      label="Hertz line p0 at Q/l")
    line_axis.set(xlabel="y along the roller [mm]", ylabel="pressure [GPa]", title="peak pressure along the roller",
                  ylim=(0, None))
    line_axis.grid(alpha=0.3)
    line_axis.legend()
    profile = result.model.inputs["bearing"].profile.kind
    figure.suptitle(f"{result.model.scene.title}: {profile} profile, Q = {float(values['contact.load']):.4g} N")


def _contact_block(method: str) -> Block:
    return Block(
        name=f"roller_contact_{method}",
        bearing_types=ROLLER_KINDS,
        enabled_by=("contact", method),
        requires=("roller_geometry",),
        inputs=("bearing", "operating"),
        scene_keys=SINGLE_CONTACT,
        outputs=_CONTACT_OUTPUTS,
        compute=_contact(method),
        validate=lambda settings, inputs: contact_settings(settings),
        plot=_contact_plot,
        checks=convergence_checks(("contact.converged", f"the roller contact solution ({method}; or its loaded "
                                                        "zone reached the grid's edge)")),
    )


# --- report --------------------------------------------------------------------------------------

def _header(result) -> list[str]:
    scene, inputs = result.model.scene, result.model.inputs
    bearing, loading = inputs["bearing"], inputs["operating"]
    if bearing.kind == "tapered_roller":
        shape = (f"d = {float(bearing.small_diameter) * 1e3:.4g} mm to D = {float(bearing.large_diameter) * 1e3:.4g} mm, "
                 f"θ = {np.degrees(float(bearing.cone_half_angle)):.3g}°")
    else:
        shape = f"D = {float(bearing.small_diameter) * 1e3:.4g} mm"
    if bearing.roller_count is not None:
        shape += _roller_count_text(scene, bearing)
    curvature = float(loading.raceway_curvature)
    raceway = ("flat raceway" if curvature == 0 else
               f"{'convex' if curvature > 0 else 'concave'} raceway, R = {abs(1 / curvature) * 1e3:.4g} mm at mid-length")
    material = bearing.material
    return [
        scene.title,
        f"scene: {scene.source}",
        "",
        f"Roller     {bearing.kind}, {shape}, effective length l = {float(bearing.length) * 1e3:.4g} mm",
        profile_line(scene, bearing),
        f"Material   E = {float(material.elastic_modulus) / 1e9:.4g} GPa, ν = {float(material.poisson_ratio):.3g} "
        "(roller and raceway)",
        f"Contact    Q = {float(loading.load) / 1e3:.4g} kN, tilt {np.degrees(float(loading.tilt)) * 60:.4g} arcmin, {raceway}",
    ]


def profile_line(scene, bearing) -> str:
    """The report's line of the roller's crowning profile with its parameters (units on each)."""
    units = {"flat_length": (1e3, "mm"), "crown_radius": (1e3, "mm"), "design_load": (1e-3, "kN"), "zm": (1e6, "µm"),
             "k1": (1, ""), "k2": (1, "")}
    parameters = ", ".join(f"{name} = {value * units[name][0]:.4g} {units[name][1]}".rstrip()
                           for name, value in profile_parameters(bearing.profile).items())
    if "contact.raceway_edge_radius" in scene.values:
        parameters += (f"; with the raceway edge radius {scene.values['contact.raceway_edge_radius'] * 1e3:.4g} mm "
                       "added to the crown")
    return f"Profile    {bearing.profile.kind}" + (f" ({parameters})" if parameters else "")


def _report(result) -> list[str]:
    values = result.values
    if "contact.pressure" not in values:
        return []
    pressure, y = np.asarray(values["contact.pressure"]), np.asarray(values["contact.y"])
    along = pressure.max(axis=0)
    stations = np.unique(np.linspace(0, len(y) - 1, 9).round().astype(int))
    lines = ["", "Peak pressure across the contact along the roller (max over x; full map in --json / --plot)",
             "  y [mm]     " + "".join(f"{y[i] * 1e3:>9.3f}" for i in stations),
             "  p [GPa]    " + "".join(f"{along[i] / 1e9:>9.4f}" for i in stations)]
    nx, ny = pressure.shape
    lines.append(f"  grid {nx} × {ny} cells of {float(np.diff(values['contact.x'][:2])[0]) * 1e6:.3g} µm × "
                 f"{float(np.diff(y[:2])[0]) * 1e6:.3g} µm")
    converged = bool(values["contact.converged"])
    if result.model.settings["effects"]["contact"] == "slices":
        lines.append("  Hertz line-contact slices (Palmgren laminae, no interaction between slices): "
                     + ("approach converged" if converged else "approach DID NOT CONVERGE"))
    else:
        if result.model.inputs["bearing"].profile.kind == "straight":
            lines.append("  straight roller: the edge peak grows as the cells shrink (an edge singularity); "
                         "it is grid dependent, not a converged value")
        state = "converged" if converged else "DID NOT CONVERGE (or reached the grid edge)"
        lines.append(f"  influence coefficients (DC-FFT, Polonsky–Keer): {state}, "
                     f"{int(values['contact.iterations'])} iterations")
    return lines


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    if "contact.max_pressure" not in values:
        return []
    return [column("p_max [GPa]", values["contact.max_pressure"], 1e-9),
            column("δ [µm]", values["contact.approach"], 1e6),
            state_column("contact", values["contact.converged"])]


ADAPTER = register(Adapter(
    name="roller",
    bearing_types=ROLLER_KINDS,
    keys={
        "bearing.roller_diameter": quantity("length"),
        "bearing.roller_small_diameter": quantity("length"),
        "bearing.roller_large_diameter": quantity("length"),
        "bearing.roller_length": quantity("length"),
        "bearing.rollers": Key("integer", doc="rollers in the bearing Z (a whole bearing's load distribution; "
                                             "reported for a single contact)"),
        "bearing.cone_half_angle": quantity("angle"),
        "bearing.pitch_diameter": quantity("length"),
        "operating.inner_speed": quantity("angular_speed"),
        "operating.outer_speed": quantity("angular_speed"),
        "profile.kind": Key("choice", choices=PROFILE_KINDS),
        "profile.flat_length": quantity("length"),
        "profile.crown_radius": quantity("length"),
        "profile.design_load": quantity("force"),
        "profile.k1": Key("number"),
        "profile.k2": Key("number"),
        "profile.zm": quantity("length"),
        "contact.raceway": Key("choice", choices=("inner", "outer")),
        "contact.raceway_radius": quantity("length"),
        "contact.raceway_edge_radius": quantity("length", "raceway edge radius, added to a circular crown "
                                                          "where the roller's flat part ends"),
        "contact.load": quantity("force"),
        "contact.tilt": quantity("angle"),
        "effects.contact": Key("choice", choices=("slices", "influence")),
        "fidelity.grid": Key("integers", length=2, read_by=("roller_contact_slices", "roller_contact_influence"),
                             doc="[nx, ny] cells along rolling and along the whole roller "
                                 "(2-D EHL solves the half y ≥ 0)"),
        "fidelity.tolerance": Key("number", read_by=("roller_contact_slices", "roller_contact_influence")),
    },
    required={"cylindrical_roller": ("bearing.roller_diameter", "bearing.roller_length"),
              "tapered_roller": ("bearing.roller_small_diameter", "bearing.roller_large_diameter",
                                 "bearing.roller_length")},
    inputs=(InputBuilder(("bearing",), ROLLER_KINDS, scene_roller_bearing),
            InputBuilder(("operating",), ROLLER_KINDS, _loading, scene_keys=SINGLE_CONTACT)),
    blocks=(ROLLER_GEOMETRY, _contact_block("slices"), _contact_block("influence")),
    header=_header,
    report=_report,
    sweep_columns=_sweep_columns,
))
