"""ISO 281:2007 Table 3: the factors e, X and Y of the equivalent dynamic load of radial ball bearings,
P = X F_r + Y F_a, for every tabulated nominal contact angle α (0°, 5°…45°), single and double row.

Radial contact groove bearings (α = 0) and angular contact ones with α = 5°, 10° and 15° take e and Y
from the relative axial load f₀ i F_a / C₀r; with C₀r = f₀ i Z D_w² cos α (ISO 76, [N, mm]) that is
F_a / (Z D_w² cos α), which `relative_axial_load` returns. Above 15° the factors are constants. Within
a block, and between angles, values are interpolated linearly (the table's note, as NSK, NTN, JTEKT and
MinebeaMitsumi apply it); a relative axial load outside the block's column is held at its end row (the
table gives no values there; at 15° the last two rows are equal). A single-row bearing of α = 5° takes
the radial-contact block (the table's instruction for that cell).

    single row:  F_a/F_r ≤ e: X = 1, Y = 0;          F_a/F_r > e: X, Y of the table
    double row:  F_a/F_r ≤ e: X = 1, Y = Y₁;         F_a/F_r > e: X₂, Y₂

Sources, each cell in at least two of them (docs/theory.md §Equivalent dynamic load): ISO 281:2007 Table 3
as transcribed in an open ISO 281 implementation; NSK Rolling Bearings (pp. B51, Б 52), GMN, ZKL, Koyo and
LYC catalogues (the same e, X, Y over the 1990 edition's i F_a/C₀ column); SKF's 33 D / 32 A series for the
45° and 30° double-row cells. The 5° and 10° columns are F_a/(Z D_w² cos α) at 25…1000 psi, the rule that
also reproduces the catalogues' printed 15° column.
"""

import jax.numpy as jnp
import numpy as np

# Relative axial load f₀ i F_a / C₀r of each load-dependent block (α = 0°, 5°, 10°, 15°).
BLOCK_ANGLES = np.radians([0.0, 5.0, 10.0, 15.0])
BLOCK_RELATIVE_AXIAL = np.array([
    [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89],
    [0.173, 0.346, 0.692, 1.04, 1.38, 2.08, 3.46, 5.19, 6.92],
    [0.175, 0.35, 0.7, 1.05, 1.4, 2.1, 3.5, 5.25, 7.0],
    [0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35, 7.14],
])
_RADIAL_E = [0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44]
_RADIAL_Y = [2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00]
# Single row (the 5° cell: "use the values of radial contact groove ball bearings", its column too).
SINGLE_RELATIVE_AXIAL = BLOCK_RELATIVE_AXIAL[[0, 0, 2, 3]]
SINGLE_E = np.array([_RADIAL_E, _RADIAL_E,
                     [0.29, 0.32, 0.36, 0.38, 0.40, 0.44, 0.49, 0.54, 0.54],
                     [0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56]])
SINGLE_X = np.array([0.56, 0.56, 0.46, 0.44])
SINGLE_Y = np.array([_RADIAL_Y, _RADIAL_Y,
                     [1.88, 1.71, 1.52, 1.41, 1.34, 1.23, 1.10, 1.01, 1.00],
                     [1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00]])
# Double row: e; Y₁ (F_a/F_r ≤ e, X = 1); X₂, Y₂ (F_a/F_r > e).
DOUBLE_E = np.array([_RADIAL_E,
                     [0.23, 0.26, 0.30, 0.34, 0.36, 0.40, 0.45, 0.50, 0.52],
                     SINGLE_E[2], SINGLE_E[3]])
DOUBLE_Y1 = np.array([np.zeros(9),
                      [2.78, 2.40, 2.07, 1.87, 1.75, 1.58, 1.39, 1.26, 1.21],
                      [2.18, 1.98, 1.76, 1.63, 1.55, 1.42, 1.27, 1.17, 1.16],
                      [1.65, 1.57, 1.46, 1.38, 1.34, 1.26, 1.14, 1.12, 1.12]])
DOUBLE_X2 = np.array([0.56, 0.78, 0.75, 0.72])
DOUBLE_Y2 = np.array([_RADIAL_Y,
                      [3.74, 3.23, 2.78, 2.52, 2.36, 2.13, 1.87, 1.69, 1.63],
                      [3.06, 2.78, 2.47, 2.29, 2.18, 2.00, 1.79, 1.64, 1.63],
                      [2.39, 2.28, 2.11, 2.00, 1.93, 1.82, 1.66, 1.63, 1.63]])

# α = 20°…45°: constants.
FIXED_ANGLES = np.radians([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
FIXED_E = np.array([0.57, 0.68, 0.80, 0.95, 1.14, 1.34])
FIXED_SINGLE_X = np.array([0.43, 0.41, 0.39, 0.37, 0.35, 0.33])
FIXED_SINGLE_Y = np.array([1.00, 0.87, 0.76, 0.66, 0.57, 0.50])
FIXED_DOUBLE_Y1 = np.array([1.09, 0.92, 0.78, 0.66, 0.55, 0.47])
FIXED_DOUBLE_X2 = np.array([0.70, 0.67, 0.63, 0.60, 0.57, 0.54])
FIXED_DOUBLE_Y2 = np.array([1.63, 1.41, 1.24, 1.07, 0.93, 0.81])

ANGLES = np.concatenate([BLOCK_ANGLES, FIXED_ANGLES])  # the table's rows, 0°…45°
LARGEST_ANGLE = float(ANGLES[-1])  # rad: beyond 45° ISO 281 rates the bearing as a thrust bearing (Table 4)


def radial_and_axial(force):
    """(F_r, F_a) [N] ≥ 0 of a load [Fx, Fy, Fz] [N]."""
    return jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])


def relative_axial_load(axial_load, ball_count, ball_diameter, contact_angle):
    """f₀ i F_a / C₀r = F_a / (Z D_w² cos α) [N/mm²] with C₀r of ISO 76 (F_a [N], D_w [m], α [rad])."""
    return axial_load / (ball_count * (ball_diameter * 1e3) ** 2 * jnp.cos(contact_angle))


def _block(columns, table, relative_axial):
    """One value per block (4,) at the relative axial load, each block's `table` row over its column."""
    return jnp.stack([jnp.interp(relative_axial, columns[k], table[k]) for k in range(len(table))])


def load_factors(contact_angle, relative_axial, double_row: bool = False):
    """(e, X, Y) where F_a/F_r > e, and Y₁ (double row, F_a/F_r ≤ e, X = 1; 0 for a single row) [-]
    at the nominal contact angle α [rad] (0…45°) and `relative_axial_load`. Outside 0°…45° NaN."""
    if double_row:
        columns, e, x, y, y1 = BLOCK_RELATIVE_AXIAL, DOUBLE_E, DOUBLE_X2, DOUBLE_Y2, DOUBLE_Y1
        fixed = (FIXED_E, FIXED_DOUBLE_X2, FIXED_DOUBLE_Y2, FIXED_DOUBLE_Y1)
    else:
        columns, e, x, y, y1 = SINGLE_RELATIVE_AXIAL, SINGLE_E, SINGLE_X, SINGLE_Y, np.zeros_like(SINGLE_Y)
        fixed = (FIXED_E, FIXED_SINGLE_X, FIXED_SINGLE_Y, np.zeros(6))
    rows = (_block(columns, e, relative_axial), jnp.asarray(x), _block(columns, y, relative_axial),
            _block(columns, y1, relative_axial))
    inside = (contact_angle >= -1e-12) & (contact_angle <= LARGEST_ANGLE + 1e-12)
    return tuple(jnp.where(inside, jnp.interp(contact_angle, ANGLES, jnp.concatenate([row, values])), jnp.nan)
                 for row, values in zip(rows, fixed))


def equivalent_dynamic_load(radial_load, axial_load, contact_angle, relative_axial, double_row: bool = False):
    """P = X F_r + Y F_a [N] (ISO 281 eq. (3), Table 3) for F_r, F_a ≥ 0 [N] at the nominal contact
    angle α [rad] and `relative_axial_load`: X = 1 and Y = 0 (single row) or Y₁ (double row) where
    F_a ≤ e F_r."""
    e, x, y, y1 = load_factors(contact_angle, relative_axial, double_row)
    light = axial_load <= e * radial_load
    return jnp.where(light, radial_load + y1 * axial_load, x * radial_load + y * axial_load)
