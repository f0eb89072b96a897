"""Thrust ball bearings, single direction (`bearings.ball.thrust_ball`) on a shaft: a `[[bearings]]`
entry of type "thrust_ball" holds its balls (ball_diameter, balls), the pitch diameter, each
washer's groove (inner: the shaft washer's, outer: the housing washer's, as a ratio or a radius)
and, for an angular-contact thrust bearing, its contact angle (45°–75°; default 90°, grooved
washers, the housing washer radially free). The shaft's effects read it through its interface:
ISO 281 (C_a, P_a) and ISO/TS 16281 life, ISO 76 (C₀a, P₀a), its overrolling frequencies; speed
effects on the balls (centrifugal force, gyroscopic moment) as a ball bearing's; the friction
models' tables hold no row for it (refused)."""

import numpy as np

from ....bearings.ball.thrust_ball import AXIAL, is_axial, thrust_ball_bearing, thrust_ball_support
from ...registry import Adapter, Mounting, register
from ..materials import material
from .ball import ball_model, require

THRUST_BALL_TYPE = "thrust_ball"
REQUIRED = ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls")


def _parameters(reads):
    """The bearing's `BallBearing` (`thrust_ball_bearing`) from a [[bearings]] entry; ValueError
    naming the key of a bad value."""
    assert reads["bearing.type"] == THRUST_BALL_TYPE
    require(reads, REQUIRED)
    ring = material(reads)
    return thrust_ball_bearing(
        ball_diameter=reads["bearing.ball_diameter"], pitch_diameter=reads["bearing.pitch_diameter"],
        balls=reads["bearing.balls"], contact_angle=reads.get("bearing.contact_angle", AXIAL),
        inner_groove_ratio=reads.get("bearing.inner_groove_ratio"),
        outer_groove_ratio=reads.get("bearing.outer_groove_ratio"),
        inner_groove_radius=reads.get("bearing.inner_groove_radius"),
        outer_groove_radius=reads.get("bearing.outer_groove_radius"),
        ball_material=material(reads, "ball_", ring), ring_material=ring, bore=reads.get("bearing.bore"),
        outer_diameter=reads.get("bearing.outer_diameter"), dynamic_load_rating=reads.get("bearing.dynamic_load_rating"))


def _support(bearing, position, offset, orientation, settings):
    return thrust_ball_support(bearing, position, offset, ball_model(settings), orientation)


def _describe(bearing) -> str:
    kind = ("grooved washers at 90°, housing washer radially free" if is_axial(bearing)
            else f"angular contact at α0 = {np.degrees(float(bearing.free_contact_angle)):.2f}°")
    return (f"thrust ball, single direction, {bearing.ball_count} balls, Dw = {float(bearing.ball_diameter) * 1e3:.4f} mm, "
            f"dm = {float(bearing.pitch_diameter) * 1e3:.2f} mm, {kind}, f_i = {float(bearing.inner_groove_ratio):.4f}, "
            f"f_o = {float(bearing.outer_groove_ratio):.4f}")


ADAPTER = register(Adapter(
    name="thrust_ball",
    bearing_types=(THRUST_BALL_TYPE,),
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
