"""ISO 281:2007 and ISO 76:2006 ratings of thrust ball bearings (α = 90°, and thrust angular
contact, 45° ≤ α ≤ 75°), as GOST 18855-2013 and GOST 18854-2013 print the standards.

* `thrust_ball_dynamic_load_rating` — ISO 281 eqs. (5)–(8), b_m = 1.3, f_c of Table 4:
      C_a = b_m f_c Z^{2/3} D_w^1.8                       (α = 90°, D_w ≤ 25.4 mm)
      C_a = b_m f_c (cos α)^0.7 tan α Z^{2/3} D_w^1.8     (α ≠ 90°, D_w ≤ 25.4 mm)
  and 3.647 b_m f_c … D_w^1.4 above 25.4 mm [N, D_w in mm], Z the balls that carry load in one
  direction; Table 4's columns are f_c against D_w/D_pw (α = 90°) and D_w cos α/D_pw at α = 45°,
  60°, 75°, linearly interpolated between them (NaN outside the tabulated ratios and angles;
  GOST's OCR read where a column's steady course shows a dropped decimal point: 45.2, 58.2, 65.2,
  90.2, 85.2, 84.0).
* `thrust_ball_equivalent_dynamic_load` — ISO 281 eqs. (10)–(11), Table 5: P_a = F_a (α = 90°),
  else P_a = X F_r + Y F_a with e = 1.25 tan α and, for F_a/F_r > e (single direction always),
  X = 1.25 tan α (1 − ⅔ sin α), Y = 1; a double-direction bearing below e, X = (20/13) tan α
  (1 − ⅓ sin α), Y = (10/13) (1 − ⅓ sin α) (the closed forms of Table 5's rows).
* `thrust_ball_static_load_rating` — ISO 76 eq. (4): C₀a = f₀ Z D_w² sin α, f₀ of Table 1's
  thrust column at D_w cos α / D_pw (61.6 at α = 90°).
* `thrust_ball_equivalent_static_load` — ISO 76 eqs. (5)–(6): P₀a = F_a (α = 90°), else
  2.3 F_r tan α + F_a.
* `thrust_ball_raceway_ratings` — ISO/TS 16281:2008's raceway ratings of thrust ball bearings,
  the ball loads of a raceway life of 10⁶ revolutions (every ball loaded alike, so no 0.407,
  0.389 of the radial bearings' load distribution, and no 1.044):
      Q_ci = C_a / (Z sin α) (1 + λ^{10/3})^0.3,   Q_ce = C_a / (Z sin α) (1 + λ^{−10/3})^0.3,
      λ = ((1 − γ)/(1 + γ))^1.72 (f_i/f_e · (2 f_e − 1)/(2 f_i − 1))^0.41,   γ = D_w cos α / D_pw,
  so that under a pure axial load (Q_ei = Q_ee = F_a / (Z sin α)) L10r = (C_a/F_a)³ = L10, at
  any α: (1 + λ^{10/3})^{−1} + (1 + λ^{−10/3})^{−1} = 1.

All pure JAX, differentiable almost everywhere (piecewise-linear tables).
"""

import jax.numpy as jnp
import numpy as np

from ..params import _is_concrete
from .life import BM_BALL, raceway_ratio
from .radial_load_factors import radial_and_axial
from .static_safety import F0_RATIO

# ISO 281 Table 4: f_c of thrust ball bearings; rows at every 0.01 of the ratio from 0.01
FC_RATIO = np.round(np.arange(1, 36) * 0.01, 2)
FC_AXIAL = np.array([36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3, 75.4, 77.4, 79.3, 81.1, 82.7, 84.4,
                     85.9, 87.4, 88.8, 90.2, 91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8, 100.8, 101.9, 102.9,
                     103.9, 104.8, 105.8, 106.7])  # α = 90°, against D_w / D_pw
FC_ANGLES = np.radians([45.0, 60.0, 75.0])  # the angular-contact columns, against D_w cos α / D_pw
FC_ANGULAR = (
    np.array([42.1, 51.7, 58.2, 63.3, 67.3, 70.7, 73.5, 75.9, 78.0, 79.7, 81.1, 82.3, 83.3, 84.1, 84.7, 85.1, 85.4,
              85.5, 85.5, 85.4, 85.2, 84.9, 84.5, 84.0, 83.4, 82.8, 82.0, 81.3, 80.4, 79.6]),  # to 0.30
    np.array([39.2, 48.1, 54.2, 58.9, 62.6, 65.8, 68.4, 70.7, 72.6, 74.2, 75.5, 76.6, 77.5, 78.3, 78.8, 79.2, 79.5,
              79.6, 79.6, 79.5]),  # to 0.20
    np.array([37.3, 45.9, 51.7, 56.1, 59.7, 62.7, 65.2, 67.3, 69.2, 70.7]),  # to 0.10
)
# ISO 76 Table 1: f₀ of thrust ball bearings against D_w cos α / D_pw, 0.00 … 0.35
F0_THRUST = np.array([61.6, 60.8, 59.9, 59.1, 58.3, 57.5, 56.7, 55.9, 55.1, 54.3, 53.5, 52.7, 51.9, 51.2, 50.4, 49.6,
                      48.8, 48.0, 47.3, 46.5, 45.7, 45.0, 44.2, 43.5, 42.7, 41.9, 41.2, 40.5, 39.7, 39.0, 38.2, 37.5,
                      36.8, 36.0, 35.3, 34.6])
AXIAL = 0.5 * np.pi


def _axial(contact_angle) -> bool:
    """Whether α is 90° (a concrete value: a traced α is an angular-contact thrust bearing's)."""
    return _is_concrete(contact_angle) and abs(float(contact_angle) - AXIAL) < 1e-12


def _column(values, ratio):
    """f_c of one Table 4 column at `ratio`, NaN outside its tabulated range."""
    ratios = FC_RATIO[:len(values)]
    inside = (ratio >= ratios[0] - 1e-12) & (ratio <= ratios[-1] + 1e-12)
    return jnp.where(inside, jnp.interp(ratio, ratios, values), jnp.nan)


def thrust_ball_factor(ball_diameter, pitch_diameter, contact_angle):
    """f_c [-] of ISO 281 Table 4 at α [rad]: the α = 90° column at D_w/D_pw, or between the 45°,
    60° and 75° columns (linear in α) at D_w cos α / D_pw; NaN outside the table."""
    if _axial(contact_angle):
        return _column(FC_AXIAL, ball_diameter / pitch_diameter)
    ratio = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    columns = jnp.stack([_column(values, ratio) for values in FC_ANGULAR])
    inside = (contact_angle >= FC_ANGLES[0] - 1e-12) & (contact_angle <= FC_ANGLES[-1] + 1e-12)
    between = jnp.interp(contact_angle, FC_ANGLES, jnp.arange(3.0))  # the angle as a column position
    lower = jnp.clip(jnp.floor(between), 0, 1).astype(int)
    share = between - lower
    value = (1.0 - share) * columns[lower] + share * columns[lower + 1]
    return jnp.where(inside, value, jnp.nan)


def thrust_ball_dynamic_load_rating(ball_count, ball_diameter, pitch_diameter, contact_angle):
    """C_a [N] of ISO 281 eqs. (5)–(8) (module docstring): Z balls a direction, D_w, D_pw [m], α [rad]."""
    ball_mm = ball_diameter * 1e3
    fc = thrust_ball_factor(ball_diameter, pitch_diameter, contact_angle)
    angle_factor = 1.0 if _axial(contact_angle) else jnp.cos(contact_angle) ** 0.7 * jnp.tan(contact_angle)
    common = BM_BALL * fc * angle_factor * ball_count ** (2.0 / 3.0)
    return jnp.where(ball_mm <= 25.4, common * ball_mm**1.8, common * 3.647 * ball_mm**1.4)


def thrust_ball_load_factors(contact_angle, double_direction: bool):
    """(e, X, Y for F_a/F_r > e, X₁, Y₁ for F_a/F_r ≤ e) of ISO 281 Table 5 at α [rad] < 90° (the
    single-direction bearing's ≤ e row does not apply: its X₁, Y₁ are the > e row's)."""
    tangent, sine = jnp.tan(contact_angle), jnp.sin(contact_angle)
    x = 1.25 * tangent * (1.0 - 2.0 / 3.0 * sine)
    if not double_direction:
        return 1.25 * tangent, x, 1.0, x, 1.0
    return (1.25 * tangent, x, 1.0, 20.0 / 13.0 * tangent * (1.0 - sine / 3.0),
            10.0 / 13.0 * (1.0 - sine / 3.0))


def thrust_ball_equivalent_dynamic_load(force, contact_angle, double_direction: bool = False):
    """P_a [N] of ISO 281 eqs. (10)–(11) under [Fx, Fy, Fz] [N] (module docstring)."""
    radial, axial = radial_and_axial(force)
    if _axial(contact_angle):
        return axial
    e, x, y, x1, y1 = thrust_ball_load_factors(contact_angle, double_direction)
    return jnp.where(axial > e * radial, x * radial + y * axial, x1 * radial + y1 * axial)


def thrust_ball_static_load_rating(ball_count, ball_diameter, pitch_diameter, contact_angle):
    """C₀a = f₀ Z D_w² sin α [N] (ISO 76 eq. (4)), f₀ of Table 1's thrust column (D_w [m] in mm)."""
    ratio = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    inside = ratio <= F0_RATIO[len(F0_THRUST) - 1] + 1e-12
    f0 = jnp.where(inside, jnp.interp(ratio, F0_RATIO[:len(F0_THRUST)], F0_THRUST), jnp.nan)
    return f0 * ball_count * (ball_diameter * 1e3) ** 2 * jnp.sin(contact_angle)


def thrust_ball_equivalent_static_load(force, contact_angle):
    """P₀a [N] of ISO 76 eqs. (5)–(6): F_a at α = 90°, else 2.3 F_r tan α + F_a."""
    radial, axial = radial_and_axial(force)
    if _axial(contact_angle):
        return axial
    return 2.3 * radial * jnp.tan(contact_angle) + axial


def thrust_ball_raceway_ratings(rating, ball_count, ball_diameter, pitch_diameter, contact_angle, inner_groove_ratio,
                                outer_groove_ratio):
    """(Q_ci, Q_ce) [N]: the shaft washer's and housing washer's ball loads for a raceway life of
    10⁶ revolutions (ISO/TS 16281, thrust ball bearings; module docstring) from C_a [N], Z, D_w,
    D_pw [m], α [rad] and the grooves' f_i, f_e [-]."""
    gamma = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    ratio = raceway_ratio(gamma, inner_groove_ratio, outer_groove_ratio)
    base = rating / (ball_count * jnp.sin(contact_angle))
    return base * (1.0 + ratio ** (10.0 / 3.0)) ** 0.3, base * (1.0 + ratio ** (-10.0 / 3.0)) ** 0.3
