"""Quasi-static 5-DOF ball bearing: load distribution, contact angles and stiffness at speed.

Model (docs/theory.md §Ball equilibrium, the stiffness paper; Jones 1960, Harris & Kotzalas vol. 2 ch. 3). The outer ring is
fixed; the inner ring moves by Δ = [δx, δy, δz, θx, θy] from the position where the rings are
concentric and every ball just touches both raceways at the free contact angle α₀. In the plane of
ball j (azimuth ψ_j from +x), with the outer groove curvature centre as origin, axial coordinate
first and radial (outward) second:

    inner groove curvature centre  A = (B D_w sin α₀ + δz + R_i (θx sin ψ − θy cos ψ),
                                        B D_w cos α₀ + ι/2 + δx cos ψ + δy sin ψ)
    B D_w = (f_i + f_o − 1) D_w,  R_i = d_m/2 + (f_i − 1/2) D_w cos α₀
    ball centre X:  δ_o = |X| − (f_o − ½)D_w,  δ_i = |A − X| − (f_i − ½)D_w
    tan α_o = X₁/X₂,  tan α_i = (A₁ − X₁)/(A₂ − X₂),  Q = K(α) max(δ, 0)^{3/2}  (Hertz, exact K(α))
    ring equilibrium: [Fx, Fy, Fz, Mx, My] = Σ_j (the forces the inner raceway exerts on ball j)

Ball j's force and moment balance (quasi-static, in the frame that orbits with the ball at ω_m).
Unit vectors at azimuth ψ: ẑ (axial), e_r = (cos ψ, sin ψ, 0) (radial, outward) and
e_t = ẑ × e_r (the direction of increasing ψ); a vector (a, r) of the ball's plane is a ẑ + r e_r.

    contact normals (ball centre to contact point)  n_o = (sin α_o, cos α_o),  −n_i = −(sin α_i, cos α_i)
    normal forces on the ball                       −Q_o n_o (outer raceway),  +Q_i n_i (inner raceway)
    centrifugal (inertial) force                    F_c e_r
    ball spin relative to the orbiting frame        ω_R (cos β ẑ − sin β e_r)   (`kinematics.ball_speeds`)
    rate of change of the ball's angular momentum   dL/dt = ω_m ẑ × (J ω_b) = −J ω_R ω_m sin β e_t = M_g e_t

The normal forces pass through the ball centre, so only friction can supply dL/dt. Raceway control
(Jones) puts all of it at the controlling contact, along its tangent t = (cos α, −sin α) in the
ball's plane. With the contact point at ± (D_w/2) n and n × t = −e_t:

    outer control, friction at (D_w/2) n_o:   (D_w/2) n_o × f t_o = M_g e_t  →  F_f = −(2 M_g/D_w) t_o
    inner control, friction at −(D_w/2) n_i:  −(D_w/2) n_i × f t_i = M_g e_t →  F_f = +(2 M_g/D_w) t_i

so under outer control the friction on the ball points radially outward and axially the way the
outer raceway's normal force pushes (for α_o > 0). ΣF = 0 gives the two scalar equations per ball:

    outer control:  Q_i sin α_i − Q_o sin α_o − (2 M_g/D_w) cos α_o = 0
                    Q_i cos α_i − Q_o cos α_o + (2 M_g/D_w) sin α_o + F_c = 0
    inner control:  Q_i sin α_i − Q_o sin α_o + (2 M_g/D_w) cos α_i = 0
                    Q_i cos α_i − Q_o cos α_o − (2 M_g/D_w) sin α_i + F_c = 0

Harris's λ-form (Harris & Kotzalas vol. 2, ch. 3; λ = 2 at the controlling raceway) is this
balance when its M_g carries the sign of J ω_R ω_m sin β, with ω_R negative as `ball_speeds`
returns it; written with |M_g| it reverses the friction. Under inner control the friction acts on
the inner ring too: it enters the ring forces, and its moment about the inner groove centre,
−(f_i D_w + δ_i) n_i × F_f = 2 M_g (f_i + δ_i/D_w) e_t, the ring moments (Harris's λ_i f_i M_g
term, which leaves out δ_i). `tests/test_ball_momentum_balance.py` rebuilds every ball in 3-D and
checks ΣF = 0 and Σ r × F = dL/dt.

Sign conventions: moments and rotations right-handed about x and y; an inner-ring rotation θx
moves the groove centre at azimuth ψ axially by R_i θx sin ψ. A deep-groove ball that is pushed the
other way takes a negative contact angle on the opposite shoulder; angular-contact bearings are
modelled with the same full groove (their low shoulder is not a separate limit).

Solution (docs/theory.md §Numerical notes): the ring problem starts from the static solution, found by minimising
the convex elastic energy Σ (2/5) K_n max(|A| − B D_w, 0)^{5/2} − F·Δ (no initial guess needed,
zero stiffness at the start is fine; `newton.minimise_convex`). Newton (`newton.newton`, full
steps) then adds the contact-angle dependence of the Hertz constants and the speed terms: without
speed effects on the 5 ring unknowns with the balls at the closed-form static split; with them on
the ring and ball unknowns together (5 + 2Z, the balls first solved per ball at the static ring
position by the same step with the ring held), each step through the 5×5 Schur complement of the
block-arrow Jacobian. Each step evaluates the Hertz constants once at the current contact angles
and holds them in the Jacobian (their angle dependence is weak); the residuals are exact. Each
solve evaluates the constants from a Chebyshev table of K(α) that it builds from the bearing
(`constant_table`) and passes down as `table`. The implicit derivative of the solution uses the exact linearisation
(`newton.implicit_root`, least squares on the 5×5 Jacobian of `ring_force`); with speed effects
ring and balls are one root (`_joint_residual`), differentiated as one: the balls eliminated
from its linearisation through the 5×5 Schur complement, which least squares solves
(`_joint_tangent_solve`), so the derivative's program holds one linearisation of the balls, not
a ring root's over each ball's. `ball_positions` solves the balls per ball (2×2 Newton steps) for a
given Δ and carries the implicit-function derivative dX = −(∂g/∂X)⁻¹ (∂g/∂(Δ, p)) dΔ
(`implicit_root`, block by block), so the ring force F(Δ) has exact total derivatives. The
stiffness K = dF/dΔ (balls re-equilibrated) is the Schur complement of one exact linearisation at
the balls' equilibrium (`stiffness_at_balls`): the same as `jax.jacfwd(ring_force)` to rounding, in
a smaller program. Given the solve's ball centres (`Equilibrium.ball_centres`), `ring_force`,
`stiffness_matrix` and `ball_results` take the balls as solved there and keep only their implicit
derivative (`solved_ball_positions`): a program holding the solve and its stiffness traces one ball
solve, not three; `stiffness_at_balls` takes the balls with their derivative
(`ball_results(...).centre`) and adds no second one.
"""

import dataclasses

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ...contact import hertz
from ...newton import guarded_solve, implicit_root, least_squares_tangent_solve, minimise_convex, newton
from ...numerics import positive_power, require_float64, safe_norm, without_gradient
from ...params import BallBearing, Operating, groove_curvature_centre_distance
from ..interface import RING_MAX_STEPS, RING_STEP_TOLERANCE, SPEED_STAGES
from . import ball_validity, kinematics
from .raceway_contact import (
    ContactConstantTable,
    ball_raceway_modulus,
    both_curvatures,
    contact_constant_table,
    contact_constants,
    table_constants,
)

BALL_NEWTON_MAX_STEPS = 40
BALL_POSITION_TOLERANCE = 1e-13  # × D_w: step size at which the per-ball Newton stops
FREE_APPROACH = 1e-12  # × D_w: below this total approach a ball at standstill is taken as free
DISPLACEMENT_SCALE = 1e-5  # m: the unit of the scaled ring unknowns (10 µm, 10 µm / R_i rad)
RESIDUAL_TOLERANCE = 1e-9  # converged when the scaled ring residual and ball residuals are below
# the speed continuation of the ring solve with speed effects and its ring tolerances, SPEED_STAGES,
# RING_STEP_TOLERANCE and RING_MAX_STEPS, are every joint solve's (bearings/interface.py)

# The static energy is only the start for Newton: a gradient of 1e-8 (scaled) is close enough, and
# the energy's rounding error stops Armijo's test from resolving much less.
STATIC_GRADIENT_TOLERANCE = 1e-8


@dataclasses.dataclass(frozen=True)
class BallModel:
    """Static model options: speed effects, raceway control, Hertz fidelity level."""

    centrifugal: bool = False
    gyroscopic: bool = False
    race_control: str = "outer"
    hertz_method: str = "exact"
    # "contact_angle": Hertz constants at each contact's current angle (Jones, Harris);
    # "free_contact_angle": fixed at α₀ (simpler codes; the static force field is then exactly
    # the gradient of an energy, so the stiffness at standstill is exactly symmetric).
    hertz_constants: str = "contact_angle"

    @property
    def speed_effects(self) -> bool:
        return self.centrifugal or self.gyroscopic


def ball_azimuths(bearing: BallBearing):
    """ψ_j = 2π j / Z [rad], ball 0 on +x: constants of the static ball count (NumPy), so a
    traced program holds them, and their sines and cosines (`_azimuth_directions`), as values
    rather than as operations in every trace of the geometry."""
    return 2.0 * np.pi * np.arange(bearing.ball_count) / bearing.ball_count


def _azimuth_directions(bearing: BallBearing):
    """(sin ψ_j, cos ψ_j), (Z,) each: constants (`ball_azimuths`)."""
    psi = ball_azimuths(bearing)
    return np.sin(psi), np.cos(psi)


def inner_groove_radius_of_centres(bearing: BallBearing):
    """R_i = d_m/2 + (f_i − ½) D_w cos α₀ [m], the moment arm of the inner contact forces."""
    return 0.5 * bearing.pitch_diameter + (bearing.inner_groove_ratio - 0.5) * bearing.ball_diameter * jnp.cos(
        bearing.free_contact_angle)


def inner_groove_centres(bearing: BallBearing, displacement):
    """(Z, 2) positions (axial, radial) of the inner groove curvature centres [m] (module docstring)."""
    sin_psi, cos_psi = _azimuth_directions(bearing)
    distance = groove_curvature_centre_distance(bearing)
    arm = inner_groove_radius_of_centres(bearing)
    dx, dy, dz, tx, ty = (displacement[i] for i in range(5))
    axial = distance * jnp.sin(bearing.free_contact_angle) + dz + arm * (tx * sin_psi - ty * cos_psi)
    radial = distance * jnp.cos(bearing.free_contact_angle) + 0.5 * bearing.interference + dx * cos_psi + dy * sin_psi
    return jnp.stack([axial, radial], axis=-1)


def hertz_constants(bearing: BallBearing, inner_angle, outer_angle, model: BallModel,
                    table: ContactConstantTable | None = None):
    """(K_i, K_o) [N/m^1.5] at the contact angles, or at α₀ (`model.hertz_constants`).

    From `table`, a Chebyshev table of K(α) (`constant_table`; the solvers build one per solve and
    pass it down), or, without one, each contact's constant solved exactly.
    """
    if model.hertz_constants == "free_contact_angle":
        angle = bearing.free_contact_angle
        return tuple(jnp.broadcast_to(k, jnp.shape(inner_angle))
                     for k in contact_constants(bearing, angle, angle, model.hertz_method))
    if table is not None:
        return table_constants(table, inner_angle, outer_angle)
    return contact_constants(bearing, inner_angle, outer_angle, model.hertz_method)


def constant_table(bearing: BallBearing, model: BallModel) -> ContactConstantTable | None:
    """A Chebyshev table of the bearing's Hertz constants K(α) at `model`'s fidelity level, or None
    where the model holds them at α₀ (`raceway_contact.contact_constant_table`)."""
    return contact_constant_table(bearing, model.hertz_method) if model.hertz_constants == "contact_angle" else None


def _groove_offsets(bearing: BallBearing):
    """((f_i − ½) D_w, (f_o − ½) D_w) [m]: ball-centre distance from each groove centre at zero load."""
    return ((bearing.inner_groove_ratio - 0.5) * bearing.ball_diameter,
            (bearing.outer_groove_ratio - 0.5) * bearing.ball_diameter)


def static_positions(bearing: BallBearing, centres, model: BallModel, constants=None, table=None):
    """(Z, 2) ball centres without speed effects: on the line of groove centres, the total approach
    split so that K_i δ_i^{3/2} = K_o δ_o^{3/2} (both contacts at the same angle).

    `constants` = (K_i, K_o) overrides the Hertz constants at the angle of the line of centres;
    otherwise they come from `table` (`hertz_constants`).
    """
    inner_offset, outer_offset = _groove_offsets(bearing)
    length = jnp.linalg.norm(centres, axis=-1)
    total = length - groove_curvature_centre_distance(bearing)
    if constants is None:
        constants = _static_constants(bearing, centres, model, table)
    k_inner, k_outer = constants
    outer_approach = total / (1.0 + (k_outer / k_inner) ** (2.0 / 3.0))
    return centres / length[..., None] * (outer_offset + outer_approach)[..., None]


def _static_constants(bearing: BallBearing, centres, model: BallModel, table=None):
    """(K_i, K_o) [N/m^1.5] at the angle of the line of groove centres, where both static contacts lie."""
    angle = jnp.arctan2(centres[..., 0], centres[..., 1])
    return hertz_constants(bearing, angle, angle, model, table)


def _static_split(bearing: BallBearing, operating: Operating, centres, model: BallModel, constants=None,
                  table=None):
    """(ball centres (Z, 2) [m], their `ball_state`) at the static split, with the Hertz constants
    evaluated once for both contacts (they lie on the line of groove centres, at the same angle)."""
    if constants is None:
        constants = _static_constants(bearing, centres, model, table)
    positions = static_positions(bearing, centres, model, constants)
    return positions, ball_state(bearing, operating, centres, positions, model, constants)


def _contact_angles(centres, positions):
    """(α_i, α_o) [rad] of balls at `positions` (Z, 2) between inner groove centres `centres`."""
    to_inner = centres - positions
    return jnp.arctan2(to_inner[..., 0], to_inner[..., 1]), jnp.arctan2(positions[..., 0], positions[..., 1])


def facing_component(bearing: BallBearing, normal):
    """The component [m] of a contact's normal (…, 2) (axial, radial), from its groove's curvature
    centre towards its raceway, along the way the grooves face (`BallBearing.groove_facing`):
    radial for a ring's groove, axial for a thrust washer's. A contact exists where it is > 0."""
    return normal[..., 1] if bearing.groove_facing == "radial" else normal[..., 0]


def _facing(approach, component):
    """The approach [m] of a contact whose groove faces the ball: a ring's groove is the arc on the
    ring's side of its curvature centre, so a ball beyond that centre (the facing component of the
    ball-to-contact normal ≤ 0, `facing_component`: |α| ≥ 90° on a ring, |α − 90°| ≥ 90° on a thrust
    washer) does not touch it, however far the full circle would overlap it; its approach is then
    −|δ| (open). Without this the circle's far side gives loaded 'contacts' at |α| > 90° (the far
    balls of a ring moved by more than its clearance), spurious roots and diverging Newton steps
    (docs/theory.md §Numerical notes)."""
    return jnp.where(component > 0.0, approach, -jnp.abs(approach))


def ball_state(bearing: BallBearing, operating: Operating, centres, positions, model: BallModel, constants=None,
               table=None):
    """Per-ball contact and kinematic state for ball centres `positions` (Z, 2); SI units.

    `constants` = (K_i, K_o) overrides the Hertz constants at the actual contact angles (the per-ball
    Newton holds them fixed within a step; the converged state always uses the exact ones), which
    otherwise come from `table` (`hertz_constants`).
    """
    inner_offset, outer_offset = _groove_offsets(bearing)
    to_inner = centres - positions
    outer_angle = jnp.arctan2(positions[..., 0], positions[..., 1])
    inner_angle = jnp.arctan2(to_inner[..., 0], to_inner[..., 1])
    outer_approach = _facing(jnp.linalg.norm(positions, axis=-1) - outer_offset, facing_component(bearing, positions))
    inner_approach = _facing(jnp.linalg.norm(to_inner, axis=-1) - inner_offset, facing_component(bearing, to_inner))
    if constants is None:
        constants = hertz_constants(bearing, inner_angle, outer_angle, model, table)
    k_inner, k_outer = constants
    ratio = bearing.ball_diameter / bearing.pitch_diameter
    relative_speed = operating.inner_speed - operating.outer_speed
    # a ball beyond the inner groove's centre (|α_i| ≥ 90°, no contact there) rolls on the outer
    # raceway alone: its speeds at α_i = α_o, not at the direction of a contact that does not exist
    rolling_inner = jnp.where(facing_component(bearing, to_inner) > 0.0, inner_angle, outer_angle)
    orbital, spin, beta = kinematics.ball_speeds(relative_speed, rolling_inner, outer_angle, ratio, model.race_control)
    orbital = orbital + operating.outer_speed
    state = dict(
        inner_approach=inner_approach, outer_approach=outer_approach,
        inner_angle=inner_angle, outer_angle=outer_angle,
        inner_constant=k_inner, outer_constant=k_outer,
        inner_load=hertz.hertz_load(inner_approach, k_inner), outer_load=hertz.hertz_load(outer_approach, k_outer),
        orbital_speed=orbital, spin_speed=spin, pitch_angle=beta,
    )
    density = bearing.ball_material.density
    state["centrifugal_force"] = (kinematics.centrifugal_force(density, bearing.ball_diameter, bearing.pitch_diameter,
                                                               orbital) if model.centrifugal else jnp.zeros_like(orbital))
    state["gyroscopic_moment"] = (kinematics.gyroscopic_moment(density, bearing.ball_diameter, orbital, spin, beta)
                                  if model.gyroscopic else jnp.zeros_like(orbital))
    return state


def contact_forces(bearing: BallBearing, state: dict, model: BallModel) -> dict:
    """Forces on each ball [N], (Z, 2) vectors (axial, radial) in its plane (module docstring).

    Keys: inner_normal (+Q_i n_i), outer_normal (−Q_o n_o), inner_friction and outer_friction (the
    raceway friction that supplies the gyroscopic moment, zero at the raceway that does not
    control), centrifugal (+F_c e_r).
    """
    def unit(angle):
        return jnp.stack([jnp.sin(angle), jnp.cos(angle)], axis=-1)

    def tangent(angle):
        return jnp.stack([jnp.cos(angle), -jnp.sin(angle)], axis=-1)

    friction = 2.0 * state["gyroscopic_moment"][..., None] / bearing.ball_diameter
    none = jnp.zeros_like(unit(state["outer_angle"]))
    inner_control = model.race_control == "inner"
    return dict(
        inner_normal=state["inner_load"][..., None] * unit(state["inner_angle"]),
        outer_normal=-state["outer_load"][..., None] * unit(state["outer_angle"]),
        inner_friction=friction * tangent(state["inner_angle"]) if inner_control else none,
        outer_friction=none if inner_control else -friction * tangent(state["outer_angle"]),
        centrifugal=jnp.stack([jnp.zeros_like(state["centrifugal_force"]), state["centrifugal_force"]], axis=-1),
    )


def ball_residual(positions, centres, bearing: BallBearing, operating: Operating, model: BallModel, constants=None,
                  table=None):
    """(Z, 2) force residual [N] of each ball's equilibrium, ΣF (module docstring), axial then radial."""
    forces = contact_forces(bearing, ball_state(bearing, operating, centres, positions, model, constants, table),
                            model)
    return sum(forces.values())


def _free_balls(bearing: BallBearing, operating: Operating, centres):
    """Balls touching neither raceway at standstill: their equilibrium is indeterminate (no force at all).

    A ball whose total approach is below `FREE_APPROACH` D_w (it would carry < 1e-10 N) counts as
    free too, so that rounding at exact contact cannot leave a singular 2×2 system.
    """
    approach = jnp.linalg.norm(centres, axis=-1) - groove_curvature_centre_distance(bearing)
    standstill = (operating.inner_speed == 0.0) & (operating.outer_speed == 0.0)
    return (approach <= FREE_APPROACH * bearing.ball_diameter) & standstill


def free_contact_constant(bearing: BallBearing, model: BallModel, table=None):
    """K_n(α₀) [N/m^1.5]: both contacts in series at the free contact angle."""
    angle = jnp.asarray(bearing.free_contact_angle)
    return hertz.combined_load_deflection_constant(*hertz_constants(bearing, angle, angle, model, table))


class _FreeBalls(eqx.Module):
    """Balls touching neither raceway at standstill, and the placeholder equation X = X_static that
    replaces their indeterminate ones, weighted by K_n(α₀) × 1 µm^{1/2} [N/m]."""

    mask: jax.Array
    reference: jax.Array
    scale: jax.Array


def _free_ball_equations(bearing, operating, centres, model, table):
    return _FreeBalls(_free_balls(bearing, operating, centres), static_positions(bearing, centres, model, table=table),
                      free_contact_constant(bearing, model, table) * 1e-3)


def _with_free_balls(residual, positions, free: _FreeBalls):
    """Ball residual (Z, 2) [N], with a free ball's indeterminate equations replaced by X = X_static (scaled)."""
    return jnp.where(free.mask[:, None], (positions - free.reference) * free.scale, residual)


def _masked_residual(positions, centres, bearing, operating, model, free: _FreeBalls, constants=None, table=None):
    """`ball_residual` at `positions`, free balls' equations replaced (`_with_free_balls`)."""
    return _with_free_balls(ball_residual(positions, centres, bearing, operating, model, constants, table), positions,
                            free)


def _ball_blocks(linear, shape):
    """(Z, 2, 2) blocks of the block-diagonal linear map `linear` on (Z, 2) arrays (ball j's
    residual depends on X_j alone): two JVPs with the same unit tangent on every ball give the two
    columns of all 2×2 blocks at once."""
    units = jnp.broadcast_to(jnp.eye(2)[:, None, :], (2,) + shape)
    return jnp.moveaxis(jax.vmap(linear)(units), 0, -1)


def _ball_equations(positions, args):
    """(Z, 2) residual [N] of every ball's equilibrium at `positions` (free balls' placeholders),
    the Hertz constants at the contact angles; args = (centres, bearing, operating, model, table, free)."""
    centres, bearing, operating, model, table, free = args
    return _masked_residual(positions, centres, bearing, operating, model, free, table=table)


def _solve_ball_blocks(blocks, rhs, scale):
    """x with (J_j − μ I) x_j = rhs_j for each ball's 2×2 block J_j (Z, 2, 2) and right-hand sides
    (Z, 2, k), μ = 1e-12 (max |J_j| + `scale` [N/m]). A ball touching neither raceway has J_j = 0:
    the shift makes its Newton step a (limited) move along the net force on it — the centrifugal
    force carries it out to the outer raceway — where a bare solve would return NaN; a ball in
    contact has J_j ≈ −(contact stiffness), which μ leaves unchanged to 1e-12."""
    shift = 1e-12 * (jnp.max(jnp.abs(blocks), axis=(-2, -1)) + scale)
    return jnp.linalg.solve(blocks - shift[..., None, None] * jnp.eye(2), rhs)


def _ball_step(positions, args):
    """(Z, 2) per-ball Newton step −J⁻¹g [m], each ball's 2×2 Jacobian (`_ball_blocks`) with the
    Hertz constants held at the current contact angles (their weak angle dependence left out)."""
    centres, bearing, operating, model, table, free = args
    constants = hertz_constants(bearing, *_contact_angles(centres, positions), model, table)
    residual, linear = jax.linearize(
        lambda x: _masked_residual(x, centres, bearing, operating, model, free, constants), positions)
    return -_solve_ball_blocks(_ball_blocks(linear, positions.shape), residual[..., None], free.scale)[..., 0]


def ball_tangent_solve(linear, rhs):
    """x (Z, 2) with linear(x) = rhs for the balls' linearised residual, block by block (`_ball_blocks`)."""
    return jnp.linalg.solve(_ball_blocks(linear, rhs.shape), rhs[..., None])[..., 0]


def _speed_start(bearing, operating, centres, model, table):
    """Start for the per-ball Newton: the static split, with a ball whose inner contact is open
    pressed onto the outer raceway by its centrifugal force along the line of groove centres. A
    ball the inner ring does not touch there (total approach ≤ 0) starts at the bottom of the outer
    groove (α_o = 0), pressed by the centrifugal force of its orbit at α_i = α_o = 0: the line of
    groove centres may point far up the groove, or past its edge, where the ring has moved by more
    than the clearance, and the static split puts the ball on the far side of the groove centre."""
    static = static_positions(bearing, centres, model, table=table)
    if not model.centrifugal:
        return static
    _, outer_offset = _groove_offsets(bearing)
    state = ball_state(bearing, operating, centres, static, model, table=table)
    pressed = (state["centrifugal_force"] / state["outer_constant"]) ** (2.0 / 3.0)
    along_centres = (static / jnp.linalg.norm(static, axis=-1, keepdims=True)
                     * (outer_offset + jnp.maximum(state["outer_approach"], pressed))[:, None])
    bottom = jnp.zeros(())
    orbital, _, _ = kinematics.ball_speeds(operating.inner_speed - operating.outer_speed, bottom, bottom,
                                           bearing.ball_diameter / bearing.pitch_diameter, model.race_control)
    force = kinematics.centrifugal_force(bearing.ball_material.density, bearing.ball_diameter, bearing.pitch_diameter,
                                         orbital + operating.outer_speed)
    at_bottom = jnp.stack([jnp.zeros(()), outer_offset
                           + (force / hertz_constants(bearing, bottom, bottom, model, table)[1]) ** (2.0 / 3.0)])
    touched = (jnp.linalg.norm(centres, axis=-1) - groove_curvature_centre_distance(bearing)) > 0.0
    return jnp.where(touched[:, None], along_centres, at_bottom)


def start_positions(displacement, bearing: BallBearing, operating: Operating, model: BallModel, table=None):
    """(Z, 2) ball centres [m] to start a joint Newton of ring (or shaft) and balls from, at
    inner-ring displacement Δ: `_speed_start` (the static split; a ball whose inner contact is open
    pressed onto the outer raceway by its centrifugal force, or, untouched, at its groove's bottom)."""
    return _speed_start(bearing, operating, inner_groove_centres(bearing, displacement), model, table)


def limited_ball_step(bearing: BallBearing, step):
    """Each ball's Newton step (Z, 2) [m], shortened to at most a tenth of the ball radius: Hertz's
    δ^{3/2} can throw a far Newton step."""
    limit = 0.05 * bearing.ball_diameter
    length = jnp.linalg.norm(step, axis=-1, keepdims=True)
    return step * jnp.minimum(1.0, limit / jnp.maximum(length, 1e-300))


def ball_positions(displacement, bearing: BallBearing, operating: Operating, model: BallModel, table=None):
    """(Z, 2) ball centres [m] in equilibrium with speed effects, for inner-ring displacement Δ.

    Per-ball Newton (`newton`, the 2×2 steps of `_ball_step`, each limited to a tenth of the ball
    radius) from `_speed_start`; stops when the largest step is below `BALL_POSITION_TOLERANCE` D_w
    (at most `BALL_NEWTON_MAX_STEPS`; the ring solver checks the ball residuals). Its derivative is
    the implicit one, dX = −(∂g/∂X)⁻¹ (∂g/∂(Δ, p)) d(Δ, p), ball by ball (`implicit_root`); a free
    ball's placeholder equation is held fixed (it carries no force wherever it is). `table`: the
    Hertz constants' Chebyshev table (`hertz_constants`).
    """
    centres = without_gradient(inner_groove_centres(bearing, displacement))
    start = _speed_start(*without_gradient((bearing, operating)), centres, model, without_gradient(table))
    return _balls_in_equilibrium(start, displacement, bearing, operating, model, table, _ball_newton)


def _ball_newton(residual, start, args):
    """Per-ball Newton for `ball_positions` (its docstring)."""
    bearing = args[1]
    return newton(residual, start, args, max_steps=BALL_NEWTON_MAX_STEPS, loop="while", linear_step=_ball_step,
                  limit=lambda step: limited_ball_step(bearing, step), line_search=False,
                  step_tolerance=(BALL_POSITION_TOLERANCE * bearing.ball_diameter, 0.0))[0]


def _balls_in_equilibrium(start, displacement, bearing, operating, model, table, solve):
    """(Z, 2) ball centres [m] that `solve(residual, start, args)` finds for `_ball_equations`, with
    their implicit derivative (`ball_positions`)."""
    centres = inner_groove_centres(bearing, displacement)
    free = jax.lax.stop_gradient(_free_ball_equations(bearing, operating, centres, model, table))
    return implicit_root(_ball_equations, start, (centres, bearing, operating, model, table, free), solve,
                         ball_tangent_solve)


def solved_ball_positions(ball_centres, displacement, bearing: BallBearing, operating: Operating, model: BallModel,
                          table=None):
    """(Z, 2) ball centres [m] at `ball_centres`, the balls' equilibrium a solve already found for Δ
    (`Equilibrium.ball_centres`), without a Newton solve of their own; their derivative is that of
    `ball_positions` (implicit, dX = −(∂g/∂X)⁻¹ (∂g/∂(Δ, p)) d(Δ, p)), so a block that reads the
    solved state traces no second solve (issue 47: one solve per program)."""
    return _balls_in_equilibrium(jax.lax.stop_gradient(ball_centres), displacement, bearing, operating, model, table,
                                 lambda residual, start, args: start)


def equilibrium_positions(displacement, bearing: BallBearing, operating: Operating, model: BallModel, table=None,
                          ball_centres=None):
    """Ball centres (Z, 2) [m] for displacement Δ: static split, or with speed effects the per-ball
    solve (`ball_positions`), or the solved `ball_centres` where given (`solved_ball_positions`)."""
    if not model.speed_effects:
        return static_positions(bearing, inner_groove_centres(bearing, displacement), model, table=table)
    if ball_centres is not None:
        return solved_ball_positions(ball_centres, displacement, bearing, operating, model, table)
    return ball_positions(displacement, bearing, operating, model, table)


def ring_force(displacement, bearing: BallBearing, operating: Operating, model: BallModel, table=None,
               ball_centres=None):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] the balls exert against an inner-ring displacement Δ.

    In equilibrium it equals the applied load; its Jacobian is the stiffness matrix. `table`: the
    Hertz constants' Chebyshev table (`hertz_constants`). `ball_centres`: the balls' equilibrium
    at this Δ where a solve found it (`Equilibrium.ball_centres`), else solved here (speed effects).
    """
    centres = inner_groove_centres(bearing, displacement)
    if model.speed_effects:
        positions = equilibrium_positions(displacement, bearing, operating, model, table, ball_centres)
        state = ball_state(bearing, operating, centres, positions, model, table=table)
    else:
        _, state = _static_split(bearing, operating, centres, model, table=table)
    return _ring_force_of_state(bearing, state, model)


def _ring_force_contributions(bearing: BallBearing, state: dict, model: BallModel):
    """(Z, 5) each ball's share of [Fx, Fy, Fz, Mx, My] the inner raceway exerts on the balls (ring
    equilibrium, module docstring).

    The normal force acts along the line through the inner groove centre, at radius R_i in the
    ring's plane of groove centres; the inner friction (inner-raceway control) acts at the ball's
    contact point, f_i D_w + δ_i from that centre, and adds its couple 2 M_g (f_i D_w + δ_i)/D_w
    along e_t.
    """
    sin_psi, cos_psi = _azimuth_directions(bearing)
    forces = contact_forces(bearing, state, model)
    axial, radial = jnp.moveaxis(forces["inner_normal"] + forces["inner_friction"], -1, 0)
    # e_t component of Σ r × F about the ring centre: −R_i F_axial, plus the friction's couple
    lever = bearing.inner_groove_ratio * bearing.ball_diameter + state["inner_approach"]
    couple = (2.0 * state["gyroscopic_moment"] * lever / bearing.ball_diameter if model.race_control == "inner"
              else jnp.zeros_like(axial))
    tangential_moment = -inner_groove_radius_of_centres(bearing) * axial + couple
    return jnp.stack([
        radial * cos_psi,
        radial * sin_psi,
        axial,
        -tangential_moment * sin_psi,
        tangential_moment * cos_psi,
    ], axis=-1)


def _ring_force_of_state(bearing: BallBearing, state: dict, model: BallModel):
    """[Fx, Fy, Fz, Mx, My] the inner raceway exerts on the balls: Σ_j `_ring_force_contributions`."""
    return jnp.sum(_ring_force_contributions(bearing, state, model), axis=0)


def _scales(bearing: BallBearing, operating: Operating, model: BallModel, table):
    """Unknown scale s (Δ = s·y), residual weights w (moments to forces) and load scale [N]."""
    inverse_arm = 1.0 / inner_groove_radius_of_centres(bearing)
    weight = jnp.stack([1.0, 1.0, 1.0, inverse_arm, inverse_arm])
    applied = jnp.concatenate([operating.force, operating.moment])
    return DISPLACEMENT_SCALE * weight, weight, safe_norm(applied * weight) + characteristic_load(bearing, model, table)


def _controls(operating: Operating):
    """(free, offset): which unknowns are solved (1) or prescribed (0), and the prescribed displacement.

    With `operating.axial_displacement` the axial displacement δz is held fixed (preload by
    displacement), with `operating.radial_displacement` δx, δy, with `operating.misalignment` the
    tilts θx, θy (a ring held by its shaft); every other component follows from the applied load.
    """
    free, offset = jnp.ones(5), jnp.zeros(5)
    if operating.radial_displacement is not None:
        free, offset = free.at[:2].set(0.0), offset.at[:2].set(operating.radial_displacement)
    if operating.axial_displacement is not None:
        free, offset = free.at[2].set(0.0), offset.at[2].set(operating.axial_displacement)
    if operating.misalignment is not None:
        free, offset = free.at[3:].set(0.0), offset.at[3:].set(operating.misalignment)
    return free, offset


def prescribed_coordinates(operating: Operating):
    """(5,) 1 where the inner ring's coordinate [δx, δy, δz, θx, θy] is prescribed (its load
    follows), 0 where it follows from the applied load (`_controls`)."""
    return 1.0 - _controls(operating)[0]


def _displacement(y, unknown, operating):
    free, offset = _controls(operating)
    return unknown * y * free + offset


def static_energy(displacement, bearing: BallBearing, combined):
    """Elastic energy Σ_j (2/5) K_n δ_j^{5/2} [J] of the balls at the static split for an inner-ring
    displacement Δ, with one load–deflection constant K_n [N/m^1.5] (both contacts in series,
    `free_contact_constant`): convex in Δ, its gradient the ring force with K_n held fixed."""
    centres = inner_groove_centres(bearing, displacement)
    approach = jnp.linalg.norm(centres, axis=-1) - groove_curvature_centre_distance(bearing)
    return 0.4 * combined * jnp.sum(positive_power(approach, 2.5))


def characteristic_load(bearing: BallBearing, model: BallModel, table=None):
    """K_n (10 µm)^{3/2} [N]: a load scale that stays positive at zero applied load."""
    return free_contact_constant(bearing, model, table) * DISPLACEMENT_SCALE**1.5


def _static_energy(y, args):
    """Scaled potential of the static problem with K_n(α₀): Σ (2/5) K_n δ^{5/2} − F·Δ (convex in Δ);
    a prescribed component contributes ½ y² (so its unknown stays 0)."""
    bearing, operating, combined, unknown, load_scale = args
    free, _ = _controls(operating)
    displacement = _displacement(y, unknown, operating)
    applied = jnp.concatenate([operating.force, operating.moment]) * free
    energy = static_energy(displacement, bearing, combined) - jnp.dot(applied, displacement)
    return energy / (load_scale * DISPLACEMENT_SCALE) + 0.5 * jnp.sum((1.0 - free) * y**2)


def _scaled_ring_residual(force, y, args):
    """(force − applied load) · w / load scale; a prescribed component's equation is replaced by its
    unknown (= 0)."""
    _, operating, _, _, _, weight, load_scale = args
    free, _ = _controls(operating)
    applied = jnp.concatenate([operating.force, operating.moment])
    return jnp.where(free > 0, (force - applied) * weight / load_scale, y)


def _ring_residual(y, args):
    """Scaled ring residual with the balls re-equilibrated (`ring_force`, the Hertz constants at the
    contact angles); args = (bearing, operating, model, table, unknown scale, weight, load scale)."""
    bearing, operating, model, table, unknown, _, _ = args
    force = ring_force(_displacement(y, unknown, operating), bearing, operating, model, table)
    return _scaled_ring_residual(force, y, args)


def _joint_residual(unknowns, args):
    """The joint solve's equations at ring unknowns y and ball centres X = s·u (s =
    `DISPLACEMENT_SCALE`): the scaled ring residual (5,) and each ball's ΣF (Z, 2) over the load
    scale (free balls: their placeholder, held), unknowns and equations of like size; the root the
    joint Newton finds, and the system its implicit derivative solves (`_joint_tangent_solve`)."""
    y, scaled_positions = unknowns
    bearing, operating, model, table, unknown, _, load_scale = args
    positions = DISPLACEMENT_SCALE * scaled_positions
    centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
    free = without_gradient(_free_ball_equations(bearing, operating, centres, model, table))
    contributions, balls = _ring_and_ball_residuals(centres, positions, bearing, operating, model, None, free, table)
    return _scaled_ring_residual(jnp.sum(contributions, axis=0), y, args), balls / load_scale


def _joint_tangent_solve(linear, rhs):
    """(dy, du) with linear((dy, du)) = rhs, the joint residual linearised at its root: its dense
    Jacobian (`jax.jacfwd`, 5 + 2Z tangents), the balls eliminated through the 5×5 Schur complement
    S = J_yy − J_yu J_uu⁻¹ J_uy (the ring's scaled stiffness with the balls re-equilibrated), S
    solved by least squares (finite where it is singular, as `newton.least_squares_tangent_solve`),
    the balls by back substitution."""
    ring_rhs, ball_rhs = rhs
    size = ball_rhs.size
    (ring_ring, ring_balls), (balls_ring, balls_balls) = jax.jacfwd(linear)(rhs)
    ring_balls = ring_balls.reshape(5, size)
    # J_uu factored once; its solves of the constant J_uy and of the right-hand side apart, so the
    # solve stays linear in rhs (reverse mode transposes it)
    factor = jax.scipy.linalg.lu_factor(balls_balls.reshape(size, size))
    coupling = jax.scipy.linalg.lu_solve(factor, balls_ring.reshape(size, 5))
    balls = jax.scipy.linalg.lu_solve(factor, ball_rhs.reshape(size))
    dy = jnp.linalg.lstsq(ring_ring - ring_balls @ coupling, ring_rhs - ring_balls @ balls)[0]
    return dy, (balls - coupling @ dy).reshape(ball_rhs.shape)


def _static_ring_residual(y, args, constants):
    """Scaled ring residual at the static split with the Hertz constants (K_i, K_o) held at `constants`."""
    bearing, operating, model, _, unknown, _, _ = args
    centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
    _, state = _static_split(bearing, operating, centres, model, constants)
    return _scaled_ring_residual(_ring_force_of_state(bearing, state, model), y, args)


def _ring_and_ball_residuals(centres, positions, bearing, operating, model, constants, free: _FreeBalls,
                             table=None):
    """Each ball's share of the ring force (Z, 5) [N, N·m] and the ball residuals (Z, 2) [N] (free
    balls: their placeholder) at inner groove centres A (Z, 2) [m] and ball centres X, with the Hertz
    constants held at `constants` (None: at the contact angles, from `table`). Ball j's share and
    residual depend on (A_j, X_j) alone."""
    state = ball_state(bearing, operating, centres, positions, model, constants, table)
    contributions = _ring_force_contributions(bearing, state, model)
    return contributions, _with_free_balls(sum(contact_forces(bearing, state, model).values()), positions, free)


class CondensedBalls(eqx.Module):
    """The ring force of a bearing's balls at a ring displacement Δ and ball centres X, with the balls'
    equations g(Δ, X) = 0 eliminated to first order (`condensed_balls`): the ring force F (5) [N,
    N·m]; the condensed force F − J_FX J_XX⁻¹ g and stiffness J_FΔ − J_FX J_XX⁻¹ J_XΔ (5, 5), the
    Schur complement of the balls' 2×2 blocks; and the ball step's parts, J_XX⁻¹ g (Z, 2) [m] and
    J_XX⁻¹ J_XΔ (Z, 2, 5): with a ring step dΔ the balls' Newton step is −(J_XX⁻¹ g + J_XX⁻¹ J_XΔ dΔ)."""

    force: jax.Array
    condensed_force: jax.Array
    condensed_stiffness: jax.Array
    ball_correction: jax.Array
    ball_coupling: jax.Array


def condensed_balls(displacement, positions, bearing: BallBearing, operating: Operating, model: BallModel,
                    table=None, exact: bool = False) -> CondensedBalls:
    """The bearing's balls at ring displacement Δ [m, rad] and ball centres X (Z, 2) [m] condensed
    onto the ring (`CondensedBalls`), for a Newton step of ring (or shaft) and ball unknowns together.

    The Hertz constants are evaluated once at the current contact angles and held in the
    Jacobian, which leaves out their weak angle dependence; the residuals are exact. With `exact`
    the Jacobian follows the constants' angle dependence too and each ball's block is solved as it
    stands (no shift): at a solution, `condensed_stiffness` is then the stiffness dF/dΔ with the
    balls re-equilibrated (`stiffness_matrix`). The Jacobian is block-arrow: ball j's residual and
    its share of the ring force depend on its inner groove centre A_j and X_j alone, so 4 JVP
    tangents with the same unit on every ball (2 for A, 2 for X) give every ball's 2×2 blocks, and
    the ring columns follow by the chain rule through the groove centres' motion dA/dΔ (affine in
    Δ: a constant (Z, 2, 5)). The condensation is the block elimination through the 5×5 Schur
    complement S = J_ΔΔ − Σ_j J_ΔXj J_XjXj⁻¹ J_XjΔ (Golub & Van Loan, Matrix Computations, §3.2).
    """
    count = bearing.ball_count
    centres = inner_groove_centres(bearing, displacement)
    groove_motion = jax.jacfwd(inner_groove_centres, argnums=1)(bearing, displacement)  # dA/dΔ (Z, 2, 5), constant
    constants = None if exact else hertz_constants(bearing, *_contact_angles(centres, positions), model, table)
    # a free ball's placeholder row carries no force and no coupling to Δ (its reference is held in
    # the linearisation): its reference and scale leave F and K unchanged, and carry no derivative
    free = without_gradient(_free_ball_equations(bearing, operating, centres, model, table))
    (contributions, balls), linear = jax.linearize(
        lambda a, x: _ring_and_ball_residuals(a, x, bearing, operating, model, constants, free, table),
        centres, positions)
    units, none = jnp.broadcast_to(jnp.eye(2)[:, None, :], (2, count, 2)), jnp.zeros((2, count, 2))
    d_shares, d_balls = jax.vmap(linear)(jnp.concatenate([units, none]), jnp.concatenate([none, units]))
    shares_centres = jnp.moveaxis(d_shares[:2], 0, -1)  # (Z, 5, 2)
    ring_balls = jnp.moveaxis(d_shares[2:], 0, -1)  # (Z, 5, 2)
    balls_ring = jnp.einsum("jab,jbc->jac", jnp.moveaxis(d_balls[:2], 0, -1), groove_motion)  # (Z, 2, 5)
    balls_balls = jnp.moveaxis(d_balls[2:], 0, -1)  # (Z, 2, 2)
    ring_ring = jnp.einsum("jab,jbc->ac", shares_centres, groove_motion)  # (5, 5)
    rhs = jnp.concatenate([balls[..., None], balls_ring], axis=-1)
    solved = jnp.linalg.solve(balls_balls, rhs) if exact else _solve_ball_blocks(balls_balls, rhs, free.scale)
    force = jnp.sum(contributions, axis=0)
    return CondensedBalls(force, force - jnp.einsum("jab,jb->a", ring_balls, solved[..., 0]),
                          ring_ring - jnp.einsum("jab,jbc->ac", ring_balls, solved[..., 1:]), solved[..., 0],
                          solved[..., 1:])


def _static_step(y, args):
    """Ring Newton step at the static split, −J⁻¹r (`newton.guarded_solve`), with J by `jax.jacfwd` (5
    tangents) and the Hertz constants evaluated once at the current contact angles and held in
    it, which leaves out their weak angle dependence; the residual itself is exact."""
    bearing, operating, model, table, unknown, _, _ = args
    centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
    constants = _static_constants(bearing, centres, model, table)
    jacobian, residual = jax.jacfwd(lambda v: (r := _static_ring_residual(v, args, constants), r), has_aux=True)(y)
    return -guarded_solve(jacobian, residual)


def _speed_step(unknowns, args, ring_held=False):
    """Newton step (−dy, −dX) of the ring and ball unknowns together (5 + 2Z), (y, ball centres
    (Z, 2) [m]): the balls condensed onto the ring (`condensed_balls`), the ring step from the
    condensed residual (a prescribed component's equation is its unknown, = 0), then the balls'.
    With `ring_held` (a bool array) the ring stays where it is (dy = 0) and the step is each ball's
    own 2×2 Newton step, −J_XX⁻¹ g: the balls solved per ball at a fixed ring."""
    y, positions = unknowns
    bearing, operating, model, table, unknown, weight, load_scale = args
    free, _ = _controls(operating)
    condensed = condensed_balls(_displacement(y, unknown, operating), positions, bearing, operating, model, table)
    ring = _scaled_ring_residual(condensed.condensed_force, y, args)
    rows = (free * weight / load_scale)[:, None]
    schur = rows * condensed.condensed_stiffness * (unknown * free)[None, :] + jnp.diag(1.0 - free)
    dy = jnp.where(ring_held, 0.0, guarded_solve(schur, ring))
    # the ring moves by −dy; the balls by −J_XX⁻¹ g − J_XX⁻¹ J_XΔ dΔ with dΔ = −(its scale) dy
    return -dy, -(condensed.ball_correction - condensed.ball_coupling @ (unknown * free * dy))


def _at_speed_fraction(operating: Operating, fraction):
    """The operating point with both ring speeds scaled by `fraction` (a stage of `_ring_solve`)."""
    return eqx.tree_at(lambda o: (o.inner_speed, o.outer_speed), operating,
                       (fraction * operating.inner_speed, fraction * operating.outer_speed))


def _ring_solve(residual, start, args):
    """Ring Newton from the static solution `start`: (y, (ball centres (Z, 2) [m] or None, steps)).

    Without speed effects on the ring unknowns at the static split (`_static_step`). With them on
    the ring and ball unknowns together (`_speed_step`), continued in speed: the speeds rise in
    `SPEED_STAGES` (fractions whose squares, and so the centrifugal forces and gyroscopic moments,
    rise in equal steps), each stage's Newton starting from the last one's solution. Before them a
    stage with the ring held at the static solution (`_speed_step` with `ring_held`) solves the
    balls per ball from `start_positions` at the first stage's speed: each ball's own 2×2 Newton
    in the same loop body as the joint stages, so the program holds one step, not a per-ball solve
    of its own. From `start_positions` without it (the balls left to the joint Newton, as a
    shaft's are), 82 of 200 loads spread as in benchmarks/ball_batch.py (aero-engine bearing,
    1500 r/min) took 17 to 194 ring steps where the held stage leaves 15 to 22 (single solves; a
    first stage wandering for its 100 steps, then discarded), and a vmapped batch runs as many
    steps as its slowest case. `Equilibrium.steps` counts the held stage's steps too. At once
    from the static solution, Newton's first steps can carry a light or radially loaded ring past
    the clearance, where contacts switch and the iteration wanders off (measured: 12 % of random
    angular-contact bearings at speed ended unconverged or on a spurious root, docs/theory.md
    §Numerical notes). Full Newton steps (`newton`), each ball's limited to a tenth of its radius;
    each stage stops when every ring step component is below `RING_STEP_TOLERANCE` (1 + |y|) and
    every ball step below `BALL_POSITION_TOLERANCE` D_w.
    """
    bearing, operating, model, table, unknown, weight, load_scale = args
    options = dict(max_steps=RING_MAX_STEPS, loop="while", line_search=False)
    if not model.speed_effects:
        y, steps = newton(residual, start, args, linear_step=_static_step,
                          step_tolerance=(RING_STEP_TOLERANCE, RING_STEP_TOLERANCE), **options)
        return y, (None, steps.astype(y.dtype))  # custom_root's JVP rule takes floating aux only
    # a first stage at the first fraction with the ring held: the balls solved per ball at the static ring
    fractions = jnp.asarray((SPEED_STAGES[0],) + SPEED_STAGES)
    ring_held = jnp.arange(len(SPEED_STAGES) + 1) == 0
    positions = start_positions(_displacement(start, unknown, operating), bearing,
                                _at_speed_fraction(operating, fractions[0]), model, table)

    def stage(unknowns, stage_input):
        fraction, held = stage_input
        staged = (bearing, _at_speed_fraction(operating, fraction), model, table, unknown, weight, load_scale)
        solved, steps = newton(None, unknowns, staged, linear_step=lambda unknowns, args: _speed_step(unknowns, args, held),
                               limit=lambda step: (step[0], limited_ball_step(bearing, step[1])),
                               step_tolerance=((RING_STEP_TOLERANCE, BALL_POSITION_TOLERANCE * bearing.ball_diameter),
                                               (RING_STEP_TOLERANCE, 0.0)), **options)
        # a ring stage that ran out of steps or off to non-finite values keeps the last stage's solution:
        # the report then names the residual at full speed, with finite values (the balls' stage keeps its
        # finite positions, as far as it came)
        reached = (held | (steps < RING_MAX_STEPS)) & jnp.all(jnp.stack([jnp.all(jnp.isfinite(x))
                                                                          for x in jax.tree.leaves(solved)]))
        return jax.tree.map(lambda new, old: jnp.where(reached, new, old), solved, unknowns), steps

    (y, positions), steps = jax.lax.scan(stage, (start, positions), (fractions, ring_held))
    return y, (positions, jnp.sum(steps).astype(y.dtype))


class Equilibrium(eqx.Module):
    """Solution of the ring problem: displacement Δ [m, rad] and how it was reached."""

    displacement: jax.Array
    force: jax.Array  # [Fx, Fy, Fz, Mx, My] the balls exert: the applied load, or the reaction of a prescribed coordinate
    converged: jax.Array  # bool: residual below RESIDUAL_TOLERANCE and the state within the model
    residual: jax.Array  # max of the scaled ring residual and the relative ball residuals [-]
    approach_ratio: jax.Array  # largest contact approach / D_w [-] (ball_validity)
    contact_angle: jax.Array  # largest |contact angle| [rad] (ball_validity)
    static_steps: jax.Array
    steps: jax.Array
    # (Z, 2) ball centres [m] (axial, radial; outer groove centre as origin) with speed effects, else None:
    # hand them to `ring_force`, `stiffness_matrix` or `ball_results` at this Δ, which then solve no balls
    ball_centres: jax.Array | None = None
    # the table of Hertz constants K(α) the solve built (`constant_table`; None where the model holds
    # them at α₀), with its derivative: hand it to `stiffness_at_balls`, which then builds none
    constant_table: ContactConstantTable | None = None


def solve_equilibrium(bearing: BallBearing, operating: Operating, model: BallModel = BallModel()) -> Equilibrium:
    """Inner-ring displacement Δ in equilibrium with the applied load; needs no initial guess.

    `converged` is False where the residual stays above `RESIDUAL_TOLERANCE` or the solved state lies
    outside the model (`ball_validity`: approach beyond 1 % of D_w, a contact angle beyond ±90°).

    With `operating.axial_displacement` set, δz is prescribed (preload by displacement) and the
    axial force is an output (`Equilibrium.force[2]`); with `operating.radial_displacement`, δx and
    δy are and the radial force is (`Equilibrium.force[:2]`); with `operating.misalignment`, θx and
    θy are prescribed and the moments are (`Equilibrium.force[3:]`).

    Differentiable with respect to every array leaf of `bearing` and `operating` (implicit adjoint,
    forward and reverse mode). At a singular stiffness (zero load, or a direction the bearing does
    not resist) the adjoint uses a least-squares pseudo-inverse: finite, not a true derivative.
    """
    return _solve(bearing, operating, model)[0]


def solve_with_balls(bearing: BallBearing, operating: Operating,
                     model: BallModel = BallModel()) -> tuple[Equilibrium, "BallResults"]:
    """`solve_equilibrium` and the `ball_results` at its solution, both from the one solved state:
    the balls' implicit derivative and the Hertz constants' table are traced once, not again for
    the per-ball results (the scenes' equilibrium block)."""
    solution, state, positions = _solve(bearing, operating, model)
    return solution, _ball_results_of_state(bearing, model, state, positions)


def _solve(bearing: BallBearing, operating: Operating, model: BallModel):
    """(`Equilibrium`, the ball state at it, the ball centres (Z, 2) [m])."""
    require_float64()
    table = constant_table(bearing, model)
    unknown, weight, load_scale = _scales(bearing, operating, model, table)
    # the starts and the joint solve carry no derivative (the roots' implicit one stands for it): their
    # inputs held, so a derivative's program holds no tangents of their loops either
    static_y, static_steps = minimise_convex(
        _static_energy, jnp.zeros(5),
        without_gradient((bearing, operating, free_contact_constant(bearing, model, table), unknown, load_scale)),
        gradient_tolerance=STATIC_GRADIENT_TOLERANCE)
    args = (bearing, operating, model, table, unknown, weight, load_scale)
    if model.speed_effects:  # ring and balls one root, differentiated as one (`_joint_residual`)
        solved, (positions, steps) = _ring_solve(_ring_residual, static_y, without_gradient(args))
        y, scaled_positions = implicit_root(_joint_residual, (solved, positions / DISPLACEMENT_SCALE), args,
                                            lambda residual, guess, args: guess, _joint_tangent_solve)
        positions = DISPLACEMENT_SCALE * scaled_positions
    else:  # the exact ring residual defines the implicit derivative
        y, (positions, steps) = implicit_root(_ring_residual, static_y, args, _ring_solve, least_squares_tangent_solve,
                                              has_aux=True)
    displacement = _displacement(y, unknown, operating)
    centres = inner_groove_centres(bearing, displacement)
    if model.speed_effects:  # the balls of the joint solve, with their implicit derivative
        state = ball_state(bearing, operating, centres, positions, model, table=table)
    else:
        positions, state = _static_split(bearing, operating, centres, model, table=table)
    force = _ring_force_of_state(bearing, state, model)
    ring_residual = jnp.max(jnp.abs(_scaled_ring_residual(force, y, args)))
    residual = ring_residual
    if model.speed_effects:
        residual = jnp.maximum(residual, relative_ball_residual(bearing, operating, centres, state, model, load_scale))
    residual = jax.lax.stop_gradient(residual)
    approach_ratio = jax.lax.stop_gradient(ball_validity.largest_approach_ratio(
        state["inner_approach"], state["outer_approach"], bearing.ball_diameter))
    contact_angle = jax.lax.stop_gradient(ball_validity.largest_contact_angle(
        state["inner_angle"], state["outer_angle"], state["inner_load"], state["outer_load"]))
    converged = (residual < RESIDUAL_TOLERANCE) & ball_validity.within_model(approach_ratio, contact_angle)
    solution = Equilibrium(displacement, force, converged, residual, approach_ratio, contact_angle, static_steps,
                           steps.astype(static_steps.dtype),
                           jax.lax.stop_gradient(positions) if model.speed_effects else None, table)
    return solution, state, positions


def relative_ball_residual(bearing: BallBearing, operating: Operating, centres, state: dict, model: BallModel, load_scale):
    """The largest |ΣF| of a ball [N] at a solved state (`ball_state` at the groove centres
    `centres`) over the forces on it (its contact loads and centrifugal force, plus 1e-6 of the
    bearing's load scale [N]); 0 for a free ball, which carries nothing."""
    ball = sum(contact_forces(bearing, state, model).values())
    size = state["inner_load"] + state["outer_load"] + state["centrifugal_force"] + load_scale * 1e-6
    free = _free_balls(bearing, operating, centres)
    return jnp.max(jnp.where(free, 0.0, jnp.max(jnp.abs(ball), axis=-1) / size))


def stiffness_matrix(displacement, bearing: BallBearing, operating: Operating, model: BallModel = BallModel(),
                     ball_centres=None, table: ContactConstantTable | None = None):
    """5×5 stiffness K = dF/dΔ [N/m, N/rad; N·m/m, N·m/rad] with the balls re-equilibrated, exact
    (`stiffness_at_balls`). `ball_centres`: the solved balls at Δ (`Equilibrium.ball_centres`);
    without them the balls are solved here. `table`: the solve's table of Hertz constants
    (`Equilibrium.constant_table`); without it, it is built here."""
    if table is None:
        table = constant_table(bearing, model)
    positions = (equilibrium_positions(displacement, bearing, operating, model, table, ball_centres)
                 if model.speed_effects else None)
    return _stiffness(displacement, positions, bearing, operating, model, table)


def stiffness_at_balls(displacement, positions, bearing: BallBearing, operating: Operating,
                       model: BallModel = BallModel(), table: ContactConstantTable | None = None):
    """5×5 stiffness K = dF/dΔ at a solved state: Δ [m, rad] and the balls' equilibrium X (Z, 2) [m]
    there, X carrying its own derivative (`ball_results(...).centre`), so nothing is solved again.
    `table`: the solve's table of Hertz constants (`Equilibrium.constant_table`); without it, it is
    built here.

    Without speed effects `jax.jacfwd` of the static ring force (X not read). With them, one
    linearisation at (Δ, X): K = J_FΔ − J_FX J_XX⁻¹ J_XΔ, the Schur complement of the balls' 2×2
    blocks (`condensed_balls` with `exact`); equal to `jax.jacfwd(ring_force)` through the balls'
    implicit derivative to rounding, and differentiable through Δ and X."""
    if table is None:
        table = constant_table(bearing, model)
    return _stiffness(displacement, positions, bearing, operating, model, table)


def _stiffness(displacement, positions, bearing, operating, model, table):
    if not model.speed_effects:
        return jax.jacfwd(ring_force)(displacement, bearing, operating, model, table)
    return condensed_balls(displacement, positions, bearing, operating, model, table, exact=True).condensed_stiffness


class BallResults(eqx.Module):
    """Per-ball results at a displacement Δ, each (Z,) in SI: azimuth ψ [rad]; per contact (inner,
    outer) the normal load Q [N], contact angle α [rad], Hertz peak pressure [Pa] and semi-axes a, b
    [m] (a across rolling); orbital speed ω_m and spin speed ω_R [rad/s] (`kinematics.ball_speeds`);
    centrifugal force F_c [N] and gyroscopic moment M_g [N·m], None where the model leaves that
    effect out; the contact approaches δ_i, δ_o [m] (negative: open), for `ball_validity`; the ball
    centres (Z, 2) [m] (`ring_force`'s `ball_centres`)."""

    azimuth: jax.Array
    inner_load: jax.Array
    inner_contact_angle: jax.Array
    inner_max_pressure: jax.Array
    inner_semi_major_axis: jax.Array
    inner_semi_minor_axis: jax.Array
    outer_load: jax.Array
    outer_contact_angle: jax.Array
    outer_max_pressure: jax.Array
    outer_semi_major_axis: jax.Array
    outer_semi_minor_axis: jax.Array
    orbital_speed: jax.Array
    spin_speed: jax.Array
    centrifugal_force: jax.Array | None
    gyroscopic_moment: jax.Array | None
    inner_approach: jax.Array
    outer_approach: jax.Array
    centre: jax.Array  # (Z, 2) ball centres [m], (axial, radial) from the outer groove centre (module docstring)


def ball_results(displacement, bearing: BallBearing, operating: Operating, model: BallModel = BallModel(),
                 ball_centres=None, table: ContactConstantTable | None = None) -> BallResults:
    """Per-ball loads, contact angles, Hertz contact sizes and pressures, kinematics at Δ (SI).
    `ball_centres`: the solved balls at Δ (`Equilibrium.ball_centres`); without them, solved here.
    `table`: the solve's table of Hertz constants (`Equilibrium.constant_table`); without it, built here."""
    if table is None:
        table = constant_table(bearing, model)
    centres = inner_groove_centres(bearing, displacement)
    positions = equilibrium_positions(displacement, bearing, operating, model, table, ball_centres)
    return _ball_results_of_state(bearing, model, ball_state(bearing, operating, centres, positions, model, table=table),
                                  positions)


def _ball_results_of_state(bearing: BallBearing, model: BallModel, state: dict, positions) -> BallResults:
    """`BallResults` of a ball state (`ball_state`) at ball centres `positions` (Z, 2) [m]."""
    both = hertz.point_contact(jnp.stack([state["inner_load"], state["outer_load"]]),
                               *both_curvatures(bearing, state["inner_angle"], state["outer_angle"]),
                               ball_raceway_modulus(bearing), model.hertz_method)
    inner, outer = (jax.tree.map(lambda x: x[k], both) for k in (0, 1))
    return BallResults(
        ball_azimuths(bearing),
        state["inner_load"], state["inner_angle"], inner.max_pressure, inner.semi_major_axis, inner.semi_minor_axis,
        state["outer_load"], state["outer_angle"], outer.max_pressure, outer.semi_major_axis, outer.semi_minor_axis,
        state["orbital_speed"], state["spin_speed"],
        state["centrifugal_force"] if model.centrifugal else None,
        state["gyroscopic_moment"] if model.gyroscopic else None,
        state["inner_approach"], state["outer_approach"], positions)
