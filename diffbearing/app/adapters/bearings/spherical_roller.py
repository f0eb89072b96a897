"""Spherical roller bearings (`bearings.roller.spherical_roller`) on a shaft: a `[[bearings]]` entry
of type "spherical_roller" holds its barrel rollers (roller_diameter at mid-length, roller_length,
rollers per row, roller_profile_radius of the barrel), the pitch diameter, the nominal contact angle,
the inner raceways' profile radius (inner_profile_radius) and the diametral clearance. The shaft's
effects read it through its interface: ISO 281 (i = 2, b_m 1.15; e, Y₁, Y₂ of double-row roller
bearings) and ISO/TS 16281 life, ISO 76, overrolling frequencies, the permissible misalignment of
spherical roller bearings (1.5°), SKF's friction (`effects.friction = "skf"`, series 222E unless
`friction.series` names 213E); Palmgren's friction table holds no row for it and the static model
no centrifugal force (both refused)."""

import numpy as np

from ....bearings.roller.spherical_roller import (
    sphere_radius,
    spherical_roller,
    spherical_roller_raceways,
    spherical_roller_support,
)
from ...registry import Adapter, Mounting, quantity, register
from ..materials import material
from .ball import require
from .roller_bearing import roller_model

SPHERICAL_ROLLER_TYPE = "spherical_roller"
REQUIRED = ("bearing.roller_diameter", "bearing.roller_length", "bearing.rollers", "bearing.roller_profile_radius",
            "bearing.pitch_diameter", "bearing.contact_angle", "bearing.inner_profile_radius")


def _parameters(reads):
    """(rollers, raceways) of a [[bearings]] entry; ValueError naming the key of a bad value."""
    assert reads["bearing.type"] == SPHERICAL_ROLLER_TYPE
    require(reads, REQUIRED)
    roller = spherical_roller(roller_diameter=reads["bearing.roller_diameter"], roller_length=reads["bearing.roller_length"],
                              rollers=reads["bearing.rollers"], profile_radius=reads["bearing.roller_profile_radius"],
                              material=material(reads))
    raceways = spherical_roller_raceways(roller, pitch_diameter=reads["bearing.pitch_diameter"],
                                         contact_angle=reads["bearing.contact_angle"],
                                         inner_profile_radius=reads["bearing.inner_profile_radius"],
                                         diametral_clearance=reads.get("bearing.radial_clearance", 0.0))
    return roller, raceways


def _support(parameters, position, offset, orientation, settings):
    roller, raceways = parameters
    return spherical_roller_support(roller, raceways, position, offset, roller_model(settings), orientation)


def _describe(parameters) -> str:
    roller, raceways = parameters
    rollers = roller.rollers
    return (f"spherical roller, 2 × {rollers.roller_count} barrel rollers of {float(rollers.large_diameter) * 1e3:.4g} × "
            f"{float(rollers.length) * 1e3:.4g} mm (profile R_r = {float(roller.profile_radius) * 1e3:.4g} mm), "
            f"dm = {float(raceways.pitch_diameter) * 1e3:.4g} mm, α = {np.degrees(float(raceways.contact_angle)):.3g}°, "
            f"outer sphere R_o = {float(sphere_radius(roller, raceways)) * 1e3:.4g} mm, inner R_i = "
            f"{float(raceways.inner_profile_radius) * 1e3:.4g} mm, Pd = {float(raceways.diametral_clearance) * 1e6:.4g} µm")


ADAPTER = register(Adapter(
    name="spherical_roller",
    bearing_types=(SPHERICAL_ROLLER_TYPE,),
    keys={
        "bearing.roller_profile_radius": quantity("length", "spherical roller bearing: the barrel roller's profile "
                                                            "radius in its axial plane (below the outer sphere's)"),
        "bearing.inner_profile_radius": quantity("length", "spherical roller bearing: the inner raceways' profile "
                                                           "radius (above the roller's)"),
    },
    mounting=Mounting(parameters=_parameters, support=_support, describe=_describe),
))
