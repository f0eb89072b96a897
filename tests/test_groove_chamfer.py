"""The 6411E chamfer paper's chamfer: its numbers are consistent with the model's contact angle and
ellipse."""

import numpy as np

from diffbearing import groove_chamfer

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
