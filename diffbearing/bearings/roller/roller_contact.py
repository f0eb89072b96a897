"""Pressure between a crowned roller and its raceway, at two fidelity levels.

* `"influence"` — the non-Hertzian numerical solution: the contact grid of nx × ny cells over
  the rolling direction and the roller's effective length, Love's rectangle coefficients by
  DC-FFT, Polonsky–Keer conjugate gradients with the load constraint (normal_contact.py).
  Straight rollers have an edge singularity: their peak grows as the cells shrink, so it is a
  grid-dependent number, never a converged one.
* `"slices"` — Hertz line-contact slices (laminae): each slice of width dy carries
  w = E' l^{−1/9} ((δ − z − ϑy)/C_P)^{10/9} per unit length, Palmgren's load–approach law
  δ = C_P (Q/(lE'))^{0.9} l^{0.1} spread over the roller (Harris & Kotzalas vol. 1, ch. 6;
  C_P = 3.84e-5·E'_steel^{0.9} in mm and N makes it dimensionless); the approach δ solves
  Σ w dy = Q (Newton from above, implicit adjoint); each slice has the Hertz line pressure
  p₀ = √(wE'/(2πR)) over half-width b = √(8wR/(πE')). No interaction between slices.

The x extent of the grid is ±1.6 times the largest slice half-width, so the same grid serves
both levels; the numerical contact must not reach it (`converged` is false if it does).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import optimistix as optx

from ...contact.hertz import LineContact, line_contact
from ...contact.influence import influence_coefficients
from ...contact.normal_contact import solve_normal_contact
from ...numerics import positive_power, require_float64
from .roller_geometry import (
    RollerBearing,
    RollerLoading,
    axial_gap,
    cell_centres,
    equivalent_radius,
    initial_gap,
    roller_modulus,
)

# Palmgren's δ = 3.84e-5 Q^0.9 / l^0.8 (mm, N) holds for steel, E = 207 GPa, ν = 0.3.
PALMGREN_STEEL_MODULUS = 207e9 / (1.0 - 0.3**2)  # E' [Pa]
PALMGREN_CONSTANT = 3.84e-5 * (PALMGREN_STEEL_MODULUS * 1e-6) ** 0.9  # C_P [-]
GRID_EXTENT_FACTOR = 1.6  # x half-extent / largest slice half-width


class RollerContact(eqx.Module):
    """The solved contact. SI: pressure [Pa] on the nx × ny grid, cell centres x [m] (rolling)
    and y [m] (axial), approach δ [m], peak pressure [Pa], carried load ΔA Σp [N], length of
    the loaded zone along y [m], largest half-width of the loaded zone along x [m], and whether
    the solution converged inside the grid (`iterations` of the solver)."""

    pressure: jax.Array
    x: jax.Array
    y: jax.Array
    approach: jax.Array
    max_pressure: jax.Array
    load: jax.Array
    contact_length: jax.Array
    max_half_width: jax.Array
    converged: jax.Array
    iterations: jax.Array


def _lamina_load(approach, gap, length, modulus):
    """Load per unit length [N/m] of laminae with the gap z + ϑy [m] at approach δ [m]."""
    return modulus * length ** (-1.0 / 9.0) * positive_power((approach - gap) / PALMGREN_CONSTANT, 10.0 / 9.0)


def _slice_balance(approach_um, args):
    gap, length, modulus, cell, load = args
    return jnp.sum(_lamina_load(approach_um * 1e-6, gap, length, modulus)) * cell / load - 1.0


def slice_loads(bearing: RollerBearing, loading: RollerLoading, y):
    """Lamina loads w [N/m] at the slice centres y [m], and the approach δ [m] (Palmgren laminae).

    Newton starts above the root (every lamina loaded at δ = max gap + Palmgren's approach), where
    Σw(δ) is convex and increasing, so it converges monotonically; derivatives by the implicit
    function theorem (optimistix ImplicitAdjoint).
    """
    require_float64()
    gap = axial_gap(bearing, loading, y)
    modulus = roller_modulus(bearing)
    cell = bearing.length / y.shape[0]
    start = jnp.max(gap) + PALMGREN_CONSTANT * (loading.load / (bearing.length * modulus)) ** 0.9 * bearing.length ** 0.1
    solution = optx.root_find(_slice_balance, optx.Newton(rtol=1e-12, atol=1e-12), start * 1e6,
                              (gap, bearing.length, modulus, cell, loading.load),
                              adjoint=optx.ImplicitAdjoint(), throw=False, max_steps=100)
    approach = solution.value * 1e-6
    return _lamina_load(approach, gap, bearing.length, modulus), approach, solution.result == optx.RESULTS.successful


class SliceSolution(eqx.Module):
    """Hertz slices: lamina loads w [N/m], each slice's Hertz line contact (`hertz.LineContact`),
    the approach δ [m], and whether its root find succeeded."""

    loads: jax.Array
    line: LineContact
    approach: jax.Array
    converged: jax.Array


def contact_grid(bearing: RollerBearing, loading: RollerLoading, nx: int, ny: int):
    """Cell centres x [m] (rolling direction) and y [m] (along the roller), and the Hertz-slice
    solution (`SliceSolution`) the x extent is sized from."""
    y, _ = cell_centres(0.5 * bearing.length, ny)
    loads, approach, ok = slice_loads(bearing, loading, y)
    line = line_contact(loads, equivalent_radius(bearing, loading, y), roller_modulus(bearing))
    x, _ = cell_centres(GRID_EXTENT_FACTOR * jnp.max(line.half_width), nx)
    return x, y, SliceSolution(loads, line, approach, ok)


def _loaded_extent(pressure, x, y):
    """(length of the loaded zone along y, largest half-width along x) [m], counted in cells."""
    loaded = jax.lax.stop_gradient(pressure) > 0
    cell_x, cell_y = x[1] - x[0], y[1] - y[0]
    return jnp.sum(jnp.any(loaded, axis=0)) * cell_y, 0.5 * jnp.max(jnp.sum(loaded, axis=0)) * cell_x


def roller_contact(bearing: RollerBearing, loading: RollerLoading, grid=(32, 256), method="influence",
                   tolerance=1e-11, max_iterations=2000) -> RollerContact:
    """Solve the roller–raceway contact on an nx × ny grid by `method` = "influence" | "slices".

    Differentiable (forward and reverse) in every array of `bearing` and `loading`: profile
    parameters, load, tilt, diameters, raceway curvature, modulus.
    """
    nx, ny = grid
    if nx < 4 or ny < 4:
        raise ValueError(f"fidelity.grid must be at least [4, 4] cells, got {list(grid)}")
    x, y, slices = contact_grid(bearing, loading, nx, ny)
    cell_x, cell_y = x[1] - x[0], y[1] - y[0]
    line = slices.line
    safe_width = jnp.where(line.half_width > 0, line.half_width, 1.0)
    slice_pressure = line.max_pressure[None, :] * positive_power(1.0 - (x[:, None] / safe_width[None, :]) ** 2, 0.5)
    if method == "slices":
        length, _ = _loaded_extent(slice_pressure, x, y)
        return RollerContact(slice_pressure, x, y, slices.approach, jnp.max(line.max_pressure),
                             jnp.sum(slices.loads) * cell_y, length, jnp.max(line.half_width), slices.converged,
                             jnp.asarray(0))
    if method != "influence":
        raise ValueError(f"effects.contact: expected \"slices\" or \"influence\", got {method!r}")
    coefficients = influence_coefficients(nx, ny, cell_x, cell_y, roller_modulus(bearing))
    solution = solve_normal_contact(initial_gap(bearing, loading, x, y), loading.load, coefficients,
                                    cell_x * cell_y, slice_pressure, tolerance, max_iterations)
    pressure = solution.pressure
    inside = (jnp.max(pressure[0]) == 0) & (jnp.max(pressure[-1]) == 0)
    converged = (solution.relative_change <= tolerance) & inside
    length, half_width = _loaded_extent(pressure, x, y)
    return RollerContact(pressure, x, y, solution.approach, jnp.max(pressure), jnp.sum(pressure) * cell_x * cell_y,
                         length, half_width, converged, solution.iterations)
