"""Numerical EHL of a line contact (isothermal, Newtonian, fully flooded), solved by Newton.

Dimensionless as in Venner & Lubrecht, Multilevel Methods in Lubrication (2000), ch. 8, with
the Hertz half-width b = √(8wR/(πE')) and pressure p_h = E'b/(4R):

    X = x/b,  P = p/p_h,  H = hR/b²,  ρ̄ = ρ/ρ₀,  η̄ = η/η₀,

    d/dX(ε dP/dX) − d(ρ̄H)/dX = 0,  ε = ρ̄H³/(η̄λ),  λ = 12 η₀ u R²/(b³ p_h)   (Reynolds)
    H(X) = H₀ + X²/2 − (1/π) ∫ P(X') ln|X − X'| dX'                          (film, elastic)
    ∫ P dX = π/2                                                             (load balance)

with u the mean entrainment speed. Viscosity: Roelands η = η₀ exp{(ln η₀ + 9.67)[(1 + p/p_R)^z − 1]},
p_R = 1.96e8 Pa, z = α p_R/(ln η₀ + 9.67), or Barus η = η₀ e^{αp}; density: Dowson–Higginson
ρ/ρ₀ = 1 + 0.6e-9 p/(1 + 1.7e-9 p) or incompressible (docs/theory.md §Line EHL).

Discretization on N nodes over X ∈ [−4.5, 1.5]: second-order central Poiseuille term, the wedge
term upwind (second order, first order next to the inlet), P piecewise constant per node for the
deflection (closed-form log integrals). Cavitation is the complementarity P ≥ 0, −L(P) ≥ 0,
P·L = 0 (L the Reynolds residual), written as the Fischer–Burmeister equation
P + s(−L) − √(P² + s²L²) = 0. Unknowns P₁ … P_{N−2} and H₀; damped Newton (`newton`, Armijo
backtracking on ½‖F‖²; a step that lowers nothing, or gives NaN, is not taken, so the iterate
stays finite) on all of them with a dense Jacobian (jacfwd) from a Hertz pressure and the
Pan–Hamrock film; the last solve sits in `newton.implicit_root`, so the derivative of the
converged film with respect to load, speed, viscosity and α costs one linear solve with the same
Jacobian.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..contact.hertz import line_contact
from ..newton import implicit_root, newton
from ..numerics import require_float64, safe_sqrt
from .film_formulas import pan_hamrock_line

ROELANDS_PRESSURE = 1.96e8  # p_R [Pa]
INLET, OUTLET = -4.5, 1.5  # default domain in Hertz half-widths (the starved-EHL paper's)


class LineFilm(eqx.Module):
    """Solution [SI]: x [m] nodes, pressure [Pa], film h [m], central film at x = 0 [m], minimum
    film [m], whether it converged (largest residual below the tolerance and a positive film;
    at high M a coarse grid can give a discrete solution with h < 0), that residual [-], the
    inlet meniscus x_m [m] where the pressure starts (the domain inlet when flooded)."""

    x: jax.Array
    pressure: jax.Array
    thickness: jax.Array
    central: jax.Array
    minimum: jax.Array
    converged: jax.Array
    residual: jax.Array
    meniscus: jax.Array


def viscosity_ratio(pressure, viscosity, pressure_viscosity, law="roelands"):
    """η/η₀ [-] at pressure p [Pa] (Roelands or Barus)."""
    if law == "barus":
        return jnp.exp(pressure_viscosity * pressure)
    log_factor = jnp.log(viscosity) + 9.67
    exponent = pressure_viscosity * ROELANDS_PRESSURE / log_factor
    return jnp.exp(log_factor * ((1.0 + jnp.maximum(pressure, 0.0) / ROELANDS_PRESSURE) ** exponent - 1.0))


def density_ratio(pressure, law="dowson_higginson"):
    """ρ/ρ₀ [-] at pressure p [Pa] (Dowson–Higginson or incompressible)."""
    if law == "incompressible":
        return jnp.ones_like(pressure)
    return 1.0 + 0.6e-9 * pressure / (1.0 + 1.7e-9 * pressure)


def log_kernel(count: int):
    """K_ij = ∫ ln|i − j − s| ds over |s| ≤ ½ [-]: the log integral over the cell of node j seen from
    node i on a grid of unit spacing, closed form. On spacing Δ the integral is ΔK_ij + Δ ln Δ."""
    offset = jnp.arange(count)[:, None] - jnp.arange(count)[None, :]

    def primitive(s):
        return s * jnp.log(jnp.abs(s)) - s

    return primitive(offset + 0.5) - primitive(offset - 0.5)


class FluidParameters(eqx.Module):
    """What the Reynolds coefficients need: λ = 12η₀uR²/(b³p_h) [-], p_h [Pa], η₀ [Pa·s], α [1/Pa]
    and the viscosity and density laws (shared by the line and the finite line contact)."""

    speed_parameter: jax.Array
    hertz_pressure: jax.Array
    viscosity: jax.Array
    pressure_viscosity: jax.Array
    viscosity_law: str = eqx.field(static=True)
    density_law: str = eqx.field(static=True)


def reynolds_coefficients(pressure, film, fluid: FluidParameters):
    """(ρ̄, ε = ρ̄H³/(η̄λ)) [-] at dimensionless pressure P and film H: the density ratio of the
    wedge term and the Poiseuille coefficient of the Reynolds equation."""
    dimensional = pressure * fluid.hertz_pressure
    density = density_ratio(dimensional, fluid.density_law)
    viscosity = viscosity_ratio(dimensional, fluid.viscosity, fluid.pressure_viscosity, fluid.viscosity_law)
    return density, density * film**3 / (viscosity * fluid.speed_parameter)


def poiseuille_terms(pressure, flow, spacing):
    """d/dX(ε dP/dX) [-] at the interior nodes along axis 0 (X, rolling), central with ε averaged
    onto the faces. Works on a line (N,) or on a grid (nx, ny), column by column."""
    face = 0.5 * (flow[1:] + flow[:-1])
    return (face[1:] * (pressure[2:] - pressure[1:-1]) - face[:-1] * (pressure[1:-1] - pressure[:-2])) / spacing**2


def rolling_terms(pressure, mass, flow, spacing):
    """d/dX(ε dP/dX) − d(ρ̄H)/dX [-] at the interior nodes along axis 0 (X, rolling): Poiseuille
    (`poiseuille_terms`), wedge upwind (second order, first order next to the inlet). Works on a
    line (N,) or on a grid (nx, ny), column by column."""
    poiseuille = poiseuille_terms(pressure, flow, spacing)
    first_order = (mass[1:-1] - mass[:-2]) / spacing
    second_order = (3.0 * mass[1:-1] - 4.0 * mass[:-2] + jnp.concatenate([jnp.zeros_like(mass[:1]), mass[:-3]])
                    ) / (2 * spacing)
    upwind_second = (jnp.arange(1, len(pressure) - 1) >= 2).reshape((-1,) + (1,) * (pressure.ndim - 1))
    return poiseuille - jnp.where(upwind_second, second_order, first_order)


def fischer_burmeister(pressure, reynolds):
    """P + s(−L) − √(P² + L²) [-]: zero exactly when P ≥ 0, L ≤ 0 and P·L = 0 (cavitation as a
    complementarity), with a finite slope at (0, 0)."""
    return pressure - reynolds - safe_sqrt(pressure**2 + reynolds**2)


class _Problem(eqx.Module):
    nodes: jax.Array
    kernel: jax.Array
    fluid: FluidParameters


def _film(pressure, offset, problem):
    spacing = problem.nodes[1] - problem.nodes[0]
    elastic = spacing * (problem.kernel @ pressure + jnp.log(spacing) * jnp.sum(pressure))
    return offset + 0.5 * problem.nodes**2 - elastic / jnp.pi


def _residual(unknowns, problem: _Problem):
    interior, offset = unknowns[:-1], unknowns[-1]
    pressure = jnp.pad(interior, 1)
    spacing = problem.nodes[1] - problem.nodes[0]
    film = _film(pressure, offset, problem)
    density, flow = reynolds_coefficients(pressure, film, problem.fluid)
    reynolds = rolling_terms(pressure, density * film, flow, spacing) * spacing  # scaled to O(P)
    balance = spacing * jnp.sum(pressure) - 0.5 * jnp.pi
    return jnp.append(fischer_burmeister(interior, reynolds), balance)


def moes_load_parameter(load_per_length, radius, speed, viscosity, effective_modulus):
    """Moes' M = W'(2U)^(−1/2) [-] with W' = w/(E'R), U = η₀u/(E'R) (Venner & Lubrecht 2000)."""
    return load_per_length / (effective_modulus * radius) / jnp.sqrt(2.0 * viscosity * speed / (effective_modulus * radius))


def _problem(nodes: int, inlet, fluid: FluidParameters) -> _Problem:
    return _Problem(jnp.linspace(inlet, OUTLET, nodes), log_kernel(nodes), fluid)


# The start: a Hertz pressure at Moes M = START_LOAD_PARAMETER; the continuation runs M
# geometrically to the case's (through λ ∝ M^-2), on START_NODES for light loads (M < 10; the
# coarser grid converges there from the Hertz start) and on COARSE_NODES, the coarsest grid of
# the nested iteration, for heavy ones.
START_NODES = 65
COARSE_NODES = 129
START_LOAD_PARAMETER = 10.0
CONTINUATION_STAGES = 8
FINAL_STEPS = 20
NEWTON_FLOOR = 2**0.5 * 1e-14  # ‖F‖₂ [-] below which Newton takes no step (½‖F‖² ≤ 1e-28: round-off)
# Starvation: the meniscus is searched for between the inlet and MENISCUS_LIMIT (Hertz
# half-widths) in MENISCUS_STEPS Illinois steps on the coarse grid.
MENISCUS_LIMIT = -0.5
MENISCUS_STEPS = 14


def _interpolate(unknowns, count, inlet):
    """Unknowns (interior pressure, H₀) of a grid from `inlet` interpolated onto `count` nodes."""
    previous = jnp.linspace(inlet, OUTLET, len(unknowns) + 1)
    pressure = jnp.interp(jnp.linspace(inlet, OUTLET, count), previous, jnp.pad(unknowns[:-1], 1))
    return jnp.append(pressure[1:-1], unknowns[-1])


def check_nodes(nodes: int) -> int:
    """ValueError unless the grid has 2^k + 1 ≥ COARSE_NODES nodes (nested iteration halves it)."""
    if nodes < COARSE_NODES or (nodes - 1) & (nodes - 2):
        raise ValueError(f"fidelity.grid[0]: the line EHL solver needs 2^k + 1 ≥ {COARSE_NODES} nodes, got {nodes}")
    return nodes


def _discrete_flux(unknowns, problem: _Problem):
    """Mass flux ρ̄H − ε dP/dX [-] through the face after the pressure peak (constant over the
    pressurized nodes of the discrete equations, whose wedge term is in flux form there)."""
    pressure = jnp.pad(unknowns[:-1], 1)
    spacing = problem.nodes[1] - problem.nodes[0]
    film = _film(pressure, unknowns[-1], problem)
    density, flow = reynolds_coefficients(pressure, film, problem.fluid)
    peak = jnp.argmax(pressure)
    mass = density * film
    face = 0.5 * (flow[peak + 1] + flow[peak])
    return 1.5 * mass[peak] - 0.5 * mass[peak - 1] - face * (pressure[peak + 1] - pressure[peak]) / spacing


def line_film(load_per_length, radius, speed, viscosity, pressure_viscosity, effective_modulus, nodes=513,
              viscosity_law="roelands", density_law="dowson_higginson", tolerance=1e-10,
              oil_layer=None, inlet=INLET) -> LineFilm:
    """Isothermal Newtonian EHL line contact by Newton on the discretized Reynolds equation,
    fully flooded or starved by an inlet oil layer.

    Args:
        load_per_length: w [N/m] > 0.
        radius: reduced radius R [m] in the rolling direction.
        speed: mean entrainment speed u [m/s] > 0.
        viscosity: η₀ [Pa·s]; pressure_viscosity: α [1/Pa]; effective_modulus: E' [Pa].
        nodes: grid size N = 2^k + 1 ≥ 129 (≤ 1025 keeps the dense Jacobian cheap).
        viscosity_law: "roelands" | "barus"; density_law: "dowson_higginson" | "incompressible".
        oil_layer: inlet oil supply layer h_oil [m] (both surfaces together, at ambient density),
            or None for fully flooded.
        inlet: where the domain (and a flooded inlet) starts [Hertz half-widths] < −1; the
            outlet is at 1.5. The starved-EHL paper's −4.5 is the default; at Moes M ≈ 2 it is short enough
            to starve the film by about 6 % (`benchmarks/line_ehl.py` shows the inlet study).

    Start (docs/theory.md §Numerical notes: a plain Newton from a Hertz start diverges at low and high loads):
    damped Newton from a Hertz pressure at M = 10, continued in 8 geometric steps of the Moes
    load parameter M to the case's (through the speed parameter λ ∝ M⁻²), on 65 nodes for
    M < 10 and on 129 nodes above; nested iteration, each finer grid started from the
    interpolated coarser solution; last, Newton inside `implicit_root`, whose implicit
    derivative is exact.

    Starvation (docs/theory.md §Numerical notes, "the inlet meniscus position as the unknown"): the pressure
    builds up from a meniscus X_m, where the oil layer fills the gap; by mass conservation in
    steady pure rolling the flux through the contact ρ̄h − (ρh³/12ηu) dp/dx equals the supplied
    u·h_oil. X_m is found on the 129-node grid by the Illinois method in [`inlet`, MENISCUS_LIMIT];
    on the fine grid it joins the unknowns with the flux equation, so the derivative with
    respect to the oil layer is implicit too. Where the flooded contact passes less than the
    supply (the excess flows back), the film is the flooded one: X_m = `inlet`.
    """
    require_float64()
    check_nodes(nodes)
    if not -50.0 <= inlet <= -2.0:
        raise ValueError(f"inlet: the line EHL domain starts between -50 and -2 Hertz half-widths, got {inlet}")
    hertz_contact = line_contact(load_per_length, radius, effective_modulus)
    half_width, hertz_pressure = hertz_contact.half_width, hertz_contact.max_pressure  # p_h = E'b/(4R)
    speed_parameter = 12.0 * viscosity * speed * radius**2 / (half_width**3 * hertz_pressure)
    fluid = FluidParameters(speed_parameter, hertz_pressure, viscosity, pressure_viscosity, viscosity_law, density_law)
    start_fluid = jax.lax.stop_gradient(fluid)  # the iterations before the last solve carry no derivative

    load_parameter = jax.lax.stop_gradient(moes_load_parameter(load_per_length, radius, speed, viscosity,
                                                                effective_modulus))

    def at_load_parameter(problem, value):  # the same contact at Moes M = value (speed scaled)
        return eqx.tree_at(lambda p: p.fluid.speed_parameter, problem,
                           problem.fluid.speed_parameter * (load_parameter / value) ** 2)

    def hertz_start(problem):  # Hertz pressure, H₀ from the Pan–Hamrock central film at M = 10
        hertz = jnp.sqrt(jnp.maximum(1.0 - problem.nodes**2, 0.0))
        start_speed = speed * (load_parameter / START_LOAD_PARAMETER) ** 2
        central_guess, _ = pan_hamrock_line(load_per_length, radius, start_speed, viscosity, pressure_viscosity,
                                            effective_modulus)
        rigid = _film(hertz, 0.0, problem)[jnp.argmin(jnp.abs(problem.nodes))]
        return jax.lax.stop_gradient(jnp.append(hertz[1:-1], central_guess * radius / half_width**2 - rigid))

    def continuation(problem, unknowns):  # M from 10 to the case's in geometric steps
        def stage(index, current):
            stage_problem = at_load_parameter(
                problem, START_LOAD_PARAMETER * (load_parameter / START_LOAD_PARAMETER) ** (index / CONTINUATION_STAGES))
            return newton(_residual, current, stage_problem, max_steps=20, floor=NEWTON_FLOOR)[0]

        return jax.lax.fori_loop(1, CONTINUATION_STAGES + 1, stage, unknowns)

    def coarse_solution(inlet):  # the flooded solution from `inlet` on the coarse grid
        coarse = _problem(COARSE_NODES, inlet, start_fluid)

        def light_load():  # M < 10: the continuation on 65 nodes, then onto the coarse grid
            start = _problem(START_NODES, inlet, start_fluid)
            unknowns = _interpolate(continuation(start, hertz_start(start)), COARSE_NODES, inlet)
            return newton(_residual, unknowns, coarse, max_steps=12, floor=NEWTON_FLOOR)[0]

        def heavy_load():  # M ≥ 10: the continuation on the coarse grid, where the contact is resolved
            return continuation(coarse, hertz_start(coarse))

        return jax.lax.cond(load_parameter < START_LOAD_PARAMETER, light_load, heavy_load), coarse

    unknowns, coarse = coarse_solution(inlet)
    if oil_layer is None:
        meniscus = inlet
    else:
        supply = oil_layer * radius / half_width**2  # h_oil in units of b²/R
        starved = jax.lax.stop_gradient(supply) < _discrete_flux(unknowns, coarse)

        def meniscus_search(flooded):  # Illinois (regula falsi) on flux(X_m) − supply
            def excess(position):
                solution, problem = coarse_solution(position)
                surplus = _discrete_flux(solution, problem) - jax.lax.stop_gradient(supply)
                return jnp.where(jnp.isfinite(surplus), surplus, -supply)  # a failed solve: no flux

            def step(_, bracket):
                low, high, excess_low, excess_high, side = bracket
                middle = (low * excess_high - high * excess_low) / (excess_high - excess_low)
                value = excess(middle)
                keep_high = value > 0  # the root lies above the new point
                return (jnp.where(keep_high, middle, low), jnp.where(keep_high, high, middle),
                        jnp.where(keep_high, value, jnp.where(side < 0, 0.5 * excess_low, excess_low)),
                        jnp.where(keep_high, jnp.where(side > 0, 0.5 * excess_high, excess_high), value),
                        jnp.where(keep_high, 1.0, -1.0))

            flooded_excess = _discrete_flux(flooded, coarse) - jax.lax.stop_gradient(supply)
            low, high, excess_low, excess_high, _ = jax.lax.fori_loop(
                0, MENISCUS_STEPS, step,
                (jnp.asarray(inlet), jnp.asarray(MENISCUS_LIMIT), flooded_excess, excess(MENISCUS_LIMIT), 0.0))
            root = (low * excess_high - high * excess_low) / (excess_high - excess_low)
            return coarse_solution(root)[0], root

        unknowns, meniscus = jax.lax.cond(starved, meniscus_search, lambda flooded: (flooded, jnp.asarray(inlet)),
                                          unknowns)
        unknowns, meniscus = jax.lax.stop_gradient((unknowns, meniscus))
    # nested iteration up to the requested grid
    count = COARSE_NODES
    while count < nodes:
        count = 2 * count - 1
        finer = _problem(count, meniscus, start_fluid)
        unknowns = newton(_residual, _interpolate(unknowns, count, meniscus), finer, max_steps=12,
                          floor=NEWTON_FLOOR)[0]

    fine = _problem(nodes, inlet, fluid)

    def equations(state, _):  # discrete Reynolds and load balance; the flux balance fixes X_m
        problem = eqx.tree_at(lambda p: p.nodes, fine, jnp.linspace(state[-1], OUTLET, nodes))
        if oil_layer is None:
            flux_balance = state[-1] - inlet
        else:
            flux_balance = jnp.where(starved, _discrete_flux(state[:-1], problem) - supply, state[-1] - inlet)
        return jnp.append(_residual(state[:-1], problem), flux_balance)

    # Final Newton on the fine grid inside `implicit_root`: its derivative is the implicit one,
    # −J⁻¹ ∂F/∂θ with the converged Jacobian (forward and reverse mode).
    solution = implicit_root(
        equations, jax.lax.stop_gradient(jnp.append(unknowns, meniscus)), None,
        solve=lambda function, guess, args: newton(function, guess, args, max_steps=FINAL_STEPS,
                                                   floor=NEWTON_FLOOR)[0])
    residual = jnp.max(jnp.abs(equations(jax.lax.stop_gradient(solution), None)))
    problem = eqx.tree_at(lambda p: p.nodes, fine, jnp.linspace(solution[-1], OUTLET, nodes))
    pressure = jnp.pad(solution[:-2], 1)
    film = _film(pressure, solution[-2], problem) * half_width**2 / radius
    centre = jnp.argmin(jnp.abs(problem.nodes))
    # a film below zero solves the discrete equations but not the physics: the grid is too coarse
    return LineFilm(problem.nodes * half_width, pressure * hertz_pressure, film, film[centre], jnp.min(film),
                    (residual < tolerance) & (jnp.min(film) > 0), residual, solution[-1] * half_width)
