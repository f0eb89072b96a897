"""Quasi-static 5-DOF roller bearing: load distribution over the rollers and along each roller
(laminae), roller tilt, rib force and stiffness — cylindrical and tapered roller bearings.

Model (ISO/TS 16281:2008 §5.2 slicing; Harris & Kotzalas vol. 2, ch. 1 and 4; docs/theory.md
§Roller bearing equilibrium). The outer ring (cup) is fixed; the inner ring (cone) moves by
Δ = [δx, δy, δz, θx, θy] (the ball model's conventions). Roller j sits at azimuth ψ_j = 2πj/Z.
In its axial plane (axial a first, radial r outward second) the inner ring moves by

    T = (δz, δx cos ψ + δy sin ψ)  and turns by  θ_t = θy cos ψ − θx sin ψ  about e_t = ẑ × e_r,

so a ring point p moves by T + θ_t (−p_r, p_a), and its moments about the bearing centre are
Mx = −sin ψ (p × f), My = cos ψ (p × f) for an in-plane force f at p (p × f = p_a f_r − p_r f_a).

Directions, with the cup contact angle α_o (`RollerRaceways.cup_angle`, 0 for cylindrical),
the roller's cone half angle θ, the cone angle α_i = α_o − 2θ and the roller axis angle
α_m = α_o − θ:

    cup normal (roller → cup)      n_o = (sin α_o, cos α_o)
    cone normal (cone → roller)    n_i = (sin α_i, cos α_i)
    roller axis, large → small end t   = (cos α_m, −sin α_m)   (the rib pushes the roller along t)
    across the roller axis         n_p = (sin α_m, cos α_m)

The roller's large end (y = +l/2) points to −a, its apex side to +a; a positive δz loads a
tapered bearing. Lamina k of width l/n sits at y_k along the roller from its middle.

The roller moves with the cone along its axis (the rib is rigid; a cylindrical roller has no
axial stiffness and no rib force) by w_f = T·t − θ_t (d_m/2) cos α_m, and is free across its axis
(u along n_p) and in tilt (φ about e_t). To first order in the displacements the approaches of
lamina k are

    cup   δ_o,k = w_f sin θ + u cos θ − φ y_k − g_k
    cone  δ_i,k = T·n_i − θ_t ((d_m/2) sin α_i + y_k) + w_f sin θ − u cos θ + φ y_k − g_k

with the gap g_k = P_d/4 + z(y_k) (a quarter of the diametral clearance P_d on each contact, and
the crown drop z of `roller_profile.crown_drop`). Each lamina carries q = c max(δ, 0)^{10/9}
(`roller_life.lamina_load`, ISO/TS 16281; scaled by E'/E'_steel). Roller j's balance across its axis and of moments about
its centre, and the rib force along its axis (F_c the roller's centrifugal force, radially out):

    R_u = cos θ (Σ q_i − Σ q_o) + F_c cos α_m = 0
    R_φ = Σ (q_o,k − q_i,k) y_k = 0
    Q_f = sin θ (Σ q_i + Σ q_o) + F_c sin α_m

and the inner ring takes, per roller, f = Σ q_i,k n_i + Q_f t with moment
p × f = −Σ q_i,k ((d_m/2) sin α_i + y_k) − Q_f (d_m/2) cos α_m.

Without centrifugal force the rollers sit midway: u cos θ = (T·n_i − θ_t (d_m/2) sin α_i)/2 and
φ = θ_t/2 make δ_i,k = δ_o,k and satisfy R_u = R_φ = 0 exactly (both contacts have the same
lamina law and gap). Then each lamina pair has the total approach

    δ_k = δ_i,k + δ_o,k = T·n_o − θ_t ((d_m/2) sin α_o + y_k) − 2 g_k

and the ring force is the gradient of the convex energy Σ 2 ∫ q(δ_k/2) — the same in closed form
for cylindrical and tapered bearings (Harris: δ_ψ = δ_a sin α_o + δ_r cos ψ cos α_o). With
centrifugal force each roller's (u, φ) is solved by damped Newton under the ring problem, with
its implicit derivative (`newton.implicit_root`), so F(Δ) has exact total derivatives and the
stiffness K = dF/dΔ (rollers re-equilibrated) is `jax.jacfwd(ring_force)`.

Solution: the static ring problem minimises the energy from Δ = 0 (`newton.minimise_convex`,
no initial guess); with centrifugal force, damped Newton (`newton.newton`, dense Jacobian
through the rollers' implicit solves) continues from there. A cylindrical bearing has no axial
unknown (δz = 0, an axial force is an error); an imposed misalignment fixes θx, θy, and the
moments become outputs; an imposed radial (axial) displacement fixes δx, δy (δz), and Fx, Fy (Fz).
"""

import dataclasses

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ...contact.hertz import line_contact
from ...newton import block_newton, block_tangent_solve, implicit_root, least_squares_tangent_solve, minimise_convex, newton
from ...numerics import require_float64, safe_norm
from ...params import _as_float, _is_concrete, check_range
from ...ratings.roller_life import lamina_load
from .roller_contact import PALMGREN_STEEL_MODULUS
from .roller_geometry import RollerBearing, RollerLoading, roller_diameter, roller_modulus
from .roller_profile import crown_drop

DISPLACEMENT_SCALE = 1e-5  # m: unit of the scaled ring unknowns (10 µm, 10 µm / (d_m/2) rad)
ROLLER_SCALE = 1e-6  # m: unit of the scaled roller unknowns (1 µm, 1 µm / (l/2) rad)
RESIDUAL_TOLERANCE = 1e-9  # converged when the scaled ring and roller residuals are below
ROLLER_NEWTON_STEPS = 40
ROLLER_STEP_TOLERANCE = 1e-12  # × ROLLER_SCALE: the per-roller Newton stops below this step (at 1e-10, light
# rollers at speed stopped up to 5e-9 of their 1 µm load off their balance, above RESIDUAL_TOLERANCE)
RING_MAX_STEPS = 60
STATIC_GRADIENT_TOLERANCE = 1e-12
# A roller that touches neither raceway (no centrifugal force, or no speed) has no equation for
# its position: a centring spring this weak (relative to one roller at 1 µm) keeps it midway. It
# biases a roller's balance by CENTRING × (its distance from midway in µm) × (its load at 1 µm):
# for a roller pressed out by its centrifugal force 60 µm from midway, 6e-13 of the 1 µm load,
# below the residual tolerance even where the roller's own load is 1/50 of that (at 1e-12 the
# bias alone failed light bearings at speed).
CENTRING = 1e-14


@dataclasses.dataclass(frozen=True)
class RollerModel:
    """Static options of the roller bearing model: laminae per roller, centrifugal force."""

    laminae: int = 30
    centrifugal: bool = False

    def __post_init__(self):
        if isinstance(self.laminae, bool) or not isinstance(self.laminae, int) or not 2 <= self.laminae <= 1000:
            raise ValueError(f"fidelity.laminae must be an integer from 2 to 1000, got {self.laminae!r}")


class RollerRaceways(eqx.Module):
    """The rings around the rollers: pitch diameter d_m [m] (roller centres at mid-length),
    diametral clearance P_d [m] and cup angle α_o [rad] (0 for a cylindrical bearing)."""

    pitch_diameter: jax.Array = eqx.field(converter=_as_float)
    diametral_clearance: jax.Array = eqx.field(converter=_as_float)
    cup_angle: jax.Array = eqx.field(converter=_as_float, default=0.0)


def roller_raceways(bearing: RollerBearing, *, pitch_diameter, diametral_clearance=0.0, cup_angle=0.0
                    ) -> RollerRaceways:
    """Validated `RollerRaceways` for `bearing` (its roller count set); ValueError names a bad key."""
    if bearing.roller_count is None:
        raise ValueError("missing required key 'bearing.rollers' (the number of rollers Z)")
    check_range("bearing.pitch_diameter", pitch_diameter, low=0.0, unit=" m")
    if _is_concrete(pitch_diameter, bearing.large_diameter) and float(pitch_diameter) <= float(bearing.large_diameter):
        raise ValueError(f"bearing.pitch_diameter must exceed the roller diameter {float(bearing.large_diameter):g} m, "
                         f"got {float(pitch_diameter):g} m")
    floor = -0.01 * float(pitch_diameter) if _is_concrete(pitch_diameter) else None
    check_range("bearing.radial_clearance", diametral_clearance, low=floor, unit=" m",
                why="diametral clearance; negative for a preloaded bearing, above −1 % of d_m")
    if bearing.kind == "cylindrical_roller":
        if _is_concrete(cup_angle) and float(cup_angle) != 0.0:
            raise ValueError("bearing.contact_angle: a cylindrical roller bearing has contact angle 0")
    else:
        cone = float(bearing.cone_half_angle) if _is_concrete(bearing.cone_half_angle) else 0.0
        check_range("bearing.contact_angle", cup_angle, low=2.0 * cone, high=np.pi / 3,
                    unit=" rad", why="the cup angle exceeds twice the roller's cone half angle (cone angle > 0) "
                                     "and is below 60°")
    return RollerRaceways(pitch_diameter, diametral_clearance, cup_angle)


class RollerOperating(eqx.Module):
    """Load case of a roller bearing: force [Fx, Fy, Fz] [N], moment [Mx, My] [N·m], ring speeds
    [rad/s], an imposed inner-ring misalignment [θx, θy] [rad] (None: the moments are applied), an
    imposed radial displacement [δx, δy] [m] (None: the radial force is applied; else Fx, Fy are
    outputs and the given ones are not read) and, for a tapered bearing, an imposed axial
    displacement δz [m] (None: Fz is applied; else Fz is an output: setting by displacement)."""

    force: jax.Array = eqx.field(converter=_as_float)
    moment: jax.Array = eqx.field(converter=_as_float)
    inner_speed: jax.Array = eqx.field(converter=_as_float, default=0.0)
    outer_speed: jax.Array = eqx.field(converter=_as_float, default=0.0)
    misalignment: jax.Array | None = eqx.field(converter=lambda v: None if v is None else _as_float(v), default=None)
    radial_displacement: jax.Array | None = eqx.field(converter=lambda v: None if v is None else _as_float(v),
                                                      default=None)
    axial_displacement: jax.Array | None = eqx.field(converter=lambda v: None if v is None else _as_float(v),
                                                     default=None)


def roller_azimuths(bearing: RollerBearing):
    """ψ_j = 2π j / Z [rad], roller 0 on +x."""
    return 2.0 * jnp.pi * jnp.arange(bearing.roller_count) / bearing.roller_count


def lamina_positions(bearing: RollerBearing, laminae: int):
    """Lamina centres y_k [m] along the roller from its middle (+ towards the large end) and the
    lamina width l/n [m]."""
    width = bearing.length / laminae
    return (jnp.arange(laminae) + 0.5) * width - 0.5 * bearing.length, width


class Directions(eqx.Module):
    """Angles [rad] and in-plane unit vectors (axial, radial) of the module docstring."""

    cup_angle: jax.Array  # α_o
    cone_angle: jax.Array  # α_i
    axis_angle: jax.Array  # α_m
    cup_normal: jax.Array  # n_o
    cone_normal: jax.Array  # n_i
    axis: jax.Array  # t


def directions(bearing: RollerBearing, raceways: RollerRaceways) -> Directions:
    """Contact and axis directions from the cup angle and the roller's cone half angle."""
    half = bearing.cone_half_angle
    cup = raceways.cup_angle
    cone, axis = cup - 2.0 * half, cup - half
    return Directions(cup, cone, axis, jnp.stack([jnp.sin(cup), jnp.cos(cup)]), jnp.stack([jnp.sin(cone), jnp.cos(cone)]),
                      jnp.stack([jnp.cos(axis), -jnp.sin(axis)]))


def ring_motion(displacement, bearing: RollerBearing):
    """(T (Z, 2) [m], θ_t (Z,) [rad]): the inner ring's in-plane translation and tilt at each roller."""
    psi = roller_azimuths(bearing)
    dx, dy, dz, tx, ty = (displacement[i] for i in range(5))
    translation = jnp.stack([jnp.broadcast_to(dz, psi.shape), dx * jnp.cos(psi) + dy * jnp.sin(psi)], axis=-1)
    return translation, ty * jnp.cos(psi) - tx * jnp.sin(psi)


def raceway_curvatures(bearing: RollerBearing, raceways: RollerRaceways, y):
    """Curvature sums in the rolling direction (inner, outer) [1/m] at lamina positions y [m]:
    roller 2 cos θ/D_k (the crowning paper, eq. 5) plus the cone's cos α_i / r_i or minus the
    cup's cos α_o / r_o (Meusnier), r the radius of the contact point from the bearing axis."""
    angles = directions(bearing, raceways)
    diameter = roller_diameter(bearing, y)
    centre_radius = 0.5 * raceways.pitch_diameter + y * jnp.sin(angles.axis_angle)
    roller = 2.0 * jnp.cos(bearing.cone_half_angle) / diameter
    inner_radius = centre_radius - 0.5 * diameter * jnp.cos(angles.cone_angle)
    outer_radius = centre_radius + 0.5 * diameter * jnp.cos(angles.cup_angle)
    return (roller + jnp.cos(angles.cone_angle) / inner_radius, roller - jnp.cos(angles.cup_angle) / outer_radius)


def lamina_gaps(bearing: RollerBearing, raceways: RollerRaceways, y):
    """Gap g_k = P_d/4 + z(y_k) [m] of each contact at the lamina positions (module docstring); the
    logarithmic profiles are sized at the inner contact's equivalent radius at mid-length."""
    inner_curvature, _ = raceway_curvatures(bearing, raceways, jnp.zeros(1))
    drop = crown_drop(bearing.profile, y, bearing.length, roller_modulus(bearing), 1.0 / inner_curvature[0])
    return 0.25 * raceways.diametral_clearance + drop


class LaminaSetup(eqx.Module):
    """What every evaluation shares: lamina positions y [m], width [m], gaps g [m], directions."""

    y: jax.Array
    width: jax.Array
    gap: jax.Array
    angles: Directions


def lamina_setup(bearing: RollerBearing, raceways: RollerRaceways, model: RollerModel) -> LaminaSetup:
    y, width = lamina_positions(bearing, model.laminae)
    return LaminaSetup(y, width, lamina_gaps(bearing, raceways, y), directions(bearing, raceways))


def _lamina_force(approach, bearing: RollerBearing, setup: LaminaSetup):
    """Force of each lamina [N] of one roller–raceway contact at approach δ [m]: ISO/TS 16281's law for
    steel (`roller_life.lamina_load`) scaled by E'/E'_steel for other materials."""
    return lamina_load(approach, setup.width, bearing.length) * roller_modulus(bearing) / PALMGREN_STEEL_MODULUS


def static_approach(displacement, bearing: RollerBearing, raceways: RollerRaceways, setup: LaminaSetup):
    """Total approach δ_i + δ_o [m] (Z, n) of each lamina pair with the rollers midway (no speed)."""
    translation, tilt = ring_motion(displacement, bearing)
    cup = setup.angles.cup_angle
    normal = translation @ setup.angles.cup_normal
    arm = 0.5 * raceways.pitch_diameter * jnp.sin(cup) + setup.y
    return normal[:, None] - tilt[:, None] * arm[None, :] - 2.0 * setup.gap[None, :]


def _rib_displacement(translation, tilt, raceways: RollerRaceways, setup: LaminaSetup):
    """w_f [m] (Z,): the roller's displacement along its axis, carried by the cone's rib."""
    return translation @ setup.angles.axis - tilt * 0.5 * raceways.pitch_diameter * jnp.cos(setup.angles.axis_angle)


def contact_approaches(displacement, roller_state, bearing: RollerBearing, raceways: RollerRaceways, setup: LaminaSetup):
    """(δ_i, δ_o) [m], each (Z, n), for roller states (u [m], φ [rad]) (Z, 2) (module docstring)."""
    translation, tilt = ring_motion(displacement, bearing)
    angles = setup.angles
    half = bearing.cone_half_angle
    rib = _rib_displacement(translation, tilt, raceways, setup)
    across, turn = roller_state[:, 0], roller_state[:, 1]
    y = setup.y[None, :]
    outer = (rib * jnp.sin(half) + across * jnp.cos(half))[:, None] - turn[:, None] * y - setup.gap
    cone = (translation @ angles.cone_normal - tilt * 0.5 * raceways.pitch_diameter * jnp.sin(angles.cone_angle)
            + rib * jnp.sin(half) - across * jnp.cos(half))
    inner = cone[:, None] - tilt[:, None] * y + turn[:, None] * y - setup.gap
    return inner, outer


def midway_states(displacement, bearing: RollerBearing, raceways: RollerRaceways, setup: LaminaSetup):
    """(Z, 2) roller states (u [m], φ [rad]) midway between the raceways: δ_i,k = δ_o,k."""
    translation, tilt = ring_motion(displacement, bearing)
    angles = setup.angles
    cone = translation @ angles.cone_normal - tilt * 0.5 * raceways.pitch_diameter * jnp.sin(angles.cone_angle)
    return jnp.stack([0.5 * cone / jnp.cos(bearing.cone_half_angle), 0.5 * tilt], axis=-1)


def roller_mass(bearing: RollerBearing):
    """Mass [kg] of a roller over its effective length (a frustum from d to D)."""
    d, big = bearing.small_diameter, bearing.large_diameter
    return bearing.material.density * jnp.pi * bearing.length / 12.0 * (d**2 + d * big + big**2)


def roller_centrifugal_force(bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating):
    """F_c = m ω_c² d_m/2 [N] with the cage speed of pure rolling ω_c = ((1 − γ) ω_i + (1 + γ) ω_o)/2,
    γ = D_m cos α_m / d_m (Harris & Kotzalas vol. 1, ch. 8)."""
    mean = 0.5 * (bearing.small_diameter + bearing.large_diameter)
    ratio = mean * jnp.cos(directions(bearing, raceways).axis_angle) / raceways.pitch_diameter
    cage = 0.5 * ((1.0 - ratio) * operating.inner_speed + (1.0 + ratio) * operating.outer_speed)
    return roller_mass(bearing) * cage**2 * 0.5 * raceways.pitch_diameter


def tapered_axial_load_needed(bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating,
                              model: RollerModel):
    """The axial load [N] a tapered roller bearing needs to carry its radial load at all (0 for a
    cylindrical one): an equilibrium needs F_z > F_r tan α_o + Z F_c sin α_o cos α_m / cos θ.

    Each roller's balance (module docstring: cone, rib, cup and F_c) makes the force the cone and its
    rib exert on roller j equal to Q_o,j n_o − F_c e_r: the inner ring takes the cup's push less the
    centrifugal force. Summed over the rollers, Σ e_r(ψ_j) = 0 removes F_c from the radial sum, so
    F_z = sin α_o Σ Q_o,j and F_r = cos α_o |Σ Q_o,j e_r(ψ_j)|. R_u = 0 with Q_i,j ≥ 0 bounds every
    cup load from below, Q_o,j ≥ Q_c = F_c cos α_m / cos θ (the cup alone holding the roller
    against its centrifugal force); with Q_o,j = Q_c + q_j, q_j ≥ 0,
    F_r ≤ cos α_o Σ q_j = cos α_o (F_z / sin α_o − Z Q_c), which is the bound above, reached with a
    single roller carrying the cone. At rest it is the static F_r tan α_o."""
    if bearing.kind == "cylindrical_roller":
        return jnp.asarray(0.0)
    angles = directions(bearing, raceways)
    radial = safe_norm(operating.force[:2])
    needed = radial * jnp.tan(angles.cup_angle)
    if model.centrifugal:
        lightest_cup_load = (roller_centrifugal_force(bearing, raceways, operating) * jnp.cos(angles.axis_angle)
                             / jnp.cos(bearing.cone_half_angle))
        needed = needed + bearing.roller_count * lightest_cup_load * jnp.sin(angles.cup_angle)
    return needed


def _roller_force_scale(bearing: RollerBearing, setup: LaminaSetup):
    """A roller's load at 1 µm approach of every lamina [N]: the unit of the roller residuals."""
    return jnp.sum(_lamina_force(jnp.full(setup.y.shape, ROLLER_SCALE), bearing, setup))


def roller_forces(inner_loads, outer_loads, centrifugal, bearing: RollerBearing, setup: LaminaSetup):
    """(R_u [N], R_φ [N·m], Q_f [N]) per roller from lamina forces (Z, n) (module docstring)."""
    half = bearing.cone_half_angle
    inner, outer = jnp.sum(inner_loads, axis=-1), jnp.sum(outer_loads, axis=-1)
    across = jnp.cos(half) * (inner - outer) + centrifugal * jnp.cos(setup.angles.axis_angle)
    moment = (outer_loads - inner_loads) @ setup.y
    rib = jnp.sin(half) * (inner + outer) + centrifugal * jnp.sin(setup.angles.axis_angle)
    return across, moment, rib


def _roller_equations(scaled_states, args):
    """(Z, 2) scaled roller residuals (R_u, R_φ/(l/2)) / force scale, with the centring spring."""
    displacement, bearing, raceways, setup, centrifugal, midway = args
    arm = 0.5 * bearing.length
    states = scaled_states * jnp.stack([ROLLER_SCALE, ROLLER_SCALE / arm])
    inner, outer = contact_approaches(displacement, states, bearing, raceways, setup)
    across, moment, _ = roller_forces(_lamina_force(inner, bearing, setup), _lamina_force(outer, bearing, setup),
                                      centrifugal, bearing, setup)
    centring = CENTRING * (scaled_states - midway)
    return jnp.stack([across, moment / arm], axis=-1) / _roller_force_scale(bearing, setup) - centring


def _roller_newton(residual, start, args):
    """Every roller's damped Newton at once on its 2×2 block (`newton.block_newton`), until no roller
    moves by more than `ROLLER_STEP_TOLERANCE` (scaled) or after `ROLLER_NEWTON_STEPS`."""
    return block_newton(residual, start, args, max_steps=ROLLER_NEWTON_STEPS, step_tolerance=ROLLER_STEP_TOLERANCE)


def roller_states(displacement, bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating,
                  model: RollerModel, setup: LaminaSetup | None = None):
    """(Z, 2) roller states (u [m], φ [rad]) in equilibrium for inner-ring displacement Δ: midway
    without centrifugal force; otherwise each roller solved, with its implicit derivative."""
    setup = lamina_setup(bearing, raceways, model) if setup is None else setup
    midway = midway_states(displacement, bearing, raceways, setup)
    if not model.centrifugal:
        return midway
    scale = jnp.stack([ROLLER_SCALE, ROLLER_SCALE / (0.5 * bearing.length)])
    centrifugal = roller_centrifugal_force(bearing, raceways, operating)
    scaled_midway = jax.lax.stop_gradient(midway / scale)
    args = (displacement, bearing, raceways, setup, centrifugal, scaled_midway)
    scaled = implicit_root(_roller_equations, scaled_midway, args, _roller_newton, block_tangent_solve)
    return scaled * scale


def _ring_contributions(displacement, states, bearing: RollerBearing, raceways: RollerRaceways, centrifugal,
                        setup: LaminaSetup):
    """(Z, 5) each roller's share of [Fx, Fy, Fz, Mx, My] that the inner ring exerts on the rollers."""
    inner, outer = contact_approaches(displacement, states, bearing, raceways, setup)
    inner_loads, outer_loads = _lamina_force(inner, bearing, setup), _lamina_force(outer, bearing, setup)
    _, _, rib = roller_forces(inner_loads, outer_loads, centrifugal, bearing, setup)
    angles = setup.angles
    radius = 0.5 * raceways.pitch_diameter
    total = jnp.sum(inner_loads, axis=-1)
    force = total[:, None] * angles.cone_normal + rib[:, None] * angles.axis  # (Z, 2) axial, radial
    moment = (-total * radius * jnp.sin(angles.cone_angle) - inner_loads @ setup.y
              - rib * radius * jnp.cos(angles.axis_angle))
    psi = roller_azimuths(bearing)
    return jnp.stack([force[:, 1] * jnp.cos(psi), force[:, 1] * jnp.sin(psi), force[:, 0],
                      -jnp.sin(psi) * moment, jnp.cos(psi) * moment], axis=-1)


def ring_force(displacement, bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating,
               model: RollerModel):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] the rollers resist an inner-ring displacement Δ with, the
    rollers re-equilibrated; `jax.jacfwd` of it is the stiffness."""
    setup = lamina_setup(bearing, raceways, model)
    states = roller_states(displacement, bearing, raceways, operating, model, setup)
    centrifugal = roller_centrifugal_force(bearing, raceways, operating) if model.centrifugal else 0.0
    return jnp.sum(_ring_contributions(displacement, states, bearing, raceways, centrifugal, setup), axis=0)


# --- the ring problem -------------------------------------------------------------------------------

def check_axial_displacement(bearing: RollerBearing, operating: RollerOperating) -> None:
    """ValueError naming operating.axial_displacement where a cylindrical bearing is given one: it
    has no ribs, so no axial position to set (its δz is held at 0)."""
    if operating.axial_displacement is not None and bearing.kind == "cylindrical_roller":
        raise ValueError("operating.axial_displacement: a cylindrical roller bearing without ribs has no axial "
                         "position to set (δz is held at 0); the key is for tapered roller bearings")


def _controls(bearing: RollerBearing, operating: RollerOperating):
    """(free, offset): solved (1) or prescribed (0) components of Δ, and the prescribed values."""
    free = np.ones(5)
    offset = jnp.zeros(5)
    if bearing.kind == "cylindrical_roller":
        free[2] = 0.0
    if operating.radial_displacement is not None:
        free[:2] = 0.0
        offset = offset.at[:2].set(operating.radial_displacement)
    if operating.axial_displacement is not None:
        check_axial_displacement(bearing, operating)
        free[2] = 0.0
        offset = offset.at[2].set(operating.axial_displacement)
    if operating.misalignment is not None:
        free[3:] = 0.0
        offset = offset.at[3:].set(operating.misalignment)
    return jnp.asarray(free), offset


def prescribed_coordinates(bearing: RollerBearing, operating: RollerOperating):
    """(5,) 1 where the inner ring's coordinate [δx, δy, δz, θx, θy] is prescribed (δz of a cylindrical
    roller bearing held at 0; an imposed radial or axial displacement or misalignment), 0 where it follows
    from the applied load (`_controls`)."""
    return 1.0 - _controls(bearing, operating)[0]


def _scales(bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating, setup: LaminaSetup):
    """Unknown scale s (Δ = s·y), residual weights (moments to forces) and load scale [N]."""
    inverse_arm = 2.0 / raceways.pitch_diameter
    weight = jnp.stack([1.0, 1.0, 1.0, inverse_arm, inverse_arm])
    applied = jnp.concatenate([operating.force, operating.moment])
    return DISPLACEMENT_SCALE * weight, weight, safe_norm(applied * weight) + characteristic_load(bearing, setup)


def _displacement(y, args):
    bearing, raceways, operating, model, setup, unknown, weight, load_scale = args
    free, offset = _controls(bearing, operating)
    return unknown * y * free + offset


def _applied(bearing, operating):
    free, _ = _controls(bearing, operating)
    return jnp.concatenate([operating.force, operating.moment]) * free


def static_energy(displacement, bearing: RollerBearing, raceways: RollerRaceways, setup: LaminaSetup):
    """Elastic energy Σ 2 ∫q(δ_k/2) [J] of the rollers midway (no speed) for an inner-ring
    displacement Δ: convex in Δ, its gradient the static ring force."""
    half = 0.5 * static_approach(displacement, bearing, raceways, setup)
    # ∫₀^δ c s^{10/9} ds = (9/19) δ q(δ)
    return 2.0 * jnp.sum(9.0 / 19.0 * half * _lamina_force(half, bearing, setup))


def characteristic_load(bearing: RollerBearing, setup: LaminaSetup):
    """Z × one roller's load at 10 µm approach, scaled linearly [N]: a load scale that stays
    positive at zero applied load."""
    return bearing.roller_count * _roller_force_scale(bearing, setup) * (DISPLACEMENT_SCALE / ROLLER_SCALE)


def _static_energy(y, args):
    """Scaled potential Σ 2 ∫q(δ_k/2) − F·Δ of the rollers midway (convex in Δ); a prescribed
    component adds ½ y² (its unknown stays 0)."""
    bearing, raceways, operating, model, setup, unknown, weight, load_scale = args
    free, _ = _controls(bearing, operating)
    displacement = _displacement(y, args)
    energy = static_energy(displacement, bearing, raceways, setup) - jnp.dot(_applied(bearing, operating), displacement)
    return energy / (load_scale * DISPLACEMENT_SCALE) + 0.5 * jnp.sum((1.0 - free) * y**2)


def _ring_residual(y, args):
    """(ring force − applied load) · weight / load scale; a prescribed component's equation is its unknown."""
    bearing, raceways, operating, model, setup, unknown, weight, load_scale = args
    free, _ = _controls(bearing, operating)
    force = ring_force(_displacement(y, args), bearing, raceways, operating, model)
    return jnp.where(free > 0, (force - _applied(bearing, operating)) * weight / load_scale, y)


def _pushed_out(args):
    """The args of `_static_energy` with every lamina gap widened by half the approach δ_c [m] of a
    roller's outer contact under its centrifugal force alone (F ∝ δ^{10/9}, `_roller_force_scale`):
    the inner ring meets rollers that the speed has pressed into the outer raceway δ_c later."""
    bearing, raceways, operating, model, setup, unknown, weight, load_scale = args
    pushed = ROLLER_SCALE * (roller_centrifugal_force(bearing, raceways, operating)
                             / _roller_force_scale(bearing, setup)) ** 0.9
    return (bearing, raceways, operating, model, eqx.tree_at(lambda s: s.gap, setup, setup.gap + 0.5 * pushed),
            unknown, weight, load_scale)


def _ring_solve(residual, start, args):
    """Static: the energy minimum (`minimise_convex`). With centrifugal force, damped Newton on the
    ring residual from the energy minimum of rollers pushed out by their centrifugal force
    (`_pushed_out`), with a dense Jacobian through the rollers' implicit solves: from the plain
    static minimum, a light load at speed leaves every inner contact open once the rollers move
    out, the Jacobian is zero and Newton stops (measured: 47 % of random cylindrical roller
    bearings at speed unconverged, most of them below the requisite minimum load)."""
    model = args[3]
    start_args = _pushed_out(args) if model.centrifugal else args
    y, steps = minimise_convex(_static_energy, start, start_args, gradient_tolerance=STATIC_GRADIENT_TOLERANCE)
    if model.centrifugal:
        y, more = newton(residual, y, args, max_steps=RING_MAX_STEPS, loop="while", fallback=True, floor=1e-13)
        steps = steps + more
    return y, steps.astype(y.dtype)


class RollerEquilibrium(eqx.Module):
    """Solution of the ring problem: displacement Δ [m, rad], the force [Fx, Fy, Fz, Mx, My] the
    rollers exert (the applied load; the moments under imposed misalignment), whether it
    converged, the scaled residual [-] and the steps taken."""

    displacement: jax.Array
    force: jax.Array
    converged: jax.Array
    residual: jax.Array
    steps: jax.Array


def _check_load(bearing: RollerBearing, operating: RollerOperating):
    if bearing.kind == "cylindrical_roller" and _is_concrete(operating.force) and float(operating.force[2]) != 0.0:
        raise ValueError(f"operating.force: a cylindrical roller bearing without ribs carries no axial load; "
                         f"Fz must be 0, got {float(operating.force[2]):g} N")


def solve_roller_equilibrium(bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating,
                             model: RollerModel = RollerModel()) -> RollerEquilibrium:
    """Inner-ring displacement Δ in equilibrium with the applied load; needs no initial guess.

    Differentiable in every array leaf of `bearing`, `raceways` and `operating` (implicit
    adjoint; least squares where the stiffness is singular, e.g. an unloaded bearing).
    `converged` is False where the scaled residual (ring and rollers) stays above
    `RESIDUAL_TOLERANCE`.
    """
    require_float64()
    _check_load(bearing, operating)
    setup = lamina_setup(bearing, raceways, model)
    unknown, weight, load_scale = _scales(bearing, raceways, operating, setup)
    args = (bearing, raceways, operating, model, setup, unknown, weight, load_scale)
    y, steps = implicit_root(_ring_residual, jnp.zeros(5), args, _ring_solve, least_squares_tangent_solve,
                             has_aux=True)
    displacement = _displacement(y, args)
    states = roller_states(displacement, bearing, raceways, operating, model, setup)
    centrifugal = roller_centrifugal_force(bearing, raceways, operating) if model.centrifugal else 0.0
    force = jnp.sum(_ring_contributions(displacement, states, bearing, raceways, centrifugal, setup), axis=0)
    free, _ = _controls(bearing, operating)
    residual = jnp.max(jnp.abs(jnp.where(free > 0, (force - _applied(bearing, operating)) * weight / load_scale, 0.0)))
    if model.centrifugal:
        scale = jnp.stack([ROLLER_SCALE, ROLLER_SCALE / (0.5 * bearing.length)])
        rollers = _roller_equations(states / scale, (displacement, bearing, raceways, setup, centrifugal, states / scale))
        residual = jnp.maximum(residual, jnp.max(jnp.abs(rollers)) * _roller_force_scale(bearing, setup)
                               / (jnp.max(jnp.abs(force[:3])) / bearing.roller_count + centrifugal + 1e-300))
    residual = jax.lax.stop_gradient(residual)
    return RollerEquilibrium(displacement, force, residual < RESIDUAL_TOLERANCE, residual, steps)


def roller_stiffness_matrix(displacement, bearing: RollerBearing, raceways: RollerRaceways,
                            operating: RollerOperating, model: RollerModel = RollerModel()):
    """5×5 stiffness K = dF/dΔ [N/m, N/rad; N·m/m, N·m/rad] with the rollers re-equilibrated (jacfwd)."""
    return jax.jacfwd(ring_force)(displacement, bearing, raceways, operating, model)


class RollerResults(eqx.Module):
    """Per-roller results at Δ (SI): azimuth ψ (Z,) [rad]; per contact (inner, outer) the roller
    load Q (Z,) [N], lamina loads per unit length (Z, n) [N/m] and the largest lamina Hertz
    line pressure (Z,) [Pa]; the rib force (Z,) [N]; the roller's tilt φ (Z,) [rad] and
    displacement across its axis u (Z,) [m]; lamina centres y (n,) [m]; the centrifugal force
    [N] (0 without that effect); the largest lamina approach [m], and each roller's at the inner
    and outer raceway (Z,) [m] (negative: open)."""

    azimuth: jax.Array
    inner_load: jax.Array
    outer_load: jax.Array
    inner_lamina_load: jax.Array
    outer_lamina_load: jax.Array
    inner_max_pressure: jax.Array
    outer_max_pressure: jax.Array
    rib_load: jax.Array
    tilt: jax.Array
    shift: jax.Array
    lamina_y: jax.Array
    centrifugal_force: jax.Array
    largest_approach: jax.Array  # the largest lamina approach at either raceway [m] (`MAX_APPROACH_FRACTION`)
    inner_approach: jax.Array
    outer_approach: jax.Array


# The model's limit on a lamina's approach: 1 % of the mean roller diameter, as for the balls
# (`ball_validity`): the line contact's half-width is then a fifth to a third of the roller radius
# and its pressure several times ISO 76's 4 GPa, where the slices' Hertz law and rigid rings no
# longer describe the contact (docs/theory.md §Envelopes).
MAX_APPROACH_FRACTION = 0.01


def roller_results(displacement, bearing: RollerBearing, raceways: RollerRaceways, operating: RollerOperating,
                   model: RollerModel = RollerModel()) -> RollerResults:
    """Per-roller and per-lamina loads, Hertz line pressures, rib forces and roller tilts at Δ."""
    setup = lamina_setup(bearing, raceways, model)
    states = roller_states(displacement, bearing, raceways, operating, model, setup)
    centrifugal = roller_centrifugal_force(bearing, raceways, operating) if model.centrifugal else jnp.asarray(0.0)
    inner, outer = contact_approaches(displacement, states, bearing, raceways, setup)
    inner_loads, outer_loads = _lamina_force(inner, bearing, setup), _lamina_force(outer, bearing, setup)
    _, _, rib = roller_forces(inner_loads, outer_loads, centrifugal, bearing, setup)
    modulus = roller_modulus(bearing)
    inner_curvature, outer_curvature = raceway_curvatures(bearing, raceways, setup.y)
    pressures = (line_contact(loads / setup.width, 1.0 / curvature[None, :], modulus).max_pressure
                 for loads, curvature in ((inner_loads, inner_curvature), (outer_loads, outer_curvature)))
    inner_pressure, outer_pressure = pressures
    return RollerResults(roller_azimuths(bearing), jnp.sum(inner_loads, axis=-1), jnp.sum(outer_loads, axis=-1),
                         inner_loads / setup.width, outer_loads / setup.width, jnp.max(inner_pressure, axis=-1),
                         jnp.max(outer_pressure, axis=-1), rib, states[:, 1], states[:, 0], setup.y, centrifugal,
                         jax.lax.stop_gradient(jnp.maximum(jnp.max(inner), jnp.max(outer))), jnp.max(inner, axis=-1),
                         jnp.max(outer, axis=-1))


def roller_contact_loadings(displacement, roller: int, bearing: RollerBearing, raceways: RollerRaceways,
                            operating: RollerOperating, model: RollerModel = RollerModel()):
    """(inner, outer) `RollerLoading`s of roller `roller`'s two contacts at Δ, for the pressure
    field by influence coefficients (`roller_contact.roller_contact`): the roller load [N], the
    tilt of roller against raceway (θ_t − φ inside, φ outside) [rad] and the raceway curvature at
    mid-length [1/m]. A logarithmic crown is sized there at each contact's own radius, the laminae's
    at the inner contact's (`lamina_gaps`): for the outer contact the two differ slightly."""
    results = roller_results(displacement, bearing, raceways, operating, model)
    _, tilt = ring_motion(displacement, bearing)
    middle = jnp.zeros(1)
    roller_curvature = 2.0 * jnp.cos(bearing.cone_half_angle) / roller_diameter(bearing, middle)[0]
    inner_sum, outer_sum = raceway_curvatures(bearing, raceways, middle)
    inner_curvature, outer_curvature = inner_sum[0] - roller_curvature, outer_sum[0] - roller_curvature
    inner = RollerLoading(load=results.inner_load[roller], tilt=tilt[roller] - results.tilt[roller],
                          raceway_curvature=inner_curvature)
    outer = RollerLoading(load=results.outer_load[roller], tilt=results.tilt[roller], raceway_curvature=outer_curvature)
    return inner, outer
