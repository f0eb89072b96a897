"""Where the quasi-static ball model stops describing a bearing: the limits a solved state is checked against.

A solver can converge to a state that no bearing reaches: under a load many times the static
rating the inner ring is pushed by millimetres and the balls come out on the far side of the
raceways. Such a state is reported as not converged, with its reason, rather than passed on.

* **Approach.** Hertz theory assumes the contact is small against the radii of the bodies
  (Johnson, *Contact Mechanics*, 1985, §4.1: a ≪ R); the load–approach law Q = K δ^{3/2} and the
  rigid-ring geometry assume deflections small against the ball. The limit is an elastic approach
  of `MAX_APPROACH_FRACTION` D_w at either contact. For the ball bearings of the tests and
  benchmarks (the aero-engine bearing of the stiffness paper, a 6411, a 218 and a 7-ball 11.5 mm
  deep-groove bearing) that is a peak pressure of 5.7–7.0 GPa, well past the 4.2 GPa of ISO 76
  where steel starts to yield, with a contact semi-major axis of 0.35–0.50 D_w
  (`hertz.point_contact` at α₀).
* **Contact angle.** A loaded contact's angle outside (−90°, 90°) puts the contact on the far side of
  the groove's curvature centre: the ball has been pushed through the raceway, or lifted over the
  inner groove's edge by its centrifugal force. An open contact's angle is not a contact's.

* **Low shoulder.** An angular-contact bearing's outer ring (or inner ring) is ground away on one side
  of the groove: a loaded contact at a negative angle would sit on the shoulder that is not there.
  `lowest_loaded_angle` is checked against 0 for that bearing type by the application layer; a
  deep-groove bearing's full groove takes either sign.

Peak pressures above the ISO 76 limit (4.2 GPa for ball bearings) remain inside the model: they are
a warning of the application layer, not an error.
"""

import jax.numpy as jnp

MAX_APPROACH_FRACTION = 0.01  # × D_w: largest elastic approach at a contact the model accepts
MAX_CONTACT_ANGLE = 0.5 * jnp.pi  # rad: |α| at which the contact leaves the groove's near side


def largest_approach_ratio(inner_approach, outer_approach, ball_diameter):
    """max over balls and both contacts of δ / D_w [-] (δ from `ball_equilibrium.ball_state`)."""
    return jnp.maximum(jnp.max(inner_approach), jnp.max(outer_approach)) / ball_diameter


def largest_contact_angle(inner_angle, outer_angle, inner_load, outer_load):
    """max over the loaded contacts (Q > 0) of |α| [rad] (0 where none is loaded): an open contact's
    angle is only the direction of its line of groove centres, which may point anywhere once the
    ring has moved by more than the clearance (the far balls of a radially loaded bearing)."""
    inner = jnp.where(inner_load > 0.0, jnp.abs(inner_angle), 0.0)
    outer = jnp.where(outer_load > 0.0, jnp.abs(outer_angle), 0.0)
    return jnp.maximum(jnp.max(inner), jnp.max(outer))


def within_model(approach_ratio, contact_angle):
    """True where both measures are inside the model's limits (module docstring)."""
    return (approach_ratio <= MAX_APPROACH_FRACTION) & (contact_angle < MAX_CONTACT_ANGLE)


def low_shoulder_angle(bearing, inner_load, inner_angle, outer_load, outer_angle):
    """The lowest loaded contact angle [rad] of an angular-contact bearing (`lowest_loaded_angle`;
    its low shoulder lies at α < 0), +π/2 for a deep-groove bearing, whose groove is full."""
    if bearing.kind != "angular_contact_ball":
        return jnp.asarray(0.5 * jnp.pi)
    return lowest_loaded_angle(inner_load, inner_angle, outer_load, outer_angle)


def lowest_loaded_angle(inner_load, inner_angle, outer_load, outer_angle):
    """min over the loaded contacts (Q > 0) of the contact angle α [rad]; +π/2 where none is loaded."""
    inner = jnp.where(inner_load > 0.0, inner_angle, 0.5 * jnp.pi)
    outer = jnp.where(outer_load > 0.0, outer_angle, 0.5 * jnp.pi)
    return jnp.minimum(jnp.min(inner), jnp.min(outer))
