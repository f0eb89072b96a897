"""Timoshenko beam elements of a stepped shaft: the linear stiffness of a shaft of circular, solid
or hollow, sections, in the five degrees of freedom per node of `shaft_equilibrium`.

A node carries [u_x, u_y, u_z, θ_x, θ_y] [m, rad] (a rigid motion moves the point z by
δ_x = u_x + z θ_y, δ_y = u_y − z θ_x): in the x–z plane the deflection w = u_x has the section
rotation φ = θ_y, in the y–z plane w = u_y has φ = −θ_x. An element of length L, modulus E, shear
modulus G = E / (2(1 + ν)), area A = π(D² − d²)/4, second moment I = π(D⁴ − d⁴)/64 and shear
coefficient κ has in (w₁, φ₁, w₂, φ₂) of each plane (Przemieniecki, Theory of Matrix Structural
Analysis, 1968, §5.6, eq. 5.116)

    K = EI / ((1 + Φ) L³) ⎡ 12    6L          −12   6L        ⎤      Φ = 12 EI / (κ G A L²)
                          ⎢ 6L    (4 + Φ)L²   −6L   (2 − Φ)L² ⎥
                          ⎢ −12   −6L         12    −6L       ⎥
                          ⎣ 6L    (2 − Φ)L²   −6L   (4 + Φ)L² ⎦

and along z the bar EA/L [[1, −1], [−1, 1]]. With no load between its nodes the element's
deflection solves Timoshenko's beam equations exactly, so the nodal displacements are exact for
loads at nodes, whatever the element length. The shear coefficient of a hollow circular section,
m = d/D (Cowper, The shear coefficient in Timoshenko's beam theory, J. Appl. Mech. 33, 1966,
Table 1):

    κ = 6 (1 + ν)(1 + m²)² / ((7 + 6ν)(1 + m²)² + (20 + 12ν) m²).

Not modelled: torsion (no degree of freedom about z), the shaft's own weight and inertia (loads
act at points), the stiffening of a section by a fitted ring.

The mesh (`beam_mesh`) puts a node at every section end and every given point (bearings, loads,
the point where the stiffness is wanted) and divides each interval into equal elements no longer
than `longest` (for the deflection line between the points; the nodal values do not depend on
it). A node's position is stored as a key point plus a fraction of the interval to the next, so
the stiffness stays differentiable in the section ends and the points' positions.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..params import Material, _as_float, _is_concrete, check_range

NODE_DOFS = 5
MERGE = 1e-9  # relative to the shaft's length: points closer than this share a node


class ShaftSections(eqx.Module):
    """The sections of a stepped shaft: section i runs from `starts[i]` to `ends[i]` [m] along z,
    with outside diameter `outer_diameters[i]` and bore `inner_diameters[i]` [m] (0: solid), all of
    `material`. Together they cover one interval without gaps or overlaps."""

    starts: jax.Array = eqx.field(converter=_as_float)
    ends: jax.Array = eqx.field(converter=_as_float)
    outer_diameters: jax.Array = eqx.field(converter=_as_float)
    inner_diameters: jax.Array = eqx.field(converter=_as_float)
    material: Material

    def __check_init__(self):
        count = np.shape(self.starts)
        if len(count) != 1 or count[0] == 0 or any(np.shape(a) != count for a in
                                                   (self.ends, self.outer_diameters, self.inner_diameters)):
            shapes = [np.shape(a) for a in (self.starts, self.ends, self.outer_diameters, self.inner_diameters)]
            raise ValueError("shaft.sections: starts, ends, outer and inner diameters must be 1-D arrays of one "
                             f"length ≥ 1, got shapes {shapes}")
        check_range("shaft.sections.outer_diameter", self.outer_diameters, low=0.0, unit=" m")
        check_range("shaft.sections.inner_diameter", self.inner_diameters, low=0.0, low_open=False, unit=" m")
        if not _is_concrete(self.starts, self.ends, self.outer_diameters, self.inner_diameters):
            return
        starts, ends = np.asarray(self.starts), np.asarray(self.ends)
        if np.any(ends <= starts):
            index = int(np.argmax(ends <= starts))
            raise ValueError(f"shaft.sections[{index}]: its end ({ends[index]:g} m) must lie beyond its start "
                             f"({starts[index]:g} m)")
        if np.any(np.asarray(self.inner_diameters) >= np.asarray(self.outer_diameters)):
            index = int(np.argmax(np.asarray(self.inner_diameters) >= np.asarray(self.outer_diameters)))
            raise ValueError(f"shaft.sections[{index}].inner_diameter must be < its outer_diameter")
        order = np.argsort(starts)
        gaps = starts[order][1:] - ends[order][:-1]
        tolerance = MERGE * (ends.max() - starts.min())
        if np.any(np.abs(gaps) > tolerance):
            index = int(order[1:][np.argmax(np.abs(gaps) > tolerance)])
            raise ValueError(f"shaft.sections[{index}]: starts at {starts[index]:g} m, where no other section ends; "
                             "the sections must follow each other without gaps or overlaps")


def shear_coefficient(diameter_ratio, poisson_ratio):
    """Timoshenko shear coefficient κ [-] of a hollow circular section with bore/outside diameter
    ratio m (Cowper 1966, Table 1; module docstring): 6(1 + ν)/(7 + 6ν) for a solid one."""
    m2 = diameter_ratio**2
    return 6.0 * (1.0 + poisson_ratio) * (1.0 + m2)**2 / (
        (7.0 + 6.0 * poisson_ratio) * (1.0 + m2)**2 + (20.0 + 12.0 * poisson_ratio) * m2)


def section_properties(outer_diameter, inner_diameter):
    """(A [m²], I [m⁴]) of a hollow circular section."""
    area = 0.25 * jnp.pi * (outer_diameter**2 - inner_diameter**2)
    second_moment = jnp.pi * (outer_diameter**4 - inner_diameter**4) / 64.0
    return area, second_moment


def element_stiffness(length, outer_diameter, inner_diameter, material: Material):
    """10 × 10 stiffness [N/m, N, N·m] of one Timoshenko element between two nodes of five
    degrees of freedom each, [u_x, u_y, u_z, θ_x, θ_y] of node 1 then of node 2 (module docstring)."""
    modulus = material.elastic_modulus
    shear_modulus = modulus / (2.0 * (1.0 + material.poisson_ratio))
    area, second_moment = section_properties(outer_diameter, inner_diameter)
    kappa = shear_coefficient(inner_diameter / outer_diameter, material.poisson_ratio)
    phi = 12.0 * modulus * second_moment / (kappa * shear_modulus * area * length**2)
    L = length
    bending = modulus * second_moment / ((1.0 + phi) * L**3) * jnp.array([
        [12.0, 6.0 * L, -12.0, 6.0 * L],
        [6.0 * L, (4.0 + phi) * L**2, -6.0 * L, (2.0 - phi) * L**2],
        [-12.0, -6.0 * L, 12.0, -6.0 * L],
        [6.0 * L, (2.0 - phi) * L**2, -6.0 * L, (4.0 + phi) * L**2]])
    axial = modulus * area / L
    matrix = jnp.zeros((10, 10))
    # x–z plane: (u_x, θ_y) of both nodes; y–z plane: (u_y, −θ_x)
    for dofs, signs in (((0, 4, 5, 9), np.array([1.0, 1.0, 1.0, 1.0])), ((1, 3, 6, 8), np.array([1.0, -1.0, 1.0, -1.0]))):
        index = np.array(dofs)
        matrix = matrix.at[np.ix_(index, index)].add(bending * np.outer(signs, signs))
    index = np.array([2, 7])
    return matrix.at[np.ix_(index, index)].add(axial * np.array([[1.0, -1.0], [-1.0, 1.0]]))


class BeamMesh(eqx.Module):
    """The mesh of a shaft (all static): each node's position as (key point a, key point b,
    fraction t), z = z_a + t (z_b − z_a), with the key points the sections' starts, then their
    ends, then the given points (`key_points`); each element's section; each given point's node."""

    anchors: tuple = eqx.field(static=True)
    element_sections: tuple = eqx.field(static=True)
    point_nodes: tuple = eqx.field(static=True)

    @property
    def node_count(self) -> int:
        return len(self.anchors)


def key_points(sections: ShaftSections, points):
    """The key points' positions [m]: the sections' starts and ends, then `points`."""
    return jnp.concatenate([jnp.asarray(sections.starts), jnp.asarray(sections.ends),
                            jnp.asarray(points, dtype=float).reshape(-1)])


def beam_mesh(sections: ShaftSections, points, longest=None) -> BeamMesh:
    """Mesh of the shaft with a node at each section end and at each of `points` (m,) [m] (concrete
    values), no element longer than `longest` [m] (default: the shaft's length / 40).

    Raises ValueError naming the first point off the shaft."""
    keys = np.asarray(key_points(sections, points), dtype=float)
    start, end = np.min(sections.starts), np.max(sections.ends)
    span = end - start
    longest = span / 40.0 if longest is None else float(longest)
    check_range("shaft.element_length", longest, low=0.0, unit=" m")
    tolerance = MERGE * span
    section_count = np.shape(sections.starts)[0]
    for index, z in enumerate(keys[2 * section_count:]):
        if z < start - tolerance or z > end + tolerance:
            raise ValueError(f"point {index} at z = {z:g} m lies off the shaft, whose sections run from "
                             f"{start:g} m to {end:g} m")
    order = np.argsort(keys, kind="stable")
    distinct = [int(order[0])]  # one key point per node position
    node_of_key = {int(order[0]): 0}
    for index in order[1:]:
        if keys[index] - keys[distinct[-1]] > tolerance:
            distinct.append(int(index))
        node_of_key[int(index)] = len(distinct) - 1
    anchors, key_nodes = [], []
    for left, right in zip(distinct[:-1], distinct[1:]):
        key_nodes.append(len(anchors))
        pieces = max(1, int(np.ceil((keys[right] - keys[left]) / longest - 1e-9)))
        anchors += [(left, right, j / pieces) for j in range(pieces)]
    key_nodes.append(len(anchors))
    anchors.append((distinct[-1], distinct[-1], 0.0))
    positions = np.array([keys[a] + t * (keys[b] - keys[a]) for a, b, t in anchors])
    middles = 0.5 * (positions[:-1] + positions[1:])
    starts, ends = np.asarray(sections.starts), np.asarray(sections.ends)
    element_sections = tuple(int(np.argmax((starts <= z) & (z <= ends))) for z in middles)
    point_nodes = tuple(key_nodes[node_of_key[2 * section_count + i]] for i in range(len(keys) - 2 * section_count))
    return BeamMesh(tuple(anchors), element_sections, point_nodes)


def node_positions(mesh: BeamMesh, sections: ShaftSections, points):
    """z of every node [m] (n,), from the key points (differentiable in them)."""
    keys = key_points(sections, points)
    a, b, t = (np.array(column) for column in zip(*mesh.anchors))
    return keys[a] + t * (keys[b] - keys[a])


def stiffness_matrix(mesh: BeamMesh, sections: ShaftSections, points):
    """(5n, 5n) stiffness of the free shaft [N/m, N, N·m], node by node in the order of z."""
    z = node_positions(mesh, sections, points)
    index = np.array(mesh.element_sections)
    elements = jax.vmap(element_stiffness, in_axes=(0, 0, 0, None))(
        z[1:] - z[:-1], jnp.asarray(sections.outer_diameters)[index], jnp.asarray(sections.inner_diameters)[index],
        sections.material)
    size = NODE_DOFS * mesh.node_count
    rows = NODE_DOFS * np.arange(mesh.node_count - 1)[:, None] + np.arange(2 * NODE_DOFS)[None, :]  # element e: nodes e, e + 1
    matrix = jnp.zeros((size, size))
    return matrix.at[rows[:, :, None], rows[:, None, :]].add(elements)
