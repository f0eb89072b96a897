"""Timoshenko beam elements of a stepped shaft (`shaft_beam`) against the closed forms of
Timoshenko beams (unit-load method: δ = ∫ M m / EI dz + ∫ V v / (κ G A) dz), the shear coefficient
against Cowper's solid value, and the mesh's errors."""

import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.systems.operating_clearance import SEAT_MATERIALS
from diffbearing.systems.shaft_beam import (
    ShaftSections,
    beam_mesh,
    node_positions,
    section_properties,
    shear_coefficient,
    stiffness_matrix,
)

STEEL = SEAT_MATERIALS["steel"][0]
E, NU = float(STEEL.elastic_modulus), float(STEEL.poisson_ratio)
G = E / (2.0 * (1.0 + NU))


def _solve(sections, points, fixed, loads, longest=None):
    """The displacements (points, 5) of `points` on the shaft with the degrees of freedom `fixed`
    [(point, dof)] held at 0 and `loads` [(point, dof, value)] applied."""
    mesh = beam_mesh(sections, points, longest)
    matrix = np.asarray(stiffness_matrix(mesh, sections, points))
    size = matrix.shape[0]
    held = [5 * mesh.point_nodes[point] + dof for point, dof in fixed]
    free = np.setdiff1d(np.arange(size), held)
    force = np.zeros(size)
    for point, dof, value in loads:
        force[5 * mesh.point_nodes[point] + dof] += value
    displacement = np.zeros(size)
    displacement[free] = np.linalg.solve(matrix[np.ix_(free, free)], force[free])
    return displacement.reshape(-1, 5)[list(mesh.point_nodes)]


def test_shear_coefficient_of_a_solid_section_is_cowpers():
    """Cowper (1966), Table 1, solid circle: κ = 6(1 + ν)/(7 + 6ν); 0.886 at ν = 0.3."""
    assert float(shear_coefficient(0.0, 0.3)) == pytest.approx(6 * 1.3 / 8.8, rel=1e-15)
    assert float(shear_coefficient(0.999, 0.3)) == pytest.approx(0.53, abs=0.01)  # thin tube: ≈ 2(1 + ν)/(4 + 3ν)


@pytest.mark.parametrize("longest", [None, 0.013])
def test_simply_supported_shaft_centre_load(longest):
    """A uniform solid shaft on two simple supports, F at mid-span: δ = F L³/(48 EI) + F L/(4 κ G A)
    in both planes (u_x under F_x, u_y under F_y), 1e-10, however finely meshed."""
    length, diameter, force = 0.4, 0.05, 10e3
    sections = ShaftSections([0.0], [length], [diameter], [0.0], STEEL)
    fixed = [(0, 0), (0, 1), (0, 2), (1, 0), (1, 1)]
    area, inertia = section_properties(diameter, 0.0)
    kappa = shear_coefficient(0.0, NU)
    expected = force * length**3 / (48 * E * inertia) + force * length / (4 * kappa * G * area)
    for dof in (0, 1):
        u = _solve(sections, [0.0, length, 0.5 * length], fixed, [(2, dof, force)], longest)
        assert u[2, dof] == pytest.approx(float(expected), rel=1e-10)


def test_stepped_hollow_cantilever_tip_load():
    """A cantilever of two sections (solid 60 mm over a = 0.12 m, then a 40/20 mm tube to L = 0.3 m)
    clamped at z = 0, tip loads F_x, F_y, F_z: the unit-load method's closed forms of the tip's
    u_x, θ_y, u_y, θ_x (u_y has slope −θ_x) and u_z, 1e-10."""
    a, length, force = 0.12, 0.3, 2e3
    sections = ShaftSections([0.0, a], [a, length], [0.06, 0.04], [0.0, 0.02], STEEL)
    u = _solve(sections, [0.0, length], [(0, dof) for dof in range(5)],
                  [(1, 0, force), (1, 1, 0.5 * force), (1, 2, 3 * force)])
    (area1, inertia1), (area2, inertia2) = section_properties(0.06, 0.0), section_properties(0.04, 0.02)
    kappa1, kappa2 = shear_coefficient(0.0, NU), shear_coefficient(0.5, NU)
    rest = length - a
    deflection = (force / (3 * E) * ((length**3 - rest**3) / inertia1 + rest**3 / inertia2)
                  + force * (a / (kappa1 * G * area1) + rest / (kappa2 * G * area2)))
    slope = force / (2 * E) * ((length**2 - rest**2) / inertia1 + rest**2 / inertia2)
    stretch = 3 * force / E * (a / area1 + rest / area2)
    tip = u[-1]
    np.testing.assert_allclose(tip, [deflection, 0.5 * deflection, stretch, -0.5 * slope, slope], rtol=1e-10)


def test_mesh_nodes_and_errors():
    """Nodes at every section end and point, no element longer than asked; points off the shaft
    and gaps between sections are refused with the parameter named."""
    sections = ShaftSections([0.0, 0.1], [0.1, 0.25], [0.05, 0.04], [0.0, 0.0], STEEL)
    mesh = beam_mesh(sections, [0.03, 0.2, 0.2], longest=0.02)
    z = np.asarray(node_positions(mesh, sections, jnp.array([0.03, 0.2, 0.2])))
    assert np.all(np.diff(z) > 0) and np.max(np.diff(z)) <= 0.02 + 1e-15
    for point, where in zip(mesh.point_nodes, (0.03, 0.2, 0.2)):
        assert z[point] == pytest.approx(where, abs=1e-15)
    assert mesh.point_nodes[1] == mesh.point_nodes[2]
    with pytest.raises(ValueError, match="point 1 at z = 0.3 m lies off the shaft"):
        beam_mesh(sections, [0.03, 0.3])
    with pytest.raises(ValueError, match=r"shaft.sections\[1\]: starts at 0.12 m"):
        ShaftSections([0.0, 0.12], [0.1, 0.25], [0.05, 0.04], [0.0, 0.0], STEEL)
    with pytest.raises(ValueError, match=r"shaft.sections\[0\].inner_diameter must be < its outer_diameter"):
        ShaftSections([0.0], [0.1], [0.05], [0.05], STEEL)
