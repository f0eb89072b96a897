"""Overrolling frequencies of a rolling bearing: cage (FTF), ball or roller pass over the outer and
inner raceways (BPFO, BPFI) and the element's spin (BSF), in Hz and per shaft revolution.

With the rings turning at ω_i and ω_o and the cage (the elements' orbit) at ω_c, Z elements of
diameter D rolling on an outer raceway of radius R_o (the contact point's distance from the
bearing axis) give

    f_c  = ω_c / 2π                               cage (fundamental train) frequency
    BPFO = Z |ω_c − ω_o| / 2π                     element passes over a point of the outer raceway
    BPFI = Z |ω_i − ω_c| / 2π                     element passes over a point of the inner raceway
    BSF  = |ω_c − ω_o| (2 R_o / D) / 2π           element rolling relative to the cage

(BSF from rolling without slip at the outer contact: the element's surface moves with the outer
raceway relative to the cage). Pure rolling at both contacts of an element whose contact points lie
at radii R_i, R_o gives the cage speed ω_c = (ω_i R_i + ω_o R_o) / (R_i + R_o); at one contact
angle α, with γ = D cos α / d_m, R_i = d_m (1 − γ)/2 and R_o = d_m (1 + γ)/2, these are the
textbook closed forms of vibration diagnostics (Harris & Kotzalas vol. 1, §8)

    f_c = ½ [f_i (1 − γ) + f_o (1 + γ)],   BPFO = ½ Z |f_i − f_o| (1 − γ),
    BPFI = ½ Z |f_i − f_o| (1 + γ),        BSF  = (d_m / 2D) |f_i − f_o| (1 − γ²).

A ball bearing's balls orbit at speeds set by their own contact angles and the raceway-control
hypothesis (`kinematics.ball_speeds`); the cage takes the load-weighted mean of the balls' orbital
speeds (the balls of the load zone drive it; all balls alike when none carries load).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from .bearings.ball import kinematics
from .bearings.roller.roller_equilibrium import directions
from .bearings.roller.roller_geometry import roller_diameter


class OverrollingFrequencies(eqx.Module):
    """Overrolling frequencies [Hz] (or orders: per revolution of the inner ring relative to the
    outer ring [-]): cage, ball (roller) pass outer and inner, ball (roller) spin."""

    cage: jax.Array
    ball_pass_outer: jax.Array
    ball_pass_inner: jax.Array
    ball_spin: jax.Array


def element_frequencies(inner_speed, outer_speed, cage_speed, element_count, element_diameter, outer_contact_radius
                        ) -> OverrollingFrequencies:
    """Overrolling frequencies [Hz] from the ring and cage speeds [rad/s], the element count Z,
    the element diameter D [m] and the outer contact radius R_o [m] (module docstring)."""
    outer_relative = jnp.abs(cage_speed - outer_speed)
    return OverrollingFrequencies(
        cage=cage_speed / (2.0 * jnp.pi),
        ball_pass_outer=element_count * outer_relative / (2.0 * jnp.pi),
        ball_pass_inner=element_count * jnp.abs(inner_speed - cage_speed) / (2.0 * jnp.pi),
        ball_spin=outer_relative * 2.0 * outer_contact_radius / element_diameter / (2.0 * jnp.pi),
    )


def pure_rolling_cage_speed(inner_speed, outer_speed, inner_contact_radius, outer_contact_radius):
    """Cage speed ω_c = (ω_i R_i + ω_o R_o) / (R_i + R_o) [rad/s] of elements rolling without slip
    on raceway contact points at radii R_i, R_o [m] from the bearing axis."""
    return (inner_speed * inner_contact_radius + outer_speed * outer_contact_radius) / (
        inner_contact_radius + outer_contact_radius)


def nominal_frequencies(inner_speed, outer_speed, element_count, element_diameter, pitch_diameter, contact_angle
                        ) -> OverrollingFrequencies:
    """The textbook overrolling frequencies [Hz] at one contact angle α [rad] (module docstring),
    ring speeds in rad/s, D and d_m in m."""
    gamma = element_diameter * jnp.cos(contact_angle) / pitch_diameter
    inner_radius, outer_radius = 0.5 * pitch_diameter * (1.0 - gamma), 0.5 * pitch_diameter * (1.0 + gamma)
    cage = pure_rolling_cage_speed(inner_speed, outer_speed, inner_radius, outer_radius)
    return element_frequencies(inner_speed, outer_speed, cage, element_count, element_diameter, outer_radius)


def load_weighted_mean(values, loads):
    """Mean of `values` weighted by `loads` ≥ 0 (the plain mean where every load is zero), with
    finite gradients at zero total load (double `where`)."""
    total = jnp.sum(loads)
    loaded = total > 0.0
    weights = jnp.where(loaded, loads / jnp.where(loaded, total, 1.0), 1.0 / values.shape[-1])
    return jnp.sum(weights * values)


def ball_bearing_frequencies(inner_speed, outer_speed, ball_count, ball_diameter, pitch_diameter, contact_angle_inner,
                             contact_angle_outer, inner_load, race_control="outer") -> OverrollingFrequencies:
    """Overrolling frequencies [Hz] of a ball bearing at its solved contact angles (Z,) [rad]:
    each ball's orbital speed by raceway control (`kinematics.ball_speeds`), the cage at their
    mean weighted by the inner contact loads (Z,) [N], the outer contact radius at that mean's
    outer contact angle. Ring speeds in rad/s, D_w and d_m in m."""
    ratio = ball_diameter / pitch_diameter
    orbital_per_relative, _, _ = kinematics.ball_speeds(1.0, contact_angle_inner, contact_angle_outer, ratio, race_control)
    cage = outer_speed + (inner_speed - outer_speed) * load_weighted_mean(orbital_per_relative, inner_load)
    outer_angle = load_weighted_mean(contact_angle_outer, inner_load)
    outer_radius = 0.5 * (pitch_diameter + ball_diameter * jnp.cos(outer_angle))
    return element_frequencies(inner_speed, outer_speed, cage, ball_count, ball_diameter, outer_radius)


def per_revolution(frequencies_at, inner_speed, outer_speed) -> OverrollingFrequencies:
    """Orders [-]: `frequencies_at(ω_i, ω_o)` [Hz] per revolution of the inner ring relative to the
    outer ring, with the ring speeds scaled to one relative revolution per second (the inner ring
    turning where both stand still). The frequencies are of degree one in the speeds at fixed
    contact angles."""
    relative = inner_speed - outer_speed
    turning = relative != 0.0
    scale = 2.0 * jnp.pi / jnp.where(turning, jnp.abs(relative), 1.0)
    inner, outer = jnp.where(turning, inner_speed * scale, 2.0 * jnp.pi), jnp.where(turning, outer_speed * scale, 0.0)
    return frequencies_at(inner, outer)


def roller_bearing_frequencies(inner_speed, outer_speed, roller_count, roller_diameter, pitch_diameter, cone_angle,
                               cup_angle) -> OverrollingFrequencies:
    """Overrolling frequencies [Hz] of a cylindrical or tapered roller bearing: rollers of
    mid-length diameter D [m] at pitch diameter d_m [m] in pure rolling on the cone (inner) and cup
    (outer) at their contact angles α_i, α_o [rad] (0 for cylindrical), the contact points at
    mid-length, R = d_m/2 ∓ (D/2) cos α from the bearing axis. Ring speeds in rad/s."""
    inner_radius = 0.5 * (pitch_diameter - roller_diameter * jnp.cos(cone_angle))
    outer_radius = 0.5 * (pitch_diameter + roller_diameter * jnp.cos(cup_angle))
    cage = pure_rolling_cage_speed(inner_speed, outer_speed, inner_radius, outer_radius)
    return element_frequencies(inner_speed, outer_speed, cage, roller_count, roller_diameter, outer_radius)


def frequencies_of_balls(bearing, inner_speed, outer_speed, contact_angle_inner, contact_angle_outer, inner_load,
                         race_control="outer") -> OverrollingFrequencies:
    """`ball_bearing_frequencies` [Hz] of a `params.BallBearing` at its balls' solved angles and loads."""
    return ball_bearing_frequencies(inner_speed, outer_speed, bearing.ball_count, bearing.ball_diameter,
                                    bearing.pitch_diameter, contact_angle_inner, contact_angle_outer, inner_load,
                                    race_control)


def frequencies_of_rollers(bearing, raceways, inner_speed, outer_speed) -> OverrollingFrequencies:
    """`roller_bearing_frequencies` [Hz] of a `roller_geometry.RollerBearing` in its
    `roller_equilibrium.RollerRaceways` (cone and cup angles, mid-length diameter)."""
    angles = directions(bearing, raceways)
    return roller_bearing_frequencies(inner_speed, outer_speed, bearing.roller_count, roller_diameter(bearing, 0.0),
                                      raceways.pitch_diameter, angles.cone_angle, angles.cup_angle)
