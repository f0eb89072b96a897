"""A cylindrical roller thrust bearing, single direction: Z cylindrical rollers, their axes radial,
between a shaft washer and a housing washer (both flat), as `AbstractSupport`.

Geometry (docs/theory.md §Cylindrical roller thrust bearings). Roller j sits at azimuth
ψ_j = 2πj/Z, its centre on the pitch circle (radius d_m/2), its axis radial; lamina k of width
L_we/n at y_k along the roller from its middle, at radius r_k = d_m/2 + y_k from the bearing axis.
The shaft washer ("inner") moves by Δ = [δx, δy, δz, θx, θy]; a point at radius r and azimuth ψ of
its face moves axially by δz − θ_t r with θ_t = θy cos ψ − θx sin ψ (the roller bearings' tilt at
the roller, `roller_equilibrium`). Each lamina pair (shaft washer and housing washer contacts in
series, the roller midway between them) has the total approach

    δ_jk = δz − θ_t,j r_k − 2 z(y_k),

z the roller's crown drop (`roller_profile.crown_drop`; flat washers: the equivalent radius in the
rolling direction is D_w/2), and each contact carries ISO/TS 16281's lamina load q(δ_jk/2)
(`roller_life.lamina_load`, scaled by E'/E'_steel as the radial roller bearings'). The ring force
is the gradient of the convex energy Σ 2 ∫₀^{δ/2} q: [0, 0, Σq, Σ q r sin ψ, −Σ q r cos ψ]. A
radial displacement changes no approach (flat washers): the housing washer floats radially, and
the bearing carries no radial load; the rollers' centrifugal force is radial, taken by the cage,
and leaves the washers' contacts alone (no gyroscopic moment is modelled).

Sliding. A cylinder rolls without sliding at one radius only; on the shaft washer, turning at ω
relative to the housing washer, a roller in pure rolling at the pitch radius (the balance of the
Coulomb friction of a load symmetric along it) slides at

    v_s(r) = ω |r − d_m/2| / 2

on both washers (`sliding_speeds`): its ends slide at ω L_we/4. This is why these bearings run hot:
with a sliding friction coefficient μ the loss is P = 2 Σ μ q v_s = μ ω Σ_jk q_jk |y_k|
(`sliding_power`), μ F_a ω L_we/4 for rollers loaded evenly along their length.

Ratings: ISO 281's C_a of thrust roller bearings at α = 90° (b_m = 1.0, f_c of Table 9;
`ratings.thrust_roller_ratings`), P_a = F_a; ISO 76's C₀a = 220 Z L_we D_we, P₀a = F_a; the
ISO/TS 16281 lamina ratings of thrust roller bearings; the permissible pressure of 4 000 MPa (ISO 76,
roller bearings).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ... import overrolling
from ...contact.hertz import line_contact
from ...params import _as_float, _is_concrete, check_range
from ...ratings import roller_life, static_safety, thrust_roller_ratings
from ..interface import AbstractSupport, ContactLoads, check_orientation
from .roller_contact import PALMGREN_STEEL_MODULUS
from .roller_equilibrium import RollerModel, lamina_positions, roller_azimuths
from .roller_geometry import RollerBearing, check_rollers_fit, roller_bearing, roller_modulus
from .roller_profile import crown_drop

AXIAL = 0.5 * np.pi
# The permissible tilt of roller bearings other than the NU/N 2, 3, 4 series, spherical and tapered
# ones (Autodesk Inventor's table, as the needle roller bearing's): flat washers take no misalignment.
PERMISSIBLE_MISALIGNMENT = float(np.radians(2.0 / 60.0))


def cylindrical_roller_thrust_bearing(*, roller_diameter, roller_length, rollers, profile=None, material=None
                                      ) -> RollerBearing:
    """The rollers of a cylindrical roller thrust bearing (SI): D_w [m], effective length L_we [m],
    Z, their crowning `profile` (straight by default) and `material` (rollers and washers; bearing
    steel by default). ValueError naming a bad key."""
    extra = {} if material is None else {"material": material}
    bearing = roller_bearing(kind="cylindrical_roller", length=roller_length, diameter=roller_diameter, profile=profile,
                             roller_count=rollers, **extra)
    if bearing.roller_count is None:
        raise ValueError("missing required key 'bearing.rollers' (the number of rollers Z)")
    return bearing


def check_pitch_diameter(bearing: RollerBearing, pitch_diameter) -> None:
    """ValueError naming bearing.pitch_diameter unless the rollers lie clear of the axis (d_m > L_we),
    bearing.rollers unless Z of them fit side by side on the pitch circle (D_w ≤ d_m sin(π/Z)) and
    bearing.roller_diameter unless D_w/d_m lies in ISO 281 Table 10 (0.01…0.30: the rating's f_c)."""
    check_range("bearing.pitch_diameter", pitch_diameter, low=0.0, unit=" m")
    if not _is_concrete(pitch_diameter, bearing.length, bearing.large_diameter):
        return
    if float(pitch_diameter) <= float(bearing.length):
        raise ValueError(f"bearing.pitch_diameter must exceed the roller length {float(bearing.length) * 1e3:.4g} mm "
                         f"(the rollers' inner ends clear of the axis), got {float(pitch_diameter) * 1e3:.4g} mm")
    check_rollers_fit(bearing.roller_count, bearing.large_diameter, pitch_diameter)
    ratios = thrust_roller_ratings.FC_RATIO
    check_range("bearing.roller_diameter", bearing.large_diameter, low=float(ratios[0] * pitch_diameter),
                high=float(ratios[-1] * pitch_diameter), low_open=False, high_open=False, unit=" m",
                why="D_w/d_m within ISO 281 Table 10's 0.01…0.30, where thrust roller bearings are rated")


def lamina_radii(bearing: RollerBearing, pitch_diameter, laminae: int):
    """r_k = d_m/2 + y_k [m]: each lamina's radius from the bearing axis, and the lamina width [m]."""
    y, width = lamina_positions(bearing, laminae)
    return 0.5 * pitch_diameter + y, width


def total_approach(displacement, bearing: RollerBearing, pitch_diameter, laminae: int):
    """δ_jk = δz − θ_t,j r_k − 2 z(y_k) [m] (Z, n): the approach of each lamina pair (module docstring)."""
    psi = roller_azimuths(bearing)
    tilt = displacement[4] * jnp.cos(psi) - displacement[3] * jnp.sin(psi)
    radii, _ = lamina_radii(bearing, pitch_diameter, laminae)
    y, _ = lamina_positions(bearing, laminae)
    drop = crown_drop(bearing.profile, y, bearing.length, roller_modulus(bearing), 0.5 * bearing.large_diameter)
    return displacement[2] - tilt[:, None] * radii[None, :] - 2.0 * drop[None, :]


def lamina_forces(approach, bearing: RollerBearing, laminae: int):
    """Force [N] of each lamina of one contact at approach `approach` [m] (ISO/TS 16281's law scaled
    by E'/E'_steel; 0 where open)."""
    return (roller_life.lamina_load(approach, bearing.length / laminae, bearing.length)
            * roller_modulus(bearing) / PALMGREN_STEEL_MODULUS)


def static_energy(displacement, bearing: RollerBearing, pitch_diameter, laminae: int):
    """E(Δ) = Σ 2 ∫₀^{δ/2} q [J]: convex in Δ, its gradient the ring force (∫₀^a c s^{10/9} = (9/19) a q(a))."""
    half = 0.5 * total_approach(displacement, bearing, pitch_diameter, laminae)
    return 2.0 * jnp.sum(9.0 / 19.0 * half * lamina_forces(half, bearing, laminae))


def ring_force(displacement, bearing: RollerBearing, pitch_diameter, laminae: int):
    """[Fx, Fy, Fz, Mx, My] [N, N·m] that holds the shaft washer at Δ: the energy's gradient (Fx = Fy = 0)."""
    return jax.grad(static_energy)(displacement, bearing, pitch_diameter, laminae)


def sliding_speeds(bearing: RollerBearing, pitch_diameter, speed, laminae: int):
    """v_s,k = ω |r_k − d_m/2| / 2 [m/s] (n,): each lamina's sliding speed on either washer for shaft
    washer speed ω [rad/s] relative to the housing washer, the rollers rolling at the pitch radius."""
    y, _ = lamina_positions(bearing, laminae)
    return 0.5 * jnp.abs(speed) * jnp.abs(y)


def sliding_power(contacts: ContactLoads, bearing: RollerBearing, pitch_diameter, speed, friction_coefficient):
    """P = Σ_jk μ (q_i,jk + q_o,jk) v_s,k [W]: the loss of the rollers' sliding on both washers with
    a Coulomb coefficient μ [-] (module docstring); its torque is P / |ω|."""
    check_range("friction_coefficient", friction_coefficient, low=0.0, high=1.0, low_open=False,
                why="a sliding friction coefficient")
    laminae = contacts.lamina_load.shape[-1]
    speeds = sliding_speeds(bearing, pitch_diameter, speed, laminae)
    return friction_coefficient * jnp.sum(jnp.sum(contacts.lamina_load, axis=1) * speeds[None, :])


class CylindricalRollerThrustSupport(AbstractSupport):
    """A cylindrical roller thrust bearing on a shaft: its rollers (`bearing`, a `RollerBearing`) on
    the pitch diameter d_m [m], at `position` z [m], `orientation` ±1 (its shaft washer pushed along
    its own +z loads it), `offset` [m] (a preload), `model` its laminae (`RollerModel`; its
    centrifugal flag changes nothing here: the rollers' centrifugal force is the cage's)."""

    bearing: RollerBearing
    pitch_diameter: jax.Array = eqx.field(converter=_as_float)
    position: jax.Array = eqx.field(converter=_as_float)
    offset: jax.Array = eqx.field(converter=_as_float, default=0.0)
    model: RollerModel = eqx.field(static=True, default=RollerModel())
    orientation: int = eqx.field(static=True, default=1)

    def __check_init__(self):
        check_orientation(self.orientation)

    def constants(self):
        return None

    def ring_force(self, displacement, speed, constants, elements=None):
        return ring_force(displacement, self.bearing, self.pitch_diameter, self.model.laminae)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """The energy's Hessian, exact (`jax.hessian`)."""
        return jax.hessian(static_energy)(displacement, self.bearing, self.pitch_diameter, self.model.laminae)

    def energy_constants(self, constants):
        return None

    def static_energy(self, displacement, energy_constants):
        return static_energy(displacement, self.bearing, self.pitch_diameter, self.model.laminae)

    def characteristic_load(self, constants, energy_constants):
        """Z × one roller's load at 10 µm of approach a contact [N]."""
        laminae = self.model.laminae
        return self.bearing.roller_count * laminae * lamina_forces(jnp.asarray(1e-5), self.bearing, laminae)

    def pitch_radius(self):
        return 0.5 * self.pitch_diameter

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Each roller's shaft-washer ("inner") and housing-washer ("outer") line contact, alike."""
        laminae = self.model.laminae
        half = 0.5 * total_approach(displacement, self.bearing, self.pitch_diameter, laminae)
        forces = lamina_forces(half, self.bearing, laminae)
        width = self.bearing.length / laminae
        pressure = line_contact(forces / width, 0.5 * self.bearing.large_diameter, roller_modulus(self.bearing)).max_pressure

        def pair(value):
            return jnp.stack([value, value], axis=1)

        return ContactLoads(roller_azimuths(self.bearing), pair(jnp.sum(forces, axis=-1)), pair(forces),
                            pair(jnp.max(pressure, axis=-1)), None, pair(jnp.max(half, axis=-1)), ("inner", "outer"),
                            "line")

    def dynamic_load_rating(self):
        """ISO 281's C_a at α = 90° (`thrust_roller_ratings.thrust_roller_dynamic_load_rating`)."""
        bearing = self.bearing
        return thrust_roller_ratings.thrust_roller_dynamic_load_rating(bearing.roller_count, bearing.large_diameter,
                                                                       bearing.length, self.pitch_diameter)

    def contact_ratings(self, rating, contacts: ContactLoads):
        """q_c [N] per lamina of either washer (`thrust_roller_ratings.thrust_roller_lamina_rating`)."""
        rated = thrust_roller_ratings.thrust_roller_lamina_rating(rating, self.bearing.roller_count,
                                                                   contacts.lamina_load.shape[-1])
        return jnp.stack([rated, rated])

    def equivalent_dynamic_load(self, force):
        """P_a = F_a (ISO 281, α = 90°; the washers take no radial load)."""
        return jnp.abs(force[2])

    def static_load_rating(self):
        """ISO 76 C₀a = 220 Z L_we D_we (α = 90°)."""
        bearing = self.bearing
        return thrust_roller_ratings.thrust_roller_static_load_rating(bearing.roller_count, bearing.large_diameter,
                                                                      bearing.length)

    def equivalent_static_load(self, force):
        """P₀a = F_a (ISO 76, α = 90°)."""
        return jnp.abs(force[2])

    def pressure_safety(self, max_pressure):
        """(4 000 MPa / p_max)², a roller bearing's."""
        return static_safety.pressure_safety(max_pressure, static_safety.ROLLER_PRESSURE_LIMIT,
                                             static_safety.LINE_CONTACT_EXPONENT)

    def rolling_element(self) -> str:
        return "roller"

    def nominal_contact_angle(self):
        return AXIAL

    def friction_kind(self, model: str) -> str | None:
        """Both models' cylindrical roller thrust rows (HR 1's 811, SKF's one row for the type)."""
        return "cylindrical_roller_thrust"

    def permissible_misalignment(self):
        """2′ (`PERMISSIBLE_MISALIGNMENT`)."""
        return PERMISSIBLE_MISALIGNMENT

    def envelope(self, contacts: ContactLoads):
        """The largest lamina approach / D_w; 0 and π/2 (no contact angle of its own, no shoulder)."""
        return jnp.stack([jnp.max(contacts.approach) / self.bearing.large_diameter, 0.0, 0.5 * jnp.pi])

    def frequencies(self, speed, contacts: ContactLoads):
        """At α = 90°: cage ω/2, roller passes Z ω/2 on either washer, roller spin (d_m/D_w) ω/2 [Hz]."""
        return overrolling.nominal_frequencies(speed, 0.0, self.bearing.roller_count, self.bearing.large_diameter,
                                               self.pitch_diameter, AXIAL)


def cylindrical_roller_thrust_support(bearing: RollerBearing, pitch_diameter, position, offset=0.0,
                                      model: RollerModel = RollerModel(), orientation=1
                                      ) -> CylindricalRollerThrustSupport:
    """A `CylindricalRollerThrustSupport` of `bearing` (`cylindrical_roller_thrust_bearing`) on the pitch
    diameter `pitch_diameter` [m]; ValueError naming a bad key (`check_pitch_diameter`)."""
    check_pitch_diameter(bearing, pitch_diameter)
    return CylindricalRollerThrustSupport(bearing, pitch_diameter, position, offset, model=model, orientation=orientation)
