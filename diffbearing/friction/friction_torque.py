"""Friction torque and power loss of a rolling bearing: Palmgren's load-dependent and viscous
moments (Harris & Kotzalas vol. 1, ch. 8 "Friction"; Schaeffler HR 1, "Friction and increases in
temperature", whose constants are used; the Timken Engineering Manual, Table 114).

    M = M₀ + M₁
    M₀ = 10⁻⁷ f₀ (ν n)^{2/3} d_m³      for ν n ≥ 2000,   M₀ = 160·10⁻⁷ f₀ d_m³ below   [N·mm]
    M₁ = f₁ P₁ d_m                                                                  [N·mm]

with ν the kinematic viscosity at the operating temperature [mm²/s] (a grease's base oil), n the
speed [r/min], d_m the pitch diameter [mm]. f₀ depends on the bearing series and lubrication (HR 1:
oil bath or recirculating oil, and grease or oil mist); f₁ = a (P₀/C₀)^b for ball bearings (P₀, C₀
of ISO 76; of a thrust ball bearing P₀ = F_a, C₀ = C₀a) and a constant for cylindrical, tapered,
needle and thrust roller bearings; P₁ per HR 1: 3.3 F_a − 0.1 F_r (deep groove), F_a − 0.1 F_r
(single-row angular contact), 2 Y F_a (tapered, Y of ISO 281 = 0.4 cot α), F_r (cylindrical and
needle), F_a (thrust bearings: "the axial load for axial bearings"), and for spherical roller
bearings, with e = 1.5 tan α (ISO 281's e of double-row roller bearings),

    P₁ = 1.6 F_a / e                          F_a/F_r > e
    P₁ = F_r (1 + 0.6 (F_a/(e F_r))³)         F_a/F_r ≤ e        (continuous at e: 1.6 F_r)

and never below F_r. Power loss N = M ω.

The default constants (`PALMGREN_CONSTANTS`) are HR 1's for the 62 series of deep-groove ball
bearings, the 72-B series of angular-contact ball bearings, the 2..-E series of cylindrical and the
302 series of tapered roller bearings, the 222 series of spherical roller bearings (f₁ = 0.0005
(P₀/C₀)^0.33), NA49 needle roller bearings (f₁ = 0.0005), 511–514 thrust ball bearings (f₁ = 0.0012
(F_a/C₀a)^0.33) and 811 cylindrical roller thrust bearings (f₁ = 0.0015) — HR 1 (Schaeffler 2006),
"Friction and increases in temperature", pp. 55–60, its tables of bearing factors; the spherical
roller, needle and thrust rows agree with KRW Leipzig's catalogue (after Brändlein, Wälzlagerpraxis)
where it has them. Timken's Table 114 (the ISO 15312 reference conditions, P₀ = 0.05 C₀, oil) gives
the same for the deep-groove and cylindrical series (tests) and a lower f₁ for angular-contact ones
(0.00025 against 0.00037).
"""

import jax.numpy as jnp

from ..numerics import positive_power
from ..ratings.roller_life import axial_load_factor

# bearing kind → (f₀ grease or oil mist, f₀ oil bath or recirculating oil, a, b) with f₁ = a (P₀/C₀)^b
PALMGREN_CONSTANTS = {
    "deep_groove_ball": (1.3, 2.0, 0.0009, 0.5),
    "angular_contact_ball": (1.3, 2.0, 0.001, 0.33),
    "cylindrical_roller": (1.3, 2.0, 0.0003, 0.0),
    "tapered_roller": (2.0, 3.0, 0.0004, 0.0),
    "spherical_roller": (2.7, 4.0, 0.0005, 0.33),
    "needle_roller": (4.0, 5.5, 0.0005, 0.0),
    "thrust_ball": (1.0, 1.5, 0.0012, 0.33),
    "cylindrical_roller_thrust": (2.0, 3.0, 0.0015, 0.0),
}
LOW_SPEED_LIMIT = 2000.0  # ν n [mm²/s · r/min] below which M₀ is constant


def speed_factor(coefficient, exponent, static_load, static_rating):
    """f₁ = a (P₀/C₀)^b [-] from the equivalent static load P₀ and the static rating C₀ [N]."""
    return coefficient * positive_power(static_load / static_rating, exponent) if exponent else coefficient


def viscous_torque(f0, kinematic_viscosity, speed, pitch_diameter):
    """Palmgren's viscous moment M₀ [N·m] from f₀ [-], ν [m²/s], the relative ring speed [rad/s] and
    d_m [m] (module docstring; the formula in its catalogue units, N·mm, mm²/s, r/min, mm)."""
    product = kinematic_viscosity * 1e6 * jnp.abs(speed) * 30.0 / jnp.pi
    dm3 = (pitch_diameter * 1e3) ** 3
    fast = 1e-7 * f0 * positive_power(product, 2.0 / 3.0) * dm3
    return jnp.where(product >= LOW_SPEED_LIMIT, fast, 160e-7 * f0 * dm3) * 1e-3


def spherical_roller_friction_load(radial, axial, contact_angle):
    """P₁ [N] of a spherical roller bearing (HR 1, module docstring) from F_r, F_a [N] and α [rad]:
    1.6 F_a/e past e = 1.5 tan α, F_r (1 + 0.6 (F_a/(e F_r))³) up to it."""
    e = 1.5 * jnp.tan(contact_angle)
    heavy = axial > e * radial
    safe_radial = jnp.where(heavy | (radial <= 0.0), 1.0, radial)  # F_a/F_r finite where unused or unloaded
    light = radial * (1.0 + 0.6 * (jnp.where(heavy, 0.0, axial) / (e * safe_radial)) ** 3)
    return jnp.where(heavy, 1.6 * axial / e, light)


# bearing kind → P₁ [N] of HR 1 before its floor F_r, from (F_r, F_a [N], the contact angle [rad])
FRICTION_LOADS = {
    "deep_groove_ball": lambda radial, axial, angle: 3.3 * axial - 0.1 * radial,
    "angular_contact_ball": lambda radial, axial, angle: axial - 0.1 * radial,
    "tapered_roller": lambda radial, axial, angle: 2.0 * axial_load_factor(angle) * axial,
    "cylindrical_roller": lambda radial, axial, angle: radial,
    "spherical_roller": spherical_roller_friction_load,
    "needle_roller": lambda radial, axial, angle: radial,
    "thrust_ball": lambda radial, axial, angle: axial,
    "cylindrical_roller_thrust": lambda radial, axial, angle: axial,
}


def friction_load(kind: str, radial, axial, contact_angle=0.0):
    """P₁ [N] of HR 1 for F_r, F_a [N] (module docstring, `FRICTION_LOADS`), never below F_r;
    `contact_angle` [rad] of a tapered bearing."""
    if kind not in FRICTION_LOADS:
        raise ValueError(f"kind must be one of {tuple(PALMGREN_CONSTANTS)}, got {kind!r}")
    return jnp.maximum(FRICTION_LOADS[kind](radial, axial, contact_angle), radial)


def load_torque(f1, load, pitch_diameter):
    """Palmgren's load-dependent moment M₁ = f₁ P₁ d_m [N·m] (P₁ [N], d_m [m])."""
    return f1 * load * pitch_diameter


def friction_power(torque, speed):
    """Power loss [W] of the friction torque [N·m] at the relative ring speed [rad/s]."""
    return torque * jnp.abs(speed)
