"""Numerical EHL of a starved elliptical point contact: the mass-conserving θ-model.

The flooded point contact (`point_ehl`) with the inlet supplied by an oil layer h_oil only
(the layer on both surfaces together, as `finite_line_ehl`'s): the Reynolds equation of the
Elrod–Adams / Jakobsson–Floberg–Olsson model, in the dimensionless units of `point_ehl`,

    ∂X(ε ∂X P) + ∂Y(ε ∂Y P) − ∂X(ρ̄Hθ) = 0,   P ≥ 0,  θ ≤ 1,  P (1 − θ) = 0,

θ the fraction of the gap that the oil fills: a full film (θ = 1) carries pressure, a partial one
(P = 0) is carried along by the surfaces, so that mass is conserved through the inlet meniscus, the
contact and the outlet cavitation alike (Elrod, J. Lubr. Technol. 103, 1981; for starved EHL,
Chevalier, Lubrecht, Cann, Colin & Dalmaz, J. Tribol. 120, 1998). The inlet node carries
ρ̄Hθ = min(H_oil, H). One unknown u per node: P = c·max(u, 0), θ = 1 + min(u, 0). The scale
c = min(1, ΔX λ/H_r²) (H_r the rigid gap) is small in the inlet, where the Poiseuille coefficient
ε/ΔX² exceeds the wedge term's ρ̄H/ΔX by up to 10⁵: unscaled, a node switching between full and
partial film there changes its equation's slope by that much and Newton stalls. Wedge term in
conservative flux form, second-order upwind faces but the first after the inlet node; where θ = 1
these are `point_ehl.point_film`'s discrete equations but for the second node's wedge term, so a
layer thicker than the inlet gap gives its film within 0.1 %.

Solver. Newton from the flooded solution with the supply at the layer stalls where many nodes
switch at once (docs/validation/lubricant_film.md §The point contact). The solution is reached by
pseudo-time continuation instead: the transient Reynolds equation's squeeze term
(ρ̄Hθ − ρ̄Hθ_old)/ΔT is added (T in b_r/u: the time to roll one reference length), the supply falls
geometrically from RAMP_START flooded central films to the layer over RAMP_STEPS steps, and
MARCH_STEPS implicit steps of MARCH_STEP march the flooded film towards the starved one (each a
damped Newton, `newton.newton`, dense Jacobian, steps of at most 0.2 + ½|u| per node); then the
steady equations by Newton from where the march ends. Converged: max|F| ≤ `tolerance` and a
positive film. Derivatives implicit through the steady root (`newton.implicit_root`, dense).
The dense Jacobian holds the grid to about 65 × 32 (one solve there about 3.5 minutes on 2 cores);
on 33 × 16 the march reaches the steady film at some layers and not at others (it says so).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from .finite_line_ehl import transverse_terms
from .line_ehl import poiseuille_terms, reynolds_coefficients
from .newton import implicit_root, newton
from .numerics import require_float64
from .params import check_range
from .point_ehl import PointFilm, film_result, point_film, point_level

MARCH_STEP = 0.5  # ΔT [b_r/u] of an implicit pseudo-time step
MARCH_STEPS = 32  # the march covers 16 b_r/u, the inlet's oil carried well past the contact
RAMP_STEPS = 16  # the supply reaches the layer after this many steps, and stays there
RAMP_START = 8.0  # the supply at T = 0, in flooded central films (the film hardly starves above)
MARCH_NEWTON = 30  # Newton steps per pseudo-time step
STEADY_NEWTON = 60  # Newton steps of the steady equations after the march
MAX_UNKNOWNS = 2100  # (nx − 2)·ny: 65 × 32 (the dense Jacobian and its forward passes, about 0.5 GB)
OFFSET_STEP = 0.06  # the largest change of H₀ per Newton step (as `point_ehl.LARGEST_STEP`)


class StarvedPointFilm(eqx.Module):
    """`film`: the solution [SI] on the half domain y ≥ 0 (`point_ehl.PointFilm`); the oil fill θ
    [-] (nx, ny); the oil layer [m]; the flooded central film on the same grid [m] (no derivative)."""

    film: PointFilm
    fill: jax.Array
    oil_layer: jax.Array
    flooded_central: jax.Array


def _inlet_scale(level):
    """c [-] (nx − 2, ny) of P = c·max(u, 0) at the interior nodes (module docstring)."""
    rigid = jnp.maximum(level.rigid[1:-1], 1e-12)
    return jnp.minimum(1.0, level.spacing * level.columns.fluid.speed_parameter / rigid**2)


def _fields(unknowns, level, scale):
    """(P, θ, H₀) [-] of the unknowns (u at the interior nodes, H₀); P = 0, θ = 1 on the edges."""
    nx, ny = level.nx, level.ny
    switch = unknowns[:-1].reshape(nx - 2, ny)
    pressure = jnp.pad(scale * jnp.maximum(switch, 0.0), ((1, 1), (0, 0)))
    fill = jnp.pad(1.0 + jnp.minimum(switch, 0.0), ((1, 1), (0, 0)), constant_values=1.0)
    return pressure, fill, unknowns[-1]


def _mass(density, film, fill, supply):
    """ρ̄Hθ [-] (nx, ny), the inlet row carrying the supply min(H_oil, H)."""
    return (density * film * fill).at[0].set(jnp.minimum(supply, film[0]))


def _state(unknowns, level, scale, supply):
    """(P, film H, ρ̄Hθ, ε) [-] (nx, ny) of the unknowns."""
    pressure, fill, offset = _fields(unknowns, level, scale)
    film = level.film(pressure, offset)
    density, flow = reynolds_coefficients(pressure, film, level.columns.fluid)
    return pressure, film, _mass(density, film, fill, supply), flow


def reynolds_residual(unknowns, level, scale, supply, old_mass, inverse_step):
    """The θ-model's equations [-]: at each interior node the Reynolds residual × ΔX (minus the
    squeeze term (ρ̄Hθ − old)/ΔT, `inverse_step` = 1/ΔT, 0 for the steady equations), then the
    load balance (`finite_line_krylov.UniformLevel.balance`)."""
    pressure, _, mass, flow = _state(unknowns, level, scale, supply)
    # the wedge term in flux form, so that mass is conserved: the face after the inlet node first-order
    # upwind, the others second-order, F_{i+½} = (3m_i − m_{i−1})/2 (`line_ehl.rolling_terms`, kept as
    # it is for the flooded levels, puts a second-order face after node 1 but a first-order one before
    # node 2, a source of (m₁ − m₀)/2 that feeds a starved inlet from nowhere)
    faces = jnp.concatenate([mass[:2], 0.5 * (3.0 * mass[2:-1] - mass[1:-2])])
    wedge = (faces[1:] - faces[:-1]) / level.spacing
    reynolds = (poiseuille_terms(pressure, flow, level.spacing) - wedge
                + transverse_terms(pressure, flow, level.columns)[1:-1] - (mass[1:-1] - old_mass) * inverse_step)
    return jnp.append(reynolds.reshape(-1) * level.spacing, level.balance(pressure))


def starved_point_film(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity,
                       effective_modulus, oil_layer, grid=(65, 32), viscosity_law="roelands",
                       density_law="dowson_higginson", tolerance=1e-9) -> StarvedPointFilm:
    """Isothermal EHL film [m] of an elliptical point contact starved by an inlet oil layer
    (module docstring). Arguments as `point_ehl.point_film`, and `oil_layer` h_oil [m] > 0: the
    oil on both surfaces ahead of the contact. Converged: max|F| ≤ `tolerance` and h > 0."""
    require_float64()
    check_range("oil_layer", oil_layer, low=0.0, unit=" m", why="the inlet oil layer")
    if (grid[0] - 2) * grid[1] > MAX_UNKNOWNS:
        raise ValueError(f"grid = (nx, ny): the starved point contact's dense Newton takes (nx − 2)·ny ≤ {MAX_UNKNOWNS}, "
                         f"e.g. (65, 32); got {tuple(grid)}")
    arguments = (load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus)
    flooded = point_film(*jax.lax.stop_gradient(arguments), grid=grid, viscosity_law=viscosity_law,
                         density_law=density_law)
    fixed, reference = point_level(*jax.lax.stop_gradient(arguments), grid, viscosity_law, density_law)
    scale = _inlet_scale(fixed)

    # the flooded solution in the θ-model's unknowns
    pressure = flooded.pressure / fixed.columns.fluid.hertz_pressure
    film = flooded.thickness * radius_rolling / reference**2
    offset = film[0, 0] - fixed.film(pressure, 0.0)[0, 0]
    start = jnp.append((pressure[1:-1] / scale).reshape(-1), offset)

    def solve(unknowns, supply, old_mass, inverse_step, steps):
        def limit(step):  # at most 0.2 + ½|u| per node and OFFSET_STEP on H₀ (module docstring)
            ratio = jnp.maximum(jnp.max(jnp.abs(step[:-1]) / (0.2 + 0.5 * jnp.abs(unknowns[:-1]))),
                                jnp.abs(step[-1]) / OFFSET_STEP)
            return step / jnp.maximum(ratio, 1.0)

        return newton(lambda y, _: reynolds_residual(y, fixed, scale, supply, old_mass, inverse_step), unknowns,
                      max_steps=steps, loop="while", limit=limit, fallback=True, floor=0.1 * tolerance)[0]

    fixed_supply = jax.lax.stop_gradient(oil_layer * radius_rolling / reference**2)

    # the supply falls geometrically from RAMP_START flooded central films to the layer
    ramp_start = jnp.maximum(fixed_supply, RAMP_START * film[fixed.centre, 0])

    def march(step, unknowns):
        supply = fixed_supply * (ramp_start / fixed_supply) ** jnp.maximum(0.0, 1.0 - step / RAMP_STEPS)
        old_mass = _state(unknowns, fixed, scale, supply)[2][1:-1]
        return solve(unknowns, supply, old_mass, 1.0 / MARCH_STEP, MARCH_NEWTON)

    marched = jax.lax.fori_loop(0, MARCH_STEPS, march, start)
    zero = jnp.zeros((fixed.nx - 2, fixed.ny))
    steady = solve(marched, fixed_supply, zero, 0.0, STEADY_NEWTON)

    live, live_reference = point_level(*arguments, grid, viscosity_law, density_law)

    def residual(unknowns, supply):
        return reynolds_residual(unknowns, live, scale, supply, zero, 0.0)

    unknowns = implicit_root(residual, steady, oil_layer * radius_rolling / live_reference**2,
                             lambda _, start, __: start)
    error = jnp.max(jnp.abs(reynolds_residual(steady, fixed, scale, fixed_supply, zero, 0.0)))
    pressure, fill, offset = _fields(unknowns, live, scale)
    starved = live.film(pressure, offset)
    converged = (error <= tolerance) & (jnp.min(jax.lax.stop_gradient(starved)) > 0)
    result = film_result(live, live_reference, radius_rolling, pressure, starved, converged, error)
    return StarvedPointFilm(result, fill, jnp.asarray(oil_layer, dtype=float), flooded.central)
