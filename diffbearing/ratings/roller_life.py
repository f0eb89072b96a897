"""Roller-bearing fatigue life: ISO 281:2007 basic rating, ISO/TS 16281:2008 §5 lamina reference rating life.

* `roller_dynamic_load_rating` — ISO 281, basic dynamic radial load rating of radial roller bearings
  (its equation and table numbers are not confirmed here: f_c from the table of radial roller
  bearings, cited as Table 7; b_m = 1.1 of cylindrical, tapered and needle roller bearings, Table 1):
      C_r = b_m f_c (i L_we cos α)^{7/9} Z^{3/4} D_we^{29/27}      D_we, L_we in mm, C_r in N.
* `lamina_load` — ISO/TS 16281 eqs. (34)–(37), the lamina load-deflection law: a roller of
  effective length L_we is cut into n_s laminae of width L_we/n_s; lamina k of roller j carries
      q_jk = c_s δ_jk^{10/9},   c_s = c_L / n_s,   c_L = 35948 L_we^{8/9}   [N, mm, steel],
  with δ_jk the approach of the whole roller between its two raceways (inner + outer contact in
  series: δ_j = δ_r cos ψ_j − s/2, eq. (38)). This module takes the approach of ONE contact.
* `lamina_ratings` — ISO/TS 16281 eqs. (47)–(49), (56)–(57): the roller loads Q_ci, Q_ce of a
  raceway life of 10⁶ revolutions, from C_r, and the lamina ratings q_c = Q_c n_s^{−7/9}.
* `roller_reference_rating_life` — ISO/TS 16281 eqs. (61)–(65), inner ring rotating: the equivalent
  lamina loads q_ei,k = (Σ_j q_jk⁴ / Z)^{1/4} (rotating ring), q_ee,k = (Σ_j q_jk^{9/2} / Z)^{2/9}
  (fixed ring) and L10r = (Σ_k [(q_ci/q_ei,k)^{−9/2} + (q_ce/q_ee,k)^{−9/2}])^{−8/9}.
All pure JAX, differentiable almost everywhere (piecewise-linear Table 7). The edge-stress factors
f_i, f_e (eqs. (58)–(60); eq. (60) is an approximation for the profiles of eqs. (42)–(44)) and the
roller profile are the caller's: the lamina loads come in as computed, f-weighted if wanted.

Sources. The standards are not public. ISO/TS 16281's equations and their numbers are taken from two
independent open implementations that agree on every one used here — github.com/minzhun/ISO16281
(RollerBearing.py) and github.com/JRaposo-m/AxisForge-Shaft-Bearing-Gear-System-Analysis-Platform
(solvers/.../ISO_16281/Roller_Bearing/, core/.../bearings/capacity.py). Table 7 is checked in the
tests against the closed form of ISO/TR 1281-1 that it tabulates (as restated in AxisForge).
"""

import jax.numpy as jnp
import numpy as np

from ..bearings.roller.roller_geometry import mean_roller_diameter
from ..numerics import positive_power

# ISO 281:2007 f_c of radial roller bearings (Table 7), D_we cos α / D_pw → f_c. Each entry equals the closed
# form of ISO/TR 1281-1, 207.9 λν γ^{2/9}(1−γ)^{29/27}(1+γ)^{−1/4}[1 + (1.04((1−γ)/(1+γ))^{143/108})^{9/2}]^{−2/9}
# with λν = 0.83, rounded to 0.1 (tests/test_roller_life.py). Outside 0.01…0.30 the end value is held.
FC_RATIO = np.round(np.arange(1, 31) * 0.01, 2)
FC_VALUE = np.array([52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2, 85.4, 86.4, 87.1, 87.7, 88.2,
                     88.5, 88.7, 88.8, 88.8, 88.7, 88.5, 88.2, 87.9, 87.5, 87.0, 86.4, 85.8, 85.2, 84.5, 83.8])
# ISO 281:2007 Table 1: b_m for radial cylindrical, tapered and needle roller bearings (machined rings).
BM_ROLLER = 1.1
# ISO/TS 16281 eq. (49): λν of radial roller bearings (line contact), which eqs. (47)–(48) divide out
# of C_r, since the lamina loads carry the edge stresses λν stands for in ISO 281.
LAMBDA_NU = 0.83
# ISO/TS 16281 eq. (35), steel on steel: c_L = LAMINA_STIFFNESS · L_we^{8/9} [N/mm^{10/9}, L_we in mm] is
# the load-deflection constant of a WHOLE roller of effective length L_we between its two raceways,
# Q = c_L δ^{10/9} with δ [mm] the approach of the roller (inner and outer contact in series) and Q [N];
# eq. (37) splits it evenly over the n_s laminae, c_s = c_L/n_s. For one contact (half the approach):
# Q = 35948 · 2^{10/9} L^{8/9} δ₁^{10/9}, i.e. δ₁ = 3.97e-5 Q^{0.9}/L^{0.8} [mm, N], 3 % above
# Palmgren's 3.84e-5 (Harris) — the constant is ISO's, not Palmgren's.
LAMINA_STIFFNESS = 35948.0
LAMINA_EXPONENT = 10.0 / 9.0


def roller_ratio(roller_diameter, contact_angle, pitch_diameter):
    """γ = D_we cos α / D_pw [–] (ISO 281 Table 7, ISO/TS 16281 eqs. (47)–(48))."""
    return roller_diameter * jnp.cos(contact_angle) / pitch_diameter


def roller_dynamic_load_rating(roller_count, roller_diameter, effective_length, contact_angle, pitch_diameter, rows=1):
    """ISO 281 basic dynamic radial load rating C_r [N] of a radial roller bearing (f_c of Table 7, b_m = 1.1).

    Inputs in SI: roller diameter D_we and effective roller length L_we [m], nominal contact angle α
    [rad] (0 for cylindrical and needle roller bearings), pitch diameter D_pw [m]; `rows` is i.
    """
    fc = jnp.interp(roller_ratio(roller_diameter, contact_angle, pitch_diameter), FC_RATIO, FC_VALUE)
    length_mm, diameter_mm = effective_length * 1e3, roller_diameter * 1e3
    return (BM_ROLLER * fc * (rows * length_mm * jnp.cos(contact_angle)) ** (7.0 / 9.0)
            * roller_count ** 0.75 * diameter_mm ** (29.0 / 27.0))


def roller_bearing_load_rating(bearing, raceways):
    """ISO 281 C_r [N] of a whole roller bearing (`roller_geometry.RollerBearing`, its
    `roller_equilibrium.RollerRaceways`): the mean roller diameter, the cup angle."""
    return roller_dynamic_load_rating(bearing.roller_count, mean_roller_diameter(bearing), bearing.length,
                                      raceways.cup_angle, raceways.pitch_diameter)


def lamina_load(approach, lamina_width, effective_length):
    """ISO/TS 16281 eqs. (34)–(37): force [N] of one lamina of width w [m] for an approach a [m] of ONE contact.

    The standard's law is for the roller's total approach δ between both raceways, q = (c_L/n_s) δ^{10/9}
    with c_L = 35948 L_we^{8/9} [N, mm]. Its constant does not depend on the raceway, so the inner and
    outer contact of a lamina share δ equally, δ = 2a, and with c_L/n_s = 35948 w L_we^{−1/9}:
        q = 35948 · 2^{10/9} · w L_we^{−1/9} · a^{10/9}      [N; w, L_we, a in mm].
    `lamina_width` w = L_we/n_s for the standard's equal laminae; L_we [m] enters because the line-contact
    law is not linear in length (the whole roller is the unit it was fitted for). a ≤ 0 gives exactly 0
    with a zero (finite) gradient (`numerics.positive_power`).
    """
    width_mm, length_mm = lamina_width * 1e3, effective_length * 1e3
    stiffness = LAMINA_STIFFNESS * 2.0**LAMINA_EXPONENT * width_mm * length_mm ** (-1.0 / 9.0)
    return stiffness * positive_power(approach * 1e3, LAMINA_EXPONENT)


def lamina_ratings(rating, roller_count, roller_diameter, contact_angle, pitch_diameter, laminae, rows=1):
    """ISO/TS 16281 eqs. (47)–(49), (56)–(57): lamina loads q_ci, q_ce [N] for a raceway life of 10⁶ revolutions.

        Q_ci = C_r / (λν 0.378 Z cos α i^{7/9}) · [1 + (1.038 ((1−γ)/(1+γ))^{143/108})^{9/2}]^{2/9}
        Q_ce = C_r / (λν 0.364 Z cos α i^{7/9}) · [1 + (1.038 ((1−γ)/(1+γ))^{143/108})^{−9/2}]^{2/9}
        q_c  = Q_c n_s^{−7/9}.
    With C_r from ISO 281 this is Lundberg–Palmgren's 552 b_m (1∓γ)^{29/27} (1±γ)^{−1/4} (γ/cos α)^{2/9}
    D_we^{29/27} (L_we/n_s)^{7/9} Z^{−1/4} [N, mm] within 0.5 %: λν cancels (tests/test_roller_life.py).
    """
    gamma = roller_ratio(roller_diameter, contact_angle, pitch_diameter)
    ratio = 1.038 * ((1.0 - gamma) / (1.0 + gamma)) ** (143.0 / 108.0)
    base = rating / (LAMBDA_NU * roller_count * jnp.cos(contact_angle) * rows ** (7.0 / 9.0))
    inner = base / 0.378 * (1.0 + ratio**4.5) ** (2.0 / 9.0)
    outer = base / 0.364 * (1.0 + ratio**-4.5) ** (2.0 / 9.0)
    split = laminae ** (-7.0 / 9.0)
    return inner * split, outer * split


def roller_reference_rating_life(rating, roller_count, roller_diameter, contact_angle, pitch_diameter,
                                 inner_lamina_loads, outer_lamina_loads):
    """ISO/TS 16281 §5.3 basic reference rating life L10r [10⁶ revolutions] of a single-row roller bearing, inner ring rotating.

    `inner_lamina_loads`, `outer_lamina_loads`: (Z, n_s) forces [N] of each lamina on the inner and the
    outer raceway (equal in a quasi-static model). Eqs. (61)–(65): per lamina column k
        (q_ei,k / q_ci)^{9/2} = (Σ_j q_jk⁴ / Z)^{9/8} / q_ci^{9/2}         rotating inner ring,
        (q_ee,k / q_ce)^{9/2} = (Σ_j q_jk^{9/2} / Z) / q_ce^{9/2}         fixed outer ring,
        L10r = (Σ_k [(q_ei,k/q_ci)^{9/2} + (q_ee,k/q_ce)^{9/2}])^{−8/9}.
    Written in these powers no root of a zero sum is taken: unloaded laminae add exactly 0 with finite
    gradients, and a bearing with no load anywhere gives L10r = +inf with a zero gradient.
    L_we enters through C_r only.
    """
    laminae = inner_lamina_loads.shape[-1]
    rating_inner, rating_outer = lamina_ratings(rating, roller_count, roller_diameter, contact_angle, pitch_diameter, laminae)
    inner_mean = jnp.sum(positive_power(inner_lamina_loads, 4.0), axis=0) / roller_count
    outer_mean = jnp.sum(positive_power(outer_lamina_loads, 4.5), axis=0) / roller_count
    damage = jnp.sum(positive_power(inner_mean, 9.0 / 8.0) / rating_inner**4.5 + outer_mean / rating_outer**4.5)
    loaded = damage > 0.0
    safe_damage = jnp.where(loaded, damage, 1.0)
    return jnp.where(loaded, safe_damage ** (-8.0 / 9.0), jnp.inf)


def axial_load_factor(contact_angle):
    """Y = 0.4 cot α [-] of a single-row tapered roller bearing with cup angle α > 0 (ISO 281:2007,
    Table 8)."""
    return 0.4 / jnp.tan(contact_angle)


def roller_equivalent_dynamic_load(force, contact_angle):
    """ISO 281 equivalent dynamic radial load P = X F_r + Y F_a [N] of a single-row radial roller
    bearing for force [Fx, Fy, Fz] [N]: α = 0 (cylindrical) gives P = F_r; α > 0 (tapered) takes
    e = 1.5 tan α, and X = 0.4, Y = 0.4 cot α where F_a/F_r > e (ISO 281:2007, Table 8)."""
    radial = jnp.sqrt(force[0] ** 2 + force[1] ** 2)
    axial = jnp.abs(force[2])
    tangent = jnp.tan(contact_angle)
    heavy_axial = axial > 1.5 * tangent * radial
    safe_tangent = jnp.where(tangent > 0, tangent, 1.0)
    return jnp.where(heavy_axial & (tangent > 0), 0.4 * radial + 0.4 / safe_tangent * axial, radial)


def roller_basic_rating_life(rating, equivalent_load):
    """ISO 281 basic rating life L10 = (C_r/P)^{10/3} [10⁶ revolutions] of a roller bearing."""
    return (rating / equivalent_load) ** (10.0 / 3.0)
