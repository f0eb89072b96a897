"""Static safety and minimum load (effect `safety`): ISO 76 C₀, P₀ and s₀ = C₀/P₀ beside the safety
of the largest computed contact pressure against ISO 76's permissible stress
(`diffbearing.ratings.static_safety`), and the requisite minimum load (`diffbearing.ratings.minimum_load`) as a
warning for a turning bearing."""

import jax.numpy as jnp
import numpy as np

from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....params import BALL_BEARING_KINDS, SILICON_NITRIDE
from ....ratings import life, roller_life, static_safety
from ....ratings.minimum_load import minimum_load
from ...registry import SHAFT, Adapter, Block, Key, Output, register
from ..systems.bearing_set import SET, SET_SIZE
from .life import roller_load_ratings, table3_angle
from ..bearings.roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING
from ..systems.shaft_layout import check_static_ratings, layout_supports, moment_warnings

HYBRID_OUTPUT = Output("safety.hybrid", "", "", "1 where the balls are silicon nitride: C0, s0 and p_limit are then "
                       "ISO 76's all-steel values", in_report=False)
HYBRID_WARNING = ("hybrid bearing (silicon nitride balls): C0, s0 and p_limit are ISO 76's all-steel values (ISO 20056-2's "
                  "hybrid ratings are not built); the pressure safety reads the computed pressure of the ceramic ball on "
                  "the steel ring, higher than an all-steel bearing's at the same load")


def _hybrid(bearing) -> jnp.ndarray:
    """1.0 for a ball bearing with silicon nitride balls (the material's static name), else 0.0."""
    return jnp.asarray(float(getattr(bearing, "ball_material", None) is not None
                             and bearing.ball_material.name == SILICON_NITRIDE.name))


def _outputs(exponent: str, minimum: str) -> tuple[Output, ...]:
    return (
        Output("safety.static_load_rating", "N", "kN", "ISO 76 static load rating C0"),
        Output("safety.equivalent_static_load", "N", "kN", "ISO 76 equivalent static load P0"),
        Output("safety.iso76", "", "", "ISO 76 static safety s0 = C0/P0"),
        Output("safety.max_pressure", "Pa", "GPa", "largest contact pressure p_max"),
        Output("safety.pressure_limit", "Pa", "GPa", "ISO 76 permissible pressure p_limit"),
        Output("safety.static", "", "", f"static safety (p_limit/p_max)^{exponent}"),
        Output("safety.equivalent_load", "N", "kN", "ISO 281 equivalent dynamic load P", in_report=False),
        Output("safety.minimum_load", "N", "kN", f"requisite minimum load P_min = {minimum} C_r"),
        Output("safety.speed", "rad/s", "rpm", "relative ring speed (for the minimum-load check)", in_report=False),
    )


SAFETY_NAMES = (("iso76", "ISO 76 static safety s0 = C0/P0"), ("static_safety", "static safety from the contact pressure"))


def _largest_pressure(results, prefix: str):
    return jnp.maximum(jnp.max(results[f"{prefix}.inner.max_pressure"]), jnp.max(results[f"{prefix}.outer.max_pressure"]))


def _safety(bearing, raceways, force, pressure, equivalent_load, minimum, operating) -> dict:
    rating, load, safety = static_safety.bearing_static_safety(bearing, raceways, force, pressure)
    limit = static_safety.BALL_PRESSURE_LIMIT if raceways is None else static_safety.ROLLER_PRESSURE_LIMIT
    return {"safety.static_load_rating": rating, "safety.equivalent_static_load": load, "safety.iso76": rating / load,
            "safety.max_pressure": pressure, "safety.pressure_limit": limit, "safety.static": safety,
            "safety.equivalent_load": equivalent_load, "safety.minimum_load": minimum,
            "safety.speed": jnp.abs(operating.inner_speed - operating.outer_speed)}


def _ball_safety(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, force = inputs["bearing"], results["force"][:3]
    return _safety(bearing, None, force, _largest_pressure(results, "balls"), life.equivalent_dynamic_load(bearing, force),
                   minimum_load(life.ball_load_rating(bearing), "ball"),
                   inputs["operating"]) | {"safety.hybrid": _hybrid(bearing)}


def _roller_safety(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, raceways, force = inputs["bearing"], inputs["raceways"], results["force"][:3]
    dynamic_rating, _ = roller_load_ratings(bearing, raceways, inputs["load_rating"])
    return _safety(bearing, raceways, force, _largest_pressure(results, "rollers"),
                   roller_life.roller_equivalent_dynamic_load(force, raceways.cup_angle),
                   minimum_load(dynamic_rating, "roller"), inputs["operating"])


def _set_safety(inputs: dict, settings: dict, results: dict) -> dict:
    """C₀ of the set's bearings, and each bearing's P₀, s₀ and pressure safety from its own load."""
    bearing = inputs["bearing"]
    out = {"safety.hybrid": _hybrid(bearing)}
    for number in range(SET_SIZE):
        prefix = f"set.bearings.{number}."
        rating, load, safety = static_safety.bearing_static_safety(bearing, None, results[prefix + "force"][:3],
                                                                   _largest_pressure(results, prefix + "balls"))
        out |= {"set.static_load_rating": rating, prefix + "equivalent_static_load": load, prefix + "iso76": rating / load,
                prefix + "static_safety": safety}
    return out


def _shaft_safety(inputs: dict, settings: dict, results: dict) -> dict:
    """Each of the shaft's bearings' C₀, P₀, s₀ and pressure safety from its own load (own frame),
    as its type rates it (`AbstractSupport.static_load_rating` and the rest)."""
    supports = layout_supports(inputs["shaft"], settings)
    rating = jnp.stack([support.static_load_rating() for support in supports])
    load = jnp.stack([support.equivalent_static_load(results["bearings.force"][number][:3])
                      for number, support in enumerate(supports)])
    return {"bearings.static_load_rating": rating, "bearings.equivalent_static_load": load,
            "bearings.iso76": rating / load, "bearings.static_safety": results["bearings.pressure_safety"],

            "safety.hybrid": jnp.asarray(float(any(support.hybrid() for support in supports)))}


def _hybrid_warning(values: dict) -> list[str]:
    return [HYBRID_WARNING] if float(values["safety.hybrid"]) > 0.5 else []


def _shaft_checks(values: dict) -> tuple[list[str], list[str]]:
    moments = moment_warnings(values, "s0", "ISO 76's P0", "s(p), from its contact pressures,")
    return [], [f"bearing {number}: {name} is {value:.3g}, below 1" for key, name in SAFETY_NAMES
                for number, value in enumerate(np.asarray(values[f"bearings.{key}"])) if value < 1.0] \
        + moments + _hybrid_warning(values)


def _set_checks(values: dict) -> tuple[list[str], list[str]]:
    warnings = [f"bearing {number}: {name} is {float(values[f'set.bearings.{number}.{key}']):.3g}, below 1"
                for number in range(SET_SIZE) for key, name in SAFETY_NAMES
                if float(values[f"set.bearings.{number}.{key}"]) < 1.0]
    return [], warnings + _hybrid_warning(values)


def _ball_checks(values: dict) -> tuple[list[str], list[str]]:
    errors, warnings = _checks(values)
    return errors, warnings + _hybrid_warning(values)


def _checks(values: dict) -> tuple[list[str], list[str]]:
    """Warnings: a static safety below 1, and a turning bearing loaded below its minimum load."""
    warnings = []
    for key, (_, name) in zip(("safety.iso76", "safety.static"), SAFETY_NAMES):
        if float(values[key]) < 1.0:
            warnings.append(f"{name} is {float(values[key]):.3g}, below 1: the load passes the static rating "
                            "(permanent deformation beyond 1e-4 Dw)")
    load, minimum = float(values["safety.equivalent_load"]), float(values["safety.minimum_load"])
    if float(values["safety.speed"]) > 0.0 and load < minimum:
        warnings.append(f"equivalent load {load / 1e3:.3g} kN is below the minimum load {minimum / 1e3:.3g} kN "
                        "(0.01 C_r for ball, 0.02 C_r for roller bearings): the rolling elements may skid at speed")
    return [], warnings


ADAPTER = register(Adapter(
    name="safety",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"effects.safety": Key("boolean", doc="ISO 76 static load rating and safety, static safety from the "
                                                "contact pressure, minimum-load check")},
    blocks=(Block(
        name="safety",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("safety", True),
        requires=("equilibrium",),
        inputs=("bearing", "operating"),
        outputs=(*_outputs("3", "0.01"), HYBRID_OUTPUT),
        compute=_ball_safety,
        checks=_ball_checks,
        validate=table3_angle,
    ), Block(
        name="roller_safety",
        bearing_types=ROLLER_KINDS,
        enabled_by=("safety", True),
        requires=(EQUILIBRIUM_BLOCK,),
        inputs=("bearing", "raceways", "operating", "load_rating"),
        outputs=_outputs("2", "0.02"),
        compute=_roller_safety,
        checks=_checks,
        scene_keys=WHOLE_BEARING,
    ), Block(
        name="set_safety",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("safety", True),
        requires=("bearing_set",),
        inputs=("bearing",),
        outputs=(Output("set.static_load_rating", "N", "kN", "ISO 76 static load rating C0 of each bearing"), HYBRID_OUTPUT,
                 *(output for number in range(SET_SIZE) for output in (
                     Output(f"set.bearings.{number}.equivalent_static_load", "N", "kN",
                            f"bearing {number}: ISO 76 equivalent static load P0"),
                     Output(f"set.bearings.{number}.iso76", "", "", f"bearing {number}: ISO 76 s0 = C0/P0"),
                     Output(f"set.bearings.{number}.static_safety", "", "",
                            f"bearing {number}: static safety (p_limit/p_max)^3")))),
        compute=_set_safety,
        checks=_set_checks,
        scene_keys=SET,
    ), Block(
        name="shaft_safety",
        bearing_types=SHAFT,
        enabled_by=("safety", True),
        requires=("shaft",),
        inputs=("shaft",),
        outputs=(Output("bearings.static_load_rating", "N", "kN", "each bearing's ISO 76 C0", in_report=False),
                 Output("bearings.equivalent_static_load", "N", "kN", "each bearing's ISO 76 P0", in_report=False),
                 Output("bearings.iso76", "", "", "each bearing's ISO 76 s0 = C0/P0", in_report=False),
                 Output("bearings.static_safety", "", "", "each bearing's static safety of its largest pressure, "
                        "(p_limit/p_max)^3 (ball) or ^2 (roller)", in_report=False), HYBRID_OUTPUT),
        compute=_shaft_safety,
        checks=_shaft_checks,
        validate=check_static_ratings,
    )),
))
