"""Numerical EHL of a roller's finite line contact starved by an inlet oil layer: the
mass-conserving θ-model by Newton–Krylov, on the grids of `finite_line_krylov`.

The flooded finite line contact (`finite_line_krylov`, uniform cells on the half roller) with the
inlet supplied by an oil layer h_oil only, by the θ-model of `starved_krylov`: where the film is
partial the oil is carried by the surfaces, and whatever flows out at the roller's ends, or round
them, is counted; no meniscus per y cell (the model of `finite_line_ehl` and `finite_line_krylov`,
whose `side_inflow` approximates that side flow). The starved-EHL paper itself solves a θ-model
(docs/validation/lubricant_film.md).

Solver (`starved_krylov.solve_starved`): the pseudo-time march on the nested grid of
`march_level` from `finite_line_film_krylov`'s flooded film there, then
Newton–Krylov grid by grid to the finest. Converged: max|F/s| ≤ `tolerance` on the finest grid and
a positive film there (a coarse march grid may close the film at the roller end, h < 0, and not
converge; the finer grids are solved from it all the same).
"""

import jax
import jax.numpy as jnp

from ..bearings.roller.roller_profile import RollerProfile
from ..numerics import require_float64
from ..params import check_range
from .finite_line_ehl import FiniteLineFilm
from .finite_line_krylov import finite_line_film_krylov, line_film_result, line_level, line_scales
from .nested_krylov import krylov_levels
from .starved_krylov import StarvedLevel, march_level, solve_starved


def starved_finite_line_film(load, radius, speed, viscosity, pressure_viscosity, effective_modulus,
                             profile: RollerProfile, length, flat_length, oil_layer, grid=(129, 129),
                             viscosity_law="roelands", density_law="dowson_higginson",
                             tolerance=1e-10) -> FiniteLineFilm:
    """Isothermal EHL of a roller of finite length on its raceway starved by an inlet oil layer
    `oil_layer` h_oil [m] > 0 (the oil on both surfaces ahead of the contact), by the θ-model
    (module docstring). Arguments as `finite_line_krylov.finite_line_film_krylov`; the result's
    `meniscus` is, per y cell, the first node from the inlet where the film is full (θ = 1)."""
    require_float64()
    check_range("oil_layer", oil_layer, low=0.0, unit=" m", why="the inlet oil layer")
    levels = krylov_levels(grid)
    marching = march_level(levels)
    arguments = (load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile, length, flat_length,
                 oil_layer)
    constants = jax.lax.stop_gradient(arguments)
    flooded_level = line_level(viscosity_law, density_law, 0.0, False)

    def level_at(*case_and_grid):
        *case, grid = case_and_grid
        half_width = line_scales(case[0], case[1], case[5], case[8])[0]
        return StarvedLevel(flooded_level(*case)(*grid), case[-1] * case[1] / half_width**2)

    flooded = finite_line_film_krylov(*constants[:-1], grid=marching, viscosity_law=viscosity_law,
                                      density_law=density_law, tolerance=tolerance)
    half_width, hertz_pressure = line_scales(constants[0], constants[1], constants[5], constants[8])
    live, unknowns = solve_starved(level_at, arguments, levels, marching, flooded.pressure / hertz_pressure,
                                   flooded.thickness * constants[1] / half_width**2, tolerance)
    pressure, film, _, error, converged = live.solution(unknowns, tolerance)
    full = live.fields(jax.lax.stop_gradient(unknowns))[1][1:] >= 1.0
    return line_film_result(live, (load, radius, effective_modulus, flat_length), pressure, film, converged, error,
                            live.columns.x[1 + jnp.argmax(full, axis=0)])
