"""A scene assembled into a model: the blocks its effects name, the input pytrees they read.

`build_model(scene)` → `Model`; `run_model(model)` compiles and runs it, timing both (a scene
with a [sweep] table runs as one batch, see sweep.py). Every scene key must be read by what the
scene runs: a key no block reads is refused (ValueError naming it), never silently ignored; a
fidelity setting that only another level of the same effect reads (a grid kept while the film
level is switched by --set) is reported as a warning.
"""

import dataclasses
import sys
import time

import jax
import numpy as np

from . import registry
from .compilation_cache import use_compilation_cache
from .adapters.designation import SCENE_LAYER_KEYS
from .registry import Reads
from .result import RunResult
from .scene import Scene
from .duty_cycle import LOAD_KEY, DutyCycle, case_values, cycle_values, duty_cycle_of, place
from .sweep import check_corners, run_points, run_sweep, sweep_axes

# keys every scene may hold that no input builder reads: the report's title, the bearing type that
# selects the adapters, the designation the scene layer reads (app/scene.py), and the effects and
# fidelity tables (checked by `resolve` and `read_by`)
_SETTINGS = ("title", "bearing.type", *SCENE_LAYER_KEYS)


def build_inputs(bearing_type: str, blocks, values) -> dict:
    """{input name: parameter pytree} the blocks read, built from the scene's SI values (a dict
    or a `Reads`; values may be JAX tracers in a sweep). ValueError names a bad value."""
    needed = dict.fromkeys(name for block in blocks for name in block.inputs)
    inputs: dict = {}
    for builder in registry.input_builders(bearing_type, needed, present=set(values)):
        inputs |= builder.build(values, inputs)
    return inputs


@dataclasses.dataclass
class Model:
    """A scene assembled: its inputs pytree and the blocks to run, in order."""

    scene: Scene
    inputs: dict
    blocks: list
    settings: dict
    not_implemented: list
    sweep_axes: dict = dataclasses.field(default_factory=dict)  # {dotted key: SI values} of a [sweep] table
    idle_settings: list = dataclasses.field(default_factory=list)  # fidelity keys only another level reads
    switched_off: list = dataclasses.field(default_factory=list)  # keys left unread by an effect an override changed
    duty: DutyCycle | None = None  # the load cases of a [[duty]] array

    @property
    def outputs(self) -> dict:
        return registry.outputs_of(self.blocks, self.settings["effects"])

    def function(self):
        """The pure function inputs → {output key: array} (jit, vmap and grad it freely)."""
        return registry.evaluate(self.blocks, self.settings)

    def inputs_from_values(self, values: dict) -> dict:
        """The inputs pytree of this model's blocks from {dotted key: SI value} (a sweep's point)."""
        return build_inputs(self.scene.bearing_type, self.blocks, values)


def _unread(scene: Scene, blocks, asked: set, axes: dict) -> tuple[list[str], list[str]]:
    """(scene and swept keys that nothing the scene runs reads, fidelity keys that only a block of
    another effect level of this bearing type and layout reads: a setting kept for when the level
    changes)."""
    keys = registry.all_keys()
    running = {block.name for block in blocks}
    of_type = {block.name for block in registry.selectable(scene.bearing_type, scene.values)}
    unread, idle = [], []
    for key in dict.fromkeys(list(scene.values) + list(axes)):
        if key in _SETTINGS or key.startswith("effects.") or key in scene.derived:
            continue
        if key.startswith("fidelity."):
            readers = set(keys[key].read_by)
            if not running & readers:
                (idle if of_type & readers else unread).append(key)
        elif key not in asked:
            unread.append(key)
    return unread, idle


def _duty(scene: Scene, blocks) -> DutyCycle | None:
    """The scene's duty cycle, every case's parameters checked (ValueError naming `duty[i]`)."""
    if scene.duty is None:
        return None
    if scene.sweep:
        raise ValueError("duty: a scene runs a [sweep] or a [[duty]] cycle, not both")
    duty = duty_cycle_of(scene.duty, scene.values)
    for number in range(duty.count):
        try:
            build_inputs(scene.bearing_type, blocks, case_values(duty, scene.values, number))
        except ValueError as error:
            raise ValueError(f"duty[{number}]: {error}") from None
    return duty


def build_model(scene: Scene) -> Model:
    """Assemble the model of a scene: only the blocks its effects name (and what they require),
    and the inputs those blocks read. ValueError for bad values, settings or unread keys.

    The persistent compilation cache is switched on first (`use_compilation_cache`): the input
    builders' array operations (fits and temperatures, a cage's geometry) compile too, and a later
    process loads them."""
    use_compilation_cache()
    if not registry.selectable(scene.bearing_type, scene.values) and scene.bearing_type in registry.mountings():
        raise ValueError(f"bearing.type: a {scene.bearing_type} bearing is modelled on a shaft only: give it as a "
                         "[[bearings]] entry (with its position) and its load as a [[loads]] entry")
    registry.check_refused(scene.bearing_type, scene.values)
    blocks, missing = registry.resolve(scene.bearing_type, scene.table("effects"), present=scene.values)
    values = Reads(scene.values)
    inputs = build_inputs(scene.bearing_type, blocks, values)
    axes = sweep_axes(scene.sweep) if scene.sweep else {}  # bad entries fail here, before compiling
    if axes:  # and parameters out of range at a corner of the grid
        check_corners(scene.values, axes, lambda point: build_inputs(scene.bearing_type, blocks, point))
    duty = _duty(scene, blocks)
    settings = {"effects": scene.table("effects"), "fidelity": scene.table("fidelity")}
    for block in blocks:
        if block.validate is not None:
            block.validate(settings, inputs)  # bad grid or tolerance fails here, before compiling
    set_by_cases = {key: None for key in (duty.cases if duty else {}) if not LOAD_KEY.fullmatch(key)}  # loads[k]: "loads"
    unread, idle = _unread(scene, blocks, values.asked, axes | set_by_cases)
    switched_off = unread if scene.switched else []  # the file's keys of an effect --set turned off: a warning
    unread = [] if scene.switched else unread
    if unread:
        effects = ", ".join(f"{k} = {v!r}" for k, v in settings["effects"].items()) or "none"
        raise ValueError(f"scene key{'s' if len(unread) > 1 else ''} {', '.join(repr(k) for k in unread)} "
                         f"not read by anything this scene runs (effects: {effects}); remove "
                         f"{'them' if len(unread) > 1 else 'it'} or switch on the effect that reads "
                         f"{'them' if len(unread) > 1 else 'it'}")
    return Model(scene=scene, inputs=inputs, blocks=blocks, settings=settings, not_implemented=missing,
                 sweep_axes=axes, idle_settings=idle, switched_off=switched_off, duty=duty)


def run_model(model: Model, progress: bool = True) -> RunResult:
    """Compile (timed; reused when cached), then run (timed, excluding compilation) the model;
    a scene with a [sweep] table runs as one vmapped batch (see sweep.py). With `progress`, on a
    terminal, each compilation is announced on stderr (`registry.compiled`), a sweep's chunks counted."""
    if model.sweep_axes:
        return run_sweep(model, model.sweep_axes, progress=progress)
    if model.duty is not None:
        return _run_duty(model, progress)
    start = time.perf_counter()
    executable, cached = registry.compiled(model.blocks, model.settings, model.inputs,
                                           progress=progress and sys.stderr.isatty())
    compile_s = 0.0 if cached else time.perf_counter() - start
    start = time.perf_counter()
    values = jax.block_until_ready(executable(model.inputs))
    run_s = time.perf_counter() - start
    return RunResult(model, {key: np.asarray(value) for key, value in values.items()}, compile_s, run_s)


def _run_duty(model: Model, progress: bool) -> RunResult:
    """The duty cycle's cases as one batch (`sweep.run_points`) and the cycle's values (`duty_cycle`)."""
    duty = model.duty
    values, compile_s, run_s = run_points(model, (duty.count,), duty.cases, progress=progress, place=place)
    values |= cycle_values(duty, values, model.outputs, model.scene.values)
    return RunResult(model, values, compile_s, run_s, duty=duty)
