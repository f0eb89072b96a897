"""Rating life of ball bearings (effect `life`): ISO 281 basic rating life and the ISO/TS 16281
reference rating life from the solved load distribution."""

from ... import life
from ...params import BALL_BEARING_KINDS
from ..formatting import column
from ..registry import Adapter, Block, Key, Output, register


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


def _sweep_columns(values: dict) -> list[tuple[str, list[str]]]:
    return [column("L10r [1e6 rev]", values["life.L10r"])]


ADAPTER = register(Adapter(
    name="life",
    bearing_types=BALL_BEARING_KINDS,
    keys={"effects.life": Key("boolean")},
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
    ),),
    sweep_columns=_sweep_columns,
))
