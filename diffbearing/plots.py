"""Plots of a run (matplotlib, Agg backend): one figure per scene, chosen by its main block."""

import jax
import jax.numpy as jnp
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import hertz  # noqa: E402
from .raceway_contact import ball_raceway_modulus, inner_curvature, outer_curvature  # noqa: E402


def plot_hertz_load_curves(result, figure):
    """Peak pressure and approach of the inner and outer contacts against ball load (free angle)."""
    bearing = result.model.inputs.bearing
    method = result.model.settings["fidelity"].get("hertz", "exact")
    limit = max(result.values["hertz.inner.static_limit_load"], result.values["hertz.outer.static_limit_load"])
    loads = jnp.linspace(0.0, float(limit), 200)
    modulus = ball_raceway_modulus(bearing)
    pressure_axis, approach_axis = figure.subplots(1, 2)
    for side, curvature, style in (("inner", inner_curvature, "-"), ("outer", outer_curvature, "--")):
        curvature_sum, difference = curvature(bearing, bearing.free_contact_angle)
        contact = jax.vmap(lambda q: hertz.point_contact(q, curvature_sum, difference, modulus, method))(loads)
        pressure_axis.plot(loads / 1e3, contact.max_pressure / 1e9, style, label=f"{side} raceway")
        approach_axis.plot(loads / 1e3, contact.approach * 1e6, style, label=f"{side} raceway")
    pressure_axis.axhline(4.2, color="grey", lw=0.8)
    pressure_axis.text(0.02 * float(limit) / 1e3, 4.25, "ISO 76 limit 4.2 GPa", fontsize=8)
    pressure_axis.set(xlabel="ball load Q [kN]", ylabel="peak pressure p0 [GPa]", title="Hertz peak pressure")
    approach_axis.set(xlabel="ball load Q [kN]", ylabel="approach δ [µm]", title="Hertz approach")
    for axis in (pressure_axis, approach_axis):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(f"{result.model.scene.title}: contacts at the free contact angle")


def plot_sweep_stiffness(result, figure):
    """Diagonal stiffness against the first swept quantity (scalar sweeps) or the point index."""
    from .report import SI_OF_DIMENSION, SWEEP_DISPLAY, to_display
    from .schema import lookup

    key, values = next(iter(result.sweep_axes.items()))
    dimension = lookup(key).dimension
    if np.ndim(values) == 1 and dimension in SWEEP_DISPLAY:
        x = to_display(values, SI_OF_DIMENSION[dimension], SWEEP_DISPLAY[dimension])
        label = f"{key} [{SWEEP_DISPLAY[dimension]}]"
    else:
        x, label = np.arange(len(values)), f"{key} (point)"
    stiffness = np.asarray(result.values["stiffness"]).reshape((len(values), -1, 5, 5))[:, 0]
    translation, rotation = figure.subplots(1, 2)
    for i, name in enumerate(("Kxx", "Kyy", "Kzz")):
        translation.plot(x, stiffness[:, i, i] * 1e-6, label=name)
    for i, name in ((3, "Kθxθx"), (4, "Kθyθy")):
        rotation.plot(x, stiffness[:, i, i] * 1e-3, label=name)
    translation.set(xlabel=label, ylabel="stiffness [N/µm]", title="translational stiffness")
    rotation.set(xlabel=label, ylabel="stiffness [N·m/mrad]", title="tilting stiffness")
    for axis in (translation, rotation):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(result.model.scene.title)


def plot_contact_pressure(result, figure):
    """Pressure map of a roller contact (x across, y along the roller) and the peak along y."""
    values = result.values
    pressure = np.asarray(values["contact.pressure"]) / 1e9
    x, y = np.asarray(values["contact.x"]) * 1e6, np.asarray(values["contact.y"]) * 1e3
    map_axis, line_axis = figure.subplots(1, 2, width_ratios=[1.6, 1])
    shown = map_axis.pcolormesh(y, x, pressure, shading="nearest", cmap="viridis")
    figure.colorbar(shown, ax=map_axis, label="pressure [GPa]")
    map_axis.set(xlabel="y along the roller [mm]", ylabel="x, rolling direction [µm]",
                 title=f"contact pressure, {pressure.shape[0]} × {pressure.shape[1]} cells")
    line_axis.plot(y, pressure.max(axis=0), label="max over x")
    line_axis.axhline(float(values["hertz.line.max_pressure"]) / 1e9, color="grey", lw=0.8, ls="--",
                      label="Hertz line p0 at Q/l")
    line_axis.set(xlabel="y along the roller [mm]", ylabel="pressure [GPa]", title="peak pressure along the roller",
                  ylim=(0, None))
    line_axis.grid(alpha=0.3)
    line_axis.legend()
    profile = result.model.inputs.bearing.profile.kind
    figure.suptitle(f"{result.model.scene.title}: {profile} profile, Q = {float(values['contact.load']):.4g} N")


def plot_line_film(result, figure):
    """Pressure and film thickness along the rolling direction of the line EHL solution, with the
    starved solution beside the flooded one when the scene names starvation."""
    values = result.values
    pressure_axis, film_axis = figure.subplots(1, 2)
    cases = [("film", "fully flooded")]
    if "starvation.x" in values:
        layer = float(values["starvation.oil_layer"]) * 1e6
        cases.append(("starvation", f"starved, h_oil = {layer:.3g} µm"))
    for prefix, label in cases:
        x = np.asarray(values[f"{prefix}.x"]) * 1e3
        pressure_axis.plot(x, np.asarray(values[f"{prefix}.pressure"]) / 1e9, label=label)
        film_axis.plot(x, np.asarray(values[f"{prefix}.thickness"]) * 1e6, label=label)
    film_axis.axhline(float(values["film.central"]) * 1e6, color="grey", lw=0.8, ls="--", label="flooded central film")
    pressure_axis.set(xlabel="x, rolling direction [mm]", ylabel="pressure [GPa]", title="film pressure")
    film_axis.set(xlabel="x, rolling direction [mm]", ylabel="film thickness [µm]", title="film thickness",
                  ylim=(0, 4 * float(values["film.central"]) * 1e6))
    for axis in (pressure_axis, film_axis):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(f"{result.model.scene.title}: line EHL")


def plot_finite_line_film(result, figure):
    """Maps of the finite line EHL solution (the starved one when the scene names starvation) over
    the half roller, and the film along the roller through its minimum, flooded and starved."""
    values = result.values
    prefix = "starvation" if "starvation.pressure" in values else "film"
    x, y = np.asarray(values[f"{prefix}.x"]) * 1e3, np.asarray(values[f"{prefix}.y"]) * 1e3
    pressure_axis, film_axis, line_axis = figure.subplots(1, 3)
    shown = pressure_axis.pcolormesh(y, x, np.asarray(values[f"{prefix}.pressure"]) / 1e9, shading="nearest",
                                     cmap="viridis")
    figure.colorbar(shown, ax=pressure_axis, label="pressure [GPa]")
    thickness = np.asarray(values[f"{prefix}.thickness"]) * 1e6
    shown = film_axis.pcolormesh(y, x, thickness, shading="nearest", cmap="magma",
                                 vmax=3 * float(values["film.central"]) * 1e6)
    figure.colorbar(shown, ax=film_axis, label="film thickness [µm]")
    case = "starved" if prefix == "starvation" else "flooded"
    for axis, name in ((pressure_axis, "pressure"), (film_axis, "film")):
        axis.set(xlabel="y from mid-length [mm]", ylabel="x, rolling [mm]", title=f"{case} {name}")
    for name, label in (("film", "fully flooded"), ("starvation", "starved")):
        if f"{name}.thickness" in values:
            film = np.asarray(values[f"{name}.thickness"]) * 1e6
            row = np.unravel_index(np.argmin(film), film.shape)[0]
            line_axis.plot(np.asarray(values[f"{name}.y"]) * 1e3, film[row], label=f"{label}, at its h_min row")
    line_axis.set(xlabel="y from mid-length [mm]", ylabel="film thickness [µm]", title="film along the roller",
                  ylim=(0, 3 * float(values["film.central"]) * 1e6))
    line_axis.grid(alpha=0.3)
    line_axis.legend()
    figure.suptitle(f"{result.model.scene.title}: finite line EHL, {len(x)} × {len(y)} half-domain grid")


def restoring_force_against_offset_angle(inputs, angles):
    """f_inv [N] (pocket kind × angle) of the scene's cage at its eccentricity, for offset angles
    `angles` [rad] from the radial load direction, outer-lock and cylindrical pockets (vmapped)."""
    import dataclasses

    from .cage_forces import cage_forces

    operating = inputs.operating
    distance = jnp.linalg.norm(inputs.cage_offset)
    load_direction = jnp.arctan2(operating.force[1], operating.force[0])
    rows = []
    for pocket in ("outer_lock", "cylindrical"):
        cage = dataclasses.replace(inputs.cage, pocket=pocket)

        def restoring(angle, cage=cage):
            direction = load_direction + angle
            offset = distance * jnp.stack([jnp.cos(direction), jnp.sin(direction)])
            return cage_forces(cage, inputs.bearing, operating, inputs.lubricant, offset).restoring_force

        rows.append(jax.jit(jax.vmap(restoring))(jnp.asarray(angles)))
    return np.asarray(rows)


def plot_cage_forces(result, figure):
    """The cage in its radial plane with the force of each ball and of the lands, and f_inv against
    the offset angle for both pocket kinds at the scene's eccentricity (the paper's Fig. 9)."""
    values, inputs = result.values, result.model.inputs
    bearing = inputs.bearing
    cage_axis, angle_axis = figure.subplots(1, 2)
    pitch = 0.5 * float(bearing.pitch_diameter) * 1e3
    azimuth = np.arctan2(float(inputs.operating.force[1]), float(inputs.operating.force[0])) + 2 * np.pi * np.arange(
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
    angles = np.radians(np.arange(0.0, 360.0, 5.0))
    outer_lock, cylindrical = restoring_force_against_offset_angle(inputs, angles)
    angle_axis.plot(np.degrees(angles), outer_lock, label="outer-lock pocket")
    angle_axis.plot(np.degrees(angles), cylindrical, "--", label="cylindrical pocket")
    angle_axis.axhline(0.0, color="grey", lw=0.8)
    angle_axis.set(xlabel="offset angle from the radial load [deg]", ylabel="restoring force f_inv [N]",
                   title=f"f_inv at ε = {float(np.hypot(*offset) / (0.5 * float(inputs.cage.guide_clearance))):.2g}, "
                         f"{float(values['cage.speed']) * 30 / np.pi:.0f} r/min cage")
    angle_axis.grid(alpha=0.3)
    angle_axis.legend()
    figure.suptitle(f"{result.model.scene.title}")


def plot_cage_orbit(result, figure):
    """The cage centre's orbit in the radial plane inside its guide clearance and the whirl
    spectrum of its second half (effect cage = "dynamics")."""
    values, inputs = result.values, result.model.inputs
    orbit_axis, spectrum_axis = figure.subplots(1, 2)
    x, y = np.asarray(values["cage.orbit.x"]) * 1e6, np.asarray(values["cage.orbit.y"]) * 1e6
    circle = np.linspace(0, 2 * np.pi, 200)
    guide = 0.5 * float(inputs.cage.guide_clearance) * 1e6
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


# Block name → plot; the last block of a run that has one draws the figure.
PLOTS = {"raceway_contact": plot_hertz_load_curves, "roller_contact_slices": plot_contact_pressure,
         "roller_contact_influence": plot_contact_pressure, "film_line": plot_line_film,
         "starvation_line": plot_line_film, "film_finite_line": plot_finite_line_film,
         "starvation_finite_line": plot_finite_line_film, "cage": plot_cage_forces,
         "cage_dynamics": plot_cage_orbit}


def save_plot(result, path: str) -> None:
    """Draw the plot of the run's main block into `path` (PNG, PDF or SVG by extension)."""
    plotters = [PLOTS[block.name] for block in result.model.blocks if block.name in PLOTS]
    if result.sweep_axes:
        plotters = [plot_sweep_stiffness] if "stiffness" in result.values else []
    if not plotters:
        raise ValueError("--plot: this scene has nothing to plot yet")
    figure = plt.figure(figsize=(11, 4.5), layout="constrained")
    plotters[-1](result, figure)
    figure.savefig(path, dpi=120)
    plt.close(figure)
