"""Bearing fatigue life: ISO 281:2007 basic rating, ISO/TS 16281:2008 reference rating life.

* `basic_dynamic_load_rating` — ISO 281 eq. (2) with f_c from Table 2 (single-row radial contact
  groove and angular contact groove ball bearings), b_m = 1.3:
      C_r = b_m f_c (i cos α)^0.7 Z^{2/3} D_w^1.8          (D_w ≤ 25.4 mm)
      C_r = 3.647 b_m f_c (i cos α)^0.7 Z^{2/3} D_w^1.4    (D_w > 25.4 mm),   D_w in mm, C_r in N,
  α the nominal contact angle (0 for deep-groove bearings).
* `equivalent_dynamic_load` and `basic_rating_life` — ISO 281 eqs. (3)–(4), Table 3 (`radial_load_factors`):
  P = X F_r + Y F_a, L10 = (C_r/P)³ [10⁶ revolutions]; up to α = 15° e and Y follow the relative axial
  load f₀ i F_a/C₀r = F_a/(Z D_w² cos α) [N, mm] (C₀r = f₀ i Z D_w² cos α by ISO 76), above it they are
  constants.
* `reference_rating_life` — ISO/TS 16281 eqs. (19)–(29): raceway ratings Q_ci, Q_ce from C_r, the
  equivalent ball loads of the rotating inner ring (cubic mean) and the fixed outer ring (10/3 mean)
  from the computed load distribution, and L10r = ((Q_ci/Q_ei)^{-10/3} + (Q_ce/Q_ee)^{-10/3})^{-9/10}.
All pure JAX (piecewise-linear table interpolation), differentiable almost everywhere.
"""

import jax.numpy as jnp
import numpy as np

from ..params import BallBearing
from . import radial_load_factors

# ISO 281:2007 Table 2, first column: D_w cos α / D_pw → f_c.
FC_RATIO = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.12, 0.14, 0.16, 0.18,
                      0.20, 0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38, 0.40])
FC_VALUE = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5, 57.5, 58.8, 59.6, 59.9,
                      59.9, 59.6, 59.0, 58.2, 57.1, 56.0, 54.6, 53.2, 51.7, 50.0, 48.4])
# ISO 281:2007 Table 2, self-aligning ball bearings, at every 0.01 of D_w cos α / D_pw from 0.01
# to 0.40 (GOST 18855-2013; its 16.6 at 0.06, out of the column's steady rise, read as 18.6)
SELF_ALIGNING_FC_RATIO = np.round(np.arange(1, 41) * 0.01, 2)
SELF_ALIGNING_FC_VALUE = np.array([9.9, 12.4, 14.3, 15.9, 17.3, 18.6, 19.9, 21.1, 22.3, 23.4, 24.5, 25.6, 26.6, 27.7,
                                   28.7, 29.7, 30.7, 31.7, 32.6, 33.5, 34.4, 35.2, 36.1, 36.8, 37.5, 38.2, 38.8, 39.4,
                                   39.9, 40.3, 40.6, 40.9, 41.1, 41.2, 41.3, 41.3, 41.2, 41.0, 40.7, 40.4])
BM_BALL = 1.3  # ISO 281 Table 1: radial and angular-contact ball bearings, self-aligning ones too

def basic_dynamic_load_rating(bearing: BallBearing):
    """ISO 281 basic dynamic radial load rating C_r [N] of a single-row ball bearing from its geometry."""
    return ball_dynamic_load_rating(bearing.ball_count, bearing.ball_diameter, bearing.pitch_diameter,
                                    bearing.nominal_contact_angle)


def ball_dynamic_load_rating(ball_count, ball_diameter, pitch_diameter, contact_angle, rows=1):
    """ISO 281 C_r [N] of `rows` rows of Z balls of D_w on D_pw [m] at the nominal angle α [rad], f_c of
    Table 2's groove column (`_dynamic_load_rating`)."""
    fc = jnp.interp(ball_diameter * jnp.cos(contact_angle) / pitch_diameter, FC_RATIO, FC_VALUE)
    return _dynamic_load_rating(ball_count, ball_diameter, contact_angle, fc, rows)


def self_aligning_load_rating(bearing: BallBearing, rows=2):
    """ISO 281 C_r [N] of a self-aligning ball bearing of `rows` rows of `bearing`'s balls, f_c of
    Table 2's self-aligning column."""
    return _dynamic_load_rating(bearing.ball_count, bearing.ball_diameter, bearing.nominal_contact_angle,
                                jnp.interp(_diameter_ratio(bearing), SELF_ALIGNING_FC_RATIO, SELF_ALIGNING_FC_VALUE), rows)


def _diameter_ratio(bearing: BallBearing):
    return bearing.ball_diameter * jnp.cos(bearing.nominal_contact_angle) / bearing.pitch_diameter


def _dynamic_load_rating(ball_count, ball_diameter, contact_angle, fc, rows):
    """ISO 281 eq. (2): b_m f_c (i cos α)^0.7 Z^{2/3} D_w^1.8 (D_w ≤ 25.4 mm), else 3.647 b_m f_c
    (i cos α)^0.7 Z^{2/3} D_w^1.4 [N]."""
    ball_mm = ball_diameter * 1e3
    common = BM_BALL * fc * (rows * jnp.cos(contact_angle)) ** 0.7 * ball_count ** (2.0 / 3.0)
    return jnp.where(ball_mm <= 25.4, common * ball_mm**1.8, common * 3.647 * ball_mm**1.4)


def ball_load_rating(bearing: BallBearing):
    """C_r [N] of a ball bearing: its own (`BallBearing.dynamic_load_rating`) where given, else
    ISO 281's from its geometry (`basic_dynamic_load_rating`)."""
    return basic_dynamic_load_rating(bearing) if bearing.dynamic_load_rating is None else bearing.dynamic_load_rating


def equivalent_dynamic_load(bearing: BallBearing, force, double_row: bool = False):
    """ISO 281 equivalent dynamic radial load P = X F_r + Y F_a [N] of a single-row ball bearing (or,
    `double_row`, of two rows of `bearing`'s) for force [Fx, Fy, Fz] [N]: Table 3 at its nominal
    contact angle (`BallBearing.nominal_contact_angle`; 0°…45°, NaN beyond) and relative axial load
    of one row's balls, f₀ i F_a/C₀r = F_a/(Z D_w² cos α) (`radial_load_factors`)."""
    radial, axial = radial_load_factors.radial_and_axial(force)
    angle = bearing.nominal_contact_angle
    relative = radial_load_factors.relative_axial_load(axial, bearing.ball_count, bearing.ball_diameter, angle)
    return radial_load_factors.equivalent_dynamic_load(radial, axial, angle, relative, double_row)


def self_aligning_equivalent_dynamic_load(force, contact_angle):
    """ISO 281 Table 3, double-row self-aligning ball bearings: P = F_r + 0.42 cot α F_a where
    F_a/F_r ≤ e = 1.5 tan α, else 0.65 F_r + 0.65 cot α F_a [N] (α [rad] > 0)."""
    radial, axial = radial_load_factors.radial_and_axial(force)
    cotangent = 1.0 / jnp.tan(contact_angle)
    light = axial <= 1.5 * jnp.tan(contact_angle) * radial
    return jnp.where(light, radial + 0.42 * cotangent * axial, 0.65 * radial + 0.65 * cotangent * axial)


# ISO 281 eq. (4): L10 = (C/P)^p, p by rolling element
BASIC_LIFE_EXPONENTS = {"ball": 3.0, "roller": 10.0 / 3.0}


def basic_life_exponent(rolling_element: str) -> float:
    """p of ISO 281 eq. (4) for "ball" (3) or "roller" (10/3) bearings."""
    return BASIC_LIFE_EXPONENTS[rolling_element]


def basic_rating_life(rating, equivalent_load):
    """ISO 281 basic rating life L10 = (C/P)³ [10⁶ revolutions] of a ball bearing."""
    return (rating / equivalent_load) ** 3


def raceway_ratio(gamma, inner_groove_ratio, outer_groove_ratio):
    """((1 − γ)/(1 + γ))^1.72 (f_i/f_e · (2 f_e − 1)/(2 f_i − 1))^0.41 [-]: ISO/TS 16281's ratio of
    the inner to the outer raceway's rating, before a bearing type's own factor (γ = D_w cos α / D_pw)."""
    conformity = (inner_groove_ratio / outer_groove_ratio * (2.0 * outer_groove_ratio - 1.0)
                  / (2.0 * inner_groove_ratio - 1.0)) ** 0.41
    return ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * conformity


def raceway_ratings(bearing: BallBearing, rating):
    """ISO/TS 16281 eqs. (19)–(20): ball loads Q_ci, Q_ce [N] for a raceway life of 10⁶ revolutions."""
    angle = bearing.nominal_contact_angle
    gamma = bearing.ball_diameter * jnp.cos(angle) / bearing.pitch_diameter
    ratio = 1.044 * raceway_ratio(gamma, bearing.inner_groove_ratio, bearing.outer_groove_ratio)
    base = rating / (bearing.ball_count * jnp.cos(angle))
    inner = base / 0.407 * (1.0 + ratio ** (10.0 / 3.0)) ** 0.3
    outer = base / 0.389 * (1.0 + ratio ** (-10.0 / 3.0)) ** 0.3
    return inner, outer


def reference_rating_life(bearing: BallBearing, rating, inner_loads, outer_loads):
    """ISO/TS 16281 basic reference rating life L10r [10⁶ revolutions], inner ring rotating.

    Q_ei = (Σ Q_i³ / Z)^{1/3} (rotating ring), Q_ee = (Σ Q_o^{10/3} / Z)^{3/10} (fixed ring),
    L10r = ((Q_ci/Q_ei)^{-10/3} + (Q_ce/Q_ee)^{-10/3})^{-9/10}. Inner and outer loads differ at speed.
    """
    z = bearing.ball_count
    equivalent_inner = (jnp.sum(inner_loads**3) / z) ** (1.0 / 3.0)
    equivalent_outer = (jnp.sum(outer_loads ** (10.0 / 3.0)) / z) ** 0.3
    rating_inner, rating_outer = raceway_ratings(bearing, rating)
    damage = (equivalent_inner / rating_inner) ** (10.0 / 3.0) + (equivalent_outer / rating_outer) ** (10.0 / 3.0)
    return damage ** (-0.9)


SYSTEM_WEIBULL_SLOPE = 10.0 / 9.0  # e of ball bearings (Lundberg–Palmgren; ISO/TS 16281's raceway combination)


def system_life(lives, slope=SYSTEM_WEIBULL_SLOPE):
    """L10 of bearings that all must survive [the lives' unit]: L = (Σ_k L_k^{−e})^{−1/e}
    (Lundberg & Palmgren's product of survival probabilities with Weibull slope e; Harris &
    Kotzalas vol. 2, ch. 11). An unloaded bearing's infinite life adds nothing."""
    return jnp.sum(jnp.asarray(lives) ** (-slope)) ** (-1.0 / slope)
