"""Overrolling frequencies (effect `frequencies`): cage, ball or roller pass over the outer and inner
raceways and element spin at the operating contact angles (`diffbearing.overrolling`), in Hz and per
revolution; for ball bearings beside the textbook values at the nominal contact angle (0 for a deep-groove
bearing, the free contact angle α0 for an angular-contact one)."""

import functools

from .... import overrolling
from ....bearings.roller.roller_geometry import ROLLER_KINDS
from ....params import BALL_BEARING_KINDS
from ...registry import Adapter, Block, Key, Output, register
from ..bearings.ball import ball_model
from ..systems.bearing_set import SET, SET_SIZE
from ..bearings.roller_bearing import WHOLE_BEARING

# (output field, report label, description); "ball" reads "roller" for a roller bearing (`_fields`)
FIELDS = (("cage", "cage FTF", "cage (fundamental train) frequency FTF"),
          ("ball_pass_outer", "ball pass, outer raceway BPFO", "ball pass frequency, outer raceway BPFO"),
          ("ball_pass_inner", "ball pass, inner raceway BPFI", "ball pass frequency, inner raceway BPFI"),
          ("ball_spin", "ball spin BSF", "ball spin frequency BSF, rolling relative to the cage"))


def _fields(element: str) -> tuple:
    """FIELDS with the labels and descriptions naming the rolling `element` ("ball", "roller"); the
    output keys stay those of FIELDS for every bearing type."""
    return tuple((field, label.replace("ball", element), text.replace("ball", element)) for field, label, text in FIELDS)


def _keyed(frequencies: overrolling.OverrollingFrequencies, prefix: str) -> dict:
    return {f"{prefix}.{field}": getattr(frequencies, field) for field, _, _ in FIELDS}


def _with_orders(at_speeds, operating) -> dict:
    """The frequencies at the operating speeds and their orders (`overrolling.per_revolution`)."""
    return (_keyed(at_speeds(operating.inner_speed, operating.outer_speed), "frequencies")
            | _keyed(overrolling.per_revolution(at_speeds, operating.inner_speed, operating.outer_speed),
                     "frequencies.orders"))


def _ball_frequencies(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, operating = inputs["bearing"], inputs["operating"]
    at_speeds = functools.partial(overrolling.frequencies_of_balls, bearing,
                                  contact_angle_inner=results["balls.inner.contact_angle"],
                                  contact_angle_outer=results["balls.outer.contact_angle"],
                                  inner_load=results["balls.inner.load"], race_control=ball_model(settings).race_control)
    nominal = overrolling.nominal_frequencies(operating.inner_speed, operating.outer_speed, bearing.ball_count,
                                              bearing.ball_diameter, bearing.pitch_diameter,
                                              bearing.nominal_contact_angle)
    return _with_orders(at_speeds, operating) | _keyed(nominal, "frequencies.nominal")


def _roller_frequencies(inputs: dict, settings: dict, results: dict) -> dict:
    return _with_orders(functools.partial(overrolling.frequencies_of_rollers, inputs["bearing"], inputs["raceways"]),
                        inputs["operating"])


def _set_frequencies(inputs: dict, settings: dict, results: dict) -> dict:
    bearing, operating = inputs["bearing"], inputs["operating"]
    out = {}
    for number in range(SET_SIZE):
        prefix = f"set.bearings.{number}."
        found = overrolling.frequencies_of_balls(bearing, operating.inner_speed, operating.outer_speed,
                                                 results[prefix + "balls.inner.contact_angle"],
                                                 results[prefix + "balls.outer.contact_angle"],
                                                 results[prefix + "balls.inner.load"], ball_model(settings).race_control)
        out |= _keyed(found, prefix + "frequencies")
    return out


def _outputs(nominal: bool, element: str) -> tuple[Output, ...]:
    fields = _fields(element)
    outputs = [Output(f"frequencies.{field}", "Hz", "Hz", text, in_report=False) for field, _, text in fields]
    outputs += [Output(f"frequencies.orders.{field}", "", "", f"{text}, per revolution of the inner ring relative "
                                                                "to the outer", in_report=False) for field, _, text in fields]
    if nominal:
        outputs += [Output(f"frequencies.nominal.{field}", "Hz", "Hz", f"{text}, textbook closed form at the "
                                                                        "nominal angle (deep groove 0, else α0)", in_report=False)
                    for field, _, text in fields]
    return tuple(outputs)


def _report(result) -> list[str]:
    values = result.values
    if "frequencies.cage" not in values:  # a set: its bearings' frequencies are in the output table
        return []
    nominal = "frequencies.nominal.cage" in values
    element = "roller" if any(block.name == "roller_frequencies" for block in result.model.blocks) else "ball"
    title = "Overrolling frequencies at the operating contact angles"
    if nominal:
        angle = "0°" if result.model.inputs["bearing"].radial_contact else "the free contact angle α0"
        title += f" (nominal: textbook, at {angle})"
    lines = ["", title, f"  {'':<40}{'[Hz]':>12}{'[per rev]':>12}"
             + (f"{'nominal [Hz]':>14}{'difference':>12}" if nominal else "")]
    for field, label, _ in _fields(element):
        value, order = float(values[f"frequencies.{field}"]), float(values[f"frequencies.orders.{field}"])
        line = f"  {label:<40}{value:>12.4f}{order:>12.5f}"
        if nominal:
            reference = float(values[f"frequencies.nominal.{field}"])
            difference = f"{(value - reference) / reference * 100:+.3f} %" if reference else "–"
            line += f"{reference:>14.4f}{difference:>12}"
        lines.append(line)
    return lines


ADAPTER = register(Adapter(
    name="frequencies",
    bearing_types=BALL_BEARING_KINDS + ROLLER_KINDS,
    keys={"effects.frequencies": Key("boolean", doc="overrolling frequencies FTF, BPFO, BPFI, BSF")},
    blocks=(Block(
        name="frequencies",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("frequencies", True),
        requires=("equilibrium",),
        inputs=("bearing", "operating"),
        outputs=_outputs(nominal=True, element="ball"),
        compute=_ball_frequencies,
    ), Block(
        name="roller_frequencies",
        bearing_types=ROLLER_KINDS,
        enabled_by=("frequencies", True),
        requires=(),
        inputs=("bearing", "raceways", "operating"),
        outputs=_outputs(nominal=False, element="roller"),
        compute=_roller_frequencies,
        scene_keys=WHOLE_BEARING,
    ), Block(
        name="set_frequencies",
        bearing_types=BALL_BEARING_KINDS,
        enabled_by=("frequencies", True),
        requires=("bearing_set",),
        inputs=("bearing", "operating"),
        outputs=tuple(Output(f"set.bearings.{number}.frequencies.{field}", "Hz", "Hz", f"bearing {number}: {label}")
                      for number in range(SET_SIZE) for field, label, _ in FIELDS),
        compute=_set_frequencies,
        scene_keys=SET,
    )),
    report=_report,
))
