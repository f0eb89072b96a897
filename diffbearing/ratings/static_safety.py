"""Static load ratings and static safety: ISO 76:2006 C₀ and P₀, and the safety of the computed
contact pressures against ISO 76's permissible stresses.

* `ball_static_load_rating` — ISO 76, radial ball bearings: C₀r = f₀ i Z D_w² cos α [N, mm] with f₀ of Table 1
  (radial and angular-contact groove ball bearings, r_i ≤ 0.52 D_w, r_e ≤ 0.53 D_w), interpolated
  in γ = D_w cos α / D_pw. Table 1 is the load that makes the most loaded contact reach
  4 200 MPa when Q_max = 5 F_r / (Z cos α) (ISO/TR 10657 §4.2.1: C₀r = 0.2 i Z Q_max cos α);
  `tests/test_static_safety.py` rebuilds it from the Hertz contacts.
* `roller_static_load_rating` — ISO 76, radial roller bearings: C₀r = 44 (1 − γ) i Z L_we D_we cos α [N, mm]
  (4 000 MPa on the inner raceway, the same factor 5).
* `ball_equivalent_static_load`, `roller_equivalent_static_load` — ISO 76, Table 2:
  P₀r = max(X₀ F_r + Y₀ F_a, F_r), X₀ = 0.6, Y₀ = 0.5 for radial-contact groove bearings, X₀ = 0.5 and
  Y₀ of Table 2 (5°…45°) for single-row angular-contact ones (`double_row_equivalent_static_load`:
  X₀ = 1, Y₀ twice that for double-row ones and pairs); X₀ = 0.5, Y₀ = 0.22 cot α for tapered
  roller bearings, P₀r = F_r for cylindrical ones.
* `pressure_safety` — the static safety from the largest computed contact pressure,
  (p_limit / p_max)³ for point contacts and (p_limit / p_max)² for line contacts (load ∝ p³ and
  p², Hertz), p_limit = 4 200 MPa (ball bearings) and 4 000 MPa (roller bearings) (ISO 76's
  definitions of C₀; the load ratio of Timken's σ₀ = 4200 (P₀/C₀)^{1/3} MPa).

Sources: ISO 76:2006 as transcribed in two independent open implementations and the catalogues of
NSK, NTN, Koyo, Schaeffler (HR 1) and SKF, which agree on every number here; the f₀ table is
checked against the Hertz chain of ISO/TR 10657 in the tests.
"""

import jax.numpy as jnp
import numpy as np

from ..bearings.roller.roller_geometry import mean_roller_diameter
from ..params import BallBearing
from .radial_load_factors import radial_and_axial

# ISO 76:2006 Table 1, radial and angular-contact groove ball bearings: γ = D_w cos α / D_pw → f₀.
F0_RATIO = np.round(np.arange(41) * 0.01, 2)
F0_VALUE = np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5, 16.4, 16.1, 15.9, 15.6, 15.4,
                     15.2, 14.9, 14.7, 14.4, 14.2, 14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
                     11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])
# ISO 76:2006 Table 2, single-row angular-contact ball bearings (X₀ = 0.5): α → Y₀.
Y0_ANGLE = np.radians(np.arange(5.0, 50.0, 5.0))
Y0_VALUE = np.array([0.52, 0.50, 0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])
# ISO 76:2006 Table 1, self-aligning ball bearings: γ → f₀ (GOST 18854-2013, the same table)
SELF_ALIGNING_F0_VALUE = np.array([1.9, 2.0, 2.0, 2.1, 2.1, 2.1, 2.2, 2.2, 2.3, 2.3, 2.4, 2.4, 2.4, 2.5, 2.5, 2.6,
                                   2.6, 2.7, 2.7, 2.8, 2.8, 2.8, 2.9, 2.9, 3.0, 3.0, 3.1, 3.1, 3.2, 3.2, 3.3, 3.3,
                                   3.4, 3.4, 3.5, 3.5, 3.6, 3.6, 3.7, 3.8, 3.8])
SELF_ALIGNING_Y0_FACTOR = 0.44  # ISO 76 Table 2, double-row self-aligning: X₀ = 1, Y₀ = 0.44 cot α
BALL_PRESSURE_LIMIT = 4.2e9  # Pa, ISO 76 §3.3: ball bearings other than self-aligning
SELF_ALIGNING_PRESSURE_LIMIT = 4.6e9  # Pa, ISO 76 §3.3: self-aligning ball bearings
ROLLER_PRESSURE_LIMIT = 4.0e9  # Pa, ISO 76 §3.3: roller bearings
ROLLER_FACTOR = 44.0  # ISO 76 eq. (4) [N/mm²]
POINT_CONTACT_EXPONENT, LINE_CONTACT_EXPONENT = 3.0, 2.0  # Q ∝ p³ (point), q ∝ p² (line), Hertz


def ball_static_load_rating(ball_count, ball_diameter, pitch_diameter, contact_angle, rows=1):
    """ISO 76 basic static radial load rating C₀r [N] of a ball bearing: D_w, D_pw [m], the nominal
    contact angle α [rad] (0 for a radial-contact groove bearing). Outside γ ≤ 0.40 the end of
    Table 1 is held."""
    gamma = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    f0 = jnp.interp(gamma, F0_RATIO, F0_VALUE)
    return f0 * rows * ball_count * (ball_diameter * 1e3) ** 2 * jnp.cos(contact_angle)


def self_aligning_static_load_rating(ball_count, ball_diameter, pitch_diameter, contact_angle, rows=2):
    """ISO 76 C₀r = f₀ i Z D_w² cos α [N] of a self-aligning ball bearing, f₀ of Table 1's
    self-aligning column at γ = D_w cos α / D_pw (held at its end beyond γ = 0.40)."""
    gamma = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    f0 = jnp.interp(gamma, F0_RATIO, SELF_ALIGNING_F0_VALUE)
    return f0 * rows * ball_count * (ball_diameter * 1e3) ** 2 * jnp.cos(contact_angle)


def self_aligning_equivalent_static_load(force, contact_angle):
    """ISO 76 P₀r = max(F_r + 0.44 cot α F_a, F_r) [N] of a double-row self-aligning ball bearing
    (Table 2: X₀ = 1, Y₀ = 0.44 cot α) under [Fx, Fy, Fz] [N], nominal angle α [rad] > 0."""
    radial, axial = radial_and_axial(force)
    return radial + SELF_ALIGNING_Y0_FACTOR / jnp.tan(contact_angle) * axial


def roller_static_load_rating(roller_count, roller_diameter, effective_length, pitch_diameter, contact_angle, rows=1):
    """ISO 76 basic static radial load rating C₀r = 44 (1 − γ) i Z L_we D_we cos α [N] of a radial
    roller bearing; D_we, L_we, D_pw [m], α [rad]."""
    gamma = roller_diameter * jnp.cos(contact_angle) / pitch_diameter
    return (ROLLER_FACTOR * (1.0 - gamma) * rows * roller_count * (effective_length * 1e3) * (roller_diameter * 1e3)
            * jnp.cos(contact_angle))


def ball_bearing_static_load_rating(bearing: BallBearing):
    """C₀r [N] of a single-row ball bearing at its nominal contact angle (0 for deep groove)."""
    return ball_static_load_rating(bearing.ball_count, bearing.ball_diameter, bearing.pitch_diameter,
                                   bearing.nominal_contact_angle)


def ball_bearing_equivalent_static_load(bearing: BallBearing, force):
    """P₀r [N] of a single-row ball bearing under [Fx, Fy, Fz] [N] (`ball_equivalent_static_load`)."""
    return ball_equivalent_static_load(force, bearing.nominal_contact_angle, bearing.radial_contact)


def roller_bearing_static_load_rating(bearing, raceways):
    """C₀r [N] of a whole roller bearing (`roller_geometry.RollerBearing`, its
    `roller_equilibrium.RollerRaceways`): the mean roller diameter, the cup angle."""
    return roller_static_load_rating(bearing.roller_count, mean_roller_diameter(bearing), bearing.length, raceways.pitch_diameter,
                                     raceways.cup_angle)


def ball_equivalent_static_load(force, contact_angle, radial_contact: bool):
    """ISO 76 equivalent static radial load P₀r [N] of a single-row ball bearing under force
    [Fx, Fy, Fz] [N]: X₀ = 0.6, Y₀ = 0.5 for a radial-contact groove bearing (`radial_contact`),
    else X₀ = 0.5 and Y₀ of Table 2 at the nominal angle α [rad] (5°…45°; NaN outside)."""
    radial, axial = radial_and_axial(force)
    if radial_contact:
        x0, y0 = 0.6, 0.5
    else:
        inside = (contact_angle >= Y0_ANGLE[0] - 1e-9) & (contact_angle <= Y0_ANGLE[-1] + 1e-9)
        x0, y0 = 0.5, jnp.where(inside, jnp.interp(contact_angle, Y0_ANGLE, Y0_VALUE), jnp.nan)
    return jnp.maximum(x0 * radial + y0 * axial, radial)


def double_row_equivalent_static_load(force, contact_angle):
    """ISO 76 equivalent static radial load P₀r [N] of a double-row angular-contact ball bearing
    (and of a pair back to back or face to face) under [Fx, Fy, Fz] [N]: Table 2's double-row
    column, X₀ = 1 and Y₀ twice the single row's at the nominal angle α [rad] (5°…45°; NaN
    outside), P₀r = F_r + Y₀ F_a (never below F_r)."""
    radial, axial = radial_and_axial(force)
    inside = (contact_angle >= Y0_ANGLE[0] - 1e-9) & (contact_angle <= Y0_ANGLE[-1] + 1e-9)
    y0 = jnp.where(inside, 2.0 * jnp.interp(contact_angle, Y0_ANGLE, Y0_VALUE), jnp.nan)
    return radial + y0 * axial


def roller_equivalent_static_load(force, contact_angle):
    """ISO 76 equivalent static radial load P₀r [N] of a single-row radial roller bearing: F_r for
    α = 0 (cylindrical), max(0.5 F_r + 0.22 cot α F_a, F_r) for α > 0 (tapered)."""
    radial, axial = radial_and_axial(force)
    tangent = jnp.tan(contact_angle)
    safe_tangent = jnp.where(tangent > 0, tangent, 1.0)
    return jnp.where(tangent > 0, jnp.maximum(0.5 * radial + 0.22 / safe_tangent * axial, radial), radial)


def pressure_safety(max_pressure, pressure_limit, exponent):
    """Static safety as a load ratio [-] from the largest contact pressure p_max [Pa]:
    (p_limit / p_max)^exponent, 3 for point and 2 for line contacts (inf where nothing is loaded)."""
    loaded = max_pressure > 0.0
    return jnp.where(loaded, (pressure_limit / jnp.where(loaded, max_pressure, 1.0)) ** exponent, jnp.inf)


def bearing_static_safety(bearing, raceways, force, max_pressure):
    """(C₀r [N], P₀r [N], pressure safety [-]) of a ball bearing (`raceways` None) or a whole roller
    bearing with its raceways, under the load [Fx, Fy, Fz] [N] it carries and with its largest
    contact pressure [Pa]."""
    if raceways is None:
        return (ball_bearing_static_load_rating(bearing), ball_bearing_equivalent_static_load(bearing, force),
                pressure_safety(max_pressure, BALL_PRESSURE_LIMIT, POINT_CONTACT_EXPONENT))
    return (roller_bearing_static_load_rating(bearing, raceways), roller_equivalent_static_load(force, raceways.cup_angle),
            pressure_safety(max_pressure, ROLLER_PRESSURE_LIMIT, LINE_CONTACT_EXPONENT))
