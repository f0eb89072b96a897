"""The classical way (the crowning paper's method): a dense influence matrix and an active set, NumPy.

The crowning paper builds the flexibility matrix of every cell pair from Love's rectangle formula,
solves the linear system for the pressures and the approach with the load equation, removes the cells
whose pressure came out negative, and solves again until no pressure is negative (cells that
then penetrate are put back). This is that method, written the usual way: `numpy.linalg.solve`
(LAPACK LU) on the bordered system

    [ C_AA  −1 ] [p_A]   [−h₀_A]
    [ ΔA·1ᵀ  0 ] [ δ ] = [  W  ]

with the initial contact set taken as the Hertz-slice contact (|x| < b of each slice; the paper
starts from an estimated half-width a₀ in the same way). The matrix is built in place and factored
in place (`scipy.linalg.solve(overwrite_a=True)`, LAPACK LU), so a 21 000-cell set needs 3.5 GB.
"""

import numpy as np
import scipy.linalg


def love_rectangle(x, y, a, b):
    """∫∫ dx'dy'/r over |x'| ≤ a, |y'| ≤ b seen from (x, y) (Love 1929): the closed form of
    `diffbearing.contact.influence.love_rectangle`, in NumPy so that the baseline runs without JAX."""
    def primitive(u, v):
        return u * np.arcsinh(v / np.abs(u)) + v * np.arcsinh(u / np.abs(v))

    return primitive(x + a, y + b) - primitive(x + a, y - b) - primitive(x - a, y + b) + primitive(x - a, y - b)


def influence_block(rows, columns, ix, iy, cell_x, cell_y, modulus):
    """C[i, j] [m/Pa] between the cells `rows` and `columns` (flat indices into ix, iy)."""
    dx = (ix[rows, None] - ix[None, columns]) * cell_x
    dy = (iy[rows, None] - iy[None, columns]) * cell_y
    return 2.0 / (np.pi * modulus) * love_rectangle(dx, dy, 0.5 * cell_x, 0.5 * cell_y)


def solve_dense_active_set(gap, load, cell_x, cell_y, modulus, initial_contact, max_rounds=50):
    """Pressure [Pa] on the grid, approach δ [m], and the number of dense solves.

    With `max_rounds` reached before the set settles it returns None for the pressure (used to
    time the first dense solve alone where the whole iteration would take too long).
    """
    nx, ny = gap.shape
    ix, iy = np.divmod(np.arange(nx * ny), ny)
    active = initial_contact.ravel().copy()
    area = cell_x * cell_y
    flat_gap = gap.ravel()
    for rounds in range(1, max_rounds + 1):
        cells = np.flatnonzero(active)
        n = len(cells)
        system = np.empty((n + 1, n + 1))
        for start in range(0, n, 2048):  # built in row blocks, in place
            rows = cells[start:start + 2048]
            system[start:start + len(rows), :n] = influence_block(rows, cells, ix, iy, cell_x, cell_y, modulus)
        system[:n, n] = -1.0
        system[n, :n] = area
        system[n, n] = 0.0
        solution = scipy.linalg.solve(system, np.concatenate([-flat_gap[cells], [load]]), overwrite_a=True,
                                      check_finite=False)
        del system
        pressure_active, approach = solution[:n], solution[n]
        negative = pressure_active < 0
        if negative.any():
            active[cells[negative]] = False
            continue
        pressure = np.zeros(nx * ny)
        pressure[cells] = pressure_active
        # gap of the cells outside the set: put back any that penetrate (checked on the free cells)
        outside = np.flatnonzero(~active)
        free_gap = _free_gap(pressure, flat_gap, approach, ix, iy, outside, cells, cell_x, cell_y, modulus)
        penetrating = outside[free_gap < 0]
        if len(penetrating) == 0:
            return pressure.reshape(nx, ny), approach, rounds
        active[penetrating] = True
    return None, approach, max_rounds


def _free_gap(pressure, flat_gap, approach, ix, iy, outside, cells, cell_x, cell_y, modulus):
    """Gap h = h₀ + C p − δ [m] at the cells outside the contact set."""
    gaps = np.empty(len(outside))
    for start in range(0, len(outside), 2048):
        rows = outside[start:start + 2048]
        influence = influence_block(rows, cells, ix, iy, cell_x, cell_y, modulus)
        gaps[start:start + 2048] = flat_gap[rows] + influence @ pressure[cells] - approach
    return gaps
