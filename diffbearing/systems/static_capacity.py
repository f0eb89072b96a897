"""A bearing's static load-carrying capacity curve: the combinations of axial load and tilting
moment at which its largest contact pressure reaches a limit (the "static limiting load curve"
that slewing-bearing makers print, axial load against tilting moment).

Along a ray of loads t (F_a,ref ẑ, M_ref ŷ) (with a fixed radial load F_r x̂), one bearing alone
carries them at its centre (`shaft_equilibrium.solve_shaft` on a one-bearing `Shaft`) and the
scale t at which the largest Hertz pressure p_max(t) equals the limit p_lim solves p_max(t) = p_lim.
A point contact's pressure grows as Q^{1/3} and, where the load distribution keeps its shape, Q as
t, so the step t ← t (p_lim / p_max(t))³ is exact for rigid rings without clearance and a fixed
point that contracts fast otherwise; it stops when p_max is within `PRESSURE_TOLERANCE` of the
limit. For rigid rings without clearance and every ball on one diagonal (a four-point bearing)
the curve is the straight line F_a / (Z sin α) + 4.37 M / (d_m Z sin α) = Q_lim (`rigid_ring_line`).
"""

import equinox as eqx
import jax.numpy as jnp
import numpy as np

from ..numerics import require_float64
from .shaft_equilibrium import Shaft, ShaftLoads, solve_shaft

PRESSURE_TOLERANCE = 1e-9  # relative: |p_max / p_lim − 1| at which a ray's scale is taken as found
MAX_ITERATIONS = 30
RIGID_RING_MOMENT_FACTOR = 4.37  # 2 / mean |cos ψ|^{5/2}: Q_max = 4.37 M / (d_m Z sin α)


class CapacityPoint(eqx.Module):
    """One point of the curve: the axial load F_a [N] and tilting moment M [N·m] (with the ray's
    radial load) at which the largest contact pressure is the limit, the solved bearing
    displacement [m, rad], whether the iteration and the bearing's solve converged, and the
    bearing solves it took."""

    axial_load: float
    moment: float
    displacement: np.ndarray
    converged: bool
    solves: int


@eqx.filter_jit
def _largest_pressure(support, force, moment):
    shaft = Shaft((support,), ShaftLoads(jnp.zeros(1), force[None], moment[None]))
    solution = solve_shaft(shaft)
    contacts = support.contacts(solution.bearing_displacements[0], 0.0, solution.constants[0])
    return jnp.max(contacts.max_pressure), solution.bearing_displacements[0], solution.converged


def capacity_point(support, axial_reference, moment_reference, pressure_limit, radial_load=0.0) -> CapacityPoint:
    """The point of the capacity curve on the ray t (axial_reference [N], moment_reference [N·m])
    of `support` (any `AbstractSupport`, at standstill) for the pressure limit [Pa] (module
    docstring); `radial_load` [N] along x, held fixed."""
    require_float64()
    scale, converged, solves = 1.0, False, 0
    while solves < MAX_ITERATIONS:
        solves += 1
        force = jnp.array([radial_load, 0.0, scale * axial_reference])
        moment = jnp.array([0.0, scale * moment_reference])
        pressure, displacement, solved = _largest_pressure(support, force, moment)
        ratio = float(pressure_limit / pressure)
        if abs(ratio - 1.0) <= PRESSURE_TOLERANCE:
            converged = bool(solved)
            break
        scale *= ratio**3
    return CapacityPoint(scale * axial_reference, scale * moment_reference, np.asarray(displacement), converged, solves)


def capacity_curve(support, axial_reference, moment_reference, pressure_limit, angles, radial_load=0.0):
    """The capacity curve's points on the rays (cos φ F_a,ref, sin φ M_ref) for each φ of `angles`
    [rad] in [0, π/2] (`capacity_point`)."""
    return [capacity_point(support, np.cos(angle) * axial_reference, np.sin(angle) * moment_reference, pressure_limit,
                           radial_load) for angle in angles]


def rigid_ring_line(ball_count, pitch_diameter, contact_angle, limit_load):
    """(F_a at M = 0 [N], M at F_a = 0 [N·m]) of the rigid-ring line F_a/(Z sin α) + 4.37 M/(d_m Z sin α)
    = Q_lim for the largest ball load Q_lim [N] (module docstring)."""
    axial = ball_count * np.sin(contact_angle) * limit_load
    return axial, axial * pitch_diameter / RIGID_RING_MOMENT_FACTOR
