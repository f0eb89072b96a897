"""Parameter pytrees: materials, lubricants, ball bearings, operating points.

Every physical number is a float64 array leaf (so `jax.grad` reaches it); counts and choices are
static fields. Validation runs at construction on concrete values and raises `ValueError` naming
the parameter and its allowed range; inside `jit`/`vmap` (traced values) it is skipped.

Conventions (fixed for every block and output):

* SI units inside: m, N, Pa, rad, rad/s, kg/m³, Pa·s.
* z is the bearing axis; x and y are radial. The outer ring is fixed; loads
  [Fx, Fy, Fz, Mx, My] act on the inner ring; moments and rotations are right-handed about x, y.
* Ball azimuth ψ is measured from +x towards +y.
* Displacement [δx, δy, δz, θx, θy] of the inner ring is measured from the position where the
  rings are concentric and every ball just touches both raceways at its free contact angle.
"""

import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

BALL_BEARING_KINDS = ("deep_groove_ball", "angular_contact_ball")
OUTER_RACEWAYS = ("groove", "sphere")  # a ball bearing's outer raceway (`BallBearing.outer_raceway`)
GROOVE_FACINGS = ("radial", "axial")  # where a ball bearing's grooves face (`BallBearing.groove_facing`)
MAX_MISALIGNMENT = 0.05  # rad: the small-angle limit of an imposed ring tilt (sin θ ≈ θ within 0.04 %)


def _as_float(value):
    """Float64 array leaf; traced values pass through untouched."""
    if isinstance(value, jax.core.Tracer):
        return value
    return np.asarray(value, dtype=np.float64)


def _is_concrete(*values) -> bool:
    return not any(isinstance(value, jax.core.Tracer) for value in values)


def check_range(name: str, value, *, low=None, high=None, low_open=True, high_open=True, unit="", why=""):
    """Raise ValueError unless every element of `value` is finite and within (low, high).

    `low_open`/`high_open` choose strict or inclusive bounds; `unit` and `why` (the reason for a
    bound) are only for the message.
    Traced values are not checked (validation happens at construction on concrete inputs).
    """
    if value is None or not _is_concrete(value):
        return
    array = np.asarray(value, dtype=np.float64)
    lo = "" if low is None else f"{'>' if low_open else '≥'} {low:g}{unit}"
    hi = "" if high is None else f"{'<' if high_open else '≤'} {high:g}{unit}"
    allowed = " and ".join(part for part in (lo, hi) if part) or "finite"
    if why:
        allowed += f" ({why})"
    shown = np.array2string(array, precision=6) if array.ndim else f"{float(array):g}"
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be a finite number ({allowed}), got {shown}")
    too_low = low is not None and np.any(array <= low if low_open else array < low)
    too_high = high is not None and np.any(array >= high if high_open else array > high)
    if too_low or too_high:
        raise ValueError(f"{name} must be {allowed}, got {shown}{unit}")


class Material(eqx.Module):
    """Isotropic elastic solid."""

    elastic_modulus: np.ndarray = eqx.field(converter=_as_float)  # E [Pa]
    poisson_ratio: np.ndarray = eqx.field(converter=_as_float)  # ν [-]
    density: np.ndarray = eqx.field(converter=_as_float)  # ρ [kg/m³]
    name: str = eqx.field(static=True, default="custom")

    def __check_init__(self):
        check_range("material.elastic_modulus", self.elastic_modulus, low=0.0, unit=" Pa")
        check_range("material.poisson_ratio", self.poisson_ratio, low=-1.0, high=0.5)
        check_range("material.density", self.density, low=0.0, unit=" kg/m^3")


# AISI 52100 / GCr15 through-hardened bearing steel: E = 208 GPa, ν = 0.3 (handbook values lie at
# 205–210 GPa; 208 GPa reproduces the 6411E chamfer paper's a = 9.234 mm within 0.3 %), ρ = 7830 kg/m³.
BEARING_STEEL = Material(208e9, 0.3, 7830.0, name="bearing_steel")
# Hot-isostatically pressed silicon nitride for hybrid bearings (typical catalogue values).
SILICON_NITRIDE = Material(310e9, 0.26, 3200.0, name="silicon_nitride")
MATERIALS = {"bearing_steel": BEARING_STEEL, "52100": BEARING_STEEL, "gcr15": BEARING_STEEL,
             "silicon_nitride": SILICON_NITRIDE}


class Lubricant(eqx.Module):
    """Newtonian lubricant at its operating temperature."""

    viscosity: np.ndarray = eqx.field(converter=_as_float)  # dynamic viscosity η₀ [Pa·s]
    pressure_viscosity: np.ndarray = eqx.field(converter=_as_float)  # α [1/Pa]
    density: np.ndarray = eqx.field(converter=_as_float)  # ρ₀ [kg/m³]
    name: str = eqx.field(static=True, default="custom")
    viscosity_law: str = eqx.field(static=True, default="roelands")  # η(p) of numerical EHL: roelands | barus
    density_law: str = eqx.field(static=True, default="dowson_higginson")  # ρ(p): dowson_higginson | incompressible

    def __check_init__(self):
        check_range("lubricant.viscosity", self.viscosity, low=0.0, unit=" Pa*s")
        check_range("lubricant.pressure_viscosity", self.pressure_viscosity, low=0.0, low_open=False, unit=" 1/Pa")
        check_range("lubricant.density", self.density, low=0.0, unit=" kg/m^3")


WOOSTER_LOWEST_VISCOSITY = 1e-3 * 10.0 ** (-0.6 / 0.965)  # Pa·s: where Wooster's α reaches 0


def wooster_pressure_viscosity(viscosity):
    """Pressure–viscosity coefficient α [1/Pa] of a mineral oil from its viscosity η₀ [Pa·s].

    Wooster's correlation α = (0.6 + 0.965 log₁₀ η₀[cP]) × 1e-8 Pa⁻¹ (Stachowiak & Batchelor,
    *Engineering Tribology*, ch. 2). A rough estimate: replace it with supplier data. Positive only
    above η₀ = 10^(−0.6/0.965) cP ≈ 0.24 mPa·s; below, ValueError (give lubricant.pressure_viscosity).
    """
    check_range("lubricant.viscosity", viscosity, low=WOOSTER_LOWEST_VISCOSITY, unit=" Pa*s",
                why="Wooster's α is positive above it; else give lubricant.pressure_viscosity")
    return (0.6 + 0.965 * math.log10(viscosity * 1e3)) * 1e-8


ISO_VG_GRADES = (32, 46, 68, 100, 150, 220)
MINERAL_OIL_DENSITY = 870.0  # kg/m³ at 40 °C, typical paraffinic mineral oil
# Kinematic viscosity at 100 °C [mm²/s] of typical paraffinic mineral oils of each grade, viscosity
# index about 100 (suppliers' data sheets of hydraulic and gear oils); ISO 3448 fixes only ν₄₀.
ISO_VG_VISCOSITY_100 = {32: 5.4, 46: 6.7, 68: 8.6, 100: 11.1, 150: 14.7, 220: 19.0}


def iso_vg_oil(grade: int) -> Lubricant:
    """Mineral oil of ISO viscosity grade `grade` at 40 °C.

    η₀ = ν₄₀ ρ with ν₄₀ = grade mm²/s (ISO 3448 mid-point), ρ = 870 kg/m³; α from Wooster.
    """
    if grade not in ISO_VG_GRADES:
        raise ValueError(f"lubricant.preset ISO VG grade must be one of {ISO_VG_GRADES}, got {grade}")
    viscosity = grade * 1e-6 * MINERAL_OIL_DENSITY
    return Lubricant(viscosity, wooster_pressure_viscosity(viscosity), MINERAL_OIL_DENSITY, name=f"iso_vg_{grade}")


LUBRICANTS = {f"iso_vg_{grade}": iso_vg_oil(grade) for grade in ISO_VG_GRADES}


class BallBearing(eqx.Module):
    """Geometry and materials of a deep-groove or angular-contact ball bearing.

    Use `ball_bearing(...)` to build one from a groove radius or ratio and a contact angle or a
    radial clearance; the fields hold the canonical set.
    """

    ball_diameter: np.ndarray = eqx.field(converter=_as_float)  # D_w [m]
    pitch_diameter: np.ndarray = eqx.field(converter=_as_float)  # d_m [m]
    inner_groove_ratio: np.ndarray = eqx.field(converter=_as_float)  # f_i = r_i / D_w [-]
    outer_groove_ratio: np.ndarray = eqx.field(converter=_as_float)  # f_o = r_o / D_w [-]
    free_contact_angle: np.ndarray = eqx.field(converter=_as_float)  # α₀ [rad]
    ball_material: Material
    ring_material: Material
    ball_count: int = eqx.field(static=True)
    kind: str = eqx.field(static=True, default="angular_contact_ball")
    bore: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v), default=None)
    outer_diameter: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v), default=None)
    dynamic_load_rating: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v), default=None)
    # A negative clearance (preloaded bearing): the diametral interference ι = −G_r ≥ 0 [m]; the
    # free contact angle is then 0 and every ball is squeezed by ι/2 at Δ = 0.
    interference: np.ndarray = eqx.field(converter=_as_float, default=0.0)
    # "groove": the outer raceway a groove of radius f_o D_w (f_o ≤ 1); "sphere": a self-aligning
    # bearing's spherical raceway, of radius f_o D_w about the bearing's centre (f_o > 1)
    outer_raceway: str = eqx.field(static=True, default="groove")
    # "radial": each ring's groove lies on its ring's side of its curvature centre's radius (a
    # contact exists while |α| < 90°); "axial": a thrust bearing's washers, each groove on its
    # washer's side of its centre's axial plane (a contact exists while |α − 90°| < 90°), α₀ up to 90°
    groove_facing: str = eqx.field(static=True, default="radial")
    # the contact angle the ratings read once a mounting has moved the free one (`with_radial_clearance`:
    # the bearing as designed keeps its nominal angle); None: the free contact angle [rad]
    rated_contact_angle: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v),
                                                       default=None)

    def __check_init__(self):
        check_range("bearing.radial_clearance", -self.interference if _is_concrete(self.interference) else None,
                    high=0.0, high_open=False, unit=" m", why="the interference of a negative clearance")
        if self.kind not in BALL_BEARING_KINDS:
            raise ValueError(f"bearing.type must be one of {BALL_BEARING_KINDS}, got {self.kind!r}")
        if not isinstance(self.ball_count, int) or isinstance(self.ball_count, bool) or self.ball_count < 3:
            raise ValueError(f"bearing.balls must be an integer ≥ 3, got {self.ball_count!r}")
        check_range("bearing.ball_diameter", self.ball_diameter, low=0.0, unit=" m")
        check_range("bearing.pitch_diameter", self.pitch_diameter, low=0.0, unit=" m")
        check_range("bearing.inner_groove_ratio", self.inner_groove_ratio, low=0.5, high=1.0, high_open=False)
        if self.outer_raceway not in OUTER_RACEWAYS:
            raise ValueError(f"outer_raceway must be one of {OUTER_RACEWAYS}, got {self.outer_raceway!r}")
        if self.outer_raceway == "groove":
            check_range("bearing.outer_groove_ratio", self.outer_groove_ratio, low=0.5, high=1.0, high_open=False)
        else:
            check_range("bearing.outer_groove_ratio", self.outer_groove_ratio, low=1.0, why="a sphere about the centre")
        if self.groove_facing not in GROOVE_FACINGS:
            raise ValueError(f"groove_facing must be one of {GROOVE_FACINGS}, got {self.groove_facing!r}")
        check_range("bearing.contact_angle", self.free_contact_angle, low=0.0, high=math.pi / 2, low_open=False,
                    high_open=self.groove_facing == "radial", unit=" rad")
        check_range("bearing.dynamic_load_rating", self.dynamic_load_rating, low=0.0, unit=" N")
        if _is_concrete(self.ball_diameter, self.pitch_diameter):
            largest = float(self.pitch_diameter) * math.sin(math.pi / self.ball_count)
            check_range("bearing.ball_diameter", self.ball_diameter, low=0.0, high=largest, unit=" m",
                        why="pitch_diameter·sin(π/balls), so that the balls fit on the pitch circle")
        for name in ("bore", "outer_diameter"):
            check_range(f"bearing.{name}", getattr(self, name), low=0.0, unit=" m")
        if self.bore is not None and _is_concrete(self.bore, self.pitch_diameter, self.ball_diameter):
            check_range("bearing.bore", self.bore, low=0.0,
                        high=float(self.pitch_diameter - self.ball_diameter), unit=" m", why="pitch_diameter − ball_diameter")
        if self.outer_diameter is not None and _is_concrete(self.outer_diameter, self.pitch_diameter, self.ball_diameter):
            check_range("bearing.outer_diameter", self.outer_diameter,
                        low=float(self.pitch_diameter + self.ball_diameter), unit=" m", why="pitch_diameter + ball_diameter")

    @property
    def radial_contact(self) -> bool:
        """Whether the standards rate it as a radial-contact bearing (a deep-groove one: ISO 281 and
        ISO 76 at a nominal contact angle of 0, ISO 76's P₀ rule for radial bearings)."""
        return self.kind == "deep_groove_ball"

    @property
    def nominal_contact_angle(self):
        """α for the ratings [rad]: 0 for a radial-contact (deep-groove) bearing, else its free
        contact angle α₀ as designed (kept by `with_radial_clearance` when a mounting moves α₀)."""
        if self.radial_contact:
            return 0.0
        return self.free_contact_angle if self.rated_contact_angle is None else self.rated_contact_angle


def groove_curvature_centre_distance(bearing: BallBearing):
    """Distance B·D_w = (f_i + f_o − 1) D_w [m] between the two groove curvature centres."""
    return (bearing.inner_groove_ratio + bearing.outer_groove_ratio - 1.0) * bearing.ball_diameter


def radial_clearance(bearing: BallBearing):
    """Diametral radial clearance G_r = 2 B D_w (1 − cos α₀) − ι [m] (Harris & Kotzalas vol. 1, ch. 2;
    docs/theory.md §Groove geometry and clearance); negative for a bearing with interference ι."""
    return 2.0 * groove_curvature_centre_distance(bearing) * (1.0 - jnp.cos(bearing.free_contact_angle)) \
        - bearing.interference


def _check_clearance(clearance, distance, pitch_diameter):
    if _is_concrete(distance, pitch_diameter):
        check_range("bearing.radial_clearance", clearance, low=-0.01 * float(pitch_diameter),
                    high=2.0 * float(distance), low_open=False, unit=" m",
                    why="2 (f_i + f_o − 1) D_w; negative for a preloaded bearing, above −1 % of d_m")


def with_radial_clearance(bearing: BallBearing, clearance) -> BallBearing:
    """The bearing at another diametral clearance G_r [m] (`contact_angle_and_interference`: a
    negative one an interference); differentiable. Its ratings stay at its nominal contact angle
    (ISO 76 and ISO 281 rate the bearing as designed, not as mounted). ValueError outside
    `ball_bearing`'s range."""
    distance = groove_curvature_centre_distance(bearing)
    _check_clearance(clearance, distance, bearing.pitch_diameter)
    angle, interference = contact_angle_and_interference(clearance, distance)
    rated = bearing.free_contact_angle if bearing.rated_contact_angle is None else bearing.rated_contact_angle
    return eqx.tree_at(lambda b: (b.free_contact_angle, b.interference, b.rated_contact_angle), bearing,
                       (angle, interference, rated), is_leaf=lambda x: x is None)


def clearance_changed(bearing: BallBearing, change) -> BallBearing:
    """The bearing with its diametral clearance changed by `change` [m] (a mounting's fits and
    temperatures): the groove centres' radial distance shifted by −change/2 (the interference
    ι − change), the free contact angle kept. The same rings as `with_radial_clearance`'s angle
    arccos(1 − G/(2 B D_w)) at a clamped axial position (`bearing_set.clamped_offset`), without that
    angle's infinite slope at G = 0, through which a warming bearing's clearance may pass."""
    return eqx.tree_at(lambda b: b.interference, bearing, bearing.interference - change)


def contact_angle_and_interference(clearance, distance):
    """(α₀ [rad], ι [m]) of a diametral clearance G_r [m] with groove centre distance B D_w [m]:
    cos α₀ = 1 − G_r/(2 B D_w) for G_r ≥ 0; α₀ = 0 and ι = −G_r for a negative one. The arccos is
    taken of a harmless stand-in where G_r ≤ 0 (double `where`), so that its infinite slope at
    G_r = 0 leaves no NaN in the derivative of a preloaded bearing."""
    opened = clearance > 0.0
    safe = jnp.where(opened, clearance, distance)
    return (jnp.where(opened, jnp.arccos(1.0 - safe / (2.0 * distance)), 0.0),
            jnp.where(opened, 0.0, -clearance))


def ball_bearing(
    *,
    ball_diameter,
    pitch_diameter,
    balls: int,
    kind: str = "angular_contact_ball",
    inner_groove_ratio=None,
    outer_groove_ratio=None,
    inner_groove_radius=None,
    outer_groove_radius=None,
    contact_angle=None,
    radial_clearance=None,
    ball_material: Material = BEARING_STEEL,
    ring_material: Material = BEARING_STEEL,
    bore=None,
    outer_diameter=None,
    dynamic_load_rating=None,
    outer_raceway: str = "groove",
    groove_facing: str = "radial",
) -> BallBearing:
    """Build a `BallBearing` from the quantities a drawing gives (SI units).

    Give each groove as a ratio f = r/D_w or a radius r [m], and either the free contact angle
    α₀ [rad] or the diametral radial clearance G_r [m]; then cos α₀ = 1 − G_r/(2(f_i + f_o − 1)D_w)
    (Harris & Kotzalas vol. 1, ch. 2; the 6411E chamfer paper). Raises ValueError naming the offending parameter.
    """
    check_range("bearing.ball_diameter", ball_diameter, low=0.0, unit=" m")
    check_range("bearing.pitch_diameter", pitch_diameter, low=0.0, unit=" m")
    for side, ratio, radius in (("inner", inner_groove_ratio, inner_groove_radius),
                                ("outer", outer_groove_ratio, outer_groove_radius)):
        if (ratio is None) == (radius is None):
            raise ValueError(f"bearing: give exactly one of {side}_groove_ratio and {side}_groove_radius")
        if radius is not None and _is_concrete(radius, ball_diameter):
            check_range(f"bearing.{side}_groove_radius", radius, low=0.5 * float(ball_diameter), high=float(ball_diameter),
                        high_open=False, unit=" m", why="the ball radius to the ball diameter: f in (0.5, 1]")
    fi = inner_groove_ratio if inner_groove_ratio is not None else inner_groove_radius / ball_diameter
    fo = outer_groove_ratio if outer_groove_ratio is not None else outer_groove_radius / ball_diameter
    if (contact_angle is None) == (radial_clearance is None):
        raise ValueError("bearing: give exactly one of contact_angle and radial_clearance")
    if radial_clearance is not None:
        check_range("bearing.inner_groove_ratio", fi, low=0.5, high=1.0, high_open=False)
        check_range("bearing.outer_groove_ratio", fo, low=0.5, high=1.0, high_open=False)
        distance = (fi + fo - 1.0) * ball_diameter
        _check_clearance(radial_clearance, distance, pitch_diameter)
        contact_angle, interference = contact_angle_and_interference(radial_clearance, distance)
    return BallBearing(
        ball_diameter=ball_diameter, pitch_diameter=pitch_diameter, inner_groove_ratio=fi,
        outer_groove_ratio=fo, free_contact_angle=contact_angle, ball_material=ball_material,
        ring_material=ring_material, ball_count=balls, kind=kind, bore=bore,
        outer_diameter=outer_diameter, dynamic_load_rating=dynamic_load_rating,
        interference=0.0 if radial_clearance is None else interference, outer_raceway=outer_raceway,
        groove_facing=groove_facing,
    )


def check_radial_force_free(force, radial_displacement) -> None:
    """ValueError naming operating.force where a radial displacement is prescribed and [Fx, Fy] is not
    zero (ball and roller bearings: the radial force is then an output)."""
    if radial_displacement is not None and _is_concrete(force) and np.any(np.asarray(force)[..., :2] != 0):
        raise ValueError("operating.force: Fx and Fy must be 0 with operating.radial_displacement "
                         "(the radial force follows from the prescribed displacement)")


def check_axial_force_free(force, axial_displacement) -> None:
    """ValueError naming operating.force where an axial displacement is prescribed and Fz is not
    zero (ball and tapered roller bearings: the axial force is then an output)."""
    if axial_displacement is not None and _is_concrete(force) and np.any(np.asarray(force)[..., 2] != 0):
        raise ValueError("operating.force: Fz must be 0 with operating.axial_displacement "
                         "(the axial force follows from the prescribed displacement)")


class Operating(eqx.Module):
    """Operating point: ring speeds and the load on the inner ring (outer ring fixed in space)."""

    inner_speed: np.ndarray = eqx.field(converter=_as_float)  # ω_i [rad/s]
    outer_speed: np.ndarray = eqx.field(converter=_as_float)  # ω_o [rad/s]
    force: np.ndarray = eqx.field(converter=_as_float)  # [Fx, Fy, Fz] [N]
    moment: np.ndarray = eqx.field(converter=_as_float)  # [Mx, My] [N·m]
    # Preload by axial displacement: δz [m] held fixed (Fz must be 0; the axial force follows).
    axial_displacement: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v),
                                                      default=None)
    # Imposed inner-ring tilt [θx, θy] [rad] (the moments must be 0; the moments the balls carry follow).
    misalignment: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v), default=None)
    # Imposed radial displacement [δx, δy] [m] (Fx, Fy must be 0; the radial force follows).
    radial_displacement: np.ndarray | None = eqx.field(converter=lambda v: None if v is None else _as_float(v),
                                                       default=None)

    def __check_init__(self):
        check_range("operating.inner_speed", self.inner_speed, unit=" rad/s")
        check_range("operating.outer_speed", self.outer_speed, unit=" rad/s")
        check_range("operating.force", self.force, unit=" N")
        check_range("operating.moment", self.moment, unit=" N*m")
        for name, size in (("force", 3), ("moment", 2)):
            value = getattr(self, name)
            if _is_concrete(value) and np.shape(value)[-1:] != (size,):
                raise ValueError(f"operating.{name} must have {size} components, got shape {np.shape(value)}")
        check_range("operating.axial_displacement", self.axial_displacement, unit=" m")
        check_axial_force_free(self.force, self.axial_displacement)
        check_range("operating.misalignment", self.misalignment, low=-MAX_MISALIGNMENT, high=MAX_MISALIGNMENT,
                    unit=" rad", why="small-angle misalignment, |θ| < 0.05 rad ≈ 2.9°")
        if self.misalignment is not None and _is_concrete(self.moment) and np.any(np.asarray(self.moment) != 0):
            raise ValueError("operating.moment: with operating.misalignment the inner ring's tilt is imposed and the "
                             "moments follow; give one of them")
        check_range("operating.radial_displacement", self.radial_displacement, unit=" m")
        if self.radial_displacement is not None and _is_concrete(self.radial_displacement) and \
                np.shape(self.radial_displacement)[-1:] != (2,):
            raise ValueError("operating.radial_displacement must have 2 components [δx, δy], "
                             f"got shape {np.shape(self.radial_displacement)}")
        check_radial_force_free(self.force, self.radial_displacement)


CAGE_POCKETS = ("outer_lock", "cylindrical")
CAGE_GUIDANCES = ("outer_ring",)  # the guidance the cage model has: lands on the outer ring

# Short-carbon-fibre PEEK (PEEK-CF30, the cage paper's cage): representative moduli of machined parts;
# the cage material only sets the ball–pocket Hertz stiffness, which hardly moves quasi-static forces.
PEEK_CF30 = Material(13e9, 0.4, 1410.0, name="peek_cf30")


class Cage(eqx.Module):
    """A ball-bearing cage guided by two outer-ring lands, with cylindrical or outer-lock pockets.

    Build it with `ball_cage(bearing, ...)`, which fills the geometry a scene leaves out. The
    pocket diameter is D_w + c_p; the cage's outer radius at the lands is (d_land − c_g)/2; the
    lands are centred at ±s/2 from the pocket row.
    """

    pocket_clearance: np.ndarray = eqx.field(converter=_as_float)  # c_p, diametral [m]
    guide_clearance: np.ndarray = eqx.field(converter=_as_float)  # c_g, diametral, at the lands [m]
    land_width: np.ndarray = eqx.field(converter=_as_float)  # L of each land [m]
    land_diameter: np.ndarray = eqx.field(converter=_as_float)  # d_land, the outer ring's guiding bore [m]
    land_spacing: np.ndarray = eqx.field(converter=_as_float)  # s, axial distance of the two land centres [m]
    friction: np.ndarray = eqx.field(converter=_as_float)  # μ, ball–pocket and land metal contact [-]
    film_threshold: np.ndarray = eqx.field(converter=_as_float)  # h_t, land film below which metal contact takes over [m]
    contact_stiffness: np.ndarray = eqx.field(converter=_as_float)  # k_m of the land metal contact [N/m]
    pushing_balls: np.ndarray = eqx.field(converter=_as_float)  # m, balls that drive the cage (a count)
    resisting_balls: np.ndarray = eqx.field(converter=_as_float)  # n, balls that the cage drives (a count)
    material: Material = PEEK_CF30
    pocket: str = eqx.field(static=True, default="outer_lock")
    guidance: str = eqx.field(static=True, default="outer_ring")

    @property
    def outer_radius(self):
        """R = (d_land − c_g)/2 [m], the cage's outer radius at the lands."""
        return 0.5 * (self.land_diameter - self.guide_clearance)

    def __check_init__(self):
        if self.pocket not in CAGE_POCKETS:
            raise ValueError(f"cage.pocket must be one of {CAGE_POCKETS}, got {self.pocket!r}")
        if self.guidance not in CAGE_GUIDANCES:
            raise ValueError(f"cage.guidance must be one of {CAGE_GUIDANCES}, got {self.guidance!r}")
        for name in ("pocket_clearance", "guide_clearance", "land_width", "land_diameter", "land_spacing"):
            check_range(f"cage.{name}", getattr(self, name), low=0.0, unit=" m")
        check_range("cage.friction", self.friction, low=0.0, low_open=False)
        check_range("cage.film_threshold", self.film_threshold, low=0.0, high=float(0.5 * self.guide_clearance)
                    if _is_concrete(self.guide_clearance) else None, unit=" m", why="half the radial guide clearance")
        check_range("cage.contact_stiffness", self.contact_stiffness, low=0.0, unit=" N/m")
        check_range("cage.pushing_balls", self.pushing_balls, low=1.0, low_open=False)
        check_range("cage.resisting_balls", self.resisting_balls, low=0.0, low_open=False)


def ball_cage(bearing: BallBearing, *, pocket: str = "outer_lock", pocket_clearance, guide_clearance, land_width,
              friction=0.1, land_diameter=None, land_spacing=None, film_threshold=1e-6, contact_stiffness=3e7,
              pushing_balls, resisting_balls, material: Material = PEEK_CF30, guidance: str = "outer_ring") -> Cage:
    """A `Cage` for `bearing` (SI units), with the geometry a drawing may leave out filled in:
    land bore d_land = d_m + 0.8 D_w (a B7005-class outer-ring shoulder) and land spacing
    s = D_w + L (the lands just outside the pockets). Checks that an outer-lock pocket's mouth,
    where the sphere meets the cage's outer surface, is narrower than the ball (else the pocket
    would not lock) and that the pushing and resisting counts fit the bearing; ValueError names
    the parameter."""
    if _is_concrete(bearing.ball_diameter, bearing.pitch_diameter):
        check_range("cage.pocket_clearance", pocket_clearance, low=0.0, high=0.5 * float(bearing.ball_diameter),
                    unit=" m", why="half bearing.ball_diameter: a pocket that holds its ball")
        check_range("cage.guide_clearance", guide_clearance, low=2.0 * float(film_threshold),
                    high=0.8 * float(bearing.ball_diameter), unit=" m",
                    why="twice the land film threshold, and the land's 0.8 D_w above the pitch circle")
    if land_diameter is None:
        land_diameter = bearing.pitch_diameter + 0.8 * bearing.ball_diameter
    if land_spacing is None:
        land_spacing = bearing.ball_diameter + land_width
    count = bearing.ball_count
    for name, value in (("pushing_balls", pushing_balls), ("resisting_balls", resisting_balls)):
        check_range(f"cage.{name}", value, low=0.0, high=float(count), low_open=False, high_open=False,
                    why="bearing.balls")
    if _is_concrete(pushing_balls, resisting_balls):
        check_range("cage.resisting_balls", resisting_balls, high=float(count - pushing_balls), high_open=False,
                    why="bearing.balls − cage.pushing_balls")
    if pocket == "outer_lock" and _is_concrete(land_diameter, guide_clearance, pocket_clearance, bearing.ball_diameter):
        ball_radius = 0.5 * float(bearing.ball_diameter)
        pocket_radius = ball_radius + 0.5 * float(pocket_clearance)
        lowest = math.sqrt(max(pocket_radius**2 - ball_radius**2, 0.0))
        check_range("cage.land_diameter", land_diameter, low=float(bearing.pitch_diameter + guide_clearance) + 2 * lowest,
                    high=float(bearing.pitch_diameter + bearing.ball_diameter), unit=" m",
                    why="the outer-lock mouth √(R_pok² − (R_cage − d_m/2)²) must be narrower than the ball, "
                        "and the land inside the outer raceway")
    return Cage(pocket_clearance=pocket_clearance, guide_clearance=guide_clearance, land_width=land_width,
                land_diameter=land_diameter, land_spacing=land_spacing, friction=friction,
                film_threshold=film_threshold, contact_stiffness=contact_stiffness, pushing_balls=pushing_balls,
                resisting_balls=resisting_balls, material=material, pocket=pocket, guidance=guidance)
