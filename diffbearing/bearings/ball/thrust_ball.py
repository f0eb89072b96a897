"""A thrust ball bearing, single direction: Z balls between a shaft washer and a housing washer, at
α₀ = 90° (grooved washers) or, as an angular-contact thrust bearing, at 45° ≤ α₀ ≤ 75°, as
`AbstractSupport`.

Geometry (docs/theory.md §Thrust ball bearings). The ball model of `ball_equilibrium` with the
shaft washer as its "inner" ring and the housing washer as its "outer" one: the grooves' curvature
centres lie on the line at α₀ through each ball's centre, B D_w = (f_i + f_o − 1) D_w apart. At
α₀ = 90° both centres sit on the pitch circle, axially apart, and each washer's groove faces along
the axis (`BallBearing.groove_facing` "axial"): a contact exists while its angle stays within 90°
of the axis, so that at speed, where the centrifugal force F_c carries each ball outward, the
shaft washer's contact turns past 90° (α_i > 90°) and the housing washer's below it (α_o < 90°),
both pushing the ball back in:

    Q_i sin α_i = Q_o sin α_o,   Q_o cos α_o − Q_i cos α_i = F_c   (no gyroscopic moment),

and with equal grooves (f_i = f_o) the two turn alike, α_i − 90° = 90° − α_o = arctan(F_c / (2 Q_a)),
Q_a = F_a / Z (tests/test_thrust_ball.py). With the gyroscopic moment the controlling washer's
friction carries it (`BallModel.race_control`).

The housing washer of a 90° bearing is not centred radially (its bore clears the shaft, its
outside diameter the housing): it carries no radial load, and takes the radial position that
makes its radial force vanish. The model holds that position at the shaft washer's (δx = δy = 0
in the bearing), where every contact normal at standstill is axial, so the radial force is zero
exactly; at speed under a tilt the balls' centrifugal loads leave a small radial force, dropped
with the radial washer shift it would cause. Its ring force is then [0, 0, Fz, Mx, My] of the
axial and tilt displacements alone, and its stiffness zero in δx, δy. An angular-contact thrust
bearing (α₀ ≤ 75°) is centred by its rings, like an angular-contact ball bearing: all five.

Ratings: ISO 281 eqs. (5)–(8) and Table 5 (C_a, P_a), ISO 76 eqs. (4)–(6) (C₀a, P₀a), ISO/TS
16281 raceway ratings of thrust ball bearings (`ratings.thrust_ball_ratings`); the permissible
pressure of 4 200 MPa (ISO 76, ball bearings).
"""

import jax.numpy as jnp
import numpy as np

from ...params import BallBearing, _is_concrete, ball_bearing, check_range
from ...ratings import thrust_ball_ratings
from ..interface import AbstractSupport, CondensedElements, ContactLoads
from . import ball_validity, kinematics
from .ball_equilibrium import BallModel
from .ball_support import BallSupport

AXIAL = 0.5 * np.pi
SMALLEST_CONTACT_ANGLE = np.radians(45.0)  # ISO 281: a ball bearing above it is a thrust bearing
LARGEST_ANGULAR_CONTACT_ANGLE = np.radians(75.0)  # ISO 281 Table 4's last angular-contact column
AXIAL_AND_TILT = np.array([0.0, 0.0, 1.0, 1.0, 1.0])  # the components a 90° bearing's floating washer transmits


def is_axial(bearing: BallBearing) -> bool:
    """Whether the bearing's balls sit at α₀ = 90° between grooved washers (`groove_facing` "axial")."""
    return bearing.groove_facing == "axial"


def thrust_ball_bearing(*, ball_diameter, pitch_diameter, balls, contact_angle=AXIAL, inner_groove_ratio=None,
                        outer_groove_ratio=None, inner_groove_radius=None, outer_groove_radius=None,
                        **materials_and_sizes) -> BallBearing:
    """A thrust ball bearing's balls and grooves (SI): D_w, d_m, Z, α₀ [rad] (90°, or 45°–75° for
    an angular-contact thrust bearing, as ISO 281 Table 4 rates them), each washer's groove as a
    ratio f = r/D_w or a radius r [m]; `materials_and_sizes` as `params.ball_bearing`'s. The balls
    touch both grooves at α₀ at zero load. ValueError naming the offending key."""
    axial = _is_concrete(contact_angle) and abs(float(contact_angle) - AXIAL) < 1e-12
    if not axial:
        _check_angular_contact_angle(contact_angle)
    return ball_bearing(ball_diameter=ball_diameter, pitch_diameter=pitch_diameter, balls=balls,
                        kind="angular_contact_ball", inner_groove_ratio=inner_groove_ratio,
                        outer_groove_ratio=outer_groove_ratio, inner_groove_radius=inner_groove_radius,
                        outer_groove_radius=outer_groove_radius, contact_angle=AXIAL if axial else contact_angle,
                        groove_facing="axial" if axial else "radial", **materials_and_sizes)


def _check_angular_contact_angle(contact_angle):
    """ValueError naming bearing.contact_angle outside 45°–75° (an angular-contact thrust bearing's)."""
    check_range("bearing.contact_angle", contact_angle, low=float(SMALLEST_CONTACT_ANGLE),
                high=float(LARGEST_ANGULAR_CONTACT_ANGLE), low_open=False, high_open=False, unit=" rad",
                why="45°–75° or 90°: ISO 281 Table 4 rates thrust ball bearings there")


class ThrustBallSupport(AbstractSupport):
    """A single-direction thrust ball bearing on a shaft: its balls and washers as a `BallSupport`
    (`balls`; `thrust_ball_support` builds it). Placement as `BallSupport`'s: at Δ = 0 the balls
    touch both grooves at α₀."""

    balls: BallSupport

    def __check_init__(self):
        if not is_axial(self.bearing):
            _check_angular_contact_angle(self.bearing.free_contact_angle)

    @property
    def bearing(self) -> BallBearing:
        return self.balls.bearing

    @property
    def position(self):
        return self.balls.position

    @property
    def offset(self):
        return self.balls.offset

    @property
    def orientation(self):
        return self.balls.orientation

    def _transmitted(self):
        """(5,) the components of Δ and F the bearing transmits (module docstring)."""
        return AXIAL_AND_TILT if is_axial(self.bearing) else np.ones(5)

    def _held(self, displacement):
        return displacement * self._transmitted()

    def constants(self):
        """None: each contact's Hertz constant solved at its own angle (a 90° bearing's contacts
        turn to either side of 90°, outside the radial bearings' table in cos α ≥ 0)."""
        return None

    def ring_force(self, displacement, speed, constants, elements=None):
        return self._transmitted() * self.balls.ring_force(self._held(displacement), speed, constants, elements)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        transmitted = self._transmitted()
        stiffness = self.balls.ring_stiffness(self._held(displacement), speed, constants, elements)
        return transmitted[:, None] * stiffness * transmitted[None, :]

    def energy_constants(self, constants):
        return self.balls.energy_constants(constants)

    def static_energy(self, displacement, energy_constants):
        return self.balls.static_energy(self._held(displacement), energy_constants)

    def characteristic_load(self, constants, energy_constants):
        return self.balls.characteristic_load(constants, energy_constants)

    def pitch_radius(self):
        return self.balls.pitch_radius()

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Each ball's shaft-washer ("inner") and housing-washer ("outer") contact."""
        return self.balls.contacts(self._held(displacement), speed, constants, elements)

    def dynamic_load_rating(self):
        """The bearing's own C_a where given, else ISO 281's (`thrust_ball_ratings.thrust_ball_dynamic_load_rating`)."""
        bearing = self.bearing
        if bearing.dynamic_load_rating is not None:
            return bearing.dynamic_load_rating
        return thrust_ball_ratings.thrust_ball_dynamic_load_rating(bearing.ball_count, bearing.ball_diameter,
                                                                   bearing.pitch_diameter, self._rated_angle())

    def _rated_angle(self):
        """α₀ as the standards' tables read it: for a 90° bearing the Python float π/2, so that the
        ratings take their 90° forms under tracing too (`thrust_ball_ratings`)."""
        return AXIAL if is_axial(self.bearing) else self.bearing.free_contact_angle

    def contact_ratings(self, rating, contacts: ContactLoads):
        """Q_ci, Q_ce [N] of ISO/TS 16281 for thrust ball bearings (`thrust_ball_raceway_ratings`)."""
        bearing = self.bearing
        return jnp.stack(thrust_ball_ratings.thrust_ball_raceway_ratings(
            rating, bearing.ball_count, bearing.ball_diameter, bearing.pitch_diameter, self._rated_angle(),
            bearing.inner_groove_ratio, bearing.outer_groove_ratio))

    def equivalent_dynamic_load(self, force):
        """ISO 281 P_a, single direction (`thrust_ball_equivalent_dynamic_load`)."""
        return thrust_ball_ratings.thrust_ball_equivalent_dynamic_load(force, self._rated_angle())

    def static_load_rating(self):
        """ISO 76 C₀a = f₀ Z D_w² sin α (`thrust_ball_static_load_rating`)."""
        bearing = self.bearing
        return thrust_ball_ratings.thrust_ball_static_load_rating(bearing.ball_count, bearing.ball_diameter,
                                                                  bearing.pitch_diameter, self._rated_angle())

    def equivalent_static_load(self, force):
        """ISO 76 P₀a (`thrust_ball_equivalent_static_load`)."""
        return thrust_ball_ratings.thrust_ball_equivalent_static_load(force, self._rated_angle())

    def pressure_safety(self, max_pressure):
        """(4 200 MPa / p_max)³, a ball bearing's (ISO 76)."""
        return self.balls.pressure_safety(max_pressure)

    def rolling_element(self) -> str:
        return self.balls.rolling_element()

    def hybrid(self) -> bool:
        return self.balls.hybrid()

    def nominal_contact_angle(self):
        return self._rated_angle()

    def friction_kind(self, model: str) -> str | None:
        """Both models' thrust ball rows (HR 1's 511–514, SKF's thrust ball bearings), which hold for
        α = 90°: None for an angular-contact thrust bearing."""
        return "thrust_ball" if is_axial(self.bearing) else None

    def envelope(self, contacts: ContactLoads):
        """The largest approach / D_w; the largest loaded contact's turn from its groove's facing
        direction (|α| on rings, |α − 90°| on a 90° bearing's washers: under 90° on the groove's near
        side); the lowest loaded α of an angular-contact thrust bearing (its low shoulder), +π/2 at 90°."""
        (inner_load, outer_load), (inner_angle, outer_angle) = contacts.load.T, contacts.angle.T
        facing = AXIAL if is_axial(self.bearing) else 0.0
        turned = ball_validity.largest_contact_angle(inner_angle - facing, outer_angle - facing, inner_load, outer_load)
        lowest = (jnp.asarray(AXIAL) if is_axial(self.bearing)
                  else ball_validity.lowest_loaded_angle(inner_load, inner_angle, outer_load, outer_angle))
        return jnp.stack([ball_validity.largest_approach_ratio(*contacts.approach.T, self.bearing.ball_diameter),
                          turned, lowest])

    def frequencies(self, speed, contacts: ContactLoads):
        return self.balls.frequencies(speed, contacts)

    def carries_elements(self) -> bool:
        return self.balls.carries_elements()

    def start_elements(self, displacement, speed, constants):
        return self.balls.start_elements(self._held(displacement), speed, constants)

    def condensed(self, displacement, elements, speed, constants) -> CondensedElements:
        transmitted = self._transmitted()
        found = self.balls.condensed(self._held(displacement), elements, speed, constants)
        return CondensedElements(transmitted * found.force, transmitted[:, None] * found.stiffness * transmitted,
                                 found.correction, found.coupling * transmitted)

    def limit_element_step(self, step):
        return self.balls.limit_element_step(step)

    def element_tolerance(self):
        return self.balls.element_tolerance()

    def element_residual(self, displacement, elements, speed, constants, load_scale):
        return self.balls.element_residual(self._held(displacement), elements, speed, constants, load_scale)


def thrust_ball_support(bearing: BallBearing, position, offset=0.0, model: BallModel = BallModel(),
                        orientation=1) -> ThrustBallSupport:
    """A `ThrustBallSupport` of `bearing` (`thrust_ball_bearing`); placement and `model` as `BallSupport`'s."""
    return ThrustBallSupport(BallSupport(bearing, position, offset, model=model, orientation=orientation))


def minimum_axial_load(bearing: BallBearing, speed, traction_coefficient):
    """F_a,min [N]: the axial load below which the controlling washer's traction μ Q cannot supply
    the balls' gyroscopic moment and they skid (spin about the radial axis): each ball needs the
    friction 2 M_g / D_w at that contact (`ball_equilibrium.contact_forces`), so
    F_a,min = Z sin α₀ · 2 M_g / (μ D_w), M_g = J ω_R ω_m sin β at α₀ and shaft speed `speed` [rad/s]
    (`kinematics`; Harris & Kotzalas vol. 2, ch. 3, "ball gyroscopic motion"), μ the traction
    coefficient [-] the contact carries. It grows with n² as the catalogues' F_am = A (n/1000)²."""
    check_range("traction_coefficient", traction_coefficient, low=0.0, high=1.0, why="a traction coefficient")
    angle = bearing.free_contact_angle
    orbital, spin, beta = kinematics.ball_speeds(speed, angle, angle, bearing.ball_diameter / bearing.pitch_diameter)
    moment = kinematics.gyroscopic_moment(bearing.ball_material.density, bearing.ball_diameter, orbital, spin, beta)
    return bearing.ball_count * jnp.sin(angle) * 2.0 * jnp.abs(moment) / (traction_coefficient * bearing.ball_diameter)

