"""The cage's guiding lands on the outer ring as short journal bearings, bounded by metal contact.

Each land (seed 000, physics.md §6; Liu et al. 2020, eqs. 25–28) is a short journal bearing of
width L, radial clearance C and radius R (the cage's outer radius), entrained at
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

from .numerics import positive_power, safe_norm


def ocvirk_force_factors(eccentricity_ratio):
    """(f_n/ε, f_t/ε) of the short bearing per unit η U L³/C² [-] (finite at ε = 0)."""
    squared = 1.0 - eccentricity_ratio**2
    normal_over_e = eccentricity_ratio / squared**2
    tangential_over_e = 0.25 * jnp.pi / squared**1.5
    return normal_over_e, tangential_over_e


def land_force(eccentricity, clearance, width, radius, cage_speed, ring_speed, viscosity, film_threshold,
               contact_stiffness, friction):
    """(force on the cage [N] (2-vector, radial plane), torque about the bearing axis [N·m],
    relative eccentricity ε [-], metal-contact force N_m [N]) of one guiding land.

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
    metal = contact_stiffness * clearance * positive_power(ratio - limit, 1.0)  # N_m [N]
    # film: f_n/ε and f_t/ε evaluated at min(ε, ε_t); beyond ε_t the film force is held at its value there
    held = jnp.where(ratio > limit, limit / jnp.where(ratio > limit, ratio, 1.0), 1.0)
    unit_e = eccentricity / clearance  # = ε ê
    perpendicular = jnp.stack([-unit_e[1], unit_e[0]])  # = ε ê⊥, +90° from ê
    sliding = jnp.sign(cage_speed - ring_speed)
    metal_over_e = metal / jnp.where(offset > 0, ratio, 1.0)
    force = (-(scale * normal_over_e * held + metal_over_e) * unit_e
             + (jnp.sign(entrainment) * scale * tangential_over_e * held - sliding * friction * metal_over_e)
             * perpendicular)
    shear = 2.0 * jnp.pi * viscosity * radius**3 * width * (cage_speed - ring_speed) / (
        clearance * jnp.sqrt(1.0 - film_ratio**2))
    torque = -shear - sliding * friction * metal * radius
    return force, torque, ratio, metal
