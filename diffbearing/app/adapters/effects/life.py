"""Rating life of ball and roller bearings (effect `life`): ISO 281 basic rating life and the
ISO/TS 16281 reference rating life from the solved load distribution (balls, or the rollers'
laminae)."""

import jax
import jax.numpy as jnp
import numpy as np

from ....bearings.roller.roller_geometry import ROLLER_KINDS, mean_roller_diameter
from ....params import BALL_BEARING_KINDS, check_range
from ....ratings import life, life_modification, radial_load_factors, roller_life, static_safety
from ...formatting import column
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register
from ..systems.bearing_set import SET, SET_SIZE
from ..bearings.roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING
from ..systems.shaft_layout import layout_supports


def _life(inputs: dict, settings: dict, results: dict) -> dict:
    bearing = inputs["bearing"]
    computed = life.basic_dynamic_load_rating(bearing)
    rating = computed if bearing.dynamic_load_rating is None else bearing.dynamic_load_rating
    load = life.equivalent_dynamic_load(bearing, inputs["operating"].force)
    return {
        "life.basic_dynamic_load_rating": rating,
        "life.iso281_load_rating": computed,
        "life.equivalent_load": load,
        "life.L10": life.basic_rating_life(rating, load),
        "life.L10r": life.reference_rating_life(bearing, rating, results["balls.inner.load"],
                                                results["balls.outer.load"]),
    }


def table3_angle(settings: dict, inputs: dict) -> None:
    """ISO 281 Table 3 rates radial ball bearings up to α = 45°; beyond, the bearing is a thrust
    bearing of Table 4 (not modelled): ValueError naming the contact angle."""
    bearing = inputs["bearing"]
    angle = bearing.nominal_contact_angle
    if not isinstance(angle, jax.core.Tracer) and float(angle) > radial_load_factors.LARGEST_ANGLE + 1e-12:
        raise ValueError(f"bearing.contact_angle: ISO 281's equivalent load (life, safety) rates radial ball "
                         f"bearings up to 45°, got {np.degrees(float(angle)):.4g}°")


def ball_bearing_life(bearing, inner_loads, outer_loads):
    """ISO/TS 16281 L10r [10⁶ rev] of a ball bearing from its ball loads [N] (`life.ball_load_rating`)."""
    return life.reference_rating_life(bearing, life.ball_load_rating(bearing), inner_loads, outer_loads)


def roller_load_ratings(bearing, raceways, given_rating=None):
    """(C_r used [N], C_r by ISO 281 [N]) of a whole roller bearing: the scene's, else ISO 281's."""
    computed = roller_life.roller_bearing_load_rating(bearing, raceways)
    return (computed if given_rating is None else given_rating), computed


def roller_bearing_life(bearing, raceways, inner_lamina_load, outer_lamina_load, given_rating=None):
    """(C_r used [N], C_r by ISO 281 [N], ISO/TS 16281 L10r [10⁶ rev]) of a whole roller bearing from
    its lamina loads per unit length (rollers × laminae) [N/m]."""
    count, diameter = bearing.roller_count, mean_roller_diameter(bearing)
    angle, pitch = raceways.cup_angle, raceways.pitch_diameter
    rating, computed = roller_load_ratings(bearing, raceways, given_rating)
    width = bearing.length / inner_lamina_load.shape[-1]
    return rating, computed, roller_life.roller_reference_rating_life(rating, count, diameter, angle, pitch,
                                                                      inner_lamina_load * width,
                                                                      outer_lamina_load * width)


def _roller_life(inputs: dict, settings: dict, results: dict) -> dict:
    rating, computed, reference = roller_bearing_life(inputs["bearing"], inputs["raceways"],
                                                      results["rollers.inner.lamina_load"],
                                                      results["rollers.outer.lamina_load"], inputs["load_rating"])
    load = roller_life.roller_equivalent_dynamic_load(inputs["operating"].force, inputs["raceways"].cup_angle)
    return {
        "life.basic_dynamic_load_rating": rating,
        "life.iso281_load_rating": computed,
        "life.equivalent_load": load,
        "life.L10": roller_life.roller_basic_rating_life(rating, load),
        "life.L10r": reference,
    }


def _set_life(inputs: dict, settings: dict, results: dict) -> dict:
    """ISO/TS 16281 reference rating life of each bearing of a set from its ball loads, and of the set."""
    bearing = inputs["bearing"]
    lives = [ball_bearing_life(bearing, results[f"set.bearings.{number}.balls.inner.load"],
                               results[f"set.bearings.{number}.balls.outer.load"]) for number in range(SET_SIZE)]
    return {"life.basic_dynamic_load_rating": life.ball_load_rating(bearing),
            **{f"set.bearings.{number}.L10r": value for number, value in enumerate(lives)},
            "set.L10r": life.system_life(jnp.stack(lives))}


def _load_rating(v, built) -> dict:
    return {"load_rating": v.get("bearing.dynamic_load_rating")}


# --- modified life a_ISO (ISO 281 §9.3) ----------------------------------------------------------

MODIFIED = ("lubricant.cleanliness",)  # the scene key that asks for a_ISO (with effects.life)
SUPPLIES = tuple(life_modification.CONTAMINATION_CONSTANTS)
SUPPLY_KEY = Key("choice", choices=SUPPLIES, doc="how the oil comes: circulating with filters, oil bath, or grease "
                                                 "(ISO 281 Annex A's e_C tables; Palmgren's f0; SKF's K_rs)")
CLEANLINESS = tuple(dict.fromkeys(level for table in life_modification.CONTAMINATION_CONSTANTS.values()
                                  for level in table)) + ("custom",)


def _contamination(v, built) -> dict:
    """The e_C of the scene: (c₁, c₂) of ISO 281 Annex A for the supply and cleanliness, or a given
    factor; with an "ep_additives" entry (no value: the dict's structure is static under jit) where
    the lubricant has effective EP additives (lubricant.ep_additives)."""
    ep_additives = {"ep_additives": None} if v.get("lubricant.ep_additives", False) else {}
    level = v["lubricant.cleanliness"]
    if level == "custom":
        if "lubricant.contamination_factor" not in v:
            raise ValueError("lubricant.cleanliness = \"custom\" needs lubricant.contamination_factor (e_C, 0 to 1)")
        check_range("lubricant.contamination_factor", v["lubricant.contamination_factor"], low=0.0, high=1.0,
                    low_open=False, high_open=False)
        return {"contamination": {"factor": v["lubricant.contamination_factor"], **ep_additives}}
    if "lubricant.contamination_factor" in v:
        raise ValueError("lubricant.contamination_factor is read only with lubricant.cleanliness = \"custom\"")
    tables = life_modification.CONTAMINATION_CONSTANTS
    default = "grease" if level in tables["grease"] else None
    supply = v.get("lubricant.supply", default)
    if supply is None:
        raise ValueError(f"lubricant.supply: the oil cleanliness {level} needs the supply, one of "
                         f"{', '.join(s for s in SUPPLIES if s != 'grease')}")
    if level not in tables[supply]:
        raise ValueError(f"lubricant.cleanliness: with lubricant.supply = {supply!r} one of "
                         f"{', '.join(tables[supply])} or custom, got {level!r}")
    return {"contamination": {"constants": tables[supply][level], **ep_additives}}


def _checked_fatigue_load_limit(v, static_rating):
    """The scene's C_u [N] inside (0, C₀) (ISO 281 Annex B: the load below which no fatigue
    occurs lies far below the static rating), or None."""
    given = v.get("bearing.fatigue_load_limit")
    if given is not None and not isinstance(static_rating, jax.core.Tracer):
        check_range("bearing.fatigue_load_limit", given, low=0.0, high=float(static_rating), unit=" N",
                    why="C0 by ISO 76")
    return {"fatigue_load_limit": given}


def _ball_fatigue_load_limit(v, built) -> dict:
    return _checked_fatigue_load_limit(v, static_safety.ball_bearing_static_load_rating(built["bearing"]))


def _roller_fatigue_load_limit(v, built) -> dict:
    return _checked_fatigue_load_limit(v, static_safety.roller_bearing_static_load_rating(built["bearing"],
                                                                                          built["raceways"]))


def _lubrication(rolling_element, pitch, static_rating, inputs, speed) -> dict:
    """ν, ν₁, κ, e_C and C_u of ISO 281 §9.3 for a bearing of pitch diameter `pitch` [m] and C₀ [N]
    at the relative ring speed `speed` [rad/s] (C_u the scene's where it gives one)."""
    lubricant = inputs["lubricant"]
    viscosity = lubricant.viscosity / lubricant.density
    reference = life_modification.reference_viscosity(speed, pitch)
    kappa = viscosity / reference
    contamination = inputs["contamination"]
    factor = (contamination["factor"] if "factor" in contamination
              else life_modification.contamination_factor(kappa, pitch, contamination["constants"]))
    given = inputs.get("fatigue_load_limit")
    limit = life_modification.fatigue_load_limit(static_rating, pitch, rolling_element) if given is None else given
    return {"life.kinematic_viscosity": viscosity, "life.reference_viscosity": reference, "life.viscosity_ratio": kappa,
            "life.contamination_factor": factor, "life.fatigue_load_limit": limit}


LIFE_EXPONENTS = {"ball": 3.0, "roller": 10.0 / 3.0}  # p of L = (C/P)^p, ISO 281


def _a_iso(rolling_element, lubrication, load, inputs):
    """a_ISO [-] at the equivalent load `load` [N] with the bearing's κ, e_C and C_u (with the
    scene's lubricant.ep_additives, ISO 281's rule for EP additives)."""
    kappa, factor = lubrication["life.viscosity_ratio"], lubrication["life.contamination_factor"]
    ratio = factor * lubrication["life.fatigue_load_limit"] / load
    if "ep_additives" in inputs["contamination"]:
        return life_modification.life_modification_factor_ep(kappa, ratio, factor, rolling_element)
    return life_modification.life_modification_factor(kappa, ratio, rolling_element)


def _reference_modified(rolling_element, lubrication, rating, reference_life, inputs):
    """(P_ref = C_r L10r^(−1/p) [N], a_ISO at P_ref, L10rm = a_ISO L10r [10⁶ rev]) (ISO/TS 16281)."""
    load = rating * reference_life ** (-1.0 / LIFE_EXPONENTS[rolling_element])
    a_iso = _a_iso(rolling_element, lubrication, load, inputs)
    return load, a_iso, a_iso * reference_life


def _modified(rolling_element, pitch, static_rating, rating, load, reference_life, inputs, operating) -> dict:
    """κ, e_C, C_u, a_ISO and the modified lives of ISO 281 §9.3 (L10m) and ISO/TS 16281 (L10rm,
    a_ISO at the reference equivalent load P_ref = C_r L10r^(−1/p))."""
    lubrication = _lubrication(rolling_element, pitch, static_rating, inputs,
                               operating.inner_speed - operating.outer_speed)
    a_iso = _a_iso(rolling_element, lubrication, load, inputs)
    reference_load, a_reference, modified = _reference_modified(rolling_element, lubrication, rating, reference_life,
                                                                inputs)
    return lubrication | {"life.a_iso": a_iso, "life.L10m": a_iso * (rating / load) ** LIFE_EXPONENTS[rolling_element],
                          "life.reference_equivalent_load": reference_load, "life.a_iso_reference": a_reference,
                          "life.L10rm": modified}


def _set_modified(inputs: dict, settings: dict, results: dict) -> dict:
    """κ, e_C, C_u of the set's bearings and each one's a_ISO at its P_ref and L10rm; the set's L10rm."""
    bearing = inputs["bearing"]
    operating = inputs["operating"]
    lubrication = _lubrication("ball", bearing.pitch_diameter, static_safety.ball_bearing_static_load_rating(bearing),
                               inputs, operating.inner_speed - operating.outer_speed)
    out, lives = dict(lubrication), []
    for number in range(SET_SIZE):
        _, a_iso, modified = _reference_modified("ball", lubrication, results["life.basic_dynamic_load_rating"],
                                                 results[f"set.bearings.{number}.L10r"], inputs)
        out |= {f"set.bearings.{number}.a_iso": a_iso, f"set.bearings.{number}.L10rm": modified}
        lives.append(modified)
    return out | {"set.L10rm": life.system_life(jnp.stack(lives))}


def _shaft_modified(inputs: dict, settings: dict, results: dict) -> dict:
    """Each of the shaft's bearings' κ, a_ISO at its P_ref and L10rm (ISO 281 Annex B's C_u), and the
    shaft's L10rm, each bearing's ratings as its type gives them."""
    layout = inputs["shaft"]
    kappas, factors, lives = [], [], []
    for number, support in enumerate(layout_supports(layout, settings)):
        element = support.rolling_element()
        lubrication = _lubrication(element, 2.0 * support.pitch_radius(), support.static_load_rating(), inputs,
                                   layout.speed)
        _, a_iso, modified = _reference_modified(element, lubrication, support.dynamic_load_rating(),
                                                 results["bearings.L10r"][number], inputs)
        kappas.append(lubrication["life.viscosity_ratio"])
        factors.append(a_iso)
        lives.append(modified)
    return {"bearings.viscosity_ratio": jnp.stack(kappas), "bearings.a_iso": jnp.stack(factors),
            "bearings.L10rm": jnp.stack(lives), "shaft.L10rm": life.system_life(jnp.stack(lives))}


def _ball_modified(inputs: dict, settings: dict, results: dict) -> dict:
    bearing = inputs["bearing"]
    return _modified("ball", bearing.pitch_diameter, static_safety.ball_bearing_static_load_rating(bearing),
                     results["life.basic_dynamic_load_rating"], results["life.equivalent_load"], results["life.L10r"],
                     inputs, inputs["operating"])


def _roller_modified(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, raceways = inputs["bearing"], inputs["raceways"]
    return _modified("roller", raceways.pitch_diameter, static_safety.roller_bearing_static_load_rating(bearing, raceways),
                     results["life.basic_dynamic_load_rating"], results["life.equivalent_load"], results["life.L10r"],
                     inputs, inputs["operating"])


def _modified_checks(values: dict) -> tuple[list[str], list[str]]:
    warnings = []
    kappa = float(np.min(values.get("life.viscosity_ratio", values.get("bearings.viscosity_ratio"))))
    if kappa < life_modification.KAPPA_RANGE[0]:
        warnings.append(f"viscosity ratio κ = {kappa:.3g} is below 0.1, outside ISO 281's a_ISO: a_ISO is taken at "
                        "κ = 0.1")
    factors = [key for key in ("life.a_iso", "bearings.a_iso", *(f"set.bearings.{n}.a_iso" for n in range(SET_SIZE)))
               if key in values]
    if any(np.max(values[key]) >= life_modification.A_ISO_CAP for key in factors):
        warnings.append("a_ISO reaches ISO 281's cap of 50 (load at or below the fatigue load limit)")
    return [], warnings


# the lubrication and the limits behind a_ISO: the same for each bearing of a set
_LUBRICATION_OUTPUTS = (
    Output("life.kinematic_viscosity", "m^2/s", "mm^2/s", "kinematic viscosity ν at the operating temperature"),
    Output("life.reference_viscosity", "m^2/s", "mm^2/s", "rated viscosity ν1 (ISO 281 eqs. 28–29)"),
    Output("life.viscosity_ratio", "", "", "viscosity ratio κ = ν/ν1"),
    Output("life.contamination_factor", "", "", "contamination factor e_C (ISO 281 Annex A)"),
    Output("life.fatigue_load_limit", "N", "kN", "fatigue load limit C_u (the scene's, else Annex B)"),
)
_MODIFIED_OUTPUTS = (
    *_LUBRICATION_OUTPUTS,
    Output("life.a_iso", "", "", "life modification factor a_ISO at P"),
    Output("life.L10m", "1e6 rev", "1e6 rev", "modified rating life L10m = a_ISO L10"),
    Output("life.reference_equivalent_load", "N", "kN", "P_ref = C_r L10r^(−1/p) of the load distribution",
           in_report=False),
    Output("life.a_iso_reference", "", "", "a_ISO at P_ref (ISO/TS 16281)"),
    Output("life.L10rm", "1e6 rev", "1e6 rev", "modified reference life L10rm = a_ISO L10r"),
)


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    key = next((key for key in ("life.L10r", "set.L10r", "shaft.L10r") if key in values), None)
    return [] if key is None else [column("L10r [1e6 rev]", values[key])]


_ROLLER_OUTPUTS = (
    Output("life.basic_dynamic_load_rating", "N", "kN", "C_r used (the scene's, else ISO 281)"),
    Output("life.iso281_load_rating", "N", "kN", "C_r by ISO 281 from the geometry"),
    Output("life.equivalent_load", "N", "kN", "ISO 281 equivalent load P = X Fr + Y Fa (Table 8)"),
    Output("life.L10", "1e6 rev", "1e6 rev", "ISO 281 basic rating life L10 = (C/P)^(10/3)"),
    Output("life.L10r", "1e6 rev", "1e6 rev", "ISO/TS 16281 reference rating life L10r (laminae)"),
)

ADAPTER = register(Adapter(
    name="life",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"effects.life": Key("boolean"),
          "bearing.dynamic_load_rating": quantity("force", "basic dynamic load rating C_r (else ISO 281 from the geometry)"),
          "bearing.fatigue_load_limit": quantity("force", "fatigue load limit C_u (else ISO 281 Annex B from C0)"),
          "lubricant.cleanliness": Key("choice", choices=CLEANLINESS,
                                       doc="ISO 281 Annex A cleanliness: an ISO 4406 code for oil, a level for "
                                           "grease, or custom (then lubricant.contamination_factor); with "
                                           "effects.life, a_ISO and the modified lives"),
          "lubricant.supply": SUPPLY_KEY,
          "lubricant.contamination_factor": Key("number", doc="e_C given directly (lubricant.cleanliness = custom)"),
          "lubricant.ep_additives": Key("boolean", doc="the oil has proven effective EP additives: where κ < 1 and "
                                                       "e_C ≥ 0.2, a_ISO at κ = 1, at most 3 (ISO 281)")},
    inputs=(InputBuilder(("load_rating",), ROLLER_KINDS, _load_rating, scene_keys=WHOLE_BEARING),
            InputBuilder(("contamination",), BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT, _contamination,
                         scene_keys=MODIFIED),
            InputBuilder(("fatigue_load_limit",), BALL_BEARING_KINDS, _ball_fatigue_load_limit, after=("bearing",)),
            InputBuilder(("fatigue_load_limit",), ROLLER_KINDS, _roller_fatigue_load_limit, after=("bearing", "raceways"),
                         scene_keys=WHOLE_BEARING)),
    blocks=(Block(
        name="life",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("life", True),
        requires=("equilibrium",),
        inputs=("bearing", "operating"),
        outputs=(
            Output("life.basic_dynamic_load_rating", "N", "kN", "C_r used (the scene's, else ISO 281)"),
            Output("life.iso281_load_rating", "N", "kN", "C_r by ISO 281 from the geometry"),
            Output("life.equivalent_load", "N", "kN", "ISO 281 equivalent load P = X Fr + Y Fa"),
            Output("life.L10", "1e6 rev", "1e6 rev", "ISO 281 basic rating life L10 = (C/P)^3"),
            Output("life.L10r", "1e6 rev", "1e6 rev", "ISO/TS 16281 reference rating life L10r"),
        ),
        compute=_life,
        validate=table3_angle,
    ), Block(
        name="roller_life",
        bearing_types=ROLLER_KINDS,
        enabled_by=("life", True),
        requires=(EQUILIBRIUM_BLOCK,),
        inputs=("bearing", "raceways", "operating", "load_rating"),
        outputs=_ROLLER_OUTPUTS,
        compute=_roller_life,
        scene_keys=WHOLE_BEARING,
    ), Block(
        name="set_life",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("life", True),
        requires=("bearing_set",),
        inputs=("bearing",),
        outputs=(
            Output("life.basic_dynamic_load_rating", "N", "kN", "C_r used (the scene's, else ISO 281)"),
            *(Output(f"set.bearings.{number}.L10r", "1e6 rev", "1e6 rev",
                     f"ISO/TS 16281 reference rating life L10r, bearing {number}") for number in range(SET_SIZE)),
            Output("set.L10r", "1e6 rev", "1e6 rev", "reference rating life of the set, (Σ L10r^(−10/9))^(−9/10)"),
        ),
        compute=_set_life,
        scene_keys=SET,
    ), Block(
        name="modified_life",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("life", True),
        requires=("life",),
        inputs=("bearing", "operating", "lubricant", "contamination", "fatigue_load_limit"),
        outputs=_MODIFIED_OUTPUTS,
        compute=_ball_modified,
        checks=_modified_checks,
        scene_keys=MODIFIED,
    ), Block(
        name="roller_modified_life",
        bearing_types=ROLLER_KINDS,
        enabled_by=("life", True),
        requires=("roller_life",),
        inputs=("bearing", "raceways", "operating", "lubricant", "contamination", "fatigue_load_limit"),
        outputs=_MODIFIED_OUTPUTS,
        compute=_roller_modified,
        checks=_modified_checks,
        scene_keys=WHOLE_BEARING + MODIFIED,
    ), Block(
        name="set_modified_life",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("life", True),
        requires=("set_life",),
        inputs=("bearing", "operating", "lubricant", "contamination", "fatigue_load_limit"),
        outputs=(*_LUBRICATION_OUTPUTS,
                 *(output for number in range(SET_SIZE) for output in (
                     Output(f"set.bearings.{number}.a_iso", "", "", f"bearing {number}: a_ISO at its P_ref"),
                     Output(f"set.bearings.{number}.L10rm", "1e6 rev", "1e6 rev",
                            f"bearing {number}: modified reference life L10rm"))),
                 Output("set.L10rm", "1e6 rev", "1e6 rev",
                        "modified reference life of the set, (Σ L10rm^(−10/9))^(−9/10)")),
        compute=_set_modified,
        checks=_modified_checks,
        scene_keys=SET + MODIFIED,
    ), Block(
        name="shaft_modified_life",
        bearing_types=SHAFT,
        enabled_by=("life", True),
        requires=("shaft",),
        inputs=("shaft", "lubricant", "contamination"),
        outputs=(Output("bearings.viscosity_ratio", "", "", "each bearing's viscosity ratio κ = ν/ν1", in_report=False),
                 Output("bearings.a_iso", "", "", "each bearing's a_ISO at its P_ref", in_report=False),
                 Output("bearings.L10rm", "1e6 rev", "1e6 rev", "each bearing's modified reference life L10rm",
                        in_report=False),
                 Output("shaft.L10rm", "1e6 rev", "1e6 rev",
                        "modified reference life of the shaft's bearings, (Σ L10rm^(−10/9))^(−9/10)")),
        compute=_shaft_modified,
        checks=_modified_checks,
        scene_keys=MODIFIED,
    )),
    sweep_columns=_sweep_columns,
))
