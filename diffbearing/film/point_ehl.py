"""Numerical EHL of an elliptical point contact (a ball on its raceway), fully flooded.

The discrete equations of the finite line contact (`finite_line_ehl.local_equations`: isothermal
Newtonian Reynolds with the Roelands or Barus viscosity and the Dowson–Higginson density,
cavitation by Fischer–Burmeister complementarity) with the gap of two bodies of radii Rx (along
rolling) and Ry (across):

    h = h₀ + x²/2Rx + y²/2Ry + v(x, y),   v = (2/πE') ∬ p/r dA   (Hamrock & Dowson 1976).

Dimensionless in the reference length b_r = 4 Rx p₀/E' (p₀ the Hertz pressure): X = x/b_r,
Y = y/b_r, P = p/p₀, H = h Rx/b_r², so that v becomes H_el = (1/2π) ∬ P/ρ dX dY exactly as in
the line units of `line_ehl` (b_r is the Hertz half-width b of a line contact and 4a/π of a
circular one) and λ = 12η₀u Rx²/(b_r³p₀). Domain: X ∈ [−4.5, 1.5], Y ∈ [0, 1.5(a/b_r) + 1.5]
(the half y ≥ 0 by symmetry about the rolling plane), p = 0 on its edge; uniform cells, so that
the deflection is a DC-FFT convolution.

Solver: the finite line contact's matrix-free Newton–Krylov (`nested_krylov.solve_nested`):
on the coarsest grid from the dry Hertz pressure at the Hamrock–Dowson central film, each step
at most LARGEST_STEP long, then grid by grid, x nodes and y cells doubled, to the finest; every
linear solve to FORCING in GMRES(RESTART). A grid whose coarser one did not converge to a
positive film starts anew from the Hertz start on its own cells: under heavy load the film is
thinner than a coarse grid's discretisation error (the 209 bearing of Hamrock's Fundamentals of
Machine Elements, 4.4 kN on its most loaded ball, p₀ 2.6 and 3.1 GPa, κ 7.3 and 9.3: on 33 × 16
its discrete film closes, h_c < 0, and 65 × 32 and 129 × 64 interpolated from it stall at scaled
residuals of 0.15 and 0.48; from the Hertz start on 65 × 32 both grids converge in 11 and 12
Newton steps).
Derivatives implicit through the finest solution.

The starved inlet: `starved_point_ehl` (the mass-conserving θ-model on the same grid).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..contact.hertz import point_contact
from ..numerics import require_float64
from ..params import _is_concrete, check_range
from .film_formulas import hamrock_dowson_point
from .line_ehl import FluidParameters
from .nested_krylov import UniformLevel, krylov_levels, solve_nested

FEWEST_CELLS = 16  # cells across the half contact of a coarser grid
COARSEST_STEPS = 120  # Newton–Krylov steps on the coarsest grid, from the Hertz start
# the largest Newton–Krylov step: |ΔP| ≤ 0.2 p₀ at any node, |ΔH₀| ≤ 0.06 (Hertz units); from the
# Hertz start the full Newton steps overshoot to h < 0 and stall, even for a circular contact
# (50 N, Rx = 10 mm, 3 m/s on 33 × 16); limited, they converge in about 20 steps
LARGEST_STEP = (0.2, 0.06)
DOMAIN_SIDE = (1.5, 1.5)  # the half domain across rolling: Y_end = 1.5 a/b_r + 1.5
# the linear solves: every one to at least 1e-8 relative, in GMRES(100). The column blocks of the
# preconditioner leave the coupling across columns to GMRES, strong where the cells across rolling
# are as fine as along it (circles on 257 × 128): with the finite line contact's loosest 1e-3 and
# GMRES(30) the light circle there stalls at a scaled residual of 1e-5; the fast one (M = 40)
# stalls with either change alone; with both, each converges in 13 to 15 Newton steps
# (docs/validation/lubricant_film.md)
FORCING = 1e-8
RESTART = 100


class PointFilm(eqx.Module):
    """Solution [SI] on the half domain y ≥ 0: x [m] (nx), y [m] cell centres (ny), pressure [Pa]
    and film [m] (nx, ny), central film at x = 0 next to y = 0 [m], minimum film [m] and where it
    is (x, y [m]), whether Newton–Krylov converged (scaled residual below the tolerance, positive
    film), that residual [-] (`nested_krylov.UniformLevel.residual_scale`), and the central
    film on the next coarser grid [m] (NaN: none, or not kept), whose difference from `central`
    measures the grid's own error (`grid_change`)."""

    x: jax.Array
    y: jax.Array
    pressure: jax.Array
    thickness: jax.Array
    central: jax.Array
    minimum: jax.Array
    minimum_x: jax.Array
    minimum_y: jax.Array
    converged: jax.Array
    residual: jax.Array
    coarser_central: jax.Array


def grid_change(film: PointFilm):
    """[-] |h_c − h_c,coarser| / h_c: how much the central film changed from the next coarser grid
    (spacing halved since). Where the films converge at order p this is (2^p − 1) times the finer
    grid's own error (Richardson): p ≈ 1.7 to 2 measured (docs/validation/lubricant_film.md §The
    point contact), so about twice that error."""
    return jnp.abs(film.central - film.coarser_central) / jnp.abs(film.central)


def hertz_scales(load, radius_rolling, radius_transverse, effective_modulus):
    """(b_r [m], p₀ [Pa], a/b_r, b/b_r): the reference length, the Hertz pressure and semi-axes."""
    curvature_sum = 1.0 / radius_rolling + 1.0 / radius_transverse
    contact = point_contact(load, curvature_sum, (1.0 / radius_rolling - 1.0 / radius_transverse) / curvature_sum,
                            effective_modulus)
    reference = 4.0 * radius_rolling * contact.max_pressure / effective_modulus
    return (reference, contact.max_pressure, contact.semi_major_axis / reference,
            contact.semi_minor_axis / reference)


def _hertz_start(level, constants):
    """The start [-] on the coarsest `level`, without derivatives: the dry Hertz pressure (scaled
    to the discrete load) and the offset H₀ that puts the Hamrock–Dowson central film at the
    centre."""
    load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus = constants
    reference, _, major, minor = hertz_scales(load, radius_rolling, radius_transverse, effective_modulus)
    x, y = level.columns.x[:, None], level.columns.y[None, :]
    hertz = jnp.sqrt(jnp.clip(1.0 - (x / minor) ** 2 - (y / major) ** 2, 0.0, None))
    hertz = hertz * level.load_target / (2.0 * level.spacing * jnp.sum(hertz * level.columns.widths))
    central, _ = hamrock_dowson_point(load, radius_rolling, major / minor, speed, viscosity, pressure_viscosity,
                                      effective_modulus)
    offset = central * radius_rolling / reference**2 - level.film(hertz, 0.0)[level.centre, 0]
    return jnp.append(hertz[1:-1].reshape(-1), offset)


def point_level(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
                grid, viscosity_law="roelands", density_law="dowson_higginson"):
    """(UniformLevel of the case on `grid` = (nx, ny), its reference length b_r [m]): the grid,
    rigid gap, fluid and load of the dimensionless equations (module docstring)."""
    reference, hertz_pressure, major, _ = hertz_scales(load, radius_rolling, radius_transverse, effective_modulus)
    fluid = FluidParameters(12.0 * viscosity * speed * radius_rolling**2 / (reference**3 * hertz_pressure),
                            hertz_pressure, viscosity, pressure_viscosity, viscosity_law, density_law)

    def rigid_transverse(y):
        return 0.5 * radius_rolling / radius_transverse * y**2

    side = DOMAIN_SIDE[0] * major + DOMAIN_SIDE[1]
    return UniformLevel(*grid, side, rigid_transverse, fluid, None, 0.0, load / (hertz_pressure * reference**2),
                        largest_step=LARGEST_STEP), reference


def point_film(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
               grid=(65, 32), viscosity_law="roelands", density_law="dowson_higginson",
               tolerance=1e-10) -> PointFilm:
    """Isothermal EHL film [m] of an elliptical point contact, fully flooded (module docstring).

    Args:
        load: contact load Q [N] > 0.
        radius_rolling: reduced radius Rx [m] along rolling; radius_transverse: Ry ≥ Rx [m] across
            (the ellipse's long axis a lies across rolling, as for a ball in its groove).
        speed: mean entrainment speed u [m/s] > 0.
        viscosity: η₀ [Pa·s]; pressure_viscosity: α [1/Pa]; effective_modulus: E' [Pa].
        grid: (nx, ny) nodes along rolling (2^k·(n₀ − 1) + 1 with n₀ from 33 to 65, e.g. 65, 129,
            257) by uniform cells on the half domain y ≥ 0 (`nested_krylov.krylov_levels`).
        viscosity_law: "roelands" or "barus"; density_law: "dowson_higginson" or
            "incompressible" (`line_ehl`).

    Converged means the scaled residual (`nested_krylov.UniformLevel.residual_scale`) below
    `tolerance` and a positive film on the finest grid."""
    require_float64()
    levels = krylov_levels(grid, FEWEST_CELLS)
    check_range("load", load, low=0.0, unit=" N")
    check_range("speed", speed, low=0.0, unit=" m/s", why="the mean entrainment speed")
    check_range("radius_rolling", radius_rolling, low=0.0, unit=" m")
    check_range("radius_transverse", radius_transverse, low=float(radius_rolling) if _is_concrete(radius_rolling)
                else 0.0, low_open=False, unit=" m", why="Ry ≥ Rx: the ellipse's long axis across rolling")

    def level_at(*arguments):
        """(nx, ny) → UniformLevel of the case."""
        return lambda nx, ny: point_level(*arguments, (nx, ny), viscosity_law, density_law)[0]

    arguments = (load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus)
    constants = jax.lax.stop_gradient(arguments)
    finest, unknowns, coarser = solve_nested(level_at, arguments, levels, lambda level: _hertz_start(level, constants),
                                             tolerance, coarsest_steps=COARSEST_STEPS, forcing=FORCING, restart=RESTART,
                                             start_anew=True)
    reference = hertz_scales(load, radius_rolling, radius_transverse, effective_modulus)[0]
    pressure, film, _, error, converged = finest.solution(unknowns, tolerance)
    coarser_central = jnp.nan
    if coarser is not None:  # its film at the centre, without derivative (a measure of the grid)
        level, solved = coarser
        coarse_pressure, offset, _ = level.unpack(solved)
        coarser_central = level.film(coarse_pressure, offset)[level.centre, 0] * jax.lax.stop_gradient(
            reference**2 / radius_rolling)
    return film_result(finest, reference, radius_rolling, pressure, film, converged, error, coarser_central)


def film_result(level, reference, radius_rolling, pressure, film, converged, error, coarser_central=jnp.nan) -> PointFilm:
    """The PointFilm [SI] of a solution on `level` (dimensionless P and H (nx, ny)), b_r [m] and
    Rx [m]: the central film next to y = 0 at x = 0, the minimum and where it is; the coarser
    grid's central film [m] as given (NaN: not kept)."""
    thickness = film * reference**2 / radius_rolling
    lowest = jnp.argmin(thickness)
    x, y = level.columns.x * reference, level.columns.y * reference
    return PointFilm(x, y, pressure * level.columns.fluid.hertz_pressure, thickness, thickness[level.centre, 0],
                     thickness.reshape(-1)[lowest], x[lowest // level.ny], y[lowest % level.ny], converged, error,
                     jnp.asarray(coarser_central, dtype=thickness.dtype))
