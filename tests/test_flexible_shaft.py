"""A flexible (Timoshenko) shaft on several bearings: one bearing carries exactly the rigid shaft's
load, the overhang bending by the closed form; the rigid shaft as the limit of a stiffening one;
the stiffness at a point against the equilibrium's own response; derivatives against central
differences; a bearing that carries nothing."""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.params import Material
from diffbearing.systems.flexible_shaft import flexible_shaft, flexible_shaft_stiffness, solve_flexible_shaft
from diffbearing.systems.operating_clearance import SEAT_MATERIALS
from diffbearing.systems.shaft_beam import ShaftSections, section_properties, shear_coefficient
from diffbearing.bearings.ball.ball_support import BallSupport
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, shaft_stiffness, solve_shaft, transfer

from .helpers import assert_jvp_matches_central_difference
from .test_shaft_equilibrium import DEEP_GROOVE

STEEL = SEAT_MATERIALS["steel"][0]


def loads(position, force, moment=(0.0, 0.0)):
    return ShaftLoads(np.array([position]), np.array([force], float), np.array([moment], float))


def sections(material=STEEL, diameter=0.04):
    """A 40 mm solid shaft from −0.15 m to 0.2 m, a 30/10 mm tube beyond 0.1 m."""
    return ShaftSections([-0.15, 0.1], [0.1, 0.2], [diameter, 0.03], [0.0, 0.01], material)


@pytest.fixture(scope="module")
def solve():
    return eqx.filter_jit(solve_flexible_shaft)


@pytest.fixture(scope="module")
def stiffness_of():
    return eqx.filter_jit(flexible_shaft_stiffness)


def test_one_bearing_carries_the_rigid_load_and_the_overhang_bends(solve):
    """Exact identities: on one bearing the shaft is statically determinate, so the bearing's load
    and its ring displacement are the rigid shaft's (1e-9), and the shaft's end at 0.2 m, 0.15 m
    beyond the bearing, sits where the bearing's node carries it rigidly plus a Timoshenko
    cantilever's tip deflection under the end load (unit-load method over the two sections, 1e-9)."""
    force = np.array([1500.0, -600.0, 800.0])
    shaft = Shaft((BallSupport(DEEP_GROOVE, 0.05),), loads(0.2, force))
    rigid = solve_shaft(shaft)
    flexible = flexible_shaft(shaft, sections(), reference=0.2)
    bent = solve(flexible)
    assert bool(rigid.converged) and bool(bent.converged)
    np.testing.assert_allclose(bent.bearing_forces[0], rigid.bearing_forces[0], rtol=1e-9, atol=1e-9 * 1500)
    np.testing.assert_allclose(bent.bearing_displacements[0], rigid.bearing_displacements[0], rtol=1e-9, atol=1e-15)
    bearing_node = flexible.mesh.point_nodes[0]
    carried = transfer(0.15) @ bent.node_displacements[bearing_node]
    E, nu = float(STEEL.elastic_modulus), float(STEEL.poisson_ratio)
    G = E / (2 * (1 + nu))
    (a1, i1), (a2, i2) = section_properties(0.04, 0.0), section_properties(0.03, 0.01)
    k1, k2 = shear_coefficient(0.0, nu), shear_coefficient(1 / 3, nu)
    # cantilever from z = 0.05: 0.05 m of the solid section, then 0.1 m of the tube; arm from the tip
    bending = (0.15**3 - 0.1**3) / (3 * E * i1) + 0.1**3 / (3 * E * i2)
    shear = 0.05 / (k1 * G * a1) + 0.1 / (k2 * G * a2)
    slope = (0.15**2 - 0.1**2) / (2 * E * i1) + 0.1**2 / (2 * E * i2)
    stretch = 0.05 / (E * a1) + 0.1 / (E * a2)
    expected = carried + np.array([force[0] * (bending + shear), force[1] * (bending + shear), force[2] * stretch,
                                   -force[1] * slope, force[0] * slope])
    np.testing.assert_allclose(bent.displacement, expected, rtol=1e-9, atol=1e-9 * float(jnp.max(jnp.abs(expected))))


def _three_bearing_shaft(speed=0.0):
    """A shaft on three 6411E bearings (statically indeterminate), a gear load between the first two."""
    supports = (BallSupport(DEEP_GROOVE, -0.12), BallSupport(DEEP_GROOVE, 0.0, orientation=-1),
                BallSupport(DEEP_GROOVE, 0.15))
    return Shaft(supports, loads(-0.05, (4000.0, 1500.0, 1000.0), (0.0, 60.0)), speed)


@pytest.mark.slow
def test_the_rigid_shaft_is_the_limit_of_a_stiffening_one(solve, stiffness_of):
    """Three bearings (the load's share follows the shaft's bending): as the shaft's modulus grows
    ×10, the bearings' loads and the stiffness at the load approach the rigid shaft's ten times
    closer (first order in the shaft's compliance): at 1e4 × steel's modulus the loads within 2e-4
    of the largest, the stiffness's diagonal within 2e-3 (measured 9.3e-5 and 1.05e-3; at steel's
    own modulus this 40 mm shaft is about ten times softer there than the rigid one)."""
    shaft = _three_bearing_shaft()
    rigid = solve_shaft(shaft)
    rigid_stiffness = np.asarray(shaft_stiffness(rigid.displacement, shaft, -0.05))
    errors = []
    for factor in (1e3, 1e4):
        material = Material(float(STEEL.elastic_modulus) * factor, STEEL.poisson_ratio, STEEL.density)
        flexible = flexible_shaft(shaft, sections(material), reference=-0.05)
        bent = solve(flexible)
        assert bool(bent.converged)
        force = np.stack(bent.bearing_forces) - np.stack(rigid.bearing_forces)
        stiffness = np.asarray(stiffness_of(bent, flexible))
        errors.append((np.max(np.abs(force[:, :3])) / 4000.0,
                       np.max(np.abs(np.diag(stiffness) / np.diag(rigid_stiffness) - 1.0))))
    (force_coarse, stiffness_coarse), (force_fine, stiffness_fine) = errors
    assert force_fine < 2e-4 and stiffness_fine < 2e-3
    assert 0.09 < force_fine / force_coarse < 0.11 and 0.09 < stiffness_fine / stiffness_coarse < 0.11


@pytest.mark.extended
@pytest.mark.slow
def test_stiffness_at_a_point_is_the_equilibriums_response(solve, stiffness_of):
    """The stiffness at the load's point, inverted, is the compliance the equilibrium itself shows:
    the point's displacement differentiated (jacfwd through the implicit solve) with respect to the
    load there, 1e-7 relative."""
    shaft = _three_bearing_shaft()
    flexible = flexible_shaft(shaft, sections(), reference=-0.05)
    bent = solve(flexible)
    stiffness = np.asarray(stiffness_of(bent, flexible))

    def displacement(load):
        moved = eqx.tree_at(lambda f: (f.shaft.loads.forces, f.shaft.loads.moments), flexible,
                            (load[None, :3], load[None, 3:]))
        return solve(moved).displacement

    load = jnp.concatenate([jnp.asarray(shaft.loads.forces[0]), jnp.asarray(shaft.loads.moments[0])])
    compliance = np.asarray(jax.jacfwd(displacement)(load))
    np.testing.assert_allclose(compliance @ stiffness, np.eye(5), atol=1e-7)


@pytest.mark.extended
@pytest.mark.slow
def test_derivatives_through_the_flexible_equilibrium(solve, stiffness_of):
    """d/d(the section diameters, the bearing positions) of every bearing's load, the deflection
    line (every node) and the stiffness's diagonal at the load point: forward and reverse mode
    against central differences."""
    shaft = _three_bearing_shaft()
    flexible = flexible_shaft(shaft, sections(), reference=-0.05)

    def outputs(parameters):
        diameters, positions = parameters
        moved = eqx.tree_at(lambda f: (f.sections.outer_diameters, *(s.position for s in f.shaft.supports)),
                            flexible, (diameters, *positions))
        bent = solve(moved)
        stiffness = jnp.diag(stiffness_of(bent, moved)) / jnp.array([1e8, 1e8, 1e7, 1e6, 1e6])
        return jnp.stack(bent.bearing_forces)[:, :3] / 1e3, bent.node_displacements * 1e6, stiffness

    point = (jnp.asarray(flexible.sections.outer_diameters), jnp.array([-0.12, 0.0, 0.15]))
    direction = (jnp.array([1.0, 0.3]), jnp.array([0.2, -0.5, 1.0]))
    assert_jvp_matches_central_difference(outputs, point, direction, step=1e-6, rtol=2e-5, atol=1e-6)


@pytest.mark.extended
@pytest.mark.slow
def test_a_bearing_without_load_stays_finite(solve):
    """A hard case: a third bearing far out on a shaft loaded only between the other two carries
    (almost) nothing in its clearance; the solve converges and every value and gradient is finite."""
    supports = (BallSupport(DEEP_GROOVE, -0.12), BallSupport(DEEP_GROOVE, 0.0, orientation=-1),
                BallSupport(DEEP_GROOVE, 0.19))
    flexible = flexible_shaft(Shaft(supports, loads(-0.06, (2000.0, 0.0, 500.0))), sections(), reference=0.19)
    bent = solve(flexible)
    assert bool(bent.converged)
    assert abs(float(bent.bearing_forces[2][0])) < 0.05 * 2000.0

    def third(diameters):
        return solve(eqx.tree_at(lambda f: f.sections.outer_diameters, flexible, diameters)).bearing_forces[2]

    gradient = jax.jacfwd(third)(jnp.asarray(flexible.sections.outer_diameters))
    assert np.all(np.isfinite(np.asarray(gradient))) and np.all(np.isfinite(np.asarray(bent.node_displacements)))


def test_points_off_the_shaft_are_refused():
    shaft = Shaft((BallSupport(DEEP_GROOVE, 0.25),), loads(0.0, (100.0, 0.0, 0.0)))
    with pytest.raises(ValueError, match=r"bearings\[0\].position = 250 mm lies off the shaft, whose sections run "
                                         r"from -150 mm to 200 mm"):
        flexible_shaft(shaft, sections())
