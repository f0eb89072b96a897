"""A double-row angular-contact ball bearing: two rows of balls between one solid inner ring and
one solid outer ring, as `AbstractSupport`.

Row r (r = 1, 2) is the single-row ball model (`ball_equilibrium`, one row's geometry `bearing`)
with its reference plane (its plane of inner groove centres) at z_r = ∓a/2 from the bearing's
centre, a the row spacing. In O arrangement (back to back) the rows' lines of contact diverge
away from the bearing (row 1 faces +z, row 2 is turned, −z); in X arrangement (face to face) they
converge (row 1 turned, row 2 facing +z: a self-aligning bearing's rows, `self_aligning`). The
rigid inner ring's displacement Δ about the bearing's centre moves row r's inner ring by

    Δ_r = P_r G(z_r) Δ + e ẑ,        F(Δ) = Σ_r G(z_r)ᵀ P_r F_row(Δ_r)

(G, P as for a shaft's bearings, bearings/interface.py), with e = −s_a/2 from the bearing's axial
clearance s_a [m] (each row backed off by half; negative: preloaded): the bearing is the pair of
its rows (back to back or face to face) with the offset e and no spacer, its rows sharing one
table of Hertz constants. With speed effects both rows' balls are carried as unknowns, stacked
(2, Z, 2) [m], and condensed onto the ring row by row (M_r = P_r G(z_r) = dΔ_r/dΔ,
`support_move`): S = Σ_r M_rᵀ S_r M_r, the balls' coupling J_XX⁻¹ J_XΔ_r M_r.

Contacts: four columns a ball position, (row 1 inner, row 1 outer, row 2 inner, row 2 outer); the
turned row's ball at its own azimuth ψ sits at −ψ in the bearing's frame, so its balls are
re-indexed to the first row's azimuths. Its ISO/TS 16281 ratings per raceway are each row's
(`life.raceway_ratings` at the row's C_r = C_r / 2^0.7: ISO 281 eq. (2) with i = 2); ISO 76 rates
it with i = 2 and Table 2's double-row X₀ = 1, Y₀ (twice a single row's).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ...params import BallBearing, _as_float, check_range
from ...ratings import life, static_safety
from ..interface import (
    AbstractSupport,
    CondensedElements,
    ContactLoads,
    check_orientation,
    support_displacement,
    support_move,
)
from .ball_equilibrium import BallModel
from .ball_support import BallSupport

ROWS = 2
# each row's facing (+1: +z) by arrangement: back to back (O), row 1 at −a/2 faces +z and row 2 at
# +a/2 faces −z, their lines of contact diverging away from the bearing; face to face (X), turned
ROW_ORIENTATIONS = {"back_to_back": (1, -1), "face_to_face": (-1, 1)}


class DoubleRowSupport(AbstractSupport):
    """A double-row angular-contact ball bearing on the shaft: each row's geometry `bearing` (a
    single row's, its free contact angle α₀), the rows' reference planes `row_spacing` [m] apart
    (each row's plane of inner groove centres, its `BallSupport`'s z), its `axial_clearance` [m]
    (the inner ring's axial play between the rows' contacts at α₀; negative: preloaded), its rows
    back to back (O, `arrangement` "back_to_back") or face to face (X, "face_to_face"); placement
    as `BallSupport`."""

    bearing: BallBearing
    row_spacing: jax.Array = eqx.field(converter=_as_float)
    position: jax.Array = eqx.field(converter=_as_float)
    axial_clearance: jax.Array = eqx.field(converter=_as_float, default=0.0)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: BallModel = eqx.field(static=True, default=BallModel())
    orientation: int = eqx.field(static=True, default=1)
    arrangement: str = eqx.field(static=True, default="back_to_back")

    def __check_init__(self):
        check_orientation(self.orientation)
        if self.arrangement not in ROW_ORIENTATIONS:
            raise ValueError(f"arrangement must be one of {tuple(ROW_ORIENTATIONS)}, got {self.arrangement!r}")
        check_range("bearing.row_spacing", self.row_spacing, low=0.0, unit=" m")
        check_range("bearing.axial_clearance", self.axial_clearance, unit=" m")
        if self.bearing.kind != "angular_contact_ball":
            raise ValueError(f"bearing.type: the rows of a double-row angular-contact bearing are angular-contact "
                             f"rows, got {self.bearing.kind!r}")

    def rows(self) -> tuple[BallSupport, BallSupport]:
        """The two rows as single-row supports in the bearing's own frame (module docstring)."""
        half = 0.5 * self.row_spacing
        return tuple(BallSupport(self.bearing, side * half, -0.5 * self.axial_clearance, self.model, orientation)
                     for side, orientation in zip((-1.0, 1.0), ROW_ORIENTATIONS[self.arrangement]))

    def _row_displacements(self, displacement):
        return tuple(support_displacement(displacement, row) for row in self.rows())

    def _row_elements(self, elements):
        return (None,) * ROWS if elements is None else tuple(elements)

    def constants(self):
        return self.rows()[0].constants()

    def constants_key(self):
        return id(self.bearing), self.model

    def ring_force(self, displacement, speed, constants, elements=None):
        return sum(support_move(row).T @ row.ring_force(local, speed, constants, state) for row, local, state
                   in zip(self.rows(), self._row_displacements(displacement), self._row_elements(elements)))

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        return sum(support_move(row).T @ row.ring_stiffness(local, speed, constants, state) @ support_move(row)
                   for row, local, state in zip(self.rows(), self._row_displacements(displacement),
                                                self._row_elements(elements)))

    def energy_constants(self, constants):
        return self.rows()[0].energy_constants(constants)

    def static_energy(self, displacement, energy_constants):
        return sum(row.static_energy(local, energy_constants)
                   for row, local in zip(self.rows(), self._row_displacements(displacement)))

    def characteristic_load(self, constants, energy_constants):
        return ROWS * self.rows()[0].characteristic_load(constants, energy_constants)

    def pitch_radius(self):
        return 0.5 * self.bearing.pitch_diameter

    def carries_elements(self) -> bool:
        return self.model.speed_effects

    def start_elements(self, displacement, speed, constants):
        return jnp.stack([row.start_elements(local, speed, constants)
                          for row, local in zip(self.rows(), self._row_displacements(displacement))])

    def condensed(self, displacement, elements, speed, constants) -> CondensedElements:
        parts = [(support_move(row), row.condensed(local, state, speed, constants)) for row, local, state
                 in zip(self.rows(), self._row_displacements(displacement), elements)]
        return CondensedElements(sum(move.T @ found.force for move, found in parts),
                                 sum(move.T @ found.stiffness @ move for move, found in parts),
                                 jnp.stack([found.correction for _, found in parts]),
                                 jnp.stack([found.coupling @ move for move, found in parts]))

    def limit_element_step(self, step):
        return self.rows()[0].limit_element_step(step)

    def element_tolerance(self):
        return self.rows()[0].element_tolerance()

    def element_residual(self, displacement, elements, speed, constants, load_scale):
        return jnp.max(jnp.stack([row.element_residual(local, state, speed, constants, load_scale) for row, local, state
                                  in zip(self.rows(), self._row_displacements(displacement), elements)]))

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Four point contacts a ball position (module docstring), azimuths row 1's."""
        found = [row.contacts(local, speed, constants, state) for row, local, state
                 in zip(self.rows(), self._row_displacements(displacement), self._row_elements(elements))]
        count = self.bearing.ball_count
        order = [np.arange(count) if row.orientation > 0 else (-np.arange(count)) % count for row in self.rows()]

        def columns(field):
            return jnp.concatenate([getattr(own, field)[index] for own, index in zip(found, order)], axis=1)

        return ContactLoads(found[0].azimuth, columns("load"), columns("lamina_load"), columns("max_pressure"),
                            columns("angle"), columns("approach"), found[0].raceways * ROWS, "point")

    def dynamic_load_rating(self):
        """`two_row_dynamic_load_rating`."""
        return two_row_dynamic_load_rating(self.bearing)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """Each row's Q_ci, Q_ce at its own C_r, in the contacts' column order (`two_row_contact_ratings`)."""
        return two_row_contact_ratings(self.bearing, rating)

    def equivalent_dynamic_load(self, force):
        """ISO 281 P, Table 3's double-row column (`life.equivalent_dynamic_load`, double row)."""
        return life.equivalent_dynamic_load(self.bearing, force, double_row=True)

    def static_load_rating(self):
        """`two_row_static_load_rating`."""
        return two_row_static_load_rating(self.bearing)

    def equivalent_static_load(self, force):
        """ISO 76 P₀r = F_r + Y₀ F_a, Table 2's double-row column (`double_row_equivalent_static_load`)."""
        return static_safety.double_row_equivalent_static_load(force, self.bearing.nominal_contact_angle)

    def pressure_safety(self, max_pressure):
        return self.rows()[0].pressure_safety(max_pressure)

    def rolling_element(self) -> str:
        return "ball"

    def hybrid(self) -> bool:
        return self.rows()[0].hybrid()

    def friction_kind(self, model: str) -> str | None:
        """SKF's model only (its angular-contact "double_row" series); Palmgren's tables hold no
        double-row row."""
        return self.bearing.kind if model == "skf" else None

    def friction_series(self) -> str | None:
        return "double_row"

    def nominal_contact_angle(self):
        return self.bearing.nominal_contact_angle

    def envelope(self, contacts: ContactLoads):
        """The rows' `BallSupport.envelope`, the worst of the two."""
        rows = [self.rows()[0].envelope(_row_columns(contacts, row)) for row in range(ROWS)]
        largest = jnp.maximum(rows[0], rows[1])
        return largest.at[2].set(jnp.minimum(rows[0][2], rows[1][2]))

    def frequencies(self, speed, contacts: ContactLoads):
        """The more loaded row's (its inner loads' sum the larger), at its solved angles."""
        found = [self.rows()[0].frequencies(speed, _row_columns(contacts, row)) for row in range(ROWS)]
        first = jnp.sum(contacts.load[:, 0]) >= jnp.sum(contacts.load[:, 2])
        return jax.tree.map(lambda one, two: jnp.where(first, one, two), *found)


def two_row_dynamic_load_rating(bearing: BallBearing):
    """C_r [N] of a bearing of two rows of `bearing`'s balls: `bearing.dynamic_load_rating` where
    given (the whole bearing's, as a catalogue gives it), else ISO 281 eq. (2) with i = 2 rows,
    2^0.7 × one row's."""
    if bearing.dynamic_load_rating is not None:
        return bearing.dynamic_load_rating
    return ROWS**0.7 * life.basic_dynamic_load_rating(bearing)


def two_row_contact_ratings(bearing: BallBearing, rating):
    """(4,) [N] each row's Q_ci, Q_ce (ISO/TS 16281 eqs. (19)–(20)) at its own C_r = C_r / 2^0.7,
    columns (inner, outer) row by row."""
    return jnp.tile(jnp.stack(life.raceway_ratings(bearing, rating / ROWS**0.7)), ROWS)


def two_row_static_load_rating(bearing: BallBearing):
    """ISO 76 C₀r [N] with i = 2 rows at the nominal contact angle (`static_safety.ball_static_load_rating`)."""
    return static_safety.ball_static_load_rating(bearing.ball_count, bearing.ball_diameter, bearing.pitch_diameter,
                                                 bearing.nominal_contact_angle, rows=ROWS)


def _row_columns(contacts: ContactLoads, row: int) -> ContactLoads:
    """Row `row`'s two columns of the bearing's contacts, as a single row's."""
    pick = slice(2 * row, 2 * row + 2)
    return ContactLoads(contacts.azimuth, contacts.load[:, pick], contacts.lamina_load[:, pick],
                        contacts.max_pressure[:, pick], contacts.angle[:, pick], contacts.approach[:, pick],
                        contacts.raceways[pick], contacts.kind)
