"""A shaft on several bearings (`[[bearings]]`, `[[loads]]`, `[shaft]`): the shaft's equilibrium
with all bearings together, rigid (`shaft_equilibrium`, five unknowns) or, where the scene gives
its `[[shaft.sections]]`, a Timoshenko beam (`flexible_shaft`); each bearing's loads, the shaft's
deflection line, the system stiffness at a point, each bearing's life and the system's. A scene
with `[[bearings]]` is a shaft: each entry holds the keys of a `[bearing]` table of a type with a
`registry.Mounting` (ball, cylindrical or tapered roller, double-row angular-contact ball bearings;
a roller bearing's crowning as its own `profile` sub-table) plus its
`position` along the shaft, `orientation` ("+z" or "−z") and an optional axial `offset` (preload);
the scene's `[material]` applies to all."""

import dataclasses

import jax
import jax.numpy as jnp
import numpy as np

from ....ratings import life
from ....ratings.reference_life import contact_reference_life
from ....systems.flexible_shaft import FlexibleShaft, flexible_shaft_stiffness, solve_flexible_shaft
from ....systems.operating_clearance import SEAT_MATERIALS
from ....systems.shaft_equilibrium import (
    RESIDUAL_TOLERANCE,
    Shaft,
    shaft_stiffness,
    solve_shaft,
    transfer,
    turned,
)
from ...formatting import format_number, stiffness_lines
from ...registry import SHAFT, Adapter, Block, InputBuilder, Key, Output, mountings, quantity, register
from ...units import to_si
from .shaft_layout import PLACEMENT, ShaftLayout, check_dynamic_ratings, layout_supports, moment_warnings, shaft_layout
from ..bearings.ball import ADAPTER as BALL_ADAPTER
from ..bearings.ball import shoulder_checks, validity_errors
from ..bearings.roller_bearing import ADAPTER as ROLLER_BEARING_ADAPTER

# the [fidelity] keys of the ball and roller bearing models, read by the shaft's block for every bearing
FIDELITY = {key: dataclasses.replace(adapter.keys[key], read_by=("shaft",))
            for adapter, names in ((BALL_ADAPTER, ("fidelity.hertz", "fidelity.race_control", "fidelity.hertz_constants")),
                                   (ROLLER_BEARING_ADAPTER, ("fidelity.laminae",)))
            for key in names}
ORIENTATIONS = {"+z": 1, "-z": -1, "−z": -1}


def _bearing_entry(index: int, table: dict, convert) -> dict:
    """One [[bearings]] table in SI: its bearing keys as `bearing.<name>`, checked as a [bearing]
    table's (`convert`, the schema's), and its placement."""
    where = f"bearings[{index}]"
    if "position" not in table:
        raise ValueError(f"{where}: missing required key 'position' (the bearing's centre along the shaft)")
    orientation = table.get("orientation", "+z")
    if orientation not in ORIENTATIONS:
        raise ValueError(f"{where}.orientation: expected \"+z\" or \"-z\", got {orientation!r}")
    entry = {"position": to_si(table["position"], "length", f"{where}.position"),
             "orientation": ORIENTATIONS[orientation],
             "offset": to_si(table.get("offset", 0.0), "length", f"{where}.offset")}
    for name, value in table.items():
        if name in PLACEMENT:
            continue
        keys = ({f"profile.{key}": item for key, item in value.items()} if name == "profile" and isinstance(value, dict)
                else {f"bearing.{name}": value})
        for dotted, item in keys.items():
            try:
                entry[dotted] = convert(dotted, item)
            except ValueError as error:
                raise ValueError(f"{where}: {error}") from None
    if entry.get("bearing.type") not in mountings():
        raise ValueError(f"{where}.type: one of {tuple(mountings())}, got {entry.get('bearing.type')!r}")
    return entry


def _load_entry(index: int, table: dict, convert) -> dict:
    where = f"loads[{index}]"
    unknown = set(table) - {"position", "force", "moment"}
    if unknown:
        raise ValueError(f"{where}: unknown key {sorted(unknown)[0]!r} (a load has position, force, moment)")
    if "position" not in table or "force" not in table and "moment" not in table:
        raise ValueError(f"{where}: give its position and a force = [Fx, Fy, Fz] and/or a moment = [Mx, My]")
    entry = {"position": to_si(table["position"], "length", f"{where}.position")}
    for name, size, dimension in (("force", 3, "force"), ("moment", 2, "moment")):
        value = table.get(name, [0.0] * size)
        if not isinstance(value, list) or len(value) != size:
            raise ValueError(f"{where}.{name}: expected a list of {size} {dimension} values, got {value!r}")
        entry[name] = [to_si(item, dimension, f"{where}.{name}[{i}]") for i, item in enumerate(value)]
    return entry


def _section_entry(index: int, table: dict, convert) -> dict:
    where = f"shaft.sections[{index}]"
    unknown = set(table) - {"from", "to", "outer_diameter", "inner_diameter"}
    if unknown:
        raise ValueError(f"{where}: unknown key {sorted(unknown)[0]!r} (a section has from, to, outer_diameter, "
                         "inner_diameter)")
    missing = [name for name in ("from", "to", "outer_diameter") if name not in table]
    if missing:
        raise ValueError(f"{where}: missing required key {missing[0]!r}")
    return {name: to_si(table.get(name, 0.0), "length", f"{where}.{name}")
            for name in ("from", "to", "outer_diameter", "inner_diameter")}


def _life(support, contacts):
    """ISO/TS 16281 L10r [10⁶ rev] of one bearing from its contacts (`ratings.reference_life`)."""
    return contact_reference_life(contacts, support.contact_ratings(support.dynamic_load_rating(), contacts))


def _moment_ratio(support, force):
    """|M| / ((F_r + F_a) d_m/2) [-] of the load [Fx, Fy, Fz, Mx, My] a bearing carries (0 unloaded)."""
    forces = jnp.hypot(force[0], force[1]) + jnp.abs(force[2])
    moment = jnp.hypot(force[3], force[4])
    return jnp.where(forces > 0.0, moment / (jnp.where(forces > 0.0, forces, 1.0) * support.pitch_radius()), 0.0)


def _basic_life(support, force):
    """ISO 281 L10 = (C_r/P)^p [10⁶ rev] of one bearing from the load it carries, its own X, Y."""
    return ((support.dynamic_load_rating() / support.equivalent_dynamic_load(force[:3]))
            ** life.basic_life_exponent(support.rolling_element()))


FREQUENCIES = ("cage", "ball_pass_outer", "ball_pass_inner", "ball_spin")
# per-element outputs: from every bearing's contacts, and the contact angles of point contacts
ELEMENT_FIELDS = ("azimuth", "inner_load", "outer_load", "inner_max_pressure", "outer_max_pressure")
BALL_ELEMENT_FIELDS = ("inner_contact_angle", "outer_contact_angle")


def _padded(own, count: int):
    """A bearing's per-element values padded with NaN to `count` (NaN throughout for None)."""
    if own is None:
        return jnp.full(count, jnp.nan)
    return jnp.pad(own, (0, count - own.shape[0]), constant_values=jnp.nan)


def _raceway_values(contacts, raceway: str) -> dict:
    """Each element's load, peak pressure and (point contacts) angle at its most loaded contact on
    `raceway` (a bearing with one contact column a raceway: that column's; a double-row bearing's:
    the more loaded row's ball at that azimuth)."""
    columns = contacts.on(raceway)
    if len(columns) == 1:
        pick = lambda values: values[:, columns[0]]
    else:
        chosen = jnp.asarray(columns)[jnp.argmax(contacts.load[:, columns], axis=1)][:, None]
        pick = lambda values: jnp.take_along_axis(values, chosen, axis=1)[:, 0]
    return {f"{raceway}_load": pick(contacts.load), f"{raceway}_max_pressure": pick(contacts.max_pressure),
            f"{raceway}_contact_angle": None if contacts.angle is None else pick(contacts.angle)}


def _element_values(contacts) -> dict:
    """One bearing's per-element outputs from its contacts (`_raceway_values` of each raceway)."""
    return {"azimuth": contacts.azimuth} | _raceway_values(contacts, "inner") | _raceway_values(contacts, "outer")


def _elements(per_bearing) -> dict:
    """`bearings.elements.*`: each bearing's per-element results (bearings × the most elements), NaN
    beyond a bearing's own element count and for the contact angles of a line-contact bearing."""
    values = [_element_values(contacts) for contacts in per_bearing]
    count = max(contacts.azimuth.shape[0] for contacts in per_bearing)
    return {f"bearings.elements.{field}": jnp.stack([_padded(own[field], count) for own in values])
            for field in ELEMENT_FIELDS + BALL_ELEMENT_FIELDS}


def _shoulders(layout: ShaftLayout, shaft: Shaft, solution, per_bearing) -> dict:
    """Where some ball bearing's entry gives its shoulder diameters: each bearing's largest angle
    past a shoulder edge (`bearings.shoulder_overrun`, −π/2 for one without) and each element's
    share of its load beyond the edge (`bearings.elements.*_shoulder_share`, NaN without), from
    the type's `Mounting.shoulder_outputs`."""
    if all(depths is None for depths in layout.shoulders):
        return {}
    count = max(contacts.azimuth.shape[0] for contacts in per_bearing)
    overrun, shares = [], {"inner": [], "outer": []}
    for kind, support, local, state, own, depths in zip(layout.kinds, shaft.supports, solution.bearing_displacements,
                                                        solution.elements, solution.constants, layout.shoulders):
        found = ({} if depths is None else
                 mountings()[kind].shoulder_outputs(support, local, layout.speed, state, own, depths))
        overrun.append(found.get("validity.shoulder_overrun", jnp.asarray(-0.5 * jnp.pi)))
        for side in shares:
            shares[side].append(_padded(found.get(f"balls.{side}.shoulder_share"), count))
    return {"bearings.shoulder_overrun": jnp.stack(overrun)} | {
        f"bearings.elements.{side}_shoulder_share": jnp.stack(share) for side, share in shares.items()}


def _solve(layout: ShaftLayout, shaft: Shaft, stiffness: bool) -> dict:
    """The rigid or flexible shaft's equilibrium: {solution, nodes, deflection, displacement at the
    reference point, and its stiffness there (where asked)}."""
    if layout.sections is None:
        solution = solve_shaft(shaft)
        nodes = jnp.sort(jnp.concatenate([jnp.asarray(layout.positions), jnp.asarray(layout.loads.positions),
                                          jnp.reshape(layout.stiffness_at, (1,))]))
        out = {"solution": solution, "shaft.nodes": nodes,
               "shaft.deflection": jax.vmap(transfer)(nodes) @ solution.displacement,
               "shaft.displacement": transfer(layout.stiffness_at) @ solution.displacement}
        if stiffness:
            out["shaft.stiffness"] = shaft_stiffness(solution.displacement, shaft, layout.stiffness_at,
                                                     solution.elements, solution.constants)
        return out
    flexible = FlexibleShaft(shaft, layout.sections, layout.stiffness_at, layout.mesh)
    solution = solve_flexible_shaft(flexible)
    out = {"solution": solution, "shaft.nodes": solution.nodes, "shaft.deflection": solution.node_displacements,
           "shaft.displacement": solution.displacement}
    if stiffness:
        out["shaft.stiffness"] = flexible_shaft_stiffness(solution, flexible)
    return out


def _shaft(inputs: dict, settings: dict, results: dict) -> dict:
    layout = inputs["shaft"]
    shaft = Shaft(layout_supports(layout, settings), layout.loads, layout.speed)
    solved = _solve(layout, shaft, settings["effects"].get("stiffness", False) is True)
    solution = solved.pop("solution")
    per_bearing = [support.contacts(local, layout.speed, own, state) for support, local, state, own
                   in zip(shaft.supports, solution.bearing_displacements, solution.elements, solution.constants)]
    out = solved | {
        "shaft.converged": solution.converged,
        "shaft.residual": solution.residual,
        "bearings.displacement": jnp.stack(solution.bearing_displacements),
        "bearings.force": jnp.stack(solution.bearing_forces),
        # the load each bearing takes from the shaft, in the shaft's frame at the bearing
        "bearings.reaction": jnp.stack([turned(support) * force
                                        for support, force in zip(shaft.supports, solution.bearing_forces)]),
        "bearings.max_element_load": jnp.stack([jnp.max(contacts.load[:, contacts.on("inner")])
                                                for contacts in per_bearing]),
        "bearings.max_pressure": jnp.stack([jnp.max(contacts.max_pressure) for contacts in per_bearing]),
        "bearings.pressure_safety": jnp.stack([support.pressure_safety(jnp.max(contacts.max_pressure))
                                               for support, contacts in zip(shaft.supports, per_bearing)]),
        "bearings.end_lamina_share": jax.lax.stop_gradient(jnp.stack([end_lamina_share(contacts)
                                                                      for contacts in per_bearing])),
        "bearings.validity": jax.lax.stop_gradient(jnp.stack([support.envelope(contacts) for support, contacts
                                                              in zip(shaft.supports, per_bearing)])),
        "bearings.permissible_misalignment": jnp.stack([jnp.asarray(support.permissible_misalignment())
                                                        for support in shaft.supports]),
        "bearings.moment_ratio": jnp.stack([_moment_ratio(support, force)
                                            for support, force in zip(shaft.supports, solution.bearing_forces)]),
    } | _elements(per_bearing) | _shoulders(layout, shaft, solution, per_bearing)
    if settings["effects"].get("life", False) is True:
        lives = [_life(support, contacts) for support, contacts in zip(shaft.supports, per_bearing)]
        out["bearings.L10r"] = jnp.stack(lives)
        out["bearings.L10"] = jnp.stack([_basic_life(support, force) for support, force
                                         in zip(shaft.supports, solution.bearing_forces)])
        out["shaft.L10r"] = life.system_life(jnp.stack(lives))
    if settings["effects"].get("frequencies", False) is True:
        found = [support.frequencies(layout.speed, contacts) for support, contacts in zip(shaft.supports, per_bearing)]
        out |= {f"bearings.frequencies.{field}": jnp.stack([getattr(f, field) for f in found]) for field in FREQUENCIES}
    return out


def end_lamina_share(contacts):
    """The largest load of a roller's end lamina (either end, any contact) over the largest lamina
    load of the bearing [-]: above 0 a line contact reaches the end of its roller, where the real
    pressure has an edge peak that laminae, each a Hertz line contact, do not show (0 for point
    contacts and for a bearing without load)."""
    if contacts.kind != "line":
        return jnp.asarray(0.0)
    laminae = contacts.lamina_load
    largest = jnp.max(laminae)
    ends = jnp.maximum(jnp.max(laminae[..., 0]), jnp.max(laminae[..., -1]))
    return jnp.where(largest > 0.0, ends / jnp.where(largest > 0.0, largest, 1.0), 0.0)


def edge_load_warnings(shares) -> list[str]:
    """A warning for each bearing whose rollers' end laminae carry load (`end_lamina_share`)."""
    return [f"bearing {number}: a roller's end lamina carries {share:.0%} of the most loaded lamina's load — its "
            "contact reaches the roller's end, where the pressure has an edge peak the laminae do not show (and "
            "ISO/TS 16281's lamina life leaves out): a deeper crown or a smaller tilt keeps the ends free"
            for number, share in enumerate(np.asarray(shares)) if share > 0.0]


def misalignment_warnings(displacements, limits) -> list[str]:
    """A warning for each bearing whose inner ring tilts against its outer ring by more than its
    `limits` [rad] (`AbstractSupport.permissible_misalignment`; `displacements` (bearings, 5):
    [x, y, z, θx, θy] [m, rad]) — a shaft on one bearing, or one bending steeply at it, which the
    catalogues do not allow."""
    tilts = np.hypot(np.asarray(displacements)[:, 3], np.asarray(displacements)[:, 4])
    return [f"bearing {number}: its rings tilt {tilt * 1e3:.3g} mrad ({np.degrees(tilt) * 60:.3g}′) against each other, "
            f"beyond the {np.degrees(limit) * 60:.0f}′ the bearing permits (a shaft held by one bearing pivots on it: "
            "add a second bearing, or check the layout)"
            for number, (tilt, limit) in enumerate(zip(tilts, np.asarray(limits))) if tilt > limit]


def pressure_warnings(pressures, safeties) -> list[str]:
    """A warning for each bearing whose peak contact pressure [Pa] passes ISO 76's permissible pressure
    of its type (4 200 MPa balls, 4 600 self-aligning balls, 4 000 rollers): its pressure safety
    `AbstractSupport.pressure_safety` below 1."""
    return [f"bearing {number}: peak contact pressure {pressure / 1e9:.3g} GPa exceeds ISO 76's permissible pressure "
            f"of its type (s(p) = {safety:.3g} < 1)"
            for number, (pressure, safety) in enumerate(zip(np.asarray(pressures), np.asarray(safeties))) if safety < 1.0]


def _checks(values: dict) -> tuple[list[str], list[str]]:
    errors = [line for number, (approach, angle, lowest) in enumerate(np.asarray(values["bearings.validity"]))
              for line in validity_errors(approach, angle, f"bearing {number}", lowest)]
    if not errors and not bool(values["shaft.converged"]):
        errors.append(f"shaft equilibrium did not converge: largest scaled residual {float(values['shaft.residual']):.1e} "
                      f"(tolerance {RESIDUAL_TOLERANCE:g})")
    warnings = pressure_warnings(values["bearings.max_pressure"], values["bearings.pressure_safety"])
    warnings += misalignment_warnings(values["bearings.displacement"], values["bearings.permissible_misalignment"])
    warnings += edge_load_warnings(values["bearings.end_lamina_share"])
    if "bearings.L10" in values:
        warnings += moment_warnings(values, "L10", "ISO 281's P", "L10r, from its contacts,")
    for number, overrun in enumerate(np.asarray(values.get("bearings.shoulder_overrun", []))):
        shares = {f"balls.{side}.shoulder_share": np.nan_to_num(values[f"bearings.elements.{side}_shoulder_share"][number])
                  for side in ("inner", "outer")}
        shoulder_errors, shoulder_warnings = shoulder_checks({"validity.shoulder_overrun": overrun, **shares},
                                                             f"bearing {number}")
        errors += shoulder_errors
        warnings += shoulder_warnings
    return errors, warnings


def _plot(result, figure):
    """The shaft's radial displacement along its length, the bearings' reactions and their element loads."""
    values, layout = result.values, result.model.inputs["shaft"]
    positions = np.asarray(layout.positions)
    nodes, moved = np.asarray(values["shaft.nodes"]), np.asarray(values["shaft.deflection"])
    line, bars, elements = figure.subplots(1, 3)
    line.plot(nodes * 1e3, moved[:, 0] * 1e6, ".-" if layout.sections is not None else "-", label="x")
    line.plot(nodes * 1e3, moved[:, 1] * 1e6, ".-" if layout.sections is not None else "-", label="y")
    for z in positions:
        line.axvline(z * 1e3, color="0.6", lw=0.8)
    line.set(xlabel="position along the shaft [mm]", ylabel="radial displacement [µm]",
             title="shaft (rigid)" if layout.sections is None else "shaft (Timoshenko beam)")
    reaction = np.asarray(values["bearings.reaction"])
    numbers = np.arange(len(positions))
    bars.bar(numbers - 0.2, np.hypot(reaction[:, 0], reaction[:, 1]) / 1e3, 0.4, label="radial")
    bars.bar(numbers + 0.2, np.abs(reaction[:, 2]) / 1e3, 0.4, label="axial")
    bars.set(xlabel="bearing", ylabel="load [kN]", title="bearing loads", xticks=numbers)
    azimuths, loads = (np.asarray(values[f"bearings.elements.{field}"]) for field in ("azimuth", "inner_load"))
    for number, (azimuth, load) in enumerate(zip(azimuths, loads)):
        held = np.isfinite(azimuth)
        elements.plot(np.degrees(azimuth[held]), load[held] / 1e3, "o-", label=f"bearing {number}")
    elements.set(xlabel="azimuth ψ in the bearing's frame [°]", ylabel="element load, inner raceway [kN]",
                 title="element loads")
    for axis in (line, bars, elements):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.suptitle(result.model.scene.title)


BLOCK = Block(
    name="shaft",
    bearing_types=SHAFT,
    enabled_by=None,
    requires=(),
    inputs=("shaft",),
    uses=("centrifugal", "gyroscopic", "stiffness", "life", "frequencies"),
    outputs=(
        Output("shaft.displacement", "m, rad", "", "shaft displacement at shaft.stiffness_at (default z = 0) "
               "[ux, uy, uz, θx, θy]", in_report=False),
        Output("shaft.nodes", "m", "mm", "z of the shaft's nodes: the mesh of a flexible shaft; a rigid one's bearings, "
               "loads and reference point, in order", in_report=False),
        Output("shaft.deflection", "m, rad", "", "each node's displacement [ux, uy, uz, θx, θy]", in_report=False),
        Output("shaft.converged", "", "", "the shaft equilibrium converged", in_report=False),
        Output("shaft.residual", "", "", "largest scaled residual of the shaft equilibrium", in_report=False),
        Output("shaft.stiffness", "N/m, N/rad, N*m/m, N*m/rad", "", "5×5 system stiffness at shaft.stiffness_at (exact)",
               effect="stiffness", in_report=False),
        Output("shaft.L10r", "1e6 rev", "1e6 rev", "reference rating life of the shaft's bearings together, "
               "(Σ L10r^(−10/9))^(−9/10)", effect="life"),
        Output("bearings.displacement", "m, rad", "", "each bearing's inner-ring displacement in its own frame",
               in_report=False),
        Output("bearings.force", "N, N*m", "", "each bearing's load in its own frame [Fx, Fy, Fz, Mx, My]",
               in_report=False),
        Output("bearings.reaction", "N, N*m", "", "each bearing's load from the shaft, shaft frame, at the bearing",
               in_report=False),
        Output("bearings.max_element_load", "N", "kN", "each bearing's largest ball or roller load (inner contact)",
               in_report=False),
        Output("bearings.max_pressure", "Pa", "GPa", "each bearing's peak Hertz pressure (rollers: of their laminae)",
               in_report=False),
        Output("bearings.pressure_safety", "", "", "each bearing's peak pressure against ISO 76's permissible pressure "
               "of its type, as a load ratio s(p)", in_report=False),
        Output("bearings.end_lamina_share", "", "", "each bearing's largest end-lamina load over its largest lamina "
               "load (line contacts; above 0 a contact reaches its roller's end: edge stress)", in_report=False),
        Output("bearings.validity", "-, rad, rad", "",
               "each bearing's largest approach / Dw (a roller bearing's / its mean roller diameter), largest "
               "|contact angle| and lowest loaded contact angle of an angular-contact bearing (model limits 1 %, "
               "90°, 0)", in_report=False),
        Output("bearings.moment_ratio", "", "", "each bearing's tilting moment over (F_r + F_a)·dm/2 (ISO 281's P and "
               "ISO 76's P0 leave it out)", in_report=False),
        Output("bearings.permissible_misalignment", "rad", "deg", "each bearing's largest tilt of its rings "
               "the catalogues permit (10′ a rigid bearing, 2.5° a self-aligning one)", in_report=False),
        Output("bearings.elements.azimuth", "rad", "deg", "each bearing's element azimuths ψ in its own frame "
               "(NaN beyond its element count)", in_report=False),
        *(output for side in ("inner", "outer") for output in (
            Output(f"bearings.elements.{side}_load", "N", "kN", f"each bearing's element loads, {side} raceway",
                   in_report=False),
            Output(f"bearings.elements.{side}_max_pressure", "Pa", "GPa", f"each bearing's element peak pressures, "
                   f"{side} raceway", in_report=False),
            Output(f"bearings.elements.{side}_contact_angle", "rad", "deg", f"each ball bearing's {side} contact "
                   "angles (NaN for a roller bearing)", in_report=False))),
        Output("bearings.shoulder_overrun", "rad", "deg", "each bearing's largest angle by which a loaded contact's "
               "centre lies past its shoulder edge (ball bearings whose entry gives the shoulder diameters; −90° "
               "without; model limit 0)", in_report=False),
        *(Output(f"bearings.elements.{side}_shoulder_share", "", "", f"each ball's share of its {side} contact load "
                 "beyond the shoulder edge (NaN for a bearing without shoulder diameters)", in_report=False)
          for side in ("inner", "outer")),
        Output("bearings.L10", "1e6 rev", "1e6 rev", "each bearing's ISO 281 basic rating life (C_r/P)^p, P = X F_r "
               "+ Y F_a with its type's X, Y, from the load it carries", effect="life", in_report=False),
        Output("bearings.L10r", "1e6 rev", "1e6 rev", "each bearing's ISO/TS 16281 L10r", effect="life",
               in_report=False),
        *(Output(f"bearings.frequencies.{field}", "Hz", "Hz", f"each bearing's {text} at its solved contact angles",
                 effect="frequencies", in_report=False)
          for field, text in zip(FREQUENCIES, ("cage frequency FTF", "ball (roller) pass frequency, outer raceway",
                                               "ball (roller) pass frequency, inner raceway",
                                               "ball (roller) spin frequency"))),
    ),
    compute=_shaft,
    checks=_checks,
    plot=_plot,
    validate=check_dynamic_ratings,
)


def _header(result) -> list[str]:
    scene, layout = result.model.scene, result.model.inputs["shaft"]
    if layout.sections is None:
        kind = "rigid"
    else:
        sections = layout.sections
        kind = (f"Timoshenko beam of {np.shape(sections.starts)[0]} sections from "
                f"{float(np.min(sections.starts)) * 1e3:.1f} to {float(np.max(sections.ends)) * 1e3:.1f} mm, "
                f"{sections.material.name} (E {float(sections.material.elastic_modulus) / 1e9:.0f} GPa), "
                f"{layout.mesh.node_count} nodes")
    lines = [scene.title, f"scene: {scene.source}", "",
             f"Shaft      {kind}, {len(layout.bearings)} bearings, {float(layout.speed) * 30 / np.pi:.1f} r/min"]
    for number, (kind, bearing, z, orientation) in enumerate(zip(layout.kinds, layout.bearings,
                                                                np.asarray(layout.positions), layout.orientations)):
        where = f"  bearing {number}: at z = {z * 1e3:.2f} mm ({'+z' if orientation > 0 else '−z'}), "
        lines.append(where + mountings()[kind].describe(bearing))
    loads = layout.loads
    for number, (z, force, moment) in enumerate(zip(np.asarray(loads.positions), np.asarray(loads.forces),
                                                    np.asarray(loads.moments))):
        lines.append(f"  load {number}: z = {z * 1e3:.2f} mm, F = [{', '.join(f'{f / 1e3:.3f}' for f in force)}] kN, "
                     f"M = [{', '.join(f'{m:.1f}' for m in moment)}] N·m")
    return lines


def _report(result) -> list[str]:
    values = result.values
    u = np.asarray(values["shaft.displacement"])
    lines = ["", f"Shaft at z = {float(result.model.inputs['shaft'].stiffness_at) * 1e3:.2f} mm",
             f"  ux = {u[0] * 1e6:.3f} µm, uy = {u[1] * 1e6:.3f} µm, uz = {u[2] * 1e6:.3f} µm, "
             f"θx = {u[3] * 1e3:.4f} mrad, θy = {u[4] * 1e3:.4f} mrad",
             "", "Bearings (loads from the shaft, shaft frame; Qmax the largest ball or roller load)",
             f"  {'#':<4}{'Fx [kN]':>10}{'Fy [kN]':>10}{'Fz [kN]':>10}{'Mx [N·m]':>10}{'My [N·m]':>10}{'Qmax [kN]':>11}"
             f"{'p0 [GPa]':>10}" + (f"{'L10 [1e6 rev]':>15}{'L10r [1e6 rev]':>16}" if "bearings.L10r" in values else "")
             + (f"{'s0':>8}{'s(p)':>8}" if "bearings.iso76" in values else "")
             + (f"{'M [N·mm]':>10}" if "bearings.friction.torque" in values else "")]
    for number, reaction in enumerate(np.asarray(values["bearings.reaction"])):
        row = (f"  {number:<4}" + "".join(f"{f / 1e3:>10.4f}" for f in reaction[:3])
               + "".join(f"{m:>10.2f}" for m in reaction[3:])
               + f"{float(values['bearings.max_element_load'][number]) / 1e3:>11.4f}"
               + f"{float(values['bearings.max_pressure'][number]) / 1e9:>10.4f}")
        if "bearings.L10r" in values:
            row += f"{format_number(values['bearings.L10'][number]):>15}{format_number(values['bearings.L10r'][number]):>16}"
        if "bearings.iso76" in values:
            row += "".join(f"{format_number(values[key][number]):>8}" for key in ("bearings.iso76",
                                                                                  "bearings.static_safety"))
        if "bearings.friction.torque" in values:
            row += f"{float(values['bearings.friction.torque'][number]) * 1e3:>10.2f}"
        lines.append(row)
    if result.model.inputs["shaft"].sections is not None:
        nodes, moved = np.asarray(values["shaft.nodes"]), np.asarray(values["shaft.deflection"])
        radial = np.hypot(moved[:, 0], moved[:, 1])
        lines.append(f"  largest radial deflection {radial.max() * 1e6:.3f} µm at z = {nodes[radial.argmax()] * 1e3:.2f} mm "
                     f"(bearings and shaft bending together)")
    lines += ["", "Element loads at the inner raceway [kN], from azimuth ψ = 0 in each bearing's frame"]
    for number, loads in enumerate(np.asarray(values["bearings.elements.inner_load"])):
        lines.append(f"  {number:<4}" + " ".join(f"{load / 1e3:.3f}" for load in loads[np.isfinite(loads)]))
    if "bearings.frequencies.cage" in values:
        lines += ["", "Overrolling frequencies at the solved contact angles [Hz]",
                  f"  {'#':<4}{'cage FTF':>12}{'BPFO':>12}{'BPFI':>12}{'BSF':>12}"]
        lines += [f"  {number:<4}" + "".join(f"{float(values[f'bearings.frequencies.{field}'][number]):>12.4f}"
                                             for field in FREQUENCIES) for number in range(len(values["bearings.reaction"]))]
    if "shaft.stiffness" in values:
        at = float(result.model.inputs["shaft"].stiffness_at)
        lines += ["", f"System stiffness at the shaft point z = {at * 1e3:.2f} mm"]
        lines += stiffness_lines(values["shaft.stiffness"], "the balls of every bearing")[1:]
    state = "converged" if bool(values["shaft.converged"]) else "DID NOT CONVERGE"
    return lines + ["", f"Shaft equilibrium: {state} (largest scaled residual {float(values['shaft.residual']):.1e})"]


ADAPTER = register(Adapter(
    name="shaft",
    bearing_types=SHAFT,
    keys={
        "bearings": Key("tables", doc="[[bearings]]: a [bearing] table's keys (and a roller bearing's profile "
                                      "sub-table) plus position, orientation (\"+z\" or \"-z\") and offset (an axial "
                                      "preload push)",
                        entry=_bearing_entry),
        "loads": Key("tables", doc="[[loads]]: position, force = [Fx, Fy, Fz], moment = [Mx, My] on the shaft",
                     entry=_load_entry),
        "shaft.speed": quantity("angular_speed", "the shaft's (inner rings') speed; the outer rings stand still"),
        "shaft.stiffness_at": quantity("length", "the shaft point of the system stiffness and of shaft.displacement "
                                                 "(default z = 0)"),
        "shaft.sections": Key("tables", doc="[[shaft.sections]]: from, to, outer_diameter, inner_diameter (default 0, "
                                            "solid) of each section of a flexible shaft (Timoshenko beam); without "
                                            "them the shaft is rigid", entry=_section_entry),
        "shaft.material": Key("choice", choices=tuple(SEAT_MATERIALS), doc="the flexible shaft's material (default "
                                                                           "steel: E 207 GPa, ν 0.292)"),
        "shaft.element_length": quantity("length", "the flexible shaft's longest beam element (default its length / 40; "
                                                   "the values at bearings and loads do not depend on it)"),
        "effects.centrifugal": Key("boolean"),
        "effects.gyroscopic": Key("boolean"),
        "effects.stiffness": Key("boolean"),
        "effects.life": Key("boolean"),
        "effects.frequencies": Key("boolean", doc="each bearing's overrolling frequencies"),
        **FIDELITY,
    },
    required={"shaft": ("bearings", "loads")},
    # with effects.mounting or effects.thermal, their adapters build the layout (the bearings as mounted)
    inputs=(InputBuilder(("shaft",), SHAFT, shaft_layout, scene_keys=("!effects.mounting", "!effects.thermal")),),
    blocks=(BLOCK,),
    header=_header,
    report=_report,
))
