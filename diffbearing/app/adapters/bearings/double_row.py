"""Double-row angular-contact ball bearings (O arrangement, `bearings.ball.double_row`) on a shaft:
a `[[bearings]]` entry of type "double_row_angular_contact_ball" holds one row's geometry (the keys
of an angular-contact `[bearing]` table: its free contact angle, groove radii, balls a row), the
rows' spacing and the bearing's axial clearance; its dynamic load rating, where given, is the whole
bearing's. The shaft's effects read it through its interface: ISO/TS 16281 life over its four
raceways, ISO 76 with i = 2 and Table 2's double-row X₀, Y₀, SKF's friction model (its "double_row"
series), its overrolling frequencies."""

import numpy as np

from ....bearings.ball.double_row import DoubleRowSupport
from ....params import check_range
from ...registry import Adapter, Mounting, quantity, register
from ..materials import material
from .ball import ball_model, catalogue_bearing, require

DOUBLE_ROW_TYPE = "double_row_angular_contact_ball"
ROW_TYPE = "angular_contact_ball"  # each row's model
REQUIRED = ("bearing.ball_diameter", "bearing.pitch_diameter", "bearing.balls", "bearing.contact_angle",
            "bearing.row_spacing")


def _parameters(reads):
    """(one row's BallBearing, row spacing [m], axial clearance [m]) of a [[bearings]] entry;
    ValueError naming the key of a bad value."""
    assert reads["bearing.type"] == DOUBLE_ROW_TYPE
    require(reads, REQUIRED)
    row = catalogue_bearing(reads, material(reads), kind=ROW_TYPE, clearance=False)
    spacing, clearance = reads["bearing.row_spacing"], reads.get("bearing.axial_clearance", 0.0)
    # the rows' planes of inner groove centres, where each row's model sits: in O arrangement each
    # lies (f_i − ½) D_w sin α₀ inside its balls' plane
    inset = float((row.inner_groove_ratio - 0.5) * row.ball_diameter * np.sin(row.free_contact_angle))
    check_range("bearing.row_spacing", spacing, low=2.0 * inset, unit=" m",
                why="2 (f_i − ½)·D_w·sin α0, the rows' inner groove centres apart")
    DoubleRowSupport(row, spacing - 2.0 * inset, 0.0, clearance)  # its checks (a finite clearance)
    return row, spacing - 2.0 * inset, clearance


def _support(parameters, position, offset, orientation, settings) -> DoubleRowSupport:
    row, spacing, clearance = parameters
    return DoubleRowSupport(row, spacing, position, clearance, offset, model=ball_model(settings),
                            orientation=orientation)


def _describe(parameters) -> str:
    row, spacing, clearance = parameters
    balls = float(spacing + 2.0 * (row.inner_groove_ratio - 0.5) * row.ball_diameter * np.sin(row.free_contact_angle))
    return (f"double-row angular contact (O), 2 × {row.ball_count} balls, Dw = {float(row.ball_diameter) * 1e3:.4f} mm, "
            f"α0 = {np.degrees(float(row.free_contact_angle)):.2f}°, rows {balls * 1e3:.2f} mm apart, axial "
            f"clearance {float(clearance) * 1e6:.1f} µm")


ADAPTER = register(Adapter(
    name="double_row",
    bearing_types=(DOUBLE_ROW_TYPE,),
    keys={
        "bearing.row_spacing": quantity("length", "double-row bearings: the axial distance between the rows' ball "
                                                  "centres (the model's rows sit at their planes of inner groove "
                                                  "centres, 2 (f_i − ½) D_w sin α0 closer)"),
        "bearing.axial_clearance": quantity("length", "double-row angular-contact bearings: the inner ring's axial play "
                                                      "between the rows' contacts at α0 (negative: preloaded; default 0)"),
    },
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
