"""Duty cycles: a scene's [[duty]] array of load cases of a bearing, a set or a shaft, solved as one
vmapped batch, and their lives combined by the Palmgren–Miner rule (`diffbearing.ratings.duty_cycle`).

    [[duty]]
    time_share = 0.7                                   # or revolution_share, the same in every case
    "operating.force" = ["4 kN", "0 N", "1 kN"]
    "operating.inner_speed" = "1500 rpm"

    [[duty]]
    time_share = 0.3
    "operating.force" = ["9 kN", "0 N", "2 kN"]
    "operating.inner_speed" = "600 rpm"

Each case sets numeric scene keys (quoted dotted names, as in [sweep]; on a shaft also
"loads[k].force" = [Fx, Fy, Fz] and "loads[k].moment" = [Mx, My] of its k-th [[loads]] entry); a key
a case leaves out takes the scene's value. The shares are of time (then the revolutions' shares
follow from each case's relative ring speed, |inner_speed − outer_speed|, a shaft's |shaft.speed|)
or of revolutions, positive, summing to 1. Every output of every case is kept (a leading axis over
the cases); for the cycle, each life the scene's effects compute (every output in 10⁶ rev) as
`duty.<key>` = 1 / Σ u_i / L_i — a set's or a shaft's system life its bearings' cycle lives combined
as its lives are, (Σ L^(−10/9))^(−9/10) — with time shares its hours `duty.hours.<key>` at the mean
speed (`duty.mean_speed`), each case's share of the damage of its first life (`duty.damage_share`),
the revolutions' shares (`duty.revolution_share`) and the equivalent load of ISO 281's L10
(`duty.equivalent_load`).
"""

import dataclasses
import re

import jax.numpy as jnp
import numpy as np

from ..ratings import duty_cycle, life
from .schema import convert, lookup
from .units import to_si

SHARES = ("time_share", "revolution_share")
SPEEDS = ("operating.inner_speed", "operating.outer_speed")
SHAFT_SPEED = "shaft.speed"
# a shaft's load in a case: "loads[k].force" = [Fx, Fy, Fz], "loads[k].moment" = [Mx, My] of its k-th [[loads]] entry
LOAD_KEY = re.compile(r"loads\[(\d+)\]\.(force|moment)")
LOAD_FIELDS = {"force": (3, "force"), "moment": (2, "moment")}
SHARE_TOLERANCE = 1e-6  # |Σ shares − 1| allowed (shares written to a few digits)
LIFE_UNIT = "1e6 rev"
# the life whose damage the cases share, the first the scene computes
DAMAGE_LIVES = ("life.L10rm", "life.L10r", "life.L10m", "life.L10", "set.L10rm", "set.L10r", "shaft.L10rm", "shaft.L10r")


@dataclasses.dataclass(frozen=True)
class DutyCycle:
    """The cases of a [[duty]] array: {key: (N, ...) SI values} each case sets (the scene's value where
    it gives none), the shares as given (N,) and their kind ("time_share" or "revolution_share")."""

    cases: dict
    shares: np.ndarray
    share_kind: str

    @property
    def count(self) -> int:
        return len(self.shares)


def duty_cycle_of(entries, scene_values: dict) -> DutyCycle:
    """The `DutyCycle` of a scene's [[duty]] entries; ValueError naming `duty[i]` and its key."""
    if not isinstance(entries, list) or not entries or not all(isinstance(entry, dict) for entry in entries):
        raise ValueError("duty: an array of tables, [[duty]], one per load case")
    kinds = {name for entry in entries for name in SHARES if name in entry}
    if len(kinds) != 1:
        raise ValueError(f"duty: every case gives one share, all of one kind ({' or '.join(SHARES)}); got "
                         f"{sorted(kinds) or 'none'}")
    (kind,) = kinds
    shares, given = [], {}
    for number, entry in enumerate(entries):
        if kind not in entry:
            raise ValueError(f"duty[{number}]: missing {kind} (the other cases give it)")
        share = entry[kind]
        if isinstance(share, bool) or not isinstance(share, int | float) or not np.isfinite(share) or share <= 0:
            raise ValueError(f"duty[{number}].{kind} must be a number > 0, got {share!r}")
        shares.append(float(share))
        for key, value in entry.items():
            if key == kind:
                continue
            load = LOAD_KEY.fullmatch(key)
            if load is not None:
                given.setdefault(key, {})[number] = _load_value(number, key, load, value, scene_values)
                continue
            try:
                schema_key = lookup(key)
            except ValueError as error:
                raise ValueError(f"duty[{number}]: {error}") from None
            if schema_key.kind not in ("quantity", "quantities", "number"):
                raise ValueError(f"duty[{number}].{key}: a case sets numeric keys only (this key is {schema_key.kind})")
            try:
                given.setdefault(key, {})[number] = convert(key, value)
            except ValueError as error:
                raise ValueError(f"duty[{number}]: {error}") from None
    if not given:
        raise ValueError("duty: no case sets a scene key, so every case is the scene itself: give each case what "
                         "changes (operating.force, the speeds, a shaft's loads[k].force)")
    total = sum(shares)
    if abs(total - 1.0) > SHARE_TOLERANCE:
        raise ValueError(f"duty: the cases' {kind}s sum to {total:.6g}, not 1")
    cases = {}
    for key, by_case in given.items():
        base = scene_value(scene_values, key)
        if len(by_case) < len(entries) and base is None:
            missing = next(number for number in range(len(entries)) if number not in by_case)
            raise ValueError(f"duty[{missing}]: {key} is given by other cases, not by this one nor by the scene")
        cases[key] = np.asarray([by_case.get(number, base) for number in range(len(entries))], float)
    duty = DutyCycle(cases, np.asarray(shares), kind)
    if kind == "time_share":
        still = [number for number, speed in enumerate(relative_speeds(duty, scene_values)) if not speed > 0]
        if still:
            raise ValueError(f"duty[{still[0]}]: a case at standstill turns no revolutions in its time_share: give the "
                             "cycle's shares as revolution_share, or the case a speed")
    return duty


def _load_value(number: int, key: str, load, value, scene_values: dict):
    """A case's `loads[k].force` or `.moment` in SI; ValueError naming it."""
    index, field = int(load.group(1)), load.group(2)
    loads = scene_values.get("loads")
    if not isinstance(loads, list) or index >= len(loads):
        raise ValueError(f"duty[{number}].{key}: the scene has no [[loads]] entry {index}")
    size, dimension = LOAD_FIELDS[field]
    if not isinstance(value, list) or len(value) != size:
        raise ValueError(f"duty[{number}].{key}: expected a list of {size} {dimension} values, got {value!r}")
    return [to_si(item, dimension, f"duty[{number}].{key}[{i}]") for i, item in enumerate(value)]


def case_dimension(key: str) -> str:
    """The dimension of a case key's values (units.SI_UNITS), a [[loads]] field's included."""
    load = LOAD_KEY.fullmatch(key)
    return LOAD_FIELDS[load.group(2)][1] if load is not None else lookup(key).dimension


def scene_value(scene_values: dict, key: str):
    """The scene's SI value of a case key (a [[loads]] entry's field for `loads[k].field`), None where absent."""
    load = LOAD_KEY.fullmatch(key)
    if load is None:
        return scene_values.get(key)
    return scene_values["loads"][int(load.group(1))][load.group(2)]


def place(values: dict, case: dict) -> dict:
    """The scene's SI `values` with a case's {key: value} set (arrays or tracers); a `loads[k].field`
    into a copy of the [[loads]] entry k."""
    values = dict(values)
    for key, value in case.items():
        load = LOAD_KEY.fullmatch(key)
        if load is None:
            values[key] = value
            continue
        loads = list(values["loads"])
        index = int(load.group(1))
        loads[index] = {**loads[index], load.group(2): value}
        values["loads"] = loads
    return values


def case_values(duty: DutyCycle, scene_values: dict, number: int) -> dict:
    """The scene's SI values with case `number`'s keys set."""
    return place(scene_values, {key: (array[number].tolist() if np.ndim(array[number]) else float(array[number]))
                                for key, array in duty.cases.items()})


def relative_speeds(duty: DutyCycle, scene_values: dict) -> np.ndarray:
    """|n_inner − n_outer| [rad/s] of each case (a shaft's: |shaft.speed|, its outer rings standing)."""
    def of(key):
        return np.asarray(duty.cases.get(key, np.full(duty.count, float(scene_values.get(key, 0.0)))))

    if SHAFT_SPEED in duty.cases or SHAFT_SPEED in scene_values:
        return np.abs(of(SHAFT_SPEED))
    inner, outer = (of(key) for key in SPEEDS)
    return np.abs(inner - outer)


def cycle_values(duty: DutyCycle, values: dict, outputs: dict, scene_values: dict) -> dict:
    """The cycle's values (module docstring) from the cases' `values` and the model's `outputs`."""
    speeds = relative_speeds(duty, scene_values)
    if duty.share_kind == "time_share":
        revolutions = np.asarray(duty_cycle.revolution_shares(duty.shares, speeds))
    else:
        revolutions = duty.shares
    out = {"duty.revolution_share": revolutions}
    lives = [key for key, output in outputs.items() if output.unit == LIFE_UNIT and key in values]
    for key in lives:
        out[f"duty.{key}"] = np.asarray(duty_cycle.miner_life(values[key], revolutions))
    for key in lives:  # a system's life over the cycle: its bearings' cycle lives combined, not Miner's of its own
        head, _, name = key.rpartition(".")
        parts = [part for part in lives if part.startswith(f"{head}.bearings.") and part.endswith(f".{name}")]
        if parts:
            out[f"duty.{key}"] = np.asarray(life.system_life(jnp.stack([out[f"duty.{part}"] for part in parts])))
        elif head == "shaft" and f"bearings.{name}" in lives:  # a shaft's bearings: one array
            out[f"duty.{key}"] = np.asarray(life.system_life(out[f"duty.bearings.{name}"]))
    if duty.share_kind == "time_share":
        mean = float(duty_cycle.mean_speed(duty.shares, speeds))
        out["duty.mean_speed"] = np.asarray(mean)
        for key in lives:  # 10⁶ rev at n_m rev/s → hours
            out[f"duty.hours.{key}"] = out[f"duty.{key}"] * 1e6 / (mean / (2 * np.pi)) / 3600.0
    damaged = damage_life(values)
    if damaged is not None:
        out["duty.damage_share"] = np.asarray(duty_cycle.damage_shares(values[damaged], revolutions))
    needed = ("life.L10", "life.equivalent_load", "life.basic_dynamic_load_rating")
    if all(key in values for key in needed):
        lives_10, loads, ratings = (np.asarray(values[key], float) for key in needed)
        ratios = np.log(ratings / loads)
        case = int(np.argmax(np.abs(ratios)))  # the life exponent p of L10 = (C/P)^p, from the case furthest from C
        if abs(ratios[case]) > 1e-12:
            exponent = float(np.log(lives_10[case]) / ratios[case])
            out["duty.equivalent_load"] = np.asarray(duty_cycle.equivalent_load(loads, revolutions, exponent))
    return out


def damage_life(values: dict) -> str | None:
    """The life whose damage `duty.damage_share` splits: the first of `DAMAGE_LIVES` the scene computes."""
    return next((key for key in DAMAGE_LIVES if key in values), None)


def describe(key: str, outputs: dict) -> tuple[str, str, str]:
    """(description, SI unit, display unit) of one of the cycle's values `duty.*` (`cycle_values`)."""
    name = key.removeprefix("duty.")
    if name.startswith("hours."):
        return f"{outputs[name.removeprefix('hours.')].description}, in hours at the mean speed", "h", "h"
    if name in outputs:
        out = outputs[name]
        return f"{out.description}, over the cycle (Palmgren–Miner)", out.unit, out.display
    return {"revolution_share": ("each case's share of the revolutions", "", ""),
            "damage_share": ("each case's share of the damage", "", ""),
            "mean_speed": ("mean speed Σ t_i n_i", "rad/s", "rpm"),
            "equivalent_load": ("equivalent load of the cycle, (Σ u_i P_i^p)^(1/p)", "N", "kN")}[name]
