"""The cage of a ball bearing, guided by the outer-ring lands and by the balls in its pockets.

effects.cage = true: quasi-static pocket and land forces at the scene's cage offset, the restoring
force f_inv, and f_inv against the offset's direction for both pocket kinds (cage_forces.py).
effects.cage = "dynamics": the orbit from the scene's offset and its stability measures
(cage_dynamics.py), and the linear whirl stability at the quasi-static equilibrium
(cage_stability.py).
"""

import dataclasses

import jax
import jax.numpy as jnp
import numpy as np

from ....cage.cage_dynamics import simulate_cage
from ....cage.cage_forces import cage_forces, cage_offset, epicyclic_cage_speed, loaded_ball_count
from ....cage.cage_stability import cage_stability
from ....params import BALL_BEARING_KINDS, CAGE_GUIDANCES, CAGE_POCKETS, _as_float, _is_concrete, ball_cage, check_range
from ...registry import Adapter, Block, InputBuilder, Key, Output, convergence_checks, quantity, register

ORBIT_SAMPLES = 1024
OFFSET_ANGLES = 72  # directions of the f_inv curve, every 5°
# At a relative eccentricity ε = 1 the cage touches the land; a prescribed ε > 1 would put it
# through the ring, where the land's metal contact (a penalty of small overlaps, cage_lands.py)
# no longer describes anything physical.
MAX_ECCENTRICITY = 1.0


def _cage(v, built) -> dict:
    """The Cage and its centre offset (x, y) [m] of a [cage] table. Pushing
    and resisting balls default to the balls inside and outside the Sjövall load zone; given
    counts must fit in it."""
    bearing, operating = built["bearing"], built["operating"]
    for key in ("pocket_clearance", "guide_clearance", "land_width"):
        if f"cage.{key}" not in v:
            raise ValueError(f"effects.cage needs cage.{key}")
    loaded = loaded_ball_count(bearing, operating.force)
    count = bearing.ball_count
    pushing = v.get("cage.pushing_balls", loaded)
    resisting = v.get("cage.resisting_balls", count - loaded)
    if _is_concrete(loaded, pushing, resisting):
        check_range("cage.pushing_balls", pushing, low=1.0, high=float(loaded), low_open=False, high_open=False,
                    why=f"pushing balls are among the {int(loaded)} balls in the Sjövall load zone of operating.force")
        check_range("cage.resisting_balls", resisting, low=0.0, high=float(count - loaded), low_open=False,
                    high_open=False, why=f"resisting balls are among the {count - int(loaded)} balls outside "
                                         "the Sjövall load zone of operating.force")
    optional = {name: v[f"cage.{name}"] for name in ("land_diameter", "land_spacing", "film_threshold",
                                                      "contact_stiffness") if f"cage.{name}" in v}
    cage = ball_cage(bearing, pocket=v.get("cage.pocket", "outer_lock"), pocket_clearance=v["cage.pocket_clearance"],
                     guide_clearance=v["cage.guide_clearance"], land_width=v["cage.land_width"],
                     friction=v.get("cage.friction", 0.1), pushing_balls=pushing, resisting_balls=resisting,
                     guidance=v.get("cage.guidance", "outer_ring"), **optional)
    eccentricity = v.get("cage.eccentricity", 0.0)
    check_range("cage.eccentricity", eccentricity, low=0.0, high=MAX_ECCENTRICITY, low_open=False, high_open=False,
                why="the cage offset over the radial guide clearance; at 1 the cage touches the land, beyond it "
                    "it would pass into the ring")
    return {"cage": cage, "cage_offset": cage_offset(cage, operating.force, eccentricity, v.get("cage.offset_angle", 0.0))}


def _duration(v, built) -> dict:
    """Time [s] the cage dynamics simulate (None: ten cage revolutions)."""
    duration = v.get("cage.duration")
    check_range("cage.duration", duration, low=0.0, unit=" s")
    return {"cage_duration": None if duration is None else _as_float(duration)}


# --- quasi-static forces -----------------------------------------------------------------------

def _restoring_against_offset_angle(inputs: dict):
    """(angles [rad] from the radial load, f_inv [N] (pocket kind × angle)) of the scene's cage at
    its offset distance, for the outer-lock and the cylindrical pocket."""
    operating = inputs["operating"]
    distance = jnp.linalg.norm(inputs["cage_offset"])
    load_direction = jnp.arctan2(operating.force[1], operating.force[0])
    angles = 2.0 * jnp.pi * jnp.arange(OFFSET_ANGLES) / OFFSET_ANGLES
    rows = []
    for pocket in CAGE_POCKETS:
        cage = dataclasses.replace(inputs["cage"], pocket=pocket)

        def restoring(angle, cage=cage):
            direction = load_direction + angle
            offset = distance * jnp.stack([jnp.cos(direction), jnp.sin(direction)])
            return cage_forces(cage, inputs["bearing"], operating, inputs["lubricant"], offset).restoring_force

        rows.append(jax.vmap(restoring)(angles))
    return angles, jnp.stack(rows)


def _cage_quasi_static(inputs: dict, settings: dict, results: dict) -> dict:
    solved = cage_forces(inputs["cage"], inputs["bearing"], inputs["operating"], inputs["lubricant"],
                         inputs["cage_offset"])
    return {"cage.restoring_force": solved.restoring_force, "cage.force": solved.force, "cage.moment": solved.moment,
            "cage.land_force": solved.land_force, "cage.land_eccentricity": solved.land_eccentricity,
            "cage.land_contact": solved.land_contact, "cage.pocket_forces": solved.pocket_forces,
            "cage.pushing": solved.pushing, "cage.resisting": solved.resisting, "cage.drag": solved.drag,
            "cage.push": solved.push, "cage.load_zone": solved.load_zone, "cage.speed": solved.cage_speed,
            "cage.offset": inputs["cage_offset"]}


def _offset_angle_curves(inputs: dict, settings: dict, results: dict) -> dict:
    angles, curves = _restoring_against_offset_angle(inputs)
    return {"cage.offset_angle.angle": angles, "cage.offset_angle.restoring_force": curves}


def _forces_plot(result, figure):
    """The cage in its radial plane with the force of each ball and of the lands, and f_inv against
    the offset angle for both pocket kinds at the scene's eccentricity."""
    values, inputs = result.values, result.model.inputs
    bearing, operating = inputs["bearing"], inputs["operating"]
    cage_axis, angle_axis = figure.subplots(1, 2)
    pitch = 0.5 * float(bearing.pitch_diameter) * 1e3
    azimuth = np.arctan2(float(operating.force[1]), float(operating.force[0])) + 2 * np.pi * np.arange(
        bearing.ball_count) / bearing.ball_count
    circle = np.linspace(0, 2 * np.pi, 200)
    cage_axis.plot(pitch * np.cos(circle), pitch * np.sin(circle), color="grey", lw=0.8)
    forces = np.asarray(values["cage.pocket_forces"])
    scale = 0.25 * pitch / max(np.abs(forces[:, :2]).max(), 1e-12)  # ball forces; the resultant is drawn at 0.5 d_m/2
    for j, psi in enumerate(azimuth):
        x, y = pitch * np.cos(psi), pitch * np.sin(psi)
        role = "push" if values["cage.pushing"][j] > 0 else ("resist" if values["cage.resisting"][j] > 0 else "")
        colour = {"push": "tab:red", "resist": "tab:blue", "": "lightgrey"}[role]
        cage_axis.plot(x, y, "o", color=colour, ms=7)
        if role:
            cage_axis.arrow(x, y, forces[j, 0] * scale, forces[j, 1] * scale, color=colour, width=0.15,
                            length_includes_head=True)
    total = np.asarray(values["cage.force"])
    length = 0.5 * pitch / max(np.hypot(total[0], total[1]), 1e-12)
    cage_axis.arrow(0, 0, total[0] * length, total[1] * length, color="k", width=0.3, length_includes_head=True,
                    label=f"resultant {np.hypot(total[0], total[1]):.3g} N (direction)")
    offset = np.asarray(values["cage.offset"])
    cage_axis.plot(*(offset / max(np.hypot(*offset), 1e-12) * 0.25 * pitch), "x", color="tab:green", ms=9,
                   label=f"offset direction ({np.hypot(*offset) * 1e6:.3g} µm)")
    cage_axis.plot([], [], "o", color="tab:red", label="pushing ball (force on cage)")
    cage_axis.plot([], [], "o", color="tab:blue", label="resisting ball")
    cage_axis.set(aspect="equal", xlabel="x [mm] (radial load along +x)", ylabel="y [mm]",
                  title=f"forces on the cage; f_inv = {float(values['cage.restoring_force']):.3g} N")
    cage_axis.legend(fontsize=7, loc="lower left")
    angles = np.degrees(np.asarray(values["cage.offset_angle.angle"]))
    curves = np.asarray(values["cage.offset_angle.restoring_force"])
    for curve, pocket, style in zip(curves, CAGE_POCKETS, ("-", "--")):
        angle_axis.plot(angles, curve, style, label=f"{pocket.replace('_', '-')} pocket")
    angle_axis.axhline(0.0, color="grey", lw=0.8)
    angle_axis.set(xlabel="offset angle from the radial load [deg]", ylabel="restoring force f_inv [N]",
                   title=f"f_inv at ε = {float(np.hypot(*offset) / (0.5 * float(inputs['cage'].guide_clearance))):.2g}, "
                         f"{float(values['cage.speed']) * 30 / np.pi:.0f} r/min cage")
    angle_axis.grid(alpha=0.3)
    angle_axis.legend()
    figure.suptitle(f"{result.model.scene.title}")


CAGE_INPUTS = ("bearing", "operating", "lubricant", "cage")

QUASI_STATIC = Block(
    name="cage",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=("cage", True),
    requires=(),
    inputs=CAGE_INPUTS,
    outputs=(
        Output("cage.restoring_force", "N", "N", "restoring force f_inv (resultant against the offset)"),
        Output("cage.force", "N", "N", "resultant force on the cage [Fx, Fy, Fz]"),
        Output("cage.moment", "N*m", "N*m", "resultant moment about the cage centre [Mx, My, Mz]"),
        Output("cage.land_force", "N", "N", "force of land A (z = −s/2) and B (z = +s/2) [[Fx, Fy], [Fx, Fy]]"),
        Output("cage.land_eccentricity", "", "", "relative eccentricity ε at land A and B"),
        Output("cage.land_contact", "N", "N", "metal contact force at land A and B (0: full film)"),
        Output("cage.pocket_forces", "N", "N", "force of each ball on the cage [Z × (Fx, Fy, Fz)]", in_report=False),
        Output("cage.pushing", "", "", "weight of each ball as a pusher (0 to 1)", in_report=False),
        Output("cage.resisting", "", "", "weight of each ball as a resister (0 to 1)", in_report=False),
        Output("cage.drag", "N", "N", "oil drag on one orbiting ball f_v"),
        Output("cage.push", "N", "N", "circumferential force of each pushing ball F_push"),
        Output("cage.load_zone", "rad", "deg", "load zone 2ψ_l (Sjövall)"),
        Output("cage.speed", "rad/s", "rpm", "cage speed ω_c"),
        Output("cage.offset", "m", "um", "cage centre offset (x, y)"),
    ),
    compute=_cage_quasi_static,
)

# f_inv against the offset's direction for both pocket kinds: the figure's data, left out of sweeps
OFFSET_ANGLE_CURVES = Block(
    name="cage_offset_angle",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=("cage", True),
    requires=("cage",),
    inputs=CAGE_INPUTS,
    outputs=(
        Output("cage.offset_angle.angle", "rad", "deg", "offset directions from the radial load, every 5°",
               in_report=False),
        Output("cage.offset_angle.restoring_force", "N", "N",
               "f_inv at the scene's offset distance per direction [outer-lock, cylindrical pocket]", in_report=False),
    ),
    compute=_offset_angle_curves,
    plot=_forces_plot,
    single_run=True,
)


# --- dynamics ----------------------------------------------------------------------------------

def default_cage_duration(inputs: dict):
    """Ten revolutions of the epicyclic cage [s] (0.1 s at rest)."""
    speed = jnp.abs(epicyclic_cage_speed(inputs["bearing"], inputs["operating"]))
    return jnp.where(speed > 0, 20.0 * jnp.pi / jnp.where(speed > 0, speed, 1.0), 0.1)


def _cage_dynamics(inputs: dict, settings: dict, results: dict) -> dict:
    duration = default_cage_duration(inputs) if inputs["cage_duration"] is None else inputs["cage_duration"]
    cage, bearing, operating, lubricant = (inputs[name] for name in ("cage", "bearing", "operating", "lubricant"))
    orbit = simulate_cage(cage, bearing, operating, lubricant, inputs["cage_offset"], duration, ORBIT_SAMPLES)
    stability = cage_stability(cage, bearing, operating, lubricant)
    return {"cage.orbit.t": orbit.t, "cage.orbit.x": orbit.centre[:, 0], "cage.orbit.y": orbit.centre[:, 1],
            "cage.orbit.converged": orbit.converged, "cage.orbit.land_contact": orbit.land_contact,
            "cage.whirl_radius": orbit.whirl_radius, "cage.mean_offset": orbit.mean_offset,
            "cage.decay_rate": orbit.decay_rate, "cage.whirl_frequency": orbit.whirl_frequency,
            "cage.spectrum.frequency": orbit.frequency, "cage.spectrum.amplitude": orbit.spectrum,
            "cage.speed": orbit.cage_speed, "cage.offset": inputs["cage_offset"],
            "cage.stability.equilibrium": stability.equilibrium, "cage.stability.eccentricity": stability.eccentricity,
            "cage.stability.decay_rate": stability.decay_rate, "cage.stability.converged": stability.converged}


def _orbit_plot(result, figure):
    """The cage centre's orbit in the radial plane inside its guide clearance and the whirl
    spectrum of its second half."""
    values, inputs = result.values, result.model.inputs
    orbit_axis, spectrum_axis = figure.subplots(1, 2)
    x, y = np.asarray(values["cage.orbit.x"]) * 1e6, np.asarray(values["cage.orbit.y"]) * 1e6
    circle = np.linspace(0, 2 * np.pi, 200)
    guide = 0.5 * float(inputs["cage"].guide_clearance) * 1e6
    orbit_axis.plot(guide * np.cos(circle), guide * np.sin(circle), color="grey", lw=1.0,
                    label=f"guide clearance C = {guide:.0f} µm (radial)")
    half = len(x) // 2
    orbit_axis.plot(x[:half + 1], y[:half + 1], color="tab:blue", lw=0.6, alpha=0.5, label="first half")
    orbit_axis.plot(x[half:], y[half:], color="tab:red", lw=0.8, label="second half (measured)")
    orbit_axis.plot(x[0], y[0], "o", color="k", ms=5, label="start")
    equilibrium = np.asarray(values["cage.stability.equilibrium"]) * 1e6
    orbit_axis.plot(*equilibrium, "x", color="tab:green", ms=9, label="quasi-static equilibrium (prescribed roles)")
    orbit_axis.set(aspect="equal", xlabel="x [µm] (radial load along +x)", ylabel="y [µm]",
                   title=f"cage orbit: whirl radius {float(values['cage.whirl_radius']) * 1e6:.3g} µm, "
                         f"{float(values['cage.orbit.t'][-1]) * 1e3:.3g} ms")
    orbit_axis.legend(fontsize=7, loc="lower left")
    frequency = np.asarray(values["cage.spectrum.frequency"])
    spectrum_axis.plot(frequency, np.asarray(values["cage.spectrum.amplitude"]) * 1e6)
    cage_hz = float(values["cage.speed"]) / (2 * np.pi)
    for multiple in (-1, 1):
        spectrum_axis.axvline(multiple * cage_hz, color="grey", ls=":", lw=0.8)
    spectrum_axis.set(xlabel="whirl frequency [Hz] (forward > 0; dotted: ± cage speed)", ylabel="amplitude [µm]",
                      xlim=(-12 * max(cage_hz, 1.0), 12 * max(cage_hz, 1.0)),
                      title=f"whirl spectrum: peak at {float(values['cage.whirl_frequency']):.4g} Hz")
    spectrum_axis.grid(alpha=0.3)
    figure.suptitle(f"{result.model.scene.title}")


DYNAMICS = Block(
    name="cage_dynamics",
    bearing_types=BALL_BEARING_KINDS,
    enabled_by=("cage", "dynamics"),
    requires=(),
    inputs=CAGE_INPUTS + ("cage_duration",),
    outputs=(
        Output("cage.offset", "m", "um", "cage centre offset at the start (x, y)"),
        Output("cage.speed", "rad/s", "rpm", "epicyclic cage speed ω_m"),
        Output("cage.orbit.converged", "", "", "the time integration reached the end"),
        Output("cage.whirl_radius", "m", "um", "whirl radius: RMS of |c − c̄| over the second half"),
        Output("cage.mean_offset", "m", "um", "mean cage offset |c̄| over the second half"),
        Output("cage.decay_rate", "1/s", "1/s", "decay rate of the whirl amplitude (> 0: dies out)"),
        Output("cage.whirl_frequency", "Hz", "Hz", "dominant whirl frequency (forward > 0)"),
        Output("cage.stability.equilibrium", "m", "um", "equilibrium offset (x, y), quasi-static"),
        Output("cage.stability.eccentricity", "", "", "equilibrium offset / radial guide clearance"),
        Output("cage.stability.decay_rate", "1/s", "1/s", "linear whirl decay rate there (> 0: stable)"),
        Output("cage.stability.converged", "", "", "the equilibrium Newton converged"),
        Output("cage.orbit.t", "s", "ms", "orbit sample times", in_report=False),
        Output("cage.orbit.x", "m", "um", "cage centre x(t)", in_report=False),
        Output("cage.orbit.y", "m", "um", "cage centre y(t)", in_report=False),
        Output("cage.orbit.land_contact", "N", "N", "metal contact force at one land over time", in_report=False),
        Output("cage.spectrum.frequency", "Hz", "Hz", "whirl spectrum frequencies (signed)", in_report=False),
        Output("cage.spectrum.amplitude", "m", "um", "whirl spectrum amplitude", in_report=False),
    ),
    compute=_cage_dynamics,
    plot=_orbit_plot,
    checks=convergence_checks(("cage.orbit.converged", "the cage's time integration"),
                              ("cage.stability.converged", "the cage's quasi-static equilibrium Newton")),
)


ADAPTER = register(Adapter(
    name="cage",
    bearing_types=BALL_BEARING_KINDS,
    keys={
        "effects.cage": Key("choice", choices=(False, True, "dynamics")),
        "cage.guidance": Key("choice", choices=CAGE_GUIDANCES, doc="the model covers outer-ring land guidance"),
        "cage.pocket": Key("choice", choices=CAGE_POCKETS),
        "cage.pocket_clearance": quantity("length", "diametral"),
        "cage.guide_clearance": quantity("length", "diametral"),
        "cage.land_width": quantity("length"),
        "cage.land_diameter": quantity("length", "outer-ring guiding bore; default d_m + 0.8 D_w"),
        "cage.land_spacing": quantity("length", "axial distance of the two land centres; default D_w + land_width"),
        "cage.friction": Key("number"),
        "cage.film_threshold": quantity("length", "land film below which metal contact takes over; default 1 µm"),
        "cage.contact_stiffness": quantity("stiffness", "land metal contact stiffness; default 3e7 N/m"),
        "cage.eccentricity": Key("number", doc="cage offset / radial guide clearance, 0 ≤ ε ≤ 1"),
        "cage.offset_angle": quantity("angle", "from the radial load direction"),
        "cage.pushing_balls": Key("integer", doc="default: the balls in the load zone"),
        "cage.resisting_balls": Key("integer", doc="default: the balls outside the load zone"),
        "cage.duration": quantity("time", "time simulated by effects.cage = 'dynamics'; default 10 cage revolutions"),
    },
    inputs=(InputBuilder(("cage", "cage_offset"), BALL_BEARING_KINDS, _cage, after=("bearing", "operating")),
            InputBuilder(("cage_duration",), BALL_BEARING_KINDS, _duration)),
    blocks=(QUASI_STATIC, OFFSET_ANGLE_CURVES, DYNAMICS),
))
