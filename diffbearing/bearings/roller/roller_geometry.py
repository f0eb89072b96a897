"""Roller and raceway geometry of one roller–raceway contact: diameters along the roller, the
equivalent radius in the rolling direction, tilt, and the undeformed gap on the contact grid.

Frame of the contact (used by every roller block and output):

* x is the rolling direction, y runs along the roller axis from the middle of the effective
  length l (−l/2 ≤ y ≤ l/2); for a tapered roller y = −l/2 is the small end.
* The roller diameter grows linearly from d (small end) to D (large end):
  D_k = (1 − L_k/l) d + (L_k/l) D with L_k = y + l/2 (the crowning paper, eq. 6); the rolling
  radius is R_k = 0.5 D_k / cos θ, θ the cone half angle (the crowning paper, eq. 5; θ = 0 for
  cylindrical rollers).
* The raceway curvature in the rolling direction is signed: convex (inner ring) positive,
  concave (outer ring) negative, 0 for a flat. For a tapered roller it scales with the roller
  diameter (roller and cone share an apex), so the raceway radius is given at mid-length.
* Tilt ϑ [rad] (misalignment of the roller axis against the raceway) adds ϑ·y to the gap:
  a positive tilt loads the −y end.
* The approach δ is measured from the position where the undeformed surfaces touch at x = 0,
  y = 0 (the middle of the roller).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ...contact.hertz import effective_modulus
from ...params import BEARING_STEEL, Material, _as_float, _is_concrete, check_range
from .roller_profile import RollerProfile, crown_drop

ROLLER_KINDS = ("cylindrical_roller", "tapered_roller")


class RollerBearing(eqx.Module):
    """A roller with its crowning profile and material (roller and raceway of the same material)."""

    small_diameter: jax.Array = eqx.field(converter=_as_float)  # d [m]
    large_diameter: jax.Array = eqx.field(converter=_as_float)  # D [m] (= d for a cylindrical roller)
    length: jax.Array = eqx.field(converter=_as_float)  # effective length l [m]
    cone_half_angle: jax.Array = eqx.field(converter=_as_float)  # θ [rad]
    profile: RollerProfile
    material: Material
    kind: str = eqx.field(static=True, default="cylindrical_roller")
    roller_count: int | None = eqx.field(static=True, default=None)  # Z, rollers in the bearing (None: one contact)


class RollerLoading(eqx.Module):
    """The load case of one roller–raceway contact."""

    load: jax.Array = eqx.field(converter=_as_float)  # roller load Q [N]
    tilt: jax.Array = eqx.field(converter=_as_float)  # ϑ [rad]
    raceway_curvature: jax.Array = eqx.field(converter=_as_float)  # 1/R_race at mid-length [1/m], convex > 0
    entrainment_speed: jax.Array = eqx.field(converter=_as_float, default=0.0)  # mean rolling speed u [m/s]

    def __check_init__(self):
        check_range("contact.load", self.load, low=0.0, unit=" N", why="a roller carries a compressive load")
        check_range("contact.tilt", self.tilt, low=-0.05, high=0.05, unit=" rad",
                    why="small-angle misalignment, |ϑ| < 0.05 rad ≈ 2.9°")


def roller_bearing(*, kind="cylindrical_roller", length, diameter=None, small_diameter=None, large_diameter=None,
                   cone_half_angle=0.0, profile=None, material: Material = BEARING_STEEL,
                   roller_count: int | None = None) -> RollerBearing:
    """A validated `RollerBearing` (SI). Cylindrical: give `diameter`; tapered: `small_diameter`,
    `large_diameter` and `cone_half_angle`. ValueError names a bad parameter."""
    if kind not in ROLLER_KINDS:
        raise ValueError(f"bearing.type: expected one of {', '.join(ROLLER_KINDS)}, got {kind!r}")
    if kind == "cylindrical_roller":
        check_range("bearing.roller_diameter", diameter, low=0.0, unit=" m")
        small_diameter = large_diameter = diameter
    else:
        check_range("bearing.roller_small_diameter", small_diameter, low=0.0, unit=" m")
        check_range("bearing.roller_large_diameter", large_diameter, low=0.0, unit=" m")
        if _is_concrete(small_diameter, large_diameter) and float(large_diameter) < float(small_diameter):
            raise ValueError(f"bearing.roller_large_diameter must be ≥ roller_small_diameter "
                             f"({float(small_diameter):g} m), got {float(large_diameter):g} m")
        check_range("bearing.cone_half_angle", cone_half_angle, low=0.0, low_open=False, high=np.pi / 6,
                    unit=" rad", why="up to 30°")
    check_range("bearing.roller_length", length, low=0.0, unit=" m")
    if roller_count is not None and (isinstance(roller_count, bool) or not isinstance(roller_count, int)
                                     or roller_count < 1):
        raise ValueError(f"bearing.rollers must be an integer ≥ 1, got {roller_count!r}")
    return RollerBearing(small_diameter, large_diameter, length, cone_half_angle,
                         profile if profile is not None else RollerProfile(), material, kind=kind,
                         roller_count=roller_count)


def check_rollers_fit(roller_count: int, diameter, pitch_diameter) -> None:
    """ValueError naming bearing.rollers unless Z rollers of diameter D [m] fit side by side on the
    pitch circle d_m [m]: D ≤ d_m sin(π/Z) (no check of traced values)."""
    if not _is_concrete(diameter, pitch_diameter):
        return
    room = float(pitch_diameter) * np.sin(np.pi / roller_count)
    if float(diameter) > room:
        raise ValueError(f"bearing.rollers: {roller_count} rollers of {float(diameter) * 1e3:.4g} mm do not fit on the "
                         f"{float(pitch_diameter) * 1e3:.4g} mm pitch circle: that needs D ≤ d_m sin(π/Z) = "
                         f"{room * 1e3:.4g} mm")


def film_length(bearing: RollerBearing):
    """Length [m] that carries the load in a line-contact film formula: the flat part of a
    circular profile, else the effective length."""
    if bearing.profile.kind == "circular":
        return bearing.profile.flat_length
    return bearing.length


def roller_modulus(bearing: RollerBearing):
    """E' [Pa] of roller and raceway (same material): E/(1 − ν²)."""
    m = bearing.material
    return effective_modulus(m.elastic_modulus, m.poisson_ratio, m.elastic_modulus, m.poisson_ratio)


def mean_roller_diameter(bearing: RollerBearing):
    """D_we [m]: the mean of the end diameters (the ratings' roller diameter)."""
    return 0.5 * (bearing.small_diameter + bearing.large_diameter)


def roller_diameter(bearing: RollerBearing, y):
    """Roller diameter D_k [m] at axial positions y [m] (the crowning paper, eq. 6)."""
    fraction = y / bearing.length + 0.5
    return (1.0 - fraction) * bearing.small_diameter + fraction * bearing.large_diameter


def equivalent_radius(bearing: RollerBearing, loading: RollerLoading, y):
    """Equivalent radius R [m] in the rolling direction at y: 1/R = cos θ/(0.5 D_k) + 1/R_race."""
    diameter = roller_diameter(bearing, y)
    mid = 0.5 * (bearing.small_diameter + bearing.large_diameter)
    curvature = jnp.cos(bearing.cone_half_angle) / (0.5 * diameter) + loading.raceway_curvature * mid / diameter
    return 1.0 / curvature


def profile_drop(bearing: RollerBearing, loading: RollerLoading, y):
    """Crown drop z(y) [m] of the roller's profile (roller_profile.crown_drop)."""
    return crown_drop(bearing.profile, y, bearing.length, roller_modulus(bearing),
                      equivalent_radius(bearing, loading, jnp.asarray(0.0)))


def axial_gap(bearing: RollerBearing, loading: RollerLoading, y):
    """Gap along the line x = 0 [m]: crown drop plus tilt, z(y) + ϑ·y."""
    return profile_drop(bearing, loading, y) + loading.tilt * y


def initial_gap(bearing: RollerBearing, loading: RollerLoading, x, y):
    """Undeformed separation h₀(x, y) = x²/(2R(y)) + z(y) + ϑy [m] on the grid of x [nx] and y [ny]."""
    radius = equivalent_radius(bearing, loading, y)
    return x[:, None] ** 2 / (2.0 * radius[None, :]) + axial_gap(bearing, loading, y)[None, :]


def cell_centres(half_extent, count: int):
    """Centres of `count` equal cells over [−half_extent, half_extent] [m] and the cell size [m]."""
    size = 2.0 * half_extent / count
    return (jnp.arange(count) + 0.5) * size - half_extent, size


def raceway_radius_of_pitch(pitch_diameter, roller_diameter_value, raceway: str):
    """Raceway radius (d_m ∓ D)/2 [m] of a cylindrical roller bearing's inner (−) or outer (+) ring."""
    sign = {"inner": 1.0, "outer": -1.0}[raceway]
    return 0.5 * (pitch_diameter - sign * roller_diameter_value)


def raceway_curvature(radius, raceway: str):
    """Signed raceway curvature [1/m] in the rolling direction: convex inner ring +1/R, concave
    outer ring −1/R; a radius of +inf is a flat raceway (0)."""
    sign = {"inner": 1.0, "outer": -1.0}[raceway]
    return sign / radius


def pure_rolling_entrainment_speed(pitch_diameter, roller_diameter_value, inner_speed, outer_speed):
    """Mean entrainment speed u = (d_m/4)(1 − γ²)|ω_i − ω_o| [m/s] of a cylindrical roller in pure
    rolling, γ = D/d_m (Harris & Kotzalas vol. 1, ch. 8)."""
    ratio = roller_diameter_value / pitch_diameter
    return 0.25 * pitch_diameter * (1.0 - ratio**2) * jnp.abs(inner_speed - outer_speed)
