"""Random inputs over the documented envelope (docs/theory.md §Envelopes).

Valid ball and roller bearings: seeded random draws of geometry, speed and load, solved in batches
(one compiled program per rolling-element count and bearing type: a batch of hundreds of random
bearings costs one compilation, where hypothesis's one-example-at-a-time draws would each pay a
dispatch and the shrinking would re-solve; ball bearings vmapped, roller bearings one after
another, `one_after_another`; the seed is printed on failure and set by DIFFBEARING_SEED). Every
output is finite. At or above the requisite minimum load (ISO 281's equivalent load ≥ 0.01 C_r
for ball bearings, 0.02 C_r for roller bearings, `minimum_load`, and at speed a rolling element's
centrifugal force below the load per element), or at standstill, and for angular-contact bearings
with the axial load to run without a partner, ≥ 99.9 % converge; every other case converges or
reports the reason the application layer gives (a state outside the model, `ball_validity`; a
centrifugal force above the load per ball, `light_at_speed`; an axial load short of
1.25 F_r tan α₀, or for a tapered roller bearing short of what any equilibrium needs at its
speed, `without_partner`). The fast profiles run in the default suite, the large ones (2000 ball,
400 cylindrical and 400 tapered roller bearings) in the slow suite. Matched pairs of
angular-contact bearings (back-to-back, face-to-face preloaded, tandem) under random radial,
axial and tilting loads at speed: 24 back-to-back pairs in the slow suite, 1200 pairs of every
arrangement in the extended one; and 400 angular-contact bearings with their tilts free (no
moment given) in the extended one. Every draw keeps its rolling elements on the pitch circle with
room for a cage bar (`fitting`).

Invalid scene values (hypothesis): any quantity key of the packaged examples given a wrong unit,
NaN, or infinity is refused with a ValueError (exit 2) naming that key.
"""

import math
import os
import tomllib

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene
from diffbearing.app.adapters.bearings.ball import centrifugal_ratio, low_shoulder_angle, missing_axial_load
from diffbearing.app.adapters.systems.bearing_set import centrifugal_ratio as set_centrifugal_ratio
from diffbearing.app.adapters.systems.bearing_set import tandem_missing_axial_load
from diffbearing.app.adapters.bearings.roller_bearing import missing_axial_load as roller_missing_axial_load
from diffbearing.app.registry import all_keys
from diffbearing.app.scene import read_document
from diffbearing.bearings.ball import ball_equilibrium, ball_validity
from diffbearing.bearings.roller.roller_equilibrium import (
    MAX_APPROACH_FRACTION,
    RESIDUAL_TOLERANCE,
    RollerModel,
    RollerOperating,
    roller_centrifugal_force,
    roller_raceways,
    roller_results,
    roller_stiffness_matrix,
    solve_roller_equilibrium,
)
from diffbearing.bearings.roller.roller_geometry import roller_bearing
from diffbearing.bearings.roller.roller_profile import roller_profile
from diffbearing.params import Operating, ball_bearing
from diffbearing.ratings import life
from diffbearing.ratings.minimum_load import BALL_MINIMUM_LOAD_RATIO, ROLLER_MINIMUM_LOAD_RATIO
from diffbearing.ratings.roller_life import roller_dynamic_load_rating, roller_equivalent_dynamic_load
from diffbearing.systems.bearing_set import bearing_set, preload_offset
from diffbearing.systems.shaft_equilibrium import Shaft, ShaftLoads, shaft_stiffness, solve_shaft

SEED = int(os.environ.get("DIFFBEARING_SEED", "20261127"))
SPEED_MODEL = ball_equilibrium.BallModel(centrifugal=True, gyroscopic=True)
# the envelope the draws walk (docs/theory.md §Envelopes, ball bearings)
BALL_DIAMETER = (3e-3, 30e-3)  # m
DIAMETER_RATIO = (0.12, 0.32)  # γ = D_w/d_m
INNER_GROOVE, OUTER_GROOVE = (0.505, 0.56), (0.51, 0.57)
FREE_ANGLE = {"deep_groove_ball": (0.0, 10.0), "angular_contact_ball": (12.0, 45.0)}  # deg
SPEED_FACTOR = (0.0, 1.0e6)  # n d_m [mm r/min]
LOAD_LEVEL = (-2.2, -0.3)  # log10 of |F| / (50 D_w^1.8 12^(2/3)) [N, mm]: a rough C; ~80 % above the minimum load


def fitting(bounds, count: int):
    """(low, high) of D/d_m, `bounds` capped where `count` elements no longer fit on the pitch circle
    with a cage bar between them: D < 0.95 d_m sin(π/Z) (the envelope's D < d_m sin(π/Z), refused beyond)."""
    return bounds[0], min(bounds[1], 0.95 * math.sin(math.pi / count))


def draw(rng, size: int, kind: str, count: int):
    """(size, 8) random cases of `count` balls: D_w, γ, f_i, f_o, α₀, ω_i, F_r, F_a (SI)."""
    diameter = rng.uniform(*BALL_DIAMETER, size)
    ratio = rng.uniform(*fitting(DIAMETER_RATIO, count), size)
    pitch = diameter / ratio
    speed = rng.uniform(*SPEED_FACTOR, size) / (pitch * 1e3) * math.pi / 30.0
    rating = 50.0 * (diameter * 1e3) ** 1.8 * 12.0 ** (2.0 / 3.0)
    load = rating * 10.0 ** rng.uniform(*LOAD_LEVEL, size)
    radial_share = rng.uniform(0.0, 1.0, size)
    axial_share = (1.0 - radial_share) * (0.5 if kind == "deep_groove_ball" else 1.0)
    return np.stack([diameter, ratio, rng.uniform(*INNER_GROOVE, size), rng.uniform(*OUTER_GROOVE, size),
                     np.radians(rng.uniform(*FREE_ANGLE[kind], size)), speed, load * radial_share,
                     load * axial_share], axis=1)


def solve_case(case, count: int, kind: str, held: bool = True):
    """One bearing with its tilts held (a shaft holds a single bearing; `held`) or free (no moment
    given, as a single bearing's scene without operating.misalignment), through the blocks the
    ball adapter runs: status flags and whether every output is finite."""
    diameter, ratio, inner, outer, angle, speed, radial, axial = (case[i] for i in range(8))
    bearing = ball_bearing(ball_diameter=diameter, pitch_diameter=diameter / ratio, balls=count, kind=kind,
                           inner_groove_ratio=inner, outer_groove_ratio=outer, contact_angle=angle)
    operating = Operating(speed, 0.0, jnp.stack([radial, 0.0, axial]), jnp.zeros(2),
                          misalignment=jnp.zeros(2) if held else None)
    solution = ball_equilibrium.solve_equilibrium(bearing, operating, SPEED_MODEL)
    balls = ball_equilibrium.ball_results(solution.displacement, bearing, operating, SPEED_MODEL)
    stiffness = ball_equilibrium.stiffness_matrix(solution.displacement, bearing, operating, SPEED_MODEL)
    outputs = (solution.displacement, solution.force, solution.residual, stiffness, *jax.tree.leaves(balls))
    minimum = BALL_MINIMUM_LOAD_RATIO * life.basic_dynamic_load_rating(bearing)
    light = centrifugal_ratio(balls, operating) > 1.0
    return {"finite": jnp.all(jnp.stack([jnp.all(jnp.isfinite(x)) for x in outputs])),
            "residual": solution.residual, "converged": solution.converged,
            "approach": solution.approach_ratio, "angle": solution.contact_angle,
            "lowest": low_shoulder_angle(bearing, balls), "light": light,
            "below_minimum": ((life.equivalent_dynamic_load(bearing, operating.force) < minimum) | light) & (speed > 0.0),
            "without_partner": missing_axial_load(bearing, operating) > 0.0}


def classify(out: dict) -> dict[str, np.ndarray]:
    """Each case's outcome, as the CLI reports it (adapters/ball.py `_equilibrium_checks`): a reason
    is a centrifugal force above the load per ball (`light_at_speed`) or an angular-contact
    bearing short of the axial load it needs without a partner (`without_partner`)."""
    solved = out["residual"] < ball_equilibrium.RESIDUAL_TOLERANCE
    outside = ((out["approach"] > ball_validity.MAX_APPROACH_FRACTION) | (out["angle"] >= np.pi / 2)
               | (out["lowest"] < -1e-9))
    reason = out["light"] | out["without_partner"]
    return {"converged": solved & ~outside, "outside the model": solved & outside,
            "unconverged, with its reason": ~solved & reason, "unexplained": ~solved & ~reason}


def tally(totals: dict, kind: str, outcome: dict, out: dict) -> None:
    """Add each outcome's count to `totals[kind]`: at or above the minimum load (and, angular-contact,
    with the axial load to run without a partner), below the minimum load, and short of that axial load."""
    short = out.get("without_partner", np.zeros_like(out["below_minimum"]))
    bands = (("loaded", ~out["below_minimum"] & ~short), ("below minimum load", out["below_minimum"]),
             ("short of axial load", short & ~out["below_minimum"]))
    for band, inside in bands:
        counts = totals.setdefault(kind, {}).setdefault(band, dict.fromkeys(outcome, 0))
        for name, flags in outcome.items():
            counts[name] += int((flags & inside).sum())


def check_totals(totals: dict) -> None:
    """≥ 99.9 % of the cases at or above the minimum load converge; none anywhere unexplained."""
    print(f"\nseed {SEED}: {totals}")
    for kind, bands in totals.items():
        loaded = bands["loaded"]
        assert loaded["converged"] >= 0.999 * sum(loaded.values()), f"seed {SEED}: {kind}: {loaded}"
        assert all(band["unexplained"] == 0 for band in bands.values()), f"seed {SEED}: {kind}: {bands}"


@pytest.fixture(scope="module")
def solvers():
    cache = {}

    def get(count, kind):
        if (count, kind) not in cache:
            cache[count, kind] = jax.jit(jax.vmap(lambda case: solve_case(case, count, kind)))
        return cache[count, kind]

    return get


def run_random(groups, size: int, rng, draw_cases, solver, classify_cases, elements: str) -> dict:
    """Each (kind, count) of `groups`: `size` cases drawn, solved in one vmapped batch by
    `solver(count, kind)`, every output finite, none unconverged without a reason; the totals
    checked (`check_totals`) and returned."""
    totals = {}
    for kind, count in groups:
        cases = draw_cases(rng, size, kind, count)
        out = jax.tree.map(np.asarray, solver(count, kind)(jnp.asarray(cases)))
        assert out["finite"].all(), (f"seed {SEED}: non-finite outputs for {kind}, {count} {elements}: "
                                     f"{cases[~out['finite']][:3].tolist()}")
        outcome = classify_cases(out)
        tally(totals, kind, outcome, out)
        assert not outcome["unexplained"].any(), (f"seed {SEED}: {kind}, {count} {elements}, unconverged without a "
                                                  f"reason: {cases[outcome['unexplained']][:3].tolist()}")
    check_totals(totals)
    return totals


def run_profile(solvers, groups, size: int) -> dict:
    return run_random(groups, size, np.random.default_rng(SEED), draw, solvers, classify, "balls")


def test_random_ball_bearings_converge_or_say_why(solvers):
    run_profile(solvers, [("deep_groove_ball", 8), ("angular_contact_ball", 14)], 32)


@pytest.mark.slow  # about 2.5 min (2 cores): the slow suite's ≥ 2000 valid cases
def test_random_ball_bearings_large_profile(solvers):
    """2000 cases: ≥ 99.9 % of those at or above the minimum load (and, angular-contact, with the
    axial load to run without a partner) converge, every other converges or reports its reason."""
    totals = run_profile(solvers, [(kind, count) for kind in ("deep_groove_ball", "angular_contact_ball")
                                   for count in (8, 14)], 500)
    assert sum(sum(bands["loaded"].values()) for bands in totals.values()) >= 1000


@pytest.mark.extended
@pytest.mark.slow
def test_random_free_tilt_bearings_large_profile():
    """400 angular-contact bearings whose inner ring tilts freely (no moment given): the free tilt
    is a soft mode under light load; every one at or above the minimum load and with the axial load
    to run without a partner converges, the rest converge or report their reason."""
    def solver(count, kind):
        return jax.jit(jax.vmap(lambda case: solve_case(case, count, kind, held=False)))

    run_random([("angular_contact_ball", 8), ("angular_contact_ball", 14)], 200, np.random.default_rng(SEED + 3), draw,
               solver, classify, "balls")


# --- roller bearings -----------------------------------------------------------------------

ROLLER_MODEL = RollerModel(laminae=20, centrifugal=True)
ROLLER_DIAMETER = (5e-3, 40e-3)  # m
ROLLER_RATIO = (0.12, 0.3)  # D/d_m
ROLLER_LENGTH = (0.8, 1.6)  # l/D
ROLLER_SPEED_FACTOR = (0.0, 6.0e5)  # n d_m [mm r/min]
ROLLER_LOAD_LEVEL = (-1.8, -0.2)  # log10 of |F| / (100 (D l)^(7/9) 12^(3/4)) [N, mm]: about half above the minimum load


def draw_rollers(rng, size: int, kind: str, count: int):
    """(size, 6) random cylindrical roller bearings of `count` rollers: D, γ, l/D, diametral
    clearance, ω_i, F_r (SI)."""
    diameter = rng.uniform(*ROLLER_DIAMETER, size)
    ratio = rng.uniform(*fitting(ROLLER_RATIO, count), size)
    length = rng.uniform(*ROLLER_LENGTH, size)
    speed = rng.uniform(*ROLLER_SPEED_FACTOR, size) / (diameter / ratio * 1e3) * math.pi / 30.0
    rating = 100.0 * (diameter * 1e3 * diameter * length * 1e3) ** (7.0 / 9.0) * 12.0 ** 0.75
    load = rating * 10.0 ** rng.uniform(*ROLLER_LOAD_LEVEL, size)
    clearance = rng.uniform(-2e-4, 1e-3, size) * diameter / ratio
    return np.stack([diameter, ratio, length, clearance, speed, load], axis=1)


def solve_roller_case(case, count: int, kind: str):
    """One cylindrical roller bearing with its tilts held, through the blocks the roller adapter runs."""
    diameter, ratio, length_ratio, clearance, speed, radial = (case[i] for i in range(6))
    length = diameter * length_ratio
    profile = roller_profile("circular", length=length, flat_length=0.8 * length, crown_radius=50.0 * diameter)
    bearing = roller_bearing(kind=kind, length=length, diameter=diameter, profile=profile, roller_count=count)
    raceways = roller_raceways(bearing, pitch_diameter=diameter / ratio, diametral_clearance=clearance)
    return held_roller_case(bearing, raceways, jnp.stack([radial, 0.0, 0.0]), speed)


def held_roller_case(bearing, raceways, force, speed):
    """A roller bearing with its tilts held under `force` [N] at `speed` [rad/s], through the blocks
    the roller adapter runs: status flags and whether every output is finite."""
    count, diameter, length = bearing.roller_count, 0.5 * (bearing.small_diameter + bearing.large_diameter), bearing.length
    operating = RollerOperating(force, jnp.zeros(2), inner_speed=speed, misalignment=jnp.zeros(2))
    solution = solve_roller_equilibrium(bearing, raceways, operating, ROLLER_MODEL)
    rollers = roller_results(solution.displacement, bearing, raceways, operating, ROLLER_MODEL)
    stiffness = roller_stiffness_matrix(solution.displacement, bearing, raceways, operating, ROLLER_MODEL)
    outputs = (solution.displacement, solution.force, solution.residual, stiffness, *jax.tree.leaves(rollers))
    rating = roller_dynamic_load_rating(count, diameter, length, raceways.cup_angle, raceways.pitch_diameter)
    equivalent = roller_equivalent_dynamic_load(force, raceways.cup_angle)
    light = roller_centrifugal_force(bearing, raceways, operating) > jnp.linalg.norm(force) / count
    return {"finite": jnp.all(jnp.stack([jnp.all(jnp.isfinite(x)) for x in outputs])),
            "residual": solution.residual, "approach": rollers.largest_approach / diameter, "light": light,
            "below_minimum": ((equivalent < ROLLER_MINIMUM_LOAD_RATIO * rating) | light) & (speed > 0.0),
            "without_partner": roller_missing_axial_load(bearing, raceways, operating, ROLLER_MODEL) > 0.0}


def classify_rollers(out: dict) -> dict[str, np.ndarray]:
    """Each case's outcome, as the CLI reports it (adapters/roller_bearing.py `_equilibrium_checks`):
    a reason is a centrifugal force above the load per roller (`light`) or a tapered bearing short
    of the axial load any equilibrium needs at its speed (`without_partner`, an error of its own)."""
    solved = out["residual"] < RESIDUAL_TOLERANCE
    outside = out["approach"] > MAX_APPROACH_FRACTION
    short = out["without_partner"]
    return {"converged": solved & ~outside & ~short, "outside the model": solved & outside & ~short,
            "unconverged, with its reason": short | (~solved & out["light"]),
            "unexplained": ~solved & ~out["light"] & ~short}


def one_after_another(solve_one):
    """A batch's cases solved one after another in one compiled program (`lax.map`), not vmapped:
    under `vmap` every case's nested roller Newtons (a while loop inside each ring step) run for as
    long as the slowest case's."""
    return jax.jit(lambda cases: jax.lax.map(solve_one, cases))


def run_roller_profile(groups, size: int) -> dict:
    def solver(count, kind):
        return one_after_another(lambda case: solve_roller_case(case, count, kind))

    return run_random(groups, size, np.random.default_rng(SEED + 1), draw_rollers, solver, classify_rollers, "rollers")


def test_random_roller_bearings_converge_or_say_why():
    run_roller_profile([("cylindrical_roller", 12)], 24)


@pytest.mark.slow  # 80 s (2 cores)
def test_random_roller_bearings_large_profile():
    """400 cylindrical roller bearings: ≥ 99.9 % of those at or above the minimum load converge, the
    rest converge or report a reason."""
    run_roller_profile([("cylindrical_roller", 12), ("cylindrical_roller", 20)], 200)


TAPER = (0.08, 0.2)  # (large − small) / mean roller diameter
CONE_HALF_ANGLE = (1.5, 3.0)  # deg
CUP_ANGLE = (10.0, 25.0)  # deg: the medium to steep series
AXIAL_MARGIN = (1.1, 4.0)  # F_z / (F_r tan α_o): above 1 an equilibrium exists at rest (below, refused); at speed
# the rollers' centrifugal forces raise that bound (`tapered_axial_load_needed`), and a draw below it is reported so


def draw_tapered(rng, size: int, kind: str, count: int):
    """(size, 10) random tapered roller bearings of `count` rollers: mean D, γ, l/D, diametral
    clearance (≤ 0: adjusted), ω_i, F_r, taper, cup angle α_o, F_z, cone half angle (SI)."""
    cases = draw_rollers(rng, size, "cylindrical_roller", count)
    cases[:, 3] = -rng.uniform(0.0, 2e-4, size) * cases[:, 0] / cases[:, 1]
    cup = np.radians(rng.uniform(*CUP_ANGLE, size))
    axial = cases[:, 5] * np.tan(cup) * rng.uniform(*AXIAL_MARGIN, size)
    half_angle = np.radians(rng.uniform(*CONE_HALF_ANGLE, size))
    return np.concatenate([cases, np.stack([rng.uniform(*TAPER, size), cup, axial, half_angle], axis=1)], axis=1)


def solve_tapered_case(case, count: int, kind: str):
    """One tapered roller bearing with its tilts held, through the blocks the roller adapter runs."""
    diameter, ratio, length_ratio, clearance, speed, radial, taper, cup, axial, half_angle = (case[i] for i in range(10))
    length = diameter * length_ratio
    profile = roller_profile("circular", length=length, flat_length=0.8 * length, crown_radius=50.0 * diameter)
    bearing = roller_bearing(kind="tapered_roller", length=length, small_diameter=diameter * (1.0 - 0.5 * taper),
                             large_diameter=diameter * (1.0 + 0.5 * taper), cone_half_angle=half_angle, profile=profile,
                             roller_count=count)
    raceways = roller_raceways(bearing, pitch_diameter=diameter / ratio, diametral_clearance=clearance, cup_angle=cup)
    return held_roller_case(bearing, raceways, jnp.stack([radial, 0.0, axial]), speed)


def run_tapered_profile(groups, size: int) -> dict:
    def solver(count, kind):
        return one_after_another(lambda case: solve_tapered_case(case, count, kind))

    return run_random(groups, size, np.random.default_rng(SEED + 4), draw_tapered, solver, classify_rollers, "rollers")


@pytest.mark.slow  # 2 min (2 cores)
def test_random_tapered_roller_bearings_large_profile():
    """400 tapered roller bearings, their tilts held: ≥ 99.9 % of those at or above the minimum load
    (with the axial load an equilibrium needs at their speed) converge, the rest converge or report a
    reason."""
    run_tapered_profile([("tapered_roller", 14), ("tapered_roller", 20)], 200)


# --- bearing sets ----------------------------------------------------------------------------

SET_ANGLE = (12.0, 40.0)  # deg: the angular-contact bearings of matched sets
SET_WIDTH = (1.3, 2.2)  # bearing width / D_w: the catalogues' 70/72 series
SET_PRELOAD = (-2.5, -1.0)  # log10 of the preload / the rough C (light to heavy spindle preloads)


def draw_sets(rng, size: int, arrangement: str, count: int):
    """(size, 11) random matched pairs: D_w, γ, f_i, f_o, α₀, ω_i, F_r, F_a, M, preload, width (SI;
    no preload for a tandem pair, whose axial load is then +z, the way both bearings face)."""
    cases = draw(rng, size, "angular_contact_ball", count)
    diameter, pitch = cases[:, 0], cases[:, 0] / cases[:, 1]
    cases[:, 4] = np.radians(rng.uniform(*SET_ANGLE, size))
    rating = 50.0 * (diameter * 1e3) ** 1.8 * 12.0 ** (2.0 / 3.0)
    tandem = arrangement == "tandem"
    axial = cases[:, 7] * (1.0 if tandem else rng.choice([-1.0, 1.0], size))
    moment = rng.uniform(-0.5, 0.5, size) * cases[:, 6] * pitch
    preload = 0.0 if tandem else rating * 10.0 ** rng.uniform(*SET_PRELOAD, size)
    width = diameter * rng.uniform(*SET_WIDTH, size)
    return np.concatenate([cases[:, :7], np.stack([axial, moment, np.broadcast_to(preload, size), width], axis=1)],
                          axis=1)


def solve_set_case(case, count: int, arrangement: str):
    """One matched pair through the blocks the set adapter runs (the preload as a force turned into
    the offset the set holds, the shaft solve, both bearings' balls, the set's stiffness), with the
    reasons its checks give (adapters/bearing_set.py `_checks`): a centrifugal force above the load
    per ball, a tandem pair short of axial load."""
    diameter, ratio, inner, outer, angle, speed, radial, axial, moment, preload, width = (case[i] for i in range(11))
    bearing = ball_bearing(ball_diameter=diameter, pitch_diameter=diameter / ratio, balls=count,
                           kind="angular_contact_ball", inner_groove_ratio=inner, outer_groove_ratio=outer,
                           contact_angle=angle)
    offset = 0.0 if arrangement == "tandem" else preload_offset(bearing, preload, SPEED_MODEL)
    supports = bearing_set(bearing, arrangement, spacing=width, offset=offset, model=SPEED_MODEL)
    shaft = Shaft(supports, ShaftLoads(jnp.zeros(1), jnp.stack([radial, 0.0, axial])[None],
                                       jnp.stack([0.0, moment])[None]), speed)
    solution = solve_shaft(shaft)
    operating = Operating(speed, 0.0, jnp.zeros(3), jnp.zeros(2))
    balls = [ball_equilibrium.ball_results(local, bearing, operating, SPEED_MODEL, centres)
             for local, centres in zip(solution.bearing_displacements, solution.elements)]
    outputs = (solution.displacement, solution.residual,
               shaft_stiffness(solution.displacement, shaft, elements=solution.elements),
               *solution.bearing_forces, *jax.tree.leaves(balls))
    validity = jnp.stack([jnp.stack([
        ball_validity.largest_approach_ratio(b.inner_approach, b.outer_approach, diameter),
        ball_validity.largest_contact_angle(b.inner_contact_angle, b.outer_contact_angle, b.inner_load, b.outer_load),
        low_shoulder_angle(bearing, b)]) for b in balls])
    force = jnp.stack([radial, 0.0, axial])
    standstill_preload = 0.0 if arrangement == "tandem" else preload
    light = set_centrifugal_ratio(balls, force, standstill_preload) > 1.0
    short = tandem_missing_axial_load(bearing, force, jnp.stack([0.0, moment]), width, arrangement) > 0.0
    return {"finite": jnp.all(jnp.stack([jnp.all(jnp.isfinite(x)) for x in outputs])),
            "residual": solution.residual, "approach": jnp.max(validity[:, 0]), "angle": jnp.max(validity[:, 1]),
            "lowest": jnp.min(validity[:, 2]), "light": light, "without_partner": short,
            "below_minimum": light & (speed > 0.0)}


def run_set_profile(groups, size: int) -> dict:
    def solver(count, arrangement):
        return jax.jit(jax.vmap(lambda case: solve_set_case(case, count, arrangement)))

    return run_random(groups, size, np.random.default_rng(SEED + 2), draw_sets, solver, classify, "balls")


@pytest.mark.slow
def test_random_bearing_sets_converge_or_say_why():
    """Back-to-back pairs, preloaded, under random radial, axial and tilting loads at speed."""
    run_set_profile([("back_to_back", 16)], 24)


@pytest.mark.extended
@pytest.mark.slow
def test_random_bearing_sets_large_profile():
    """Every arrangement: ≥ 99.9 % of the preloaded pairs (and the tandem pairs with the axial load
    to run without a partner) converge, the rest converge or report a reason."""
    run_set_profile([(arrangement, count) for arrangement in ("back_to_back", "face_to_face", "tandem")
                     for count in (12, 20)], 200)


# --- invalid values of scene keys ----------------------------------------------------------

EXAMPLES = ("aero_angular_contact", "mounted_6411", "gearbox_6411_ratings", "cylindrical_roller_bearing",
            "tapered_roller_bearing", "cage_b7005", "starved_roller", "spindle_pair")
SI_OF = {"length": "mm", "force": "N", "moment": "N*m", "angle": "deg", "angular_speed": "rpm", "pressure": "MPa",
         "viscosity": "Pa*s", "kinematic_viscosity": "mm^2/s", "density": "kg/m^3", "inverse_pressure": "1/Pa",
         "stiffness": "N/m", "time": "s", "temperature": "degC", "thermal_expansion": "1/K", "dimensionless": "",
         "temperature_difference": "K", "volume_flow": "l/min", "heat_transfer_coefficient": "W/(m^2*K)"}


SHOULDERS = ('bearing.inner_shoulder_diameter="78 mm"', 'bearing.outer_shoulder_diameter="117 mm"')
# Keys no packaged example sets, walked on an example with a valid value of them given first.
OPTIONAL_KEYS = (
    ("gearbox_6411_ratings", "bearing.inner_shoulder_diameter", "length", None, SHOULDERS),
    ("gearbox_6411_ratings", "bearing.outer_shoulder_diameter", "length", None, SHOULDERS),
    ("gearbox_6411_ratings", "operating.radial_displacement", "length", 2,
     ('operating.force=["0 N", "0 N", "2 kN"]', 'operating.radial_displacement=["20 µm", "0 µm"]')),
    ("cylindrical_roller_bearing", "operating.radial_displacement", "length", 2,
     ('operating.force=["0 N", "0 N", "0 N"]', 'operating.radial_displacement=["20 µm", "0 µm"]')),
    ("tapered_roller_bearing", "operating.axial_displacement", "length", None,
     ('operating.force=["4 kN", "0 N", "0 N"]', 'operating.axial_displacement="10 µm"')),
)


def _quantity_keys():
    """(example, dotted key, dimension, list length or None, overrides given first) of every quantity
    the examples set, and of the optional keys no example sets (`OPTIONAL_KEYS`)."""
    keys = all_keys()
    found = []
    for example in EXAMPLES:
        document, _ = read_document(example)
        for table, content in document.items():
            if not isinstance(content, dict) or table == "sweep":
                continue
            for name, value in content.items():
                key = keys.get(f"{table}.{name}")
                if key is not None and key.kind in ("quantity", "quantities"):
                    found.append((example, f"{table}.{name}", key.dimension,
                                  len(value) if isinstance(value, list) else None, ()))
    return found + list(OPTIONAL_KEYS)


QUANTITY_KEYS = _quantity_keys()
hypothesis.settings.register_profile("fast", max_examples=40, deadline=None)
hypothesis.settings.register_profile("large", max_examples=400, deadline=None)


INVALID = st.sampled_from(["3 kg", "nan", "-inf", "x"])


def check_refused(target, bad, position):
    """The example with one quantity (or one element of a list) set to `bad`: ValueError naming the key."""
    example, key, dimension, length, given = target
    unit = SI_OF[dimension]
    text = bad if bad in ("3 kg", "x") else f"{bad} {unit}".strip()
    if length is None:
        override = f'{key}="{text}"'
    else:
        values = [f'"0 {unit}"'] * length
        values[position % length] = f'"{text}"'
        override = f"{key}=[{', '.join(values)}]"
    with pytest.raises(ValueError) as error:
        build_model(load_scene(example, [*given, override]))
    assert key in str(error.value), (example, override, str(error.value))


def _user_keys(example: str) -> set[str]:
    document, _ = read_document(example)
    return {f"{table}.{name}" for table, content in document.items() if isinstance(content, dict) for name in content}


def check_scaled(target, factor):
    """The example with one quantity scaled by `factor` (its sign flipped, zeroed, ×1e3, ×1e-6): it
    runs, or is refused by a message that starts with a key the user wrote — the changed one, or
    the other key of a relation between two keys the scene sets — never a derived one."""
    example, key, _, length, given = target
    document, _ = read_document(example)
    table, name = key.split(".", 1)
    written = {item.split("=", 1)[0]: tomllib.loads("value = " + item.split("=", 1)[1])["value"] for item in given}
    value = written[key] if key in written else document[table][name]

    def scaled(item):
        if isinstance(item, (int, float)):
            return repr(item * factor)
        number, _, unit = item.strip().partition(" ")
        return f'"{float(number) * factor:g} {unit}"'

    text = scaled(value) if length is None else "[" + ", ".join(scaled(item) for item in value) + "]"
    try:
        build_model(load_scene(example, [*given, f"{key}={text}"]))
    except ValueError as error:
        named = str(error).split(":")[0].split(" ")[0]
        assert named in _user_keys(example) | set(written) | {key}, (example, key, text, str(error))


@hypothesis.given(target=st.sampled_from(QUANTITY_KEYS), bad=INVALID, position=st.integers(0, 2))
@hypothesis.settings(hypothesis.settings.get_profile("fast"))
def test_invalid_scene_values_name_their_key(target, bad, position):
    check_refused(target, bad, position)


@hypothesis.given(target=st.sampled_from(QUANTITY_KEYS), factor=st.sampled_from([-1.0, 0.0, 1e3, 1e-6]))
@hypothesis.settings(hypothesis.settings.get_profile("fast"))
def test_out_of_range_values_name_a_key_the_user_wrote(target, factor):
    check_scaled(target, factor)


@pytest.mark.slow
@hypothesis.given(target=st.sampled_from(QUANTITY_KEYS), bad=INVALID, position=st.integers(0, 2))
@hypothesis.settings(hypothesis.settings.get_profile("large"))
def test_invalid_scene_values_name_their_key_large(target, bad, position):
    check_refused(target, bad, position)


@pytest.mark.slow
@hypothesis.given(target=st.sampled_from(QUANTITY_KEYS), factor=st.sampled_from([-1.0, 0.0, 1e3, 1e-6]))
@hypothesis.settings(hypothesis.settings.get_profile("large"))
def test_out_of_range_values_name_a_key_the_user_wrote_large(target, factor):
    check_scaled(target, factor)
