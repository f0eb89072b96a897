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

Solver: Newton–Krylov (`newton_krylov`, the column-block preconditioner of
`finite_line_krylov.UniformLevel.column_preconditioner` with ∂P/∂u = c where u > 0; each step at
most 0.2 + ½|u| per node and OFFSET_STEP on H₀). Newton from the flooded solution with the supply
at the layer stalls where many nodes switch at once (docs/validation/lubricant_film.md §The starved
point contact); so on the grid of MARCH_NODES nodes along rolling (or the finest, if coarser) the
solution is reached by pseudo-time continuation: from the flooded film with its inlet emptied to
the layer (a partial film θ = H_oil/ρ̄H where the flooded film holds more oil and its pressure is
below EMPTIED_PRESSURE; otherwise that oil must drain through the sides of the domain, slowly for
an elongated contact), MARCH_STEPS implicit steps of the transient Reynolds equation (the squeeze
term (ρ̄Hθ − ρ̄Hθ_old)/ΔT added, ΔT = MARCH_STEP in b_r/u, the time to roll one reference length);
then the steady equations by Newton–Krylov from where the march ends, and on each finer grid
(x nodes and y cells doubled) from the coarser solution interpolated (`interpolate_fill`): marched
there, the implicit second-order upwind transport of the inlet's partial film (Courant number
ΔT/ΔX ≈ 10 on 129 × 64) stalls Newton. Converged: max|F/s| ≤ `tolerance` on the finest grid and a
positive film there. Derivatives implicit through the finest root (`newton_krylov.krylov_root`).
Where the march does not reach the steady film (the circle's thinnest layers on 33 × 16; a κ ≈ 9
contact at a layer of twice its flooded film, whose meniscus lies far upstream) the result says
so.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from .finite_line_ehl import transverse_terms
from .finite_line_krylov import UniformLevel, krylov_levels
from .line_ehl import INLET, poiseuille_terms, reynolds_coefficients
from .newton_krylov import krylov_root, newton_krylov
from .numerics import require_float64
from .params import check_range
from .point_ehl import FEWEST_CELLS, PointFilm, film_result, point_film, point_level

MARCH_STEP = 0.5  # ΔT [b_r/u] of an implicit pseudo-time step
MARCH_STEPS = 32  # the march covers 16 b_r/u, the inlet's oil carried well past the contact
EMPTIED_PRESSURE = 0.05  # [p₀] the march starts with the inlet emptied to the layer below this pressure
MARCH_NEWTON = 30  # Newton–Krylov steps per pseudo-time step
STEADY_NEWTON = 80  # Newton–Krylov steps of the steady equations after the march
MARCH_NODES = 65  # the march runs on the grid of this many nodes along rolling (or the finest, if coarser)
OFFSET_STEP = 0.06  # the largest change of H₀ per Newton step (as `point_ehl.LARGEST_STEP`)


class StarvedPointFilm(eqx.Module):
    """`film`: the solution [SI] on the half domain y ≥ 0 (`point_ehl.PointFilm`); the oil fill θ
    [-] (nx, ny); the oil layer [m]."""

    film: PointFilm
    fill: jax.Array
    oil_layer: jax.Array


class MarchStage(eqx.Module):
    """The equations of one pseudo-time step (the `args` of `StarvedLevel.residual`): the squeeze
    term (ρ̄Hθ − `old_mass`)/ΔT with `inverse_step` = 1/ΔT."""

    old_mass: jax.Array
    inverse_step: jax.Array


class StarvedLevel(UniformLevel):
    """The θ-model's equations (module docstring) on the grid of a flooded `UniformLevel`: the
    unknowns u at the interior nodes (row-major) and H₀; the oil layer H_oil = `supply` [-]."""

    def __init__(self, level: UniformLevel, supply):
        self.__dict__.update(vars(level))  # the grid, spectrum, rigid film, fluid and load of `level`
        self.supply = supply
        # c = min(1, ΔX λ/H_r²) of P = c·max(u, 0) (module docstring)
        rigid = jnp.maximum(self.rigid[1:-1], 1e-12)
        self.scale = jnp.minimum(1.0, self.spacing * self.columns.fluid.speed_parameter / rigid**2)

    def split(self, switch):
        """(P, θ) [-] (nx, ny) of u (nx − 2, ny) at the interior nodes; P = 0, θ = 1 on the edges."""
        pressure = jnp.pad(self.scale * jnp.maximum(switch, 0.0), ((1, 1), (0, 0)))
        fill = jnp.pad(1.0 + jnp.minimum(switch, 0.0), ((1, 1), (0, 0)), constant_values=1.0)
        return pressure, fill

    def fields(self, unknowns):
        """(P, θ, H₀) [-] of the unknowns."""
        return *self.split(unknowns[:-1].reshape(self.nx - 2, self.ny)), unknowns[-1]

    def unpack(self, unknowns):
        pressure, _, offset = self.fields(unknowns)
        return pressure, offset, jnp.full(self.ny, INLET)

    def mass(self, pressure, fill, film):
        """ρ̄Hθ [-] (nx, ny), the inlet row carrying the supply min(H_oil, H)."""
        density = reynolds_coefficients(pressure, film, self.columns.fluid)[0]
        return (density * film * fill).at[0].set(jnp.minimum(self.supply, film[0]))

    def rows(self, switch, film, stage):
        """The Reynolds residual × ΔX [-] (nx − 2, ny) at the interior nodes of the unknowns u
        (nx − 2, ny) and the film H (nx, ny), minus the squeeze term of `stage` (a MarchStage;
        None: the steady equations)."""
        pressure, fill = self.split(switch)
        mass = self.mass(pressure, fill, film)
        flow = reynolds_coefficients(pressure, film, self.columns.fluid)[1]
        # the wedge term in flux form, so that mass is conserved: the face after the inlet node first-order
        # upwind, the others second-order, F_{i+½} = (3m_i − m_{i−1})/2 (`line_ehl.rolling_terms`, kept as
        # it is for the flooded levels, puts a second-order face after node 1 but a first-order one before
        # node 2, a source of (m₁ − m₀)/2 that feeds a starved inlet from nowhere)
        faces = jnp.concatenate([mass[:2], 0.5 * (3.0 * mass[2:-1] - mass[1:-2])])
        wedge = (faces[1:] - faces[:-1]) / self.spacing
        reynolds = poiseuille_terms(pressure, flow, self.spacing) - wedge + transverse_terms(pressure, flow,
                                                                                             self.columns)[1:-1]
        if stage is not None:
            reynolds = reynolds - (mass[1:-1] - stage.old_mass) * stage.inverse_step
        return reynolds * self.spacing

    def residual(self, unknowns, stage=None):
        """The Reynolds rows (`rows`, row-major), then the load balance."""
        switch = unknowns[:-1].reshape(self.nx - 2, self.ny)
        pressure = self.split(switch)[0]
        return jnp.append(self.rows(switch, self.film(pressure, unknowns[-1]), stage).reshape(-1),
                          self.balance(pressure))

    def residual_scale(self, unknowns):
        """The size of each equation [-]: 1 + c (s − 1) for the Reynolds rows, s the flooded row's
        (`UniformLevel.row_scale`), so that F/s is the change of u a row asks of its own node; 1 for
        the load balance."""
        rows = 1.0 + self.scale * (self.row_scale(unknowns) - 1.0)
        return jnp.append(rows.reshape(-1), 1.0)

    def limit(self, step, unknowns):
        """`step` shortened so that no u changes by more than 0.2 + ½|u| and H₀ by at most
        OFFSET_STEP."""
        ratio = jnp.maximum(jnp.max(jnp.abs(step[:-1]) / (0.2 + 0.5 * jnp.abs(unknowns[:-1]))),
                            jnp.abs(step[-1]) / OFFSET_STEP)
        return step / jnp.maximum(ratio, 1.0)

    def preconditioner(self, unknowns, stage=None):
        """v ↦ M⁻¹v: the column blocks of J (`UniformLevel.column_preconditioner`), ∂P/∂u = c where
        u > 0."""
        fixed = jax.lax.stop_gradient(unknowns)
        pressure, offset, meniscus = self.unpack(fixed)
        switch = fixed[:-1].reshape(self.nx - 2, self.ny)
        return self.column_preconditioner(lambda interior, film, _: self.rows(interior, film, stage), switch,
                                          self.film(pressure, offset), meniscus, self.scale * (switch > 0), False)


def march_grid(grid) -> tuple[int, int]:
    """(nx, ny) of the nested grid (`finite_line_krylov.krylov_levels`) of `grid` that the march
    runs on: the finest with at most MARCH_NODES nodes along rolling."""
    return [level for level in krylov_levels(grid, FEWEST_CELLS) if level[0] <= MARCH_NODES][-1]


def interpolate_fill(unknowns, coarse: StarvedLevel, fine: StarvedLevel):
    """Unknowns of `coarse` on `fine`: P and θ bilinear (the edges' values held beyond the outer
    cell centres), u = P/c where P > 0, θ − 1 elsewhere; H₀ kept."""
    pressure, fill, offset = coarse.fields(unknowns)

    def bilinear(values):
        along_y = jax.vmap(lambda row: jnp.interp(fine.columns.y, coarse.columns.y, row))(values)
        return jax.vmap(lambda column: jnp.interp(fine.columns.x, coarse.columns.x, column), in_axes=1,
                        out_axes=1)(along_y)[1:-1]

    pressure, fill = bilinear(pressure), bilinear(fill)
    switch = jnp.where(pressure > 0, pressure / fine.scale, jnp.minimum(fill - 1.0, 0.0))
    return jnp.append(switch.reshape(-1), offset)


def starved_point_film(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity,
                       effective_modulus, oil_layer, grid=(65, 32), viscosity_law="roelands",
                       density_law="dowson_higginson", tolerance=1e-10) -> StarvedPointFilm:
    """Isothermal EHL film [m] of an elliptical point contact starved by an inlet oil layer
    (module docstring). Arguments as `point_ehl.point_film`, and `oil_layer` h_oil [m] > 0: the
    oil on both surfaces ahead of the contact. Converged: max|F/s| ≤ `tolerance`
    (`StarvedLevel.residual_scale`) on the finest grid and h > 0 there."""
    require_float64()
    check_range("oil_layer", oil_layer, low=0.0, unit=" m", why="the inlet oil layer")
    levels = krylov_levels(grid, FEWEST_CELLS)
    marching = march_grid(grid)
    finer = levels[levels.index(marching) + 1:]
    arguments = (load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
                 oil_layer)
    constants = jax.lax.stop_gradient(arguments)

    def level_at(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
                 oil_layer, grid):
        level, reference = point_level(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity,
                                       effective_modulus, grid, viscosity_law, density_law)
        return StarvedLevel(level, oil_layer * radius_rolling / reference**2), reference

    def solve(level, unknowns, stage, steps):
        return newton_krylov(level.residual, unknowns, stage, level.preconditioner, tolerance=tolerance,
                             max_steps=steps, limit=level.limit, scale=level.residual_scale)[0]

    # on the march grid: from the flooded solution, in the θ-model's unknowns
    flooded = point_film(*constants[:-1], grid=marching, viscosity_law=viscosity_law, density_law=density_law)
    level, reference = level_at(*constants, marching)
    pressure = flooded.pressure / level.columns.fluid.hertz_pressure
    film = flooded.thickness * radius_rolling / reference**2
    offset = film[0, 0] - level.film(pressure, 0.0)[0, 0]
    # the inlet emptied to the layer: where the flooded film holds more oil than the layer carries and its
    # pressure is below EMPTIED_PRESSURE, a partial film of the layer's mass (θ = H_oil/ρ̄H)
    density = reynolds_coefficients(pressure, film, level.columns.fluid)[0][1:-1]
    emptied = ((level.columns.x[1:-1, None] < 0) & (pressure[1:-1] < EMPTIED_PRESSURE)
               & (density * film[1:-1] > level.supply))
    switch = jnp.where(emptied, level.supply / (density * film[1:-1]) - 1.0, pressure[1:-1] / level.scale)
    start = jnp.append(switch.reshape(-1), offset)

    def march(_, unknowns):
        pressure, fill, offset = level.fields(unknowns)
        old_mass = level.mass(pressure, fill, level.film(pressure, offset))[1:-1]
        return solve(level, unknowns, MarchStage(old_mass, jnp.asarray(1.0 / MARCH_STEP)), MARCH_NEWTON)

    unknowns = solve(level, jax.lax.fori_loop(0, MARCH_STEPS, march, start), None, STEADY_NEWTON)
    for nx, ny in finer:  # nested iteration: the steady equations grid by grid
        finer_level = level_at(*constants, (nx, ny))[0]
        unknowns = solve(finer_level, interpolate_fill(unknowns, level, finer_level), None, STEADY_NEWTON)
        level = finer_level
    live, live_reference = level_at(*arguments, levels[-1])
    unknowns = krylov_root(live.residual, unknowns, None, level.preconditioner(unknowns))
    pressure, starved, _, error, converged = live.solution(unknowns, tolerance)
    result = film_result(live, live_reference, radius_rolling, pressure, starved, converged, error)
    return StarvedPointFilm(result, live.fields(unknowns)[1], jnp.asarray(oil_layer, dtype=float))
