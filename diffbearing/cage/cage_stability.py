"""Linear whirl stability of the cage at its quasi-static equilibrium: a smooth design objective.

The simulated orbit (`cage_dynamics`) is an impact oscillator: over many revolutions its
measures depend on the parameters in a fractal way (a central difference of the whirl radius
does not converge as the step shrinks), so no gradient of them is meaningful. The linear
stability of the equilibrium is smooth, and it is what rotor-dynamics codes report for a journal
on its film:

1. equilibrium offset c* of the cage centre where the quasi-static resultant (`cage_forces`,
   the scene's pushing and resisting balls) vanishes: Newton on F(c) = 0 (optimistix, implicit
   adjoint), from the centred cage;
2. stiffness K = −∂F/∂c at c* (pockets and lands, autodiff) and damping D = −∂F/∂ċ of the two
   lands' squeeze films (`whirling_land_force`) at c*;
3. the eigenvalues λ of m c̈ + D ċ + K c = 0 (m the cage mass); the decay rate of the slowest
   mode, σ = −max Re λ [1/s], is the stability margin (σ < 0: the equilibrium whirls off).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import lineax as lx
import optimistix as optx

from ..params import BallBearing, Cage, Lubricant, Operating
from .cage_dynamics import cage_land_force, cage_mass_properties
from .cage_forces import cage_forces, epicyclic_cage_speed

EQUILIBRIUM_SOLVER = optx.Newton(rtol=1e-10, atol=1e-10)


class CageStability(eqx.Module):
    """Linear stability of the cage at its quasi-static equilibrium (SI)."""

    equilibrium: jax.Array  # (2,) offset c* of the cage centre [m]
    eccentricity: jax.Array  # |c*|/C, relative to the radial guide clearance [-]
    stiffness: jax.Array  # (2, 2) K = −∂F/∂c [N/m]
    damping: jax.Array  # (2, 2) D = −∂F/∂ċ [N·s/m]
    eigenvalues: jax.Array  # (4,) of the linearised whirl [1/s]
    decay_rate: jax.Array  # σ = −max Re λ [1/s]
    converged: jax.Array  # the equilibrium Newton converged


def _resultant(offset_in_clearances, args):
    """Radial-plane resultant on the cage [N] with its centre at C·(offset) (scaled unknowns)."""
    cage, bearing, operating, lubricant = args
    return cage_forces(cage, bearing, operating, lubricant, 0.5 * cage.guide_clearance * offset_in_clearances).force[:2]


def cage_stability(cage: Cage, bearing: BallBearing, operating: Operating, lubricant: Lubricant,
                   start=None) -> CageStability:
    """Equilibrium offset, stiffness, damping and whirl decay rate of the cage (module docstring).
    `start` (x, y) [m] is Newton's first iterate (default: the centred cage)."""
    clearance = 0.5 * cage.guide_clearance
    args = (cage, bearing, operating, lubricant)
    first = jnp.zeros(2) if start is None else jnp.asarray(start) / clearance
    solution = optx.root_find(_resultant, EQUILIBRIUM_SOLVER, first, args=args, max_steps=100, throw=False,
                              adjoint=optx.ImplicitAdjoint(linear_solver=lx.AutoLinearSolver(well_posed=True)))
    equilibrium = clearance * solution.value
    stiffness = -jax.jacfwd(lambda c: cage_forces(cage, bearing, operating, lubricant, c).force[:2])(equilibrium)
    cage_speed = epicyclic_cage_speed(bearing, operating)
    damping = -2.0 * jax.jacfwd(
        lambda v: cage_land_force(cage, operating, lubricant, equilibrium, v, cage_speed)[0])(jnp.zeros(2))
    mass, _ = cage_mass_properties(cage, bearing)
    system = jnp.block([[jnp.zeros((2, 2)), jnp.eye(2)], [-stiffness / mass, -damping / mass]])
    eigenvalues = jnp.linalg.eigvals(system)
    return CageStability(equilibrium=equilibrium, eccentricity=jnp.linalg.norm(solution.value),
                         stiffness=stiffness, damping=damping, eigenvalues=eigenvalues,
                         decay_rate=-jnp.max(eigenvalues.real),
                         converged=solution.result == optx.RESULTS.successful)
