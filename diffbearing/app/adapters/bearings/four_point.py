"""Four-point-contact ball bearings and slewing rings (split inner ring, gothic-arch grooves,
`bearings.ball.four_point`) on a shaft: a `[[bearings]]` entry of type "four_point_contact_ball"
holds the arches' geometry (the keys of an angular-contact `[bearing]` table, `contact_angle` the
arches' angle α₀: each half's contact angle with the rings concentric and no clearance) and its
diametral `radial_clearance` (required; negative: preloaded). Its model is static (no speed
effects on the balls). The shaft's effects read it through its interface: ISO/TS 16281 life over
its four raceway halves, ISO 76 as a double-row bearing (i = 2, P₀ = F_r + Y₀ F_a of Table 2's
double-row column), SKF's friction model (its "four_point" series), its overrolling frequencies."""

import numpy as np

from ....bearings.ball.four_point import FourPointSupport, axial_clearance
from ...registry import Adapter, Mounting, register
from ..materials import material
from .ball import ball_model, catalogue_bearing, require

FOUR_POINT_TYPE = "four_point_contact_ball"
ARCH_TYPE = "angular_contact_ball"  # the arches' geometry
REQUIRED = ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls", "bearing.contact_angle",
            "bearing.radial_clearance")


def _parameters(reads):
    """(the arches' BallBearing, radial clearance [m]) of a [[bearings]] entry; ValueError naming the
    key of a bad value."""
    assert reads["bearing.type"] == FOUR_POINT_TYPE
    require(reads, REQUIRED)
    arches = catalogue_bearing(reads, material(reads), kind=ARCH_TYPE, clearance=False)
    clearance = reads["bearing.radial_clearance"]
    FourPointSupport(arches, 0.0, clearance)  # its checks (the clearance within ± the arches' centre distance)
    return arches, clearance


def _support(parameters, position, offset, orientation, settings) -> FourPointSupport:
    arches, clearance = parameters
    return FourPointSupport(arches, position, clearance, offset, model=ball_model(settings), orientation=orientation)


def _describe(parameters) -> str:
    arches, clearance = parameters
    play = float(axial_clearance(FourPointSupport(arches, 0.0, clearance)))
    return (f"four-point contact, {arches.ball_count} balls, Dw = {float(arches.ball_diameter) * 1e3:.4f} mm, "
            f"dm = {float(arches.pitch_diameter) * 1e3:.1f} mm, "
            f"arches at α0 = {np.degrees(float(arches.free_contact_angle)):.2f}°, "
            f"radial clearance {float(clearance) * 1e6:.1f} µm (axial play {play * 1e6:.1f} µm)")


ADAPTER = register(Adapter(
    name="four_point",
    bearing_types=(FOUR_POINT_TYPE,),
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
