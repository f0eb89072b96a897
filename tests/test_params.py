"""Parameter validation: each rule raises ValueError naming the parameter and its range."""

import math

import numpy as np
import pytest

from diffbearing.params import (
    BEARING_STEEL,
    Lubricant,
    Material,
    Operating,
    ball_bearing,
    iso_vg_oil,
    radial_clearance,
    wooster_pressure_viscosity,
)

GOOD = dict(ball_diameter=26.9875e-3, pitch_diameter=97.5e-3, balls=7, kind="deep_groove_ball",
            inner_groove_radius=13.9e-3, outer_groove_radius=14.17e-3, radial_clearance=0.028e-3)


def build(**changes):
    arguments = dict(GOOD)
    arguments.update(changes)
    return ball_bearing(**arguments)


@pytest.mark.parametrize("changes, message", [
    (dict(ball_diameter=-0.01), "bearing.ball_diameter must be > 0"),
    (dict(ball_diameter=0.0), "bearing.ball_diameter must be > 0"),
    (dict(pitch_diameter=0.0), "bearing.pitch_diameter must be > 0"),
    (dict(ball_diameter=math.nan), "bearing.ball_diameter must be a finite number"),
    (dict(pitch_diameter=math.inf), "bearing.pitch_diameter must be a finite number"),
    (dict(balls=2), "bearing.balls must be an integer ≥ 3"),
    (dict(balls=7.0), "bearing.balls must be an integer ≥ 3"),
    (dict(pitch_diameter=60e-3), "so that the balls fit on the pitch circle"),
    (dict(inner_groove_radius=None, inner_groove_ratio=0.5), "bearing.inner_groove_ratio must be > 0.5"),
    (dict(outer_groove_radius=None, outer_groove_ratio=0.49), "bearing.outer_groove_ratio must be > 0.5"),
    (dict(inner_groove_radius=13.0e-3), "bearing.inner_groove_radius must be > 0.0134938 m and ≤ 0.0269875 m"),
    (dict(radial_clearance=-1.1e-3), "bearing.radial_clearance must be ≥ -0.000975 m"),
    (dict(radial_clearance=None), "give exactly one of contact_angle and radial_clearance"),
    (dict(radial_clearance=None, contact_angle=math.radians(95)), "bearing.contact_angle must be ≥ 0 rad and < 1.5708"),
    (dict(bore=0.08), "bearing.bore must be > 0 m and < 0.0705125 m (pitch_diameter − ball_diameter)"),
    (dict(outer_diameter=0.12), "bearing.outer_diameter must be > 0.124488 m (pitch_diameter + ball_diameter)"),
    (dict(kind="thrust_ball"), "bearing.type must be one of"),
])
def test_bad_bearing_raises_naming_parameter(changes, message):
    with pytest.raises(ValueError, match=None) as error:
        build(**changes)
    assert message in str(error.value)


def test_clearance_and_free_contact_angle_round_trip():
    # The 6411E chamfer paper: cos α0 = 1 − Gr/(2(fi + fe − 1)Dw) gives α0 = 9.23° for Gr = 28 µm
    # (docs/theory.md, §Groove geometry and clearance).
    bearing = build()
    np.testing.assert_allclose(np.degrees(bearing.free_contact_angle), 9.23, atol=0.01)
    np.testing.assert_allclose(radial_clearance(bearing), 0.028e-3, rtol=1e-12)
    zero = build(radial_clearance=0.0)
    assert float(zero.free_contact_angle) == 0.0


@pytest.mark.parametrize("factory, message", [
    (lambda: Material(-1.0, 0.3, 7800.0), "material.elastic_modulus must be > 0"),
    (lambda: Material(2e11, 0.5, 7800.0), "material.poisson_ratio must be > -1 and < 0.5"),
    (lambda: Material(2e11, 0.3, math.nan), "material.density must be a finite number"),
    (lambda: Lubricant(0.0, 2e-8, 870.0), "lubricant.viscosity must be > 0"),
    (lambda: Lubricant(0.01, -1e-8, 870.0), "lubricant.pressure_viscosity must be ≥ 0"),
    (lambda: Operating(0.0, 0.0, [0.0, math.nan, 0.0], [0.0, 0.0]), "operating.force must be a finite number"),
    (lambda: Operating(0.0, 0.0, [0.0, 0.0], [0.0, 0.0]), "operating.force must have 3 components"),
    (lambda: iso_vg_oil(33), "ISO VG grade must be one of"),
])
def test_bad_materials_lubricants_operating(factory, message):
    with pytest.raises(ValueError) as error:
        factory()
    assert message in str(error.value)


def test_oil_presets():
    # ISO 3448: VG 68 means 68 mm²/s at 40 °C; η = ν ρ with ρ = 870 kg/m³.
    oil = iso_vg_oil(68)
    np.testing.assert_allclose(oil.viscosity, 68e-6 * 870, rtol=1e-12)
    # Wooster: α = (0.6 + 0.965 log10 η[cP]) × 1e-8 1/Pa; mineral oils lie in 1–3e-8 1/Pa.
    np.testing.assert_allclose(oil.pressure_viscosity, (0.6 + 0.965 * np.log10(59.16)) * 1e-8, rtol=1e-12)
    assert 1e-8 < wooster_pressure_viscosity(iso_vg_oil(32).viscosity) < wooster_pressure_viscosity(oil.viscosity) < 3e-8


def test_steel_is_default_material():
    assert build().ball_material is BEARING_STEEL
