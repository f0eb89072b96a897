"""A rigid shaft on several bearings: its 5-DOF equilibrium, reactions and system stiffness.

Frames (docs/theory.md §Shaft on several bearings). The shaft axis is z; the outer rings are fixed in
the housing. The shaft's displacement u = [u_x, u_y, u_z, θ_x, θ_y] [m, rad] is that of its point
z = 0 (small rotations). A point of the shaft at z moves by u + θ × (0, 0, z):

    δ(z) = G(z) u,   G(z) = I + z (e_x e_θyᵀ − e_y e_θxᵀ)    (δ_x = u_x + z θ_y, δ_y = u_y − z θ_x)

and a force F with moment M applied at z acts on the shaft at z = 0 as G(z)ᵀ [F, M] (its moment
grows by (0, 0, z) × F; virtual work: [F, M]·δ(z) = (Gᵀ[F, M])·u). Bearing k sits at z_k. One
mounted the other way round (orientation −1, "−z") is the same bearing turned by π about x: in its
own frame y, z and θ_y change sign, P = diag(1, −1, −1, 1, −1) (P = Pᵀ = P⁻¹). Its inner ring may be
pushed axially against its outer ring by an offset e_k in its own frame (preload by an axial
offset: `bearing_set`). At u = 0 an angular-contact or roller bearing sits at its own model's
reference (balls touching at α₀; rollers at their clearance), a deep-groove ball bearing in the
middle of its axial play, c_k = −(f_i + f_o − 1) D_w sin α₀ from there. Its inner-ring
displacement and the load it takes from the shaft are

    Δ_k = P_k G(z_k) u + (e_k + c_k) ẑ,     F_shaft,k = G(z_k)ᵀ P_k F_k(Δ_k)

with F_k the bearing's ring force (`ball_equilibrium.ring_force`, `roller_equilibrium.ring_force`:
the load on the inner ring that holds it at Δ_k, the balls or rollers re-equilibrated, speed
effects included). The shaft is in equilibrium where Σ_k F_shaft,k(u) = Σ_l G(z_l)ᵀ [F_l, M_l].

Solution, as for one bearing: the start is the minimum of the convex static energy
Σ_k E_k(Δ_k(u)) − F·u (each E_k with its contact constants at the free contact angle; no
guess needed), then damped Newton on the exact residual (dense Jacobian through the bearings'
implicit solves, regularised by 1e-12 of its diagonal so that a direction no bearing resists keeps
the step finite) — with speed effects on the shaft's and the balls' unknowns together
(`solve_jointly`) — and the implicit derivative of the root (least squares: finite where the
stiffness is singular). The system stiffness is `jax.jacfwd` of the shaft force; at another point
z_p it is G(−z_p)ᵀ K G(−z_p).

A bearing's ring speed is the shaft speed (the outer rings stand still); the quasi-static models
depend on the speed's square only, so a turned bearing runs the same.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..bearings.ball import ball_equilibrium
from ..bearings.ball.ball_equilibrium import BallModel
from ..bearings.roller import roller_equilibrium
from ..bearings.roller.roller_equilibrium import RollerModel, RollerOperating, RollerRaceways
from ..bearings.roller.roller_geometry import RollerBearing
from ..newton import guarded_solve, implicit_root, least_squares_tangent_solve, minimise_convex, newton
from ..numerics import require_float64, safe_norm, without_gradient
from ..params import BallBearing, Operating, _as_float, _is_concrete, check_range, groove_curvature_centre_distance

DISPLACEMENT_SCALE = 1e-5  # m: unit of the scaled shaft unknowns (10 µm, 10 µm / arm rad)
RESIDUAL_TOLERANCE = 1e-9  # converged when the scaled shaft residual is below
MAX_STEPS = 60
STATIC_GRADIENT_TOLERANCE = 1e-8
TURNED = np.array([1.0, -1.0, -1.0, 1.0, -1.0])  # P: a bearing turned by π about x


class BallSupport(eqx.Module):
    """A ball bearing on the shaft: at `position` z [m], `orientation` +1 ("+z": its own axial
    direction along the shaft's +z) or −1 ("−z"), inner ring pushed by `offset` [m] along its own
    axis against the outer ring (preload; 0: none)."""

    bearing: BallBearing
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: BallModel = eqx.field(static=True, default=BallModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        _check_orientation(self.orientation)


class RollerSupport(eqx.Module):
    """A roller bearing (cylindrical or tapered) on the shaft; fields as `BallSupport`."""

    bearing: RollerBearing
    raceways: RollerRaceways
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: RollerModel = eqx.field(static=True, default=RollerModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        _check_orientation(self.orientation)
        if self.bearing.kind == "cylindrical_roller" and _is_concrete(self.offset) and float(self.offset) != 0.0:
            raise ValueError("offset: a cylindrical roller bearing takes no axial preload; it must be 0")


def _check_orientation(orientation):
    if orientation not in (1, -1):
        raise ValueError(f"orientation must be +1 ('+z') or -1 ('-z'), got {orientation!r}")


class ShaftLoads(eqx.Module):
    """Loads on the shaft: at `positions` z (n,) [m], forces (n, 3) [N] and moments (n, 2) [N·m]."""

    positions: jax.Array = eqx.field(converter=_as_float)
    forces: jax.Array = eqx.field(converter=_as_float)
    moments: jax.Array = eqx.field(converter=_as_float)

    def __check_init__(self):
        count = np.shape(self.positions)
        if len(count) != 1 or np.shape(self.forces) != count + (3,) or np.shape(self.moments) != count + (2,):
            raise ValueError(f"loads: positions (n,), forces (n, 3) and moments (n, 2), got shapes "
                             f"{np.shape(self.positions)}, {np.shape(self.forces)}, {np.shape(self.moments)}")
        check_range("loads.force", self.forces, unit=" N")
        check_range("loads.moment", self.moments, unit=" N*m")


class Shaft(eqx.Module):
    """A rigid shaft on `supports` (BallSupport / RollerSupport), under `loads`, turning at
    `speed` [rad/s] with the outer rings fixed."""

    supports: tuple
    loads: ShaftLoads
    speed: jax.Array = eqx.field(converter=_as_float, default=0.0)

    def __check_init__(self):
        if not self.supports:
            raise ValueError("bearings: the shaft needs at least one bearing")
        for support in self.supports:
            if not isinstance(support, (BallSupport, RollerSupport)):
                raise ValueError(f"bearings: a support must be a BallSupport or RollerSupport, got {type(support)}")
        if all(isinstance(s, RollerSupport) and s.bearing.kind == "cylindrical_roller" for s in self.supports):
            raise ValueError("bearings: no bearing locates the shaft axially (cylindrical roller bearings carry no "
                             "axial load); add a ball or tapered roller bearing")
        check_range("shaft.speed", self.speed, unit=" rad/s")


def transfer(position):
    """G(z) (5, 5): the displacement [δx, δy, δz, θx, θy] of the shaft point at z from that at 0."""
    matrix = jnp.eye(5)
    return matrix.at[0, 4].set(position).at[1, 3].set(-position)


def turned(support):
    """P_k as its diagonal: TURNED for a bearing mounted "−z", else ones (it turns the bearing's
    own frame into the shaft's and back)."""
    return TURNED if support.orientation < 0 else np.ones(5)


def _centring(support):
    """c_k [m]: a deep-groove ball bearing sits in the middle of its axial play at u = 0,
    −(f_i + f_o − 1) D_w sin α₀ from where its balls touch at α₀ (`ball_equilibrium`'s reference);
    any other bearing at its own model's reference (0)."""
    bearing = support.bearing
    if isinstance(support, BallSupport) and bearing.kind == "deep_groove_ball":
        return -groove_curvature_centre_distance(bearing) * jnp.sin(bearing.free_contact_angle)
    return 0.0


def local_displacement(point_displacement, support):
    """Δ_k [m, rad]: the bearing's inner-ring displacement in its own frame from the displacement
    of the shaft point it sits at, P_k δ + (e_k + c_k) ẑ (module docstring)."""
    return (turned(support) * point_displacement).at[2].add(support.offset + _centring(support))


def support_displacement(shaft_displacement, support):
    """Δ_k [m, rad] of the rigid shaft's displacement u at z = 0 (module docstring)."""
    return local_displacement(transfer(support.position) @ shaft_displacement, support)


def support_move(support):
    """P_k G(z_k) (5, 5): dΔ_k/du, the bearing's inner-ring displacement per rigid-shaft displacement
    at z = 0 (`support_displacement` is P_k G(z_k) u + (e_k + c_k) ẑ)."""
    return turned(support)[:, None] * transfer(support.position)


def _operating(support, speed):
    if isinstance(support, BallSupport):
        return Operating(inner_speed=speed, outer_speed=0.0, force=jnp.zeros(3), moment=jnp.zeros(2))
    return RollerOperating(jnp.zeros(3), jnp.zeros(2), inner_speed=speed)


def support_force(local_displacement, support, speed, table=None, ball_centres=None):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] that holds the bearing's inner ring at Δ_k, in its own frame.
    `ball_centres`: a ball bearing's balls as a solve found them at Δ_k (else solved here)."""
    operating = _operating(support, speed)
    if isinstance(support, BallSupport):
        return ball_equilibrium.ring_force(local_displacement, support.bearing, operating, support.model, table,
                                           ball_centres)
    return roller_equilibrium.ring_force(local_displacement, support.bearing, support.raceways, operating,
                                         support.model)


def support_stiffness(local_displacement, support, speed, table=None, ball_centres=None):
    """K_k = dF_k/dΔ_k (5, 5) [N/m, N/rad; N·m/m, N·m/rad] of the bearing at Δ_k, in its own frame, with
    its balls re-equilibrated: a ball bearing's exact stiffness (`ball_equilibrium.stiffness_matrix`:
    with speed effects one linearisation at the balls, those the solve found where `ball_centres`
    are given); a roller bearing's `jax.jacfwd` of its ring force."""
    if isinstance(support, BallSupport):
        return ball_equilibrium.stiffness_matrix(local_displacement, support.bearing, _operating(support, speed),
                                                 support.model, ball_centres, table)
    return jax.jacfwd(support_force)(local_displacement, support, speed, table)


def reaction(shaft_displacement, support, speed, table=None, ball_centres=None):
    """G(z_k)ᵀ P_k F_k: the load the bearing takes from the shaft, moved to z = 0 [N, N·m]."""
    local = support_force(support_displacement(shaft_displacement, support), support, speed, table, ball_centres)
    return transfer(support.position).T @ (turned(support) * local)


def constant_tables(shaft: Shaft):
    """Each ball bearing's table of contact constants (`ball_equilibrium.constant_table`); None for a
    roller bearing. Supports holding the same bearing object with the same model (a matched set)
    share one table."""
    built = {}  # (id of the bearing object, model) → its table
    for support in shaft.supports:
        if isinstance(support, BallSupport) and (id(support.bearing), support.model) not in built:
            built[id(support.bearing), support.model] = ball_equilibrium.constant_table(support.bearing, support.model)
    return tuple(built[id(s.bearing), s.model] if isinstance(s, BallSupport) else None for s in shaft.supports)


def shaft_force(shaft_displacement, shaft: Shaft, tables=None, ball_centres=None):
    """Σ_k of the bearings' loads on the shaft at displacement u, about z = 0 [N, N·m]; in
    equilibrium it equals the applied load, and its Jacobian is the system stiffness.
    `ball_centres`: per bearing, its solved balls at this u (`ShaftEquilibrium.ball_centres`) or None."""
    tables = constant_tables(shaft) if tables is None else tables
    centres = (None,) * len(shaft.supports) if not ball_centres else ball_centres
    return sum(reaction(shaft_displacement, support, shaft.speed, table, balls)
               for support, table, balls in zip(shaft.supports, tables, centres))


def applied_load(shaft: Shaft):
    """Σ_l G(z_l)ᵀ [F_l, M_l] [N, N·m]: the loads on the shaft moved to z = 0."""
    loads = shaft.loads
    combined = jnp.concatenate([loads.forces, loads.moments], axis=-1)
    return jnp.einsum("lij,li->j", jax.vmap(transfer)(loads.positions), combined)


def energy_constants(shaft: Shaft, tables):
    """Per support, what its static energy holds fixed (`support_energy`): a ball bearing's combined
    contact constant K_n(α₀) [N/m^1.5] (from its table of Hertz constants, `constant_tables`), a
    roller bearing's lamina setup; evaluated once per solve, not in every trace of the energy and
    its derivatives."""
    return tuple(ball_equilibrium.free_contact_constant(s.bearing, s.model, table) if isinstance(s, BallSupport)
                 else roller_equilibrium.lamina_setup(s.bearing, s.raceways, s.model)
                 for s, table in zip(shaft.supports, tables))


def support_energy(local, support, constants):
    """E_k(Δ_k) [J] with the contact constants at the free contact angle (convex in Δ_k);
    `constants`: the support's entry of `energy_constants`."""
    if isinstance(support, BallSupport):
        return ball_equilibrium.static_energy(local, support.bearing, constants)
    return roller_equilibrium.static_energy(local, support.bearing, support.raceways, constants)


def _characteristic_load(support, table, held):
    if isinstance(support, BallSupport):
        return ball_equilibrium.characteristic_load(support.bearing, support.model, table)
    return roller_equilibrium.characteristic_load(support.bearing, held)


def _pitch_radius(support):
    bearing = support.bearing if isinstance(support, BallSupport) else support.raceways
    return 0.5 * bearing.pitch_diameter


def shaft_scales(shaft: Shaft, tables, constants):
    """Unknown scale s (u = s·y), residual weights w (moments to forces by an arm) and load scale [N]
    (the bearings' characteristic loads from their tables of Hertz constants, `constant_tables`, and
    their `energy_constants`).

    The arm is the largest of the bearings' distances from z = 0 and pitch radii."""
    arm = jnp.max(jnp.stack([jnp.maximum(jnp.abs(s.position), _pitch_radius(s)) for s in shaft.supports]))
    weight = jnp.stack([1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm])
    scale = safe_norm(applied_load(shaft) * weight) + sum(_characteristic_load(s, table, held)
                                                          for s, table, held in zip(shaft.supports, tables, constants))
    return DISPLACEMENT_SCALE * weight, weight, scale


def _static_energy(y, args):
    """Scaled potential Σ_k E_k − F·u of the static problem (convex in u); args' last: `energy_constants`."""
    shaft, unknown, _, load_scale, constants = args
    u = unknown * y
    energy = sum(support_energy(support_displacement(u, support), support, held)
                 for support, held in zip(shaft.supports, constants))
    energy = energy - jnp.dot(applied_load(shaft), u)
    return energy / (load_scale * DISPLACEMENT_SCALE)


def _residual(y, args):
    """(Σ bearing loads − applied load) · w / load scale at u = s·y."""
    shaft, unknown, weight, load_scale, tables = args
    return (shaft_force(unknown * y, shaft, tables) - applied_load(shaft)) * weight / load_scale


def damped_newton(residual, start, args):
    """(root, steps) of a shaft's scaled residual: damped Newton with Levenberg–Marquardt steps
    where it stalls, on the dense Jacobian regularised by 1e-12 of its largest diagonal entry (a
    direction no bearing resists keeps the step finite)."""
    y, steps = newton(residual, start, args, max_steps=MAX_STEPS, loop="while", guard=True, fallback=True, floor=1e-14)
    return y, steps.astype(y.dtype)


def balls_solved_jointly(supports) -> tuple[bool, ...]:
    """Per support, whether `solve_jointly` carries its balls as unknowns: a ball bearing with speed
    effects, whose balls leave the static split."""
    return tuple(isinstance(support, BallSupport) and support.model.speed_effects for support in supports)


class Structure(eqx.Module):
    """What the bearings are mounted on, linear in its unknowns U (n,) [m, rad]: its stiffness
    (n, n) and the applied load (n,) [N, N·m] (a rigid shaft's: none and the loads moved to z = 0),
    and per bearing the map `moves[k]` (5, n) to its inner ring's displacement, Δ_k = M_k U +
    (e_k + c_k) ẑ (a rigid shaft's P_k G(z_k); a flexible one's P_k times its node's five).
    In equilibrium K U − F + Σ_k M_kᵀ F_k(Δ_k) = 0."""

    stiffness: jax.Array
    load: jax.Array
    moves: tuple


def _local(unknowns, support, move):
    """Δ_k [m, rad] of the structure's displacement U: M_k U + (e_k + c_k) ẑ."""
    return move @ unknowns + local_displacement(jnp.zeros(5), support)


def structure_residual(y, supports, speed, tables, structure: Structure, unknown, weight, load_scale, ball_centres):
    """(K U − F + Σ_k M_kᵀ F_k(Δ_k)) · w / load scale at U = s·y, each bearing's balls at
    `ball_centres` where given (their implicit derivative kept), else solved at Δ_k."""
    u = unknown * y
    out = structure.stiffness @ u - structure.load
    for support, table, move, balls in zip(supports, tables, structure.moves, ball_centres):
        out = out + move.T @ support_force(_local(u, support, move), support, speed, table, balls)
    return out * weight / load_scale


def _joint_step(unknowns, args):
    """Newton step (−dy, −dX_k) of the structure and the balls of every bearing with speed effects
    together, (y, per bearing its ball centres (Z, 2) [m] or None).

    Each such bearing's balls are condensed onto its ring (`ball_equilibrium.condensed_balls`: its
    force and stiffness with the balls' equations eliminated to first order); any other bearing
    gives its ring force and stiffness (`jax.jacfwd`). The Jacobian is K + Σ_k M_kᵀ S_k M_k, and
    the balls follow the structure's step.
    """
    y, positions = unknowns
    supports, speed, tables, structure, unknown, weight, load_scale = args
    u = unknown * y
    force, stiffness, condensed = structure.stiffness @ u - structure.load, structure.stiffness, []
    for support, balls, table, move in zip(supports, positions, tables, structure.moves):
        local = _local(u, support, move)
        if balls is None:
            own = support_force(local, support, speed, table)
            own_stiffness = jax.jacfwd(support_force)(local, support, speed, table)
            condensed.append(None)
        else:
            found = ball_equilibrium.condensed_balls(local, balls, support.bearing, _operating(support, speed),
                                                     support.model, table)
            own, own_stiffness = found.condensed_force, found.condensed_stiffness
            condensed.append(found)
        force = force + move.T @ own
        stiffness = stiffness + move.T @ own_stiffness @ move
    dy = guarded_solve((weight / load_scale)[:, None] * stiffness * unknown[None, :], force * weight / load_scale)
    # the structure moves by −s·dy; each bearing's balls by −J_XX⁻¹ g − J_XX⁻¹ J_XΔ dΔ_k
    ball_steps = tuple(None if found is None else
                       -(found.ball_correction - found.ball_coupling @ (move @ (unknown * dy)))
                       for found, move in zip(condensed, structure.moves))
    return -dy, ball_steps


def _joint_solve(start, args):
    """(y, per bearing its ball centres or None, steps) of the structure and the balls together
    (`_joint_step`), from the static solution `start`, continued in speed as one bearing's ring
    solve is (`ball_equilibrium._ring_solve`): the speed rises in `ball_equilibrium.SPEED_STAGES`,
    each stage's Newton from the last one's solution, the balls from their start at the static
    solution and the first stage's speed (`ball_equilibrium.start_positions`), a stage that fails
    keeping the last solution. Without line search; each ball's step limited to a tenth of its radius
    (`ball_equilibrium.limited_ball_step`); each stage stops when every structure step component
    is below `ball_equilibrium.RING_STEP_TOLERANCE` (1 + |y|) and every ball step below
    `ball_equilibrium.BALL_POSITION_TOLERANCE` D_w."""
    supports, speed, tables, structure, unknown, weight, load_scale = args
    fractions = jnp.asarray(ball_equilibrium.SPEED_STAGES)
    jointly = balls_solved_jointly(supports)
    positions = tuple(ball_equilibrium.start_positions(_local(unknown * start, support, move), support.bearing,
                                                       _operating(support, fractions[0] * speed), support.model, table)
                      if joint else None
                      for support, table, move, joint in zip(supports, tables, structure.moves, jointly))

    def per_bearing(value):
        return tuple(value(support) if joint else None for support, joint in zip(supports, jointly))

    ring = ball_equilibrium.RING_STEP_TOLERANCE
    tolerance = ((ring, per_bearing(lambda s: ball_equilibrium.BALL_POSITION_TOLERANCE * s.bearing.ball_diameter)),
                 (ring, per_bearing(lambda s: 0.0)))

    def limit(step):
        return step[0], tuple(None if balls is None else ball_equilibrium.limited_ball_step(support.bearing, balls)
                              for support, balls in zip(supports, step[1]))

    def stage(unknowns, fraction):
        staged = (supports, fraction * speed, tables, structure, unknown, weight, load_scale)
        solved, steps = newton(None, unknowns, staged, linear_step=_joint_step, limit=limit, step_tolerance=tolerance,
                               max_steps=ball_equilibrium.RING_MAX_STEPS, loop="while", line_search=False)
        reached = ((steps < ball_equilibrium.RING_MAX_STEPS)
                   & jnp.all(jnp.stack([jnp.all(jnp.isfinite(x)) for x in jax.tree.leaves(solved)])))
        return jax.tree.map(lambda new, old: jnp.where(reached, new, old), solved, unknowns), steps

    (y, positions), steps = jax.lax.scan(stage, (start, positions), fractions)
    return y, positions, jnp.sum(steps).astype(y.dtype)


def _residual_at_balls(y, args):
    supports, speed, tables, structure, unknown, weight, load_scale, centres = args
    return structure_residual(y, supports, speed, tables, structure, unknown, weight, load_scale, centres)


def solve_jointly(start, supports, speed, tables, structure: Structure, unknown, weight, load_scale):
    """(y, ball centres per bearing (None where not carried), steps, largest residual) of bearings
    with speed effects on a linear structure: the structure's unknowns and every such bearing's
    ball centres solved together (`_joint_solve`) from the static solution `start` (scaled,
    U = s·y), the root's derivative taken at the solved balls (their implicit derivative: no ball
    Newton traced but the start's). The residual is the largest of the scaled structure residual
    and each ball's own relative balance (`ball_equilibrium.relative_ball_residual`).

    Solving each bearing's balls inside every step of the structure's Newton instead (a ring force
    of Δ_k alone, `support_force`) makes that force jump where a ball, released by its inner ring,
    drops to the bottom of its outer groove, and the Newton stalls there (measured: a preloaded
    back-to-back pair at 2.3e4 r/min under random loads, residual 0.13; solved together it
    converges in 24 steps)."""
    args = (supports, speed, tables, structure, unknown, weight, load_scale)
    solved, centres, steps = _joint_solve(start, without_gradient(args))  # the root's derivative is implicit
    args = (*args, centres)
    y = implicit_root(_residual_at_balls, solved, args, lambda residual, guess, args: guess,
                      least_squares_tangent_solve)
    residual = jnp.max(jnp.abs(_residual_at_balls(y, args)))
    for support, table, move, balls in zip(supports, tables, structure.moves, centres):
        if balls is not None:  # each ball's own balance, as one bearing's solve checks it
            operating = _operating(support, speed)
            grooves = ball_equilibrium.inner_groove_centres(support.bearing, _local(unknown * y, support, move))
            state = ball_equilibrium.ball_state(support.bearing, operating, grooves, balls, support.model, table=table)
            residual = jnp.maximum(residual, ball_equilibrium.relative_ball_residual(
                support.bearing, operating, grooves, state, support.model, load_scale))
    return y, centres, steps, jax.lax.stop_gradient(residual)


class ShaftEquilibrium(eqx.Module):
    """The shaft in equilibrium: its displacement u at z = 0 [m, rad]; per bearing (tuples in the
    order of `Shaft.supports`) the inner-ring displacement in its own frame [m, rad] and the load
    it carries, [Fx, Fy, Fz, Mx, My] in its own frame [N, N·m]; whether it converged (scaled
    residual below `RESIDUAL_TOLERANCE`), the residual [-] and the Newton steps; per bearing its
    balls' centres (Z, 2) [m] where the solve carried them (ball bearings with speed effects; else
    None): hand them to `shaft_stiffness` and `ball_equilibrium.ball_results`, which then solve no
    balls of their own; and per bearing the table of Hertz constants the solve built (None for a
    roller bearing or constants held at α₀), likewise for `shaft_stiffness` and `ball_results`."""

    displacement: jax.Array
    bearing_displacements: tuple
    bearing_forces: tuple
    converged: jax.Array
    residual: jax.Array
    static_steps: jax.Array
    steps: jax.Array
    ball_centres: tuple
    constant_tables: tuple


def solve_shaft(shaft: Shaft) -> ShaftEquilibrium:
    """Shaft displacement u in equilibrium with the loads on it; needs no initial guess.

    Differentiable in every array leaf of `shaft` (bearings, positions, offsets, loads, speed;
    implicit adjoint, least squares where the system stiffness is singular).
    """
    require_float64()
    tables = constant_tables(shaft)
    constants = energy_constants(shaft, tables)
    unknown, weight, load_scale = shaft_scales(shaft, tables, constants)
    start, static_steps = minimise_convex(_static_energy, jnp.zeros(5),
                                          without_gradient((shaft, unknown, weight, load_scale, constants)),
                                          gradient_tolerance=STATIC_GRADIENT_TOLERANCE)  # a start: no derivative
    args = (shaft, unknown, weight, load_scale, tables)
    if not any(balls_solved_jointly(shaft.supports)):
        y, steps = implicit_root(_residual, start, args, damped_newton, least_squares_tangent_solve, has_aux=True)
        centres = (None,) * len(shaft.supports)
        residual = jax.lax.stop_gradient(jnp.max(jnp.abs(_residual(y, args))))
    else:  # the shaft and the balls together
        structure = Structure(jnp.zeros((5, 5)), applied_load(shaft), tuple(map(support_move, shaft.supports)))
        y, centres, steps, residual = solve_jointly(start, shaft.supports, shaft.speed, tables, structure, unknown,
                                                    weight, load_scale)
    u = unknown * y
    locals_ = tuple(support_displacement(u, support) for support in shaft.supports)
    forces = tuple(support_force(local, support, shaft.speed, table, balls)
                   for local, support, table, balls in zip(locals_, shaft.supports, tables, centres))
    return ShaftEquilibrium(u, locals_, forces, residual < RESIDUAL_TOLERANCE, residual, static_steps,
                            steps.astype(static_steps.dtype), centres, tables)


def shaft_stiffness(shaft_displacement, shaft: Shaft, at=0.0, ball_centres=None, tables=None):
    """5×5 system stiffness [N/m, N/rad; N·m/m, N·m/rad] at the shaft point z = `at` [m]: the
    Jacobian of the bearings' loads with respect to that point's displacement (exact), Σ_k G_kᵀ P_k
    K_k P_k G_k with each bearing's own K_k (`support_stiffness`; P_k G_k: `support_move`).
    `ball_centres`: the solve's balls (`ShaftEquilibrium.ball_centres`; else solved here);
    `tables`: the solve's (`ShaftEquilibrium.constant_tables`; else built here)."""
    tables = constant_tables(shaft) if tables is None else tables
    centres = (None,) * len(shaft.supports) if not ball_centres else ball_centres
    stiffness = jnp.zeros((5, 5))
    for support, table, balls in zip(shaft.supports, tables, centres):
        own = support_stiffness(support_displacement(shaft_displacement, support), support, shaft.speed, table, balls)
        stiffness = stiffness + support_move(support).T @ own @ support_move(support)
    back = transfer(-jnp.asarray(at, dtype=float))
    return back.T @ stiffness @ back
