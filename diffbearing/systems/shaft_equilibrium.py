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
offset: `bearing_set`). At u = 0 a bearing sits c_k from its own model's reference
(`AbstractSupport.reference_offset`: 0 for an angular-contact or roller bearing, the middle of a
deep-groove ball bearing's axial play). Its inner-ring displacement and the load it takes from the
shaft are

    Δ_k = P_k G(z_k) u + (e_k + c_k) ẑ,     F_shaft,k = G(z_k)ᵀ P_k F_k(Δ_k)

with F_k the bearing's ring force (`AbstractSupport.ring_force`, bearings/interface.py: the load
on the inner ring that holds it at Δ_k, the balls or rollers re-equilibrated, speed effects
included); the shaft sees its bearings through that interface alone. The shaft is in
equilibrium where Σ_k F_shaft,k(u) = Σ_l G(z_l)ᵀ [F_l, M_l].

Solution, as for one bearing: the start is the minimum of the convex static energy
Σ_k E_k(Δ_k(u)) − F·u (each E_k the bearing's own; no guess needed), then damped Newton on the
exact residual (dense Jacobian through the bearings' implicit solves, regularised by 1e-12 of
its diagonal so that a direction no bearing resists keeps the step finite) — where a bearing
carries its rolling elements' state (a ball bearing with speed effects), on the shaft's and the
elements' unknowns together (`solve_jointly`) — and the implicit derivative of the root (least
squares: finite where the stiffness is singular). The system stiffness is Σ_k G_kᵀ P_k K_k P_k G_k
with each bearing's own K_k; at another point z_p it is G(−z_p)ᵀ K G(−z_p).

A bearing's ring speed is the shaft speed (the outer rings stand still); the quasi-static models
depend on the speed's square only, so a turned bearing runs the same.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..bearings.interface import (
    RING_MAX_STEPS,
    RING_STEP_TOLERANCE,
    SPEED_STAGES,
    AbstractSupport,
    local_displacement,
    support_displacement,
    support_move,
    transfer,
    turned,
)
from ..newton import guarded_solve, implicit_root, least_squares_tangent_solve, minimise_convex, newton
from ..numerics import require_float64, safe_norm, without_gradient
from ..params import _as_float, check_range

DISPLACEMENT_SCALE = 1e-5  # m: unit of the scaled shaft unknowns (10 µm, 10 µm / arm rad)
RESIDUAL_TOLERANCE = 1e-9  # converged when the scaled shaft residual is below
MAX_STEPS = 60
STATIC_GRADIENT_TOLERANCE = 1e-8


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
    """A rigid shaft on `supports` (each an `AbstractSupport`: `BallSupport`, `RollerSupport`, …),
    under `loads`, turning at `speed` [rad/s] with the outer rings fixed."""

    supports: tuple
    loads: ShaftLoads
    speed: jax.Array = eqx.field(converter=_as_float, default=0.0)

    def __check_init__(self):
        if not self.supports:
            raise ValueError("bearings: the shaft needs at least one bearing")
        for support in self.supports:
            if not isinstance(support, AbstractSupport):
                raise ValueError(f"bearings: a support must be an AbstractSupport (BallSupport, RollerSupport, …), "
                                 f"got {type(support)}")
        if not any(support.locates_axially() for support in self.supports):
            raise ValueError("bearings: no bearing locates the shaft axially (cylindrical roller bearings carry no "
                             "axial load); add a ball or tapered roller bearing")
        check_range("shaft.speed", self.speed, unit=" rad/s")


def support_force(local_displacement, support: AbstractSupport, speed, constants=None, elements=None):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] that holds the bearing's inner ring at Δ_k, in its own frame
    (`AbstractSupport.ring_force`). `elements`: the state of its rolling elements as a solve found
    them at Δ_k (else re-equilibrated here)."""
    return support.ring_force(local_displacement, speed, constants, elements)


def support_stiffness(local_displacement, support: AbstractSupport, speed, constants=None, elements=None):
    """K_k = dF_k/dΔ_k (5, 5) [N/m, N/rad; N·m/m, N·m/rad] of the bearing at Δ_k, in its own frame, with
    its rolling elements re-equilibrated (`AbstractSupport.ring_stiffness`: a ball bearing's exact
    stiffness, at the balls the solve found where `elements` are given)."""
    return support.ring_stiffness(local_displacement, speed, constants, elements)


def reaction(shaft_displacement, support, speed, constants=None, elements=None):
    """G(z_k)ᵀ P_k F_k: the load the bearing takes from the shaft, moved to z = 0 [N, N·m]."""
    local = support_force(support_displacement(shaft_displacement, support), support, speed, constants, elements)
    return transfer(support.position).T @ (turned(support) * local)


def support_constants(shaft: Shaft):
    """Each bearing's constants for a solve (`AbstractSupport.constants`: a ball bearing's table of
    Hertz constants, None for a roller bearing), built once; supports with the same
    `constants_key` (a matched set's bearings: the same bearing object and model) share them."""
    keys = [("own", id(support)) if support.constants_key() is None else support.constants_key()
            for support in shaft.supports]
    built = {}
    for key, support in zip(keys, shaft.supports):
        if key not in built:
            built[key] = support.constants()
    return tuple(built[key] for key in keys)


def shaft_force(shaft_displacement, shaft: Shaft, constants=None, elements=None):
    """Σ_k of the bearings' loads on the shaft at displacement u, about z = 0 [N, N·m]; in
    equilibrium it equals the applied load, and its Jacobian is the system stiffness.
    `elements`: per bearing, its solved rolling elements at this u (`ShaftEquilibrium.elements`) or None."""
    constants = support_constants(shaft) if constants is None else constants
    elements = (None,) * len(shaft.supports) if not elements else elements
    return sum(reaction(shaft_displacement, support, shaft.speed, own, state)
               for support, own, state in zip(shaft.supports, constants, elements))


def applied_load(shaft: Shaft):
    """Σ_l G(z_l)ᵀ [F_l, M_l] [N, N·m]: the loads on the shaft moved to z = 0."""
    loads = shaft.loads
    combined = jnp.concatenate([loads.forces, loads.moments], axis=-1)
    return jnp.einsum("lij,li->j", jax.vmap(transfer)(loads.positions), combined)


def energy_constants(shaft: Shaft, constants):
    """Per support, what its static energy holds fixed (`AbstractSupport.energy_constants`: a ball
    bearing's combined contact constant K_n(α₀) [N/m^1.5], a roller bearing's lamina setup);
    evaluated once per solve, not in every trace of the energy and its derivatives."""
    return tuple(support.energy_constants(own) for support, own in zip(shaft.supports, constants))


def support_energy(local, support: AbstractSupport, held):
    """E_k(Δ_k) [J], convex in Δ_k (`AbstractSupport.static_energy`); `held`: the support's entry
    of `energy_constants`."""
    return support.static_energy(local, held)


def shaft_scales(shaft: Shaft, constants, held):
    """Unknown scale s (u = s·y), residual weights w (moments to forces by an arm) and load scale [N]
    (the bearings' characteristic loads from their `support_constants` and `energy_constants`).

    The arm is the largest of the bearings' distances from z = 0 and pitch radii."""
    arm = jnp.max(jnp.stack([jnp.maximum(jnp.abs(s.position), s.pitch_radius()) for s in shaft.supports]))
    weight = jnp.stack([1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm])
    scale = safe_norm(applied_load(shaft) * weight) + sum(s.characteristic_load(own, energy)
                                                          for s, own, energy in zip(shaft.supports, constants, held))
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
    shaft, unknown, weight, load_scale, constants = args
    return (shaft_force(unknown * y, shaft, constants) - applied_load(shaft)) * weight / load_scale


def damped_newton(residual, start, args):
    """(root, steps) of a shaft's scaled residual: damped Newton with Levenberg–Marquardt steps
    where it stalls, on the dense Jacobian regularised by 1e-12 of its largest diagonal entry (a
    direction no bearing resists keeps the step finite)."""
    y, steps = newton(residual, start, args, max_steps=MAX_STEPS, loop="while", guard=True, fallback=True, floor=1e-14)
    return y, steps.astype(y.dtype)


def elements_solved_jointly(supports) -> tuple[bool, ...]:
    """Per support, whether `solve_jointly` carries its rolling elements' state as unknowns
    (`AbstractSupport.carries_elements`: a ball bearing with speed effects, whose balls leave the
    static split)."""
    return tuple(support.carries_elements() for support in supports)


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


def structure_residual(y, supports, speed, constants, structure: Structure, unknown, weight, load_scale, elements):
    """(K U − F + Σ_k M_kᵀ F_k(Δ_k)) · w / load scale at U = s·y, each bearing's rolling elements
    at `elements` where given (their implicit derivative kept), else re-equilibrated at Δ_k."""
    u = unknown * y
    out = structure.stiffness @ u - structure.load
    for support, own, move, state in zip(supports, constants, structure.moves, elements):
        out = out + move.T @ support_force(_local(u, support, move), support, speed, own, state)
    return out * weight / load_scale


def _joint_step(unknowns, args):
    """Newton step (−dy, −dX_k) of the structure and the rolling elements of every bearing that
    carries them together, (y, per bearing its elements' state or None).

    Each such bearing's elements are condensed onto its ring (`AbstractSupport.condensed`: its
    force and stiffness with the elements' equations eliminated to first order); any other
    bearing gives its ring force and stiffness. The Jacobian is K + Σ_k M_kᵀ S_k M_k, and the
    elements follow the structure's step.
    """
    y, states = unknowns
    supports, speed, constants, structure, unknown, weight, load_scale = args
    u = unknown * y
    force, stiffness, condensed = structure.stiffness @ u - structure.load, structure.stiffness, []
    for support, state, own, move in zip(supports, states, constants, structure.moves):
        local = _local(u, support, move)
        if state is None:
            own_force = support_force(local, support, speed, own)
            own_stiffness = support_stiffness(local, support, speed, own)
            condensed.append(None)
        else:
            found = support.condensed(local, state, speed, own)
            own_force, own_stiffness = found.force, found.stiffness
            condensed.append(found)
        force = force + move.T @ own_force
        stiffness = stiffness + move.T @ own_stiffness @ move
    dy = guarded_solve((weight / load_scale)[:, None] * stiffness * unknown[None, :], force * weight / load_scale)
    # the structure moves by −s·dy; each bearing's elements by −J_XX⁻¹ g − J_XX⁻¹ J_XΔ dΔ_k
    element_steps = tuple(None if found is None else
                          -(found.correction - found.coupling @ (move @ (unknown * dy)))
                          for found, move in zip(condensed, structure.moves))
    return -dy, element_steps


def _joint_solve(start, args):
    """(y, per bearing its elements' state or None, steps) of the structure and the rolling
    elements together (`_joint_step`), from the static solution `start`, continued in speed as one
    bearing's ring solve is: the speed rises in `SPEED_STAGES` (bearings/interface.py), each
    stage's Newton from the last one's solution, the elements from their start at the static
    solution and the first stage's speed (`AbstractSupport.start_elements`), a stage that fails
    keeping the last solution. Without line search; each element step limited as its type says
    (`AbstractSupport.limit_element_step`); each stage stops when every structure step component
    is below `RING_STEP_TOLERANCE` (1 + |y|) and every element step below its type's
    `element_tolerance`."""
    supports, speed, constants, structure, unknown, weight, load_scale = args
    fractions = jnp.asarray(SPEED_STAGES)
    jointly = elements_solved_jointly(supports)
    states = tuple(support.start_elements(_local(unknown * start, support, move), fractions[0] * speed, own)
                   if joint else None
                   for support, own, move, joint in zip(supports, constants, structure.moves, jointly))

    def per_bearing(value):
        return tuple(value(support) if joint else None for support, joint in zip(supports, jointly))

    tolerance = ((RING_STEP_TOLERANCE, per_bearing(lambda s: s.element_tolerance())),
                 (RING_STEP_TOLERANCE, per_bearing(lambda s: 0.0)))

    def limit(step):
        return step[0], tuple(None if state is None else support.limit_element_step(state)
                              for support, state in zip(supports, step[1]))

    def stage(unknowns, fraction):
        staged = (supports, fraction * speed, constants, structure, unknown, weight, load_scale)
        solved, steps = newton(None, unknowns, staged, linear_step=_joint_step, limit=limit, step_tolerance=tolerance,
                               max_steps=RING_MAX_STEPS, loop="while", line_search=False)
        reached = ((steps < RING_MAX_STEPS)
                   & jnp.all(jnp.stack([jnp.all(jnp.isfinite(x)) for x in jax.tree.leaves(solved)])))
        return jax.tree.map(lambda new, old: jnp.where(reached, new, old), solved, unknowns), steps

    (y, states), steps = jax.lax.scan(stage, (start, states), fractions)
    return y, states, jnp.sum(steps).astype(y.dtype)


def _residual_at_elements(y, args):
    supports, speed, constants, structure, unknown, weight, load_scale, elements = args
    return structure_residual(y, supports, speed, constants, structure, unknown, weight, load_scale, elements)


def solve_jointly(start, supports, speed, constants, structure: Structure, unknown, weight, load_scale):
    """(y, elements' state per bearing (None where not carried), steps, largest residual) of
    bearings that carry their rolling elements on a linear structure: the structure's unknowns and
    every such bearing's elements solved together (`_joint_solve`) from the static solution `start`
    (scaled, U = s·y), the root's derivative taken at the solved elements (their implicit
    derivative: no element Newton traced but the start's). The residual is the largest of the
    scaled structure residual and each bearing's own element balance
    (`AbstractSupport.element_residual`).

    Solving each bearing's balls inside every step of the structure's Newton instead (a ring force
    of Δ_k alone, `support_force`) makes that force jump where a ball, released by its inner ring,
    drops to the bottom of its outer groove, and the Newton stalls there (measured: a preloaded
    back-to-back pair at 2.3e4 r/min under random loads, residual 0.13; solved together it
    converges in 24 steps)."""
    args = (supports, speed, constants, structure, unknown, weight, load_scale)
    solved, elements, steps = _joint_solve(start, without_gradient(args))  # the root's derivative is implicit
    args = (*args, elements)
    y = implicit_root(_residual_at_elements, solved, args, lambda residual, guess, args: guess,
                      least_squares_tangent_solve)
    residual = jnp.max(jnp.abs(_residual_at_elements(y, args)))
    for support, own, move, state in zip(supports, constants, structure.moves, elements):
        if state is not None:
            residual = jnp.maximum(residual, support.element_residual(_local(unknown * y, support, move), state, speed,
                                                                      own, load_scale))
    return y, elements, steps, jax.lax.stop_gradient(residual)


class ShaftEquilibrium(eqx.Module):
    """The shaft in equilibrium: its displacement u at z = 0 [m, rad]; per bearing (tuples in the
    order of `Shaft.supports`) the inner-ring displacement in its own frame [m, rad] and the load
    it carries, [Fx, Fy, Fz, Mx, My] in its own frame [N, N·m]; whether it converged (scaled
    residual below `RESIDUAL_TOLERANCE`), the residual [-] and the Newton steps; per bearing its
    rolling elements' state where the solve carried them (a ball bearing with speed effects: its
    balls' centres (Z, 2) [m]; else None): hand them to `shaft_stiffness` and the type's results
    (`ball_equilibrium.ball_results`), which then solve no elements of their own; and per bearing
    the constants the solve built (`AbstractSupport.constants`: a ball bearing's table of Hertz
    constants, None for a roller bearing or constants held at α₀), likewise."""

    displacement: jax.Array
    bearing_displacements: tuple
    bearing_forces: tuple
    converged: jax.Array
    residual: jax.Array
    static_steps: jax.Array
    steps: jax.Array
    elements: tuple
    constants: tuple


def solve_shaft(shaft: Shaft) -> ShaftEquilibrium:
    """Shaft displacement u in equilibrium with the loads on it; needs no initial guess.

    Differentiable in every array leaf of `shaft` (bearings, positions, offsets, loads, speed;
    implicit adjoint, least squares where the system stiffness is singular).
    """
    require_float64()
    constants = support_constants(shaft)
    held = energy_constants(shaft, constants)
    unknown, weight, load_scale = shaft_scales(shaft, constants, held)
    start, static_steps = minimise_convex(_static_energy, jnp.zeros(5),
                                          without_gradient((shaft, unknown, weight, load_scale, held)),
                                          gradient_tolerance=STATIC_GRADIENT_TOLERANCE)  # a start: no derivative
    args = (shaft, unknown, weight, load_scale, constants)
    if not any(elements_solved_jointly(shaft.supports)):
        y, steps = implicit_root(_residual, start, args, damped_newton, least_squares_tangent_solve, has_aux=True)
        elements = (None,) * len(shaft.supports)
        residual = jax.lax.stop_gradient(jnp.max(jnp.abs(_residual(y, args))))
    else:  # the shaft and the rolling elements together
        structure = Structure(jnp.zeros((5, 5)), applied_load(shaft), tuple(map(support_move, shaft.supports)))
        y, elements, steps, residual = solve_jointly(start, shaft.supports, shaft.speed, constants, structure, unknown,
                                                     weight, load_scale)
    u = unknown * y
    locals_ = tuple(support_displacement(u, support) for support in shaft.supports)
    residual = jnp.maximum(residual, supports_balance(shaft.supports, locals_, shaft.speed, constants, load_scale))
    forces = tuple(support_force(local, support, shaft.speed, own, state)
                   for local, support, own, state in zip(locals_, shaft.supports, constants, elements))
    return ShaftEquilibrium(u, locals_, forces, residual < RESIDUAL_TOLERANCE, residual, static_steps,
                            steps.astype(static_steps.dtype), elements, constants)


def supports_balance(supports, local_displacements, speed, constants, load_scale):
    """The largest of the bearings' own balance residuals at their solved displacements
    (`AbstractSupport.balance_residual`), without derivative."""
    return jax.lax.stop_gradient(jnp.max(jnp.stack([
        support.balance_residual(local, speed, own, load_scale)
        for support, local, own in zip(supports, local_displacements, constants)])))


def shaft_stiffness(shaft_displacement, shaft: Shaft, at=0.0, elements=None, constants=None):
    """5×5 system stiffness [N/m, N/rad; N·m/m, N·m/rad] at the shaft point z = `at` [m]: the
    Jacobian of the bearings' loads with respect to that point's displacement (exact), Σ_k G_kᵀ P_k
    K_k P_k G_k with each bearing's own K_k (`support_stiffness`; P_k G_k: `support_move`).
    `elements`: the solve's rolling elements (`ShaftEquilibrium.elements`; else re-equilibrated
    here); `constants`: the solve's (`ShaftEquilibrium.constants`; else built here)."""
    constants = support_constants(shaft) if constants is None else constants
    elements = (None,) * len(shaft.supports) if not elements else elements
    stiffness = jnp.zeros((5, 5))
    for support, own, state in zip(shaft.supports, constants, elements):
        local, move = support_displacement(shaft_displacement, support), support_move(support)
        stiffness = stiffness + move.T @ support_stiffness(local, support, shaft.speed, own, state) @ move
    back = transfer(-jnp.asarray(at, dtype=float))
    return back.T @ stiffness @ back
