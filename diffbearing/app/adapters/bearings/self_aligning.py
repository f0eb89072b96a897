"""Self-aligning ball bearings (two rows in the inner ring's grooves, one spherical outer raceway,
`bearings.ball.self_aligning`) on a shaft: a `[[bearings]]` entry of type "self_aligning_ball"
holds one row's balls (ball_diameter, balls a row), the pitch diameter, the inner grooves'
ratio or radius, the nominal contact angle and the diametral radial clearance (required); the
outer raceway's sphere follows from them. Its model is static (no speed effects on the balls) and
carries no moment. The shaft's effects read it through its interface: ISO/TS 16281 life over its
four raceways, ISO 76 for self-aligning ball bearings (i = 2, X₀ = 1, Y₀ = 0.44 cot α₀, 4 600 MPa),
its overrolling frequencies; the friction models' tables hold no row for it (refused)."""

import numpy as np

from ....bearings.ball.self_aligning import self_aligning_row, self_aligning_support
from ...registry import Adapter, Mounting, register
from ..materials import material
from .ball import ball_model, require

SELF_ALIGNING_TYPE = "self_aligning_ball"
REQUIRED = ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls", "bearing.contact_angle",
            "bearing.radial_clearance")


def _parameters(reads):
    """(one row's BallBearing, radial clearance [m]) of a [[bearings]] entry; ValueError naming the
    key of a bad value."""
    assert reads["bearing.type"] == SELF_ALIGNING_TYPE
    require(reads, REQUIRED)
    ring = material(reads)
    row = self_aligning_row(
        ball_diameter=reads["bearing.ball_diameter"], pitch_diameter=reads["bearing.pitch_diameter"],
        balls=reads["bearing.balls"], inner_groove_ratio=reads.get("bearing.inner_groove_ratio"),
        inner_groove_radius=reads.get("bearing.inner_groove_radius"), contact_angle=reads["bearing.contact_angle"],
        ball_material=material(reads, "ball_", ring), ring_material=ring,
        bore=reads.get("bearing.bore"), outer_diameter=reads.get("bearing.outer_diameter"),
        dynamic_load_rating=reads.get("bearing.dynamic_load_rating"))
    clearance = reads["bearing.radial_clearance"]
    self_aligning_support(row, clearance, 0.0)  # its checks
    return row, clearance


def _support(parameters, position, offset, orientation, settings):
    row, clearance = parameters
    return self_aligning_support(row, clearance, position, offset, ball_model(settings), orientation)


def _describe(parameters) -> str:
    row, clearance = parameters
    return (f"self-aligning ball, 2 × {row.ball_count} balls, Dw = {float(row.ball_diameter) * 1e3:.4f} mm, "
            f"dm = {float(row.pitch_diameter) * 1e3:.2f} mm, α0 = {np.degrees(float(row.free_contact_angle)):.2f}°, "
            f"sphere radius {float(row.outer_groove_ratio * row.ball_diameter) * 1e3:.3f} mm, radial clearance "
            f"{float(clearance) * 1e6:.1f} µm")


ADAPTER = register(Adapter(
    name="self_aligning",
    bearing_types=(SELF_ALIGNING_TYPE,),
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
