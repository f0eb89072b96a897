"""A self-aligning ball bearing: two rows of balls in the inner ring's two grooves, one spherical
outer raceway, as `AbstractSupport`.

Geometry (docs/theory.md §Self-aligning ball bearings). The outer raceway is a sphere of radius
R_s = f_o D_w about the bearing's centre O; a ball at the pitch radius d_m/2 and at the nominal
contact angle α₀ touches it where the line from O through the ball's centre meets it, so

    (R_s − D_w/2) cos α₀ = d_m/2,   f_o = d_m / (2 D_w cos α₀) + ½,

and each row is the single-row ball model with that f_o (`BallBearing.outer_raceway` "sphere"):
its outer "groove" centre is O for both rows, its plane of inner groove centres at
z_r = ±B D_w sin α₀ (B = f_i + f_o − 1), the rows face to face (X: their lines of contact meet
at O; `double_row.DoubleRowSupport`, `arrangement` "face_to_face"). The contact on a sphere is
circular (F(ρ) = 0: its curvature is 1/R_s across and along the rolling direction).

A rotation of the inner ring about O keeps every inner groove centre's distance from O, so it
loads no ball: a self-aligning bearing carries no moment and its tilt stiffness is zero, exactly,
at any tilt (at standstill, where each ball lies on the line from O to its inner groove centre,
so that every contact force passes through O). The small-rotation ring model would make the
distance grow as R θ²/2, so the support takes the rows' load at the inner ring's translation
alone, F = [F_rows(δ, 0)_{1..3}, 0, 0], and its stiffness with zero rows and columns in θ. The
model is static (no speed effects: centrifugal force moves a ball off the line through O).

Radial clearance G_r (diametral): each row's inner ring backed off along its own axis by
e = B D_w sin α₀ − √((B D_w)² − (B D_w cos α₀ + G_r/2)²), the radial play that then closes a row
being G_r/2 (`axial_backoff`); s_a = 2e is the rows' `axial_clearance`.

Ratings: ISO 281 eq. (2) with i = 2 and Table 2's f_c for self-aligning ball bearings; ISO/TS
16281 over the four raceways; ISO 76 with i = 2, Table 1's f₀ for self-aligning ball bearings,
X₀ = 1, Y₀ = 0.44 cot α₀ (Table 2, double row) and the permissible pressure of 4 600 MPa.
"""

import jax.numpy as jnp
import numpy as np

from ...params import BallBearing, _is_concrete, ball_bearing, check_range, groove_curvature_centre_distance
from ...ratings import life, static_safety
from ..interface import AbstractSupport, ContactLoads
from .ball_equilibrium import BallModel
from .double_row import ROWS, DoubleRowSupport

PERMISSIBLE_MISALIGNMENT = np.radians(2.5)  # rad: the catalogues' for self-aligning ball bearings (SKF: 2.5°–3°)
TRANSLATION = np.array([1.0, 1.0, 1.0, 0.0, 0.0])  # the components of Δ and F a sphere transmits


def sphere_ratio(ball_diameter, pitch_diameter, contact_angle):
    """f_o = R_s / D_w = d_m / (2 D_w cos α₀) + ½ [-]: the sphere through the rows' balls at α₀."""
    return pitch_diameter / (2.0 * ball_diameter * jnp.cos(contact_angle)) + 0.5


def axial_backoff(row: BallBearing, radial_clearance):
    """e [m]: each row's inner ring backed off along its axis for a diametral radial clearance G_r
    [m] (module docstring; negative G_r: pressed, e < 0)."""
    distance = groove_curvature_centre_distance(row)
    angle = row.free_contact_angle
    return distance * jnp.sin(angle) - jnp.sqrt(distance**2 - (distance * jnp.cos(angle) + 0.5 * radial_clearance) ** 2)


class SelfAligningSupport(AbstractSupport):
    """A self-aligning ball bearing on a shaft: its rows (`rows`, a face-to-face
    `DoubleRowSupport` of rows with a spherical outer raceway; `self_aligning_support` builds it
    from a row, `self_aligning_row`, and the clearance). Placement as `BallSupport`'s, the rows'."""

    rows: DoubleRowSupport

    def __check_init__(self):
        if self.rows.arrangement != "face_to_face" or self.rows.bearing.outer_raceway != "sphere":
            raise ValueError("a self-aligning bearing's rows face to face on a spherical outer raceway "
                             "(`self_aligning_support`)")
        if self.rows.model.speed_effects:
            raise ValueError("effects.centrifugal, effects.gyroscopic: the self-aligning ball bearing model is static "
                             "(no speed effects on its balls)")

    @property
    def position(self):
        return self.rows.position

    @property
    def offset(self):
        return self.rows.offset

    @property
    def orientation(self):
        return self.rows.orientation

    def _translated(self, displacement):
        return displacement * TRANSLATION

    def constants(self):
        return self.rows.constants()

    def constants_key(self):
        return self.rows.constants_key()

    def ring_force(self, displacement, speed, constants, elements=None):
        """The rows' load at the inner ring's translation; no moment (module docstring)."""
        return TRANSLATION * self.rows.ring_force(self._translated(displacement), speed, constants)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """The rows' stiffness at the translation, zero in the tilts."""
        stiffness = self.rows.ring_stiffness(self._translated(displacement), speed, constants)
        return TRANSLATION[:, None] * stiffness * TRANSLATION[None, :]

    def energy_constants(self, constants):
        return self.rows.energy_constants(constants)

    def static_energy(self, displacement, energy_constants):
        return self.rows.static_energy(self._translated(displacement), energy_constants)

    def characteristic_load(self, constants, energy_constants):
        return self.rows.characteristic_load(constants, energy_constants)

    def pitch_radius(self):
        return self.rows.pitch_radius()

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """The rows' four contacts a ball position at the inner ring's translation."""
        return self.rows.contacts(self._translated(displacement), speed, constants)

    def dynamic_load_rating(self):
        """The bearing's own C_r where given, else ISO 281 eq. (2), i = 2, f_c of Table 2's
        self-aligning column (`life.self_aligning_load_rating`)."""
        row = self.rows.bearing
        if row.dynamic_load_rating is not None:
            return row.dynamic_load_rating
        return life.self_aligning_load_rating(row, ROWS)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """Each row's Q_ci, Q_ce at its own C_r = C_r / 2^0.7 (`life.raceway_ratings`; the sphere's
        radius as r_e)."""
        return self.rows.contact_ratings(rating, contacts)

    def equivalent_dynamic_load(self, force):
        """ISO 281 P, Table 3's double-row self-aligning row (`life.self_aligning_equivalent_dynamic_load`)."""
        return life.self_aligning_equivalent_dynamic_load(force, self.rows.bearing.free_contact_angle)

    def static_load_rating(self):
        """ISO 76 C₀r = f₀ · 2 Z D_w² cos α₀ with Table 1's f₀ for self-aligning ball bearings."""
        row = self.rows.bearing
        return static_safety.self_aligning_static_load_rating(row.ball_count, row.ball_diameter, row.pitch_diameter,
                                                              row.free_contact_angle, rows=ROWS)

    def equivalent_static_load(self, force):
        """ISO 76 P₀r = F_r + 0.44 cot α₀ F_a (Table 2, double-row self-aligning)."""
        return static_safety.self_aligning_equivalent_static_load(force, self.rows.bearing.free_contact_angle)

    def pressure_safety(self, max_pressure):
        """(4 600 MPa / p_max)³."""
        return static_safety.pressure_safety(max_pressure, static_safety.SELF_ALIGNING_PRESSURE_LIMIT,
                                             static_safety.POINT_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "ball"

    def hybrid(self) -> bool:
        return self.rows.hybrid()

    def nominal_contact_angle(self):
        return self.rows.bearing.free_contact_angle

    def permissible_misalignment(self):
        return PERMISSIBLE_MISALIGNMENT

    def envelope(self, contacts: ContactLoads):
        return self.rows.envelope(contacts)

    def frequencies(self, speed, contacts: ContactLoads):
        return self.rows.frequencies(speed, contacts)


def self_aligning_row(*, ball_diameter, pitch_diameter, balls, contact_angle, inner_groove_ratio=None,
                      inner_groove_radius=None, **materials_and_sizes) -> BallBearing:
    """One row of a self-aligning ball bearing from its drawing's numbers (SI): D_w, d_m, balls a
    row, the nominal contact angle α₀ [rad], the inner grooves' f_i or radius r_i [m] (one of
    them), its sphere's f_o (`sphere_ratio`);
    `materials_and_sizes` as `params.ball_bearing`'s (ball_material, ring_material, bore,
    outer_diameter, dynamic_load_rating: the whole bearing's). ValueError naming the offending key."""
    check_range("bearing.contact_angle", contact_angle, low=0.0, high=0.5 * np.pi, unit=" rad")
    check_range("bearing.ball_diameter", ball_diameter, low=0.0, unit=" m")
    return ball_bearing(ball_diameter=ball_diameter, pitch_diameter=pitch_diameter, balls=balls,
                        inner_groove_ratio=inner_groove_ratio, inner_groove_radius=inner_groove_radius,
                        outer_groove_ratio=sphere_ratio(ball_diameter, pitch_diameter, contact_angle),
                        contact_angle=contact_angle, outer_raceway="sphere", **materials_and_sizes)


def self_aligning_support(row: BallBearing, radial_clearance, position, offset=0.0, model: BallModel = BallModel(),
                          orientation=1) -> SelfAligningSupport:
    """A `SelfAligningSupport` of rows `row` (`self_aligning_row`) with the diametral radial
    clearance G_r [m]; placement as `BallSupport`'s. ValueError naming bearing.radial_clearance
    outside the rows' geometry."""
    distance = groove_curvature_centre_distance(row)
    if _is_concrete(distance, row.free_contact_angle):
        cosine = float(np.cos(row.free_contact_angle))
        check_range("bearing.radial_clearance", radial_clearance, low=-2.0 * float(distance) * cosine,
                    high=2.0 * float(distance) * (1.0 - cosine), unit=" m",
                    why="−2 B·D_w cos α₀ to 2 B·D_w (1 − cos α₀), B = f_i + f_o − 1: a row touching within 0°–90°")
    spacing = 2.0 * distance * jnp.sin(row.free_contact_angle)
    rows = DoubleRowSupport(row, spacing, position, 2.0 * axial_backoff(row, radial_clearance), offset, model,
                            orientation, arrangement="face_to_face")
    return SelfAligningSupport(rows)
