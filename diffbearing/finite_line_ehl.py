"""Numerical EHL of a finite line contact (roller on raceway, 2-D), fully flooded, by Newton.

Seed 003 (physics.md §4): the gap h = h₀ + x²/2R + g(y) + v(x, y) with g the roller's axial
profile drop and v the elastic deflection of both half-spaces; isothermal Newtonian Reynolds

    ∂X(ε ∂X P) + ∂Y(ε ∂Y P) − ∂X(ρ̄H) = 0,   ε = ρ̄H³/(η̄λ),

in the dimensionless variables of `line_ehl` (X = x/b, Y = y/b, P = p/p_h, H = hR/b², b and p_h
of the Hertz line contact under the load per flat length). Deflection: Love's rectangle
coefficients (`influence.love_rectangle`), H_el = (1/2π) Σ P_j C_ij, each cell mirrored at Y = 0.
Load balance over the whole roller, ∬P dX dY = (π/2) l/b.

Grid: half domain by symmetry. X ∈ [−4.5, 1.5] on nx uniform nodes (as `line_ehl`); Y
cell-centred on ny cells, a quarter of them uniform over the middle of the roller and the rest
uniform over the last 10 % of the flat and the crowned end, where the pressure spike and the end
constriction of the film sit. Symmetry (no flux) at Y = 0, p = 0 at the roller end.
Cavitation: the Fischer–Burmeister complementarity of `line_ehl`, node by node.

Solver: damped Newton with a dense Jacobian from the 1-D line solution extruded along the flat
length, inside `lax.custom_root` so the derivatives are implicit (checked against central
differences on a 17 × 16 grid). Dense means (nx−2)·ny ≤ 2500 unknowns: 3–7 s per solve at 25–41 × 48 on 2 cores
after a 6–7 s compile (`benchmarks/finite_line_ehl.py`); finer grids need a matrix-free
Newton–Krylov (not built). No load continuation yet: at seed 003's 2471 N the Newton from the
extruded start does not converge, and the result says so.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from .hertz import line_contact
from .influence import love_rectangle
from .line_ehl import (INLET, OUTLET, FluidParameters, _damped_newton, fischer_burmeister, line_film, reynolds_coefficients,
                       rolling_terms)
from .numerics import require_float64
from .roller_profile import RollerProfile, crown_drop

MAX_UNKNOWNS = 2500
NEWTON_STEPS = 30
FINE_START = 0.9  # the fine cells start at this fraction of the flat half-length


class FiniteLineFilm(eqx.Module):
    """Solution [SI] on the half domain y ≥ 0: x [m] (nx), y [m] cell centres (ny), pressure [Pa]
    and film [m] (nx, ny), central film at x = 0 on y = 0 [m], minimum film [m] and its y [m],
    whether Newton converged (residual below the tolerance, positive film), that residual [-]."""

    x: jax.Array
    y: jax.Array
    pressure: jax.Array
    thickness: jax.Array
    central: jax.Array
    minimum: jax.Array
    minimum_position: jax.Array
    converged: jax.Array
    residual: jax.Array


def axial_cells(count: int, flat_end: float, roller_end: float):
    """Cell edges [m] on [0, roller_end]: a quarter of the cells over [0, FINE_START·flat_end],
    the rest over the fine zone from there to the roller end (numpy: fixed by the geometry)."""
    coarse = max(count // 4, 1)
    split = FINE_START * flat_end
    return np.concatenate([np.linspace(0.0, split, coarse + 1), np.linspace(split, roller_end, count - coarse + 1)[1:]])


def check_grid(grid) -> tuple[int, int]:
    """ValueError unless (nx, ny) fits the dense Newton: nx ≥ 17, ny ≥ 8, (nx − 2)·ny ≤ MAX_UNKNOWNS."""
    nx, ny = (int(n) for n in grid)
    if nx < 17 or ny < 8 or (nx - 2) * ny > MAX_UNKNOWNS:
        raise ValueError(f"fidelity.grid: the finite-line EHL (dense Newton) needs nx ≥ 17, ny ≥ 8 and (nx − 2)·ny ≤ "
                         f"{MAX_UNKNOWNS}, got {[nx, ny]} ((nx − 2)·ny = {(nx - 2) * ny}); e.g. [33, 48]")
    return nx, ny


def finite_line_film(load, radius, speed, viscosity, pressure_viscosity, effective_modulus, profile: RollerProfile,
                     length: float, flat_length: float, grid=(33, 48), viscosity_law="roelands",
                     density_law="dowson_higginson", tolerance=1e-10) -> FiniteLineFilm:
    """Fully flooded isothermal EHL of a roller of finite length on its raceway (2-D, half domain).

    Args:
        load: roller load W [N] > 0.
        radius: reduced radius R [m] in the rolling direction.
        speed: mean entrainment speed u [m/s] > 0.
        viscosity: η₀ [Pa·s]; pressure_viscosity: α [1/Pa]; effective_modulus: E' [Pa].
        profile: the roller's axial profile (`roller_profile`); length: effective length l [m];
            flat_length: the length b and p_h are based on [m] (the flat of a circular profile).
        grid: (nx, ny) nodes along rolling and cells along the half roller (`check_grid`).
    """
    require_float64()
    nx, ny = check_grid(grid)
    hertz_contact = line_contact(load / flat_length, radius, effective_modulus)
    half_width, hertz_pressure = hertz_contact.half_width, hertz_contact.max_pressure
    speed_parameter = 12.0 * viscosity * speed * radius**2 / (half_width**3 * hertz_pressure)
    fluid = FluidParameters(speed_parameter, hertz_pressure, viscosity, pressure_viscosity, viscosity_law, density_law)

    x = np.linspace(INLET, OUTLET, nx)
    spacing = x[1] - x[0]
    edges = jnp.asarray(axial_cells(ny, 0.5 * flat_length, 0.5 * length)) / half_width
    y, widths = 0.5 * (edges[1:] + edges[:-1]), jnp.diff(edges)
    # elastic film (1/2π) Σ P C: cell (j, k) and its mirror image at −y
    offset_x = (x[:, None] - x[None, :])[:, None, :, None]
    below = (y[:, None] - y[None, :])[None, :, None, :]
    above = (y[:, None] + y[None, :])[None, :, None, :]  # the mirror image
    half_cell = 0.5 * widths[None, None, None, :]
    kernel = (love_rectangle(offset_x, below, 0.5 * spacing, half_cell)
              + love_rectangle(offset_x, above, 0.5 * spacing, half_cell)).reshape(nx * ny, nx * ny) / (2 * np.pi)
    profile_film = crown_drop(profile, y * half_width, length, effective_modulus, radius) * radius / half_width**2
    load_target = 0.5 * np.pi * flat_length / half_width  # ∬P dX dY over the whole roller

    def film(pressure, offset):
        elastic = (kernel @ pressure.reshape(-1)).reshape(nx, ny)
        return offset + 0.5 * jnp.asarray(x)[:, None] ** 2 + profile_film[None, :] + elastic

    def unpack(unknowns):
        return jnp.pad(unknowns[:-1].reshape(nx - 2, ny), ((1, 1), (0, 0))), unknowns[-1]

    def residual(unknowns):
        pressure, offset = unpack(unknowns)
        height = film(pressure, offset)
        density, flow = reynolds_coefficients(pressure, height, fluid)
        # along y, finite volumes: no flux at y = 0 (symmetry), p = 0 on the roller end
        flux_y = 0.5 * (flow[:, 1:] + flow[:, :-1]) * (pressure[:, 1:] - pressure[:, :-1]) / jnp.diff(y)
        end = -flow[:, -1:] * pressure[:, -1:] / (edges[-1] - y[-1])
        flux_y = jnp.concatenate([jnp.zeros((nx, 1)), flux_y, end], axis=1)
        poiseuille_y = (flux_y[:, 1:] - flux_y[:, :-1]) / widths
        reynolds = (rolling_terms(pressure, density * height, flow, spacing) + poiseuille_y[1:-1]) * spacing
        complementarity = fischer_burmeister(pressure[1:-1], reynolds)
        balance = (2.0 * spacing * jnp.sum(pressure * widths) - load_target) / load_target * 0.5 * np.pi
        return jnp.append(complementarity.reshape(-1), balance)

    # start: the 1-D solution under the load per flat length, extruded over the flat and tapered
    # off over the first half-width of the crown, scaled to the load; H₀ matching its central film
    line = line_film(*jax.lax.stop_gradient((load / flat_length, radius, speed, viscosity, pressure_viscosity,
                                             effective_modulus)),
                     nodes=129, viscosity_law=viscosity_law, density_law=density_law)
    line_pressure = jnp.interp(jnp.asarray(x), line.x / half_width, line.pressure / hertz_pressure)
    taper = jnp.clip(0.5 * flat_length / half_width + 1.0 - y, 0.0, 1.0)
    start = line_pressure[:, None] * taper[None, :]
    start = start * load_target / (2.0 * spacing * jnp.sum(start * widths))
    centre = int(np.argmin(np.abs(x)))
    offset = line.central * radius / half_width**2 - film(start, 0.0)[centre, 0]
    guess = jax.lax.stop_gradient(jnp.append(start[1:-1].reshape(-1), offset))

    solution = jax.lax.custom_root(
        residual, guess, solve=lambda function, initial: _damped_newton(function, initial, NEWTON_STEPS),
        tangent_solve=lambda linear, rhs: jnp.linalg.solve(jax.jacfwd(linear)(rhs), rhs))
    error = jnp.max(jnp.abs(residual(jax.lax.stop_gradient(solution))))
    pressure, offset = unpack(solution)
    thickness = film(pressure, offset) * half_width**2 / radius
    lowest = jnp.argmin(thickness)
    return FiniteLineFilm(jnp.asarray(x) * half_width, y * half_width, pressure * hertz_pressure, thickness,
                          thickness[centre, 0], thickness.reshape(-1)[lowest], y[lowest % ny] * half_width,
                          (error < tolerance) & (jnp.min(thickness) > 0), error)
