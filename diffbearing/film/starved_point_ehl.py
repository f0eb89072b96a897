"""Numerical EHL of a starved elliptical point contact: the mass-conserving θ-model.

The flooded point contact (`point_ehl`) with the inlet supplied by an oil layer h_oil only
(the layer on both surfaces together, as `finite_line_ehl`'s), by the θ-model of
`starved_krylov` (Elrod, J. Lubr. Technol. 103, 1981; for starved EHL, Chevalier, Lubrecht, Cann,
Colin & Dalmaz, J. Tribol. 120, 1998) on `point_ehl`'s grid and units: a layer thicker than the
inlet gap gives `point_film`'s film within 0.1 %.

Solver (`starved_krylov.solve_starved`): the pseudo-time march on the nested grid of `march_grid`
from `point_film`'s flooded film there, then
Newton–Krylov grid by grid to the finest. Converged: max|F/s| ≤ `tolerance` on the finest grid
and a positive film there. Where the march does not reach the steady film (the circle's thinnest
layers on 33 × 16; a κ ≈ 9 contact at a layer of twice its flooded film, whose meniscus lies far
upstream) the result says so.
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ..numerics import require_float64
from ..params import check_range
from .nested_krylov import krylov_levels
from .point_ehl import FEWEST_CELLS, PointFilm, film_result, hertz_scales, point_film, point_level
from .starved_krylov import StarvedLevel, march_level, solve_starved


class StarvedPointFilm(eqx.Module):
    """`film`: the solution [SI] on the half domain y ≥ 0 (`point_ehl.PointFilm`); the oil fill θ
    [-] (nx, ny); the oil layer [m]."""

    film: PointFilm
    fill: jax.Array
    oil_layer: jax.Array


def march_grid(grid) -> tuple[int, int]:
    """(nx, ny) of the nested grid of `grid` that the march runs on (`starved_krylov.march_level`)."""
    return march_level(krylov_levels(grid, FEWEST_CELLS))


def starved_point_film(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity,
                       effective_modulus, oil_layer, grid=(65, 32), viscosity_law="roelands",
                       density_law="dowson_higginson", tolerance=1e-10) -> StarvedPointFilm:
    """Isothermal EHL film [m] of an elliptical point contact starved by an inlet oil layer
    (module docstring). Arguments as `point_ehl.point_film`, and `oil_layer` h_oil [m] > 0: the
    oil on both surfaces ahead of the contact. Converged: max|F/s| ≤ `tolerance`
    (`starved_krylov.StarvedLevel.residual_scale`) on the finest grid and h > 0 there."""
    require_float64()
    check_range("oil_layer", oil_layer, low=0.0, unit=" m", why="the inlet oil layer")
    levels = krylov_levels(grid, FEWEST_CELLS)
    marching = march_level(levels)
    arguments = (load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
                 oil_layer)
    constants = jax.lax.stop_gradient(arguments)

    def level_at(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity, effective_modulus,
                 oil_layer, grid):
        level, reference = point_level(load, radius_rolling, radius_transverse, speed, viscosity, pressure_viscosity,
                                       effective_modulus, grid, viscosity_law, density_law)
        return StarvedLevel(level, oil_layer * radius_rolling / reference**2)

    flooded = point_film(*constants[:-1], grid=marching, viscosity_law=viscosity_law, density_law=density_law)
    reference, hertz_pressure, _, _ = hertz_scales(*constants[:3], constants[6])
    live, unknowns = solve_starved(level_at, arguments, levels, marching, flooded.pressure / hertz_pressure,
                                   flooded.thickness * constants[1] / reference**2, tolerance)
    live_reference = hertz_scales(load, radius_rolling, radius_transverse, effective_modulus)[0]
    pressure, starved, _, error, converged = live.solution(unknowns, tolerance)
    result = film_result(live, live_reference, radius_rolling, pressure, starved, converged, error)
    return StarvedPointFilm(result, live.fields(unknowns)[1], jnp.asarray(oil_layer, dtype=float))
