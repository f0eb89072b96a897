"""A flexible shaft on several bearings: Timoshenko beam elements (`shaft_beam`) with each
bearing's nonlinear load at its node; the equilibrium of the whole shaft, each bearing's load, the
deflection line, and the stiffness at a point.

Frames and bearings as in `shaft_equilibrium`, whose rigid shaft this one becomes as its sections
stiffen. Node j carries U_j = [u_x, u_y, u_z, θ_x, θ_y] [m, rad]; bearing k sits at node n_k, so its
inner-ring displacement is Δ_k = P_k U_{n_k} + (e_k + c_k) ẑ and it takes P_k F_k(Δ_k) from its
node. With the beam's stiffness K and the loads F applied at their nodes, the shaft is in
equilibrium where

    K U + Σ_k S_kᵀ P_k F_k(Δ_k) = F          (S_k picks node n_k's five components).

The beam is linear, so the nodes without a bearing (set r) are eliminated exactly (static
condensation; Guyan, Reduction of stiffness and mass matrices, AIAA J. 3, 1965): with b the set of
the bearings' nodes,

    K_c = K_bb − K_br K_rr⁻¹ K_rb,   F_c = F_b − K_br K_rr⁻¹ F_r,   U_r = K_rr⁻¹ (F_r − K_rb U_b)

(K_rr is regular: every node reaches a bearing's node along the beam). That leaves five unknowns
per bearing node, solved as the rigid shaft's five are: the start is the minimum of the convex
energy ½ U_bᵀ K_c U_b − F_c·U_b + Σ_k E_k(Δ_k), then damped Newton on the exact residual (with
the nodes' and the rolling elements' unknowns together where a bearing carries them,
`shaft_equilibrium.solve_jointly`),
and the implicit derivative of the root.

The stiffness at node p (the load there against its displacement, every other node free and in
equilibrium) is the Schur complement onto p of the tangent stiffness
K_T = K + Σ_k S_kᵀ P_k (∂F_k/∂Δ_k) P_k S_k; K_T without p's rows and columns is regular (the beam
clamped at p), so the complement exists wherever the beam does, singular only in a direction no
bearing resists, as the rigid shaft's.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..newton import implicit_root, least_squares_tangent_solve, minimise_convex
from ..numerics import require_float64, without_gradient
from ..params import _as_float, _is_concrete
from .shaft_beam import NODE_DOFS, BeamMesh, ShaftSections, beam_mesh, node_positions, stiffness_matrix
from .shaft_equilibrium import (
    DISPLACEMENT_SCALE,
    RESIDUAL_TOLERANCE,
    STATIC_GRADIENT_TOLERANCE,
    Shaft,
    ShaftEquilibrium,
    Structure,
    damped_newton,
    elements_solved_jointly,
    energy_constants,
    local_displacement,
    shaft_scales,
    solve_jointly,
    support_constants,
    supports_balance,
    support_energy,
    support_force,
    support_stiffness,
    turned,
)


class FlexibleShaft(eqx.Module):
    """`shaft` (its bearings, loads and speed) as a Timoshenko beam of `sections`, meshed by
    `mesh` (built by `flexible_shaft`); `reference` [m] is the shaft point whose displacement and
    stiffness are reported."""

    shaft: Shaft
    sections: ShaftSections
    reference: jax.Array = eqx.field(converter=_as_float)
    mesh: BeamMesh = eqx.field(static=True, default=None)


def points(flexible: FlexibleShaft):
    """z [m] of the mesh's given points: the bearings, the loads, then the reference point."""
    shaft = flexible.shaft
    return jnp.concatenate([jnp.stack([jnp.asarray(s.position) for s in shaft.supports]),
                            jnp.asarray(shaft.loads.positions), jnp.reshape(jnp.asarray(flexible.reference), (1,))])


def shaft_mesh(sections: ShaftSections, bearing_positions, load_positions, reference=0.0, longest=None) -> BeamMesh:
    """The mesh of a shaft of `sections` with a node at every bearing, load (positions [m], concrete),
    section end and the `reference` point [m], no element longer than `longest` [m] (default the
    shaft's length / 40); its given points in that order. ValueError names a point off the shaft."""
    given = [*np.ravel(bearing_positions), *np.ravel(load_positions), reference]
    if not _is_concrete(*given):
        raise ValueError("the bearing, load and reference positions of a flexible shaft must be concrete to mesh it "
                         "(they cannot be swept or traced)")
    where = ([f"bearings[{k}].position" for k in range(np.size(bearing_positions))]
             + [f"loads[{l}].position" for l in range(np.size(load_positions))] + ["shaft.stiffness_at"])
    start, end = float(np.min(sections.starts)), float(np.max(sections.ends))
    for name, z in zip(where, np.asarray(given, dtype=float)):
        if not start - 1e-9 * (end - start) <= z <= end + 1e-9 * (end - start):
            raise ValueError(f"{name} = {z * 1e3:g} mm lies off the shaft, whose sections run from {start * 1e3:g} mm "
                             f"to {end * 1e3:g} mm")
    return beam_mesh(sections, np.asarray(given, dtype=float), longest)


def flexible_shaft(shaft: Shaft, sections: ShaftSections, reference=0.0, longest=None) -> FlexibleShaft:
    """The shaft on its bearings as a beam of `sections`, meshed by `shaft_mesh` (positions must be
    concrete: build it outside jit)."""
    mesh = shaft_mesh(sections, [s.position for s in shaft.supports], shaft.loads.positions, reference, longest)
    return FlexibleShaft(shaft, sections, reference, mesh)


def _structure(flexible: FlexibleShaft):
    """(bearing nodes b, each bearing's slot in b, the load nodes, the reference node): static."""
    count = len(flexible.shaft.supports)
    support_nodes = flexible.mesh.point_nodes[:count]
    bearing_nodes = tuple(sorted(set(support_nodes)))
    slots = tuple(bearing_nodes.index(node) for node in support_nodes)
    return bearing_nodes, slots, flexible.mesh.point_nodes[count:-1], flexible.mesh.point_nodes[-1]


def _dofs(nodes):
    return (NODE_DOFS * np.asarray(nodes, dtype=int)[:, None] + np.arange(NODE_DOFS)).reshape(-1)


def nodal_loads(flexible: FlexibleShaft):
    """F (5n,) [N, N·m]: the shaft's loads [F_x, F_y, F_z, M_x, M_y] at their nodes."""
    _, _, load_nodes, _ = _structure(flexible)
    loads = flexible.shaft.loads
    combined = jnp.concatenate([jnp.asarray(loads.forces), jnp.asarray(loads.moments)], axis=-1)
    return jnp.zeros(NODE_DOFS * flexible.mesh.node_count).at[_dofs(load_nodes)].add(combined.reshape(-1))


def condensed(flexible: FlexibleShaft):
    """(K_c, F_c, recover): the beam condensed onto its bearing nodes (module docstring), and
    U_b ↦ U, every node's displacement (n, 5)."""
    bearing_nodes, _, _, _ = _structure(flexible)
    matrix = stiffness_matrix(flexible.mesh, flexible.sections, points(flexible))
    load = nodal_loads(flexible)
    kept = _dofs(bearing_nodes)
    rest = np.setdiff1d(np.arange(matrix.shape[0]), kept)
    size = matrix.shape[0]
    if rest.size == 0:
        return matrix[np.ix_(kept, kept)], load[kept], lambda u_b: jnp.zeros(size).at[kept].set(u_b).reshape(-1, NODE_DOFS)
    solved = jnp.linalg.solve(matrix[np.ix_(rest, rest)],
                              jnp.concatenate([matrix[np.ix_(rest, kept)], load[rest][:, None]], axis=1))
    coupling = matrix[np.ix_(kept, rest)]
    stiffness = matrix[np.ix_(kept, kept)] - coupling @ solved[:, :-1]
    force = load[kept] - coupling @ solved[:, -1]

    def recover(u_b):
        u = jnp.zeros(size).at[kept].set(u_b).at[rest].set(solved[:, -1] - solved[:, :-1] @ u_b)
        return u.reshape(-1, NODE_DOFS)

    return stiffness, force, recover


def _bearing_locals(u_b, flexible: FlexibleShaft):
    _, slots, _, _ = _structure(flexible)
    nodes = u_b.reshape(-1, NODE_DOFS)
    return tuple(local_displacement(nodes[slot], support) for slot, support in zip(slots, flexible.shaft.supports))


def _static_energy(y, args):
    """Scaled ½ U_bᵀ K_c U_b − F_c·U_b + Σ_k E_k(Δ_k) (convex in U_b); args' fifth: `energy_constants`."""
    flexible, unknown, _, load_scale, constants, stiffness, force = args
    u_b = unknown * y
    energy = 0.5 * u_b @ stiffness @ u_b - force @ u_b + sum(
        support_energy(local, support, held)
        for local, support, held in zip(_bearing_locals(u_b, flexible), flexible.shaft.supports, constants))
    return energy / (load_scale * DISPLACEMENT_SCALE)


def _residual(y, args):
    """(K_c U_b − F_c + Σ_k S_kᵀ P_k F_k) · w / load scale at U_b = s·y."""
    flexible, unknown, weight, load_scale, constants, stiffness, force = args
    u_b = unknown * y
    out = stiffness @ u_b - force
    _, slots, _, _ = _structure(flexible)
    for slot, local, support, own in zip(slots, _bearing_locals(u_b, flexible), flexible.shaft.supports, constants):
        taken = turned(support) * support_force(local, support, flexible.shaft.speed, own)
        out = out.at[NODE_DOFS * slot:NODE_DOFS * (slot + 1)].add(taken)
    return out * weight / load_scale


class FlexibleShaftEquilibrium(ShaftEquilibrium):
    """The flexible shaft in equilibrium: `ShaftEquilibrium`'s fields, with `displacement` that of
    the reference point (5,) [m, rad], and the nodes' z [m] (n,) and displacements (n, 5) [m, rad]."""

    nodes: jax.Array
    node_displacements: jax.Array


def solve_flexible_shaft(flexible: FlexibleShaft) -> FlexibleShaftEquilibrium:
    """Every node's displacement in equilibrium with the loads; needs no initial guess.

    Differentiable in every array leaf of `flexible` (bearings, positions, offsets, loads, speed,
    section diameters and ends, the shaft's material; implicit adjoint)."""
    require_float64()
    shaft = flexible.shaft
    bearing_nodes, _, _, reference_node = _structure(flexible)
    constants = support_constants(shaft)
    held = energy_constants(shaft, constants)
    unknown, weight, load_scale = shaft_scales(shaft, constants, held)
    unknown, weight = jnp.tile(unknown, len(bearing_nodes)), jnp.tile(weight, len(bearing_nodes))
    stiffness, force, recover = condensed(flexible)
    start, static_steps = minimise_convex(
        _static_energy, jnp.zeros(unknown.shape[0]),
        without_gradient((flexible, unknown, weight, load_scale, held, stiffness, force)),
        gradient_tolerance=STATIC_GRADIENT_TOLERANCE)  # a start: no derivative
    args = (flexible, unknown, weight, load_scale, constants, stiffness, force)
    if not any(elements_solved_jointly(shaft.supports)):
        y, steps = implicit_root(_residual, start, args, damped_newton, least_squares_tangent_solve, has_aux=True)
        elements = (None,) * len(shaft.supports)
        residual = jax.lax.stop_gradient(jnp.max(jnp.abs(_residual(y, args))))
    else:  # the bearing nodes and the rolling elements together (`shaft_equilibrium.solve_jointly`)
        _, slots, _, _ = _structure(flexible)
        picks = jnp.eye(unknown.shape[0])
        moves = tuple(turned(support)[:, None] * picks[NODE_DOFS * slot:NODE_DOFS * (slot + 1)]
                      for slot, support in zip(slots, shaft.supports))
        y, elements, steps, residual = solve_jointly(start, shaft.supports, shaft.speed, constants,
                                                     Structure(stiffness, force, moves), unknown, weight, load_scale)
    u_b = unknown * y
    locals_ = _bearing_locals(u_b, flexible)
    residual = jnp.maximum(residual, supports_balance(shaft.supports, locals_, shaft.speed, constants, load_scale))
    forces = tuple(support_force(local, support, shaft.speed, own, state)
                   for local, support, own, state in zip(locals_, shaft.supports, constants, elements))
    nodes = recover(u_b)
    return FlexibleShaftEquilibrium(
        displacement=nodes[reference_node], bearing_displacements=locals_, bearing_forces=forces,
        converged=residual < RESIDUAL_TOLERANCE, residual=residual, static_steps=static_steps,
        steps=steps.astype(static_steps.dtype), elements=elements, constants=constants,
        nodes=node_positions(flexible.mesh, flexible.sections, points(flexible)),
        node_displacements=nodes)


def flexible_shaft_stiffness(solution: FlexibleShaftEquilibrium, flexible: FlexibleShaft):
    """5×5 stiffness [N/m, N/rad; N·m/m, N·m/rad] at the reference point: the Schur complement onto
    its node of the tangent stiffness of beam and bearings (module docstring; exact, each bearing's own
    `support_stiffness`)."""
    bearing_nodes, slots, _, reference_node = _structure(flexible)
    tangent = stiffness_matrix(flexible.mesh, flexible.sections, points(flexible))
    for slot, local, support, own, state in zip(slots, solution.bearing_displacements, flexible.shaft.supports,
                                                solution.constants, solution.elements):
        sign = turned(support)
        bearing = support_stiffness(local, support, flexible.shaft.speed, own, state)
        index = _dofs([bearing_nodes[slot]])
        tangent = tangent.at[np.ix_(index, index)].add(sign[:, None] * bearing * sign[None, :])
    kept = _dofs([reference_node])
    rest = np.setdiff1d(np.arange(tangent.shape[0]), kept)
    if rest.size == 0:
        return tangent[np.ix_(kept, kept)]
    coupling = tangent[np.ix_(kept, rest)]
    return tangent[np.ix_(kept, kept)] - coupling @ jnp.linalg.solve(tangent[np.ix_(rest, rest)],
                                                                     tangent[np.ix_(rest, kept)])
