"""Lives at a reliability other than 90 % (`life.reliability`, with `effects.life`): ISO 281's a₁
(`diffbearing.ratings.reliability`, Table 12) on every life the scene's life blocks compute — L_n,
L_nr, and with a lubricant L_nm, L_nrm — for a bearing, a matched set and a shaft (each bearing and
the system; a₁ on the system life, as on each bearing's, is the catalogue tools' practice: the
system's own Weibull slope is not that of Table 12)."""

from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....params import BALL_BEARING_KINDS
from ....ratings.reliability import reliability_factor
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, register
from ..systems.bearing_set import SET, SET_SIZE
from ..bearings.roller_bearing import WHOLE_BEARING

RELIABILITY = ("life.reliability",)  # the scenes whose lives are taken at another reliability
# what each life is called at the reliability R: L10 → L_n (ISO 281 §9: "n" the failure probability 100 − R)
LIFE_NAMES = {"L10": "Ln", "L10r": "Lnr", "L10m": "Lnm", "L10rm": "Lnrm"}
DESCRIPTIONS = {"Ln": "rating life at reliability R, L_n = a₁ L10", "Lnr": "reference life at R, L_nr = a₁ L10r",
                "Lnm": "modified life at R, L_nm = a₁ a_ISO L10", "Lnrm": "modified reference life at R, L_nrm = a₁ L10rm"}


def _factor(v, built) -> dict:
    return {"reliability_factor": reliability_factor(v["life.reliability"])}


def _renamed(key: str) -> str:
    """The key of a life at the reliability R: `set.bearings.1.L10rm` → `set.bearings.1.Lnrm`."""
    head, _, name = key.rpartition(".")
    return f"{head}.{LIFE_NAMES[name]}"


def _scaled(sources: tuple[str, ...], with_factor: bool):
    """compute: a₁ times each life of `sources` under its name at R (and a₁ itself with `with_factor`)."""

    def compute(inputs: dict, settings: dict, results: dict) -> dict:
        factor = inputs["reliability_factor"]
        out = {_renamed(key): factor * results[key] for key in sources}
        return out | ({"life.a1": factor} if with_factor else {})

    return compute


def _outputs(sources: tuple[str, ...], with_factor: bool) -> tuple[Output, ...]:
    """a₁ and the lives at R; each bearing's of a shaft (arrays) in the JSON, not as report lines."""
    factor = (Output("life.a1", "", "", "life modification factor for reliability a₁ (ISO 281 Table 12)"),)
    lives = tuple(Output(_renamed(key), "1e6 rev", "1e6 rev",
                         DESCRIPTIONS[LIFE_NAMES[key.rpartition(".")[2]]]
                         + ("" if key.startswith("life.") else f" ({key.rpartition('.')[0]})"),
                         in_report=not key.startswith("bearings."))
                  for key in sources)
    return (factor if with_factor else ()) + lives


def _block(name: str, types, requires: str, sources: tuple[str, ...], with_factor: bool, scene_keys=()) -> Block:
    return Block(name=name, bearing_types=types, enabled_by=("life", True), requires=(requires,),
                 inputs=("reliability_factor",), outputs=_outputs(sources, with_factor),
                 compute=_scaled(sources, with_factor), scene_keys=RELIABILITY + scene_keys)


SINGLE = ("life.L10", "life.L10r")
SINGLE_MODIFIED = ("life.L10m", "life.L10rm")
SET_LIVES = tuple(f"set.bearings.{number}.L10r" for number in range(SET_SIZE)) + ("set.L10r",)
SET_MODIFIED = tuple(f"set.bearings.{number}.L10rm" for number in range(SET_SIZE)) + ("set.L10rm",)
SHAFT_LIVES = ("bearings.L10", "bearings.L10r", "shaft.L10r")
SHAFT_MODIFIED = ("bearings.L10rm", "shaft.L10rm")

ADAPTER = register(Adapter(
    name="reliability",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT,
    keys={"life.reliability": Key("number", doc="reliability R [%] of the lives, 90 to 99.95 (default 90: L10): "
                                                "ISO 281 Table 12's a₁ on every life, reported as L_n, L_nr, L_nm, L_nrm")},
    inputs=(InputBuilder(("reliability_factor",), BALL_BEARING_KINDS + ROLLER_KINDS + SHAFT, _factor,
                         scene_keys=RELIABILITY),),
    blocks=(
        _block("reliability", BALL_BEARING_KINDS, "life", SINGLE, True),
        _block("roller_reliability", ROLLER_KINDS, "roller_life", SINGLE, True, WHOLE_BEARING),
        _block("modified_reliability", BALL_BEARING_KINDS, "modified_life", SINGLE_MODIFIED, False),
        _block("roller_modified_reliability", ROLLER_KINDS, "roller_modified_life", SINGLE_MODIFIED, False),
        _block("set_reliability", BALL_BEARING_KINDS, "set_life", SET_LIVES, True, SET),
        _block("set_modified_reliability", BALL_BEARING_KINDS, "set_modified_life", SET_MODIFIED, False, SET),
        _block("shaft_reliability", SHAFT, "shaft", SHAFT_LIVES, True),
        _block("shaft_modified_reliability", SHAFT, "shaft_modified_life", SHAFT_MODIFIED, False),
    ),
))
