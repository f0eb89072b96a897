"""A four-point-contact ball bearing (split inner ring, gothic-arch grooves; slewing rings), as
`AbstractSupport`: each ball touches up to two inner and two outer raceway halves, each contact
opening and closing on its own.

Geometry (docs/theory.md §Four-point contact). In the plane of ball j (azimuth ψ_j), axial
coordinate first and radial (outward) second, the origin at the ball's nominal centre (pitch
radius d_m/2, the bearing's mid-plane), ρ_i = (f_i − ½) D_w, ρ_o = (f_o − ½) D_w and the arches'
angle α₀ (each half's contact angle when the rings are concentric without clearance):

    outer halves' curvature centres (fixed)   O_1 = (−ρ_o sin α₀, −ρ_o cos α₀),  O_2 = (+ρ_o sin α₀, −ρ_o cos α₀)
    inner halves' curvature centres            I_k = (z_k, ρ_i cos α₀ − G_r/2) + (w_k, v_k),  z_1,2 = ±ρ_i sin α₀
    w_k = δz + R (θx sin ψ − θy cos ψ),   v_k = δx cos ψ + δy sin ψ + z_k (θy cos ψ − θx sin ψ)

with R = d_m/2 + ρ_i cos α₀ − G_r/2 the inner centres' radius and G_r the diametral radial
clearance (the inner arch drawn in by G_r/2: at G_r = 0 a centred ball touches all four halves at
α₀; negative: preloaded). (w_k, v_k) is the rigid ring's small motion δ + θ × r of the point
r = z_k ẑ + R e_r. Contact k (columns inner 1, outer 1, inner 2, outer 2; pairs 1 and 2 the
bearing's two diagonals, O_1–I_1 at +α and O_2–I_2 at −α) of a ball centred at X:

    δ_k = |C_k − X| − ρ_k,   Q_k = K(α_k) max(δ_k, 0)^{3/2},   force on the ball Q_k (C_k − X)/|C_k − X|
    α_k = atan2 of (C_k − X) for an inner half, of (X − C_k) for an outer one (pair 1 positive)

Each ball's balance Σ_k Q_k u_k = 0 has two unknowns X (its position); with no speed effects (the
model is static: slewing rings and the low speeds four-point bearings run at) they are found per
ball by minimising the convex energy Σ_k (2/5) K_k(α₀) max(δ_k, 0)^{5/2} + (ε/2) |X − X_ref|²
(`newton.minimise_convex`), then by Newton on the exact balance with K(α) at the contacts'
angles (held within a step, as `ball_equilibrium` does). ε = 10⁻¹⁴ K_n √D_w [N/m] makes a ball
that touches nothing (in the clearance) sit at the nearest free point to X_ref = (0, −G_r/4) and
keeps every 2×2 block regular; in a loaded ball it moves the balance by ε |X − X_ref| (ε =
1.5·10⁻⁵ N/m for the 15 mm balls of tests/test_four_point.py: 1.5·10⁻⁹ N at 100 µm). Their
derivative is the implicit one, ball by ball (`newton.implicit_root`). The ring's load is what
the inner halves exert on the balls,

    F = Σ_j Σ_{k inner} L_kᵀ Q_k u_k   ([Fz, Fr] at the point (z_k, R): M_t = z_k F_r − R F_z along e_t),

so with the Hertz constants held at α₀ it is the gradient of the balls' energy and the stiffness
is symmetric. The start of a system's solve is each diagonal's energy as an angular-contact row's,
Σ (2/5) K_n max(|I_k − O_k| − (f_i + f_o − 1) D_w, 0)^{5/2} (exact while each ball touches one
diagonal). A solved state is inside the model while every loaded contact lies on its own half,
0 < ±α_k < 90° (`envelope`'s lowest entry: a negative one is a contact past the groove's bottom).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ... import overrolling
from ...contact import hertz
from ...newton import implicit_root, minimise_convex, newton
from ...numerics import positive_power
from ...params import BallBearing, _as_float, _is_concrete, check_range, groove_curvature_centre_distance
from ...ratings import life, static_safety
from ..interface import AbstractSupport, ContactLoads, check_orientation
from . import ball_equilibrium
from .ball_equilibrium import DISPLACEMENT_SCALE, BallModel
from .double_row import two_row_contact_ratings, two_row_dynamic_load_rating, two_row_static_load_rating
from .raceway_contact import ball_raceway_modulus, both_curvatures

RACEWAYS = ("inner", "outer", "inner", "outer")  # the contact columns: pair 1 (inner, outer), pair 2
INNER_COLUMNS = (0, 2)
OWN_SIDE = np.array([1.0, 1.0, -1.0, -1.0])  # the sign of a contact angle on its own half
TOWARD_CONTACT = np.array([1.0, -1.0, 1.0, -1.0])  # α from C − X (inner) or X − C (outer)
REGULARISATION = 1e-14  # ε / (K_n √D_w): the weight of a free ball's reference point
BALL_NEWTON_STEPS = 20  # exact-balance Newton steps after the convex start (they stop early)


class FourPointSupport(AbstractSupport):
    """A four-point-contact ball bearing on a shaft: the arches' geometry `bearing` (ball size and
    count, pitch diameter, groove ratios, the arches' angle α₀ as its free contact angle), its
    diametral `radial_clearance` G_r [m] (negative: preloaded); placement as `BallSupport`. The
    model is static (`model` with no speed effects)."""

    bearing: BallBearing
    position: jax.Array = eqx.field(converter=_as_float)
    radial_clearance: jax.Array = eqx.field(converter=_as_float, default=0.0)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: BallModel = eqx.field(static=True, default=BallModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        check_orientation(self.orientation)
        if self.model.speed_effects:
            raise ValueError("effects.centrifugal, effects.gyroscopic: the four-point-contact model is static "
                             "(no speed effects on its balls)")
        if self.bearing.kind != "angular_contact_ball":
            raise ValueError(f"bearing.type: a four-point bearing's arches are given as an angular-contact geometry, "
                             f"got {self.bearing.kind!r}")
        if _is_concrete(self.bearing.ball_diameter, self.bearing.inner_groove_ratio, self.bearing.outer_groove_ratio,
                        self.bearing.free_contact_angle):
            distance = float(groove_curvature_centre_distance(self.bearing))
            cosine = float(np.cos(self.bearing.free_contact_angle))
            check_range("bearing.radial_clearance", self.radial_clearance, low=-2.0 * distance * (1.0 - cosine),
                        high=2.0 * distance * cosine, low_open=False, unit=" m",
                        why="−2(1 − cos α₀)·B·D_w to 2 cos α₀·B·D_w, B = f_i + f_o − 1: a diagonal touching "
                            "within 0°–90°")

    # --- geometry and the balls' balance ---------------------------------------------------------

    def raceway_radii(self):
        """(4,) ρ_k [m]: each column's groove radius less the ball radius."""
        inner, outer = ((ratio - 0.5) * self.bearing.ball_diameter
                        for ratio in (self.bearing.inner_groove_ratio, self.bearing.outer_groove_ratio))
        return jnp.stack([inner, outer, inner, outer])

    def inner_centre_radius(self):
        """R = d_m/2 + ρ_i cos α₀ − G_r/2 [m]: the inner halves' curvature centres' radius."""
        return (0.5 * self.bearing.pitch_diameter + self.raceway_radii()[0] * jnp.cos(self.bearing.free_contact_angle)
                - 0.5 * self.radial_clearance)

    def groove_centres(self, displacement):
        """(Z, 4, 2) curvature centres C_k (axial, radial) [m] of each ball's four contacts (module
        docstring), the inner ring at Δ `displacement`."""
        bearing = self.bearing
        psi = ball_equilibrium.ball_azimuths(bearing)
        sin_psi, cos_psi = np.sin(psi), np.cos(psi)
        sin_a, cos_a = jnp.sin(bearing.free_contact_angle), jnp.cos(bearing.free_contact_angle)
        inner, outer = self.raceway_radii()[:2]
        dx, dy, dz, tx, ty = (displacement[i] for i in range(5))
        arm = self.inner_centre_radius()
        axial_move = dz + arm * (tx * sin_psi - ty * cos_psi)

        def inner_centre(side):
            height = side * inner * sin_a
            radial = (inner * cos_a - 0.5 * self.radial_clearance + dx * cos_psi + dy * sin_psi
                      + height * (ty * cos_psi - tx * sin_psi))
            return jnp.stack([height + axial_move, radial], axis=-1)

        def outer_centre(side):
            return jnp.broadcast_to(jnp.stack([-side * outer * sin_a, -outer * cos_a]), (bearing.ball_count, 2))

        return jnp.stack([inner_centre(1.0), outer_centre(1.0), inner_centre(-1.0), outer_centre(-1.0)], axis=1)

    def free_reference(self):
        """X_ref = (0, −G_r/4) [m]: where a ball that touches nothing is held (module docstring)."""
        return jnp.stack([jnp.zeros(()), -0.25 * self.radial_clearance])

    def regularisation(self, constants):
        """ε [N/m] (module docstring)."""
        return REGULARISATION * self.energy_constants(constants) * jnp.sqrt(self.bearing.ball_diameter)

    def contact_geometry(self, positions, centres):
        """(approach δ (Z, 4) [m], angle α (Z, 4) [rad], unit u (Z, 4, 2) from the ball towards C_k)."""
        to_centre = centres - positions[:, None, :]
        distance = jnp.linalg.norm(to_centre, axis=-1)
        angle = jnp.arctan2(TOWARD_CONTACT * to_centre[..., 0], TOWARD_CONTACT * to_centre[..., 1])
        return distance - self.raceway_radii(), angle, to_centre / distance[..., None]

    def hertz_constants(self, angle, constants):
        """(Z, 4) K_k [N/m^1.5] at the contacts' angles (or α₀, `model.hertz_constants`)."""
        return _columns(*ball_equilibrium.hertz_constants(self.bearing, angle[:, 0::2], angle[:, 1::2], self.model,
                                                          constants))

    def ball_forces(self, positions, centres, constants, held=None):
        """(Z, 4, 2) the force of each contact on its ball [N], the Hertz constants `held` (Z, 4)
        where given (a Newton step holds them), else at the contacts' angles."""
        approach, angle, unit = self.contact_geometry(positions, centres)
        if held is None:
            held = self.hertz_constants(angle, constants)
        return hertz.hertz_load(approach, held)[..., None] * unit

    def ball_residual(self, positions, args):
        """(Z, 2) [N] each ball's balance Σ_k Q_k u_k + ε (X_ref − X); args = (centres, constants,
        hertz constants held or None)."""
        centres, constants, held = args
        return (jnp.sum(self.ball_forces(positions, centres, constants, held), axis=1)
                + self.regularisation(constants) * (self.free_reference() - positions))

    def _ball_energy(self, scaled, args):
        """One ball's energy [J] over the load scale × 10 µm with K at α₀, X = 10 µm × `scaled`."""
        centres, fixed, weight, scale = args
        position = DISPLACEMENT_SCALE * scaled
        approach = jnp.linalg.norm(centres - position, axis=-1) - self.raceway_radii()
        energy = (0.4 * jnp.sum(fixed * positive_power(approach, 2.5))
                  + 0.5 * weight * jnp.sum((position - self.free_reference()) ** 2))
        return energy / scale

    def _solve_balls(self, start, centres, constants):
        """Each ball's convex start (`minimise_convex`, K at α₀), then Newton on the exact balance."""
        alpha = jnp.full(centres.shape[:2], self.bearing.free_contact_angle)
        fixed = self.hertz_constants(alpha, constants)
        energy_args = (fixed, self.regularisation(constants),
                       self.characteristic_load(constants, self.energy_constants(constants)) * DISPLACEMENT_SCALE)

        def minimum(centre, fixed_ball, first):
            found, _ = minimise_convex(self._ball_energy, first / DISPLACEMENT_SCALE,
                                       (centre, fixed_ball) + energy_args[1:], gradient_tolerance=1e-13)
            return found * DISPLACEMENT_SCALE

        positions = jax.vmap(minimum)(centres, energy_args[0], start)
        if self.model.hertz_constants == "free_contact_angle":
            return positions

        def step(positions, _):
            held = self.hertz_constants(self.contact_geometry(positions, centres)[1], constants)
            return -jnp.linalg.solve(self._ball_blocks(positions, (centres, constants, held)),
                                     self.ball_residual(positions, (centres, constants, held))[..., None])[..., 0]

        return newton(None, positions, None, max_steps=BALL_NEWTON_STEPS, loop="while", linear_step=step,
                      line_search=False, step_tolerance=(ball_equilibrium.BALL_POSITION_TOLERANCE
                                                         * self.bearing.ball_diameter, 0.0))[0]

    def _ball_blocks(self, positions, args):
        """(Z, 2, 2) each ball's Jacobian of its balance (ball j's depends on X_j alone)."""
        def one(position, centre, held):
            return jax.jacfwd(lambda x: self.ball_residual(x[None], (centre[None], args[1],
                                                                     None if held is None else held[None]))[0])(position)

        return jax.vmap(one, in_axes=(0, 0, None if args[2] is None else 0))(positions, args[0], args[2])

    def ball_positions(self, displacement, constants):
        """(Z, 2) ball centres [m] in balance at Δ, with their implicit derivative (module docstring)."""
        centres = self.groove_centres(displacement)
        start = jnp.broadcast_to(jax.lax.stop_gradient(self.free_reference()), (self.bearing.ball_count, 2))

        centres_fixed = jax.lax.stop_gradient(centres)
        constants_fixed = jax.lax.stop_gradient(constants)
        solution = jax.lax.stop_gradient(self._solve_balls(start, centres_fixed, constants_fixed))
        return implicit_root(self.ball_residual, solution, (centres, constants, None),
                             lambda residual, guess, args: guess, ball_equilibrium.ball_tangent_solve)

    def _ring_force_of_balls(self, positions, centres, constants):
        """[Fx, Fy, Fz, Mx, My] [N, N·m] the inner halves exert on the balls (module docstring)."""
        psi = ball_equilibrium.ball_azimuths(self.bearing)
        sin_psi, cos_psi = np.sin(psi), np.cos(psi)
        forces = self.ball_forces(positions, centres, constants)[:, INNER_COLUMNS, :]  # (Z, 2, 2)
        heights = jnp.stack([1.0, -1.0]) * self.raceway_radii()[0] * jnp.sin(self.bearing.free_contact_angle)
        axial, radial = jnp.sum(forces[..., 0], axis=1), jnp.sum(forces[..., 1], axis=1)
        tangential_moment = jnp.sum(heights * forces[..., 1], axis=1) - self.inner_centre_radius() * axial
        return jnp.stack([jnp.sum(radial * cos_psi), jnp.sum(radial * sin_psi), jnp.sum(axial),
                          -jnp.sum(tangential_moment * sin_psi), jnp.sum(tangential_moment * cos_psi)])

    # --- AbstractSupport -------------------------------------------------------------------------

    def balance_residual(self, displacement, speed, constants, load_scale):
        """The largest ball's force balance (`ball_residual`, exact Hertz constants) at its solved
        position over `load_scale` [-]: a ball solve stopped short shows here."""
        positions = self.ball_positions(displacement, constants)
        residual = self.ball_residual(positions, (self.groove_centres(displacement), constants, None))
        return jnp.max(jnp.abs(residual)) / load_scale

    def constants(self):
        """The table of Hertz constants (`ball_equilibrium.constant_table`; None held at α₀)."""
        return ball_equilibrium.constant_table(self.bearing, self.model)

    def constants_key(self):
        return id(self.bearing), self.model

    def ring_force(self, displacement, speed, constants, elements=None):
        """The ring's load at Δ (the model is static: `speed` only turns the balls)."""
        positions = self.ball_positions(displacement, constants)
        return self._ring_force_of_balls(positions, self.groove_centres(displacement), constants)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """dF/dΔ, the balls re-balanced (forward mode through their implicit derivative)."""
        return jax.jacfwd(lambda d: self.ring_force(d, speed, constants))(displacement)

    def energy_constants(self, constants):
        """K_n(α₀) [N/m^1.5], an inner and an outer contact in series at the arches' angle."""
        return ball_equilibrium.free_contact_constant(self.bearing, self.model, constants)

    def static_energy(self, displacement, energy_constants):
        """Σ_j over both diagonals (2/5) K_n max(|I_k − O_k| − B D_w, 0)^{5/2} [J] (module docstring)."""
        centres = self.groove_centres(displacement)
        lengths = jnp.linalg.norm(centres[:, 0::2, :] - centres[:, 1::2, :], axis=-1)
        approach = lengths - groove_curvature_centre_distance(self.bearing)
        return 0.4 * energy_constants * jnp.sum(positive_power(approach, 2.5))

    def characteristic_load(self, constants, energy_constants):
        """K_n (10 µm)^{3/2} [N]."""
        return energy_constants * DISPLACEMENT_SCALE**1.5

    def pitch_radius(self):
        return 0.5 * self.bearing.pitch_diameter

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Four point contacts a ball (columns `RACEWAYS`), their Hertz pressures."""
        centres = self.groove_centres(displacement)
        positions = self.ball_positions(displacement, constants)
        approach, angle, _ = self.contact_geometry(positions, centres)
        load = hertz.hertz_load(approach, self.hertz_constants(angle, constants))
        sums, differences = both_curvatures(self.bearing, angle[:, 0::2], angle[:, 1::2])
        found = hertz.point_contact(jnp.stack([load[:, 0::2], load[:, 1::2]]), sums, differences,
                                    ball_raceway_modulus(self.bearing), self.model.hertz_method)
        return ContactLoads(jnp.asarray(ball_equilibrium.ball_azimuths(self.bearing)), load, load[..., None],
                            _columns(*found.max_pressure), angle, approach, RACEWAYS, "point")

    def dynamic_load_rating(self):
        """As a double-row angular-contact bearing at α₀ (`double_row.two_row_dynamic_load_rating`,
        i = 2: its two diagonals; the catalogues' P = X F_r + Y F_a of a four-point bearing are ISO
        281 Table 3's double-row row at 35°)."""
        return two_row_dynamic_load_rating(self.bearing)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """Each diagonal's Q_ci, Q_ce [N] at its own C_r = C_r / 2^0.7 (`double_row.two_row_contact_ratings`):
        under a pure axial load, the life of the diagonal that carries it is a single row's."""
        return two_row_contact_ratings(self.bearing, rating)

    def static_load_rating(self):
        """ISO 76 C₀r with i = 2 at α₀ (`double_row.two_row_static_load_rating`; the catalogues' P₀
        = F_r + 0.58 F_a at 35° is ISO 76 Table 2's double-row row)."""
        return two_row_static_load_rating(self.bearing)

    def equivalent_dynamic_load(self, force):
        """ISO 281 P of Table 3's double-row column at α₀ (the catalogues' QJ factors, X = 1, Y = 0.66
        and X = 0.6, Y = 1.07 beyond e = 0.95 at 35°; `life.equivalent_dynamic_load`, double row)."""
        return life.equivalent_dynamic_load(self.bearing, force, double_row=True)

    def equivalent_static_load(self, force):
        """P₀r = F_r + Y₀ F_a with ISO 76 Table 2's double-row Y₀ at α₀ (its two diagonals carry
        either axial direction; `static_safety.double_row_equivalent_static_load`)."""
        return static_safety.double_row_equivalent_static_load(force, self.bearing.free_contact_angle)

    def pressure_safety(self, max_pressure):
        """(4 200 MPa / p_max)³."""
        return static_safety.pressure_safety(max_pressure, static_safety.BALL_PRESSURE_LIMIT,
                                             static_safety.POINT_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "ball"

    def friction_kind(self, model: str) -> str | None:
        """SKF's model only (its angular-contact "four_point" series)."""
        return self.bearing.kind if model == "skf" else None

    def friction_series(self) -> str | None:
        return "four_point"

    def nominal_contact_angle(self):
        return self.bearing.free_contact_angle

    def envelope(self, contacts: ContactLoads):
        """The largest approach / D_w, the largest loaded |α| and the lowest loaded angle on its own
        half, ±α_k (negative: past the groove's bottom)."""
        loaded = contacts.load > 0.0
        own = jnp.where(loaded, OWN_SIDE * contacts.angle, 0.5 * jnp.pi)
        return jnp.stack([jnp.max(contacts.approach) / self.bearing.ball_diameter,
                          jnp.max(jnp.where(loaded, jnp.abs(contacts.angle), 0.0)), jnp.min(own)])

    def frequencies(self, speed, contacts: ContactLoads):
        """`overrolling.frequencies_of_balls` at each ball's more loaded diagonal's angles."""
        first = contacts.load[:, 0] >= contacts.load[:, 2]
        inner = jnp.abs(jnp.where(first, contacts.angle[:, 0], contacts.angle[:, 2]))
        outer = jnp.abs(jnp.where(first, contacts.angle[:, 1], contacts.angle[:, 3]))
        return overrolling.frequencies_of_balls(self.bearing, speed, 0.0, inner, outer,
                                                contacts.load[:, 0] + contacts.load[:, 2], self.model.race_control)


def _columns(inner, outer):
    """(Z, 4) in the column order `RACEWAYS` from the inner and the outer halves' (Z, 2), pair by pair."""
    return jnp.stack([inner, outer], axis=-1).reshape(inner.shape[0], 4)


def axial_clearance(support: FourPointSupport):
    """The inner ring's axial play [m] between closing one diagonal and the other, the balls free
    and the rings concentric: 2 (√((B D_w)² − (B D_w cos α₀ − G_r/2)²) − B D_w sin α₀)."""
    distance = groove_curvature_centre_distance(support.bearing)
    angle = support.bearing.free_contact_angle
    radial = distance * jnp.cos(angle) - 0.5 * support.radial_clearance
    return 2.0 * (jnp.sqrt(distance**2 - radial**2) - distance * jnp.sin(angle))
