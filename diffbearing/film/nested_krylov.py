"""The 2-D EHL engine on uniform grids, shared by the finite line contact (`finite_line_krylov`)
and the point contact (`point_ehl`): nested matrix-free Newton–Krylov with FFT deflection.

The discrete equations are those of `finite_line_ehl` (Reynolds complementarity, load balance,
menisci; `local_equations`) on uniform cells along y, so that the elastic film is a convolution
applied by DC-FFT (`influence`); a `UniformLevel` holds one grid of them in Hertz half-width units.

Solver: nested iteration. The coarsest grid (nx ≤ 2·COARSEST_NODES − 1 nodes) is solved by the
dense Newton of `finite_line_ehl` with its load continuation and held menisci; each finer grid, x
nodes and y cells doubled, starts from the coarser solution interpolated (bilinear, p = 0 on the
roller end; a node is wet only where every coarse node around it is) and is solved by inexact
Newton–Krylov (`newton_krylov`). Preconditioner: the exact Jacobian blocks of each y column —
its interior pressures and meniscus against its own equations, the elastic coupling of the column
with itself and its two neighbours' films included — built and inverted COLUMN_BATCH columns at
a time (`jax.lax.map`, so that the temporaries stay O(COLUMN_BATCH·nx²)), bordered by the film
offset H₀ and the load balance through their Schur complement. The blocks come from
colored Jacobian-vector products of the column-local equations (Curtis–Powell–Reid: the Reynolds
row of node i reads nodes i − 2 … i + 1 of columns j − 1 … j + 1, so 5 × 3 colors suffice)
and from the meniscus rows by three colored vector-Jacobian products. The coupling between
columns that the blocks leave out is what GMRES iterates on (docs/benchmarks.md §Finite line EHL
by Newton–Krylov). Newton steps are limited (`UniformLevel.limit`): no meniscus moves more than
a cell, and, where a caller asks, no pressure and H₀ more than given amounts.

Starved, each finer level (`solve_nested`): the interpolated menisci are moved upstream of where
the fine column's gap closes below the oil layer, or to the highest where it never does
(`interpolate_level`); Newton–Krylov solves for the pressure and H₀ with the menisci held
(`Stage.held`); the flux that this solution carries differs from the supply (by 9 %
at 1607 N from 33 × 65 to 65 × 65: the inlet is resolved anew), and a Newton step that moves
every meniscus at once stalls on near-singular modes of single columns' menisci (singular values
of 1e-5 where it stalled at 1607 N on 65 × 65, 3e-2 at the 1028 N solution); so the supply is
continued from the one the held solution carries to the oil layer's, in stages of ln H_oil that
double when a stage converges and halve when it does not (`Stage.supply_factor`).

The coarsest grid keeps 64 cells or more along the half roller (`COARSEST_CELLS`), flooded and
starved: on 33 × 33 the dense Newton ends with h < 0 (starved, 0.8 µm, 1028 N; flooded at 1607 N on
the paper's roller with its raceway edge, crown radius 9.09 mm: −0.40 µm), and on that roller at
2471 N it does not converge, so that no finer grid did either; from 33 × 65 all converge.

Derivatives: implicit, through the finest solution (`newton_krylov.krylov_root`), the tangent
systems solved by the same preconditioned GMRES.
"""

import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..contact.influence import coefficient_spectrum, influence_coefficients, love_rectangle
from ..newton_krylov import FORCING_LARGEST, krylov_root, newton_krylov
from .finite_line_ehl import ColumnGrid, axial_cells, local_equations
from .line_ehl import INLET, OUTLET, reynolds_coefficients

COARSEST_NODES = 33  # nodes along rolling of the coarsest (dense) grid
COARSEST_CELLS = 64  # fewest cells on the half roller of a coarser grid (module docstring)
NEWTON_STEPS = 80  # Newton–Krylov steps per level: 257 × 257 flooded at 1028 N takes 50 (docs/benchmarks.md)
HELD_MENISCUS_STEPS = 15  # starved levels: Newton–Krylov steps on the pressure and H₀ before the menisci move
SUPPLY_STAGE_STEPS = 20  # Newton–Krylov steps of one stage of the supply continuation
SUPPLY_STAGES = 24  # the most stages tried (accepted or halved) of one level's supply continuation
SUPPLY_SMALLEST_STAGE = 2e-3  # the smallest change of ln H_oil the continuation tries
STARVED_FORCING = 1e-6  # the loosest linear solve of a starved level: at 1e-3 the 65 × 48 starved case stalls
BAND = 5  # colors along x: a Reynolds row reads nodes i − 2 … i + 1
READ_BAND = (-2, -1, 0, 1)  # those nodes, from the row's own
COLUMN_BATCH = 8  # columns whose blocks are built and inverted at once: memory ∝ COLUMN_BATCH·(nx − 2)²
DIMENSIONLESS_MODULUS = 4.0  # E' in influence_coefficients' 2/(πE') so that H_el = (1/2π) Σ P C


def krylov_levels(grid, fewest_cells: int = COARSEST_CELLS) -> list[tuple[int, int]]:
    """The nested grids (nx, ny on the half domain), coarsest first: nx nodes halved while the
    coarser grid keeps ≥ COARSEST_NODES nodes, ny cells halved alike while they stay
    ≥ `fewest_cells` (for the roller, a coarse solution with h < 0 at its end is no start);
    ValueError unless nx = 2^k·(n₀ − 1) + 1 with n₀ ≥ COARSEST_NODES and ny ≥ 8."""
    nx, ny = (int(n) for n in grid)
    if nx < COARSEST_NODES or ny < 8:
        raise ValueError(f"grid: the finite-line EHL (Newton–Krylov) needs nx ≥ {COARSEST_NODES} and ny ≥ 8 cells on "
                         f"the half roller, got {[nx, ny]}")
    levels = [(nx, ny)]
    while (levels[0][0] - 1) % 2 == 0 and (levels[0][0] - 1) // 2 + 1 >= COARSEST_NODES:
        cells = levels[0][1]
        levels.insert(0, ((levels[0][0] - 1) // 2 + 1, math.ceil(cells / 2) if cells >= 2 * fewest_cells else cells))
    if (levels[0][0] - 2) * levels[0][1] > 4200:
        raise ValueError(f"grid: nx must be 2^k·(n₀ − 1) + 1 with a coarsest n₀ of {COARSEST_NODES} … 65 nodes "
                         f"(e.g. 65, 129, 257, 513), got nx = {nx}")
    return levels


def preconditioner_bytes(grid, starved: bool = False) -> int:
    """Bytes [B] of the column preconditioner's stored inverses on the half-domain grid (nx, ny):
    ny dense float64 blocks of (nx − 2)² ((nx − 1)² starved, with the meniscus row), the part of
    the solve's memory that grows as nx²·ny (the films, FFTs and Krylov vectors grow as nx·ny)."""
    nx, ny = (int(n) for n in grid)
    size = nx - 1 if starved else nx - 2
    return 8 * ny * size * size


class Stage(eqx.Module):
    """The equations a starved level solves at one stage of `solve_nested` (the `args` of its
    residual and preconditioner): with `held`, each meniscus row X_m − X_m,now (the menisci held
    where the unknowns have them); the oil layer H_oil multiplied by `supply_factor` [-]."""

    held: jax.Array
    supply_factor: jax.Array


class UniformLevel:
    """One grid of the nested iteration: its columns (ColumnGrid), FFT spectrum, rigid film and
    the elastic coefficients the preconditioner reads. Dimensionless, Hertz half-width units:
    nx nodes on X ∈ [INLET, OUTLET] by ny uniform cells on Y ∈ [0, half_length], the rigid film
    X²/2 + rigid_axial(Y), ∬P dX dY = load_target over the whole contact, H_oil = supply (None:
    flooded); largest_step = (ΔP, ΔH₀) bounds each Newton step (None: only the menisci's)."""

    def __init__(self, nx, ny, half_length, rigid_axial, fluid, supply, side_inflow, load_target, largest_step=None):
        self.nx, self.ny = nx, ny
        x = np.linspace(INLET, OUTLET, nx)
        self.spacing = x[1] - x[0]
        self.centre = int(np.argmin(np.abs(x)))  # the node at x = 0
        edges = axial_cells(ny, 0.0, half_length, 0.0)
        self.cell = half_length / ny
        y = 0.5 * (edges[1:] + edges[:-1])
        self.columns = ColumnGrid(jnp.asarray(x), self.spacing, y, edges, jnp.diff(edges), fluid, supply, side_inflow)
        self.spectrum = coefficient_spectrum(
            influence_coefficients(nx, 2 * ny, self.spacing, self.cell, DIMENSIONLESS_MODULUS))
        self.rigid = 0.5 * jnp.asarray(x)[:, None] ** 2 + rigid_axial(y)[None, :]
        self.load_target = load_target
        self.largest_step = largest_step
        self.starved = supply is not None
        self.interior = (nx - 2) * ny
        offsets = np.arange(-(nx - 1), nx)[:, None] * self.spacing  # node offset, then cell offset −1 … 2ny
        cells = np.arange(-1, 2 * ny + 1)[None, :] * self.cell
        self.coefficients = love_rectangle(jnp.asarray(offsets), jnp.asarray(cells), 0.5 * self.spacing,
                                           0.5 * self.cell) / (2 * np.pi)

    def limit(self, step, unknowns=None):
        """`step` (from `unknowns`) shortened so that no meniscus moves more than a cell (as the
        dense Newton) and, with `largest_step` = (ΔP, ΔH₀), no pressure and offset more than those."""
        ratio = 1.0
        if self.starved:
            ratio = jnp.abs(step[self.interior + 1:]).max() / self.spacing
        if self.largest_step is not None:
            pressure_step, offset_step = self.largest_step
            ratio = jnp.maximum(ratio, jnp.maximum(jnp.abs(step[:self.interior]).max() / pressure_step,
                                                   jnp.abs(step[self.interior]) / offset_step))
        return step / jnp.maximum(ratio, 1.0)

    def staged(self, stage):
        """The columns with the oil layer of `stage` (a Stage or None: the level's own)."""
        if stage is None:
            return self.columns
        return eqx.tree_at(lambda columns: columns.supply, self.columns, self.columns.supply * stage.supply_factor)

    def flux_ratio(self, unknowns):
        """[-] The median over the columns with a meniscus inside the grid of the flux each carries
        over the supply, 1 − F_m (the meniscus equation is −(flux/H_oil − 1) away from its bounds)."""
        _, _, meniscus = self.unpack(unknowns)
        inside = (meniscus > INLET + self.spacing) & (meniscus < OUTLET - self.spacing)
        ratio = 1.0 - self.residual(unknowns)[self.interior + 1:]
        return jnp.where(inside.any(), jnp.nanmedian(jnp.where(inside, ratio, jnp.nan)), 1.0)

    def elastic(self, pressure):
        """H_el (nx, ny) of P (nx, ny) on y ≥ 0 and its mirror image."""
        whole = jnp.concatenate([pressure[:, ::-1], pressure], axis=1)
        shape = (2 * self.nx, 4 * self.ny)
        spectrum = jnp.fft.rfft2(whole, s=shape)
        return jnp.fft.irfft2(self.spectrum * spectrum, s=shape)[:self.nx, self.ny:2 * self.ny]

    def film(self, pressure, offset):
        return offset + self.rigid + self.elastic(pressure)

    def unpack(self, unknowns):
        pressure = jnp.pad(unknowns[:self.interior].reshape(self.nx - 2, self.ny), ((1, 1), (0, 0)))
        meniscus = unknowns[self.interior + 1:] if self.starved else jnp.full(self.ny, INLET)
        return pressure, unknowns[self.interior], meniscus

    def row_scale(self, unknowns):
        """(nx − 2, ny) [-]: 1 + |∂L/∂P| of each Reynolds row at its own node from the Poiseuille
        terms, (ε_{i−½} + ε_{i+½})/ΔX + ΔX (ε_{j−½}/ΔY_{j−½} + ε_{j+½}/ΔY_{j+½})/w_j with |ε| (a
        start's film may be negative) (`local_equations`: L is the Reynolds residual × ΔX)."""
        pressure, offset, _ = self.unpack(unknowns)
        flow = jnp.abs(reynolds_coefficients(pressure, self.film(pressure, offset), self.columns.fluid)[1])
        along_x = 0.5 * (flow[2:] + 2.0 * flow[1:-1] + flow[:-2]) / self.spacing
        faces = 0.5 * (flow[:, 1:] + flow[:, :-1]) / jnp.diff(self.columns.y)  # no flux at y = 0; p = 0 at the end
        end = flow[:, -1:] / (self.columns.edges[-1] - self.columns.y[-1])
        across = (jnp.pad(faces, ((0, 0), (1, 0))) + jnp.concatenate([faces, end], axis=1)) / self.columns.widths
        return 1.0 + along_x + self.spacing * across[1:-1]

    def residual_scale(self, unknowns):
        """The size of each equation [-]: `row_scale` for the Reynolds rows, 1 for the load balance
        and the menisci. F/s is the pressure change (in p_h) a Reynolds row asks of its own node:
        unscaled, rows in the inlet and at the crowned ends, where ε ∝ H³ is large, keep O(1)
        residuals for pressures below 1e-10 p_h and rule the merit of the line search."""
        rest = jnp.ones(unknowns.shape[0] - self.interior)
        return jnp.concatenate([self.row_scale(unknowns).reshape(-1), rest])

    def solution(self, unknowns, tolerance):
        """(P, H, X_m, max|F/s| (`residual_scale`), converged) of `unknowns`: converged where that
        is below `tolerance` and the film is positive."""
        fixed = jax.lax.stop_gradient
        error = jnp.max(jnp.abs(self.residual(fixed(unknowns)) / self.residual_scale(fixed(unknowns))))
        pressure, offset, meniscus = self.unpack(unknowns)
        film = self.film(pressure, offset)
        return pressure, film, meniscus, error, (error < tolerance) & (jnp.min(fixed(film)) > 0)

    def balance(self, pressure):
        return (2.0 * self.spacing * jnp.sum(pressure * self.columns.widths) - self.load_target) / self.load_target \
            * 0.5 * np.pi

    def residual(self, unknowns, stage=None):
        """Reynolds complementarity (row-major), load balance, (starved) menisci: the dense
        solver's order; starved, the equations of `stage` (a Stage; None: the level's own)."""
        pressure, offset, meniscus = self.unpack(unknowns)
        local = local_equations(pressure, self.film(pressure, offset), meniscus, self.staged(stage))
        result = jnp.append(local[:self.nx - 2].reshape(-1), self.balance(pressure))
        if not self.starved:
            return result
        menisci = local[self.nx - 2]
        if stage is not None:
            menisci = jnp.where(stage.held, meniscus - jax.lax.stop_gradient(meniscus), menisci)
        return jnp.concatenate([result, menisci])

    def preconditioner(self, unknowns, stage=None):
        """v ↦ M⁻¹v: the column blocks of J at `unknowns` (of the equations of `stage`), bordered
        by H₀ and the load balance (module docstring)."""
        pressure, offset, meniscus = self.unpack(jax.lax.stop_gradient(unknowns))
        columns = self.staged(stage)

        def local(interior, film, menisci):
            return local_equations(jnp.pad(interior, ((1, 1), (0, 0))), film, menisci, columns)

        return self.column_preconditioner(local, pressure[1:-1], self.film(pressure, offset), meniscus,
                                          jnp.ones_like(pressure[1:-1]), False if stage is None else stage.held)

    def column_preconditioner(self, local, interior, height, meniscus, pressure_slope, held):
        """v ↦ M⁻¹v (module docstring) of the equations `local(interior, film, meniscus)` → (R, ny)
        (`local_equations`' rows and reads), the unknowns `interior` (nx − 2, ny) at the interior
        nodes with ∂P/∂unknown = `pressure_slope` (nx − 2, ny) (1 where they are the pressures),
        the film `height` (nx, ny), H₀ and the load balance; starved, the menisci (held: their
        rows X_m − X_m,now)."""
        nx, ny = self.nx, self.ny
        rows = nx - 2
        size = rows + 1 if self.starved else rows  # unknowns of a column: its interior ones (and meniscus)
        _, linear = jax.linearize(local, interior, height, meniscus)
        zero_p, zero_h, zero_m = jnp.zeros_like(interior), jnp.zeros_like(height), jnp.zeros_like(meniscus)
        column = jnp.arange(ny)

        def colors(count):  # [c] → the tangent on nodes i ≡ c_x (mod BAND) of columns j ≡ c_y (mod 3)
            node = jnp.arange(count)
            return jnp.stack([((node[:, None] % BAND == cx) & (column[None, :] % 3 == cy)).astype(float)
                              for cx in range(BAND) for cy in range(3)])

        by_pressure = jax.vmap(lambda t: linear(t, zero_h, zero_m))(colors(rows))  # [color, r, j]
        by_height = jax.vmap(lambda t: linear(zero_p, t, zero_m))(colors(nx))
        by_offset = linear(zero_p, jnp.ones_like(height), zero_m)
        equation = jnp.arange(rows)
        target = equation + 1  # the node of each interior unknown
        node = jnp.arange(nx)
        if self.starved:
            by_meniscus = linear(zero_p, zero_h, jnp.ones_like(meniscus))  # a column's rows read its own meniscus
            _, pull = jax.vjp(local, interior, height, meniscus)

            def meniscus_rows(c):  # cotangent on the meniscus rows of the columns of class c
                return pull(jnp.zeros((rows + 1, ny)).at[rows].set((column % 3 == c).astype(float)))[:2]

            by_row = [meniscus_rows(c) for c in range(3)]
            meniscus_by_pressure = jnp.stack([by_row[c][0] for c in range(3)])  # [c, r, j]
            meniscus_by_height = jnp.stack([by_row[c][1] for c in range(3)])  # [c, node, j]

        def elastic(shift, j, rows_from, nodes_to):
            """∂H[rows_from, j + shift]/∂P[nodes_to, j] (len(rows_from), len(nodes_to)): the cell of
            column j and its mirror image (the cells between y_{j+shift} and −y_j)."""
            mirror = jnp.clip(2 * j + shift + 1, -1, 2 * ny)
            offset = rows_from[:, None] - nodes_to[None, :] + nx - 1
            return self.coefficients[offset, shift + 1] + self.coefficients[offset, mirror + 1]

        def column_block(j):
            """(M_j⁻¹ (size, size), M_j⁻¹ ∂F_j/∂H₀) of column j: its exact Jacobian block."""
            block = jnp.zeros((size, size))
            for shift in (-2, -1, 0, 1):  # ∂(Reynolds r, j)/∂P[r + shift, j]
                a = equation + shift
                inside = (a >= 0) & (a < rows)
                block = block.at[equation, jnp.clip(a, 0, rows - 1)].add(
                    by_pressure[(a % BAND) * 3 + j % 3, equation, j] * inside)
            for shift in (-1, 0, 1):  # Σ_d ∂(Reynolds r, j)/∂H[r + 1 + d, j + shift] · ∂H[r + 1 + d, j + shift]/∂P[a, j]
                neighbour = j + shift
                inside = (neighbour >= 0) & (neighbour < ny)
                for d in READ_BAND:
                    reads = (equation + 1 + d >= 0) & (equation + 1 + d < nx)
                    band = reads * inside * by_height[((equation + 1 + d) % BAND) * 3 + jnp.clip(neighbour, 0, ny - 1) % 3,
                                                      equation, j]
                    block = block.at[:rows, :rows].add(band[:, None] * elastic(shift, j, equation + 1 + d, target)
                                                       * pressure_slope[None, :, j])
            offset_column = by_offset[:rows, j]
            if self.starved:
                block = block.at[:rows, rows].set(by_meniscus[:rows, j])
                meniscus_row = meniscus_by_pressure[j % 3, :, j]
                for shift in (-1, 0, 1):  # the meniscus row reads the whole film of its column and its neighbours'
                    neighbour = j + shift
                    inside = (neighbour >= 0) & (neighbour < ny)
                    sensitivity = meniscus_by_height[j % 3, :, jnp.clip(neighbour, 0, ny - 1)]
                    meniscus_row = meniscus_row + inside * sensitivity @ elastic(shift, j, node, target) \
                        * pressure_slope[:, j]
                # held, the meniscus row is X_m − X_m,now
                unit = jnp.zeros(size).at[rows].set(1.0)
                block = block.at[rows].set(jnp.where(held, unit, jnp.append(meniscus_row, by_meniscus[rows, j])))
                offset_column = jnp.append(offset_column, jnp.where(held, 0.0, by_offset[rows, j]))
            inverse = jnp.linalg.inv(block)
            return inverse, inverse @ offset_column

        inverse, offset_response = jax.lax.map(column_block, column, batch_size=COLUMN_BATCH)
        balance_row = jnp.zeros((ny, size)).at[:, :rows].set(
            (2.0 * self.spacing * self.columns.widths / self.load_target * 0.5 * np.pi)[:, None] * pressure_slope.T)
        schur = jnp.sum(balance_row * offset_response)

        def to_columns(vector):
            by_column = vector[:self.interior].reshape(rows, ny).T
            if self.starved:
                by_column = jnp.concatenate([by_column, vector[self.interior + 1:][:, None]], axis=1)
            return by_column, vector[self.interior]

        def from_columns(by_column, scalar):
            flat = jnp.append(by_column[:, :rows].T.reshape(-1), scalar)
            return jnp.concatenate([flat, by_column[:, rows]]) if self.starved else flat

        def apply(vector):
            by_column, balance_residual = to_columns(vector)
            response = jnp.einsum("jab,jb->ja", inverse, by_column)
            correction = (jnp.sum(balance_row * response) - balance_residual) / schur
            return from_columns(response - offset_response * correction, correction)

        return apply


def interpolate_level(unknowns, coarse: UniformLevel, fine: UniformLevel):
    """Unknowns of `coarse` on `fine`: P bilinear (p = 0 at the roller end; wet only where every
    coarse node around is), H₀ kept, menisci linear along y, moved upstream of where the fine
    column's gap closes below the oil layer."""
    pressure, offset, meniscus = coarse.unpack(unknowns)
    y_coarse = jnp.append(coarse.columns.y, coarse.columns.edges[-1])

    def bilinear(values):
        values = jnp.concatenate([values, jnp.zeros((coarse.nx, 1))], axis=1)
        along_y = jax.vmap(lambda row: jnp.interp(fine.columns.y, y_coarse, row))(values)
        return jax.vmap(lambda col: jnp.interp(fine.columns.x, coarse.columns.x, col), in_axes=1, out_axes=1)(along_y)

    wet = bilinear((pressure > 0).astype(float)) > 1.0 - 1e-9
    fine_pressure = jnp.where(wet, bilinear(pressure), 0.0)
    result = jnp.append(fine_pressure[1:-1].reshape(-1), offset)
    if not fine.starved:
        return result
    # a meniscus lies upstream of where its column's gap first closes below the oil layer (a cell
    # upstream); where it never closes, no full film forms (at its pressure peak the film would carry
    # ρ̄h > h_oil): the meniscus is the highest. The fine grid's end columns close where the coarse
    # ones they come from did not, and the other way round.
    highest = OUTLET - 0.5 * fine.spacing
    closes = fine.film(fine_pressure, offset) <= fine.columns.supply
    closure = fine.columns.x[jnp.argmax(closes, axis=0)] - fine.spacing
    menisci = jnp.interp(fine.columns.y, coarse.columns.y, meniscus)
    menisci = jnp.where(closes.any(axis=0), jnp.minimum(menisci, closure), highest)
    return jnp.concatenate([result, jnp.clip(menisci, INLET, highest)])


def solve_nested(level_at, arguments, levels, start, tolerance, coarsest_steps=None, forcing=FORCING_LARGEST,
                 restart=30, start_anew=False):
    """(the finest UniformLevel built from the live `arguments`, its solution with implicit
    derivatives, (the next coarser level, its solution without derivatives) or None where there
    is one level): `start(coarsest level)` → unknowns there, solved by Newton–Krylov in at most
    `coarsest_steps` (None: taken as solved), then interpolated to each finer level and solved
    again in at most NEWTON_STEPS (starved: after the held menisci and the supply continuation of
    the module docstring); no derivative flows through the iterations. With `start_anew`, a
    finer level whose coarser solution did not converge to a positive film starts from
    `start(level)` instead of it (a coarse grid too coarse for a thin film: its discrete film
    closes, h < 0, and no finer grid recovers from that start). The loosest linear solve
    is `forcing` on flooded levels and STARVED_FORCING on starved ones; `restart` is GMRES's
    Krylov dimension. `level_at(*arguments)` → a function (nx, ny) → UniformLevel."""
    solving = level_at(*jax.lax.stop_gradient(arguments))

    def solve(level, unknowns, steps, stage=None):
        return newton_krylov(level.residual, unknowns, stage, level.preconditioner, tolerance=tolerance,
                             max_steps=steps, limit=level.limit, scale=level.residual_scale,
                             loosest=STARVED_FORCING if level.starved else forcing, restart=restart)[0]

    def solve_finer(level, unknowns):
        """Starved: the pressure and H₀ first with the menisci held; then the supply continued
        from the one that the flux of that solution carries (`UniformLevel.flux_ratio`) to the oil
        layer's, each stage's change of ln H_oil doubled where it converges and halved where not;
        last, the level's own equations. One Newton–Krylov is traced for all of them: the stage
        is its argument (`Stage`)."""
        if not level.starved:
            return solve(level, unknowns, NEWTON_STEPS)
        holding, continuing, finishing, done = 0, 1, 2, 3

        def continues(factor, stride, count):
            return (factor != 1.0) & (stride >= SUPPLY_SMALLEST_STAGE) & (count < SUPPLY_STAGES)

        def step(state):
            unknowns, factor, stride, count, phase = state
            target = jnp.where(phase == continuing, factor * jnp.exp(-jnp.clip(jnp.log(factor), -stride, stride)), 1.0)
            steps = jnp.select([phase == holding, phase == continuing], [HELD_MENISCUS_STEPS, SUPPLY_STAGE_STEPS],
                               NEWTON_STEPS)
            stage = Stage(phase == holding, target)
            trial = solve(level, unknowns, steps, stage)
            error = jnp.max(jnp.abs(level.residual(trial, stage) / level.residual_scale(trial)))
            accepted = (phase != continuing) | (error <= tolerance)
            ratio = level.flux_ratio(trial)  # after the held stage, where the continuation starts
            factor = jnp.select([phase == holding, accepted], [ratio, target], factor)
            stride = jnp.select([phase == holding, accepted], [jnp.abs(jnp.log(ratio)), 2.0 * stride], 0.5 * stride)
            count = jnp.where(phase == continuing, count + 1, count)
            phase = jnp.where(phase == finishing, done,
                              jnp.where(continues(factor, stride, count), continuing, finishing))
            return jnp.where(accepted, trial, unknowns), factor, stride, count, phase

        state = (unknowns, jnp.asarray(1.0), jnp.asarray(0.0), jnp.asarray(0), jnp.asarray(holding))
        return jax.lax.while_loop(lambda state: state[-1] != done, step, state)[0]

    previous = solving(*levels[0])
    unknowns = start(previous)
    if coarsest_steps is not None:
        unknowns = solve(previous, unknowns, coarsest_steps)
    coarser = None
    for nx, ny in levels[1:]:
        coarser = (previous, unknowns)
        current = solving(nx, ny)
        carried = interpolate_level(unknowns, previous, current)
        if start_anew:
            carried = jnp.where(previous.solution(unknowns, tolerance)[-1], carried, start(current))
        unknowns = solve_finer(current, carried)
        previous = current
    finest = level_at(*arguments)(*levels[-1])
    root = krylov_root(finest.residual, unknowns, None, previous.preconditioner(unknowns), restart=restart)
    return finest, root, coarser
