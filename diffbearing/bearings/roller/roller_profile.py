"""Roller crowning profiles: the drop z(y) [m] of the roller surface below its straight generatrix,
as differentiable functions of their parameters.

y is measured along the roller axis from the middle of the effective length l (|y| ≤ l/2).
Logarithmic profiles follow the elastic deflection of a uniform line load of finite length
(2Q/(πlE') ln(...)); E' is the effective modulus of `hertz.effective_modulus` and Q a design load.

* straight: z = 0 (edge stress peaks, Johnson §5.5).
* circular: flat middle of length Lz, then an arc of radius Rc: z = Rc − √(Rc² − (|y| − Lz/2)²)
  beyond |y| = Lz/2; Lz = 0 gives a fully crowned roller (the crowning paper, eq. 11).
* lundberg: z = 2Q/(πlE') ln[1 / (1 − (2y/l)²)] (Lundberg 1939); infinite at the ends, so it is
  only evaluated at cell centres.
* johns_gohar: z = 2Q/(πlE') ln[1 / (1 − (1 − 0.3033 b/a)(y/a)²)], a = l/2, b the Hertz line
  half-width at Q (Johns & Gohar 1981, as restated by Fujiwara & Kawase 2007, NTN Tech. Rev. 75).
* fujiwara_kawase: z = A ln[1 / (1 − (1 − e^{−zm/A}) ((|y| − a(1 − K2))/(K2 a))²)] beyond
  |y| = a(1 − K2), 0 inside, with A = 2K1 Q/(πlE') (Fujiwara & Kawase 2007, eq. 3): K1 scales
  the load, K2 is the crowned fraction of each half, zm the drop at the end of the effective length.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ...contact.hertz import line_contact
from ...numerics import positive_power, safe_sqrt
from ...params import _as_float, _is_concrete, check_range

PROFILE_KINDS = ("straight", "circular", "lundberg", "johns_gohar", "fujiwara_kawase")

# Johns & Gohar (1981): end-of-contact factor on the Hertz half-width ratio b/a.
JOHNS_GOHAR_END_FACTOR = 0.3033


class RollerProfile(eqx.Module):
    """A crowning profile: `kind` is static; every parameter is a float leaf (0 where unused).

    flat_length Lz [m], crown_radius Rc [m] (circular); design_load Q [N] (logarithmic kinds);
    k1 [-], k2 [-], zm [m] (fujiwara_kawase).
    """

    flat_length: jax.Array = eqx.field(converter=_as_float, default=0.0)
    crown_radius: jax.Array = eqx.field(converter=_as_float, default=0.0)
    design_load: jax.Array = eqx.field(converter=_as_float, default=0.0)
    k1: jax.Array = eqx.field(converter=_as_float, default=0.0)
    k2: jax.Array = eqx.field(converter=_as_float, default=0.0)
    zm: jax.Array = eqx.field(converter=_as_float, default=0.0)
    kind: str = eqx.field(static=True, default="straight")


_NEEDS = {
    "straight": (),
    "circular": ("flat_length", "crown_radius"),
    "lundberg": ("design_load",),
    "johns_gohar": ("design_load",),
    "fujiwara_kawase": ("design_load", "k1", "k2", "zm"),
}


def roller_profile(kind: str = "straight", *, length=None, **parameters) -> RollerProfile:
    """A validated `RollerProfile`; `length` (the roller's effective length [m]) bounds Lz.

    ValueError names a missing or out-of-range parameter.
    """
    if kind not in PROFILE_KINDS:
        raise ValueError(f"profile.kind: expected one of {', '.join(PROFILE_KINDS)}, got {kind!r}")
    unknown = [name for name, value in parameters.items() if value is not None and name not in _NEEDS[kind]]
    if unknown:
        raise ValueError(f"profile.{unknown[0]}: not a parameter of profile kind {kind!r} "
                         f"(it takes {', '.join(_NEEDS[kind]) or 'none'})")
    for name in _NEEDS[kind]:
        if parameters.get(name) is None:
            raise ValueError(f"missing required key 'profile.{name}' (profile kind {kind!r})")
    given = {name: value for name, value in parameters.items() if value is not None}
    check_range("bearing.roller_length", length, low=0.0, unit=" m")
    if kind == "circular":
        concrete = length is not None and _is_concrete(length, given["flat_length"])
        check_range("profile.flat_length", given["flat_length"], low=0.0, low_open=False,
                    high=float(length) if concrete else None, unit=" m",
                    why="the flat part lies within the roller's effective length")
        if concrete:
            crowned = 0.5 * (float(length) - float(given["flat_length"]))
            check_range("profile.crown_radius", given["crown_radius"], low=crowned, high_open=False, unit=" m",
                        why="the arc must reach the roller end: Rc > (l − Lz)/2")
    if "design_load" in given:
        check_range("profile.design_load", given["design_load"], low=0.0, unit=" N")
    if kind == "fujiwara_kawase":
        check_range("profile.k1", given["k1"], low=0.0)
        check_range("profile.k2", given["k2"], low=0.0, high=1.0, high_open=False,
                    why="K2 is the crowned fraction of each half of the roller")
        check_range("profile.zm", given["zm"], low=0.0, unit=" m")
    return RollerProfile(kind=kind, **given)


def logarithmic_scale(load, length, effective_modulus):
    """2Q/(πlE') [m]: the drop scale of the logarithmic profiles (Lundberg 1939)."""
    return 2.0 * load / (jnp.pi * length * effective_modulus)


def crown_drop(profile: RollerProfile, y, length, effective_modulus, radius):
    """Profile drop z(y) [m] at axial positions y [m] from the middle of the effective length.

    Args:
        profile: the `RollerProfile`.
        y: positions with |y| < l/2 [m] (cell centres).
        length: effective length l [m].
        effective_modulus: E' [Pa] of roller and raceway.
        radius: equivalent radius R [m] in the rolling direction at mid-length (Johns–Gohar's b).
    """
    half = 0.5 * length
    if profile.kind == "straight":
        return jnp.zeros_like(y)
    if profile.kind == "circular":
        beyond = positive_power(jnp.abs(y) - 0.5 * profile.flat_length, 1.0)
        # Rc − √(Rc² − s²) written as s² / (Rc + √(Rc² − s²)): the same drop without the cancellation
        # of two near-equal radii (a 1 µm drop of a 1.5 m arc would keep 6 of its 16 digits)
        return beyond**2 / (profile.crown_radius + safe_sqrt(profile.crown_radius**2 - beyond**2))
    scale = logarithmic_scale(profile.design_load, length, effective_modulus)
    if profile.kind == "lundberg":
        return scale * jnp.log(1.0 / (1.0 - (y / half) ** 2))
    if profile.kind == "johns_gohar":
        half_width = line_contact(profile.design_load / length, radius, effective_modulus).half_width
        reach = 1.0 - JOHNS_GOHAR_END_FACTOR * half_width / half
        return scale * jnp.log(1.0 / (1.0 - reach * (y / half) ** 2))
    if profile.kind == "fujiwara_kawase":
        amplitude = profile.k1 * scale
        crowned = profile.k2 * half
        relative = positive_power(jnp.abs(y) - (half - crowned), 1.0) / crowned
        reach = -jnp.expm1(-profile.zm / amplitude)
        return amplitude * jnp.log(1.0 / (1.0 - reach * relative**2))
    raise AssertionError(profile.kind)


def profile_parameters(profile: RollerProfile) -> dict[str, float]:
    """{name: value} of the parameters the profile's kind uses (for reports)."""
    return {name: float(np.asarray(getattr(profile, name))) for name in _NEEDS[profile.kind]}


def with_raceway_edge(profile: RollerProfile, edge_radius) -> RollerProfile:
    """The axial gap profile of a circular-crowned roller on a raceway whose edges fall away with
    radius R_e [m] from where the roller's flat part ends: the two curvatures add, so the gap is a
    circular crown of radius 1/(1/R_c + 1/R_e) (the raceway edge radius of the starved
    finite line contact). ValueError unless the profile is circular and R_e > 0."""
    if profile.kind != "circular":
        raise ValueError(f"contact.raceway_edge_radius needs profile.kind = \"circular\" (the raceway edge falls away "
                         f"where the roller's flat part ends), got {profile.kind!r}")
    check_range("contact.raceway_edge_radius", edge_radius, low=0.0, unit=" m")
    return RollerProfile(flat_length=profile.flat_length, crown_radius=1.0 / (1.0 / profile.crown_radius + 1.0 / edge_radius),
                         kind="circular")
