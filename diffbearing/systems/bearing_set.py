"""Matched sets of two angular-contact ball bearings: back-to-back, face-to-face, tandem, preloaded
by an axial offset (docs/theory.md §Bearing sets).

A set is two identical bearings side by side on the shaft (`shaft_equilibrium`), their centres
`spacing` apart (the bearing width, plus any spacer), at z = ∓spacing/2. Their orientations
(+1: the bearing's own axial direction along the shaft's +z):

    back_to_back (DB)  +1, −1   lines of contact diverge away from the set: wide spread, stiff in tilt
    face_to_face (DF)  −1, +1   lines of contact converge inside the set: tolerant of misalignment
    tandem (DT)        +1, +1   both carry axial load in +z only; no preload without a third bearing

Preload by an axial offset: clamping the set pushes each bearing's inner ring by `offset` along
its own axis against its outer ring (the rings' face offset of a matched pair is twice it). With
no external load each bearing then carries the axial force it carries alone at δz = offset. A
preload given as a force P is turned into that offset at standstill (`preload_offset`, the single
bearing's axial solve), and from there the offset, not the force, is what the set holds: at
speed or under load the preload force changes. Mounted with fits and temperatures that move the
bearing's free contact angle from α₀ (as matched) to α₀' (`params.with_radial_clearance`), the rings stay
where the set was clamped: the offset in the running bearing's own reference is
e + (f_i + f_o − 1) D_w (sin α₀ − sin α₀') (`clamped_offset`).
"""

import dataclasses

import jax.numpy as jnp

from ..bearings.ball.ball_equilibrium import BallModel, ring_force, solve_equilibrium
from ..bearings.ball.ball_support import BallSupport
from ..params import BallBearing, Operating, _is_concrete, check_range, groove_curvature_centre_distance

ARRANGEMENTS = {"back_to_back": (1, -1), "face_to_face": (-1, 1), "tandem": (1, 1)}


def _at_standstill(model: BallModel) -> BallModel:
    """`model` without speed effects (its Hertz options kept)."""
    return dataclasses.replace(model, centrifugal=False, gyroscopic=False)


def preload_offset(bearing: BallBearing, preload, model: BallModel = BallModel()):
    """δz [m]: the axial displacement of one bearing under an axial force `preload` [N] at
    standstill (no speed effects, `model`'s Hertz options); differentiable in `preload`."""
    check_range("operating.preload", preload, low=0.0, low_open=False, unit=" N")
    operating = Operating(0.0, 0.0, jnp.stack([0.0, 0.0, jnp.asarray(preload, dtype=float)]), jnp.zeros(2))
    return solve_equilibrium(bearing, operating, _at_standstill(model)).displacement[2]


def preload_force(bearing: BallBearing, offset, model: BallModel = BallModel()):
    """F_z [N]: the axial force of one bearing pushed axially by `offset` [m] at standstill (the
    inverse of `preload_offset`)."""
    at_rest = Operating(0.0, 0.0, jnp.zeros(3), jnp.zeros(2))
    return ring_force(jnp.zeros(5).at[2].set(offset), bearing, at_rest, _at_standstill(model))[2]


def bearing_set(bearing: BallBearing, arrangement: str, *, spacing, offset=0.0, model: BallModel = BallModel()
                ) -> tuple[BallSupport, BallSupport]:
    """The two `BallSupport`s of a matched pair (module docstring): centres at z = ∓spacing/2 [m],
    each inner ring pushed by `offset` [m] along its own axis (preload; 0: none)."""
    if arrangement not in ARRANGEMENTS:
        raise ValueError(f"bearing.arrangement must be one of {tuple(ARRANGEMENTS)}, got {arrangement!r}")
    check_range("bearing.spacing", spacing, low=0.0, unit=" m", why="the distance between the two bearings' centres")
    check_range("operating.preload_offset", offset, low=0.0, low_open=False, unit=" m")
    if arrangement == "tandem" and _is_concrete(offset) and float(offset) != 0.0:
        raise ValueError("operating.preload: a tandem pair cannot be preloaded by itself (both bearings face the same "
                         "way); use back_to_back or face_to_face")
    half = 0.5 * jnp.asarray(spacing, dtype=float)
    return tuple(BallSupport(bearing, position=side * half, offset=offset, model=model, orientation=orientation)
                 for side, orientation in zip((-1.0, 1.0), ARRANGEMENTS[arrangement]))


def clamped_offset(matched: BallBearing, running: BallBearing, offset):
    """The preload offset [m] in the running bearing's reference (module docstring): the matched
    offset e plus (f_i + f_o − 1) D_w (sin α₀ − sin α₀'), α₀ as matched, α₀' as running."""
    return offset + groove_curvature_centre_distance(running) * (jnp.sin(matched.free_contact_angle)
                                                                - jnp.sin(running.free_contact_angle))
