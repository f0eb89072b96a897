"""The finite line contact on fine grids: matrix-free Newton–Krylov with FFT deflection.

The same discrete equations as `finite_line_ehl` (Reynolds complementarity, load balance,
menisci; `local_equations`) on uniform cells along the half roller, so that the elastic film is a
convolution: H_el = (1/2π) Σ P C with Love's rectangle coefficients over the whole roller (each
cell and its mirror image at −y), applied by DC-FFT (`influence`) in O(N log N) and O(N) memory
instead of the dense influence matrix's O(N²).

Solver: the nested Newton–Krylov of `nested_krylov` (a `UniformLevel` per grid, `solve_nested`), its
coarsest grid solved by the dense Newton of `finite_line_ehl` with its load continuation and held menisci;
derivatives implicit, through the finest solution.
"""

import jax
import jax.numpy as jnp
import numpy as np

from ..bearings.roller.roller_profile import RollerProfile, crown_drop
from ..contact.hertz import line_contact
from ..numerics import require_float64
from .finite_line_ehl import FiniteLineFilm, finite_line_film
from .line_ehl import FluidParameters
from .nested_krylov import UniformLevel, krylov_levels, solve_nested


def line_scales(load, radius, effective_modulus, flat_length):
    """The Hertz half-width b [m] and pressure p_h [Pa] of a roller under `load` [N] on its flat
    length [m] (the reference length and pressure of the finite line contact's equations)."""
    hertz_contact = line_contact(load / flat_length, radius, effective_modulus)
    return hertz_contact.half_width, hertz_contact.max_pressure


def line_level(viscosity_law, density_law, side_inflow, starved):
    """level_at(load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile,
    length, flat_length, oil_layer) → a function (nx, ny) → the UniformLevel of the roller's case
    (starved: the oil layer as its supply H_oil; else flooded)."""

    def level_at(load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile, length, flat_length,
                 oil_layer):
        half_width, hertz_pressure = line_scales(load, radius, effective_modulus, flat_length)
        speed_parameter = 12.0 * viscosity * speed * radius**2 / (half_width**3 * hertz_pressure)
        fluid = FluidParameters(speed_parameter, hertz_pressure, viscosity, pressure_viscosity, viscosity_law,
                                density_law)
        supply = oil_layer * radius / half_width**2 if starved else None

        def rigid_axial(y):
            return crown_drop(profile, y * half_width, length, effective_modulus, radius) * radius / half_width**2

        return lambda nx, ny: UniformLevel(nx, ny, 0.5 * length / half_width, rigid_axial, fluid, supply, side_inflow,
                                           0.5 * np.pi * flat_length / half_width)

    return level_at


def finite_line_film_krylov(load, radius, speed, viscosity, pressure_viscosity, effective_modulus,
                            profile: RollerProfile, length, flat_length, grid=(129, 129), viscosity_law="roelands",
                            density_law="dowson_higginson", tolerance=1e-10, oil_layer=None,
                            side_inflow: float = 0.0) -> FiniteLineFilm:
    """Isothermal EHL of a roller of finite length on its raceway (2-D, half domain), fully
    flooded or starved, on a fine grid of uniform cells by Newton–Krylov (module docstring).

    Arguments as `finite_line_ehl.finite_line_film`, except: grid (nx, ny): nx nodes along
    rolling, 2^k·(n₀ − 1) + 1 with n₀ from 33 to 65 (e.g. 129, 257, 513), by ny uniform cells on
    the half roller (`krylov_levels`). Converged means the residual, each Reynolds row scaled to
    the pressure change it asks (`UniformLevel.residual_scale`), below `tolerance` and a positive film on the
    finest grid (at most NEWTON_STEPS per level)."""
    require_float64()
    starved = oil_layer is not None
    levels = krylov_levels(grid)
    if not 0.0 <= side_inflow <= 1.0:
        raise ValueError(f"side_inflow: the fraction of the side inflow in the meniscus balance, in [0, 1], "
                         f"got {side_inflow}")
    fixed = jax.lax.stop_gradient
    arguments = (load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile, length, flat_length,
                 oil_layer)
    if len(levels) == 1:  # the dense Newton alone, on uniform cells
        return finite_line_film(*arguments[:-1], grid=levels[0], viscosity_law=viscosity_law, density_law=density_law,
                                tolerance=tolerance, oil_layer=oil_layer, axial_clustering=0.0, side_inflow=side_inflow)
    coarse = finite_line_film(*fixed(arguments[:-1]), grid=levels[0], viscosity_law=viscosity_law,
                              density_law=density_law, tolerance=tolerance, oil_layer=fixed(oil_layer),
                              axial_clustering=0.0, side_inflow=side_inflow)

    level_at = line_level(viscosity_law, density_law, side_inflow, starved)

    def from_dense(coarsest):
        """The dense Newton's coarse solution as the unknowns of the coarsest level."""
        half_width, hertz_pressure = line_scales(*fixed((load, radius, effective_modulus, flat_length)))
        pressure = coarse.pressure / hertz_pressure
        offset = coarse.central * radius / half_width**2 - coarsest.film(pressure, 0.0)[coarsest.centre, 0]
        unknowns = jnp.append(pressure[1:-1].reshape(-1), offset)
        return jnp.concatenate([unknowns, coarse.meniscus / half_width]) if starved else unknowns

    finest, unknowns, _ = solve_nested(level_at, arguments, levels, from_dense, tolerance)
    pressure, film, meniscus, error, converged = finest.solution(unknowns, tolerance)
    return line_film_result(finest, (load, radius, effective_modulus, flat_length), pressure, film, converged, error,
                            meniscus)


def line_film_result(level, case, pressure, film, converged, error, meniscus) -> FiniteLineFilm:
    """The FiniteLineFilm [SI] of a solution on `level`: dimensionless P, H (nx, ny) and menisci X_m
    (ny), `case` = (load [N], radius [m], E' [Pa], flat length [m])."""
    half_width, hertz_pressure = line_scales(*case)
    thickness = film * half_width**2 / case[1]
    lowest = jnp.argmin(thickness)
    y = level.columns.y
    return FiniteLineFilm(level.columns.x * half_width, y * half_width, pressure * hertz_pressure, thickness,
                          thickness[level.centre, 0], thickness.reshape(-1)[lowest], y[lowest % level.ny] * half_width,
                          converged, error, meniscus * half_width)
