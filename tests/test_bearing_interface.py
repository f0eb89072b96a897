"""A bearing type added through the interface alone (bearings/interface.py): a toy bearing, a
hardening spring in each of its five directions, mounted on rigid and flexible shafts that know
nothing of it; its loads, the shaft's displacement and stiffness against closed forms."""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import BallSupport, Shaft, ShaftLoads, ShaftSections, flexible_shaft, shaft_stiffness, solve_shaft
from diffbearing.bearings.interface import AbstractSupport, ContactLoads
from diffbearing.numerics import positive_power
from diffbearing.ratings.reference_life import contact_reference_life
from diffbearing.systems.flexible_shaft import flexible_shaft_stiffness, solve_flexible_shaft

from .helpers import assert_jvp_matches_central_difference


class SpringSupport(AbstractSupport):
    """F_i = k_i Δ_i + h k_i Δ_i³ / (10 µm)² [N, N·m] in each direction (no coupling), from the
    convex energy Σ ½ k_i Δ_i² + ¼ h k_i Δ_i⁴ / (10 µm)²: a bearing that is not a ball or roller one."""

    stiffness: jax.Array  # (5,) [N/m, N/m, N/m, N·m/rad, N·m/rad]
    position: jax.Array
    offset: jax.Array = 0.0
    hardening: float = eqx.field(static=True, default=0.5)
    orientation: int = eqx.field(static=True, default=1)

    def constants(self):
        return None

    def _cubic(self, displacement):
        return self.hardening * self.stiffness * displacement**3 / 1e-10

    def ring_force(self, displacement, speed, constants, elements=None):
        return self.stiffness * displacement + self._cubic(displacement)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        return jnp.diag(self.stiffness * (1.0 + 3.0 * self.hardening * displacement**2 / 1e-10))

    def energy_constants(self, constants):
        return None

    def static_energy(self, displacement, energy_constants):
        return jnp.sum(0.5 * self.stiffness * displacement**2 + 0.25 * self._cubic(displacement) * displacement)

    def characteristic_load(self, constants, energy_constants):
        return self.stiffness[0] * 1e-5

    def pitch_radius(self):
        return jnp.asarray(0.03)

    def contacts(self, displacement, speed, constants, elements=None):
        """Four virtual elements a quarter turn apart, each a point contact on either ring carrying
        the radial ring force's component towards it (0 where it points away)."""
        force = self.ring_force(displacement, speed, constants)
        azimuth = jnp.arange(4) * 0.5 * jnp.pi
        load = positive_power(force[0] * jnp.cos(azimuth) + force[1] * jnp.sin(azimuth), 1.0)
        pair = jnp.stack([load, load], axis=-1)
        return ContactLoads(azimuth, pair, pair[..., None], jnp.zeros_like(pair), jnp.zeros_like(pair),
                            jnp.zeros_like(pair), ("inner", "outer"), "point")

    def dynamic_load_rating(self):
        return jnp.asarray(5e4)

    def contact_ratings(self, rating, contacts):
        return jnp.stack([rating, 1.2 * rating])

    def static_load_rating(self):
        return jnp.asarray(4e4)

    def equivalent_dynamic_load(self, force):
        return jnp.sqrt(force[0] ** 2 + force[1] ** 2) + jnp.abs(force[2])

    def equivalent_static_load(self, force):
        return jnp.sqrt(force[0] ** 2 + force[1] ** 2) + 0.5 * jnp.abs(force[2])

    def pressure_safety(self, max_pressure):
        return jnp.asarray(jnp.inf)

    def rolling_element(self):
        return "ball"

    def envelope(self, contacts):
        return jnp.array([0.0, 0.0, 0.5 * jnp.pi])

    def frequencies(self, speed, contacts):
        raise NotImplementedError("a spring has no rolling elements")


SPRINGS = jnp.array([2e8, 2e8, 1e8, 5e5, 5e5])


def _pair(load=(3000.0, -1000.0, 500.0), springs=SPRINGS, at=0.06):
    supports = (SpringSupport(springs, -0.1), SpringSupport(springs, 0.1, orientation=-1))
    return Shaft(supports, ShaftLoads(np.array([at]), np.array([load]), np.zeros((1, 2))))


def _cubic_root(force, spring, hardening=0.5):
    """Δ with k Δ + h k Δ³ / (10 µm)² = F (one real root: the left side is increasing)."""
    roots = np.roots([hardening * spring / 1e-10, 0.0, spring, -force])
    return roots.real[np.abs(roots.imag) < 1e-20][0]


def test_a_shaft_on_a_toy_bearing_type_balances_its_loads_as_statics_says():
    """Two springs without tilting stiffness 0.2 m apart, the load at z = 0.06: each takes its
    lever-rule share of the radial load (0.2 and 0.8 of it), the axial load is split between the
    two in parallel (the turned one pushed the other way in its own frame); every bearing's
    deflection is the root of its own cubic (the rigid shaft turns to meet both)."""
    load = np.array([3000.0, -1000.0, 500.0])
    springs = SPRINGS.at[3:].set(0.0)
    solution = solve_shaft(_pair(tuple(load), springs))
    assert bool(solution.converged)
    near, far = (np.asarray(force) for force in solution.bearing_forces)
    share_far = (0.06 + 0.1) / 0.2  # the bearing at +0.1 takes this share of the radial load
    np.testing.assert_allclose(far[:2] * [1.0, -1.0], share_far * load[:2], rtol=1e-9)  # turned: y sign
    np.testing.assert_allclose(near[:2], (1 - share_far) * load[:2], rtol=1e-9)
    np.testing.assert_allclose([near[2], -far[2]], [0.5 * load[2]] * 2, rtol=1e-9)
    for force, local in zip(solution.bearing_forces, solution.bearing_displacements):
        for direction in range(3):
            assert float(local[direction]) == pytest.approx(_cubic_root(float(force[direction]), springs[direction]),
                                                            rel=1e-8)


def test_a_toy_bearings_shaft_stiffness_is_the_sum_of_its_own_moved_to_the_shaft():
    """K = Σ_k G_kᵀ P_k K_k P_k G_k at the solution, and equal to jax.jacfwd of the shaft force."""
    from diffbearing.systems.shaft_equilibrium import shaft_force, support_move

    shaft = _pair()
    solution = solve_shaft(shaft)
    expected = sum(support_move(s).T @ s.ring_stiffness(local, 0.0, None) @ support_move(s)
                   for s, local in zip(shaft.supports, solution.bearing_displacements))
    stiffness = shaft_stiffness(solution.displacement, shaft)
    np.testing.assert_allclose(stiffness, expected, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(stiffness, jax.jacfwd(shaft_force)(solution.displacement, shaft), rtol=1e-10, atol=1e-3)


def test_the_shafts_derivative_through_a_toy_bearing_matches_central_differences():
    def displacement(springs):
        return solve_shaft(_pair(springs=springs)).displacement

    assert_jvp_matches_central_difference(displacement, SPRINGS, SPRINGS * jnp.array([1.0, -0.5, 0.3, 0.2, 0.7]),
                                          step=1e-5, rtol=1e-6)


@pytest.mark.slow
def test_a_toy_bearing_beside_a_ball_bearing_on_a_flexible_shaft():
    """A mixed shaft (a spring and a deep-groove ball bearing) as a Timoshenko beam: it converges
    and balances the radial load, and as the beam stiffens (0.04, 0.3, 0.6 m solid shafts) its
    bearing loads and radial stiffness approach the rigid shaft's: within 1e-3 of the load and 1e-2
    of the stiffness at 0.3 m (measured 8e-4, 7.5e-3), at least three times closer at 0.6 m (bending
    compliance ∝ d⁻⁴, shear ∝ d⁻²; measured 5 times)."""
    from .test_flexible_shaft import STEEL
    from .test_shaft_equilibrium import DEEP_GROOVE

    supports = (SpringSupport(SPRINGS, -0.1), BallSupport(DEEP_GROOVE, 0.1))
    shaft = Shaft(supports, ShaftLoads(np.array([0.0]), np.array([[2000.0, 0.0, 300.0]]), np.zeros((1, 2))))
    rigid = solve_shaft(shaft)
    rigid_stiffness = np.asarray(shaft_stiffness(rigid.displacement, shaft, elements=rigid.elements,
                                                 constants=rigid.constants))
    gaps = []
    for diameter in (0.04, 0.3, 0.6):
        flexible = flexible_shaft(shaft, ShaftSections([-0.15], [0.15], [diameter], [0.0], STEEL), reference=0.0)
        solution = solve_flexible_shaft(flexible)
        assert bool(solution.converged)
        assert sum(float(force[0]) for force in solution.bearing_forces) == pytest.approx(2000.0, rel=1e-9)
        stiffness = np.asarray(flexible_shaft_stiffness(solution, flexible))
        gaps.append((max(np.max(np.abs(np.asarray(flexed - held)[:3])) for flexed, held
                         in zip(solution.bearing_forces, rigid.bearing_forces)) / 2000.0,
                     np.abs(stiffness[0, 0] - rigid_stiffness[0, 0]) / rigid_stiffness[0, 0]))
    assert gaps[1][0] < 1e-3 and gaps[1][1] < 1e-2
    assert gaps[2][0] < gaps[1][0] / 3 and gaps[2][1] < gaps[1][1] / 3


def test_the_reference_life_reads_a_toy_bearings_contacts():
    """ISO/TS 16281 through the interface alone: each spring's four virtual contacts from the shaft's
    solution, their life from `contact_reference_life`, against the formula written out (point
    contacts: inner ring's cubic mean, outer ring's 10/3 mean, raceways combined with exponent
    10/9, L10r = damage^{−9/10})."""
    shaft = _pair()
    solution = solve_shaft(shaft)
    for support, local in zip(shaft.supports, solution.bearing_displacements):
        contacts = support.contacts(local, 0.0, None)
        rating = support.dynamic_load_rating()
        got = contact_reference_life(contacts, support.contact_ratings(rating, contacts))
        force = np.asarray(support.ring_force(local, 0.0, None))
        loads = np.maximum(force[0] * np.cos(np.arange(4) * np.pi / 2) + force[1] * np.sin(np.arange(4) * np.pi / 2),
                           0.0)
        damage = (np.mean(loads**3) ** (1 / 3) / 5e4) ** (10 / 3) + (np.mean(loads ** (10 / 3)) ** 0.3 / 6e4) ** (10 / 3)
        assert float(got) == pytest.approx(damage**-0.9, rel=1e-12)
