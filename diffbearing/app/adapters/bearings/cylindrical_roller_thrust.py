"""Cylindrical roller thrust bearings, single direction (`bearings.roller.cylindrical_roller_thrust`)
on a shaft: a `[[bearings]]` entry of type "cylindrical_roller_thrust" holds its rollers
(roller_diameter, roller_length, rollers, a crowning `profile` sub-table as a cylindrical roller's)
and the pitch diameter. The shaft's effects read it through its interface: ISO 281 (C_a, P_a) and
ISO/TS 16281 life, ISO 76 (C₀a, P₀a), its overrolling frequencies, the permissible misalignment of
flat washers (2′); its sliding loss is the Python function `cylindrical_roller_thrust.sliding_power`
(the friction models' tables hold no row for it: refused)."""

from ....bearings.roller.cylindrical_roller_thrust import (
    check_pitch_diameter,
    cylindrical_roller_thrust_bearing,
    cylindrical_roller_thrust_support,
)
from ...registry import Adapter, Mounting, register
from ..materials import material
from .ball import require
from .roller import scene_roller_profile
from .roller_bearing import roller_model

CYLINDRICAL_ROLLER_THRUST_TYPE = "cylindrical_roller_thrust"
REQUIRED = ("bearing.roller_diameter", "bearing.roller_length", "bearing.rollers", "bearing.pitch_diameter")


def _parameters(reads):
    """(rollers, pitch diameter) of a [[bearings]] entry; ValueError naming the key of a bad value."""
    assert reads["bearing.type"] == CYLINDRICAL_ROLLER_THRUST_TYPE
    require(reads, REQUIRED)
    bearing = cylindrical_roller_thrust_bearing(roller_diameter=reads["bearing.roller_diameter"],
                                                roller_length=reads["bearing.roller_length"],
                                                rollers=reads["bearing.rollers"], profile=scene_roller_profile(reads),
                                                material=material(reads))
    pitch = reads["bearing.pitch_diameter"]
    check_pitch_diameter(bearing, pitch)
    _check_washers(bearing, pitch, reads.get("bearing.bore"), reads.get("bearing.outer_diameter"))
    return bearing, pitch


def _check_washers(bearing, pitch, bore, outside) -> None:
    """ValueError naming bearing.bore (bearing.outer_diameter) unless the rollers' inner (outer) ends
    lie outside the bore (inside the outside diameter): d < d_m − L_we < d_m + L_we < D."""
    length = float(bearing.length)
    if bore is not None and bore >= pitch - length:
        raise ValueError(f"bearing.bore: the rollers' inner ends lie at d_m − L_we = {(pitch - length) * 1e3:.4g} mm; the "
                         f"shaft washer's bore must be smaller, got {bore * 1e3:.4g} mm")
    if outside is not None and outside <= pitch + length:
        raise ValueError(f"bearing.outer_diameter: the rollers' outer ends lie at d_m + L_we = {(pitch + length) * 1e3:.4g} "
                         f"mm; the housing washer's outside diameter must be larger, got {outside * 1e3:.4g} mm")


def _support(parameters, position, offset, orientation, settings):
    bearing, pitch = parameters
    return cylindrical_roller_thrust_support(bearing, pitch, position, offset, roller_model(settings), orientation)


def _describe(parameters) -> str:
    bearing, pitch = parameters
    return (f"cylindrical roller thrust, single direction, {bearing.roller_count} rollers of "
            f"{float(bearing.large_diameter) * 1e3:.4g} × {float(bearing.length) * 1e3:.4g} mm, "
            f"dm = {float(pitch) * 1e3:.4g} mm, flat washers (the housing washer radially free)")


ADAPTER = register(Adapter(
    name="cylindrical_roller_thrust",
    bearing_types=(CYLINDRICAL_ROLLER_THRUST_TYPE,),
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
