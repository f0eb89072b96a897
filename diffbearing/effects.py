"""The effect registry: which physics blocks a scene runs, and the outputs each one produces.

A `Block` declares the bearing types it applies to, the scene effect that switches it on
(`enabled_by`, or None for a block every scene of those types runs), the blocks it needs
(`requires`), the effects it reads as options (`uses`, e.g. centrifugal force inside the
equilibrium), its output keys with their SI units (`outputs`; an output tied to an effect is
produced only when that effect is on), and `compute`, a pure function
(inputs, settings, results so far) → {output key: array}; `settings` holds the scene's
`effects` and `fidelity` tables. `resolve` returns, in dependency order,
exactly the blocks a scene asks for: a block no named effect reaches is never called, so it is
never traced or compiled.

New physics plugs in by `register(Block(...))` in its own module's adapter below.
"""

import dataclasses
from collections.abc import Callable

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from . import ball_equilibrium, ball_validity, film_formulas, hertz, life
from .cage_dynamics import simulate_cage
from .cage_forces import cage_forces, epicyclic_cage_speed
from .cage_stability import cage_stability
from .params import BallBearing, Cage, Lubricant, Operating, groove_curvature_centre_distance, radial_clearance
from .raceway_contact import ball_raceway_modulus, diameter_ratio, inner_curvature, outer_curvature
from .finite_line_ehl import finite_line_film, half_domain_grid
from .line_ehl import check_nodes, density_ratio, line_film
from .roller_contact import roller_contact
from .roller_geometry import ROLLER_KINDS, RollerBearing, RollerLoading, equivalent_radius, film_length, roller_modulus

BALL_TYPES = ("deep_groove_ball", "angular_contact_ball")
ROLLER_TYPES = ROLLER_KINDS
DEFAULT_CONTACT_GRID = (32, 256)
DEFAULT_CONTACT_TOLERANCE = 1e-11

# ISO 76:2006, 7.1: contact stress limit at the basic static load rating of ball bearings.
ISO76_BALL_PRESSURE_LIMIT = 4.2e9  # Pa


class SceneInputs(eqx.Module):
    """Everything numeric a scene feeds the physics: the pytree `jax.grad` and `vmap` act on."""

    bearing: BallBearing | RollerBearing
    operating: Operating | RollerLoading
    lubricant: Lubricant | None = None
    roughness: jax.Array | None = None  # composite RMS roughness √(σ₁² + σ₂²) [m] of the contacting surfaces
    cage: Cage | None = None
    cage_offset: jax.Array | None = None  # (x, y) of the cage centre from the bearing axis [m]
    cage_duration: jax.Array | None = None  # time simulated by effects.cage = "dynamics" [s]


@dataclasses.dataclass(frozen=True)
class Output:
    """One output key: `unit` of the SI value in JSON, `display` unit of the report."""

    key: str
    unit: str
    display: str
    description: str
    effect: str | None = None  # produced only when this effect is on
    in_report: bool = True  # False for fields (maps, coordinates): JSON and plots only


@dataclasses.dataclass(frozen=True)
class Block:
    name: str
    bearing_types: tuple[str, ...]
    enabled_by: tuple[str, object] | None  # (effect key, value) that switches it on; None: always
    requires: tuple[str, ...]
    outputs: tuple[Output, ...]
    compute: Callable[[SceneInputs, dict, dict], dict]
    uses: tuple[str, ...] = ()
    only_with: tuple[str, tuple] | None = None  # (effect key, values): another effect it refines must be one of these
    # swept point by point (`jax.lax.map`), not under `jax.vmap`: the numerical EHL solvers, whose
    # vmapped compiled batch of 1-D line solves ran past 150 s where one solve takes 0.03 s
    sequential_sweep: bool = False
    # values of one point (NumPy, SI) → (errors, warnings): one line each, with units; an error
    # means the result is outside the model (the CLI exits 3), a warning that a limit is passed
    checks: Callable[[dict], tuple[list[str], list[str]]] | None = None


REGISTRY: dict[str, Block] = {}


def register(block: Block) -> Block:
    """Add a block to the registry (its name must be new)."""
    if block.name in REGISTRY:
        raise ValueError(f"block {block.name!r} is already registered")
    REGISTRY[block.name] = block
    return block


def resolve(bearing_type: str, effects: dict) -> tuple[list[Block], list[str]]:
    """Blocks to run, in dependency order, and the named effects no registered block provides.

    `effects` maps effect names to their scene values (false / absent means off).
    """
    wanted = [b for b in REGISTRY.values() if bearing_type in b.bearing_types and b.enabled_by is None]
    provided = {effect for b in REGISTRY.values() if bearing_type in b.bearing_types for effect in b.uses}
    for block in REGISTRY.values():
        if bearing_type in block.bearing_types and block.enabled_by is not None:
            effect, value = block.enabled_by
            refines = block.only_with is None or effects.get(block.only_with[0]) in block.only_with[1]
            if effect in effects and effects[effect] == value and type(effects[effect]) is type(value) and refines:
                wanted.append(block)
                provided.add(effect)
    missing = [name if value is True else f"{name} = {value!r}"
               for name, value in effects.items() if value is not False and name not in provided]
    ordered: list[Block] = []

    def visit(block: Block, chain: tuple[str, ...]):
        if block in ordered:
            return
        if block.name in chain:
            raise ValueError(f"blocks require each other in a cycle: {' → '.join(chain + (block.name,))}")
        for name in block.requires:
            visit(REGISTRY[name], chain + (block.name,))
        ordered.append(block)

    for block in wanted:
        visit(block, ())
    return ordered, missing


def problems(blocks, values: dict, grid_shape: tuple[int, ...] = ()) -> tuple[list[str], list[str]]:
    """(errors, warnings) of the blocks' checks over every point of a run (`grid_shape` () for one point)."""
    errors, warnings = [], []
    for number, index in enumerate(np.ndindex(grid_shape)):
        point = {key: np.asarray(value)[index] for key, value in values.items()}
        prefix = f"sweep point {number}: " if grid_shape else ""
        for block in blocks:
            if block.checks is not None:
                found_errors, found_warnings = block.checks(point)
                errors += [prefix + line for line in found_errors]
                warnings += [prefix + line for line in found_warnings]
    return errors, warnings


def outputs_of(blocks, effects: dict | None = None) -> dict[str, Output]:
    """{key: Output} the given blocks produce (with `effects`, only those whose effect is on)."""
    return {out.key: out for block in blocks for out in block.outputs
            if effects is None or out.effect is None or effects.get(out.effect, False) is True}


# ---------------------------------------------------------------------------------------------
# Ball bearings: raceway contact geometry and Hertz constants at the free contact angle.


def _raceway_contact(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    bearing = inputs.bearing
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
    constants = {}
    for side, curvature in (("inner", inner_curvature), ("outer", outer_curvature)):
        curvature_sum, curvature_difference = curvature(bearing, angle)
        unit = hertz.point_contact(1.0, curvature_sum, curvature_difference, modulus, method)
        # p₀ ∝ Q^{1/3}: the load that reaches the ISO 76 limit follows from p₀ at 1 N.
        limit = (ISO76_BALL_PRESSURE_LIMIT / unit.max_pressure) ** 3
        constants[side] = unit.load_deflection_constant
        out |= {
            f"hertz.{side}.curvature_sum": curvature_sum,
            f"hertz.{side}.curvature_difference": curvature_difference,
            f"hertz.{side}.ellipticity": unit.ellipticity,
            f"hertz.{side}.load_deflection_constant": unit.load_deflection_constant,
            f"hertz.{side}.static_limit_load": limit,
        }
    out["hertz.combined_load_deflection_constant"] = hertz.combined_load_deflection_constant(
        constants["inner"], constants["outer"])
    return out


def _side_outputs(side):
    return (
        Output(f"hertz.{side}.curvature_sum", "1/m", "1/mm", f"curvature sum Σρ, {side}"),
        Output(f"hertz.{side}.curvature_difference", "", "", f"curvature difference F(ρ), {side}"),
        Output(f"hertz.{side}.ellipticity", "", "", f"ellipticity κ = a/b, {side}"),
        Output(f"hertz.{side}.load_deflection_constant", "N/m**1.5", "N/mm**1.5", f"load–deflection constant K (Q = K δ^1.5), {side}"),
        Output(f"hertz.{side}.static_limit_load", "N", "kN", f"ball load at p0 = 4.2 GPa (ISO 76), {side}"),
    )


register(Block(
    name="raceway_contact",
    bearing_types=BALL_TYPES,
    enabled_by=None,
    requires=(),
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
))


def evaluate(blocks, settings: dict) -> Callable[[SceneInputs], dict]:
    """The pure function inputs → {output key: array} that runs exactly `blocks` in order."""

    def run(inputs: SceneInputs) -> dict:
        results: dict = {}
        for block in blocks:
            results |= block.compute(inputs, settings, results)
        return results

    return run


_COMPILED: dict = {}


def compiled(blocks, settings: dict, inputs: SceneInputs):
    """(`jax.jit` of `evaluate(...)` compiled ahead of time for `inputs`, whether it was cached).

    Compiled models are kept per process, keyed by the blocks, the settings and the structure,
    shapes and dtypes of the inputs: a second run of the same model with other numbers reuses it.
    """
    leaves, treedef = jax.tree.flatten(inputs)
    key = (tuple(b.name for b in blocks), repr(sorted((k, sorted(v.items())) for k, v in settings.items())),
           treedef, tuple((jnp.shape(x), jnp.result_type(x)) for x in leaves))
    if key in _COMPILED:
        return _COMPILED[key], True
    executable = jax.jit(evaluate(blocks, settings)).lower(inputs).compile()
    _COMPILED[key] = executable
    return executable, False


# ---------------------------------------------------------------------------------------------
# Ball bearings: quasi-static equilibrium (always), stiffness (effect "stiffness").


def ball_model(settings: dict) -> "ball_equilibrium.BallModel":
    """The static model options a scene's effects and fidelity tables select."""
    effects, fidelity = settings["effects"], settings["fidelity"]
    return ball_equilibrium.BallModel(
        centrifugal=effects.get("centrifugal", False) is True,
        gyroscopic=effects.get("gyroscopic", False) is True,
        race_control=fidelity.get("race_control", "outer"),
        hertz_method=fidelity.get("hertz", "exact"),
        hertz_constants=fidelity.get("hertz_constants", "contact_angle"),
    )


def _equilibrium(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    model = ball_model(settings)
    solution = ball_equilibrium.solve_equilibrium(inputs.bearing, inputs.operating, model)
    out = {"displacement": solution.displacement, "force": solution.force, "converged": solution.converged,
           "residual": solution.residual, "validity.approach_ratio": solution.approach_ratio,
           "validity.contact_angle": solution.contact_angle}
    balls = ball_equilibrium.ball_results(solution.displacement, inputs.bearing, inputs.operating, model)
    return out | {"balls." + field.name.replace("inner_", "inner.").replace("outer_", "outer."): getattr(balls, field.name)
                  for field in dataclasses.fields(balls) if getattr(balls, field.name) is not None}


def _equilibrium_checks(values: dict) -> tuple[list[str], list[str]]:
    """Errors: a state outside the ball model (ball_validity) or a solver that did not converge;
    warnings: a peak pressure above the ISO 76 static limit."""
    errors, warnings = [], []
    approach, angle = float(values["validity.approach_ratio"]), float(values["validity.contact_angle"])
    if approach > ball_validity.MAX_APPROACH_FRACTION:
        errors.append(f"equilibrium outside the model: a contact approach of {approach * 100:.3g} % of Dw passes the "
                      f"limit of {ball_validity.MAX_APPROACH_FRACTION * 100:g} % of Dw (Hertz theory's small contacts)")
    if angle >= float(ball_validity.MAX_CONTACT_ANGLE):
        errors.append(f"equilibrium outside the model: a contact angle |α| = {np.degrees(angle):.1f}° leaves "
                      "(−90°, 90°) (a ball pushed through its raceway)")
    if not errors and not bool(values["converged"]):
        errors.append(f"equilibrium solver did not converge: largest scaled residual {float(values['residual']):.1e} "
                      f"(tolerance {ball_equilibrium.RESIDUAL_TOLERANCE:g})")
    for side in ("inner", "outer"):
        pressure = np.asarray(values[f"balls.{side}.max_pressure"])
        ball = int(np.argmax(pressure))
        if pressure[ball] > ISO76_BALL_PRESSURE_LIMIT:
            warnings.append(f"peak contact pressure {pressure[ball] / 1e9:.3g} GPa ({side} raceway, ball {ball}) "
                            f"exceeds the ISO 76 static limit {ISO76_BALL_PRESSURE_LIMIT / 1e9:g} GPa")
    return errors, warnings


def _ball_outputs(side):
    return (
        Output(f"balls.{side}.load", "N", "kN", f"contact load Q, {side}"),
        Output(f"balls.{side}.contact_angle", "rad", "deg", f"contact angle α, {side}"),
        Output(f"balls.{side}.max_pressure", "Pa", "GPa", f"peak Hertz pressure p0, {side}"),
        Output(f"balls.{side}.semi_major_axis", "m", "mm", f"contact semi-major axis a, {side}"),
        Output(f"balls.{side}.semi_minor_axis", "m", "mm", f"contact semi-minor axis b, {side}"),
    )


register(Block(
    name="equilibrium",
    bearing_types=BALL_TYPES,
    enabled_by=None,
    requires=("raceway_contact",),
    uses=("centrifugal", "gyroscopic"),
    outputs=(
        Output("displacement", "m, rad", "", "inner-ring displacement [δx, δy, δz, θx, θy]"),
        Output("force", "N, N*m", "", "load the balls carry [Fx, Fy, Fz, Mx, My] (Fz follows under axial_displacement)"),
        Output("converged", "", "", "the equilibrium solver converged to a state within the model"),
        Output("residual", "", "", "largest scaled residual of ring and ball equations"),
        Output("validity.approach_ratio", "", "",
               f"largest contact approach δ / Dw (model limit {ball_validity.MAX_APPROACH_FRACTION:g})", in_report=False),
        Output("validity.contact_angle", "rad", "deg", "largest |contact angle| (model limit 90°)", in_report=False),
        Output("balls.azimuth", "rad", "deg", "ball azimuth ψ from +x"),
        *_ball_outputs("inner"),
        *_ball_outputs("outer"),
        Output("balls.orbital_speed", "rad/s", "rpm", "orbital (cage) speed ω_m"),
        Output("balls.spin_speed", "rad/s", "rpm", "ball spin speed ω_R about its own axis"),
        Output("balls.centrifugal_force", "N", "N", "centrifugal force F_c", effect="centrifugal"),
        Output("balls.gyroscopic_moment", "N*m", "N*m",
               "gyroscopic moment M_g (dL/dt = M_g e_t, along the direction of increasing azimuth)",
               effect="gyroscopic"),
    ),
    compute=_equilibrium,
    checks=_equilibrium_checks,
))


def _stiffness(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    matrix = ball_equilibrium.stiffness_matrix(results["displacement"], inputs.bearing, inputs.operating,
                                           ball_model(settings))
    return {"stiffness": matrix}


register(Block(
    name="stiffness",
    bearing_types=BALL_TYPES,
    enabled_by=("stiffness", True),
    requires=("equilibrium",),
    outputs=(Output("stiffness", "N/m, N/rad, N*m/m, N*m/rad", "",
                    "5×5 stiffness K = dF/dΔ, balls re-equilibrated (jacfwd through the implicit solve)"),),
    compute=_stiffness,
))


def _life(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    bearing = inputs.bearing
    computed = life.basic_dynamic_load_rating(bearing)
    rating = computed if bearing.dynamic_load_rating is None else bearing.dynamic_load_rating
    load = life.equivalent_dynamic_load(bearing, inputs.operating.force)
    return {
        "life.basic_dynamic_load_rating": rating,
        "life.iso281_load_rating": computed,
        "life.equivalent_load": load,
        "life.L10": life.basic_rating_life(rating, load),
        "life.L10r": life.reference_rating_life(bearing, rating, results["balls.inner.load"],
                                                results["balls.outer.load"]),
    }


register(Block(
    name="life",
    bearing_types=BALL_TYPES,
    enabled_by=("life", True),
    requires=("equilibrium",),
    outputs=(
        Output("life.basic_dynamic_load_rating", "N", "kN", "C_r used (the scene's, else ISO 281)"),
        Output("life.iso281_load_rating", "N", "kN", "C_r by ISO 281 from the geometry"),
        Output("life.equivalent_load", "N", "kN", "ISO 281 equivalent load P = X Fr + Y Fa"),
        Output("life.L10", "1e6 rev", "1e6 rev", "ISO 281 basic rating life L10 = (C/P)^3"),
        Output("life.L10r", "1e6 rev", "1e6 rev", "ISO/TS 16281 reference rating life L10r"),
    ),
    compute=_life,
))


def _film_hamrock_dowson(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    bearing, operating, lubricant = inputs.bearing, inputs.operating, inputs.lubricant
    modulus = ball_raceway_modulus(bearing)
    diameter, pitch = bearing.ball_diameter, bearing.pitch_diameter
    orbital = results["balls.orbital_speed"]
    out = {}
    for side, curvature, ring_speed, sign in (("inner", inner_curvature, operating.inner_speed, -1.0),
                                              ("outer", outer_curvature, operating.outer_speed, 1.0)):
        load, angle = results[f"balls.{side}.load"], results[f"balls.{side}.contact_angle"]
        # rolling-direction radius D(1 ∓ γ)/2 and entrainment speed ½|ω_ring − ω_m| d_m (1 ∓ γ)
        spread = 1.0 + sign * diameter_ratio(bearing, angle)
        radius = 0.5 * diameter * spread
        speed = 0.5 * jnp.abs(ring_speed - orbital) * pitch * spread
        ellipticity = hertz.ellipticity(curvature(bearing, angle)[1])
        loaded = load > 0
        central, minimum = film_formulas.hamrock_dowson_point(
            jnp.where(loaded, load, 1.0), radius, ellipticity, speed, lubricant.viscosity,
            lubricant.pressure_viscosity, modulus)
        out |= {f"film.{side}.central": jnp.where(loaded, central, jnp.nan),
                f"film.{side}.minimum": jnp.where(loaded, minimum, jnp.nan),
                f"film.{side}.entrainment_speed": speed}
        if inputs.roughness is not None:
            out[f"film.{side}.film_parameter"] = jnp.where(
                loaded, film_formulas.film_parameter(minimum, inputs.roughness), jnp.nan)
    return out


def _film_outputs(side):
    return (
        Output(f"film.{side}.central", "m", "um", f"central film h_c (Hamrock–Dowson), {side}"),
        Output(f"film.{side}.minimum", "m", "um", f"minimum film h_min (Hamrock–Dowson), {side}"),
        Output(f"film.{side}.entrainment_speed", "m/s", "m/s", f"mean entrainment speed u, {side}"),
        Output(f"film.{side}.film_parameter", "", "", f"film parameter Λ = h_min/σ, {side}"),
    )


register(Block(
    name="film_hamrock_dowson",
    bearing_types=BALL_TYPES,
    enabled_by=("film", "hamrock_dowson"),
    requires=("equilibrium",),
    outputs=(*_film_outputs("inner"), *_film_outputs("outer")),
    compute=_film_hamrock_dowson,
))


# ---------------------------------------------------------------------------------------------
# Roller–raceway contact: geometry and the Hertz line-contact reference (always), the pressure
# field by Hertz slices (effect contact = "slices") or influence coefficients ("influence").


def _roller_geometry(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    bearing, loading = inputs.bearing, inputs.operating
    modulus = roller_modulus(bearing)
    radius = equivalent_radius(bearing, loading, jnp.asarray(0.0))
    line = hertz.line_contact(loading.load / bearing.length, radius, modulus)
    return {"geometry.effective_modulus": modulus, "geometry.equivalent_radius": radius,
            "hertz.line.max_pressure": line.max_pressure, "hertz.line.half_width": line.half_width}


register(Block(
    name="roller_geometry",
    bearing_types=ROLLER_TYPES,
    enabled_by=None,
    requires=(),
    outputs=(
        Output("geometry.effective_modulus", "Pa", "GPa", "effective modulus E' of roller and raceway"),
        Output("geometry.equivalent_radius", "m", "mm", "equivalent radius R in rolling, at mid-length"),
        Output("hertz.line.max_pressure", "Pa", "GPa", "Hertz line contact p0 at Q/l (reference)"),
        Output("hertz.line.half_width", "m", "um", "Hertz line contact half-width b at Q/l"),
    ),
    compute=_roller_geometry,
))


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


_CONTACT_OUTPUTS = (
    Output("contact.max_pressure", "Pa", "GPa", "peak contact pressure p_max"),
    Output("contact.approach", "m", "um", "approach δ (from touching at mid-length)"),
    Output("contact.load", "N", "N", "load carried by the pressure field, ΔA Σp"),
    Output("contact.contact_length", "m", "mm", "length of the loaded zone along the roller"),
    Output("contact.max_half_width", "m", "um", "largest half-width of the loaded zone (rolling)"),
    Output("contact.converged", "", "", "the contact solution converged inside its grid"),
    Output("contact.iterations", "", "", "conjugate-gradient iterations (0 for slices)"),
    Output("contact.pressure", "Pa", "GPa", "pressure map p[x, y] on the nx × ny grid", in_report=False),
    Output("contact.x", "m", "mm", "cell centres along rolling (x)", in_report=False),
    Output("contact.y", "m", "mm", "cell centres along the roller axis (y)", in_report=False),
)


def _contact(method):
    def compute(inputs: SceneInputs, settings: dict, results: dict) -> dict:
        grid, tolerance = contact_settings(settings)
        solved = roller_contact(inputs.bearing, inputs.operating, grid, method, tolerance)
        return {f"contact.{name}": getattr(solved, name) for name in
                ("max_pressure", "approach", "load", "contact_length", "max_half_width", "converged", "iterations",
                 "pressure", "x", "y")}

    return compute


for _method in ("slices", "influence"):
    register(Block(
        name=f"roller_contact_{_method}",
        bearing_types=ROLLER_TYPES,
        enabled_by=("contact", _method),
        requires=("roller_geometry",),
        outputs=_CONTACT_OUTPUTS,
        compute=_contact(_method),
    ))


# ---------------------------------------------------------------------------------------------
# Roller–raceway film (fully flooded, pure rolling): Pan–Hamrock (effect film = "formula") or the
# numerical line contact (film = "line") at mid-length, with the load on the film length.

DEFAULT_LINE_NODES = 513


def film_settings(settings: dict, inputs: SceneInputs) -> int:
    """Nodes of the line EHL level (fidelity.grid[0], default 513); ValueError for a bad grid (of
    the line or the finite line level) or a roller scene without entrainment speed."""
    speed = inputs.operating.entrainment_speed
    if not isinstance(speed, jax.core.Tracer) and float(speed) <= 0:
        raise ValueError("effects.film needs an entrainment speed: give operating.inner_speed (or outer_speed) "
                         "and bearing.pitch_diameter (cylindrical roller)")
    nodes = settings["fidelity"].get("grid", [DEFAULT_LINE_NODES])[0]
    if settings["effects"].get("film") == "line":
        check_nodes(nodes)
    if settings["effects"].get("film") == "finite_line":
        finite_line_settings(settings)
    return nodes


def _roller_film_case(inputs: SceneInputs):
    bearing, loading, lubricant = inputs.bearing, inputs.operating, inputs.lubricant
    return (loading.load / film_length(bearing), equivalent_radius(bearing, loading, jnp.asarray(0.0)),
            loading.entrainment_speed, lubricant.viscosity, lubricant.pressure_viscosity, roller_modulus(bearing))


def _film_formula(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    central, minimum = film_formulas.pan_hamrock_line(*_roller_film_case(inputs))
    return {"film.central": central, "film.minimum": minimum, "film.entrainment_speed": inputs.operating.entrainment_speed}


def _line(inputs: SceneInputs, settings: dict, oil_layer=None):
    lubricant = inputs.lubricant
    return line_film(*_roller_film_case(inputs), nodes=film_settings(settings, inputs), oil_layer=oil_layer,
                     viscosity_law=lubricant.viscosity_law, density_law=lubricant.density_law)


def _film_line(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    solved = _line(inputs, settings)
    return {"film.central": solved.central, "film.minimum": solved.minimum, "film.converged": solved.converged,
            "film.entrainment_speed": inputs.operating.entrainment_speed, "film.x": solved.x,
            "film.pressure": solved.pressure, "film.thickness": solved.thickness}


_ROLLER_FILM_COMMON = (
    Output("film.central", "m", "um", "central film h_c at x = 0"),
    Output("film.minimum", "m", "um", "minimum film h_min"),
    Output("film.entrainment_speed", "m/s", "m/s", "mean entrainment speed u (pure rolling)"),
)

register(Block(
    name="film_formula",
    bearing_types=ROLLER_TYPES,
    enabled_by=("film", "formula"),
    requires=("roller_geometry",),
    outputs=_ROLLER_FILM_COMMON,
    compute=_film_formula,
))

register(Block(
    name="film_line",
    sequential_sweep=True,
    bearing_types=ROLLER_TYPES,
    enabled_by=("film", "line"),
    requires=("roller_geometry",),
    outputs=(
        *_ROLLER_FILM_COMMON,
        Output("film.converged", "", "", "the line EHL Newton converged"),
        Output("film.x", "m", "mm", "nodes along rolling (x), inlet at −4.5 b", in_report=False),
        Output("film.pressure", "Pa", "GPa", "film pressure p(x)", in_report=False),
        Output("film.thickness", "m", "um", "film thickness h(x)", in_report=False),
    ),
    compute=_film_line,
))


# The finite line level (film = "finite_line"): the 2-D EHL of the whole roller length, half
# domain, on fidelity.grid = [nx, ny]: nx nodes along rolling by ny cells along the whole roller,
# of which the ⌈ny/2⌉ on y ≥ 0 are solved (`finite_line_ehl.half_domain_grid`).
DEFAULT_FINITE_LINE_GRID = (33, 96)


def finite_line_settings(settings: dict) -> tuple[int, int]:
    """(nx, ny on the half domain) of the finite line level from fidelity.grid (whole roller
    length), default [33, 96]; ValueError beyond the dense Newton's size."""
    return half_domain_grid(settings["fidelity"].get("grid", DEFAULT_FINITE_LINE_GRID))


def _finite_line(inputs: SceneInputs, settings: dict, oil_layer=None):
    bearing, lubricant = inputs.bearing, inputs.lubricant
    _, radius, speed, viscosity, pressure_viscosity, modulus = _roller_film_case(inputs)
    return finite_line_film(inputs.operating.load, radius, speed, viscosity, pressure_viscosity, modulus, bearing.profile,
                            bearing.length, film_length(bearing), grid=finite_line_settings(settings),
                            viscosity_law=lubricant.viscosity_law, density_law=lubricant.density_law,
                            oil_layer=oil_layer)


_FINITE_LINE_FIELDS = ("central", "minimum", "minimum_position", "converged", "x", "y", "pressure", "thickness")


def _film_finite_line(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    solved = _finite_line(inputs, settings)
    return {"film.entrainment_speed": inputs.operating.entrainment_speed,
            **{f"film.{name}": getattr(solved, name) for name in _FINITE_LINE_FIELDS}}


def _finite_line_outputs(prefix: str, case: str):
    return (
        Output(f"{prefix}.minimum_position", "m", "mm", f"where the {case} h_min is, y from mid-length"),
        Output(f"{prefix}.converged", "", "", f"the {case} finite line EHL Newton converged"),
        Output(f"{prefix}.x", "m", "mm", "nodes along rolling (x), inlet at −4.5 b", in_report=False),
        Output(f"{prefix}.y", "m", "mm", "cell centres along the roller from mid-length (y ≥ 0)", in_report=False),
        Output(f"{prefix}.pressure", "Pa", "GPa", f"{case} film pressure p[x, y]", in_report=False),
        Output(f"{prefix}.thickness", "m", "um", f"{case} film thickness (the gap where dry) h[x, y]",
               in_report=False),
    )


register(Block(
    name="film_finite_line",
    sequential_sweep=True,
    bearing_types=ROLLER_TYPES,
    enabled_by=("film", "finite_line"),
    requires=("roller_geometry",),
    outputs=(*_ROLLER_FILM_COMMON, *_finite_line_outputs("film", "flooded")),
    compute=_film_finite_line,
))

# ---------------------------------------------------------------------------------------------
# Starvation (effect starvation = true, with operating.oil_layer): the film of the same level
# with the inlet supplied by an oil layer h_oil only, and Er = (h_c,ff − h_c)/h_c,ff against the
# flooded film (seed 003's criterion: starved when Er > 1 %).

# Chevalier's γ for a line contact: no side flow, so the film follows the supply until it meets
# the flooded one; γ = 20 matches the 1-D numerical starved films (`benchmarks/line_ehl.py`).
LINE_STARVATION_SHARPNESS = 20.0


def starvation_settings(settings: dict, inputs: SceneInputs) -> None:
    """ValueError for a starvation effect without an oil layer."""
    if settings["effects"].get("starvation") is True and inputs.operating.oil_layer is None:
        raise ValueError("effects.starvation needs operating.oil_layer (the inlet oil supply layer, e.g. \"0.8 um\")")


def _starvation_formula(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    oil_layer = inputs.operating.oil_layer
    load_per_length, radius, _, _, _, modulus = _roller_film_case(inputs)
    density = density_ratio(hertz.line_contact(load_per_length, radius, modulus).max_pressure,
                            inputs.lubricant.density_law)
    flooded_central, flooded_minimum = results["film.central"], results["film.minimum"]
    central = film_formulas.starved_film(flooded_central, oil_layer, density, LINE_STARVATION_SHARPNESS)
    minimum = flooded_minimum * central / flooded_central  # the flooded h_min/h_c ratio kept (an estimate)
    return {"starvation.oil_layer": oil_layer, "starvation.central": central, "starvation.minimum": minimum,
            "starvation.relative_error": 1.0 - central / flooded_central}


def _starvation_line(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    oil_layer = inputs.operating.oil_layer
    solved = _line(inputs, settings, oil_layer)
    return {"starvation.oil_layer": oil_layer, "starvation.central": solved.central, "starvation.minimum": solved.minimum,
            "starvation.relative_error": 1.0 - solved.central / results["film.central"],
            "starvation.meniscus": solved.meniscus, "starvation.converged": solved.converged,
            "starvation.x": solved.x, "starvation.pressure": solved.pressure, "starvation.thickness": solved.thickness}


_STARVATION_COMMON = (
    Output("starvation.oil_layer", "m", "um", "inlet oil supply layer h_oil"),
    Output("starvation.central", "m", "um", "starved central film h_c"),
    Output("starvation.minimum", "m", "um", "starved minimum film h_min"),
    Output("starvation.relative_error", "", "percent", "Er = (h_c,ff − h_c)/h_c,ff (starved if > 1 %)"),
)

register(Block(
    name="starvation_formula",
    bearing_types=ROLLER_TYPES,
    enabled_by=("starvation", True),
    only_with=("film", ("formula",)),
    requires=("film_formula",),
    outputs=_STARVATION_COMMON,
    compute=_starvation_formula,
))

register(Block(
    name="starvation_line",
    sequential_sweep=True,
    bearing_types=ROLLER_TYPES,
    enabled_by=("starvation", True),
    only_with=("film", ("line",)),
    requires=("film_line",),
    outputs=(
        *_STARVATION_COMMON,
        Output("starvation.meniscus", "m", "mm", "inlet meniscus x_m, where the pressure starts"),
        Output("starvation.converged", "", "", "the starved line EHL Newton converged"),
        Output("starvation.x", "m", "mm", "nodes along rolling (x), from the meniscus", in_report=False),
        Output("starvation.pressure", "Pa", "GPa", "starved film pressure p(x)", in_report=False),
        Output("starvation.thickness", "m", "um", "starved film thickness h(x)", in_report=False),
    ),
    compute=_starvation_line,
))


def _starvation_finite_line(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    solved = _finite_line(inputs, settings, oil_layer=inputs.operating.oil_layer)
    return {"starvation.oil_layer": inputs.operating.oil_layer,
            "starvation.relative_error": 1.0 - solved.central / results["film.central"],
            "starvation.meniscus": solved.meniscus,
            **{f"starvation.{name}": getattr(solved, name) for name in _FINITE_LINE_FIELDS}}


register(Block(
    name="starvation_finite_line",
    sequential_sweep=True,
    bearing_types=ROLLER_TYPES,
    enabled_by=("starvation", True),
    only_with=("film", ("finite_line",)),
    requires=("film_finite_line",),
    outputs=(
        *_STARVATION_COMMON,
        Output("starvation.meniscus", "m", "mm", "inlet meniscus x_m per y cell, where the pressure starts",
               in_report=False),
        *_finite_line_outputs("starvation", "starved"),
    ),
    compute=_starvation_finite_line,
))

# ---------------------------------------------------------------------------------------------
# Cage (effect cage = true): quasi-static pocket and land forces at the scene's cage offset and
# the restoring force f_inv (cage_forces.py; seed 000).


def cage_settings(inputs: SceneInputs) -> None:
    """ValueError for a cage effect without its inputs."""
    if inputs.cage is None:
        raise ValueError("effects.cage needs a [cage] table (cage.pocket_clearance, cage.guide_clearance, "
                         "cage.land_width, ...)")
    if inputs.lubricant is None:
        raise ValueError("effects.cage needs a [lubricant] table (viscosity and density of the oil around the cage)")


def _cage(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    solved = cage_forces(inputs.cage, inputs.bearing, inputs.operating, inputs.lubricant, inputs.cage_offset)
    return {"cage.restoring_force": solved.restoring_force, "cage.force": solved.force, "cage.moment": solved.moment,
            "cage.land_force": solved.land_force, "cage.land_eccentricity": solved.land_eccentricity,
            "cage.land_contact": solved.land_contact, "cage.pocket_forces": solved.pocket_forces,
            "cage.pushing": solved.pushing, "cage.resisting": solved.resisting, "cage.drag": solved.drag,
            "cage.push": solved.push, "cage.load_zone": solved.load_zone, "cage.speed": solved.cage_speed,
            "cage.offset": inputs.cage_offset}


register(Block(
    name="cage",
    bearing_types=BALL_TYPES,
    enabled_by=("cage", True),
    requires=(),
    outputs=(
        Output("cage.restoring_force", "N", "N", "restoring force f_inv (resultant against the offset)"),
        Output("cage.force", "N", "N", "resultant force on the cage [Fx, Fy, Fz]"),
        Output("cage.moment", "N*m", "N*m", "resultant moment about the cage centre [Mx, My, Mz]"),
        Output("cage.land_force", "N", "N", "force of land A (z = −s/2) and B (z = +s/2) [[Fx, Fy], [Fx, Fy]]"),
        Output("cage.land_eccentricity", "", "", "relative eccentricity ε at land A and B"),
        Output("cage.land_contact", "N", "N", "metal contact force at land A and B (0: full film)"),
        Output("cage.pocket_forces", "N", "N", "force of each ball on the cage [Z × (Fx, Fy, Fz)]", in_report=False),
        Output("cage.pushing", "", "", "weight of each ball as a pusher (0 to 1)", in_report=False),
        Output("cage.resisting", "", "", "weight of each ball as a resister (0 to 1)", in_report=False),
        Output("cage.drag", "N", "N", "oil drag on one orbiting ball f_v"),
        Output("cage.push", "N", "N", "circumferential force of each pushing ball F_push"),
        Output("cage.load_zone", "rad", "deg", "load zone 2ψ_l (Sjövall)"),
        Output("cage.speed", "rad/s", "rpm", "cage speed ω_c"),
        Output("cage.offset", "m", "um", "cage centre offset (x, y)"),
    ),
    compute=_cage,
))

# Cage dynamics (effect cage = "dynamics"): the orbit from the scene's cage offset, its stability
# measures (cage_dynamics.py), and the linear whirl stability at the quasi-static equilibrium
# (cage_stability.py).

ORBIT_SAMPLES = 1024


def default_cage_duration(inputs: SceneInputs):
    """Ten revolutions of the epicyclic cage [s] (0.1 s at rest)."""
    speed = jnp.abs(epicyclic_cage_speed(inputs.bearing, inputs.operating))
    return jnp.where(speed > 0, 20.0 * jnp.pi / jnp.where(speed > 0, speed, 1.0), 0.1)


def _cage_dynamics(inputs: SceneInputs, settings: dict, results: dict) -> dict:
    duration = default_cage_duration(inputs) if inputs.cage_duration is None else inputs.cage_duration
    orbit = simulate_cage(inputs.cage, inputs.bearing, inputs.operating, inputs.lubricant, inputs.cage_offset,
                          duration, ORBIT_SAMPLES)
    stability = cage_stability(inputs.cage, inputs.bearing, inputs.operating, inputs.lubricant)
    return {"cage.orbit.t": orbit.t, "cage.orbit.x": orbit.centre[:, 0], "cage.orbit.y": orbit.centre[:, 1],
            "cage.orbit.converged": orbit.converged, "cage.orbit.land_contact": orbit.land_contact,
            "cage.whirl_radius": orbit.whirl_radius, "cage.mean_offset": orbit.mean_offset,
            "cage.decay_rate": orbit.decay_rate, "cage.whirl_frequency": orbit.whirl_frequency,
            "cage.spectrum.frequency": orbit.frequency, "cage.spectrum.amplitude": orbit.spectrum,
            "cage.speed": orbit.cage_speed, "cage.offset": inputs.cage_offset,
            "cage.stability.equilibrium": stability.equilibrium, "cage.stability.eccentricity": stability.eccentricity,
            "cage.stability.decay_rate": stability.decay_rate, "cage.stability.converged": stability.converged}


register(Block(
    name="cage_dynamics",
    bearing_types=BALL_TYPES,
    enabled_by=("cage", "dynamics"),
    requires=(),
    outputs=(
        Output("cage.offset", "m", "um", "cage centre offset at the start (x, y)"),
        Output("cage.speed", "rad/s", "rpm", "epicyclic cage speed ω_m"),
        Output("cage.orbit.converged", "", "", "the time integration reached the end"),
        Output("cage.whirl_radius", "m", "um", "whirl radius: RMS of |c − c̄| over the second half"),
        Output("cage.mean_offset", "m", "um", "mean cage offset |c̄| over the second half"),
        Output("cage.decay_rate", "1/s", "1/s", "decay rate of the whirl amplitude (> 0: dies out)"),
        Output("cage.whirl_frequency", "Hz", "Hz", "dominant whirl frequency (forward > 0)"),
        Output("cage.stability.equilibrium", "m", "um", "equilibrium offset (x, y), quasi-static"),
        Output("cage.stability.eccentricity", "", "", "equilibrium offset / radial guide clearance"),
        Output("cage.stability.decay_rate", "1/s", "1/s", "linear whirl decay rate there (> 0: stable)"),
        Output("cage.stability.converged", "", "", "the equilibrium Newton converged"),
        Output("cage.orbit.t", "s", "ms", "orbit sample times", in_report=False),
        Output("cage.orbit.x", "m", "um", "cage centre x(t)", in_report=False),
        Output("cage.orbit.y", "m", "um", "cage centre y(t)", in_report=False),
        Output("cage.orbit.land_contact", "N", "N", "metal contact force at one land over time", in_report=False),
        Output("cage.spectrum.frequency", "Hz", "Hz", "whirl spectrum frequencies (signed)", in_report=False),
        Output("cage.spectrum.amplitude", "m", "um", "whirl spectrum amplitude", in_report=False),
    ),
    compute=_cage_dynamics,
))
