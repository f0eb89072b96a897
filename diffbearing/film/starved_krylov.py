"""The starved (mass-conserving θ-model) Reynolds equation on the uniform grids of the
Newton–Krylov EHL solvers, and its solution from a flooded film.

The θ-model (Elrod–Adams / Jakobsson–Floberg–Olsson; for starved EHL Chevalier, Lubrecht, Cann,
Colin & Dalmaz, J. Tribol. 120, 1998), in the dimensionless units of a `nested_krylov.UniformLevel`
(a roller's finite line contact or a ball's point contact),

    ∂X(ε ∂X P) + ∂Y(ε ∂Y P) − ∂X(ρ̄Hθ) = 0,   P ≥ 0,  θ ≤ 1,  P (1 − θ) = 0,

θ the fraction of the gap that the oil fills: a full film (θ = 1) carries pressure, a partial one
(P = 0) is carried along by the surfaces, so that mass is conserved through the inlet meniscus,
the contact, the sides and the outlet cavitation alike. The inlet node carries
ρ̄Hθ = min(H_oil, H). One unknown u per node: P = c·max(u, 0), θ = 1 + min(u, 0). The scale
c = min(1, ΔX λ/H_r²) (H_r the rigid gap) is small in the inlet, where the Poiseuille coefficient
ε/ΔX² exceeds the wedge term's ρ̄H/ΔX by up to 10⁵: unscaled, a node switching between full and
partial film there changes its equation's slope by that much and Newton stalls. Wedge term in
conservative flux form, second-order upwind faces but the first after the inlet node; where θ = 1
these are the flooded level's discrete equations but for the second node's wedge term.

Solver (`solve_starved`): Newton–Krylov (`newton_krylov`, the column-block preconditioner of
`UniformLevel.column_preconditioner` with ∂P/∂u = c where u > 0; each step at most 0.2 + ½|u|
per node and OFFSET_STEP on H₀). Newton from the flooded solution with the supply at the layer
stalls where many nodes switch at once (docs/validation/lubricant_film.md §The starved point
contact); so on a march grid (`march_level`) the solution is reached by pseudo-time
continuation: from the flooded film with its inlet emptied to the layer (a partial film
θ = H_oil/ρ̄H where the flooded film holds more oil and its pressure is below EMPTIED_PRESSURE;
otherwise that oil must drain through the sides of the domain, slowly for an elongated contact),
MARCH_STEPS implicit steps of the transient Reynolds equation (the squeeze term
(ρ̄Hθ − ρ̄Hθ_old)/ΔT added, ΔT = MARCH_STEP in reference lengths rolled); then the steady
equations by Newton–Krylov from where the march ends, and on each finer grid (x nodes and y cells
doubled) from the coarser solution interpolated (`interpolate_fill`): marched there, the implicit
second-order upwind transport of the inlet's partial film (Courant number ΔT/ΔX ≈ 10 on 129 nodes)
stalls Newton. Derivatives implicit through the finest root (`newton_krylov.krylov_root`).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..newton_krylov import krylov_root, newton_krylov
from .finite_line_ehl import transverse_terms
from .line_ehl import INLET, poiseuille_terms, reynolds_coefficients
from .nested_krylov import UniformLevel

MARCH_STEP = 0.5  # ΔT [b_r/u] of an implicit pseudo-time step
MARCH_STEPS = 32  # the march covers 16 b_r/u, the inlet's oil carried well past the contact
EMPTIED_PRESSURE = 0.05  # [p₀] the march starts with the inlet emptied to the layer below this pressure
MARCH_NEWTON = 30  # Newton–Krylov steps per pseudo-time step
STEADY_NEWTON = 80  # Newton–Krylov steps of the steady equations after the march
MARCH_NODES = 65  # the march runs on the nested grid of at most this many nodes along rolling
OFFSET_STEP = 0.06  # the largest change of H₀ per Newton step (as `point_ehl.LARGEST_STEP`)


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


def march_level(levels) -> tuple[int, int]:
    """(nx, ny) of the nested grids `levels` (coarsest first) that the march runs on: the finest
    with at most MARCH_NODES nodes along rolling."""
    return [level for level in levels if level[0] <= MARCH_NODES][-1]


def solve_starved(level_at, arguments, levels, marching, flooded_pressure, flooded_film, tolerance):
    """(the finest StarvedLevel built from the live `arguments`, its solution with implicit
    derivatives) (module docstring): `level_at(*arguments, grid)` → the StarvedLevel of the case on
    `grid`; `levels` the nested grids, coarsest first, of which `marching` is the march grid;
    the flooded solution on it, P and H [-] (nx, ny), without derivatives."""
    constants = jax.lax.stop_gradient(arguments)

    def solve(level, unknowns, stage, steps):
        return newton_krylov(level.residual, unknowns, stage, level.preconditioner, tolerance=tolerance,
                             max_steps=steps, limit=level.limit, scale=level.residual_scale)[0]

    level = level_at(*constants, marching)
    pressure, film = flooded_pressure, flooded_film
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
    for grid in levels[levels.index(marching) + 1:]:  # nested iteration: the steady equations grid by grid
        finer = level_at(*constants, grid)
        unknowns = solve(finer, interpolate_fill(unknowns, level, finer), None, STEADY_NEWTON)
        level = finer
    live = level_at(*arguments, levels[-1])
    return live, krylov_root(live.residual, unknowns, None, level.preconditioner(unknowns))
