"""Frictional moment of a rolling bearing by SKF's four-component model (SKF General Catalogue 6000,
"Friction", pp. 88–105 of the Russian edition: "The new SKF model for calculating the frictional
moment", its Table 2 of the variables G_rr, G_sl and Table 3 of the geometry constants).

    M = φ_ish φ_rs M_rr + M_sl + M_seal + M_drag                                      [N·mm]
    M_rr = G_rr (ν n)^0.6                    rolling moment
    M_sl = G_sl μ_sl                         sliding moment
    φ_ish = 1 / (1 + 1.84·10⁻⁹ (n d_m)^1.28 ν^0.64)                    inlet shear heating
    φ_rs = 1 / exp(K_rs ν n (d + D) √(K_Z / (2 (D − d))))            kinematic replenishment
    μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL,  φ_bl = 1 / exp(2.6·10⁻⁸ (n ν)^1.4 d_m)
    M_seal = K_S1 d_s^β + K_S2               (two seals; one seal half of it)
    M_drag = V_M K_ball d_m⁵ n²              ball bearings, oil bath
    M_drag = 10 V_M K_roll B d_m⁴ n²         roller bearings, oil bath
    K_ball = i_rw K_Z (d + D)/(D − d) · 10⁻¹²,  K_roll = K_L K_Z (d + D)/(D − d) · 10⁻¹²

in the catalogue's units: M in N·mm, bore d, outside diameter D, d_m = (d + D)/2, the inner ring
width B and the seal counterface diameter d_s in mm, loads in N, n in r/min, ν (the operating
viscosity of the oil or of a grease's base oil) in mm²/s. K_rs = 3·10⁻⁸ for a low-level oil bath
and oil jet, 6·10⁻⁸ for grease and oil–air; μ_bl ≈ 0.15; μ_EHL = 0.02 for cylindrical and 0.002
for tapered roller bearings, else 0.05 with mineral oil, 0.04 synthetic oil, 0.1 transmission
fluid. V_M is read off the catalogue's diagram of the drag loss factor against H/d_m (H the oil
level), for which no formula is given: the drag functions take it as an argument.

G_rr and G_sl (Table 2), with α_F = 24.6 (F_a/C₀)^0.24 [°], F_g the balls' centrifugal term:

    deep groove ball     F_a = 0:  G_rr = R1 d_m^1.96 F_r^0.54,  G_sl = S1 d_m^−0.26 F_r^{5/3}
                         F_a > 0:  G_rr = R1 d_m^1.96 (F_r + R2/sin α_F · F_a)^0.54,
                                   G_sl = S1 d_m^−0.145 (F_r⁵ + S2 d_m^1.5/sin α_F · F_a⁴)^{1/3}
    angular contact      G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54,  F_g = R3 d_m⁴ n²
    ball (1 and 2 rows,  G_sl = S1 d_m^0.26 ((F_r + F_g)^{4/3} + S2 F_a^{4/3}),  F_g = S3 d_m⁴ n²
    four-point)
    cylindrical roller   G_rr = R1 d_m^2.41 F_r^0.31,  G_sl = S1 d_m^0.9 F_a + S2 d_m F_r
    tapered roller       G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31,  G_sl = S1 d_m^0.82 (F_r + S2 Y F_a)
    spherical roller     G_rr.e = R1 d_m^1.85 (F_r + R2 F_a)^0.54,  G_rr.l = R3 d_m^2.3 (F_r + R4 F_a)^0.31
                         G_sl.e = S1 d_m^0.25 (F_r⁴ + S2 F_a⁴)^{1/3},  G_sl.l = S3 d_m^0.94 (F_r³ + S4 F_a³)^{1/3}
                         the .e pair where G_rr.e < G_rr.l, else the .l pair
    thrust ball          G_rr = R1 d_m^1.83 F_a^0.54,  G_sl = S1 d_m^0.05 F_a^{4/3}
    cylindrical roller   G_rr = R1 d_m^2.38 F_a^0.31,  G_sl = S1 d_m^0.62 F_a
    thrust

The deep-groove forms at F_a = 0 and F_a → 0⁺ agree for G_rr but not for G_sl (d_m^−0.26 against
d_m^−0.145): the catalogue's own jump, kept as printed. Y is the bearing's axial load factor.

Every function takes and returns SI quantities (N, m, rad/s, m²/s, N·m) and converts to the
catalogue's units inside, as `friction_torque` does; the exceptions are G_rr, G_sl and the drag
constants K_ball, K_roll, which exist only in the catalogue's units and are returned in them.
Power loss N = M ω [W] (`friction_torque.friction_power`).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..numerics import positive_power
from ..params import _is_concrete, check_range
from ..ratings import roller_life
from .friction_torque import friction_power

# Geometry constants by bearing series (SKF General Catalogue 6000, Friction, Table 3).
# deep groove ball bearings: series → (R1, R2, S1, S2)
DEEP_GROOVE_BALL_CONSTANTS = {
    **dict.fromkeys(("2", "3"), (4.4e-7, 1.7, 2.00e-3, 100.0)),
    **dict.fromkeys(("42", "43"), (5.4e-7, 0.96, 3.00e-3, 40.0)),
    **dict.fromkeys(("60", "630"), (4.1e-7, 1.7, 3.73e-3, 14.6)),
    **dict.fromkeys(("62", "622"), (3.9e-7, 1.7, 3.23e-3, 36.5)),
    **dict.fromkeys(("63", "623"), (3.7e-7, 1.7, 2.84e-3, 92.8)),
    "64": (3.6e-7, 1.7, 2.43e-3, 198.0),
    **dict.fromkeys(("160", "161"), (4.3e-7, 1.7, 4.63e-3, 4.25)),
    **dict.fromkeys(("617", "618", "628", "637", "638"), (4.7e-7, 1.7, 6.50e-3, 0.78)),
    **dict.fromkeys(("619", "639"), (4.3e-7, 1.7, 4.75e-3, 3.6)),
}
# angular contact ball bearings: design → (R1, R2, R3, S1, S2, S3)
ANGULAR_CONTACT_BALL_CONSTANTS = {
    "single_row": (5.03e-7, 1.97, 1.90e-12, 1.30e-2, 0.68, 1.91e-12),
    "double_row": (6.34e-7, 1.41, 7.83e-13, 7.56e-3, 1.21, 7.83e-13),
    "four_point": (4.78e-7, 2.42, 1.40e-12, 1.20e-2, 0.9, 1.40e-12),
}
# cylindrical roller bearings: series (caged) or "full_complement" → (R1, S1, S2)
CYLINDRICAL_ROLLER_CONSTANTS = {
    **dict.fromkeys(("2", "3"), (1.09e-6, 0.16, 0.0015)),
    "4": (1.00e-6, 0.16, 0.0015),
    "10": (1.12e-6, 0.17, 0.0015),
    **dict.fromkeys(("12", "20"), (1.23e-6, 0.16, 0.0015)),
    "22": (1.40e-6, 0.16, 0.0015),
    "23": (1.48e-6, 0.16, 0.0015),
    "full_complement": (2.13e-6, 0.16, 0.0015),
}
# tapered roller bearings: series → (R1, R2, S1, S2); "other" for the series not listed
TAPERED_ROLLER_CONSTANTS = {
    "302": (1.76e-6, 10.9, 0.017, 2.0),
    "303": (1.69e-6, 10.9, 0.017, 2.0),
    "313": (1.84e-6, 10.9, 0.048, 2.0),
    "320X": (2.38e-6, 10.9, 0.014, 2.0),
    "322": (2.27e-6, 10.9, 0.018, 2.0),
    "322B": (2.38e-6, 10.9, 0.026, 2.0),
    "323": (2.38e-6, 10.9, 0.019, 2.0),
    "323B": (2.79e-6, 10.9, 0.030, 2.0),
    "329": (2.31e-6, 10.9, 0.009, 2.0),
    "330": (2.71e-6, 11.3, 0.010, 2.0),
    "331": (2.71e-6, 10.9, 0.015, 2.0),
    "332": (2.71e-6, 10.9, 0.018, 2.0),
    "other": (2.31e-6, 10.9, 0.019, 2.0),
}
# spherical roller bearings: series → (R1, R2, R3, R4, S1, S2, S3, S4) (Table 3e)
SPHERICAL_ROLLER_CONSTANTS = {
    **dict.fromkeys(("213E", "222E"), (1.6e-6, 5.84, 2.81e-6, 5.8, 3.62e-3, 508.0, 8.8e-3, 117.0)),
    "222": (2.0e-6, 5.54, 2.92e-6, 5.5, 5.10e-3, 414.0, 9.7e-3, 100.0),
    "223": (1.7e-6, 4.1, 3.13e-6, 4.05, 6.92e-3, 124.0, 1.7e-2, 41.0),
    "223E": (1.6e-6, 4.1, 3.14e-6, 4.05, 6.23e-3, 124.0, 1.7e-2, 41.0),
    "230": (2.4e-6, 6.44, 3.76e-6, 6.4, 4.13e-3, 755.0, 1.1e-2, 160.0),
    "231": (2.4e-6, 4.7, 4.04e-6, 4.72, 6.70e-3, 231.0, 1.7e-2, 65.0),
    "232": (2.3e-6, 4.1, 4.00e-6, 4.05, 8.66e-3, 126.0, 2.1e-2, 41.0),
    "238": (3.1e-6, 12.1, 3.82e-6, 12.0, 1.74e-3, 9495.0, 5.9e-3, 1057.0),
    "239": (2.7e-6, 8.53, 3.87e-6, 8.47, 2.77e-3, 2330.0, 8.5e-3, 371.0),
    "240": (2.9e-6, 4.87, 4.78e-6, 4.84, 6.95e-3, 240.0, 2.1e-2, 68.0),
    "241": (2.6e-6, 3.8, 4.79e-6, 3.7, 1.00e-2, 86.7, 2.9e-2, 31.0),
    "248": (3.8e-6, 9.4, 5.09e-6, 9.3, 2.80e-3, 3415.0, 1.2e-2, 486.0),
    "249": (3.0e-6, 6.67, 5.09e-6, 6.62, 3.90e-3, 887.0, 1.7e-2, 180.0),
}
# thrust ball and cylindrical roller thrust bearings: series → (R1, S1); Table 3 gives one row for each
# type, which every series of the type shares
THRUST_BALL_CONSTANTS = dict.fromkeys(("511", "512", "513", "514"), (1.03e-6, 1.6e-2))
CYLINDRICAL_ROLLER_THRUST_CONSTANTS = dict.fromkeys(("811", "812", "893", "894"), (2.25e-6, 0.154))
SERIES_CONSTANTS = {
    "deep_groove_ball": DEEP_GROOVE_BALL_CONSTANTS,
    "angular_contact_ball": ANGULAR_CONTACT_BALL_CONSTANTS,
    "cylindrical_roller": CYLINDRICAL_ROLLER_CONSTANTS,
    "tapered_roller": TAPERED_ROLLER_CONSTANTS,
    "spherical_roller": SPHERICAL_ROLLER_CONSTANTS,
    "thrust_ball": THRUST_BALL_CONSTANTS,
    "cylindrical_roller_thrust": CYLINDRICAL_ROLLER_THRUST_CONSTANTS,
}
# the series of each kind when a scene names none: the series of Palmgren's defaults (friction_torque),
# for spherical roller bearings the catalogue example's 222E
DEFAULT_SERIES = {"deep_groove_ball": "62", "angular_contact_ball": "single_row", "cylindrical_roller": "2",
                  "tapered_roller": "302", "spherical_roller": "222E", "thrust_ball": "511",
                  "cylindrical_roller_thrust": "811"}

# bearing type → (K_Z, K_L), the geometry constants of the replenishment factor and the drag loss
# (SKF General Catalogue 6000, Friction, "Drag losses in oil bath lubrication", Table 5); K_L only for rollers
BEARING_TYPE_CONSTANTS = {
    "deep_groove_ball": (3.1, None),
    "angular_contact_ball.single_row": (4.4, None),
    "angular_contact_ball.double_row": (3.1, None),
    "angular_contact_ball.four_point": (3.1, None),
    "cylindrical_roller": (5.1, 0.65),
    "cylindrical_roller.full_complement": (6.2, 0.7),
    "tapered_roller": (6.0, 0.7),
    "spherical_roller": (5.5, 0.8),
    "thrust_ball": (3.8, None),
    "cylindrical_roller_thrust": (4.4, 0.43),
}

# lubrication → K_rs of φ_rs (SKF General Catalogue 6000, Friction, "Kinematic replenishment/starvation")
REPLENISHMENT_CONSTANTS = {"oil_bath": 3e-8, "oil_jet": 3e-8, "grease": 6e-8, "oil_air": 6e-8}
# μ_EHL, the sliding friction coefficient in full film (catalogue, "Effect of lubrication on sliding
# friction"): by bearing kind for cylindrical and tapered roller bearings, else by the oil
FULL_FILM_COEFFICIENTS_BY_KIND = {"cylindrical_roller": 0.02, "tapered_roller": 0.002}
FULL_FILM_COEFFICIENTS_BY_OIL = {"mineral": 0.05, "synthetic": 0.04, "transmission_fluid": 0.1}
BOUNDARY_COEFFICIENT = 0.15  # μ_bl, "generally ≈ 0.15" (depends on the lubricant's additives)

# seal → (β, K_S1, K_S2) of M_seal = K_S1 d_s^β + K_S2 [N·mm, d_s mm] (catalogue, "Frictional moment
# of seals"); the key names the bearing type, the seal and the outside diameter D [mm] it holds for
SEAL_CONSTANTS = {
    "deep_groove_ball.RS1.D<=62": (2.25, 0.023, 2.0),
    "deep_groove_ball.RS1.62<D<=80": (2.25, 0.018, 20.0),
    "deep_groove_ball.RSH.D<=52": (2.25, 0.028, 2.0),
    "angular_contact_ball.RS1.30<D<=120": (2.0, 0.014, 10.0),
    "cylindrical_roller.LS": (2.0, 0.032, 50.0),
}

SEALS = ("RS1", "RSH", "LS")  # the seal designations of SEAL_CONSTANTS
# the kinds whose K_L (rollers' length) the replenishment and drag terms need
ROLLER_LENGTH_KINDS = tuple(dict.fromkeys(key.split(".")[0] for key, (_, length) in BEARING_TYPE_CONSTANTS.items()
                                          if length is not None))
KINDS = tuple(SERIES_CONSTANTS)
SUPPLIES = tuple(REPLENISHMENT_CONSTANTS)


class FrictionalMoment(eqx.Module):
    """The components of SKF's frictional moment (module docstring), SI unless stated."""

    rolling: jax.Array  # M_rr [N·m], before the factors φ_ish φ_rs
    sliding: jax.Array  # M_sl [N·m]
    seal: jax.Array  # M_seal [N·m]
    drag: jax.Array  # M_drag [N·m]
    inlet_shear: jax.Array  # φ_ish [-]
    replenishment: jax.Array  # φ_rs [-]
    sliding_coefficient: jax.Array  # μ_sl [-]
    rolling_variable: jax.Array  # G_rr, catalogue units (Table 2)
    sliding_variable: jax.Array  # G_sl, catalogue units (Table 2)
    total: jax.Array  # M = φ_ish φ_rs M_rr + M_sl + M_seal + M_drag [N·m]
    power: jax.Array  # N = M ω [W]


class SkfBearing(eqx.Module):
    """What SKF's model reads beyond the bearing and its load: its series (Table 3), lubrication
    (K_rs: one of `SUPPLIES`), bore and outside diameter [m], for the drag in an oil bath V_M [-] and
    (roller bearings) the inner ring width B [m], and its seals: the row of `SEAL_CONSTANTS` (None:
    open), their counterface diameter d_s [m] and count."""

    series: str = eqx.field(static=True)
    supply: str = eqx.field(static=True)
    bore: jax.Array
    outside_diameter: jax.Array
    drag_loss_factor: jax.Array | None
    inner_ring_width: jax.Array | None
    seal: str | None = eqx.field(static=True, default=None)
    counterface_diameter: jax.Array | None = None
    seals: int = eqx.field(static=True, default=2)


# ---- catalogue units -------------------------------------------------------------------------

def _rpm(speed):
    """n [r/min] from an angular speed [rad/s] (its magnitude)."""
    return jnp.abs(speed) * 30.0 / jnp.pi


def _mm(length):
    return length * 1e3


def _mm2_per_s(kinematic_viscosity):
    return kinematic_viscosity * 1e6


def _newton_metre(moment_nmm):
    return moment_nmm * 1e-3


# ---- rolling and sliding variables (Table 2) ---------------------------------------------------

def contact_angle_factor(axial, static_load_rating):
    """α_F = 24.6 (F_a/C₀)^0.24 [°] of a deep-groove ball bearing (F_a, C₀ [N]; Table 2)."""
    return 24.6 * positive_power(axial / static_load_rating, 0.24)


def deep_groove_ball_variables(constants, radial, axial, pitch_diameter, static_load_rating):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of a deep-groove ball bearing: F_r, F_a, C₀ [N],
    d_m [m], `constants` (R1, R2, S1, S2) of Table 3. The F_a = 0 forms where F_a ≤ 0, else the F_a > 0
    forms (the catalogue's jump in G_sl kept; gradients finite on both sides)."""
    r1, r2, s1, s2 = constants
    dm = _mm(pitch_diameter)
    loaded = axial > 0
    safe_axial = jnp.where(loaded, axial, static_load_rating)  # keeps 1/sin α_F finite where unused
    sin_angle = jnp.sin(jnp.deg2rad(contact_angle_factor(safe_axial, static_load_rating)))
    rolling_loaded = r1 * dm**1.96 * positive_power(radial + r2 / sin_angle * safe_axial, 0.54)
    rolling_unloaded = r1 * dm**1.96 * positive_power(radial, 0.54)
    sliding_loaded = s1 * dm**-0.145 * positive_power(radial**5 + s2 * dm**1.5 / sin_angle * safe_axial**4, 1.0 / 3.0)
    sliding_unloaded = s1 * dm**-0.26 * positive_power(radial, 5.0 / 3.0)
    return jnp.where(loaded, rolling_loaded, rolling_unloaded), jnp.where(loaded, sliding_loaded, sliding_unloaded)


def angular_contact_ball_variables(constants, radial, axial, speed, pitch_diameter):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of an angular-contact or four-point ball bearing:
    F_r, F_a [N], ω [rad/s], d_m [m], `constants` (R1, R2, R3, S1, S2, S3) of Table 3."""
    r1, r2, r3, s1, s2, s3 = constants
    dm, n = _mm(pitch_diameter), _rpm(speed)
    rolling_centrifugal = r3 * dm**4 * n**2  # F_g of G_rr
    sliding_centrifugal = s3 * dm**4 * n**2  # F_g of G_sl
    rolling = r1 * dm**1.97 * positive_power(radial + rolling_centrifugal + r2 * axial, 0.54)
    sliding = s1 * dm**0.26 * (positive_power(radial + sliding_centrifugal, 4.0 / 3.0) + s2 * positive_power(axial, 4.0 / 3.0))
    return rolling, sliding


def cylindrical_roller_variables(constants, radial, axial, pitch_diameter):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of a cylindrical roller bearing: F_r, F_a [N],
    d_m [m], `constants` (R1, S1, S2) of Table 3."""
    r1, s1, s2 = constants
    dm = _mm(pitch_diameter)
    return r1 * dm**2.41 * positive_power(radial, 0.31), s1 * dm**0.9 * axial + s2 * dm * radial


def tapered_roller_variables(constants, radial, axial, pitch_diameter, axial_load_factor):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of a tapered roller bearing: F_r, F_a [N], d_m [m],
    Y [-] the bearing's axial load factor, `constants` (R1, R2, S1, S2) of Table 3."""
    r1, r2, s1, s2 = constants
    dm = _mm(pitch_diameter)
    rolling = r1 * dm**2.38 * positive_power(radial + r2 * axial_load_factor * axial, 0.31)
    return rolling, s1 * dm**0.82 * (radial + s2 * axial_load_factor * axial)


def spherical_roller_variables(constants, radial, axial, pitch_diameter):
    """(G_rr.e, G_rr.l, G_sl.e, G_sl.l) in the catalogue's units (Table 2) of a spherical roller bearing:
    F_r, F_a [N], d_m [m], `constants` (R1, R2, R3, R4, S1, S2, S3, S4) of Table 3."""
    r1, r2, r3, r4, s1, s2, s3, s4 = constants
    dm = _mm(pitch_diameter)
    rolling_e = r1 * dm**1.85 * positive_power(radial + r2 * axial, 0.54)
    rolling_l = r3 * dm**2.3 * positive_power(radial + r4 * axial, 0.31)
    sliding_e = s1 * dm**0.25 * positive_power(radial**4 + s2 * axial**4, 1.0 / 3.0)
    sliding_l = s3 * dm**0.94 * positive_power(radial**3 + s4 * axial**3, 1.0 / 3.0)
    return rolling_e, rolling_l, sliding_e, sliding_l


def thrust_ball_variables(constants, axial, pitch_diameter):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of a thrust ball bearing: F_a [N], d_m [m],
    `constants` (R1, S1) of Table 3."""
    r1, s1 = constants
    dm = _mm(pitch_diameter)
    return r1 * dm**1.83 * positive_power(axial, 0.54), s1 * dm**0.05 * positive_power(axial, 4.0 / 3.0)


def cylindrical_roller_thrust_variables(constants, axial, pitch_diameter):
    """(G_rr, G_sl) in the catalogue's units (Table 2) of a cylindrical roller thrust bearing: F_a [N],
    d_m [m], `constants` (R1, S1) of Table 3."""
    r1, s1 = constants
    dm = _mm(pitch_diameter)
    return r1 * dm**2.38 * positive_power(axial, 0.31), s1 * dm**0.62 * axial


def frictional_variables(kind: str, constants, radial, axial, speed, pitch_diameter, *, static_load_rating=None,
                         axial_load_factor=None):
    """(G_rr, G_sl) in the catalogue's units (Table 2) for `kind` (one of `KINDS`): F_r, F_a [N],
    ω [rad/s], d_m [m]; `constants` a series of `SERIES_CONSTANTS[kind]` or the tuple of Table 3 itself;
    C₀ [N] for deep-groove ball bearings, Y [-] for tapered roller bearings."""
    constants = series_constants(kind, constants)
    variables, needs = FRICTIONAL_VARIABLES[kind]
    given = {"static_load_rating": static_load_rating, "axial_load_factor": axial_load_factor}
    for name, why in needs:
        _require(name, given[name], why)
    return variables(constants, radial, axial, speed, pitch_diameter, **{name: given[name] for name, _ in needs})


def needed_inputs(kind: str) -> tuple[str, ...]:
    """The keywords `frictional_variables` needs for `kind` beyond the loads ("static_load_rating",
    "axial_load_factor")."""
    return tuple(name for name, _ in FRICTIONAL_VARIABLES[kind][1])


def _spherical_roller_pair(constants, radial, axial, pitch_diameter):
    """(G_rr, G_sl) of a spherical roller bearing: the catalogue's ".e" pair where G_rr.e < G_rr.l."""
    rolling_e, rolling_l, sliding_e, sliding_l = spherical_roller_variables(constants, radial, axial, pitch_diameter)
    elastic = rolling_e < rolling_l
    return jnp.where(elastic, rolling_e, rolling_l), jnp.where(elastic, sliding_e, sliding_l)


# bearing kind → ((constants, F_r, F_a, ω, d_m, **needed) → (G_rr, G_sl), the inputs it needs with why)
FRICTIONAL_VARIABLES = {
    "deep_groove_ball": (
        lambda c, radial, axial, speed, dm, static_load_rating: deep_groove_ball_variables(
            c, radial, axial, dm, static_load_rating),
        (("static_load_rating", "deep-groove ball bearings (α_F = 24.6 (F_a/C₀)^0.24)"),)),
    "angular_contact_ball": (
        lambda c, radial, axial, speed, dm: angular_contact_ball_variables(c, radial, axial, speed, dm), ()),
    "cylindrical_roller": (lambda c, radial, axial, speed, dm: cylindrical_roller_variables(c, radial, axial, dm), ()),
    "tapered_roller": (
        lambda c, radial, axial, speed, dm, axial_load_factor: tapered_roller_variables(
            c, radial, axial, dm, axial_load_factor),
        (("axial_load_factor", "tapered roller bearings (the bearing's Y)"),)),
    "spherical_roller": (lambda c, radial, axial, speed, dm: _spherical_roller_pair(c, radial, axial, dm), ()),
    "thrust_ball": (lambda c, radial, axial, speed, dm: thrust_ball_variables(c, axial, dm), ()),
    "cylindrical_roller_thrust": (lambda c, radial, axial, speed, dm: cylindrical_roller_thrust_variables(c, axial, dm),
                                  ()),
}


def series_constants(kind: str, series):
    """Table 3's constants of `series` (a key of `SERIES_CONSTANTS[kind]`); a tuple passes through."""
    if kind not in SERIES_CONSTANTS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    table = SERIES_CONSTANTS[kind]
    if isinstance(series, str):
        if series not in table:
            raise ValueError(f"constants: the {kind} series must be one of {tuple(table)} (SKF Table 3) or a tuple "
                             f"of the table's constants, got {series!r}")
        return table[series]
    size = len(next(iter(table.values())))
    if len(series) != size:
        raise ValueError(f"constants: {size} constants of SKF Table 3 for a {kind} bearing, got {len(series)}")
    return tuple(series)


def bearing_type_constants(kind: str, series):
    """(K_Z, K_L) of the bearing type (`BEARING_TYPE_CONSTANTS`; K_L None for ball bearings) from the kind and
    its series: the design of an angular-contact bearing, "full_complement" for a cylindrical one."""
    designed = f"{kind}.{series}"  # an angular-contact design, a full-complement cylindrical bearing
    key = designed if designed in BEARING_TYPE_CONSTANTS else kind
    if key not in BEARING_TYPE_CONSTANTS:
        raise ValueError(f"K_Z: no bearing type {key!r} in {tuple(BEARING_TYPE_CONSTANTS)}; give geometry_constant")
    return BEARING_TYPE_CONSTANTS[key]


# ---- moments and factors -----------------------------------------------------------------------

def rolling_moment(rolling_variable, kinematic_viscosity, speed):
    """M_rr = G_rr (ν n)^0.6 [N·m] from G_rr (catalogue units), ν [m²/s] and ω [rad/s] (SKF General
    Catalogue 6000, Friction, "Rolling frictional moment")."""
    return _newton_metre(rolling_variable * positive_power(_mm2_per_s(kinematic_viscosity) * _rpm(speed), 0.6))


def sliding_moment(sliding_variable, sliding_coefficient):
    """M_sl = G_sl μ_sl [N·m] from G_sl (catalogue units) and μ_sl [-] (catalogue, "Sliding frictional
    moment")."""
    return _newton_metre(sliding_variable * sliding_coefficient)


def boundary_weighting(kinematic_viscosity, speed, pitch_diameter):
    """φ_bl = 1 / exp(2.6·10⁻⁸ (n ν)^1.4 d_m) [-] from ν [m²/s], ω [rad/s], d_m [m] (catalogue, "Effect of
    lubrication on sliding friction"): 1 at standstill, → 0 in full film."""
    product = _mm2_per_s(kinematic_viscosity) * _rpm(speed)
    return jnp.exp(-2.6e-8 * positive_power(product, 1.4) * _mm(pitch_diameter))


def sliding_coefficient(kinematic_viscosity, speed, pitch_diameter, full_film_coefficient,
                        boundary_coefficient=BOUNDARY_COEFFICIENT):
    """μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL [-] from ν [m²/s], ω [rad/s], d_m [m], μ_EHL and μ_bl [-]
    (catalogue, "Effect of lubrication on sliding friction")."""
    weighting = boundary_weighting(kinematic_viscosity, speed, pitch_diameter)
    return weighting * boundary_coefficient + (1.0 - weighting) * full_film_coefficient


def inlet_shear_factor(kinematic_viscosity, speed, pitch_diameter):
    """φ_ish = 1 / (1 + 1.84·10⁻⁹ (n d_m)^1.28 ν^0.64) [-] from ν [m²/s], ω [rad/s], d_m [m] (catalogue,
    "Inlet shear heating reduction factor")."""
    nu = _mm2_per_s(kinematic_viscosity)
    return 1.0 / (1.0 + 1.84e-9 * positive_power(_rpm(speed) * _mm(pitch_diameter), 1.28) * positive_power(nu, 0.64))


def replenishment_factor(kinematic_viscosity, speed, bore, outside_diameter, geometry_constant, replenishment_constant):
    """φ_rs = 1 / exp(K_rs ν n (d + D) √(K_Z / (2 (D − d)))) [-] from ν [m²/s], ω [rad/s], d, D [m], K_Z and
    K_rs (`REPLENISHMENT_CONSTANTS`; catalogue, "Kinematic replenishment/starvation reduction factor")."""
    d, outside = _mm(bore), _mm(outside_diameter)
    exponent = (replenishment_constant * _mm2_per_s(kinematic_viscosity) * _rpm(speed) * (d + outside)
                * jnp.sqrt(geometry_constant / (2.0 * (outside - d))))
    return jnp.exp(-exponent)


def ball_drag_constant(geometry_constant, bore, outside_diameter, rows=1):
    """K_ball = i_rw K_Z (d + D)/(D − d) · 10⁻¹² (catalogue units) from K_Z, d, D [m] and i_rw rows of balls
    (catalogue, "Drag losses in oil bath lubrication")."""
    return rows * geometry_constant * (bore + outside_diameter) / (outside_diameter - bore) * 1e-12


def roller_drag_constant(geometry_constant, roller_length_constant, bore, outside_diameter):
    """K_roll = K_L K_Z (d + D)/(D − d) · 10⁻¹² (catalogue units) from K_Z, K_L, d, D [m] (catalogue, "Drag
    losses in oil bath lubrication")."""
    return roller_length_constant * geometry_constant * (bore + outside_diameter) / (outside_diameter - bore) * 1e-12


def drag_moment_ball(drag_loss_factor, speed, bore, outside_diameter, geometry_constant, rows=1):
    """M_drag = V_M K_ball d_m⁵ n² [N·m] of a ball bearing in an oil bath from V_M [-] (the catalogue's
    diagram against H/d_m), ω [rad/s], d, D [m], K_Z and i_rw rows of balls (catalogue, "Drag losses")."""
    dm = 0.5 * (_mm(bore) + _mm(outside_diameter))
    constant = ball_drag_constant(geometry_constant, bore, outside_diameter, rows)
    return _newton_metre(drag_loss_factor * constant * dm**5 * _rpm(speed) ** 2)


def drag_moment_roller(drag_loss_factor, speed, bore, outside_diameter, inner_ring_width, geometry_constant,
                       roller_length_constant):
    """M_drag = 10 V_M K_roll B d_m⁴ n² [N·m] of a roller bearing in an oil bath from V_M [-] (the catalogue's
    diagram against H/d_m), ω [rad/s], d, D, the inner ring width B [m], K_Z and K_L (catalogue, "Drag
    losses")."""
    dm = 0.5 * (_mm(bore) + _mm(outside_diameter))
    constant = roller_drag_constant(geometry_constant, roller_length_constant, bore, outside_diameter)
    return _newton_metre(10.0 * drag_loss_factor * constant * _mm(inner_ring_width) * dm**4 * _rpm(speed) ** 2)


def seal_row(kind: str, seal: str, outside_diameter) -> str:
    """The key of `SEAL_CONSTANTS` for the seal `seal` (one of `SEALS`) of a `kind` bearing of outside
    diameter D [m] (a concrete number); ValueError naming the rows there are where none holds (a
    seal of another size takes its own (β, K_S1, K_S2) in `frictional_moment`)."""
    outside = float(_mm(outside_diameter))
    rows = [key for key in SEAL_CONSTANTS if key.split(".")[:2] == [kind, seal]]
    for key in rows:
        bounds = key.split(".", 2)[2:]  # [] (any D), ["D<=62"], ["62<D<=80"]
        low, _, high = bounds[0].partition("D<=") if bounds else ("", "", "")
        if (not low or outside > float(low.rstrip("<"))) and (not high or outside <= float(high)):
            return key
    if not rows:
        raise ValueError(f"seal: SKF's seal constants give no {seal} seal on a {kind} bearing (rows: "
                         f"{tuple(SEAL_CONSTANTS)})")
    raise ValueError(f"seal: SKF's constants of the {seal} seal on a {kind} bearing hold for {rows}, not for "
                     f"D = {outside:g} mm")


def seal_moment(diameter_coefficient, exponent, constant_term, counterface_diameter, seals=2):
    """M_seal = K_S1 d_s^β + K_S2 [N·m] of a bearing sealed on both sides, half of it for one seal, from K_S1
    [N·mm/mm^β], β [-], K_S2 [N·mm] (`SEAL_CONSTANTS`) and the counterface diameter d_s [m] (catalogue,
    "Frictional moment of seals")."""
    moment = diameter_coefficient * positive_power(_mm(counterface_diameter), exponent) + constant_term
    return _newton_metre(0.5 * seals * moment)


# ---- the whole model -----------------------------------------------------------------------------

def frictional_moment(kind: str, constants, radial, axial, speed, kinematic_viscosity, bore, outside_diameter, *,
                      supply: str, static_load_rating=None, axial_load_factor=None, base_oil="mineral",
                      sliding_friction_coefficient=None, full_film_coefficient=None,
                      boundary_coefficient=BOUNDARY_COEFFICIENT, drag_loss_factor=None, inner_ring_width=None, rows=None,
                      seal=None, counterface_diameter=None, seals=2, geometry_constant=None,
                      roller_length_constant=None) -> FrictionalMoment:
    """SKF's frictional moment M = φ_ish φ_rs M_rr + M_sl + M_seal + M_drag (module docstring).

    kind: one of `KINDS`; constants: the series (a key of `SERIES_CONSTANTS[kind]`: for angular-contact
    bearings the design "single_row", "double_row" or "four_point"; "full_complement" for a cylindrical
    one) or the tuple of Table 3's constants. F_r, F_a [N], ω the relative ring speed [rad/s], ν the
    operating viscosity [m²/s], d, D [m]; supply one of `SUPPLIES` (K_rs; drag only in an oil bath).
    C₀ [N] for deep-groove ball bearings, Y [-] for tapered ones. μ_sl: `sliding_friction_coefficient`
    if given (the catalogue's worked example takes 0.05), else blended by φ_bl between μ_bl and μ_EHL
    (`full_film_coefficient`, default by kind or `base_oil`, one of `FULL_FILM_COEFFICIENTS_BY_OIL`).
    Drag: V_M `drag_loss_factor` read off the catalogue's diagram (None: no drag), B `inner_ring_width`
    [m] for roller bearings, `rows` of balls (default 2 for double-row, else 1). Seals: `seal` a key of
    `SEAL_CONSTANTS` or (β, K_S1, K_S2), d_s `counterface_diameter` [m], `seals` 1 or 2. K_Z, K_L default
    from the bearing type (`bearing_type_constants`).
    """
    table_constants = series_constants(kind, constants)
    if supply not in REPLENISHMENT_CONSTANTS:
        raise ValueError(f"supply must be one of {SUPPLIES}, got {supply!r}")
    check_range("kinematic_viscosity", kinematic_viscosity, low=0.0, unit=" m²/s")
    check_range("radial", radial, low=0.0, low_open=False, unit=" N")
    check_range("axial", axial, low=0.0, low_open=False, unit=" N")
    check_range("bore", bore, low=0.0, unit=" m")
    check_range("outside_diameter", outside_diameter, low=0.0, unit=" m")
    if _is_concrete(bore, outside_diameter) and np.any(np.asarray(outside_diameter) <= np.asarray(bore)):
        raise ValueError(f"outside_diameter must be larger than the bore, got D = {outside_diameter} m, d = {bore} m")
    check_range("static_load_rating", static_load_rating, low=0.0, unit=" N")
    if seals not in (1, 2):
        raise ValueError(f"seals must be 1 or 2, got {seals!r}")

    needs_length = kind in ROLLER_LENGTH_KINDS
    if geometry_constant is None or (needs_length and roller_length_constant is None):
        if not isinstance(constants, str):
            raise ValueError("geometry_constant: K_Z (and K_L for roller bearings) must be given with a tuple of constants")
        type_geometry, type_length = bearing_type_constants(kind, constants)
        geometry_constant = type_geometry if geometry_constant is None else geometry_constant
        roller_length_constant = type_length if roller_length_constant is None else roller_length_constant

    pitch_diameter = 0.5 * (bore + outside_diameter)
    rolling_variable, sliding_variable = frictional_variables(kind, table_constants, radial, axial, speed, pitch_diameter,
                                                              static_load_rating=static_load_rating,
                                                              axial_load_factor=axial_load_factor)
    if sliding_friction_coefficient is None:
        if full_film_coefficient is None:
            if base_oil not in FULL_FILM_COEFFICIENTS_BY_OIL:
                raise ValueError(f"base_oil must be one of {tuple(FULL_FILM_COEFFICIENTS_BY_OIL)}, got {base_oil!r}")
            full_film_coefficient = FULL_FILM_COEFFICIENTS_BY_KIND.get(kind, FULL_FILM_COEFFICIENTS_BY_OIL[base_oil])
        mu = sliding_coefficient(kinematic_viscosity, speed, pitch_diameter, full_film_coefficient, boundary_coefficient)
    else:
        mu = jnp.asarray(sliding_friction_coefficient, dtype=jnp.float64)

    rolling = rolling_moment(rolling_variable, kinematic_viscosity, speed)
    sliding = sliding_moment(sliding_variable, mu)
    inlet_shear = inlet_shear_factor(kinematic_viscosity, speed, pitch_diameter)
    replenishment = replenishment_factor(kinematic_viscosity, speed, bore, outside_diameter, geometry_constant,
                                         REPLENISHMENT_CONSTANTS[supply])
    drag = _drag(kind, constants, supply, drag_loss_factor, speed, bore, outside_diameter, inner_ring_width, rows,
                 geometry_constant, roller_length_constant)
    seal_part = _seal(seal, counterface_diameter, seals)
    total = inlet_shear * replenishment * rolling + sliding + seal_part + drag
    return FrictionalMoment(rolling=rolling, sliding=sliding, seal=seal_part, drag=drag, inlet_shear=inlet_shear,
                            replenishment=replenishment, sliding_coefficient=mu, rolling_variable=rolling_variable,
                            sliding_variable=sliding_variable, total=total, power=friction_power(total, speed))


def _drag(kind, series, supply, drag_loss_factor, speed, bore, outside_diameter, inner_ring_width, rows, geometry_constant,
          roller_length_constant):
    if drag_loss_factor is None:
        return jnp.zeros(())
    if supply != "oil_bath":
        raise ValueError(f"drag_loss_factor: the drag loss applies to supply 'oil_bath' only, got supply {supply!r}")
    check_range("drag_loss_factor", drag_loss_factor, low=0.0, low_open=False, why="V_M of the catalogue's diagram")
    if kind not in ROLLER_LENGTH_KINDS:
        rows = (2 if series == "double_row" else 1) if rows is None else rows
        return drag_moment_ball(drag_loss_factor, speed, bore, outside_diameter, geometry_constant, rows)
    _require("inner_ring_width", inner_ring_width, "the drag loss of roller bearings (B [m])")
    return drag_moment_roller(drag_loss_factor, speed, bore, outside_diameter, inner_ring_width, geometry_constant,
                              roller_length_constant)


def _seal(seal, counterface_diameter, seals):
    if seal is None:
        return jnp.zeros(())
    if isinstance(seal, str):
        if seal not in SEAL_CONSTANTS:
            raise ValueError(f"seal must be one of {tuple(SEAL_CONSTANTS)} or (β, K_S1, K_S2), got {seal!r}")
        seal = SEAL_CONSTANTS[seal]
    _require("counterface_diameter", counterface_diameter, "a seal's moment (d_s [m])")
    exponent, diameter_coefficient, constant_term = seal
    return seal_moment(diameter_coefficient, exponent, constant_term, counterface_diameter, seals)


def _require(name, value, purpose):
    if value is None:
        raise ValueError(f"{name} is needed for {purpose}")


def bearing_moment(kind: str, static_rating, angle, skf: SkfBearing, kinematic_viscosity, speed,
                   force) -> FrictionalMoment:
    """`frictional_moment` of a bearing of `kind` described by `skf` under [Fx, Fy, Fz] `force` [N] at
    the relative ring speed `speed` [rad/s] in oil of `kinematic_viscosity` [m²/s]: its C₀ `static_rating`
    [N] (a deep-groove ball bearing's α_F reads it; None where unknown), and ISO 281's Y = 0.4 cot α
    of the cup `angle` [rad] where the kind's rows read it (a tapered one)."""
    options = {"static_load_rating": static_rating}
    if "axial_load_factor" in needed_inputs(kind):
        options["axial_load_factor"] = roller_life.axial_load_factor(angle)
    radial, axial = jnp.sqrt(force[0] ** 2 + force[1] ** 2), jnp.abs(force[2])
    return frictional_moment(
        kind, skf.series, radial, axial, speed, kinematic_viscosity, skf.bore, skf.outside_diameter, supply=skf.supply,
        drag_loss_factor=skf.drag_loss_factor, inner_ring_width=skf.inner_ring_width, seal=skf.seal,
        counterface_diameter=skf.counterface_diameter, seals=skf.seals, **options)
