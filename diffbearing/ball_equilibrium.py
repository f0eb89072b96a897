"""Quasi-static 5-DOF ball bearing: load distribution, contact angles and stiffness at speed.

Model (physics.md §2, seed 001; Jones 1960, Harris & Kotzalas vol. 2 ch. 3). The outer ring is
fixed; the inner ring moves by Δ = [δx, δy, δz, θx, θy] from the position where the rings are
concentric and every ball just touches both raceways at the free contact angle α₀. In the plane of
ball j (azimuth ψ_j from +x), with the outer groove curvature centre as origin, axial coordinate
first and radial (outward) second:

    inner groove curvature centre  A = (B D_w sin α₀ + δz + R_i (θx sin ψ − θy cos ψ),
                                        B D_w cos α₀ + δx cos ψ + δy sin ψ)
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

Solution (physics.md §7): the ring problem starts from the static solution, found by minimising
the convex elastic energy Σ (2/5) K_n max(|A| − B D_w, 0)^{5/2} − F·Δ (no initial guess needed,
zero stiffness at the start is fine). Newton then adds the contact-angle dependence of the Hertz
constants and the speed terms: without speed effects on the 5 ring unknowns with the balls at the
closed-form static split; with them on the ring and ball unknowns together (5 + 2Z, the balls
first solved per ball at the static ring position), each step through the 5×5 Schur complement of
the block-arrow Jacobian. Each step evaluates the Hertz constants once at the current contact
angles and holds them in the Jacobian (their angle dependence is weak); the residuals are exact.
The implicit derivative of the solution uses the exact linearisation (`jax.lax.custom_root`,
least squares on the 5×5 Jacobian of `ring_force`). `ball_positions` solves the balls per ball
(vmap, 2×2 Newton) for a given Δ and carries the implicit-function derivative
dX = −(∂g/∂X)⁻¹ (∂g/∂(Δ, p)) dΔ, so the ring force F(Δ) has exact total derivatives and the
stiffness K = dF/dΔ (balls re-equilibrated) is `jax.jacfwd(ring_force)`.
"""

import dataclasses
import functools

import equinox as eqx
import jax
import jax.numpy as jnp

from . import ball_validity, hertz, kinematics
from .numerics import positive_power, require_float64, safe_norm
from .params import BallBearing, Operating, groove_curvature_centre_distance
from .raceway_contact import (ball_raceway_modulus, contact_constant_table, contact_constants, inner_curvature,
                              outer_curvature, table_constants)
from .solvers import minimise_convex

BALL_NEWTON_MAX_STEPS = 40
BALL_POSITION_TOLERANCE = 1e-13  # × D_w: step size at which the per-ball Newton stops
FREE_APPROACH = 1e-12  # × D_w: below this total approach a ball at standstill is taken as free
DISPLACEMENT_SCALE = 1e-5  # m: the unit of the scaled ring unknowns (10 µm, 10 µm / R_i rad)
RESIDUAL_TOLERANCE = 1e-9  # converged when the scaled ring residual and ball residuals are below

RING_STEP_TOLERANCE = 1e-11  # ring Newton stops when every scaled step component is below this × (1 + |y|)
RING_MAX_STEPS = 100
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
    """ψ_j = 2π j / Z [rad], ball 0 on +x."""
    return 2.0 * jnp.pi * jnp.arange(bearing.ball_count) / bearing.ball_count


def inner_groove_radius_of_centres(bearing: BallBearing):
    """R_i = d_m/2 + (f_i − ½) D_w cos α₀ [m], the moment arm of the inner contact forces."""
    return 0.5 * bearing.pitch_diameter + (bearing.inner_groove_ratio - 0.5) * bearing.ball_diameter * jnp.cos(
        bearing.free_contact_angle)


def inner_groove_centres(bearing: BallBearing, displacement):
    """(Z, 2) positions (axial, radial) of the inner groove curvature centres [m] (module docstring)."""
    psi = ball_azimuths(bearing)
    distance = groove_curvature_centre_distance(bearing)
    arm = inner_groove_radius_of_centres(bearing)
    dx, dy, dz, tx, ty = (displacement[i] for i in range(5))
    axial = distance * jnp.sin(bearing.free_contact_angle) + dz + arm * (tx * jnp.sin(psi) - ty * jnp.cos(psi))
    radial = distance * jnp.cos(bearing.free_contact_angle) + dx * jnp.cos(psi) + dy * jnp.sin(psi)
    return jnp.stack([axial, radial], axis=-1)


def hertz_constants(bearing: BallBearing, inner_angle, outer_angle, model: BallModel):
    """(K_i, K_o) [N/m^1.5] at the contact angles, or at α₀ (`model.hertz_constants`).

    Inside the solvers the bearing carries a Chebyshev table of K(α) (`with_constant_table`);
    without one each contact's constant is solved exactly.
    """
    if model.hertz_constants == "free_contact_angle":
        angle = bearing.free_contact_angle
        return tuple(jnp.broadcast_to(k, jnp.shape(inner_angle))
                     for k in contact_constants(bearing, angle, angle, model.hertz_method))
    if bearing.contact_constant_table is not None:
        return table_constants(bearing.contact_constant_table, inner_angle, outer_angle)
    return contact_constants(bearing, inner_angle, outer_angle, model.hertz_method)


def with_constant_table(bearing: BallBearing, model: BallModel) -> BallBearing:
    """The bearing with a fresh Chebyshev table of its Hertz constants for `model`'s fidelity level."""
    table = contact_constant_table(bearing, model.hertz_method) if model.hertz_constants == "contact_angle" else None
    return eqx.tree_at(lambda b: b.contact_constant_table, bearing, table, is_leaf=lambda x: x is None)


def _groove_offsets(bearing: BallBearing):
    """((f_i − ½) D_w, (f_o − ½) D_w) [m]: ball-centre distance from each groove centre at zero load."""
    return ((bearing.inner_groove_ratio - 0.5) * bearing.ball_diameter,
            (bearing.outer_groove_ratio - 0.5) * bearing.ball_diameter)


def static_positions(bearing: BallBearing, centres, model: BallModel, constants=None):
    """(Z, 2) ball centres without speed effects: on the line of groove centres, the total approach
    split so that K_i δ_i^{3/2} = K_o δ_o^{3/2} (both contacts at the same angle).

    `constants` = (K_i, K_o) overrides the Hertz constants at the angle of the line of centres.
    """
    inner_offset, outer_offset = _groove_offsets(bearing)
    length = jnp.linalg.norm(centres, axis=-1)
    total = length - groove_curvature_centre_distance(bearing)
    if constants is None:
        constants = _static_constants(bearing, centres, model)
    k_inner, k_outer = constants
    outer_approach = total / (1.0 + (k_outer / k_inner) ** (2.0 / 3.0))
    return centres / length[..., None] * (outer_offset + outer_approach)[..., None]


def _static_constants(bearing: BallBearing, centres, model: BallModel):
    """(K_i, K_o) [N/m^1.5] at the angle of the line of groove centres, where both static contacts lie."""
    angle = jnp.arctan2(centres[..., 0], centres[..., 1])
    return hertz_constants(bearing, angle, angle, model)


def _static_state(bearing: BallBearing, operating: Operating, centres, model: BallModel, constants=None):
    """`ball_state` at the static split, with the Hertz constants evaluated once for both contacts
    (they lie on the line of groove centres, at the same angle)."""
    if constants is None:
        constants = _static_constants(bearing, centres, model)
    positions = static_positions(bearing, centres, model, constants)
    return ball_state(bearing, operating, centres, positions, model, constants)


def _contact_angles(centres, positions):
    """(α_i, α_o) [rad] of balls at `positions` (Z, 2) between inner groove centres `centres`."""
    to_inner = centres - positions
    return jnp.arctan2(to_inner[..., 0], to_inner[..., 1]), jnp.arctan2(positions[..., 0], positions[..., 1])


def ball_state(bearing: BallBearing, operating: Operating, centres, positions, model: BallModel, constants=None):
    """Per-ball contact and kinematic state for ball centres `positions` (Z, 2); SI units.

    `constants` = (K_i, K_o) overrides the Hertz constants at the actual contact angles (the per-ball
    Newton holds them fixed within a step; the converged state always uses the exact ones).
    """
    inner_offset, outer_offset = _groove_offsets(bearing)
    to_inner = centres - positions
    outer_approach = jnp.linalg.norm(positions, axis=-1) - outer_offset
    inner_approach = jnp.linalg.norm(to_inner, axis=-1) - inner_offset
    outer_angle = jnp.arctan2(positions[..., 0], positions[..., 1])
    inner_angle = jnp.arctan2(to_inner[..., 0], to_inner[..., 1])
    if constants is None:
        constants = hertz_constants(bearing, inner_angle, outer_angle, model)
    k_inner, k_outer = constants
    ratio = bearing.ball_diameter / bearing.pitch_diameter
    relative_speed = operating.inner_speed - operating.outer_speed
    orbital, spin, beta = kinematics.ball_speeds(relative_speed, inner_angle, outer_angle, ratio, model.race_control)
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


def ball_residual(positions, centres, bearing: BallBearing, operating: Operating, model: BallModel, constants=None):
    """(Z, 2) force residual [N] of each ball's equilibrium, ΣF (module docstring), axial then radial."""
    forces = contact_forces(bearing, ball_state(bearing, operating, centres, positions, model, constants), model)
    return sum(forces.values())


def _free_balls(bearing: BallBearing, operating: Operating, centres):
    """Balls touching neither raceway at standstill: their equilibrium is indeterminate (no force at all).

    A ball whose total approach is below `FREE_APPROACH` D_w (it would carry < 1e-10 N) counts as
    free too, so that rounding at exact contact cannot leave a singular 2×2 system.
    """
    approach = jnp.linalg.norm(centres, axis=-1) - groove_curvature_centre_distance(bearing)
    standstill = (operating.inner_speed == 0.0) & (operating.outer_speed == 0.0)
    return (approach <= FREE_APPROACH * bearing.ball_diameter) & standstill


def free_contact_constant(bearing: BallBearing, model: BallModel):
    """K_n(α₀) [N/m^1.5]: both contacts in series at the free contact angle."""
    angle = jnp.asarray(bearing.free_contact_angle)
    return hertz.combined_load_deflection_constant(*hertz_constants(bearing, angle, angle, model))


class _FreeBalls(eqx.Module):
    """Balls touching neither raceway at standstill, and the placeholder equation X = X_static that
    replaces their indeterminate ones, weighted by K_n(α₀) × 1 µm^{1/2} [N/m]."""

    mask: jax.Array
    reference: jax.Array
    scale: jax.Array


def _free_ball_equations(bearing, operating, centres, model):
    return _FreeBalls(_free_balls(bearing, operating, centres), static_positions(bearing, centres, model),
                      free_contact_constant(bearing, model) * 1e-3)


def _with_free_balls(residual, positions, free: _FreeBalls):
    """Ball residual (Z, 2) [N], with a free ball's indeterminate equations replaced by X = X_static (scaled)."""
    return jnp.where(free.mask[:, None], (positions - free.reference) * free.scale, residual)


def _masked_residual(positions, centres, bearing, operating, model, free: _FreeBalls, constants=None):
    """`ball_residual` at `positions`, free balls' equations replaced (`_with_free_balls`)."""
    return _with_free_balls(ball_residual(positions, centres, bearing, operating, model, constants), positions, free)


def _ball_jacobians(positions, centres, bearing, operating, model, free: _FreeBalls, constants=None):
    """(Z, 2, 2) ∂g/∂X of every ball. Ball j's residual depends on X_j alone, so two JVPs with the
    same unit tangent on every ball give the two columns of all 2×2 blocks at once. With fixed
    `constants` the Hertz constants' (weak) dependence on the contact angles is left out."""
    def residual(x):
        return _masked_residual(x, centres, bearing, operating, model, free, constants)

    _, linear = jax.linearize(residual, positions)
    units = jnp.broadcast_to(jnp.eye(2)[:, None, :], (2,) + positions.shape)
    return jnp.moveaxis(jax.vmap(linear)(units), 0, -1)


def _speed_start(bearing, operating, centres, model):
    """Start for the per-ball Newton: the static split, with a ball whose inner contact is open
    pressed onto the outer raceway by its centrifugal force along the line of groove centres."""
    static = static_positions(bearing, centres, model)
    if not model.centrifugal:
        return static
    state = ball_state(bearing, operating, centres, static, model)
    pressed = (state["centrifugal_force"] / state["outer_constant"]) ** (2.0 / 3.0)
    _, outer_offset = _groove_offsets(bearing)
    approach = jnp.maximum(state["outer_approach"], pressed)
    direction = static / jnp.linalg.norm(static, axis=-1, keepdims=True)
    return direction * (outer_offset + approach)[:, None]


def _ball_newton(start, displacement, bearing: BallBearing, operating: Operating, model: BallModel):
    """(Z, 2) ball centres [m] in equilibrium with speed effects, by per-ball Newton from `start`.

    Each step holds the Hertz constants at the current contact angles in the 2×2 Jacobians; stops
    when the largest step is below `BALL_POSITION_TOLERANCE` D_w (at most `BALL_NEWTON_MAX_STEPS`;
    the ring solver checks the ball residuals). Not differentiated: see `_equilibrium_balls`.
    """
    centres = inner_groove_centres(bearing, displacement)
    free = _free_ball_equations(bearing, operating, centres, model)
    tolerance = BALL_POSITION_TOLERANCE * bearing.ball_diameter

    def newton_step(carry):
        positions, _, count = carry
        constants = hertz_constants(bearing, *_contact_angles(centres, positions), model)
        residual = _masked_residual(positions, centres, bearing, operating, model, free, constants)
        jacobian = _ball_jacobians(positions, centres, bearing, operating, model, free, constants)
        step = _limited_ball_step(bearing, jnp.linalg.solve(jacobian, residual[..., None])[..., 0])
        return positions - step, jnp.max(jnp.abs(step)), count + 1

    def not_converged(carry):
        _, largest_step, count = carry
        return (largest_step > tolerance) & (count < BALL_NEWTON_MAX_STEPS)

    positions, _, _ = jax.lax.while_loop(not_converged, newton_step, (start, jnp.inf, 0))
    return positions


@functools.partial(jax.custom_jvp, nondiff_argnums=(4,))
def _equilibrium_balls(positions, displacement, bearing: BallBearing, operating: Operating, model: BallModel):
    """`positions` (Z, 2) [m], ball centres in equilibrium at Δ, with their derivative from the implicit
    function theorem on each ball's 2×2 system (custom JVP; reverse mode by transposition)."""
    return positions


@_equilibrium_balls.defjvp
def _equilibrium_balls_jvp(model, primals, tangents):
    _, displacement, bearing, operating = primals
    # through the function itself, so that a derivative of this rule (second order) sees dX again
    positions = _equilibrium_balls(*primals, model)
    centres = inner_groove_centres(bearing, displacement)
    free = _free_ball_equations(bearing, operating, centres, model)

    def residual_of_inputs(d, b, o):
        # a free ball carries no force whatever its placeholder: hold the placeholder fixed
        return _masked_residual(positions, inner_groove_centres(b, d), b, o, model, jax.lax.stop_gradient(free))

    _, residual_dot = jax.jvp(residual_of_inputs, primals[1:], tangents[1:])
    jacobian = _ball_jacobians(positions, centres, bearing, operating, model, free)
    return positions, -jnp.linalg.solve(jacobian, residual_dot[..., None])[..., 0]


def _without_gradient(tree):
    """`tree` with every floating array leaf under `jax.lax.stop_gradient`."""
    return jax.tree.map(lambda x: jax.lax.stop_gradient(x) if eqx.is_inexact_array(x) else x, tree)


def _limited_ball_step(bearing: BallBearing, step):
    """Each ball's Newton step (Z, 2) [m], shortened to at most a tenth of the ball radius: Hertz's
    δ^{3/2} can throw a far Newton step."""
    limit = 0.05 * bearing.ball_diameter
    length = jnp.linalg.norm(step, axis=-1, keepdims=True)
    return step * jnp.minimum(1.0, limit / jnp.maximum(length, 1e-300))


def ball_positions(displacement, bearing: BallBearing, operating: Operating, model: BallModel):
    """(Z, 2) ball centres [m] in equilibrium with speed effects, for inner-ring displacement Δ.

    Per-ball Newton from `_speed_start` (`_ball_newton`), with the implicit-function derivative
    (`_equilibrium_balls`).
    """
    d, b, o = _without_gradient((displacement, bearing, operating))
    positions = _ball_newton(_speed_start(b, o, inner_groove_centres(b, d), model), d, b, o, model)
    return _equilibrium_balls(positions, displacement, bearing, operating, model)


def equilibrium_positions(displacement, bearing: BallBearing, operating: Operating, model: BallModel):
    """Ball centres (Z, 2) [m] for displacement Δ: static split, or per-ball solve with speed effects."""
    if model.speed_effects:
        return ball_positions(displacement, bearing, operating, model)
    return static_positions(bearing, inner_groove_centres(bearing, displacement), model)


def ring_force(displacement, bearing: BallBearing, operating: Operating, model: BallModel):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] the balls exert against an inner-ring displacement Δ.

    In equilibrium it equals the applied load; its Jacobian is the stiffness matrix.
    """
    centres = inner_groove_centres(bearing, displacement)
    if model.speed_effects:
        state = ball_state(bearing, operating, centres, ball_positions(displacement, bearing, operating, model), model)
    else:
        state = _static_state(bearing, operating, centres, model)
    return _ring_force_of_state(bearing, state, model)


def _ring_force_contributions(bearing: BallBearing, state: dict, model: BallModel):
    """(Z, 5) each ball's share of [Fx, Fy, Fz, Mx, My] the inner raceway exerts on the balls (ring
    equilibrium, module docstring).

    The normal force acts along the line through the inner groove centre, at radius R_i in the
    ring's plane of groove centres; the inner friction (inner-raceway control) acts at the ball's
    contact point, f_i D_w + δ_i from that centre, and adds its couple 2 M_g (f_i D_w + δ_i)/D_w
    along e_t.
    """
    psi = ball_azimuths(bearing)
    forces = contact_forces(bearing, state, model)
    axial, radial = jnp.moveaxis(forces["inner_normal"] + forces["inner_friction"], -1, 0)
    # e_t component of Σ r × F about the ring centre: −R_i F_axial, plus the friction's couple
    lever = bearing.inner_groove_ratio * bearing.ball_diameter + state["inner_approach"]
    couple = (2.0 * state["gyroscopic_moment"] * lever / bearing.ball_diameter if model.race_control == "inner"
              else jnp.zeros_like(axial))
    tangential_moment = -inner_groove_radius_of_centres(bearing) * axial + couple
    return jnp.stack([
        radial * jnp.cos(psi),
        radial * jnp.sin(psi),
        axial,
        -tangential_moment * jnp.sin(psi),
        tangential_moment * jnp.cos(psi),
    ], axis=-1)


def _ring_force_of_state(bearing: BallBearing, state: dict, model: BallModel):
    """[Fx, Fy, Fz, Mx, My] the inner raceway exerts on the balls: Σ_j `_ring_force_contributions`."""
    return jnp.sum(_ring_force_contributions(bearing, state, model), axis=0)


def _scales(bearing: BallBearing, operating: Operating, model: BallModel):
    """Unknown scale s (Δ = s·y), residual weights w (moments to forces) and load scale [N]."""
    inverse_arm = 1.0 / inner_groove_radius_of_centres(bearing)
    weight = jnp.stack([1.0, 1.0, 1.0, inverse_arm, inverse_arm])
    applied = jnp.concatenate([operating.force, operating.moment])
    # a characteristic contact load (K_n × (10 µm)^{3/2}) keeps the scale positive at zero load
    characteristic = free_contact_constant(bearing, model) * DISPLACEMENT_SCALE**1.5
    return DISPLACEMENT_SCALE * weight, weight, safe_norm(applied * weight) + characteristic


def _controls(operating: Operating):
    """(free, offset): which unknowns are solved (1) or prescribed (0), and the prescribed displacement.

    With `operating.axial_displacement` the axial displacement δz is held fixed (preload by
    displacement); otherwise every component follows from the applied load.
    """
    if operating.axial_displacement is None:
        return jnp.ones(5), jnp.zeros(5)
    return jnp.array([1.0, 1.0, 0.0, 1.0, 1.0]), jnp.zeros(5).at[2].set(operating.axial_displacement)


def _displacement(y, unknown, operating):
    free, offset = _controls(operating)
    return unknown * y * free + offset


def _static_energy(y, args):
    """Scaled potential of the static problem with K_n(α₀): Σ (2/5) K_n δ^{5/2} − F·Δ (convex in Δ);
    a prescribed component contributes ½ y² (so its unknown stays 0)."""
    bearing, operating, combined, unknown, load_scale = args
    free, _ = _controls(operating)
    displacement = _displacement(y, unknown, operating)
    centres = inner_groove_centres(bearing, displacement)
    approach = jnp.linalg.norm(centres, axis=-1) - groove_curvature_centre_distance(bearing)
    applied = jnp.concatenate([operating.force, operating.moment]) * free
    energy = 0.4 * combined * jnp.sum(positive_power(approach, 2.5)) - jnp.dot(applied, displacement)
    return energy / (load_scale * DISPLACEMENT_SCALE) + 0.5 * jnp.sum((1.0 - free) * y**2)


def _scaled_ring_residual(force, y, args):
    """(force − applied load) · w / load scale; a prescribed component's equation is replaced by its
    unknown (= 0)."""
    _, operating, _, _, weight, load_scale = args
    free, _ = _controls(operating)
    applied = jnp.concatenate([operating.force, operating.moment])
    return jnp.where(free > 0, (force - applied) * weight / load_scale, y)


def _ring_residual(y, args):
    """Scaled ring residual with the balls re-equilibrated (`ring_force`, exact Hertz constants)."""
    bearing, operating, model, unknown, _, _ = args
    return _scaled_ring_residual(ring_force(_displacement(y, unknown, operating), bearing, operating, model), y, args)


def _static_ring_residual(y, args, constants):
    """Scaled ring residual at the static split with the Hertz constants (K_i, K_o) held at `constants`."""
    bearing, operating, model, unknown, _, _ = args
    centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
    state = _static_state(bearing, operating, centres, model, constants)
    return _scaled_ring_residual(_ring_force_of_state(bearing, state, model), y, args)


def _speed_residual(y, positions, args, constants, free: _FreeBalls):
    """Residuals of the ring and ball unknowns together, with the Hertz constants held at `constants`.

    Returns each ball's scaled share of the ring residual (Z, 5) (zero for a prescribed component),
    the scaled ring residual (5) and the ball residuals (Z, 2) [N] (free balls: their placeholder).
    """
    bearing, operating, model, unknown, weight, load_scale = args
    centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
    state = ball_state(bearing, operating, centres, positions, model, constants)
    contributions = _ring_force_contributions(bearing, state, model)
    ring = _scaled_ring_residual(jnp.sum(contributions, axis=0), y, args)
    balls = _with_free_balls(sum(contact_forces(bearing, state, model).values()), positions, free)
    return contributions * (_controls(operating)[0] * weight / load_scale), ring, balls


def _ring_step(jacobian, residual):
    """Newton step J⁻¹ r (LU), J regularised by 1e-12 (max |J_kk| + 1) I (Levenberg–Marquardt form):
    at a singular J (zero load, every inner contact open) the step stays finite and, with a zero
    residual, zero."""
    guard = 1e-12 * (jnp.max(jnp.abs(jnp.diag(jacobian))) + 1.0)
    return jnp.linalg.solve(jacobian + guard * jnp.eye(jacobian.shape[0]), residual)


def _static_newton(y, args):
    """Ring Newton at the static split: (y, None, steps) (no ball unknowns).

    Each step evaluates the Hertz constants once at the current contact angles and holds them in the
    Jacobian (`jax.jacfwd`, 5 tangents), which leaves out their weak angle dependence; the residual
    itself is exact. Stops when no component of the step exceeds `RING_STEP_TOLERANCE` (1 + |y|).
    """
    bearing, operating, model, unknown, _, _ = args

    def step(carry):
        y, _, count = carry
        centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
        constants = _static_constants(bearing, centres, model)
        jacobian, residual = jax.jacfwd(lambda v: (r := _static_ring_residual(v, args, constants), r),
                                        has_aux=True)(y)
        dy = _ring_step(jacobian, residual)
        return y - dy, jnp.max(jnp.abs(dy) / (1.0 + jnp.abs(y))), count + 1

    y, _, steps = jax.lax.while_loop(_ring_not_converged, step, (y, jnp.inf, 0))
    return y, None, steps


def _speed_newton(y, args):
    """Newton on the ring and ball unknowns together (5 + 2Z): (y, ball centres (Z, 2) [m], steps).

    Starts from the static ring solution with the balls solved there (`ball_positions`). Each step evaluates the Hertz constants
    once at the current contact angles and holds them in the Jacobian, which leaves out their weak
    angle dependence; the residuals are exact. The Jacobian is block-arrow: 5 JVP tangents give the
    ring columns, and 2 tangents with the same unit on every ball give all 2×2 ball blocks and the
    5×2 couplings of each ball (ball j's residual and its share of the ring residual depend on X_j
    alone). The step follows by block elimination through the 5×5 Schur complement
    S = J_yy − Σ_j J_yXj J_XjXj⁻¹ J_Xjy (Golub & Van Loan, Matrix Computations, §3.2); each ball's
    step is limited to a tenth of its radius.
    Stops when the ring step is below `RING_STEP_TOLERANCE` (1 + |y|) and every ball step below
    `BALL_POSITION_TOLERANCE` D_w.
    """
    bearing, operating, model, unknown, _, _ = args
    count = bearing.ball_count
    ball_tolerance = BALL_POSITION_TOLERANCE * bearing.ball_diameter
    tangents = (jnp.concatenate([jnp.eye(5), jnp.zeros((2, 5))]),
                jnp.concatenate([jnp.zeros((5, count, 2)), jnp.broadcast_to(jnp.eye(2)[:, None, :], (2, count, 2))]))

    def step(carry):
        y, positions, _, steps = carry
        centres = inner_groove_centres(bearing, _displacement(y, unknown, operating))
        constants = hertz_constants(bearing, *_contact_angles(centres, positions), model)
        free = _free_ball_equations(bearing, operating, centres, model)
        (_, ring, balls), linear = jax.linearize(lambda v, x: _speed_residual(v, x, args, constants, free),
                                                 y, positions)
        d_shares, d_ring, d_balls = jax.vmap(linear)(*tangents)
        ring_ring = d_ring[:5].T  # (5, 5)
        balls_ring = jnp.moveaxis(d_balls[:5], 0, -1)  # (Z, 2, 5)
        ring_balls = jnp.moveaxis(d_shares[5:], 0, -1)  # (Z, 5, 2)
        balls_balls = jnp.moveaxis(d_balls[5:], 0, -1)  # (Z, 2, 2)
        solved = jnp.linalg.solve(balls_balls, jnp.concatenate([balls[..., None], balls_ring], axis=-1))
        schur = ring_ring - jnp.einsum("jab,jbc->ac", ring_balls, solved[..., 1:])
        dy = _ring_step(schur, ring - jnp.einsum("jab,jb->a", ring_balls, solved[..., 0]))
        dx = _limited_ball_step(bearing, solved[..., 0] - solved[..., 1:] @ dy)
        size = jnp.maximum(jnp.max(jnp.abs(dy) / (1.0 + jnp.abs(y))),
                           jnp.max(jnp.abs(dx)) * (RING_STEP_TOLERANCE / ball_tolerance))
        return y - dy, positions - dx, size, steps + 1

    start = ball_positions(_displacement(y, unknown, operating), bearing, operating, model)
    y, positions, _, steps = jax.lax.while_loop(_ring_not_converged, step, (y, start, jnp.inf, 0))
    return y, positions, steps


def _ring_not_converged(carry):
    size, steps = carry[-2:]
    return (size > RING_STEP_TOLERANCE) & (steps < RING_MAX_STEPS)


def _tangent_solve(linear, rhs):
    """Solves the linearised exact ring residual for the implicit derivative: its 5×5 Jacobian
    (`jax.jacfwd` of the linear map) by least squares, finite at a singular stiffness (pseudo-inverse)."""
    return jnp.linalg.lstsq(jax.jacfwd(linear)(rhs), rhs)[0]


class Equilibrium(eqx.Module):
    """Solution of the ring problem: displacement Δ [m, rad] and how it was reached."""

    displacement: jax.Array
    force: jax.Array  # [Fx, Fy, Fz, Mx, My] the balls exert: the applied load, and Fz under displacement control
    converged: jax.Array  # bool: residual below RESIDUAL_TOLERANCE and the state within the model
    residual: jax.Array  # max of the scaled ring residual and the relative ball residuals [-]
    approach_ratio: jax.Array  # largest contact approach / D_w [-] (ball_validity)
    contact_angle: jax.Array  # largest |contact angle| [rad] (ball_validity)
    static_steps: jax.Array
    steps: jax.Array


def solve_equilibrium(bearing: BallBearing, operating: Operating, model: BallModel = BallModel()) -> Equilibrium:
    """Inner-ring displacement Δ in equilibrium with the applied load; needs no initial guess.

    `converged` is False where the residual stays above `RESIDUAL_TOLERANCE` or the solved state lies
    outside the model (`ball_validity`: approach beyond 1 % of D_w, a contact angle beyond ±90°).

    With `operating.axial_displacement` set, δz is prescribed (preload by displacement) and the
    axial force is an output (`Equilibrium.force[2]`).

    Differentiable with respect to every array leaf of `bearing` and `operating` (implicit adjoint,
    forward and reverse mode). At a singular stiffness (zero load, or a direction the bearing does
    not resist) the adjoint uses a least-squares pseudo-inverse: finite, not a true derivative.
    """
    require_float64()
    bearing = with_constant_table(bearing, model)
    unknown, weight, load_scale = _scales(bearing, operating, model)
    static_y, _, static_steps = minimise_convex(
        _static_energy, jnp.zeros(5), (bearing, operating, free_contact_constant(bearing, model), unknown, load_scale),
        gradient_tolerance=STATIC_GRADIENT_TOLERANCE)
    static_y = jax.lax.stop_gradient(static_y)
    args = (bearing, operating, model, unknown, weight, load_scale)

    def solve(_, start):
        y, positions, steps = (_speed_newton if model.speed_effects else _static_newton)(start, args)
        return y, (positions, steps.astype(y.dtype))  # custom_root's JVP rule takes floating aux only

    # the exact ring residual defines the implicit derivative
    y, (positions, steps) = jax.lax.custom_root(functools.partial(_ring_residual, args=args), static_y, solve,
                                                _tangent_solve, has_aux=True)
    displacement = _displacement(y, unknown, operating)
    centres = inner_groove_centres(bearing, displacement)
    if model.speed_effects:
        positions = _equilibrium_balls(positions, displacement, bearing, operating, model)
        state = ball_state(bearing, operating, centres, positions, model)
    else:
        state = _static_state(bearing, operating, centres, model)
    force = _ring_force_of_state(bearing, state, model)
    ring_residual = jnp.max(jnp.abs(_scaled_ring_residual(force, y, args)))
    residual = ring_residual
    if model.speed_effects:
        ball = sum(contact_forces(bearing, state, model).values())  # ΣF of each ball at the solved state
        free = _free_balls(bearing, operating, centres)
        size = state["inner_load"] + state["outer_load"] + state["centrifugal_force"] + load_scale * 1e-6
        residual = jnp.maximum(residual, jnp.max(jnp.where(free, 0.0, jnp.max(jnp.abs(ball), axis=-1) / size)))
    residual = jax.lax.stop_gradient(residual)
    approach_ratio = jax.lax.stop_gradient(ball_validity.largest_approach_ratio(
        state["inner_approach"], state["outer_approach"], bearing.ball_diameter))
    contact_angle = jax.lax.stop_gradient(ball_validity.largest_contact_angle(state["inner_angle"], state["outer_angle"]))
    converged = (residual < RESIDUAL_TOLERANCE) & ball_validity.within_model(approach_ratio, contact_angle)
    return Equilibrium(displacement, force, converged, residual, approach_ratio, contact_angle, static_steps,
                       steps.astype(static_steps.dtype))


def stiffness_matrix(displacement, bearing: BallBearing, operating: Operating, model: BallModel = BallModel()):
    """5×5 stiffness K = dF/dΔ [N/m, N/rad; N·m/m, N·m/rad] with the balls re-equilibrated (exact, jacfwd)."""
    return jax.jacfwd(ring_force)(displacement, with_constant_table(bearing, model), operating, model)


class BallResults(eqx.Module):
    """Per-ball results at a ring displacement (SI): azimuth ψ [rad]; per raceway the contact load
    Q [N], contact angle α [rad], peak Hertz pressure p₀ [Pa] and semi-axes a, b [m]; orbital and
    spin speeds [rad/s]; centrifugal force [N] and gyroscopic moment [N·m] (None where the model
    leaves that effect out)."""

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


def ball_results(displacement, bearing: BallBearing, operating: Operating, model: BallModel = BallModel()) -> BallResults:
    """Per-ball loads, contact angles, Hertz contact sizes and pressures, kinematics at Δ (SI)."""
    bearing = with_constant_table(bearing, model)
    centres = inner_groove_centres(bearing, displacement)
    positions = equilibrium_positions(displacement, bearing, operating, model)
    s = ball_state(bearing, operating, centres, positions, model)
    modulus = ball_raceway_modulus(bearing)
    sides = {}
    for side, curvature in (("inner", inner_curvature), ("outer", outer_curvature)):
        load, angle = s[f"{side}_load"], s[f"{side}_angle"]
        contact = hertz.point_contact(load, *curvature(bearing, angle), modulus, model.hertz_method)
        sides |= {f"{side}_load": load, f"{side}_contact_angle": angle, f"{side}_max_pressure": contact.max_pressure,
                  f"{side}_semi_major_axis": contact.semi_major_axis, f"{side}_semi_minor_axis": contact.semi_minor_axis}
    return BallResults(azimuth=ball_azimuths(bearing), orbital_speed=s["orbital_speed"], spin_speed=s["spin_speed"],
                       centrifugal_force=s["centrifugal_force"] if model.centrifugal else None,
                       gyroscopic_moment=s["gyroscopic_moment"] if model.gyroscopic else None, **sides)
