"""The 6411E chamfer paper's chamfer: its numbers are consistent with the model's contact angle and
ellipse."""

import jax
import numpy as np

from diffbearing.bearings.ball import groove_chamfer

INNER_GROOVE_RADIUS = 13.9e-3


def test_chamfer_paper_chamfer_height():
    """The 6411E chamfer paper prints α′ = 18.10°, a = 9.234 mm and H = 0.34 mm but not the shoulder geometry.
    Those three imply a groove depth of 6.50 mm (0.241 D_w). With that depth, this model's own
    α′ = 18.06° (10 kN axial, tests/test_ball_equilibrium.py) and exact a = 9.262 mm at
    Q_max = 72.14 kN (tests/test_hertz.py) must give H within 0.03 mm of 0.34 mm: the printed H
    has two digits, and H moves by r sin θ_M (Δα′ + Δa/r) ≈ 0.015 mm between the two."""
    depth = 0.34e-3 + groove_chamfer.limit_point_height(np.radians(18.10), 9.234e-3, INNER_GROOVE_RADIUS)
    np.testing.assert_allclose(depth, 6.50e-3, atol=0.005e-3)
    height = groove_chamfer.chamfer_height(depth, np.radians(18.06), 9.262e-3, INNER_GROOVE_RADIUS)
    assert abs(float(height) - 0.34e-3) < 0.03e-3


def test_limit_point_geometry():
    # M lies on the groove circle, a/r beyond the contact point: its chord from the contact point is
    # 2 r sin(a / 2r), and with no ellipse (a = 0) M is the contact point itself.
    r, alpha, a = INNER_GROOVE_RADIUS, np.radians(20.0), 5e-3
    theta = groove_chamfer.limit_point_angle(alpha, a, r)
    contact = np.array([r * np.sin(alpha), r * (1 - np.cos(alpha))])
    limit = np.array([r * np.sin(theta), groove_chamfer.limit_point_height(alpha, a, r)])
    np.testing.assert_allclose(np.linalg.norm(limit - contact), 2 * r * np.sin(a / (2 * r)), rtol=1e-12)
    np.testing.assert_allclose(groove_chamfer.limit_point_height(alpha, 0.0, r), contact[1], rtol=1e-12)


def test_shoulder_edge_is_where_the_groove_reaches_the_shoulder_height():
    """θ_s puts the groove point r(1 − cos θ_s) at the shoulder depth (exact identity); a shoulder at
    or above the groove centre's height gives π/2 or more."""
    r = INNER_GROOVE_RADIUS
    for depth in (1e-3, 6.5e-3, 13.9e-3):
        theta = groove_chamfer.shoulder_angle(depth, r)
        np.testing.assert_allclose(groove_chamfer.limit_point_height(theta, 0.0, r), depth, rtol=1e-12)
    assert float(groove_chamfer.shoulder_angle(r, r)) == np.pi / 2


def test_truncated_share_is_the_hertz_load_beyond_the_edge():
    """The share against a direct quadrature of the semi-ellipsoidal pressure p₀√(1 − ξ² − η²) over the
    part of the ellipse past the edge (midpoint rule, 1e-4); 0 below the edge, ½ with the edge
    through the centre, 1 a whole semi-axis past it, 0 for an unloaded contact, with a finite
    derivative there."""
    r, a, depth = INNER_GROOVE_RADIUS, 3e-3, 6.5e-3
    edge = float(groove_chamfer.shoulder_angle(depth, r))
    xi = (np.arange(4000) + 0.5) / 2000 - 1.0
    eta = xi[:, None]
    pressure = np.sqrt(np.clip(1.0 - xi**2 - eta**2, 0.0, None))
    for offset in (-0.7, -0.2, 0.3, 0.9):  # ξ₀: the edge's position along the major axis
        alpha = edge - offset * a / r
        expected = pressure[:, xi > offset].sum() / pressure.sum()
        share = groove_chamfer.truncated_load_share(alpha, a, r, depth)
        np.testing.assert_allclose(share, expected, atol=1e-4)
    share = [float(groove_chamfer.truncated_load_share(edge - k * a / r, a, r, depth)) for k in (1.5, 0.0, -1.0, -2.0)]
    np.testing.assert_allclose(share, [0.0, 0.5, 1.0, 1.0], atol=1e-15)
    assert float(groove_chamfer.truncated_load_share(edge, 0.0, r, depth)) == 0.0
    slope = jax.grad(lambda semi_axis: groove_chamfer.truncated_load_share(edge + 0.1, semi_axis, r, depth))(0.0)
    assert np.isfinite(float(slope))


def test_truncated_share_derivatives_match_central_differences():
    """d(share)/d(contact angle, semi-major axis, shoulder depth) at a truncated contact (ξ₀ ≈ 0.3),
    forward and reverse, against central differences."""
    from .helpers import assert_jvp_matches_central_difference

    r, depth = INNER_GROOVE_RADIUS, 6.5e-3
    alpha = float(groove_chamfer.shoulder_angle(depth, r)) - 0.3 * 3e-3 / r

    def share(x):  # (α [rad], a [mm], h [mm]) → share
        return groove_chamfer.truncated_load_share(x[0], x[1] * 1e-3, r, x[2] * 1e-3)

    for direction in np.eye(3):
        assert_jvp_matches_central_difference(share, jax.numpy.array([alpha, 3.0, 6.5]), jax.numpy.asarray(direction),
                                              step=1e-6, rtol=1e-7)
