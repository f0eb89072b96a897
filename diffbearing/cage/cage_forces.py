"""Quasi-static forces on an outer-ring guided ball-bearing cage, and its restoring force f_inv.

The cage paper (docs/theory.md, §Cage forces; Liu et al., J. Vib. Shock 39(21), 2020, §2).
Inertial frame: z the bearing axis, x and y radial; ball j sits at azimuth ψ_j = φ_F + 2πj/Z on
the pitch circle, with φ_F the direction of the radial load; the cage centre is offset by (x, y)
and tilted by (θx, θy) (small angles). Assumptions of the paper:

1. steady rotation: the cage turns at the epicyclic speed ω_c = ω_o + (ω_i − ω_o)(1 − γ)/2,
   γ = D_w cos α/d_m, its spin in moment balance on the pitch circle (item 3; the radial parts of
   the wall normals and the friction leave a small M_z, which `moment` reports);
2. balls in the load zone push the cage, the others resist it: `cage.pushing_balls` m balls
   nearest the load direction push, `cage.resisting_balls` n balls nearest the opposite
   direction resist (load zone by the Sjövall integrals, J_r/J_a = F_r tan α/F_a);
3. a resisting ball costs its oil drag f_v = ½ C_D ρ v² S (S = π D_w²/4, v = ω_c d_m/2; C_D of a
   sphere, Schiller–Naumann: 24/Re (1 + 0.15 Re^0.687), at least 0.44); the pushing balls share
   the cage's whole resistance equally: m F_push d_m/2 = n f_v d_m/2 + |T_lands| (eq. 16 with the
   lands' shear torque added, so the spin is in balance).

Each contacting ball's wall force follows from its prescribed circumferential force
(`cage_pocket.seat_ball`), the lands from `cage_lands.land_force`; the resultant force and moment
are about the cage centre, and the restoring force f_inv = −F·ê is the resultant's component
opposite to the offset direction ê.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..numerics import positive_power, safe_norm
from ..params import BallBearing, Cage, Lubricant, Operating
from ..ratings.load_distribution import load_zone_half_angle, load_zone_parameter
from .cage_lands import land_force
from .cage_pocket import ball_spin, pocket_force, pocket_stiffness, radial_distance_on_sphere, seat_ball

# J_r/J_a spans (0.6, 1): at 0.6 every ball is loaded, towards 1 a single one (load_distribution.py).
_RATIO_RANGE = (0.6 + 1e-9, 1.0 - 1e-9)


class CageForces(eqx.Module):
    """Forces on the cage [N], moments [N·m] about its centre, inertial frame."""

    restoring_force: jax.Array  # f_inv = −F·ê, the resultant's component against the offset [N]
    force: jax.Array  # (3,) resultant of pockets and lands [N]
    moment: jax.Array  # (3,) about the cage centre [N·m]
    land_force: jax.Array  # (2, 2) radial-plane force of land A (z = −s/2) and B (z = +s/2) [N]
    land_eccentricity: jax.Array  # (2,) relative eccentricity ε at each land [-]
    land_contact: jax.Array  # (2,) metal-contact force N_m at each land [N]
    pocket_forces: jax.Array  # (Z, 3) force of each ball on the cage (0 where it does not touch) [N]
    pushing: jax.Array  # (Z,) weight of each ball's role as a pusher (`ball_roles`)
    resisting: jax.Array  # (Z,) weight of each ball's role as a resister
    drag: jax.Array  # oil drag f_v on one ball [N]
    push: jax.Array  # circumferential force F_push of each pushing ball [N]
    load_zone: jax.Array  # full angle of the load zone 2ψ_l [rad]
    cage_speed: jax.Array  # ω_c [rad/s]


def epicyclic_cage_speed(bearing: BallBearing, operating: Operating):
    """ω_c = ω_o + (ω_i − ω_o)(1 − γ)/2 [rad/s], γ = D_w cos α/d_m (pure rolling)."""
    gamma = bearing.ball_diameter * jnp.cos(bearing.free_contact_angle) / bearing.pitch_diameter
    return operating.outer_speed + 0.5 * (operating.inner_speed - operating.outer_speed) * (1.0 - gamma)


def ball_drag(orbital_speed, ball_diameter, density, viscosity):
    """Oil drag ½ C_D ρ v² (π D_w²/4) [N] on a ball orbiting at v [m/s] (paper eq. 16, after Deng
    et al., *Rolling bearing design principles*), C_D of a sphere by Schiller–Naumann below
    Re = 1000 and 0.44 above. Written as max(3π η D_w v (1 + 0.15 Re^0.687), 0.055 π ρ v² D_w²),
    which is exact at v = 0 (Stokes) and differentiable there."""
    speed = jnp.abs(orbital_speed)
    reynolds = density * speed * ball_diameter / viscosity
    stokes = 3.0 * jnp.pi * viscosity * ball_diameter * speed * (1.0 + 0.15 * positive_power(reynolds, 0.687))
    newton = 0.5 * 0.44 * density * speed**2 * 0.25 * jnp.pi * ball_diameter**2
    return jnp.maximum(stokes, newton)


def ball_roles(ball_count: int, pushing_balls, resisting_balls):
    """(pushing, resisting) weights (Z,) in [0, 1]: the m balls nearest ψ = φ_F push and the n
    nearest φ_F + π resist. Balls at equal distance on either side form one class; a class the
    count fills only in part shares the rest equally (m = 2 of 17: ball 0 whole, balls ±1 half
    each), which is the mean of the two mirror-image choices, so the roles stay symmetric about the
    load direction. m and n may be traced (a sweep varies them)."""
    angles = 2.0 * np.pi * np.arange(ball_count) / ball_count

    def weights(distance, count):
        classes, index, sizes = np.unique(np.round(distance, 9), return_inverse=True, return_counts=True)
        before = np.concatenate([[0], np.cumsum(sizes)[:-1]])
        return jnp.clip((count - before[index]) / sizes[index], 0.0, 1.0)

    ahead = np.abs(np.angle(np.exp(1j * angles)))
    behind = np.abs(np.angle(np.exp(1j * (angles - np.pi))))
    return weights(ahead, pushing_balls), weights(behind, resisting_balls)


def loaded_ball_count(bearing: BallBearing, force):
    """Balls inside the Sjövall load zone for the load [Fx, Fy, Fz] [N], ball 0 on the load line
    (a float count; traceable)."""
    angles = 2.0 * np.pi * np.arange(bearing.ball_count) / bearing.ball_count
    return jnp.sum(jnp.abs(np.angle(np.exp(1j * angles))) <= load_zone_half(bearing, force)).astype(float)


def load_zone_half(bearing: BallBearing, force):
    """ψ_l [rad], half the Sjövall load zone for the load [Fx, Fy, Fz] [N]: J_r/J_a = F_r tan α/F_a,
    clipped to (0.6, 1) (every ball loaded below, a single one above)."""
    force = jnp.asarray(force)
    radial = safe_norm(force[:2])
    axial = jnp.abs(force[2])
    ratio = radial * jnp.tan(bearing.free_contact_angle) / jnp.where(axial > 0, axial, 1.0)
    ratio = jnp.clip(jnp.where(axial > 0, ratio, _RATIO_RANGE[1]), *_RATIO_RANGE)
    return load_zone_half_angle(load_zone_parameter(ratio))


def cage_forces(cage: Cage, bearing: BallBearing, operating: Operating, lubricant: Lubricant, offset,
                tilt=None) -> CageForces:
    """Quasi-static forces on the cage with its centre at `offset` (x, y) [m] and tilted by
    `tilt` (θx, θy) [rad] (module docstring for the model and its assumptions)."""
    offset = jnp.asarray(offset)
    tilt = jnp.zeros(2) if tilt is None else jnp.asarray(tilt)
    count = bearing.ball_count
    ball_radius = 0.5 * bearing.ball_diameter
    pitch_radius = 0.5 * bearing.pitch_diameter
    pocket_radius = ball_radius + 0.5 * cage.pocket_clearance
    angle = bearing.free_contact_angle

    relative = operating.inner_speed - operating.outer_speed
    cage_speed = epicyclic_cage_speed(bearing, operating)
    rotation = jnp.sign(cage_speed)
    drag = ball_drag(cage_speed * pitch_radius, bearing.ball_diameter, lubricant.density, lubricant.viscosity)

    # lands A (z = −s/2) and B (z = +s/2): the tilt moves each land's centre by θ × (0, 0, z)
    half_spacing = 0.5 * cage.land_spacing
    swing = half_spacing * jnp.stack([tilt[1], -tilt[0]])
    clearance = 0.5 * cage.guide_clearance
    land_forces, land_torques, land_eccentricity, land_contact = jax.vmap(
        lambda sign: land_force(offset + sign * swing, clearance, cage.land_width, cage.outer_radius, cage_speed,
                                operating.outer_speed, lubricant.viscosity, cage.film_threshold,
                                cage.contact_stiffness, cage.friction))(jnp.array([-1.0, 1.0]))
    land_torque = jnp.sum(land_torques)

    pushing, resisting = ball_roles(count, cage.pushing_balls, cage.resisting_balls)
    push = (cage.resisting_balls * drag * pitch_radius - rotation * land_torque) / (
        jnp.maximum(cage.pushing_balls, 1.0) * pitch_radius)
    circumferential = rotation * jnp.where(pushing > 0, push, jnp.where(resisting > 0, -drag, 0.0))
    weight = jnp.where(circumferential != 0.0, pushing + resisting, 0.0)
    target = jnp.where(weight > 0, circumferential, 1.0)  # a stand-in where no ball touches (weight 0)

    azimuth = jnp.arctan2(operating.force[1], operating.force[0]) + 2.0 * jnp.pi * jnp.arange(count) / count
    radial_unit = jnp.stack([jnp.cos(azimuth), jnp.sin(azimuth), jnp.zeros(count)], axis=-1)
    tangential_unit = jnp.stack([-jnp.sin(azimuth), jnp.cos(azimuth), jnp.zeros(count)], axis=-1)
    axial_unit = jnp.broadcast_to(jnp.array([0.0, 0.0, 1.0]), (count, 3))
    radial_offset = -(radial_unit[:, :2] @ offset)  # ball centre relative to its pocket, x_b
    axial_offset = -pitch_radius * (tilt[0] * jnp.sin(azimuth) - tilt[1] * jnp.cos(azimuth))  # z_b

    stiffness = pocket_stiffness(ball_radius, pocket_radius, bearing.ball_material.elastic_modulus,
                                 bearing.ball_material.poisson_ratio, cage.material.elastic_modulus,
                                 cage.material.poisson_ratio, cage.pocket)
    spin = ball_spin(relative, bearing.pitch_diameter, bearing.ball_diameter, angle)
    play = pocket_radius - ball_radius

    def one_ball(force, x_b, z_b):
        approach = seat_ball(force, radial_distance_on_sphere(x_b, cage.pocket), z_b, play, stiffness)
        return pocket_force(jnp.stack([x_b, 0.0, z_b]), approach, jnp.sign(force), pocket_radius, ball_radius,
                            spin, cage.friction, stiffness, cage.pocket)

    local_force, local_contact = jax.vmap(one_ball)(target, radial_offset, axial_offset)
    frames = jnp.stack([radial_unit, tangential_unit, axial_unit], axis=-1)  # columns: pocket axes
    pocket_forces = weight[:, None] * jnp.einsum("jab,jb->ja", frames, local_force)
    arms = pitch_radius * radial_unit + jnp.einsum("jab,jb->ja", frames, local_contact)

    land_3d = jnp.concatenate([land_forces, jnp.zeros((2, 1))], axis=1)
    land_arms = jnp.array([[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]]) * half_spacing
    force = jnp.sum(pocket_forces, axis=0) + jnp.sum(land_3d, axis=0)
    moment = (jnp.sum(jnp.cross(arms, pocket_forces), axis=0) + jnp.sum(jnp.cross(land_arms, land_3d), axis=0)
              + jnp.array([0.0, 0.0, 1.0]) * land_torque)
    distance = safe_norm(offset)
    direction = jnp.where(distance > 0, offset / jnp.where(distance > 0, distance, 1.0), 0.0)
    return CageForces(
        restoring_force=-(force[:2] @ direction), force=force, moment=moment, land_force=land_forces,
        land_eccentricity=land_eccentricity, land_contact=land_contact, pocket_forces=pocket_forces,
        pushing=pushing, resisting=resisting, drag=drag, push=push,
        load_zone=2.0 * load_zone_half(bearing, operating.force), cage_speed=cage_speed)


def cage_offset(cage: Cage, force, eccentricity, offset_angle):
    """Cage centre offset (x, y) [m] at relative eccentricity ε (offset over the radial guide
    clearance c_g/2) in the direction `offset_angle` [rad] from the radial load [Fx, Fy, Fz] [N]."""
    force = jnp.asarray(force)
    direction = jnp.arctan2(force[1], force[0]) + offset_angle
    return eccentricity * 0.5 * cage.guide_clearance * jnp.stack([jnp.cos(direction), jnp.sin(direction)])
