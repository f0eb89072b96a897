"""Ball–pocket contact of a ball-bearing cage: cylindrical and "outer-lock" pockets.

The cage paper (docs/theory.md, §Cage pockets; Liu et al., J. Vib. Shock 39(21), 2020, eqs. 1–7).
Pocket frame: origin at the pocket's centre on the pitch circle, x radially outward, z along the
bearing axis, y = z × x (the direction of positive rotation). r_b = (x_b, y_b, z_b) is the ball
centre in that frame.

* cylindrical pocket: a cylinder of radius R_pok = (D_w + c_p)/2 about the pocket's x axis;
* outer-lock pocket: for x_b > 0 a sphere of radius R_pok about the origin (its outer mouth is
  narrower than the ball), for x_b ≤ 0 the same cylinder.

Both are one formula: the ball is at distance ρ = |(x_s, y_b, z_b)| from the pocket's centre line,
x_s = max(x_b, 0) for the outer-lock pocket and x_s = 0 for the cylinder, and the contact normal
(from the ball centre to the contact point) is n = (x_s, y_b, z_b)/ρ. The contact point is
r_c = (x_b − x_s, 0, 0) + R_pok n (paper eq. 2's piecewise r_c). The approach is δ = ρ + R_b − R_pok
and the normal force Hertz's Q = K δ^{3/2} (ball in a conforming pocket). The ball's surface slides on the wall at
v = ω_b × (R_b n), with the ball spin ω_b = s ω_R (−sin α, 0, −cos α) (eq. 5, gyroscopic spin
neglected) and ω_R = (d_m/2D_w)(1 − γ²)|ω_i − ω_o| (eq. 6); Coulomb friction μQ acts on the cage
along v (the ball drags the wall with it; the paper's eq. 3 writes the friction on the ball).

Quasi-static use (the paper's model): the ball's circumferential force on the cage is prescribed
(the drag a resisting ball needs, or a pushing ball's share of the cage's resistance, eq. 16), and
the ball sits where its wall contact carries it: `seat_ball` solves Q n_y = F for the approach δ
(monotone in δ), so a ball the pocket holds radially (|x_s| → R_pok − R_b) still gives a finite
force — the rigid-pocket limit Q = F/n_y would diverge there.
"""

import jax
import jax.numpy as jnp

from ..contact.hertz import effective_modulus, load_deflection_constant
from ..numerics import positive_power, safe_norm, safe_sqrt

POCKET_KINDS = ("outer_lock", "cylindrical")

# Newton steps on t = ln(δ − δ_lo) (`seat_ball`): from the rigid-pocket start 12 steps reach
# rounding for every case in tests/test_cage.py.
_SEAT_STEPS = 12


def pocket_stiffness(ball_radius, pocket_radius, ball_material_modulus, ball_poisson, cage_modulus, cage_poisson,
                     kind: str):
    """Hertz constant K [N/m^1.5] (Q = K δ^{3/2}) of the ball on the sphere (outer-lock) or on the
    cylinder: curvature sum Σρ = 2/R_b − 2/R_pok (sphere, F(ρ) = 0) or 2/R_b − 1/R_pok (cylinder,
    F(ρ) = (1/R_pok)/Σρ); Hamrock–Brewe ellipticity (Harris & Kotzalas vol. 1, ch. 6)."""
    modulus = effective_modulus(ball_material_modulus, ball_poisson, cage_modulus, cage_poisson)
    conformity = 1.0 / pocket_radius
    if kind == "outer_lock":
        curvature_sum, difference = 2.0 / ball_radius - 2.0 * conformity, 0.0
    else:
        curvature_sum = 2.0 / ball_radius - conformity
        difference = conformity / curvature_sum
    return load_deflection_constant(curvature_sum, difference, modulus, "hamrock_brewe")


def radial_distance_on_sphere(ball_radial_offset, kind: str):
    """x_s [m]: the part of the ball's radial offset x_b that the pocket wall sees (the sphere
    takes x_b > 0 of an outer-lock pocket; a cylinder sees none)."""
    if kind == "outer_lock":
        return jnp.maximum(ball_radial_offset, 0.0)
    if kind == "cylindrical":
        return jnp.zeros_like(ball_radial_offset)
    raise ValueError(f"cage.pocket must be one of {POCKET_KINDS}, got {kind!r}")


def circumferential_force(approach, sphere_offset, axial_offset, play, stiffness):
    """Circumferential (y) component Q n_y [N] of the wall force when the ball sits at approach δ
    [m] on the wall of positive y; `play` = R_pok − R_b [m]. Increases monotonically with δ."""
    distance = play + approach
    lateral = safe_sqrt(distance**2 - sphere_offset**2 - axial_offset**2)
    return stiffness * positive_power(approach, 1.5) * lateral / distance


def seat_ball(force, sphere_offset, axial_offset, play, stiffness):
    """Approach δ [m] at which the wall carries the circumferential force |F| [N] (F ≠ 0).

    With δ_lo = max(√(x_s² + z²) − (R_pok − R_b), 0), where the wall carries nothing, solves
    ln(Q n_y) = ln|F| for t = ln(δ − δ_lo) by Newton. ln(Q n_y) is nearly linear in t in both
    limits — slope 3/2 for a free ball (Q ∝ δ^{3/2}), slope 1/2 for one the pocket holds radially
    (n_y ∝ √(δ − δ_lo)) — so Newton converges in a few steps from the rigid-pocket start.
    Derivatives by the implicit function theorem (`jax.lax.custom_root`).
    """
    offset = safe_norm(jnp.stack([sphere_offset, axial_offset]))
    low = jnp.maximum(offset - play, 0.0)
    log_force = jnp.log(jnp.abs(force))

    def residual(log_excess):  # t = ln(δ − δ_lo)
        carried = circumferential_force(low + jnp.exp(log_excess), sphere_offset, axial_offset, play, stiffness)
        return jnp.log(carried) - log_force

    def solve(residual, start):
        def step(_, log_excess):
            value, slope = jax.jvp(residual, (log_excess,), (jnp.ones_like(log_excess),))
            return log_excess - jnp.clip(value / jnp.maximum(slope, 0.25), -5.0, 5.0)

        return jax.lax.fori_loop(0, _SEAT_STEPS, step, start)

    # rigid-pocket start: the ball where it touches, with the Hertz approach of Q = |F|/n_y there
    touching = play + low
    lateral = safe_sqrt(touching**2 - offset**2)
    rigid = (jnp.abs(force) * touching / jnp.maximum(lateral, 1e-3 * touching) / stiffness) ** (2.0 / 3.0)

    def tangent_solve(linear, value):
        return value / linear(jnp.ones_like(value))

    return low + jnp.exp(jax.lax.custom_root(residual, jnp.log(rigid), solve, tangent_solve))


def pocket_force(ball_centre, approach, direction, pocket_radius, ball_radius, spin, friction, stiffness, kind: str):
    """(force on the cage [N], contact point [m]) in the pocket frame, for a ball at `ball_centre`
    (x_b, ·, z_b) seated on the wall of sign `direction` (±1 in y) at approach δ.

    Normal force Q n along n = (x_s, y_b, z_b)/ρ plus Coulomb friction μQ along the sliding
    velocity v = ω_b × (R_b n) of the ball's surface on the wall (module docstring)."""
    radial, _, axial = ball_centre
    sphere_offset = radial_distance_on_sphere(radial, kind)
    play = pocket_radius - ball_radius
    distance = play + approach
    lateral = direction * safe_sqrt(distance**2 - sphere_offset**2 - axial**2)
    normal = jnp.stack([sphere_offset, lateral, axial]) / distance
    load = stiffness * positive_power(approach, 1.5)
    sliding = jnp.cross(spin, ball_radius * normal)
    speed = safe_norm(sliding)
    drag_direction = jnp.where(speed > 0, sliding / jnp.where(speed > 0, speed, 1.0), 0.0)
    force = load * normal + friction * load * drag_direction
    contact = jnp.stack([radial - sphere_offset, 0.0, 0.0]) + pocket_radius * normal
    return force, contact


def ball_spin(relative_speed, pitch_diameter, ball_diameter, contact_angle):
    """Ball spin ω_b [rad/s] in the pocket frame, paper eqs. 5–6 with ω_g = 0:
    s ω_R (−sin α, 0, −cos α), ω_R = (d_m/2D_w)(1 − (D_w cos α/d_m)²)|ω|, s = sign(ω)."""
    ratio = ball_diameter * jnp.cos(contact_angle) / pitch_diameter
    magnitude = pitch_diameter / (2.0 * ball_diameter) * (1.0 - ratio**2) * relative_speed
    return magnitude * jnp.stack([-jnp.sin(contact_angle), jnp.zeros_like(contact_angle), -jnp.cos(contact_angle)])


def pocket_impact_force(ball_offset, approach_rate, pocket_radius, ball_radius, spin, friction, stiffness, damping,
                        kind: str):
    """(force on the cage [N], contact point [m]), both (radial, circumferential) in the pocket
    frame, of a ball whose centre sits at `ball_offset` (x_b, y_b) [m] from the pocket centre in
    the cage's mid-plane and approaches the wall at `approach_rate` δ̇ [m/s]: the dynamic,
    penetration-based counterpart of `seat_ball` + `pocket_force` (cage_dynamics.py).

    Approach δ = ρ − (R_pok − R_b), ρ = |(x_s, y_b)| (module docstring); normal force
    Hunt–Crossley Q = K δ^{3/2} max(1 + α δ̇, 0) with damping α [s/m] (`damping`; Hunt & Crossley,
    J. Appl. Mech. 42, 1975), along n = (x_s, y_b)/ρ; Coulomb friction μQ along the in-plane part
    of the wall sliding ω_b × (R_b n), as in `pocket_force`. Zero where the ball is free."""
    radial, circumferential = ball_offset
    sphere_offset = radial_distance_on_sphere(radial, kind)
    distance = safe_norm(jnp.stack([sphere_offset, circumferential]))
    approach = distance - (pocket_radius - ball_radius)
    touching = distance > 0
    normal = jnp.where(touching, jnp.stack([sphere_offset, circumferential]) / jnp.where(touching, distance, 1.0), 0.0)
    load = stiffness * positive_power(approach, 1.5) * jnp.maximum(1.0 + damping * approach_rate, 0.0)
    sliding = jnp.cross(spin, ball_radius * jnp.stack([normal[0], normal[1], 0.0]))
    speed = safe_norm(sliding)
    drag_direction = jnp.where(speed > 0, sliding[:2] / jnp.where(speed > 0, speed, 1.0), 0.0)
    force = load * (normal + friction * drag_direction)
    contact = jnp.stack([radial - sphere_offset, 0.0]) + pocket_radius * normal
    return force, contact
