"""Grease life (`effects.grease_life = "<method>"`, `diffbearing.ratings.grease_life`) of a single
deep groove ball bearing greased for life: the average life of its grease by one manufacturer's
published formula, at the load the equilibrium solves (ISO 281's P of it, the bearing's C_r), its
relative ring speed and its operating temperature — the network's outer ring temperature with
`effects.thermal` (the bearing temperature catalogues measure), else `grease_life.temperature`,
else `lubricant.temperature`. Outside the method's stated range the life is an error (exit 2 for
a temperature given, exit 3 for a solved state); NSK's load guide is a warning."""

from ....params import check_range
from ....ratings import life
from ....ratings.grease_life import CELSIUS_ZERO, GREASE_LIFE_METHODS, GREASE_LIFE_SOURCES, GreaseLife, envelope_problems
from ...registry import ADAPTERS, SHAFT, Adapter, Block, InputBuilder, Key, Output, quantity, register

KIND = ("deep_groove_ball",)  # the methods' scope: single-row deep groove ball bearings
# the scene types registered before this adapter (every bearing type's; adapters/__init__.py) outside
# that scope: each refuses effects.grease_life, exit 2 (a shaft's bearings are not rated yet)
OUTSIDE = sorted({kind for adapter in ADAPTERS.values() for kind in adapter.bearing_types} - set(KIND) - set(SHAFT))
NSK_METHODS = ("nsk_general_purpose", "nsk_wide_range")
TEMPERATURE_RANGE = (213.15, 523.15)  # K: −60 °C to 250 °C, the thermal network's (below each method's floor: its floor)


def _scene_temperature(v, method: str):
    """The operating temperature a scene gives [K]: grease_life.temperature, else
    lubricant.temperature; ValueError naming the key where none is given or the method's upper
    bound is passed."""
    key = next((key for key in ("grease_life.temperature", "lubricant.temperature") if key in v), None)
    if key is None:
        raise ValueError("grease_life.temperature is needed by effects.grease_life (the bearing's operating "
                         "temperature; with effects.thermal, the network's)")
    top = GREASE_LIFE_METHODS[method].limits().temperature
    check_range(key, v[key], low=TEMPERATURE_RANGE[0], high=top, high_open=False, unit=" K",
                why=f"up to {top - CELSIUS_ZERO:g} °C, the upper bound of {GREASE_LIFE_SOURCES[method]}")
    return v[key]


def _grease(v, built) -> dict:
    """The method, the bearing's d and D, N_max (NSK's methods only) and the temperature: the
    network's outer ring's with effects.thermal (the "thermal" input), else the scene's."""
    method = v["effects.grease_life"]
    for key in ("bearing.bore", "bearing.outer_diameter"):
        if key not in v:
            raise ValueError(f"{key} is needed by effects.grease_life (the bearing's mean diameter (D + d)/2)")
    limiting = v.get("grease_life.limiting_speed")
    if method in NSK_METHODS:
        if limiting is None:
            raise ValueError(f"grease_life.limiting_speed is needed by effects.grease_life = \"{method}\": N_max, the "
                             "bearing's limiting speed with grease lubrication (the ZZ/VV value of NSK's tables)")
        check_range("grease_life.limiting_speed", limiting, low=0.0, high=1e4, unit=" rad/s",
                    why="positive, below 95 000 r/min")
    elif limiting is not None:
        raise ValueError(f"grease_life.limiting_speed: read only by NSK's methods {NSK_METHODS}, not by \"{method}\"")
    state = (built.get("thermal") or {}).get("state")
    if state is None:
        temperature = _scene_temperature(v, method)
    else:
        if "grease_life.temperature" in v:
            raise ValueError("grease_life.temperature: the bearing's temperature is the thermal network's with "
                             "effects.thermal (its outer ring's), not given")
        temperature = state.temperatures[1]
    return {"grease_life": {"bore": v["bearing.bore"], "outer_diameter": v["bearing.outer_diameter"],
                            "limiting_speed": 1.0 if limiting is None else limiting, "temperature": temperature}}


def _life(method: str):
    """compute: the method's grease life at the solved load and the bearing's speed."""
    formula = GREASE_LIFE_METHODS[method]

    def compute(inputs: dict, settings: dict, results: dict) -> dict:
        bearing, operating, grease = inputs["bearing"], inputs["operating"], inputs["grease_life"]
        found = formula.grease_life(operating.inner_speed - operating.outer_speed, grease["limiting_speed"],
                                    grease["bore"], grease["outer_diameter"],
                                    life.equivalent_dynamic_load(bearing, results["force"][:3]),
                                    life.ball_load_rating(bearing), grease["temperature"])
        return {"grease_life.life": found.life, "grease_life.temperature": found.temperature,
                "grease_life.speed_term": found.speed_term, "grease_life.load_ratio": found.load_ratio}

    return compute


def _checks(method: str):
    """checks: the operating point against the method's stated range (`envelope_problems`)."""
    formula = GREASE_LIFE_METHODS[method]

    def checks(values: dict) -> tuple[list[str], list[str]]:
        found = GreaseLife(values["grease_life.life"], values["grease_life.temperature"],
                           values["grease_life.speed_term"], values["grease_life.load_ratio"])
        return envelope_problems(formula, found)

    return checks


def _outputs(method: str) -> tuple[Output, ...]:
    limits = GREASE_LIFE_METHODS[method].limits()
    unit = f" [{limits.speed_unit.strip()}]" if limits.speed_unit else ""
    return (
        Output("grease_life.life", "s", "h", "average grease life t (the report names the method)"),
        Output("grease_life.temperature", "K", "degC", "operating temperature T read (floored)"),
        Output("grease_life.speed_term", "", "", f"{limits.speed_name}{unit} read (floored)"),
        Output("grease_life.load_ratio", "", "", "P_r/C_r (ISO 281's P of the solved load)"),
    )


def _report(result) -> list[str]:
    method = result.model.settings["effects"].get("grease_life")
    if method not in GREASE_LIFE_METHODS or "grease_life.life" not in result.values:
        return []
    return ["", f"Grease life by {GREASE_LIFE_SOURCES[method]}: an average life, greased for life (no relubrication)"]


ADAPTER = register(Adapter(
    name="grease_life",
    bearing_types=KIND,
    keys={"effects.grease_life": Key("choice", choices=tuple(GREASE_LIFE_METHODS),
                                     doc="grease life of a deep groove ball bearing greased for life, by: "
                                         + "; ".join(f"{name}: {source}" for name, source in GREASE_LIFE_SOURCES.items())),
          "grease_life.temperature": quantity("temperature", "the bearing's operating temperature (default: "
                                                             "lubricant.temperature; with effects.thermal the network's "
                                                             "outer ring's)"),
          "grease_life.limiting_speed": quantity("angular_speed", "N_max of NSK's methods: the bearing's limiting speed "
                                                                  "with grease lubrication (NSK's tables, ZZ/VV)"),
          "bearing.bore": quantity("length"),
          "bearing.outer_diameter": quantity("length")},
    inputs=(InputBuilder(("grease_life",), KIND, _grease, after=("bearing",), scene_keys=("!effects.thermal",)),
            InputBuilder(("grease_life",), KIND, _grease, after=("bearing", "thermal"), scene_keys=("effects.thermal",))),
    blocks=tuple(Block(name=f"grease_life_{method}", bearing_types=KIND, enabled_by=("grease_life", method),
                       requires=("equilibrium",), inputs=("bearing", "operating", "grease_life"),
                       outputs=_outputs(method), compute=_life(method), checks=_checks(method))
                 for method in GREASE_LIFE_METHODS),
    report=_report,
    refused={(kind, "effects.grease_life"): f"the published grease-life formulas hold for single-row deep groove ball "
                                            f"bearings (NSK E1102, JTEKT BS004, FYH 3300), not for {kind}"
             for kind in OUTSIDE},
))
