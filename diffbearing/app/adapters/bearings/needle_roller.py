"""Needle roller bearings (`bearings.roller.needle_roller`) on a shaft: a `[[bearings]]` entry of type
"needle_roller" holds its rollers (roller_diameter, roller_length > 2.5 roller_diameter, rollers, a
crowning `profile` sub-table as a cylindrical roller's), the pitch diameter, the diametral
clearance, its `outer_ring` ("machined", default, or "drawn_cup": ISO 281's b_m) and whether it has
an `inner_ring` (default true; false: the rollers run on the shaft, whose raceway diameter F_w =
d_m − D_w the entry's bore must then equal). The shaft's effects read it through its interface:
ISO 281 and ISO/TS 16281 life, ISO 76, overrolling frequencies, the permissible misalignment of
needle roller bearings (2′); the friction models' tables hold no row for it (refused)."""

import math

import equinox as eqx

from ....bearings.roller.needle_roller import (
    OUTER_RINGS,
    needle_roller_bearing,
    needle_roller_raceways,
    needle_roller_support,
)
from ....bearings.roller.roller_equilibrium import RollerRaceways
from ....bearings.roller.roller_geometry import RollerBearing
from ...registry import Adapter, Key, Mounting, register
from ..materials import material
from .ball import require
from .roller import scene_roller_profile
from .roller_bearing import roller_model

NEEDLE_ROLLER_TYPE = "needle_roller"
REQUIRED = ("bearing.roller_diameter", "bearing.roller_length", "bearing.rollers", "bearing.pitch_diameter")
BORE_TOLERANCE = 1e-3  # relative: a bore "equal" to the shaft raceway F_w of a bearing without inner ring


class NeedleRollerEntry(eqx.Module):
    """A [[bearings]] entry's needle roller bearing: its rollers and raceways, and (static) its outer
    ring ("machined" or "drawn_cup") and whether it has an inner ring."""

    bearing: RollerBearing
    raceways: RollerRaceways
    outer_ring: str = eqx.field(static=True)
    inner_ring: bool = eqx.field(static=True)


def _parameters(reads) -> NeedleRollerEntry:
    """The `NeedleRollerEntry` of a [[bearings]] entry; ValueError naming the key of a bad value."""
    assert reads["bearing.type"] == NEEDLE_ROLLER_TYPE
    require(reads, REQUIRED)
    bearing = needle_roller_bearing(roller_diameter=reads["bearing.roller_diameter"],
                                    roller_length=reads["bearing.roller_length"], rollers=reads["bearing.rollers"],
                                    profile=scene_roller_profile(reads), material=material(reads))
    pitch = reads["bearing.pitch_diameter"]
    raceways = needle_roller_raceways(bearing, pitch_diameter=pitch,
                                      diametral_clearance=reads.get("bearing.radial_clearance", 0.0))
    inner_ring = reads.get("bearing.inner_ring", True)
    _check_bore(reads.get("bearing.bore"), pitch - float(bearing.large_diameter), inner_ring)
    return NeedleRollerEntry(bearing, raceways, reads.get("bearing.outer_ring", "machined"), inner_ring)


def _check_bore(bore, raceway, inner_ring: bool) -> None:
    """ValueError naming bearing.bore unless it equals the shaft raceway F_w = d_m − D_w of a bearing
    without inner ring, or lies below it (the inner ring's thickness) with one."""
    if bore is None:
        return
    if not inner_ring and not math.isclose(bore, raceway, rel_tol=BORE_TOLERANCE):
        raise ValueError(f"bearing.bore: without an inner ring the rollers run on the shaft, whose raceway diameter is "
                         f"F_w = d_m − D_w = {raceway * 1e3:.4g} mm; got {bore * 1e3:.4g} mm (give that or leave bore out)")
    if inner_ring and bore >= raceway * (1.0 - BORE_TOLERANCE):
        raise ValueError(f"bearing.bore: the inner ring's bore lies below its raceway F_w = d_m − D_w = "
                         f"{raceway * 1e3:.4g} mm, got {bore * 1e3:.4g} mm (set inner_ring = false for rollers on the shaft)")


def _support(entry: NeedleRollerEntry, position, offset, orientation, settings):
    return needle_roller_support(entry.bearing, entry.raceways, position, offset, roller_model(settings), orientation,
                                 outer_ring=entry.outer_ring)


def _describe(entry: NeedleRollerEntry) -> str:
    bearing, raceways, outer_ring, inner_ring = entry.bearing, entry.raceways, entry.outer_ring, entry.inner_ring
    raceway = float(raceways.pitch_diameter - bearing.large_diameter) * 1e3
    rings = ("drawn cup" if outer_ring == "drawn_cup" else "machined outer ring") + (
        ", inner ring" if inner_ring else f", no inner ring: on the shaft, F_w = {raceway:.4g} mm (its raceway hardened "
                                          "58–64 HRC, as the ratings assume)")
    return (f"needle roller, {bearing.roller_count} rollers of {float(bearing.large_diameter) * 1e3:.4g} × "
            f"{float(bearing.length) * 1e3:.4g} mm, dm = {float(raceways.pitch_diameter) * 1e3:.4g} mm, {rings}")


ADAPTER = register(Adapter(
    name="needle_roller",
    bearing_types=(NEEDLE_ROLLER_TYPE,),
    keys={
        "bearing.outer_ring": Key("choice", choices=OUTER_RINGS,
                                  doc='needle roller bearing: "machined" (b_m 1.1) or "drawn_cup" (b_m 1.0), ISO 281'),
        "bearing.inner_ring": Key("boolean", doc="needle roller bearing: false where its rollers run on the shaft"),
    },
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
