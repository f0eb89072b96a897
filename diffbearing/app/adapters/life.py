"""Rating life of ball and roller bearings (effect `life`): ISO 281 basic rating life and the
ISO/TS 16281 reference rating life from the solved load distribution (balls, or the rollers'
laminae)."""

import jax.numpy as jnp

from ... import life, roller_life
from ...params import BALL_BEARING_KINDS
from ...roller_geometry import ROLLER_KINDS
from ..formatting import column
from ..registry import Adapter, Block, InputBuilder, Key, Output, quantity, register
from .bearing_set import SET, SET_SIZE
from .roller_bearing import EQUILIBRIUM_BLOCK, WHOLE_BEARING


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


def ball_load_rating(bearing):
    """C_r [N] used for a ball bearing: its own, else ISO 281's from the geometry."""
    return life.basic_dynamic_load_rating(bearing) if bearing.dynamic_load_rating is None else bearing.dynamic_load_rating


def ball_bearing_life(bearing, inner_loads, outer_loads):
    """ISO/TS 16281 L10r [10⁶ rev] of a ball bearing from its ball loads [N] (`ball_load_rating`)."""
    return life.reference_rating_life(bearing, ball_load_rating(bearing), inner_loads, outer_loads)


def roller_load_ratings(bearing, raceways, given_rating=None):
    """(C_r used [N], C_r by ISO 281 [N]) of a whole roller bearing: the scene's, else ISO 281's."""
    diameter = 0.5 * (bearing.small_diameter + bearing.large_diameter)
    computed = roller_life.roller_dynamic_load_rating(bearing.roller_count, diameter, bearing.length,
                                                      raceways.cup_angle, raceways.pitch_diameter)
    return (computed if given_rating is None else given_rating), computed


def roller_bearing_life(bearing, raceways, inner_lamina_load, outer_lamina_load, given_rating=None):
    """(C_r used [N], C_r by ISO 281 [N], ISO/TS 16281 L10r [10⁶ rev]) of a whole roller bearing from
    its lamina loads per unit length (rollers × laminae) [N/m]."""
    count, diameter = bearing.roller_count, 0.5 * (bearing.small_diameter + bearing.large_diameter)
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
    return {"life.basic_dynamic_load_rating": ball_load_rating(bearing),
            **{f"set.bearings.{number}.L10r": value for number, value in enumerate(lives)},
            "set.L10r": life.system_life(jnp.stack(lives))}


def _load_rating(v, built) -> dict:
    return {"load_rating": v.get("bearing.dynamic_load_rating")}


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    key = "life.L10r" if "life.L10r" in values else "set.L10r"
    return [column("L10r [1e6 rev]", values[key])]


_ROLLER_OUTPUTS = (
    Output("life.basic_dynamic_load_rating", "N", "kN", "C_r used (the scene's, else ISO 281)"),
    Output("life.iso281_load_rating", "N", "kN", "C_r by ISO 281 from the geometry"),
    Output("life.equivalent_load", "N", "kN", "ISO 281 equivalent load P = X Fr + Y Fa (Table 8)"),
    Output("life.L10", "1e6 rev", "1e6 rev", "ISO 281 basic rating life L10 = (C/P)^(10/3)"),
    Output("life.L10r", "1e6 rev", "1e6 rev", "ISO/TS 16281 reference rating life L10r (laminae)"),
)

ADAPTER = register(Adapter(
    name="life",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={"effects.life": Key("boolean"),
          "bearing.dynamic_load_rating": quantity("force", "basic dynamic load rating C_r (else ISO 281 from the geometry)")},
    inputs=(InputBuilder(("load_rating",), ROLLER_KINDS, _load_rating, scene_keys=WHOLE_BEARING),),
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
    )),
    sweep_columns=_sweep_columns,
))
