"""Groove–shoulder transition chamfer: the contact-ellipse limit point M and the chamfer height H.

The 6411E chamfer paper (docs/papers.md, §The 6411E chamfer paper; docs/theory.md, §Groove
chamfer): under the worst case — the largest ball load Q_max (the ellipse's semi-major axis a)
at the contact angle α′ the axial load produces — the loaded ellipse reaches
along the groove to the limit point M, at the angle θ_M = α′ + a/r from the groove bottom (a laid
along the groove arc of radius r = f D_w, as the paper does). In the ring's own cross-section, M
lies r(1 − cos θ_M) above the groove bottom; a chamfer that starts at the shoulder must stop above
M, so its height is H = h_shoulder − r(1 − cos θ_M), with h_shoulder the groove depth (shoulder
radius minus groove-bottom radius). SI units; angles in rad.
"""

import jax.numpy as jnp


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
