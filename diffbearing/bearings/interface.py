"""The interface a bearing type implements for the systems it is mounted in.

A rigid shaft (`shaft_equilibrium`), a flexible one (`flexible_shaft`) and a matched set
(`bearing_set`) see each bearing through `AbstractSupport` alone: a bearing at axial position z_k
on the shaft, turned or not (`orientation`), its inner ring pushed by an axial offset e_k, whose
load on its inner ring F_k(Δ_k) [N, N·m] for an inner-ring displacement Δ_k = [δx, δy, δz, θx, θy]
[m, rad] in its own frame the type computes with its rolling elements re-equilibrated. What a
system needs of it (docs/extending.md, "Adding a bearing type"):

* its ring force F_k(Δ, ω) and stiffness dF_k/dΔ at the shaft speed ω [rad/s] (outer ring fixed);
* a convex static energy E_k(Δ) whose gradient approximates F_k at standstill (the start of every
  solve: the minimum of Σ_k E_k − F·u needs no guess), a characteristic load [N] and its pitch
  radius [m] (the solve's scales), and where its Δ = 0 sits (`reference_offset`);
* constants built once per solve and handed back to every call (`constants`: a ball bearing's
  table of Hertz constants); supports with the same `constants_key` share them;
* its contacts at a solved state, one typed result for every type (`ContactLoads`: per rolling
  element and contact the load, laminae, pressure, angle, approach; which raceway; point or line),
  which the effects read (`ratings.reference_life`), its ratings' inputs (`dynamic_load_rating`,
  `contact_ratings`, ISO 281's `equivalent_dynamic_load`; ISO 76's `static_load_rating`,
  `equivalent_static_load`, `pressure_safety`;
  `rolling_element` for ISO 281's a_ISO; the friction models' rows, `friction_kind`; where a
  mounting's fits and temperatures act, `ring_section` and `with_clearance_change`), where a
  state stands against its envelope, the tilt it permits (`permissible_misalignment`) and its
  overrolling frequencies;
* where its rolling elements leave the static split at speed (`carries_elements`), their state
  as unknowns of the system's own Newton: a start, the elements condensed onto the ring
  (`CondensedElements`), a step limit and tolerance, and their own residual.

A system calls nothing else of a bearing, and no module outside a type's own package branches on
the type (tests/test_architecture.py checks both). The frames a mounted bearing sits in (a shaft's
bearings, a double-row bearing's rows): `transfer` G(z) moves a displacement from z = 0 to the
point at z, `turned` P turns a bearing mounted "−z" (docs/theory.md, §Shaft on several bearings).
"""

import abc

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

# The continuation in speed of every solve that carries rolling elements as unknowns (one bearing's
# ring solve, a shaft's, a flexible shaft's): the speed rises in these fractions of the operating
# speed, ω² in equal steps, each stage's Newton from the last one's solution.
SPEED_STAGES = tuple(((1.0 + stage) / 4.0) ** 0.5 for stage in range(4))  # plain floats: no JAX at import
RING_STEP_TOLERANCE = 1e-11  # a stage stops when every scaled ring step component is below this × (1 + |y|)
RING_MAX_STEPS = 100  # Newton steps per stage
TURNED = np.array([1.0, -1.0, -1.0, 1.0, -1.0])  # P: a bearing turned by π about x
RIGID_MISALIGNMENT = float(np.radians(10.0 / 60.0))  # rad: `AbstractSupport.permissible_misalignment`'s default


class CondensedElements(eqx.Module):
    """A bearing's rolling elements at ring displacement Δ and element state X, their equations
    g(Δ, X) = 0 eliminated to first order: the condensed ring force F − J_FX J_XX⁻¹ g (5) [N, N·m]
    and stiffness J_FΔ − J_FX J_XX⁻¹ J_XΔ (5, 5), and the elements' step parts J_XX⁻¹ g and
    J_XX⁻¹ J_XΔ (shaped as X, then X × 5): with a ring step dΔ the elements' Newton step is
    −(correction + coupling dΔ)."""

    force: jax.Array
    stiffness: jax.Array
    correction: jax.Array
    coupling: jax.Array


class RingSection(eqx.Module):
    """What a mounting's fits and temperatures act on (`systems.operating_clearance_change`): the
    inner and outer raceway diameters [m] (d_m ∓ D: a ball bearing's groove bottoms), the rolling
    element's diameter D [m] (a roller's at mid-length), the rings' material, and the diametral
    clearance [m] they change (negative: a preloaded bearing)."""

    inner_raceway_diameter: jax.Array
    outer_raceway_diameter: jax.Array
    element_diameter: jax.Array
    material: eqx.Module
    clearance: jax.Array


CONTACT_KINDS = ("point", "line")


class ContactLoads(eqx.Module):
    """The contacts of a bearing's rolling elements at a solved state: Z elements, each with C
    contacts (columns, each on one raceway: a ball bearing's inner and outer; a double-row
    bearing's four), SI units.

    `azimuth` (Z,) [rad]: each element's position; `load` (Z, C) [N]: its normal load at each
    contact; `lamina_load` (Z, C, L) [N]: a line contact's load on each of its L laminae (a point
    contact's: L = 1, its load); `max_pressure` (Z, C) [Pa]: the contact's (a line contact's:
    its largest lamina's) Hertz peak pressure; `angle` (Z, C) [rad]: a point contact's angle from
    the radial plane (None for line contacts, whose angle is the raceway's); `approach` (Z, C) [m]:
    the contact's elastic approach (a line contact's: its largest lamina's; negative: open);
    static: `raceways` (C,) "inner" or "outer" per column, `kind` "point" or "line" (an effect
    covers the kinds it names: `ratings.reference_life.EXPONENTS`)."""

    azimuth: jax.Array
    load: jax.Array
    lamina_load: jax.Array
    max_pressure: jax.Array
    angle: jax.Array | None
    approach: jax.Array
    raceways: tuple = eqx.field(static=True)
    kind: str = eqx.field(static=True)

    def __check_init__(self):
        if self.kind not in CONTACT_KINDS:
            raise ValueError(f"contact kind must be one of {CONTACT_KINDS}, got {self.kind!r}")
        if any(raceway not in ("inner", "outer") for raceway in self.raceways):
            raise ValueError(f"raceways: each 'inner' or 'outer', got {self.raceways!r}")

    def on(self, raceway: str):
        """The column indices of the contacts on `raceway` ("inner" or "outer")."""
        return tuple(column for column, name in enumerate(self.raceways) if name == raceway)


class AbstractSupport(eqx.Module):
    """A bearing mounted on a shaft: at `position` z [m], `orientation` +1 ("+z": its own axial
    direction along the shaft's +z) or −1 ("−z"), its inner ring pushed by `offset` [m] along its
    own axis against the outer ring (preload; 0: none). A bearing type subclasses it (module
    docstring); displacements and loads are in the bearing's own frame."""

    position: eqx.AbstractVar[jax.Array]
    offset: eqx.AbstractVar[jax.Array]
    orientation: eqx.AbstractVar[int]

    @abc.abstractmethod
    def constants(self):
        """What a solve builds once and hands to every call below (a pytree or None)."""

    def constants_key(self):
        """Supports whose keys are equal (and not None) share one `constants()`; None: its own."""
        return None

    @abc.abstractmethod
    def ring_force(self, displacement, speed, constants, elements=None):
        """[Fx, Fy, Fz, Mx, My] [N, N·m] that holds the inner ring at Δ `displacement` [m, rad] at
        shaft speed `speed` [rad/s], the rolling elements re-equilibrated (at `elements`, a solve's
        state of them, where given and the type carries them)."""

    @abc.abstractmethod
    def ring_stiffness(self, displacement, speed, constants, elements=None):
        """dF/dΔ (5, 5) [N/m, N/rad; N·m/m, N·m/rad] at Δ, the rolling elements re-equilibrated."""

    @abc.abstractmethod
    def energy_constants(self, constants):
        """What `static_energy` holds fixed, evaluated once per solve."""

    @abc.abstractmethod
    def static_energy(self, displacement, energy_constants):
        """E(Δ) [J], convex in Δ, its gradient the ring force at standstill with `energy_constants`
        held (the start of every solve)."""

    @abc.abstractmethod
    def characteristic_load(self, constants, energy_constants):
        """A load scale [N] that stays positive at zero applied load (a solve's residual scale)."""

    @abc.abstractmethod
    def pitch_radius(self):
        """Half the pitch diameter [m] (a solve's moment arm)."""

    @abc.abstractmethod
    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """The rolling elements' contacts at Δ (`ContactLoads`), at `elements` where a solve found
        them."""

    @abc.abstractmethod
    def dynamic_load_rating(self):
        """C_r [N]: the bearing's basic dynamic load rating (its own where given, else ISO 281's)."""

    @abc.abstractmethod
    def contact_ratings(self, rating, contacts: ContactLoads):
        """(C,) [N]: each contact column's ISO/TS 16281 rating per lamina, the lamina load of a
        raceway life of 10⁶ revolutions, from the dynamic load rating `rating` [N]
        (`ratings.reference_life`)."""

    @abc.abstractmethod
    def equivalent_dynamic_load(self, force):
        """P [N]: ISO 281's equivalent dynamic load of the load [Fx, Fy, Fz] [N] the bearing carries
        (its own frame), with the type's own X, Y (Table 3 or 8), for its basic rating life
        L10 = (C_r/P)^p (`ratings.life.basic_life_exponent`)."""

    @abc.abstractmethod
    def static_load_rating(self):
        """C₀ [N]: the bearing's basic static load rating (ISO 76)."""

    @abc.abstractmethod
    def equivalent_static_load(self, force):
        """P₀ [N]: ISO 76's equivalent static load of the load [Fx, Fy, Fz] [N] the bearing carries
        (its own frame), with the type's own X₀, Y₀."""

    @abc.abstractmethod
    def pressure_safety(self, max_pressure):
        """The static safety [-] of the largest contact pressure p_max [Pa] against ISO 76's
        permissible pressure of the type, as a load ratio (`ratings.static_safety.pressure_safety`)."""

    @abc.abstractmethod
    def rolling_element(self) -> str:
        """"ball" or "roller": which of ISO 281's life modification factors (a_ISO, e_C) apply."""

    def hybrid(self) -> bool:
        """Whether its rolling elements are ceramic while its rings are steel (the ISO 76 ratings
        above are then the all-steel ones); False unless the type says otherwise."""
        return False

    def friction_kind(self, model: str) -> str | None:
        """The bearing kind whose rows the friction model `model` ("palmgren": `friction.friction_torque`,
        "skf": `friction.skf_friction`) reads for this bearing; None where the model covers it not."""
        return None

    def friction_series(self) -> str | None:
        """The series of SKF's friction model the type's design fixes (None: the scene's or the
        kind's default)."""
        return None

    def nominal_contact_angle(self):
        """α [rad]: the nominal contact angle its ratings and friction loads read (0 for radial
        contact; a tapered roller bearing's cup angle)."""
        return 0.0

    def ring_section(self) -> "RingSection | None":
        """Its rings' raceway diameters, rolling element, material and clearance (`RingSection`),
        which a mounting's fits and temperatures act on (`systems.operating_clearance`); None where
        the type takes no mounting (its clearance is not one diametral clearance)."""
        return None

    def with_clearance_change(self, change) -> "AbstractSupport":
        """The support with its diametral clearance changed by `change` [m] (a mounting's:
        `operating_clearance_change`), for the types whose `ring_section` is not None."""
        raise NotImplementedError(f"{type(self).__name__} takes no mounting")

    def permissible_misalignment(self):
        """The largest tilt [rad] of its inner ring against its outer ring the catalogues permit:
        10′ for a rigid rolling bearing (deep-groove ball 2′–10′, angular-contact 2′, cylindrical
        roller 3′–4′: SKF Rolling bearings catalogue, 2018, "Permissible misalignment" of each
        type) unless the type says otherwise."""
        return RIGID_MISALIGNMENT

    @abc.abstractmethod
    def envelope(self, contacts: ContactLoads):
        """(3,) where a solved state stands against the model's envelope: the largest contact
        approach over the element's size [-], the largest loaded |contact angle| [rad] (0 for line
        contacts) and the lowest loaded contact angle [rad] (+π/2 where no low shoulder limits it)."""

    @abc.abstractmethod
    def frequencies(self, speed, contacts: ContactLoads):
        """The overrolling frequencies [Hz] (`overrolling.OverrollingFrequencies`) at shaft speed
        `speed` [rad/s], outer ring fixed, at the contacts' angles."""

    def balance_residual(self, displacement, speed, constants, load_scale):
        """The largest balance residual [-] of what the type solves inside its own ring force (its
        elements' equilibrium where a system does not carry them), over `load_scale` [N], at Δ: a
        system counts it in its convergence. 0 unless the type solves something there."""
        return jnp.zeros(())

    def reference_offset(self):
        """c [m]: where Δ = 0 sits along the bearing's axis when the shaft is at rest, from the
        type's own reference (Δ_k = P_k G_k u + (e_k + c_k) ẑ); 0 unless the type says otherwise."""
        return 0.0

    def locates_axially(self) -> bool:
        """Whether the bearing can carry an axial load (a shaft needs one that does)."""
        return True

    def carries_elements(self) -> bool:
        """Whether a system's Newton carries the rolling elements' state as unknowns (the methods
        below); else the system reads `ring_force` and `ring_stiffness` alone."""
        return False

    def start_elements(self, displacement, speed, constants):
        """The elements' state to start a joint Newton from, at Δ and `speed`."""
        raise NotImplementedError(f"{type(self).__name__} carries no element state")

    def condensed(self, displacement, elements, speed, constants) -> CondensedElements:
        """The elements at state `elements` condensed onto the ring (`CondensedElements`)."""
        raise NotImplementedError(f"{type(self).__name__} carries no element state")

    def limit_element_step(self, step):
        """An element step shortened where the type's contact law could throw it far."""
        raise NotImplementedError(f"{type(self).__name__} carries no element state")

    def element_tolerance(self):
        """The element step [as the state's unit] below which a stage has converged."""
        raise NotImplementedError(f"{type(self).__name__} carries no element state")

    def element_residual(self, displacement, elements, speed, constants, load_scale):
        """The elements' largest relative force balance [-] at a solved state."""
        raise NotImplementedError(f"{type(self).__name__} carries no element state")


def transfer(position):
    """G(z) (5, 5): the displacement [δx, δy, δz, θx, θy] of the shaft point at z from that at 0."""
    matrix = jnp.eye(5)
    return matrix.at[0, 4].set(position).at[1, 3].set(-position)


def turned(support):
    """P_k as its diagonal: TURNED for a bearing mounted "−z", else ones (it turns the bearing's
    own frame into the shaft's and back)."""
    return TURNED if support.orientation < 0 else np.ones(5)


def local_displacement(point_displacement, support):
    """Δ_k [m, rad]: a bearing's inner-ring displacement in its own frame from the displacement δ
    of the point it sits at, P_k δ + (e_k + c_k) ẑ (its offset e_k and `reference_offset` c_k)."""
    return (turned(support) * point_displacement).at[2].add(support.offset + support.reference_offset())


def support_displacement(displacement, support):
    """Δ_k [m, rad] of a displacement u at z = 0 of what the bearing sits on (a rigid shaft, a
    double-row bearing's rings): P_k G(z_k) u + (e_k + c_k) ẑ."""
    return local_displacement(transfer(support.position) @ displacement, support)


def support_move(support):
    """P_k G(z_k) (5, 5): dΔ_k/du, the bearing's inner-ring displacement per displacement u at
    z = 0 (`support_displacement`)."""
    return turned(support)[:, None] * transfer(support.position)


def check_orientation(orientation):
    """ValueError unless `orientation` is +1 ("+z") or −1 ("−z")."""
    if orientation not in (1, -1):
        raise ValueError(f"orientation must be +1 ('+z') or -1 ('-z'), got {orientation!r}")
