"""Numerical EHL of a finite line contact (roller on raceway, 2-D), flooded or starved, by Newton.

The starved-EHL paper (Bai & Liu, 2013; docs/theory.md §Finite line EHL): the gap
h = h₀ + x²/2R + g(y) + v(x, y) with g the roller's axial profile drop and v the elastic
deflection of both half-spaces; isothermal Newtonian Reynolds

    ∂X(ε ∂X P) + ∂Y(ε ∂Y P) − ∂X(ρ̄H) = 0,   ε = ρ̄H³/(η̄λ),

in the dimensionless variables of `line_ehl` (X = x/b, Y = y/b, P = p/p_h, H = hR/b², b and p_h
of the Hertz line contact under the load per flat length). Deflection: Love's rectangle
coefficients (`influence.love_rectangle`), H_el = (1/2π) Σ P_j C_ij, each cell mirrored at Y = 0.
Load balance over the whole roller, ∬P dX dY = (π/2) l/b.

Grid: half domain by symmetry. X ∈ [−4.5, 1.5] on nx uniform nodes (as `line_ehl`); Y
cell-centred on ny cells, a quarter of them uniform over the middle of the roller and the rest
uniform over the last 10 % of the flat and the crowned end, where the pressure spike and the end
constriction of the film sit; or, with `axial_clustering`, clustered there by one smooth map
(`axial_cells`), which resolves the end minimum with fewer cells but is not yet the default (the
starved Newton near the flooded limit fails on it). Symmetry (no flux) at Y = 0, p = 0 at the
roller end.
Cavitation: the Fischer–Burmeister complementarity of `line_ehl`, node by node.

Starvation (docs/theory.md §Starvation and §Numerical notes): the mass-conserving θ-model
written with its free boundary explicit. Each y cell has an inlet meniscus X_m,j (an unknown); upstream the oil layer rides on
the surfaces (θh = h_oil, p = 0), downstream the film is full, and across the meniscus the mass
flux is continuous: ρ̄h − (ρh³/12ηu) ∂p/∂x = h_oil. The meniscus cuts the grid between nodes; the
discrete equations are made continuous in its position (`reynolds_from_meniscus`), and it is
bounded to [inlet, outlet − Δ/2] by a box complementarity: at the inlet the column is flooded, at
the upper bound no full film forms (the crowned ends, where the gap exceeds the oil layer).

Solver: Newton with a dense Jacobian, assembled as J = ∂F/∂u|_H + (∂F/∂H)·K from colored
forward derivatives of the column-local equations and the influence matrix K
(`local_and_elastic_jacobian`; a forward pass per unknown through K would cost (nx·ny)³ and
was 3× slower on 65 × 65); `newton` with Armijo backtracking and a Levenberg–Marquardt fallback
where the piecewise smooth equations stall it, the meniscus moving at most a cell per step, each
step's LU in float32 refined in float64 (`newton.refined_solve`),
stopping once ‖F‖₂ ≤ `tolerance` (below it a step lowers round-off only); from the 1-D line
solution (starved alike) extruded along the flat. Where that Newton fails on a flooded grid of 65
nodes or more along rolling, Newton again from the solution on the grid of half the nodes (same
cells along the roller), interpolated along x: the starved-EHL paper's roller with its raceway edge,
flooded on 65 × 65, stalls from the 1-D start at 1607 and 2471 N (scaled residual 2.4 at
1607 N, and through the load stages below) and converges from 33 × 65's solution. Where that
fails too (the paper's roller starved at 0.8 µm: 2471 N on 33 × 48, where it stalls with
h < 0 at the end constriction; at h_oil = 1.8 µm, 1028 N, 33 × 48), a load continuation: Newton
again at 65, 80, 90 and 100 % of the load (`LOAD_PATH`), the first stage from the 1-D start at its load, each next
from the previous solution. Starved, each stage first solves for the pressure and H₀ with the
menisci held (Newton without the fallback, `HELD_MENISCUS_STEPS`), then releases them: from a
start's pressure the flux through the columns is off, and menisci that move with it can end
where Newton stalls (1.8 µm converged only with the held menisci). The dimensionless grid stays
the full load's. Inside `newton.implicit_root`, so the derivatives are implicit (checked against
central differences on 17 × 16 flooded and 25 × 16 starved). Dense means (nx−2)·ny ≤ MAX_UNKNOWNS
= 4200 on the half domain (65 × 65: one float32 LU about 0.35 s on 2 cores); measured times and films in
`benchmarks/finite_line_ehl.py`. A scene's
`fidelity.grid = [nx, ny]` counts ny cells along the whole roller, of which the ⌈ny/2⌉ on y ≥ 0
are solved (`half_domain_grid`). The discrete problem is not always unique at the roller end:
1607 N on 65 × 65 converges to a minimum film of 0.273 µm through `LOAD_PATH` and, in a scratch
copy of this solver, to 0.230 µm through the stages (0.5, 0.7, 0.85, 1) (one meniscus per y cell
is a simplification of the θ-model's partial film there). On cells clustered at the flat's end
the same case has one resolved minimum, 0.281 µm on 33 × 48 and 33 × 64, 0.283 µm on 65 × 48.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..bearings.roller.roller_profile import RollerProfile, crown_drop
from ..contact.hertz import line_contact
from ..contact.influence import love_rectangle
from ..newton import implicit_root, newton
from ..numerics import require_float64
from .line_ehl import INLET, OUTLET, FluidParameters, fischer_burmeister, line_film, reynolds_coefficients

MAX_UNKNOWNS = 4200  # 65 × 65 on the half domain: about 0.35 s per float32 LU on 2 cores
HELD_MENISCUS_STEPS = 30  # starved load stages: Newton steps on pressure and H₀ with the menisci held
NEWTON_STEPS = 60  # per load stage; the starved-EHL paper's roller at 1607 N starved needs 31–60 (short L–M steps)
SHORTEST_STEP = 1e-4  # the shortest step length the backtracking tries
LOAD_PATH = (0.65, 0.8, 0.9, 1.0)  # the load continuation's stages, fractions of the load
COARSE_START_NODES = 33  # the fewest nodes along rolling of the coarse-grid start's grid: the Newton–Krylov's coarsest
FINE_START = 0.9  # the fine cells start at this fraction of the flat half-length


class FiniteLineFilm(eqx.Module):
    """Solution [SI] on the half domain y ≥ 0: x [m] (nx), y [m] cell centres (ny), pressure [Pa]
    and film [m] (nx, ny), central film at x = 0 on y = 0 [m], minimum film [m] and its y [m],
    whether Newton converged (residual below the tolerance, positive film), that residual [-],
    the inlet meniscus x_m [m] of each y cell (the domain inlet when flooded)."""

    x: jax.Array
    y: jax.Array
    pressure: jax.Array
    thickness: jax.Array
    central: jax.Array
    minimum: jax.Array
    minimum_position: jax.Array
    converged: jax.Array
    residual: jax.Array
    meniscus: jax.Array


def axial_cells(count: int, flat_end, roller_end, clustering: float | None = None):
    """Cell edges [m] on [0, roller_end].

    clustering None (the default): a quarter of the cells uniform over [0, FINE_START·flat_end],
    the rest uniform over the fine zone from there to the roller end.

    clustering 0: uniform cells (the matrix-free solver's, whose deflection is an FFT convolution).

    clustering β > 0: one smooth map for every count, the cells clustered at the flat's end
    y = f (`flat_end`), where the profile's curvature jumps and the end constriction of the film
    sits: uniform η ∈ [0, 1] mapped by y = f[1 + sinh(β(η − B))/sinh(βB)], with
    B = ln[(1 + (e^β − 1) f/e)/(1 + (e^−β − 1) f/e)]/(2β) so that y(1) = e (`roller_end`)
    (Farrashkhalvat & Miles, Basic Structured Grid Generation, 2003, eqs. 4.90–4.91). The
    starved-EHL paper's roller (f = 6.35, e = 7.35 mm) with β = 8 on 64 cells: 0.012 mm at the
    flat's end, 0.75 mm at mid-length, neighbours within 13 %. Measured against the default in
    `benchmarks/finite_line_grid.py`."""
    if clustering is None:
        coarse = max(count // 4, 1)
        split = FINE_START * flat_end
        return jnp.concatenate([jnp.linspace(0.0, split, coarse + 1),
                                jnp.linspace(split, roller_end, count - coarse + 1)[1:]])
    if clustering == 0:
        return jnp.linspace(0.0, roller_end, count + 1)
    ratio = flat_end / roller_end
    shift = jnp.log((1.0 + np.expm1(clustering) * ratio) / (1.0 + np.expm1(-clustering) * ratio)) / (2.0 * clustering)
    eta = jnp.linspace(0.0, 1.0, count + 1)
    return flat_end * (1.0 + jnp.sinh(clustering * (eta - shift)) / jnp.sinh(clustering * shift))


def check_grid(grid) -> tuple[int, int]:
    """(nx, ny) of the half domain; ValueError unless the dense Newton takes it: nx ≥ 17 nodes
    along rolling, ny ≥ 8 cells on y ≥ 0, (nx − 2)·ny ≤ MAX_UNKNOWNS."""
    nx, ny = (int(n) for n in grid)
    if nx < 17 or ny < 8 or (nx - 2) * ny > MAX_UNKNOWNS:
        raise ValueError(f"grid: the finite-line EHL (dense Newton, half domain) needs nx ≥ 17, ny ≥ 8 and "
                         f"(nx − 2)·ny ≤ {MAX_UNKNOWNS}, got {[nx, ny]} ((nx − 2)·ny = {(nx - 2) * ny})")
    return nx, ny


def half_domain_grid(grid) -> tuple[int, int]:
    """(nx, ⌈ny/2⌉): a grid of nx nodes along rolling by ny cells along the whole roller length
    (a scene's `fidelity.grid`), solved on the half y ≥ 0 by symmetry; ValueError, naming
    `fidelity.grid`, unless the half fits the dense Newton (`check_grid`)."""
    nx, ny = (int(n) for n in grid)
    half = (ny + 1) // 2
    try:
        return check_grid((nx, half))
    except ValueError:
        raise ValueError(f"fidelity.grid = [nx, ny] (nodes along rolling, cells along the whole roller; half solved "
                         f"by symmetry): the finite-line EHL (dense Newton) needs nx ≥ 17, ny ≥ 15 and "
                         f"(nx − 2)·⌈ny/2⌉ ≤ {MAX_UNKNOWNS}, got {[nx, ny]} ((nx − 2)·⌈ny/2⌉ = {(nx - 2) * half}); "
                         f"e.g. [65, 129]") from None


def _box_complementarity(position, lower, upper, excess):
    """Zero exactly when lower ≤ position ≤ upper with excess = 0 inside, excess ≤ 0 at the lower
    bound and excess ≥ 0 at the upper one (Billups' nesting of Fischer–Burmeister functions,
    φ(a, b) = a + b − √(a² + b²) = `fischer_burmeister(a, −b)`)."""
    return fischer_burmeister(position - lower, fischer_burmeister(upper - position, -excess))


def reynolds_from_meniscus(pressure, mass, flow, dry_flow, transverse, spacing, cells_from_meniscus, meniscus_mass,
                           meniscus_flow):
    """Reynolds residual L [-] (×Δ, axis 0 the rolling direction) at the interior nodes when the
    pressure starts at an inlet meniscus inside the grid, column by column, written so that it is
    continuous in the meniscus position (a Newton line search needs that):

    - the first wet node k, s_k ∈ (0, 1] cells past the meniscus, takes its upstream face at the
      meniscus (P = 0, ε and ρ̄H of the gap there) and its wedge term first order; its equation
      is multiplied by s_k, so that as s_k → 0 it tends to −ε_face P_k/Δ;
    - the dry nodes upstream take exactly that, −ε_face P/Δ: with Fischer–Burmeister, P = 0;
    - the next node blends the wedge term from first to second order as s goes from 1 to 2.

    With the meniscus on the inlet node this is (`line_ehl.rolling_terms` + transverse) × Δ.
    `flow` is ε at the nodes, `dry_flow` ε of the gap at zero pressure, `transverse` the
    ∂Y(ε ∂Y P) terms at the interior nodes."""
    s = cells_from_meniscus[1:-1]
    first = (s > 0) & (s <= 1)
    s_first = jnp.where(first, s, 1.0)
    face_down = 0.5 * (flow[2:] + flow[1:-1])
    face_up = jnp.where(first, 0.5 * (meniscus_flow + flow[1:-1]), 0.5 * (flow[1:-1] + flow[:-2]))
    gradient_up = jnp.where(first, pressure[1:-1] / s_first, pressure[1:-1] - pressure[:-2]) / spacing
    poiseuille = face_down * (pressure[2:] - pressure[1:-1]) / spacing - face_up * gradient_up
    mass_up = jnp.where(first, meniscus_mass, mass[:-2])
    curvature = mass[1:-1] - 2.0 * mass[:-2] + jnp.concatenate([mass[:1], mass[:-3]])  # row 1 has weight 0
    blend = jnp.clip(s - 1.0, 0.0, 1.0).at[0].set(0.0)
    wet = poiseuille - (mass[1:-1] - mass_up) - blend * curvature / 2 + transverse * spacing
    dry = -0.5 * (dry_flow[1:-1] + flow[1:-1]) * pressure[1:-1] / spacing
    return jnp.where(s > 1, wet, jnp.where(first, s_first * wet, dry))


class ColumnGrid(eqx.Module):
    """What the column-local equations read (dimensionless, Hertz half-width units): nodes x
    (nx) along rolling and their spacing, cell centres y (ny), edges (ny + 1) and widths (ny)
    along the half roller, the fluid, the oil supply H_oil (None: flooded) and the fraction of
    the side inflow in the meniscus balance."""

    x: jax.Array
    spacing: float
    y: jax.Array
    edges: jax.Array
    widths: jax.Array
    fluid: FluidParameters
    supply: jax.Array | None
    side_inflow: float = eqx.field(static=True)


def transverse_terms(pressure, flow, columns: ColumnGrid):
    """∂Y(ε ∂Y P) [-] (nx, ny) at every node by finite volumes across the cells: no flux at y = 0
    (symmetry), P = 0 at the far edge (the roller end, or the side of a point contact's domain)."""
    y, edges = columns.y, columns.edges
    flux = 0.5 * (flow[:, 1:] + flow[:, :-1]) * (pressure[:, 1:] - pressure[:, :-1]) / jnp.diff(y)
    end = -flow[:, -1:] * pressure[:, -1:] / (edges[-1] - y[-1])
    flux = jnp.concatenate([jnp.zeros_like(end), flux, end], axis=1)
    return (flux[:, 1:] - flux[:, :-1]) / columns.widths


def local_equations(pressure, height, meniscus, columns: ColumnGrid):
    """The column-local equations [-], (R, ny) with R = nx − 2 (+ 1 when starved): the Reynolds
    complementarity of each interior node, then the meniscus equation of each column (docstring
    of `finite_line_film`). The equations of column j read the pressure P (nx, ny) and film H
    (nx, ny) of columns j − 1, j, j + 1 and the meniscus X_m,j (ny) of column j alone; along x,
    a Reynolds row at node i reads nodes i − 2 … i + 1, a meniscus row its whole column."""
    x, spacing = columns.x, columns.spacing
    fluid, supply, side_inflow = columns.fluid, columns.supply, columns.side_inflow
    nx, ny = pressure.shape
    highest_meniscus = OUTLET - 0.5 * spacing
    density, flow = reynolds_coefficients(pressure, height, fluid)
    # the meniscus of each column: cells from it to each node, the gap and ε there (p = 0)
    cells = (x[:, None] - jnp.clip(meniscus, INLET, highest_meniscus)[None, :]) / spacing
    first = (cells[1:] > 0) & (cells[1:] <= 1)
    meniscus_height = jnp.sum(jnp.where(first, cells[1:] * height[:-1] + (1 - cells[1:]) * height[1:], 0.0),
                              axis=0)
    meniscus_flow = reynolds_coefficients(jnp.zeros(ny), meniscus_height, fluid)[1]
    poiseuille_y = transverse_terms(pressure, flow, columns)
    dry_flow = reynolds_coefficients(jnp.zeros_like(height), height, fluid)[1]
    reynolds = reynolds_from_meniscus(pressure, density * height, flow, dry_flow, poiseuille_y[1:-1], spacing,
                                      cells, meniscus_height, meniscus_flow)
    complementarity = fischer_burmeister(pressure[1:-1], reynolds)
    if supply is None:
        return complementarity
    # mass across the meniscus: ρ̄H − ε ∂P/∂X of the full film = H_oil, taken where the
    # wedge term is in flux form (second-order upwind face values (3m_i − m_{i−1})/2), on
    # the faces k + 3/2 and k + 5/2 after the first wet node k, weighted s_k and 1 − s_k so
    # that it is continuous as the meniscus crosses a node
    mass = density * height
    upwind = 0.5 * (3.0 * mass[:-1] - jnp.concatenate([mass[:1], mass[:-2]]))
    face_flux = upwind - 0.5 * (flow[1:] + flow[:-1]) * jnp.diff(pressure, axis=0) / spacing
    face_flux = jnp.concatenate([face_flux, jnp.repeat(height[-1:], 3, axis=0)])  # past the outlet: the gap
    flux = jnp.sum(jnp.where(first, cells[1:] * face_flux[2:-1] + (1 - cells[1:]) * face_flux[3:], 0.0), axis=0)
    if side_inflow:  # the side inflow up to those faces (docstring)
        flux = flux - side_inflow * spacing * jnp.sum(jnp.clip(3.0 - cells, 0.0, 1.0) * poiseuille_y, axis=0)
    meniscus_equation = _box_complementarity(meniscus, INLET, highest_meniscus, flux / supply - 1.0)
    return jnp.concatenate([complementarity, meniscus_equation[None, :]])


def local_and_elastic_jacobian(local, interior, height, meniscus, influence):
    """Jacobian [-] of column-local equations under elastic coupling, by coloring.

    `local(interior, height, meniscus)` → (R, ny): the equations of column j depend on the
    interior pressure P (nx − 2, ny) and the film H (nx, ny) of columns j − 1, j, j + 1 only, and
    on the meniscus of column j; along x, the Reynolds row r (node r + 1) reads H at the nodes
    r − 1 … r + 2 (`local_equations`), a meniscus row (r = nx − 2, starved) its whole column;
    H = H₀ + K·P with `influence` K = ∂H/∂P (nx, ny, nx − 2, ny), dense. Forward derivatives with
    one tangent per x row and per column class j mod 3 (Curtis–Powell–Reid coloring) give ∂F/∂P|_H
    and ∂F/∂H exactly in 3(2nx − 2) + 4 passes of the local equations; J = ∂F/∂P|_H + (∂F/∂H)·K
    then follows by contracting ∂F/∂H with the rows of K it touches: 12 per Reynolds row (four
    nodes along x in three columns), a whole column's per meniscus row — about 12·(nx·ny)²
    operations instead of the (nx·ny)³ of one forward pass per unknown through K.

    Returns (∂F/∂P (ny, R, nx − 2, ny) indexed [j, r, a, b] for equation (r, j) and unknown
    P[a, b]; ∂F/∂H₀ (R, ny) for a uniform film offset; ∂F[r, j]/∂X_m,j (R, ny))."""
    rows, ny = interior.shape
    nx = height.shape[0]
    _, linear = jax.linearize(local, interior, height, meniscus)
    columns = jnp.arange(ny)
    colour = columns % 3
    in_class = (colour[None, :] == jnp.arange(3)[:, None]).astype(interior.dtype)  # (3, ny)

    def seeds(count):  # [c, i] → the unit tangent on row i of every column of class c
        return jnp.eye(count)[None, :, :, None] * in_class[:, None, None, :]

    zero_p, zero_h, zero_m = jnp.zeros_like(interior), jnp.zeros_like(height), jnp.zeros_like(meniscus)
    by_pressure = jax.vmap(jax.vmap(lambda tangent: linear(tangent, zero_h, zero_m)))(seeds(rows))  # [c, a, r, j]
    by_height = jax.vmap(jax.vmap(lambda tangent: linear(zero_p, tangent, zero_m)))(seeds(nx))  # [c, i, r, j]
    by_meniscus = jax.vmap(lambda tangent: linear(zero_p, zero_h, tangent))(in_class)  # [c, r, j]
    offset_column = linear(zero_p, jnp.ones_like(height), zero_m)
    equations = by_pressure.shape[2]  # R: the Reynolds rows (the nx − 2 interior ones), then (starved) the meniscus row
    reynolds = jnp.arange(rows)
    shifts = []
    for shift in (-1, 0, 1):  # equation column j, unknown column j + shift: the one of its class
        neighbour = columns + shift
        inside = ((neighbour >= 0) & (neighbour < ny))[:, None, None]
        neighbour = jnp.clip(neighbour, 0, ny - 1)
        by_film = by_height[neighbour % 3, :, :, columns] * inside  # [j, i, r]: ∂F[r, j]/∂H[i, j + shift]
        shifts.append((neighbour, inside, by_film))
    # the elastic part, Reynolds row r, column j: Σ ∂F/∂H[r + along, j + shift] · K[r + along, j + shift]
    jacobian = 0.0
    for neighbour, _, by_film in shifts:
        for along in (-1, 0, 1, 2):
            node = jnp.clip(reynolds + along, 0, nx - 1)
            weight = jnp.where(node == reynolds + along, by_film[:, node, reynolds], 0.0)  # [j, r]; 0 off the grid
            jacobian = jacobian + weight[:, :, None, None] * influence[node[None, :], neighbour[:, None]]
    if equations > rows:  # the meniscus row reads the whole column
        meniscus_row = sum(jnp.einsum("ji,ijab->jab", by_film[:, :, rows], influence[:, neighbour])
                           for neighbour, _, by_film in shifts)
        jacobian = jnp.concatenate([jacobian, meniscus_row[:, None]], axis=1)
    # plus ∂F/∂P|_H, the direct dependence on the pressures
    for neighbour, inside, _ in shifts:
        direct = by_pressure[neighbour % 3, :, :, columns] * inside  # [j, a, r]
        jacobian = jacobian.at[columns, :, :, neighbour].add(jnp.transpose(direct, (0, 2, 1)))
    return jacobian, offset_column, by_meniscus[colour, :, columns].T


def finite_line_film(load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile: RollerProfile,
                     length, flat_length, grid=(33, 48), viscosity_law="roelands",
                     density_law="dowson_higginson", tolerance=1e-10, oil_layer=None,
                     load_path=LOAD_PATH, start: FiniteLineFilm | None = None,
                     axial_clustering: float | None = None, side_inflow: float = 0.0,
                     coarse_grid_start: bool = True) -> FiniteLineFilm:
    """Isothermal EHL of a roller of finite length on its raceway (2-D, half domain), fully
    flooded or starved by an inlet oil layer.

    Args:
        load: roller load W [N] > 0.
        radius: reduced radius R [m] in the rolling direction.
        speed: mean entrainment speed u [m/s] > 0.
        viscosity: η₀ [Pa·s]; pressure_viscosity: α [1/Pa]; effective_modulus: E' [Pa].
        profile: the roller's axial profile (`roller_profile`); length: effective length l [m];
            flat_length: the length b and p_h are based on [m] (the flat of a circular profile).
        grid: (nx, ny) nodes along rolling and cells along the half roller (`check_grid`).
        oil_layer: inlet oil supply layer h_oil [m], or None for fully flooded.
        load_path: the load continuation's stages, increasing fractions of the load in (0, 1]
            ending at 1, taken only where Newton at the load from the 1-D start and from the
            coarse grid fails (starved, each stage with the menisci held first).
        coarse_grid_start: flooded, where Newton at the load from the 1-D start (or `start`)
            fails, and nx − 1 is even with (nx − 1)/2 + 1 ≥ COARSE_START_NODES, Newton again
            from this solver's solution on the grid of half the nodes along rolling (the same
            cells along the roller; its own load path, no coarse start of its own), interpolated
            along x, before the load continuation. Not starved: there the held menisci of each
            stage carry the paper's roller at 1028, 1607 and 2471 N on 65 × 65 without it, and
            it would double the program (29 431 → 58 044 StableHLO lines, compile 33 → 56 s on
            2 cores; flooded 12 323 → 23 941 lines, 16 → 26 s).
        start: a solution on the same grid (a flooded one has its menisci at the inlet) to start Newton from
            instead of the 1-D line solution: a continuation in any argument, taken in steps
            small enough that each converges (the starved-EHL paper's roller from 2.0 to 1.8 µm,
            1028 N, 33 × 48: steps of 0.02 µm, about 2 s each).
        axial_clustering: None for the default cells along the roller, 0 for uniform cells, or β > 0 for cells clustered
            at the flat's end by a smooth map (`axial_cells`; not yet the default: the
            starved-EHL paper's roller near the flooded limit, h_oil = 1.8 and 2.0 µm on 33 × 48, does not converge on it).
        side_inflow: the fraction in [0, 1] of the side inflow that each column's meniscus
            balance counts (below): 0, the default, is one meniscus per column fed by the oil
            layer alone; 1 conserves mass across the meniscus, side flow included. Not yet
            robust: at 1 the Newton from the 1-D start converges on 25 × 16 but fails on 33 × 48
            clustered (the starved-EHL paper's roller at 1028 and 1607 N, residual 0.75), which is reached by
            continuation in this fraction with `start`, filling by hand each dry end column the
            side inflow must fill (`benchmarks/finite_line_side_flow.py`).

    Starvation: each column y_j has its own inlet meniscus X_m,j, an unknown. Upstream of it the
    oil layer rides on the surfaces (the partial film of the Elrod θ-model carries u·h_oil); the
    full film starts at the meniscus with p = 0, and mass conservation across it fixes X_m,j:
    ρ̄h − (ρh³/12ηu) ∂p/∂x = h_oil (taken on the faces a cell or two downstream, where the discrete
    wedge term is in flux form; the meniscus taken as straight along y there). X_m,j lies in
    [inlet, outlet − Δ/2]: at the inlet when the flooded column passes less than the supply (the
    film is the flooded one); at the upper bound when no full film forms (the crowned ends, where
    the gap exceeds the layer). The Newton starts from the starved 1-D line solution extruded
    along the flat.

    Side flow at the meniscus: near the ends the full film of a column pushes oil sideways into
    the partial film of its drier neighbour (ε ∂P/∂Y across the face to a p = 0 node). The
    θ-model carries that oil on downstream in the neighbour's partial film; the default meniscus
    balance drops it (its supply is h_oil alone). With `side_inflow` = γ the balance of column j
    reads F_x = H_oil + γ Δ Σ_i w_i ∂Y(ε ∂Y P)_ij, the sum over the nodes from the inlet to the
    faces F_x is taken on (weights w = clip(3 − s, 0, 1) in the cells s past the meniscus, so
    that the sum is continuous as it crosses a node): with γ = 1 the x-flux through the
    column's full film is the supply plus every side inflow upstream of where it is measured,
    the discrete ∂X F_x = ∂Y(ε ∂Y P) of the Reynolds equation. On the starved-EHL paper's roller (33 × 48 clustered,
    0.8 µm) γ = 1 leaves the central film and raises the end minimum by 9.6 % at 1028 N and 8.4 %
    at 1607 N: the side inflow fills end columns that had no full film.
    """
    require_float64()
    nx, ny = check_grid(grid)
    if not (load_path and load_path[-1] == 1.0 and all(a < b for a, b in zip((0.0, *load_path), load_path))):
        raise ValueError(f"load_path: increasing load fractions in (0, 1] ending at 1.0, got {load_path}")
    if axial_clustering is not None and not axial_clustering >= 0:
        raise ValueError(f"axial_clustering: None, 0 (uniform cells) or a clustering β > 0, got {axial_clustering}")
    if not 0.0 <= side_inflow <= 1.0:
        raise ValueError(f"side_inflow: the fraction of the side inflow in the meniscus balance, in [0, 1], "
                         f"got {side_inflow}")
    if start is not None and start.pressure.shape != (nx, ny):
        raise ValueError(f"start: a solution on the grid {(nx, ny)} (half domain), got one on {start.pressure.shape}")
    starved = oil_layer is not None
    x = np.linspace(INLET, OUTLET, nx)
    spacing = x[1] - x[0]
    highest_meniscus = OUTLET - 0.5 * spacing
    centre = int(np.argmin(np.abs(x)))
    hertz_contact = line_contact(load / flat_length, radius, effective_modulus)
    half_width, hertz_pressure = hertz_contact.half_width, hertz_contact.max_pressure
    speed_parameter = 12.0 * viscosity * speed * radius**2 / (half_width**3 * hertz_pressure)
    fluid = FluidParameters(speed_parameter, hertz_pressure, viscosity, pressure_viscosity, viscosity_law, density_law)
    edges = axial_cells(ny, 0.5 * flat_length, 0.5 * length, axial_clustering) / half_width
    y, widths = 0.5 * (edges[1:] + edges[:-1]), jnp.diff(edges)
    # elastic film (1/2π) Σ P C: cell (k, l) and its mirror image at −y, seen from node (i, j); C
    # depends on i − k alone, so it is evaluated on the 2nx − 1 node offsets and gathered (Love's
    # formula on the whole (nx, ny, nx, ny) kernel holds a dozen temporaries of the kernel's size)
    offset_x = (np.arange(-(nx - 1), nx) * spacing)[:, None, None]
    below = (y[:, None] - y[None, :])[None]
    above = (y[:, None] + y[None, :])[None]  # the mirror image
    half_cell = 0.5 * widths[None, None, :]
    by_offset = (love_rectangle(offset_x, below, 0.5 * spacing, half_cell)
                 + love_rectangle(offset_x, above, 0.5 * spacing, half_cell)) / (2 * np.pi)  # [i − k, j, l]
    node_offset = np.arange(nx)[:, None] - np.arange(nx)[None, :] + nx - 1
    kernel = jnp.transpose(by_offset[node_offset], (0, 2, 1, 3)).reshape(nx * ny, nx * ny)
    profile_film = crown_drop(profile, y * half_width, length, effective_modulus, radius) * radius / half_width**2
    load_target = 0.5 * np.pi * flat_length / half_width  # ∬P dX dY over the whole roller
    supply = oil_layer * radius / half_width**2 if starved else None  # H_oil
    columns = ColumnGrid(jnp.asarray(x), spacing, y, edges, widths, fluid, supply, side_inflow)

    def film(pressure, offset):
        elastic = (kernel @ pressure.reshape(-1)).reshape(nx, ny)
        return offset + 0.5 * jnp.asarray(x)[:, None] ** 2 + profile_film[None, :] + elastic

    def balance(pressure, fraction=1.0):
        return (2.0 * spacing * jnp.sum(pressure * widths) - fraction * load_target) / load_target * 0.5 * np.pi

    def residual(unknowns, fraction=1.0):
        """Residual [-]: the Reynolds complementarity at the interior nodes (row-major, x first),
        the load balance (at `fraction` of the load: the continuation's stages), then (starved)
        the meniscus equation of each column."""
        pressure, offset, meniscus = unpack(unknowns)
        local = local_equations(pressure, film(pressure, offset), meniscus, columns)
        result = jnp.append(local[:nx - 2].reshape(-1), balance(pressure, fraction))
        return jnp.concatenate([result, local[nx - 2]]) if starved else result

    def jacobian(unknowns):
        """∂residual/∂unknowns [-], dense, assembled as J = ∂F/∂u|_H + (∂F/∂H)·K rather than by
        one forward pass per unknown through the influence matrix K (`local_and_elastic_jacobian`)."""
        pressure, offset, meniscus = unpack(unknowns)
        blocks, offset_column, meniscus_diagonal = local_and_elastic_jacobian(
            lambda inner, height, menisci: local_equations(jnp.pad(inner, ((1, 1), (0, 0))), height, menisci, columns),
            pressure[1:-1], film(pressure, offset), meniscus, influence)
        rows = blocks.shape[1]  # nx − 2, or nx − 1 with the meniscus equations
        # rows (r, j) → equation order: Reynolds r < nx − 2 row-major, the balance, the menisci
        by_row = jnp.transpose(blocks, (1, 0, 2, 3)).reshape(rows * ny, interior)
        pressure_columns = jnp.concatenate([by_row[:interior], balance_row, by_row[interior:]])
        offset_column = jnp.concatenate([offset_column[:nx - 2].reshape(-1), jnp.zeros(1),
                                         offset_column[nx - 2:].reshape(-1)])
        matrix = jnp.concatenate([pressure_columns, offset_column[:, None]], axis=1)
        if not starved:
            return matrix
        meniscus_columns = jnp.concatenate([
            (meniscus_diagonal[:nx - 2, :, None] * jnp.eye(ny)[None]).reshape(interior, ny), jnp.zeros((1, ny)),
            jnp.diag(meniscus_diagonal[nx - 2])])
        return jnp.concatenate([matrix, meniscus_columns], axis=1)

    # constant parts of the Jacobian: ∂H/∂P at the interior nodes, the (linear) load balance row
    influence = kernel.reshape(nx, ny, nx, ny)[:, :, 1:-1, :]
    balance_row = jax.grad(balance)(jnp.zeros((nx, ny)))[1:-1].reshape(1, -1)
    interior = (nx - 2) * ny

    def unpack(unknowns):
        pressure = jnp.pad(unknowns[:interior].reshape(nx - 2, ny), ((1, 1), (0, 0)))
        meniscus = unknowns[interior + 1:] if starved else jnp.full(ny, INLET)
        return pressure, unknowns[interior], meniscus

    fixed = jax.lax.stop_gradient  # the starts and the iterations carry no derivative
    taper = jnp.clip(0.5 * flat_length / half_width + 1.0 - y, 0.0, 1.0)

    def unknowns_from(pressure, central, meniscus):
        """Newton's unknowns [-], without derivative, from a pressure P (nx, ny), the central film
        [m] that fixes the offset H₀, and (starved) the menisci X_m (ny)."""
        offset = central * radius / half_width**2 - film(pressure, 0.0)[centre, 0]
        guess = jnp.append(pressure[1:-1].reshape(-1), offset)
        return fixed(jnp.concatenate([guess, meniscus]) if starved else guess)

    def start_at(fraction):
        """Start at `fraction` of the load: the 1-D solution (starved alike) under that load per
        flat length, extruded over the flat and tapered off over the first half-width of the
        crown, scaled to that load."""
        line = line_film(*fixed((fraction * load / flat_length, radius, speed, viscosity, pressure_viscosity,
                                 effective_modulus)),
                         nodes=129, viscosity_law=viscosity_law, density_law=density_law, oil_layer=fixed(oil_layer))
        line_pressure = jnp.interp(jnp.asarray(x), line.x / half_width, line.pressure / hertz_pressure, left=0.0)
        start = line_pressure[:, None] * taper[None, :]
        start = start * fraction * load_target / (2.0 * spacing * jnp.sum(start * widths))
        return unknowns_from(start, line.central, jnp.where(taper > 0, line.meniscus / half_width, highest_meniscus))

    coarser_nodes = (nx - 1) // 2 + 1
    coarse_start = coarse_grid_start and not starved and (nx - 1) % 2 == 0 and coarser_nodes >= COARSE_START_NODES

    def from_coarse_grid():
        """Newton's unknowns from this solver's flooded solution on (coarser_nodes, ny) (the
        same cells along the roller), P interpolated along x, the central film kept."""
        coarse = finite_line_film(*fixed((load, radius, speed, viscosity, pressure_viscosity, effective_modulus,
                                          profile, length, flat_length)),
                                  grid=(coarser_nodes, ny), viscosity_law=viscosity_law, density_law=density_law,
                                  tolerance=tolerance, load_path=load_path,
                                  axial_clustering=axial_clustering, side_inflow=side_inflow, coarse_grid_start=False)
        scale = fixed(half_width)
        pressure = jax.vmap(lambda column: jnp.interp(jnp.asarray(x), coarse.x / scale, column), in_axes=1,
                            out_axes=1)(coarse.pressure / fixed(hertz_pressure))
        return unknowns_from(pressure, coarse.central, None)

    # the meniscus positions move at most a cell per Newton step
    largest_change = jnp.concatenate([jnp.full((nx - 2) * ny + 1, jnp.inf), jnp.full(ny if starved else 0, spacing)])

    def limited(step):
        return step * jnp.minimum(1.0, jnp.min(largest_change / (jnp.abs(step) + 1e-300)))

    def error_and_solved(unknowns):
        """(largest residual [-], whether it is below the tolerance with a positive film)."""
        pressure, offset, _ = unpack(unknowns)
        error = jnp.max(jnp.abs(residual(unknowns)))
        return error, (error < tolerance) & (jnp.min(film(pressure, offset)) > 0)

    def with_menisci_held(unknowns, fraction):
        """Starved: Newton on the Reynolds equations and the load balance (at `fraction` of the
        load) for the pressure and H₀, the menisci held where `unknowns` has them; flooded: `unknowns`."""
        if not starved:
            return unknowns
        menisci = unknowns[interior + 1:]

        def held(point, _):
            return residual(jnp.concatenate([point, menisci]), fraction)[:interior + 1]

        def held_jacobian(point, _):
            return jacobian(jnp.concatenate([point, menisci]))[:interior + 1, :interior + 1]

        settled, _ = newton(held, unknowns[:interior + 1], max_steps=HELD_MENISCUS_STEPS, jacobian=held_jacobian,
                            shortest=SHORTEST_STEP, floor=tolerance, single_precision_factor=True)
        return jnp.concatenate([settled, menisci])

    def newton_then_continuation(_, guess, __):
        """Newton at the load from `guess` (without `start`, from the 1-D start at the load);
        where that fails, from the coarse grid's solution (`coarse_grid_start`); where that
        fails too, through the load stages `load_path`, each from the previous one's solution,
        the first from its own 1-D start; starved, each stage after the first with the menisci
        held first. One 1-D solve is traced for both starts (its load an argument)."""
        coarse_stages = (1.0,) if coarse_start else ()
        stage_loads = jnp.asarray((1.0, *coarse_stages, *load_path))
        continuation = 1 + len(coarse_stages)  # the index of the load path's first stage

        def stage(state):
            index, unknowns = state
            restart = (index == continuation) if start is not None else ((index == 0) | (index == continuation))
            unknowns = jax.lax.cond(restart, lambda: start_at(stage_loads[index]), lambda: unknowns)
            if coarse_start:
                unknowns = jax.lax.cond(index == 1, from_coarse_grid, lambda: unknowns)
            if starved:
                unknowns = jax.lax.cond(index > 0, lambda: with_menisci_held(unknowns, stage_loads[index]),
                                        lambda: unknowns)
            return index + 1, newton(residual, unknowns, stage_loads[index], max_steps=NEWTON_STEPS,
                                     jacobian=lambda point, _: jacobian(point), limit=limited, fallback=True,
                                     shortest=SHORTEST_STEP, floor=tolerance, single_precision_factor=True)[0]

        def more(state):
            index, unknowns = state
            at_the_load = index <= continuation  # stages at the whole load: solved there, done
            return (index == 0) | ((index < stage_loads.size) & ~(at_the_load & error_and_solved(unknowns)[1]))

        return jax.lax.while_loop(more, stage, (0, guess))[1]

    size = interior + 1 + (ny if starved else 0)
    solution = implicit_root(
        residual, jnp.zeros(size) if start is None else unknowns_from(start.pressure / hertz_pressure, start.central,
                                                                      start.meniscus / half_width), 1.0,
        solve=newton_then_continuation)
    error, converged = error_and_solved(fixed(solution))
    pressure, offset, meniscus = unpack(solution)
    thickness = film(pressure, offset) * half_width**2 / radius
    lowest = jnp.argmin(thickness)
    return FiniteLineFilm(jnp.asarray(x) * half_width, y * half_width, pressure * hertz_pressure, thickness,
                          thickness[centre, 0], thickness.reshape(-1)[lowest], y[lowest % ny] * half_width,
                          converged, error, meniscus * half_width)
