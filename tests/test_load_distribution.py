"""Sjövall integrals, load zone, Stribeck: published values and derivatives."""

import jax
import numpy as np

from diffbearing.ratings import load_distribution as ld

from .helpers import assert_jvp_matches_central_difference


def test_sjovall_integrals_against_harris_table():
    # Harris & Kotzalas vol. 1, table 7.1 (point contact): ε = 0.5 → J_r = 0.2288, J_r/J_a = 0.8225;
    # ε = 0.7 → J_r/J_a = 0.7427 (printed to 4 digits).
    radial, axial = ld.sjovall_integrals(0.5)
    np.testing.assert_allclose(radial, 0.2288, atol=5e-5)
    np.testing.assert_allclose(radial / axial, 0.8225, atol=5e-5)
    radial, axial = ld.sjovall_integrals(0.7)
    np.testing.assert_allclose(radial / axial, 0.7427, atol=5e-5)


def test_cage_paper_load_zone():
    """The cage paper quotes "a load zone of about 229°" for F_r tan α / F_a = 0.75 (docs/papers.md,
    §The cage paper). The point-contact Sjövall integrals give ε = 0.682 and 222.8° (they reproduce
    Harris's table: 0.7427 at ε = 0.7); 229° would need J_r/J_a = 0.740. Asserted: 229° within 7°
    (3 %), the gap stated."""
    epsilon = ld.load_zone_parameter(0.75)
    radial, axial = ld.sjovall_integrals(epsilon)
    np.testing.assert_allclose(radial / axial, 0.75, rtol=1e-12)
    zone = np.degrees(2 * ld.load_zone_half_angle(epsilon))
    np.testing.assert_allclose(zone, 222.8, atol=0.1)
    assert abs(zone - 229.0) < 7.0


def test_full_circle_limit_and_stribeck():
    # ε = 1: every ball loaded, J_r/J_a = 0.6 (the bracket is cos²(ψ/2)^{3/2} = |cos³(ψ/2)|: ratio 3/5).
    radial, axial = ld.sjovall_integrals(1.0)
    np.testing.assert_allclose(radial / axial, 0.6, rtol=1e-9)
    assert float(ld.stribeck_max_ball_load(101e3, 7)) == 5 * 101e3 / 7  # the 6411E chamfer paper: 72.14 kN
    np.testing.assert_allclose(ld.stribeck_max_ball_load(101e3, 7), 72.14e3, rtol=1e-4)


def test_derivatives():
    for epsilon in (0.3, 0.5, 0.8):
        assert_jvp_matches_central_difference(lambda e: jax.numpy.stack(ld.sjovall_integrals(e)), epsilon, 1.0,
                                              step=1e-6, rtol=1e-6)
    assert_jvp_matches_central_difference(ld.load_zone_parameter, 0.75, 1.0, step=1e-6, rtol=1e-5)
