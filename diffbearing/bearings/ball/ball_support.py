"""A ball bearing (deep groove or angular contact) mounted on a shaft: `AbstractSupport` through
the ball model (`ball_equilibrium`).

At u = 0 an angular-contact bearing sits at its model's reference (balls touching at α₀), a
deep-groove one in the middle of its axial play, c = −(f_i + f_o − 1) D_w sin α₀ from there. With
speed effects the balls leave the static split: a system carries their centres (Z, 2) [m] as
unknowns (`ball_equilibrium.condensed_balls`).
"""

import equinox as eqx
import jax
import jax.numpy as jnp

from ... import overrolling
from ...params import (
    SILICON_NITRIDE,
    BallBearing,
    Operating,
    _as_float,
    clearance_changed,
    groove_curvature_centre_distance,
    radial_clearance,
)
from ...ratings import life, static_safety
from ..interface import AbstractSupport, CondensedElements, ContactLoads, RingSection, check_orientation
from . import ball_equilibrium, ball_validity
from .ball_equilibrium import BallModel, BallResults


class BallSupport(AbstractSupport):
    """A ball bearing on the shaft: at `position` z [m], `orientation` +1 ("+z": its own axial
    direction along the shaft's +z) or −1 ("−z"), inner ring pushed by `offset` [m] along its own
    axis against the outer ring (preload; 0: none)."""

    bearing: BallBearing
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: BallModel = eqx.field(static=True, default=BallModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        check_orientation(self.orientation)

    def _operating(self, speed):
        return Operating(inner_speed=speed, outer_speed=0.0, force=jnp.zeros(3), moment=jnp.zeros(2))

    def constants(self):
        """The table of Hertz constants (`ball_equilibrium.constant_table`; None held at α₀)."""
        return ball_equilibrium.constant_table(self.bearing, self.model)

    def constants_key(self):
        return id(self.bearing), self.model

    def ring_force(self, displacement, speed, constants, elements=None):
        return ball_equilibrium.ring_force(displacement, self.bearing, self._operating(speed), self.model, constants,
                                           elements)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """The exact stiffness (`ball_equilibrium.stiffness_matrix`: with speed effects one
        linearisation at the balls, those a solve found where `elements` are given)."""
        return ball_equilibrium.stiffness_matrix(displacement, self.bearing, self._operating(speed), self.model,
                                                 elements, constants)

    def energy_constants(self, constants):
        """K_n(α₀) [N/m^1.5], both contacts in series at the free contact angle."""
        return ball_equilibrium.free_contact_constant(self.bearing, self.model, constants)

    def static_energy(self, displacement, energy_constants):
        return ball_equilibrium.static_energy(displacement, self.bearing, energy_constants)

    def characteristic_load(self, constants, energy_constants):
        return ball_equilibrium.characteristic_load(self.bearing, self.model, constants)

    def pitch_radius(self):
        return 0.5 * self.bearing.pitch_diameter

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Each ball's inner and outer contact (`ball_equilibrium.ball_results`)."""
        return contact_loads(ball_equilibrium.ball_results(displacement, self.bearing, self._operating(speed),
                                                           self.model, elements, constants))

    def dynamic_load_rating(self):
        """The bearing's own C_r where given, else ISO 281's (`life.ball_load_rating`)."""
        return life.ball_load_rating(self.bearing)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """Q_ci, Q_ce [N] (ISO/TS 16281 eqs. (19)–(20), `life.raceway_ratings`)."""
        return jnp.stack(life.raceway_ratings(self.bearing, rating))

    def equivalent_dynamic_load(self, force):
        """ISO 281 P, single row (`life.equivalent_dynamic_load`)."""
        return life.equivalent_dynamic_load(self.bearing, force)

    def static_load_rating(self):
        """ISO 76 C₀r at the nominal contact angle (`static_safety.ball_bearing_static_load_rating`)."""
        return static_safety.ball_bearing_static_load_rating(self.bearing)

    def equivalent_static_load(self, force):
        """ISO 76 P₀r, single row (`static_safety.ball_bearing_equivalent_static_load`)."""
        return static_safety.ball_bearing_equivalent_static_load(self.bearing, force)

    def pressure_safety(self, max_pressure):
        """(4 200 MPa / p_max)³."""
        return static_safety.pressure_safety(max_pressure, static_safety.BALL_PRESSURE_LIMIT,
                                             static_safety.POINT_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "ball"

    def hybrid(self) -> bool:
        """Silicon nitride balls (the material's static name)."""
        return self.bearing.ball_material is not None and self.bearing.ball_material.name == SILICON_NITRIDE.name

    def friction_kind(self, model: str) -> str | None:
        """Its own kind (deep groove or angular contact) in both friction models."""
        return self.bearing.kind

    def nominal_contact_angle(self):
        return self.bearing.nominal_contact_angle

    def ring_section(self) -> RingSection:
        """The groove bottoms d_m ∓ D_w, the ball, the rings' material, G_r (`params.radial_clearance`)."""
        pitch, ball = self.bearing.pitch_diameter, self.bearing.ball_diameter
        return RingSection(pitch - ball, pitch + ball, ball, self.bearing.ring_material, radial_clearance(self.bearing))

    def with_clearance_change(self, change) -> "BallSupport":
        """`params.clearance_changed`: the groove centres moved, the free contact angle kept."""
        return eqx.tree_at(lambda support: support.bearing, self, clearance_changed(self.bearing, change))

    def envelope(self, contacts: ContactLoads):
        """`ball_validity`: the largest approach / D_w, the largest loaded |α|, and an angular-contact
        bearing's lowest loaded α (its low shoulder lies at α < 0; +π/2 for a deep-groove one)."""
        (inner_load, outer_load), (inner_angle, outer_angle) = contacts.load.T, contacts.angle.T
        lowest = ball_validity.low_shoulder_angle(self.bearing, inner_load, inner_angle, outer_load, outer_angle)
        return jnp.stack([ball_validity.largest_approach_ratio(*contacts.approach.T, self.bearing.ball_diameter),
                          ball_validity.largest_contact_angle(inner_angle, outer_angle, inner_load, outer_load),
                          lowest])

    def frequencies(self, speed, contacts: ContactLoads):
        """`overrolling.frequencies_of_balls` at the balls' solved angles and inner loads."""
        return overrolling.frequencies_of_balls(self.bearing, speed, 0.0, contacts.angle[:, 0], contacts.angle[:, 1],
                                                contacts.load[:, 0], self.model.race_control)

    def reference_offset(self):
        if self.bearing.kind == "deep_groove_ball":
            return -groove_curvature_centre_distance(self.bearing) * jnp.sin(self.bearing.free_contact_angle)
        return 0.0

    def carries_elements(self) -> bool:
        return self.model.speed_effects

    def start_elements(self, displacement, speed, constants):
        return ball_equilibrium.start_positions(displacement, self.bearing, self._operating(speed), self.model,
                                                constants)

    def condensed(self, displacement, elements, speed, constants) -> CondensedElements:
        found = ball_equilibrium.condensed_balls(displacement, elements, self.bearing, self._operating(speed),
                                                 self.model, constants)
        return CondensedElements(found.condensed_force, found.condensed_stiffness, found.ball_correction,
                                 found.ball_coupling)

    def limit_element_step(self, step):
        return ball_equilibrium.limited_ball_step(self.bearing, step)

    def element_tolerance(self):
        return ball_equilibrium.BALL_POSITION_TOLERANCE * self.bearing.ball_diameter

    def element_residual(self, displacement, elements, speed, constants, load_scale):
        """Each ball's own balance, as one bearing's solve checks it (`relative_ball_residual`)."""
        operating = self._operating(speed)
        grooves = ball_equilibrium.inner_groove_centres(self.bearing, displacement)
        state = ball_equilibrium.ball_state(self.bearing, operating, grooves, elements, self.model, table=constants)
        return ball_equilibrium.relative_ball_residual(self.bearing, operating, grooves, state, self.model, load_scale)


def contact_loads(balls: BallResults) -> ContactLoads:
    """A ball bearing's per-ball results as its `ContactLoads`: two point contacts a ball, inner then outer."""
    def pair(inner, outer):
        return jnp.stack([inner, outer], axis=-1)

    load = pair(balls.inner_load, balls.outer_load)
    return ContactLoads(balls.azimuth, load, load[..., None], pair(balls.inner_max_pressure, balls.outer_max_pressure),
                        pair(balls.inner_contact_angle, balls.outer_contact_angle),
                        pair(balls.inner_approach, balls.outer_approach), ("inner", "outer"), "point")
