"""Groove–shoulder transition chamfer: the contact-ellipse limit point M and the chamfer height H.

The 6411E chamfer paper (docs/papers.md, §The 6411E chamfer paper; docs/theory.md, §Groove
chamfer): under the worst case — the largest ball load Q_max (the ellipse's semi-major axis a)
at the contact angle α′ the axial load produces — the loaded ellipse reaches
along the groove to the limit point M, at the angle θ_M = α′ + a/r from the groove bottom (a laid
along the groove arc of radius r = f D_w, as the paper does). In the ring's own cross-section, M
lies r(1 − cos θ_M) above the groove bottom; a chamfer that starts at the shoulder must stop above
M, so its height is H = h_shoulder − r(1 − cos θ_M), with h_shoulder the groove depth (shoulder
radius minus groove-bottom radius). SI units; angles in rad.

The same ellipse against a shoulder without chamfer (MESYS reports it as the ellipse's extension
against the shoulder): the shoulder edge lies at θ_s = arccos(1 − h_shoulder/r) from the groove
bottom; a contact at α with a/r reaching past θ_s is truncated, and the share of its load the
Hertz pressure puts beyond the edge is the semi-ellipsoid's: the pressure p₀√(1 − ξ² − η²)
(ξ = x/a along the groove, η = y/b) carries (π/2)p₀b(1 − ξ²) per unit of x, so the share past
ξ₀ = (θ_s − α)r/a is (3/4)∫_{ξ₀}^{1}(1 − ξ²)dξ = (2 − 3ξ₀ + ξ₀³)/4.
"""

import jax.numpy as jnp

from ...params import BallBearing, radial_clearance


def limit_point_angle(contact_angle, semi_major_axis, groove_radius):
    """θ_M = α′ + a/r [rad]: angle of M from the groove bottom, seen from the groove curvature centre."""
    return contact_angle + semi_major_axis / groove_radius


def limit_point_height(contact_angle, semi_major_axis, groove_radius):
    """Height of M above the groove bottom [m]: r (1 − cos θ_M)."""
    return groove_radius * (1.0 - jnp.cos(limit_point_angle(contact_angle, semi_major_axis, groove_radius)))


def chamfer_height(shoulder_depth, contact_angle, semi_major_axis, groove_radius):
    """Largest chamfer height H [m] that keeps the loaded contact ellipse on the groove:
    H = h_shoulder − r (1 − cos(α′ + a/r)); negative means the ellipse already runs over the shoulder."""
    return shoulder_depth - limit_point_height(contact_angle, semi_major_axis, groove_radius)


def shoulder_angle(shoulder_depth, groove_radius):
    """θ_s = arccos(1 − h_shoulder/r) [rad]: angle of the shoulder edge from the groove bottom, seen
    from the groove curvature centre; π/2 and more for a shoulder at or above the centre's height."""
    return jnp.arccos(jnp.clip(1.0 - shoulder_depth / groove_radius, -1.0, 1.0))


def truncated_load_share(contact_angle, semi_major_axis, groove_radius, shoulder_depth):
    """Share [0, 1] of a contact's load the Hertz pressure puts beyond the shoulder edge: 0 where the
    ellipse (a laid along the groove arc) ends below the edge, 1 where the contact centre lies a
    whole semi-axis past it; (2 − 3ξ₀ + ξ₀³)/4 with ξ₀ = (θ_s − α) r / a (module docstring).
    An unloaded contact (a = 0) carries nothing: 0."""
    loaded = semi_major_axis > 0.0
    edge = (shoulder_angle(shoulder_depth, groove_radius) - contact_angle) * groove_radius \
        / jnp.where(loaded, semi_major_axis, 1.0)
    edge = jnp.clip(edge, -1.0, 1.0)
    return jnp.where(loaded, (2.0 - 3.0 * edge + edge**3) / 4.0, 0.0)


def groove_bottom_diameters(bearing: BallBearing):
    """(d_i, d_o) [m]: the inner and outer groove-bottom diameters, d_m ∓ (D_w + G_r/2) (d_m their
    mean, G_r the diametral clearance)."""
    half_span = bearing.ball_diameter + 0.5 * radial_clearance(bearing)
    return bearing.pitch_diameter - half_span, bearing.pitch_diameter + half_span


def shoulder_depths(bearing: BallBearing, inner_shoulder_diameter, outer_shoulder_diameter):
    """(h_i, h_o) [m]: each ring's (high) shoulder above its groove bottom (`groove_bottom_diameters`),
    from the shoulder diameters d₁ (inner ring) and D₂ (outer ring)."""
    inner_bottom, outer_bottom = groove_bottom_diameters(bearing)
    return 0.5 * (inner_shoulder_diameter - inner_bottom), 0.5 * (outer_bottom - outer_shoulder_diameter)
