"""A needle roller bearing: a cylindrical roller bearing whose rollers are long and thin
(L_we > 2.5 D_we), with a machined outer ring or a drawn cup, with an inner ring or running
directly on the shaft, as `AbstractSupport`.

Model. The rollers, their laminae and the rings are the cylindrical roller bearing's
(`roller_equilibrium`, ISO/TS 16281 slicing; docs/theory.md §Needle roller bearings): the rollers
carry radial load and tilt, no axial load, and a long roller's laminae see the tilt ϑ of its rings
as a gap ϑ y_k that grows along its length. A roller of length L_we whose ends differ by ϑ L_we
more than its approach δ at mid-length carries its load on one end only — the edge-stress hazard
of long rollers, which crowning (the roller's `profile`) and alignment keep away. Catalogues
therefore allow needle roller bearings less tilt than short-roller bearings
(`PERMISSIBLE_MISALIGNMENT`); a shaft warns past it.

Without an inner ring the rollers run on the shaft, whose raceway diameter is then the rollers'
inner envelope F_w = d_m − D_w, and whose hardness and finish (58–64 HRC, the ring steel's) the
ratings assume.

Ratings: ISO 281's C_r of radial roller bearings with its b_m of needle roller bearings
(`RATING_FACTORS`, ISO 281:2007 Table 1: 1.1 with machined rings, 1.0 drawn cup); ISO 76's C₀r,
P₀r and the ISO/TS 16281 lamina ratings as the cylindrical roller bearing's; the permissible
pressure of 4 000 MPa (ISO 76, roller bearings).
"""

import equinox as eqx
import numpy as np

from ...params import BEARING_STEEL, Material, _is_concrete
from ...ratings import roller_life
from ..interface import AbstractSupport, ContactLoads
from .roller_equilibrium import RollerModel, RollerRaceways, roller_raceways
from .roller_geometry import RollerBearing, check_rollers_fit, roller_bearing
from .roller_support import RollerSupport

# ISO/TS 16281:2008 eqs. (42)–(43): its reference roller profile splits short rollers (L_we ≤ 2.5 D_we)
# from long ones; a roller bearing with long rollers is a needle roller bearing here.
LONG_ROLLER_RATIO = 2.5
OUTER_RINGS = ("machined", "drawn_cup")
# ISO 281:2007 Table 1, b_m of radial roller bearings: needle roller bearings with machined rings 1.1
# (as cylindrical roller bearings, `roller_life.BM_ROLLER`), drawn cup needle roller bearings 1.0.
RATING_FACTORS = {"machined": roller_life.BM_ROLLER, "drawn_cup": 1.0}
# The table of permissible bearing tilt in Autodesk Inventor's bearing calculator (Inventor Help,
# "Permissible bearing misalignment"): 2′ for roller bearings other than the NU/N 2, 3, 4 series'
# 6′ (and other than spherical and tapered ones), which holds needle roller bearings.
PERMISSIBLE_MISALIGNMENT = float(np.radians(2.0 / 60.0))


def needle_roller_bearing(*, roller_diameter, roller_length, rollers, profile=None,
                          material: Material = BEARING_STEEL) -> RollerBearing:
    """The rollers of a needle roller bearing (SI): D_w [m], effective length L_we [m] > 2.5 D_w
    (`LONG_ROLLER_RATIO`), Z, the crowning `profile` (`roller_profile`, straight by default) and the
    `material` of rollers and rings. A `RollerBearing` of kind "cylindrical_roller", so every roller
    block (and the crowning design notebook) takes it as it is. ValueError naming a bad key."""
    bearing = roller_bearing(kind="cylindrical_roller", length=roller_length, diameter=roller_diameter,
                             profile=profile, material=material, roller_count=rollers)
    if bearing.roller_count is None:
        raise ValueError("missing required key 'bearing.rollers' (the number of rollers Z)")
    if _is_concrete(roller_length, roller_diameter) and float(roller_length) <= LONG_ROLLER_RATIO * float(roller_diameter):
        raise ValueError(f"bearing.roller_length: a needle roller is longer than {LONG_ROLLER_RATIO:g} D_w = "
                         f"{LONG_ROLLER_RATIO * float(roller_diameter) * 1e3:.4g} mm (ISO/TS 16281's long rollers), got "
                         f"{float(roller_length) * 1e3:.4g} mm: a shorter roller makes a cylindrical roller bearing "
                         "(type cylindrical_roller)")
    return bearing


def needle_roller_raceways(bearing: RollerBearing, *, pitch_diameter, diametral_clearance=0.0) -> RollerRaceways:
    """The rings (or cup and shaft) around the rollers: d_m [m], the diametral clearance P_d [m]
    (`roller_equilibrium.roller_raceways`, contact angle 0); ValueError naming bearing.rollers
    where Z rollers do not fit on the pitch circle (D_w > d_m sin(π/Z))."""
    raceways = roller_raceways(bearing, pitch_diameter=pitch_diameter, diametral_clearance=diametral_clearance)
    check_rollers_fit(bearing.roller_count, bearing.large_diameter, pitch_diameter)
    return raceways


def shaft_raceway_diameter(bearing: RollerBearing, raceways: RollerRaceways):
    """F_w = d_m − D_w [m]: the rollers' inner envelope, the shaft's raceway diameter of a bearing
    without inner ring."""
    return raceways.pitch_diameter - bearing.large_diameter


class NeedleRollerSupport(AbstractSupport):
    """A needle roller bearing on a shaft: its rollers and rings as a `RollerSupport` (`rollers`;
    `needle_roller_support` builds it); static: its `outer_ring`, "machined" or "drawn_cup" (its
    rating factor). With an inner ring or without (on the shaft) its model is the same."""

    rollers: RollerSupport
    outer_ring: str = eqx.field(static=True, default="machined")

    def __check_init__(self):
        if self.outer_ring not in OUTER_RINGS:
            raise ValueError(f"bearing.outer_ring: one of {OUTER_RINGS}, got {self.outer_ring!r}")

    @property
    def bearing(self) -> RollerBearing:
        return self.rollers.bearing

    @property
    def raceways(self) -> RollerRaceways:
        return self.rollers.raceways

    @property
    def position(self):
        return self.rollers.position

    @property
    def offset(self):
        return self.rollers.offset

    @property
    def orientation(self):
        return self.rollers.orientation

    def constants(self):
        return self.rollers.constants()

    def ring_force(self, displacement, speed, constants, elements=None):
        return self.rollers.ring_force(displacement, speed, constants, elements)

    def ring_stiffness(self, displacement, speed, constants, elements=None):
        return self.rollers.ring_stiffness(displacement, speed, constants, elements)

    def energy_constants(self, constants):
        return self.rollers.energy_constants(constants)

    def static_energy(self, displacement, energy_constants):
        return self.rollers.static_energy(displacement, energy_constants)

    def characteristic_load(self, constants, energy_constants):
        return self.rollers.characteristic_load(constants, energy_constants)

    def pitch_radius(self):
        return self.rollers.pitch_radius()

    def contacts(self, displacement, speed, constants, elements=None) -> ContactLoads:
        """Each roller's inner (shaft or inner ring) and outer line contact with its laminae."""
        return self.rollers.contacts(displacement, speed, constants, elements)

    def dynamic_load_rating(self):
        """ISO 281's C_r with the needle roller bearing's b_m (`RATING_FACTORS`): C_r ∝ b_m, so the
        cylindrical roller bearing's rating (b_m = 1.1) times b_m / 1.1."""
        return self.rollers.dynamic_load_rating() * (RATING_FACTORS[self.outer_ring] / roller_life.BM_ROLLER)

    def contact_ratings(self, rating, contacts: ContactLoads):
        return self.rollers.contact_ratings(rating, contacts)

    def static_load_rating(self):
        return self.rollers.static_load_rating()

    def equivalent_dynamic_load(self, force):
        """P = F_r (ISO 281, radial roller bearings at α = 0)."""
        return self.rollers.equivalent_dynamic_load(force)

    def equivalent_static_load(self, force):
        return self.rollers.equivalent_static_load(force)

    def pressure_safety(self, max_pressure):
        return self.rollers.pressure_safety(max_pressure)

    def rolling_element(self) -> str:
        return "roller"

    def friction_kind(self, model: str) -> str | None:
        """Palmgren's needle roller row (HR 1's NA49); SKF's model has none."""
        return "needle_roller" if model == "palmgren" else None

    def permissible_misalignment(self):
        """2′ (`PERMISSIBLE_MISALIGNMENT`): long rollers turn a tilt into edge load sooner."""
        return PERMISSIBLE_MISALIGNMENT

    def envelope(self, contacts: ContactLoads):
        return self.rollers.envelope(contacts)

    def frequencies(self, speed, contacts: ContactLoads):
        return self.rollers.frequencies(speed, contacts)

    def locates_axially(self) -> bool:
        """A needle roller bearing carries no axial load."""
        return False


def needle_roller_support(bearing: RollerBearing, raceways: RollerRaceways, position, offset=0.0,
                          model: RollerModel = RollerModel(), orientation=1, *,
                          outer_ring="machined") -> NeedleRollerSupport:
    """A `NeedleRollerSupport` of `bearing` (`needle_roller_bearing`) in `raceways`
    (`needle_roller_raceways`) at `position` [m]; `model` the laminae (`RollerModel`); `outer_ring`
    "machined" or "drawn_cup". ValueError for an axial `offset` (it carries no axial load)."""
    if _is_concrete(offset) and float(offset) != 0.0:
        raise ValueError("offset: a needle roller bearing takes no axial preload; it must be 0")
    return NeedleRollerSupport(RollerSupport(bearing, raceways, position, offset, model=model, orientation=orientation),
                               outer_ring=outer_ring)
