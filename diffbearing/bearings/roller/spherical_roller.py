"""A spherical roller bearing: two rows of symmetrical barrel rollers between an inner ring with two
raceways and one spherical outer raceway, as `AbstractSupport`.

Geometry (docs/theory.md §Spherical roller bearings). In the axial plane of a roller (axial a,
radial r) the outer raceway is an arc of the sphere of radius R_o about the bearing's centre O. A
roller of row 1 (row 2 mirrored in a) touches it at the nominal contact angle α, on the normal
n = (sin α, cos α) through O; its centre lies on that normal at R_c = d_m/(2 cos α) from O, so that
R_o = R_c + D_w/2, and its axis along t = (cos α, −sin α). The barrel's profile (in the axial
plane) is an arc of radius R_r about the point on n at R_o − R_r from O (outer side) and the mirror
point (inner side); the inner raceway's profile an arc of radius R_i about the point on n at
q = R_o − D_w + R_i from O. Both contacts conform (R_r < R_i, R_r < R_o): lamina k at y_k along the
roller is open by y_k²/2 (1/R_r − 1/R_race) at zero load, the crown its profiles make.

Each roller moves in its plane by u along n, w along t and turns by φ (t → t + φ n); the inner ring
by Δ = [δx, δy, δz, θx, θy], that is by T = (δz, δx cos ψ + δy sin ψ) and the tilt
θ_t = θy cos ψ − θx sin ψ at the roller (`roller_equilibrium`'s convention). To first order in the
displacements the lamina approaches are

    outer  δ_o,k = u + y_k (φ R_c + w)/R_o − y_k²/2 (1/R_r − 1/R_o) − c
    inner  δ_i,k = T·n − u − φ y_k + (y_k/R_i)(w + φ D_w/2 − T·t ∓ θ_t q) − y_k²/2 (1/R_r − 1/R_i) − c

(∓: − for row 1, + for row 2, the sense in which the ring's tilt moves its raceway's profile
centre along t), with c = P_d cos α / 4 a quarter of the normal play of a diametral clearance P_d.
A rotation of the inner ring and its rollers about O (θ_t = β, and each roller w = ∓β R_c, φ = ±β)
leaves every approach unchanged: the bearing is self-aligning, its tilt stiffness zero and the
moment of its contact forces about O zero (tests/test_spherical_roller.py checks both on this
model). As for the self-aligning ball bearing the support therefore takes the rows' load at the
inner ring's translation alone, F = [F(δ, 0)_{1..3}, 0, 0], exact at any tilt within the outer
raceway (`PERMISSIBLE_MISALIGNMENT`).

Each contact lamina carries ISO/TS 16281's q(δ) (`roller_life.lamina_load`, scaled by E'/E'_steel);
each roller minimises its energy Σ_k Φ(δ_i,k) + Φ(δ_o,k), Φ' = q, a convex problem in (u, w, φ)
solved by damped Newton per roller with its implicit derivative (`newton.implicit_root`); the ring
force is the energy's gradient in Δ at the rollers' minimum, and its stiffness `jax.jacfwd` of it.
The model is static: a roller's centrifugal force is radial, not along the normal through O, and in
the unloaded zone only the guide ring between the rows keeps it from sliding along the sphere,
which the model does not hold (`effects.centrifugal` is refused).

Ratings: ISO 281 C_r of radial roller bearings with i = 2 and b_m = 1.15 (spherical roller
bearings, Table 6), P = X F_r + Y F_a of double-row radial roller bearings (Table 8: e = 1.5 tan α,
Y₁ = 0.45 cot α with X = 1 up to e, X = 0.67 and Y₂ = 0.67 cot α above); ISO 76 C₀r = 44 (1 − γ)
i Z L_we D_we cos α, P₀ = F_r + 0.44 cot α F_a; ISO/TS 16281's lamina ratings with i = 2; the
permissible pressure of 4 000 MPa (ISO 76, roller bearings).
"""

import functools

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ... import overrolling
from ...contact.hertz import line_contact
from ...newton import block_newton, block_tangent_solve, implicit_root
from ...params import BEARING_STEEL, Material, _as_float, _is_concrete, check_range
from ...ratings import roller_life, static_safety
from ...ratings.radial_load_factors import radial_and_axial
from ..interface import AbstractSupport, ContactLoads, check_orientation
from .roller_contact import PALMGREN_STEEL_MODULUS
from .roller_equilibrium import ROLLER_SCALE, ROLLER_STEP_TOLERANCE, RollerModel
from .roller_equilibrium import roller_azimuths as _azimuths
from .roller_geometry import RollerBearing, check_rollers_fit, roller_bearing, roller_modulus

ROWS = 2
# ISO 281:2007 Table 6: b_m of spherical roller bearings (the cylindrical roller bearings' 1.1, `BM_ROLLER`)
BM_SPHERICAL = 1.15
# The permissible tilt of double-row spherical roller bearings in Autodesk Inventor's table (Inventor
# Help, "Permissible bearing misalignment"): 1.5°; the catalogues give 1.5°–3° by series.
PERMISSIBLE_MISALIGNMENT = float(np.radians(1.5))
TRANSLATION = np.array([1.0, 1.0, 1.0, 0.0, 0.0])  # the components of Δ and F a sphere transmits
ROLLER_NEWTON_STEPS = 60  # the barrel rollers' three unknowns take more steps than the radial rollers' two
# The centring spring that keeps an unloaded roller's modes at their start, per scaled unit over the
# force scale: the radial rollers' 1e-14 (`roller_equilibrium.CENTRING`) biased a barely loaded
# barrel roller's nearly free w, φ enough to move the ring force by up to 4e-4 of itself against the
# exact minimum (Δ = [−8.1, 4.1, −131] µm); at 1e-18 the ring force is the energy's total derivative
# to 4e-8 over 150 random states, all finite (tests/test_spherical_roller.py walks them).
CENTRING = 1e-18
MAX_CONTACT_ANGLE = float(np.radians(20.0))  # spherical roller bearings' α: about 6°–15° by series


class SphericalRollerRaceways(eqx.Module):
    """The rings of a spherical roller bearing: pitch diameter d_m [m] (the roller centres'),
    nominal contact angle α [rad], the inner raceways' profile radius R_i [m], the diametral
    clearance P_d [m]."""

    pitch_diameter: jax.Array = eqx.field(converter=_as_float)
    contact_angle: jax.Array = eqx.field(converter=_as_float)
    inner_profile_radius: jax.Array = eqx.field(converter=_as_float)
    diametral_clearance: jax.Array = eqx.field(converter=_as_float, default=0.0)


class SphericalRoller(eqx.Module):
    """A barrel roller: its `RollerBearing` (diameter D_w at mid-length, effective length L_we, count
    Z per row, material; its own profile straight: the barrel is `profile_radius`) and the profile
    radius R_r [m] of its barrel in the axial plane."""

    rollers: RollerBearing
    profile_radius: jax.Array = eqx.field(converter=_as_float)


def sphere_radius(roller: SphericalRoller, raceways: SphericalRollerRaceways):
    """R_o = d_m / (2 cos α) + D_w/2 [m]: the outer raceway through the rollers at α."""
    return 0.5 * raceways.pitch_diameter / jnp.cos(raceways.contact_angle) + 0.5 * roller.rollers.large_diameter


def spherical_roller(*, roller_diameter, roller_length, rollers, profile_radius,
                     material: Material = BEARING_STEEL) -> SphericalRoller:
    """The barrel rollers (SI): D_w, L_we, Z per row, the barrel's profile radius R_r [m] > L_we;
    ValueError naming a bad key."""
    bearing = roller_bearing(kind="cylindrical_roller", length=roller_length, diameter=roller_diameter,
                             material=material, roller_count=rollers)
    if bearing.roller_count is None:
        raise ValueError("missing required key 'bearing.rollers' (the number of rollers Z in each row)")
    low = float(roller_length) if _is_concrete(roller_length) else 0.0
    check_range("bearing.roller_profile_radius", profile_radius, low=low, unit=" m",
                why="the barrel's profile radius exceeds the roller's length")
    return SphericalRoller(bearing, profile_radius)


def spherical_roller_raceways(roller: SphericalRoller, *, pitch_diameter, contact_angle, inner_profile_radius,
                              diametral_clearance=0.0) -> SphericalRollerRaceways:
    """Validated `SphericalRollerRaceways`: d_m, α (0 < α ≤ 20°), R_i [m] above the roller's R_r
    and P_d; ValueError naming a bad key (rollers that do not fit, a sphere not larger than R_r)."""
    diameter = roller.rollers.large_diameter
    check_range("bearing.pitch_diameter", pitch_diameter, low=float(diameter) if _is_concrete(diameter) else 0.0,
                unit=" m", why="the pitch diameter exceeds the roller diameter")
    check_range("bearing.contact_angle", contact_angle, low=0.0, high=MAX_CONTACT_ANGLE, high_open=False, unit=" rad",
                why="a spherical roller bearing's nominal contact angle, up to 20°")
    check_range("bearing.inner_profile_radius", inner_profile_radius,
                low=float(roller.profile_radius) if _is_concrete(roller.profile_radius) else 0.0, unit=" m",
                why="the inner raceways' profile radius exceeds the roller's (a conforming contact)")
    floor = -0.01 * float(pitch_diameter) if _is_concrete(pitch_diameter) else None
    check_range("bearing.radial_clearance", diametral_clearance, low=floor, unit=" m",
                why="diametral clearance; negative for a preloaded bearing, above −1 % of d_m")
    raceways = SphericalRollerRaceways(pitch_diameter, contact_angle, inner_profile_radius, diametral_clearance)
    if _is_concrete(pitch_diameter, contact_angle, diameter, roller.profile_radius):
        outer = float(sphere_radius(roller, raceways))
        if float(roller.profile_radius) >= outer:
            raise ValueError(f"bearing.roller_profile_radius must be below the outer raceway's sphere radius "
                             f"R_o = d_m/(2 cos α) + D_w/2 = {outer * 1e3:.4g} mm, got "
                             f"{float(roller.profile_radius) * 1e3:.4g} mm")
    check_rollers_fit(roller.rollers.roller_count, diameter, pitch_diameter)
    return raceways


class SphericalSetup(eqx.Module):
    """What every evaluation shares: lamina positions y [m] and width [m], each row's n, t (2, 2)
    (axial, radial) and tilt sense ∓1, the radii R_o, R_c, q [m] and each contact's gap (n,) [m]."""

    y: jax.Array
    width: jax.Array
    normal: jax.Array
    axis: jax.Array
    tilt_sense: jax.Array
    outer_radius: jax.Array
    centre_radius: jax.Array
    inner_centre: jax.Array
    inner_gap: jax.Array
    outer_gap: jax.Array


def spherical_setup(roller: SphericalRoller, raceways: SphericalRollerRaceways, laminae: int) -> SphericalSetup:
    rollers = roller.rollers
    width = rollers.length / laminae
    y = (jnp.arange(laminae) + 0.5) * width - 0.5 * rollers.length
    angle = raceways.contact_angle
    sin, cos = jnp.sin(angle), jnp.cos(angle)
    normal = jnp.stack([jnp.stack([sin, cos]), jnp.stack([-sin, cos])])
    axis = jnp.stack([jnp.stack([cos, -sin]), jnp.stack([-cos, -sin])])
    outer = sphere_radius(roller, raceways)
    diameter = rollers.large_diameter
    play = 0.25 * raceways.diametral_clearance * cos
    return SphericalSetup(y, width, normal, axis, jnp.array([-1.0, 1.0]), outer, outer - 0.5 * diameter,
                          outer - diameter + raceways.inner_profile_radius,
                          0.5 * y**2 * (1.0 / roller.profile_radius - 1.0 / raceways.inner_profile_radius) + play,
                          0.5 * y**2 * (1.0 / roller.profile_radius - 1.0 / outer) + play)


def roller_azimuths(roller: SphericalRoller):
    """ψ_j = 2πj/Z [rad], roller 0 of each row on +x (the rows' rollers side by side)."""
    return _azimuths(roller.rollers)


def _translation(displacement, psi):
    """T (Z, 2) [m]: the inner ring's in-plane translation (axial, radial) at each roller."""
    return jnp.stack([jnp.broadcast_to(displacement[2], psi.shape),
                      displacement[0] * jnp.cos(psi) + displacement[1] * jnp.sin(psi)], axis=-1)


def approaches(displacement, states, roller: SphericalRoller, raceways: SphericalRollerRaceways, setup: SphericalSetup):
    """(inner, outer) lamina approaches [m], each (2 rows, Z, n), for ring displacement Δ and roller
    states (2, Z, 3) = (u [m], w [m], φ [rad]) (module docstring)."""
    psi = roller_azimuths(roller)
    translation = _translation(displacement, psi)
    tilt = displacement[4] * jnp.cos(psi) - displacement[3] * jnp.sin(psi)
    along_normal = jnp.einsum("zc,rc->rz", translation, setup.normal)  # (2, Z)
    along_axis = jnp.einsum("zc,rc->rz", translation, setup.axis)
    u, w, phi = states[..., 0][..., None], states[..., 1][..., None], states[..., 2][..., None]
    y = setup.y
    half = 0.5 * roller.rollers.large_diameter
    outer = u + y * (phi * setup.centre_radius + w) / setup.outer_radius - setup.outer_gap
    shift = w + phi * half - (along_axis + setup.tilt_sense[:, None] * tilt[None, :] * setup.inner_centre)[..., None]
    inner = (along_normal[..., None] - u - phi * y + y * shift / raceways.inner_profile_radius - setup.inner_gap)
    return inner, outer


def lamina_forces(approach, roller: SphericalRoller, setup: SphericalSetup):
    """Force [N] of each lamina of one contact at approach δ [m] (ISO/TS 16281's law, E'/E'_steel)."""
    rollers = roller.rollers
    return roller_life.lamina_load(approach, setup.width, rollers.length) * roller_modulus(rollers) / PALMGREN_STEEL_MODULUS


def energy(displacement, states, roller: SphericalRoller, raceways: SphericalRollerRaceways, setup: SphericalSetup):
    """Σ over rollers and laminae of Φ(δ_i) + Φ(δ_o) [J], convex in (Δ, states) (Φ(a) = ∫₀^a q = (9/19) a q(a))."""
    inner, outer = approaches(displacement, states, roller, raceways, setup)
    return sum(jnp.sum(9.0 / 19.0 * a * lamina_forces(a, roller, setup)) for a in (inner, outer))


def _state_scale(roller: SphericalRoller):
    return jnp.stack([ROLLER_SCALE, ROLLER_SCALE, ROLLER_SCALE / (0.5 * roller.rollers.length)])


def _force_scale(roller: SphericalRoller, setup: SphericalSetup):
    """One roller's load at 1 µm of approach a contact [N]."""
    return jnp.sum(lamina_forces(jnp.full(setup.y.shape, ROLLER_SCALE), roller, setup))


def _roller_equations(scaled, args):
    """(2, Z, 3) each roller's energy gradient in its scaled state over the force scale, plus the
    centring spring (an unloaded roller keeps its start)."""
    displacement, roller, raceways, setup, start = args
    scale = _state_scale(roller)
    gradient = jax.grad(lambda s: energy(displacement, s * scale, roller, raceways, setup))(scaled)
    return gradient / _force_scale(roller, setup) + CENTRING * (scaled - start)


def roller_states(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways, setup: SphericalSetup):
    """(2, Z, 3) the rollers' (u [m], w [m], φ [rad]) at their energy's minimum for Δ, from midway
    (u = T·n/2), with the implicit derivative."""
    translation = _translation(displacement, roller_azimuths(roller))
    midway = 0.5 * jnp.einsum("zc,rc->rz", translation, setup.normal)
    scale = _state_scale(roller)
    start = jax.lax.stop_gradient(jnp.stack([midway, jnp.zeros_like(midway), jnp.zeros_like(midway)], axis=-1) / scale)
    args = (displacement, roller, raceways, setup, start)
    solve = functools.partial(block_newton, max_steps=ROLLER_NEWTON_STEPS, step_tolerance=ROLLER_STEP_TOLERANCE)
    return implicit_root(_roller_equations, start, args, solve, block_tangent_solve) * scale


def full_ring_force(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways, model: RollerModel):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] of the first-order model at any Δ, tilt included: the energy's
    gradient in Δ at the rollers' minimum (their implicit derivative carried, so that `jax.jacfwd` of
    it is the stiffness with the rollers re-equilibrated). Its moments vanish and it does not change
    with the tilt: the self-aligning identities the support relies on."""
    setup = spherical_setup(roller, raceways, model.laminae)
    states = roller_states(displacement, roller, raceways, setup)
    return jax.grad(energy)(displacement, states, roller, raceways, setup)


def ring_force(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways, model: RollerModel):
    """F = [F(δ, 0)_{1..3}, 0, 0]: the rows' load at the inner ring's translation (module docstring)."""
    return TRANSLATION * full_ring_force(displacement * TRANSLATION, roller, raceways, model)


def static_energy(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways, model: RollerModel):
    """E(Δ) = min over the rollers of the energy at standstill, of Δ's translation [J]: convex, its
    gradient the static ring force."""
    setup = spherical_setup(roller, raceways, model.laminae)
    held = displacement * TRANSLATION
    states = roller_states(held, roller, raceways, setup)
    return energy(held, states, roller, raceways, setup)


def roller_balance(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways, model: RollerModel):
    """The largest component of any roller's energy gradient in its scaled state [N] at the solved
    states for Δ's translation (0 in equilibrium; the centring spring left out)."""
    setup = spherical_setup(roller, raceways, model.laminae)
    held = displacement * TRANSLATION
    states = roller_states(held, roller, raceways, setup)
    scale = _state_scale(roller)
    gradient = jax.grad(lambda s: energy(held, s * scale, roller, raceways, setup))(states / scale)
    return jnp.max(jnp.abs(gradient))


class SphericalRollerResults(eqx.Module):
    """Per roller (2 rows, Z) at Δ: loads [N], lamina loads (2, Z, n) [N], the largest lamina Hertz
    line pressure [Pa] and approach [m] of each contact; the states (2, Z, 3)."""

    inner_load: jax.Array
    outer_load: jax.Array
    inner_lamina_load: jax.Array
    outer_lamina_load: jax.Array
    inner_max_pressure: jax.Array
    outer_max_pressure: jax.Array
    inner_approach: jax.Array
    outer_approach: jax.Array
    states: jax.Array


def roller_results(displacement, roller: SphericalRoller, raceways: SphericalRollerRaceways,
                   model: RollerModel) -> SphericalRollerResults:
    """Every roller's contacts at Δ's translation (the tilt moves no contact)."""
    setup = spherical_setup(roller, raceways, model.laminae)
    held = displacement * TRANSLATION
    states = roller_states(held, roller, raceways, setup)
    inner, outer = approaches(held, states, roller, raceways, setup)
    inner_loads, outer_loads = lamina_forces(inner, roller, setup), lamina_forces(outer, roller, setup)
    modulus = roller_modulus(roller.rollers)
    half = 0.5 * roller.rollers.large_diameter
    # rolling direction: the roller's curvature 2/D_w and the ring's at the contact, cos α / r
    centre = 0.5 * raceways.pitch_diameter
    cos = jnp.cos(raceways.contact_angle)
    inner_radius = 1.0 / (1.0 / half + cos / (centre - half * cos))
    outer_radius = 1.0 / (1.0 / half - cos / (centre + half * cos))

    def peak(loads, radius):
        return jnp.max(line_contact(loads / setup.width, radius, modulus).max_pressure, axis=-1)

    return SphericalRollerResults(jnp.sum(inner_loads, axis=-1), jnp.sum(outer_loads, axis=-1), inner_loads, outer_loads,
                                  peak(inner_loads, inner_radius), peak(outer_loads, outer_radius),
                                  jnp.max(inner, axis=-1), jnp.max(outer, axis=-1), states)


def equivalent_dynamic_load(force, contact_angle):
    """ISO 281 P [N] of a double-row radial roller bearing (Table 8): e = 1.5 tan α; F_a/F_r ≤ e:
    F_r + 0.45 cot α F_a, else 0.67 F_r + 0.67 cot α F_a."""
    radial, axial = radial_and_axial(force)
    cotangent = 1.0 / jnp.tan(contact_angle)
    light = axial <= 1.5 * jnp.tan(contact_angle) * radial
    return jnp.where(light, radial + 0.45 * cotangent * axial, 0.67 * radial + 0.67 * cotangent * axial)


def equivalent_static_load(force, contact_angle):
    """ISO 76 P₀ = F_r + 0.44 cot α F_a [N] of a double-row radial roller bearing (X₀ = 1, Y₀ = 0.44 cot α)."""
    radial, axial = radial_and_axial(force)
    return radial + 0.44 / jnp.tan(contact_angle) * axial


class SphericalRollerSupport(AbstractSupport):
    """A spherical roller bearing on a shaft: its `roller` and `raceways` at `position` z [m],
    `orientation` ±1, `offset` [m] (a preload along its axis), `model` the laminae (`RollerModel`;
    static: its centrifugal force is refused, module docstring)."""

    roller: SphericalRoller
    raceways: SphericalRollerRaceways
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: RollerModel = eqx.field(static=True, default=RollerModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        check_orientation(self.orientation)
        if self.model.centrifugal:
            raise ValueError("effects.centrifugal: the spherical roller bearing model is static (its unloaded rollers' "
                             "centrifugal force would need the guide ring, not modelled)")

    def constants(self):
        return None

    def ring_force(self, displacement, speed, constants, elements=None):
        return ring_force(displacement, self.roller, self.raceways, self.model)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """`jax.jacfwd` of the ring force: zero rows and columns in θ."""
        return jax.jacfwd(ring_force)(displacement, self.roller, self.raceways, self.model)

    def energy_constants(self, constants):
        return None

    def static_energy(self, displacement, energy_constants):
        return static_energy(displacement, self.roller, self.raceways, self.model)

    def balance_residual(self, displacement, speed, constants, load_scale):
        """The rollers' largest force balance [N] at their solved states over `load_scale` [N] (each
        roller's Newton inside the ring force)."""
        return jax.lax.stop_gradient(roller_balance(displacement, self.roller, self.raceways, self.model) / load_scale)

    def characteristic_load(self, constants, energy_constants):
        """Both rows' rollers at 10 µm of approach a contact [N]."""
        setup = spherical_setup(self.roller, self.raceways, self.model.laminae)
        one = jnp.sum(lamina_forces(jnp.full(setup.y.shape, 1e-5), self.roller, setup))
        return ROWS * self.roller.rollers.roller_count * one

    def pitch_radius(self):
        return 0.5 * self.raceways.pitch_diameter

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Four contacts a position: row 1 inner and outer, row 2 inner and outer."""
        found = roller_results(displacement, self.roller, self.raceways, self.model)

        def columns(inner, outer):
            return jnp.stack([inner[0], outer[0], inner[1], outer[1]], axis=1)

        return ContactLoads(roller_azimuths(self.roller), columns(found.inner_load, found.outer_load),
                            columns(found.inner_lamina_load, found.outer_lamina_load),
                            columns(found.inner_max_pressure, found.outer_max_pressure), None,
                            columns(found.inner_approach, found.outer_approach), ("inner", "outer", "inner", "outer"),
                            "line")

    def dynamic_load_rating(self):
        """ISO 281 C_r with i = 2 and b_m = 1.15: the radial roller bearings' (b_m = 1.1) times 1.15/1.1."""
        rollers = self.roller.rollers
        return (roller_life.roller_dynamic_load_rating(rollers.roller_count, rollers.large_diameter, rollers.length,
                                                       self.raceways.contact_angle, self.raceways.pitch_diameter, ROWS)
                * BM_SPHERICAL / roller_life.BM_ROLLER)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """q_ci, q_ce [N] per lamina (ISO/TS 16281 eqs. (47)–(49), (56)–(57), i = 2) for each row's columns."""
        rollers = self.roller.rollers
        inner, outer = roller_life.lamina_ratings(rating, rollers.roller_count, rollers.large_diameter,
                                                  self.raceways.contact_angle, self.raceways.pitch_diameter,
                                                  contacts.lamina_load.shape[-1], ROWS)
        return jnp.stack([inner, outer, inner, outer])

    def equivalent_dynamic_load(self, force):
        return equivalent_dynamic_load(force, self.raceways.contact_angle)

    def static_load_rating(self):
        """ISO 76 C₀r = 44 (1 − γ) i Z L_we D_we cos α, i = 2."""
        rollers = self.roller.rollers
        return static_safety.roller_static_load_rating(rollers.roller_count, rollers.large_diameter, rollers.length,
                                                       self.raceways.pitch_diameter, self.raceways.contact_angle, ROWS)

    def equivalent_static_load(self, force):
        return equivalent_static_load(force, self.raceways.contact_angle)

    def pressure_safety(self, max_pressure):
        """(4 000 MPa / p_max)², a roller bearing's."""
        return static_safety.pressure_safety(max_pressure, static_safety.ROLLER_PRESSURE_LIMIT,
                                             static_safety.LINE_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "roller"

    def nominal_contact_angle(self):
        return self.raceways.contact_angle

    def friction_kind(self, model: str) -> str | None:
        """Both models' spherical roller rows (HR 1's 222 series by default; SKF's Table 3e)."""
        return "spherical_roller"

    def permissible_misalignment(self):
        """1.5° (`PERMISSIBLE_MISALIGNMENT`)."""
        return PERMISSIBLE_MISALIGNMENT

    def envelope(self, contacts: ContactLoads):
        """The largest lamina approach / D_w; 0 and π/2 (line contacts, no shoulder)."""
        return jnp.stack([jnp.max(contacts.approach) / self.roller.rollers.large_diameter, 0.0, 0.5 * jnp.pi])

    def frequencies(self, speed, contacts: ContactLoads):
        """The nominal overrolling frequencies at α (`overrolling.nominal_frequencies`)."""
        rollers = self.roller.rollers
        return overrolling.nominal_frequencies(speed, 0.0, rollers.roller_count, rollers.large_diameter,
                                               self.raceways.pitch_diameter, self.raceways.contact_angle)


def spherical_roller_support(roller: SphericalRoller, raceways: SphericalRollerRaceways, position, offset=0.0,
                             model: RollerModel = RollerModel(), orientation=1) -> SphericalRollerSupport:
    """A `SphericalRollerSupport` of `roller` (`spherical_roller`) in `raceways` (`spherical_roller_raceways`)."""
    return SphericalRollerSupport(roller, raceways, position, offset, model=model, orientation=orientation)
