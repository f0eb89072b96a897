"""ISO 281:2007 and ISO 76 ratings of thrust roller bearings at α = 90° (cylindrical roller thrust
bearings), as GOST 18855-2013 (ISO 281:2007, MOD) and GOST 18854-94 (ISO 76:1987) print them.

* `thrust_roller_dynamic_load_rating` — ISO 281 eq. (17), α = 90°:
      C_a = b_m f_c L_we^{7/9} Z^{3/4} D_we^{29/27}      [N; L_we, D_we in mm]
  with b_m = 1.0 of cylindrical roller thrust bearings (Table 9) and f_c of Table 10's α = 90° column
  against D_we/D_pw (linear between its rows; NaN outside 0.01…0.30). Every printed row equals
  293.16 (D_we/D_pw)^{2/9} to its rounding (tests/test_cylindrical_roller_thrust.py): Lundberg–
  Palmgren's form at α = 90°, where the washers are flat and the (1 ∓ γ) terms of the radial bearings
  drop out; the constant is fitted to the table (ISO/TR 1281-1's own expression was not at hand).
* `thrust_roller_static_load_rating` — ISO 76 eq. (11) at α = 90°: C₀a = 220 Z L_we D_we [N, mm];
  P₀a = F_a (eq. (13)).
* `thrust_roller_lamina_rating` — ISO/TS 16281's rating of a lamina of either washer, the lamina load
  of a raceway life of 10⁶ revolutions: Q_c = C_a 2^{2/9} / (λν Z), λν = 0.73 of thrust roller
  bearings, q_c = Q_c n^{−7/9} (both washers' contacts alike at 90°: the radial bearings'
  [1 + (…)^{±9/2}]^{2/9} is 2^{2/9}). The open implementation minzhun/ISO16281 (RollerBearing.py)
  has the same. Under a pure axial load on straight rollers every lamina carries F_a/(Z n) and
  ISO/TS 16281's L10r is (C_a / (λν F_a))⁴ exactly.
"""

import jax.numpy as jnp
import numpy as np

# ISO 281:2007 Table 9: b_m of cylindrical (and needle) roller thrust bearings
BM_CYLINDRICAL_THRUST = 1.0
# ISO 281:2007 Table 10, α = 90°: f_c against D_we / D_pw at every 0.01 from 0.01 to 0.30
FC_RATIO = np.round(np.arange(1, 31) * 0.01, 2)
FC_AXIAL = np.array([105.4, 122.9, 134.5, 143.4, 150.7, 156.9, 162.4, 167.2, 171.7, 175.7, 179.5, 183.0, 186.3, 189.4,
                     192.3, 195.1, 197.7, 200.3, 202.7, 205.0, 207.2, 209.4, 211.5, 213.5, 215.4, 217.3, 219.1, 220.9,
                     222.7, 224.3])
# ISO/TS 16281: λν of thrust roller bearings (the radial ones' is 0.83, `roller_life.LAMBDA_NU`)
LAMBDA_NU_THRUST = 0.73
STATIC_FACTOR = 220.0  # ISO 76 eq. (11): C₀a = 220 (1 − D cos α/D_pw) Z L_we D_we sin α [N, mm]


def thrust_roller_factor(roller_diameter, pitch_diameter):
    """f_c [-] of ISO 281 Table 10 at α = 90° for D_we/D_pw (NaN outside 0.01…0.30)."""
    ratio = roller_diameter / pitch_diameter
    inside = (ratio >= FC_RATIO[0]) & (ratio <= FC_RATIO[-1])
    return jnp.where(inside, jnp.interp(ratio, FC_RATIO, FC_AXIAL), jnp.nan)


def thrust_roller_dynamic_load_rating(roller_count, roller_diameter, effective_length, pitch_diameter,
                                      rating_factor=BM_CYLINDRICAL_THRUST):
    """ISO 281 C_a [N] of a single-row thrust roller bearing at α = 90° (module docstring): Z rollers
    of D_we and effective length L_we on the pitch diameter D_pw [m]; `rating_factor` b_m."""
    factor = thrust_roller_factor(roller_diameter, pitch_diameter)
    return (rating_factor * factor * (effective_length * 1e3) ** (7.0 / 9.0) * roller_count ** 0.75
            * (roller_diameter * 1e3) ** (29.0 / 27.0))


def thrust_roller_static_load_rating(roller_count, roller_diameter, effective_length):
    """ISO 76 C₀a = 220 Z L_we D_we [N] at α = 90° (D_we, L_we in m)."""
    return STATIC_FACTOR * roller_count * (effective_length * 1e3) * (roller_diameter * 1e3)


def thrust_roller_lamina_rating(rating, roller_count, laminae):
    """q_c = C_a 2^{2/9} / (λν Z) · n^{−7/9} [N]: ISO/TS 16281's lamina rating of either washer of a
    thrust roller bearing at α = 90° from its C_a [N] (module docstring)."""
    return rating * 2.0 ** (2.0 / 9.0) / (LAMBDA_NU_THRUST * roller_count) * laminae ** (-7.0 / 9.0)
