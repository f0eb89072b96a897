"""Ball kinematics under raceway control, centrifugal force and gyroscopic moment.

docs/theory.md, §Ball kinematics (the stiffness paper; Harris & Kotzalas vol. 2, ch. 2–3, Jones'
raceway control), with r = D_w / d_m and ω the speed of the inner ring relative to the outer ring:

    outer-raceway control: tan β = sin α_o / (cos α_o + r)
    inner-raceway control: tan β = sin α_i / (cos α_i − r)
    ω_m = ω / (1 + (1 + r cos α_o)(cos α_i + tan β sin α_i) / ((1 − r cos α_i)(cos α_o + tan β sin α_o)))
    ω_R = −ω / ( ((cos α_o + tan β sin α_o)/(1 + r cos α_o) + (cos α_i + tan β sin α_i)/(1 − r cos α_i)) · r cos β )
    F_c = (π/12) ρ D_w³ d_m ω_m²,   M_g = −J ω_R ω_m sin β with J = ρ π D_w⁵ / 60.

ω_m is the orbital speed relative to the outer ring; the absolute orbital speed, which sets F_c and
M_g, adds the outer ring's speed. Relative to the orbiting frame the ball turns at
ω_R (cos β ẑ − sin β e_r) (ẑ the bearing axis, e_r radially outward at the ball): with this axis
the ball rolls without sliding at both contacts and without spin at the controlling one. ω_R turns
opposite to ω_m.
"""

import jax.numpy as jnp

RACE_CONTROLS = ("outer", "inner")


def pitch_angle(contact_angle_inner, contact_angle_outer, diameter_ratio, race_control="outer"):
    """Ball spin-axis pitch angle β [rad] under outer- or inner-raceway control."""
    if race_control == "outer":
        return jnp.arctan2(jnp.sin(contact_angle_outer), jnp.cos(contact_angle_outer) + diameter_ratio)
    if race_control == "inner":
        return jnp.arctan2(jnp.sin(contact_angle_inner), jnp.cos(contact_angle_inner) - diameter_ratio)
    raise ValueError(f"race_control must be one of {RACE_CONTROLS}, got {race_control!r}")


def ball_speeds(relative_speed, contact_angle_inner, contact_angle_outer, diameter_ratio, race_control="outer"):
    """(orbital speed ω_m relative to the outer ring, spin speed ω_R, pitch angle β) [rad/s, rad/s, rad].

    `relative_speed` is ω_inner − ω_outer [rad/s]; `diameter_ratio` is r = D_w/d_m [-].
    """
    beta = pitch_angle(contact_angle_inner, contact_angle_outer, diameter_ratio, race_control)
    tan_beta = jnp.tan(beta)
    inner_term = (jnp.cos(contact_angle_inner) + tan_beta * jnp.sin(contact_angle_inner)) / (
        1.0 - diameter_ratio * jnp.cos(contact_angle_inner))
    outer_term = (jnp.cos(contact_angle_outer) + tan_beta * jnp.sin(contact_angle_outer)) / (
        1.0 + diameter_ratio * jnp.cos(contact_angle_outer))
    orbital = relative_speed / (1.0 + inner_term / outer_term)
    spin = -relative_speed / ((outer_term + inner_term) * diameter_ratio * jnp.cos(beta))
    return orbital, spin, beta


def centrifugal_force(ball_density, ball_diameter, pitch_diameter, orbital_speed):
    """F_c = (π/12) ρ D_w³ d_m ω_m² [N] with the absolute orbital speed ω_m [rad/s]."""
    return jnp.pi / 12.0 * ball_density * ball_diameter**3 * pitch_diameter * orbital_speed**2


def gyroscopic_moment(ball_density, ball_diameter, orbital_speed, spin_speed, pitch_angle_value):
    """Gyroscopic moment M_g = −J ω_R ω_m sin β [N·m], J = ρ π D_w⁵ / 60 (solid sphere).

    Its direction: the moment the raceways must apply to the ball is dL/dt = ω_m ẑ × (J ω_b) =
    M_g e_t, with e_t = ẑ × e_r the direction of increasing azimuth. Since ω_R turns opposite to
    ω_m, M_g > 0 whenever β > 0 (positive contact angles), in either direction of rotation; it
    equals Harris's magnitude J |ω_R ω_m sin β| there and changes sign with β.
    """
    inertia = ball_density * jnp.pi * ball_diameter**5 / 60.0
    return -inertia * spin_speed * orbital_speed * jnp.sin(pitch_angle_value)


def raceway_entrainment_speed(ring_speed, orbital_speed, pitch_diameter, diameter_ratio_value, side: str):
    """Mean entrainment speed u = ½ |ω_ring − ω_m| d_m (1 ∓ γ) [m/s] of a ball–raceway contact in
    pure rolling, γ = D_w cos α / d_m, − for the inner and + for the outer raceway (Harris &
    Kotzalas vol. 1, ch. 8; Hamrock & Dowson's u)."""
    sign = {"inner": -1.0, "outer": 1.0}[side]
    return 0.5 * jnp.abs(ring_speed - orbital_speed) * pitch_diameter * (1.0 + sign * diameter_ratio_value)
