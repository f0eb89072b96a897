"""The cage's guiding lands on the outer ring as short journal bearings, bounded by metal contact.

Each land (the cage paper, docs/theory.md, §Cage lands; Liu et al. 2020, eqs. 25–28) is a short
journal bearing of width L, radial clearance C and radius R (the cage's outer radius), entrained at
U = R(ω_c + ω_o). With ε = e/C the cage's relative eccentricity at the land, the Ocvirk
(half-Sommerfeld) film force on the cage (Hamrock, Schmid & Jacobson, *Fundamentals of Fluid
Film Lubrication*, 2nd ed., ch. 10) is

    f_n = η U L³/C² · ε²/(1 − ε²)²              against the eccentricity,
    f_t = η U L³/(4C²) · π ε/(1 − ε²)^{3/2}      perpendicular to it, in the sense of rotation,

(the pressure of the converging wedge pushes the cage forward: it drives forward whirl) and the
Couette shear torque T = 2π η R³ L (ω_c − ω_o)/(C √(1 − ε²)) resists the cage's spin relative to
the ring. The paper's eq. 28 writes f_t the other way round and its torque as f_t R; neither
follows from Reynolds' equation, so the forms above are used.

Bound (the hard case ε → 1): below a film h_t (`film_threshold`) the film force is held at its
value at ε_t = 1 − h_t/C and a metal contact of stiffness k_m (`contact_stiffness`) takes the
rest, N_m = k_m (e − e_t), with Coulomb friction μ N_m against the cage's sliding, as dynamic
bearing codes do: every value and derivative is finite for any position, touching the land or
beyond, and at any speed (at rest the contact alone holds the cage).
Directions are written as multiples of e itself (f/ε is finite at ε = 0), so the centred cage
has exact zero force and finite gradients.
"""

import jax.numpy as jnp
import numpy as np

from ..numerics import positive_power, safe_norm

# Gauss–Legendre nodes on each of the two pieces of the pressure arc (`squeeze_film_force`): the
# arc is split at the thinnest film, so the 1/h³ peak sits at a piece's end, where the nodes
# cluster; 64 per piece reproduce the Ocvirk closed forms to < 1e-9 up to ε = 0.99 (tested).
_ARC_NODES, _ARC_WEIGHTS = np.polynomial.legendre.leggauss(64)


def ocvirk_force_factors(eccentricity_ratio):
    """(f_n/ε, f_t/ε) of the short bearing per unit η U L³/C² [-] (finite at ε = 0)."""
    squared = 1.0 - eccentricity_ratio**2
    normal_over_e = eccentricity_ratio / squared**2
    tangential_over_e = 0.25 * jnp.pi / squared**1.5
    return normal_over_e, tangential_over_e


def land_force(eccentricity, clearance, width, radius, cage_speed, ring_speed, viscosity, film_threshold,
               contact_stiffness, friction):
    """(force on the cage [N] (2-vector, radial plane), torque about the bearing axis [N·m],
    relative eccentricity ε [-], metal-contact force N_m [N]) of one guiding land, cage at rest
    in the radial plane (the quasi-static model).

    `eccentricity` is the cage centre's offset (2-vector [m]) from the ring's centre at the land,
    `clearance` the radial clearance C [m], `width` L [m], `radius` R [m], speeds ω_c, ω_o
    [rad/s], `viscosity` η [Pa·s], `film_threshold` h_t [m], `contact_stiffness` k_m [N/m] and
    `friction` μ [-] of metal contact.
    """
    offset = safe_norm(eccentricity)
    ratio = offset / clearance
    limit = 1.0 - film_threshold / clearance
    film_ratio = jnp.minimum(ratio, limit)
    normal_over_e, tangential_over_e = ocvirk_force_factors(film_ratio)
    entrainment = radius * (cage_speed + ring_speed)
    scale = viscosity * jnp.abs(entrainment) * width**3 / clearance**2
    # film: f_n/ε and f_t/ε evaluated at min(ε, ε_t); beyond ε_t the film force is held at its value there
    held = jnp.where(ratio > limit, limit / jnp.where(ratio > limit, ratio, 1.0), 1.0)
    unit_e = eccentricity / clearance  # = ε ê
    perpendicular = jnp.stack([-unit_e[1], unit_e[0]])  # = ε ê⊥, +90° from ê
    film = scale * held * (-normal_over_e * unit_e + jnp.sign(entrainment) * tangential_over_e * perpendicular)
    metal_force, torque, metal = _metal_contact_and_shear(eccentricity, clearance, width, radius, cage_speed,
                                                          ring_speed, viscosity, film_threshold, contact_stiffness,
                                                          friction)
    return film + metal_force, torque, ratio, metal


def whirling_land_force(position, velocity, clearance, width, radius, cage_speed, ring_speed, viscosity,
                        film_threshold, contact_stiffness, friction):
    """`land_force` for a cage centre at `position` [m] moving at `velocity` [m/s]: the film
    force by `squeeze_film_force` (its squeeze part damps the whirl), held beyond ε_t at the
    position scaled back to ε_t (the velocity is kept, so the squeeze film still damps an impact on
    the land); metal contact and shear torque as in `land_force`."""
    offset = safe_norm(position)
    ratio = offset / clearance
    limit = 1.0 - film_threshold / clearance
    held = jnp.where(ratio > limit, limit / jnp.where(ratio > limit, ratio, 1.0), 1.0)
    film = squeeze_film_force(held * position, velocity, clearance, width, radius, cage_speed + ring_speed,
                              viscosity)
    metal_force, torque, metal = _metal_contact_and_shear(position, clearance, width, radius, cage_speed,
                                                          ring_speed, viscosity, film_threshold, contact_stiffness,
                                                          friction)
    return film + metal_force, torque, ratio, metal


def _metal_contact_and_shear(eccentricity, clearance, width, radius, cage_speed, ring_speed, viscosity,
                             film_threshold, contact_stiffness, friction):
    """(metal-contact force on the cage [N] (2-vector), land torque [N·m], N_m [N]): contact
    N_m = k_m (e − e_t) against the offset with Coulomb friction against the sliding, and the
    Couette shear torque of the film at min(ε, ε_t) (module docstring)."""
    offset = safe_norm(eccentricity)
    ratio = offset / clearance
    limit = 1.0 - film_threshold / clearance
    film_ratio = jnp.minimum(ratio, limit)
    metal = contact_stiffness * clearance * positive_power(ratio - limit, 1.0)  # N_m [N]
    unit_e = eccentricity / clearance  # = ε ê
    perpendicular = jnp.stack([-unit_e[1], unit_e[0]])  # = ε ê⊥, +90° from ê
    sliding = jnp.sign(cage_speed - ring_speed)
    metal_over_e = metal / jnp.where(offset > 0, ratio, 1.0)
    force = -metal_over_e * unit_e - sliding * friction * metal_over_e * perpendicular
    shear = 2.0 * jnp.pi * viscosity * radius**3 * width * (cage_speed - ring_speed) / (
        clearance * jnp.sqrt(1.0 - film_ratio**2))
    torque = -shear - sliding * friction * metal * radius
    return force, torque, metal


def squeeze_film_force(position, velocity, clearance, width, radius, surface_speed_sum, viscosity):
    """Short-bearing (Ocvirk, half-Sommerfeld) film force [N] (2-vector) on a journal at
    `position` (x, y) [m] moving at `velocity` (ẋ, ẏ) [m/s] in a bearing of radial clearance C
    [m], width L [m] and radius R [m], with ω_s = ω_journal + ω_bearing (`surface_speed_sum`)
    [rad/s]: the land force of a whirling cage, squeeze damping included.

    Film h(θ) = C − x cos θ − y sin θ. Short-bearing Reynolds equation
    ∂_z(h³ ∂_z p) = 12η S(θ), S = (ω_s/2) ∂_θ h + ∂_t h (Hamrock, Schmid & Jacobson, *Fundamentals
    of Fluid Film Lubrication*, 2nd ed., ch. 10 and §12.2), so ∫p dz = −η L³ S/h³; the film
    carries pressure where S < 0 (half-Sommerfeld), a half circle θ = π − β + φ, φ ∈ [0, π], with
    S = A sin(θ + β). The force −R ∫ ∫p dz (cos θ, sin θ) dθ is integrated over that arc.
    At rest it is `ocvirk_force_factors` (tests/test_cage_dynamics.py); the squeeze term ∂_t h
    gives the land's damping, and a whirl at ω_s/2 carries no load (the classical half-frequency
    whirl).
    """
    x, y = position
    x_rate, y_rate = velocity
    # S(θ) = a sin θ + b cos θ = A sin(θ + β)
    a = 0.5 * surface_speed_sum * x - y_rate
    b = -0.5 * surface_speed_sum * y - x_rate
    amplitude = safe_norm(jnp.stack([a, b]))
    has_load = amplitude > 0
    phase = jnp.where(has_load, jnp.arctan2(jnp.where(has_load, b, 0.0), jnp.where(has_load, a, 1.0)), 0.0)
    start = jnp.pi - phase
    # split the arc at the thinnest film (θ = direction of the offset), or at its nearer end
    offset = safe_norm(position)
    centred = offset > 0
    thinnest = jnp.where(centred, jnp.arctan2(jnp.where(centred, y, 0.0), jnp.where(centred, x, 1.0)), start)
    split = jnp.clip(jnp.mod(thinnest - start + 0.5 * jnp.pi, 2.0 * jnp.pi) - 0.5 * jnp.pi, 0.0, jnp.pi)

    def piece(low, high):
        arc = low + 0.5 * (high - low) * (_ARC_NODES + 1.0)
        theta = start + arc
        film = clearance - x * jnp.cos(theta) - y * jnp.sin(theta)
        line_load = jnp.sin(arc) / film**3  # −S/A on the arc, over h³
        weights = 0.5 * (high - low) * _ARC_WEIGHTS * line_load
        return jnp.stack([jnp.sum(weights * jnp.cos(theta)), jnp.sum(weights * jnp.sin(theta))])

    return -radius * viscosity * width**3 * amplitude * (piece(0.0, split) + piece(split, jnp.pi))
