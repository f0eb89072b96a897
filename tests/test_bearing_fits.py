"""ISO 286 seat classes with the ring's ISO 492 Normal tolerances: the derived hole deviations
against ISO 286-2's tabulated classes, the interferences of a k5 shaft and an M7 housing, and
the errors a user meets."""

import numpy as np
import pytest

from diffbearing.systems.bearing_fits import housing_deviations, housing_interference, shaft_deviations, shaft_interference


@pytest.mark.parametrize("tolerance, diameter, expected", [
    # ISO 286-2 tables (µm): holes derived from the shafts' deviations by ISO 286-1's rules
    ("K6", 100e-3, (-18, 4)), ("K7", 60e-3, (-21, 9)), ("M6", 60e-3, (-24, -5)), ("M7", 60e-3, (-30, 0)),
    ("N6", 60e-3, (-33, -14)), ("N7", 60e-3, (-39, -9)), ("P6", 60e-3, (-45, -26)), ("P7", 60e-3, (-51, -21)),
    ("H7", 140e-3, (0, 40)), ("G6", 60e-3, (10, 29)), ("JS7", 60e-3, (-15, 15)),
    # the J classes, tabulated (NSK, NTN CAT.2203 and Koyo print the same)
    ("J6", 15e-3, (-5, 6)), ("J6", 100e-3, (-6, 16)), ("J6", 450e-3, (-7, 33)), ("J7", 60e-3, (-12, 18)),
    ("J7", 200e-3, (-16, 30)), ("J7", 350e-3, (-18, 39)),
])
def test_housing_classes_match_iso_286_2(tolerance, diameter, expected):
    np.testing.assert_allclose(np.array(housing_deviations(tolerance, diameter)) * 1e6, expected, atol=1e-9)


@pytest.mark.parametrize("tolerance, diameter, expected", [
    ("k5", 55e-3, (2, 15)), ("k6", 55e-3, (2, 21)), ("m5", 55e-3, (11, 24)), ("m6", 100e-3, (13, 35)),
    ("n6", 40e-3, (17, 33)), ("p6", 200e-3, (50, 79)), ("js6", 25e-3, (-6.5, 6.5)), ("h6", 55e-3, (-19, 0)),
    ("g6", 30e-3, (-20, -7)),
    # the j classes, tabulated (NSK, NTN CAT.2203; j5, j6 also Koyo)
    ("j5", 15e-3, (-3, 5)), ("j5", 300e-3, (-16, 7)), ("j6", 55e-3, (-7, 12)), ("j6", 280e-3, (-16, 16)),
    ("j7", 350e-3, (-28, 29)), ("j7", 450e-3, (-32, 31)), ("j7", 100e-3, (-15, 20)),
])
def test_shaft_classes_match_iso_286_2(tolerance, diameter, expected):
    np.testing.assert_allclose(np.array(shaft_deviations(tolerance, diameter)) * 1e6, expected, atol=1e-9)


def test_interferences_of_a_6411_on_k5_in_m7():
    """The 6411 (d = 55 mm, bore 0/−15 µm; D = 140 mm, outside 0/−18 µm, ISO 492 Normal): on a k5 shaft
    (+2/+15 µm) 2 to 30 µm, probable 16 µm; in an M7 housing (−40/0 µm) −18 to +40 µm, probable 11 µm."""
    got = [shaft_interference("k5", 55e-3, value) * 1e6 for value in ("min", "max", "probable")]
    np.testing.assert_allclose(got, [2.0, 30.0, 16.0], atol=1e-9)
    got = [housing_interference("M7", 140e-3, value) * 1e6 for value in ("min", "max", "probable")]
    np.testing.assert_allclose(got, [-18.0, 40.0, 11.0], atol=1e-9)


@pytest.mark.parametrize("call, named", [
    (lambda: shaft_deviations("q6", 55e-3), "mounting.shaft_tolerance"),
    (lambda: shaft_deviations("k8", 55e-3), "mounting.shaft_tolerance"),
    (lambda: housing_deviations("K5", 55e-3), "mounting.housing_tolerance"),
    (lambda: shaft_deviations("k5", 600e-3), "10 to 500 mm"),
    (lambda: shaft_interference("k5", 55e-3, "typical"), "mounting.fit_value"),
])
def test_bad_classes_are_refused(call, named):
    with pytest.raises(ValueError, match=named):
        call()
