"""The effect registry: adapters declare scene keys, inputs, blocks and outputs; `resolve` picks
the blocks a scene asks for and `evaluate` runs them.

An `Adapter` (one module in `diffbearing.app.adapters` per effect family) declares

* `keys`: the scene keys it reads, {dotted key: `Key`}, effects and fidelity keys included;
* `required`: per bearing type, the keys without which its inputs cannot be built;
* `inputs`: `InputBuilder`s, each turning the scene's SI values into parameter pytrees;
* `blocks`: the physics `Block`s with their `Output`s (SI unit, display unit), checks and plot;
* `header`, `report`, `sweep_columns`: its lines in the text report.

The registry knows no adapter or block by name: a block runs when its bearing type matches and
its `enabled_by` effect is on (or it has none), together with the blocks it `requires`. A block no
named effect reaches is never called, so it is never traced or compiled.

One bearing type may be modelled in more than one layout, told apart by the keys a scene holds: a
roller type is one roller–raceway contact where the scene gives `contact.load`, the whole bearing
where it gives `operating.force`; a ball type is one bearing, or a matched set where the scene
gives `bearing.arrangement`. A block or input builder with `scene_keys` belongs to the layout of
the scene that holds all of those keys and none of those written "!key"; a block that requires a
block of another layout is left out with it (`selectable`). Blocks and builders without
`scene_keys` serve every layout.
"""

import dataclasses
import sys
import time
from collections.abc import Callable, Mapping

import jax
import jax.numpy as jnp
import numpy as np

from .compilation_cache import use_compilation_cache
from .stored_models import compile_stored, release_memory

# The bearing type of a scene with [[bearings]]: a shaft on several bearings (adapters/systems/shaft.py).
SHAFT_TYPE = "shaft"
SHAFT = (SHAFT_TYPE,)


@dataclasses.dataclass(frozen=True)
class Key:
    """One scene key: `kind` is quantity | quantities | number | integer | integers | boolean |
    choice | text | tables (an array of tables, each converted by `entry`); `dimension` names an
    entry of units.SI_UNITS; `choices` lists allowed values (for choice; True/False may be among
    them); `length` fixes the size of a list; a fidelity key lists in `read_by` the blocks that
    read it (given while none of them runs, it is refused)."""

    kind: str
    dimension: str = "dimensionless"
    choices: tuple = ()
    length: int | None = None
    doc: str = ""
    read_by: tuple[str, ...] = ()
    # kind "tables" (a TOML array of tables, [[name]]): (index, table, convert) → the table in SI, ValueError
    # naming it; `convert(dotted, value)` is the schema's, for keys of other tables
    entry: Callable[[int, dict, Callable], dict] | None = dataclasses.field(default=None, compare=False)

    def same_meaning(self, other: "Key") -> bool:
        return (self.kind, self.dimension, self.choices, self.length) == (
            other.kind, other.dimension, other.choices, other.length)


def quantity(dimension: str, doc: str = "") -> Key:
    """A scalar scene quantity of `dimension` ("28 mm", or a bare SI number)."""
    return Key("quantity", dimension, doc=doc)


@dataclasses.dataclass(frozen=True)
class Output:
    """One output key: `unit` of the SI value in JSON, `display` unit of the report."""

    key: str
    unit: str
    display: str
    description: str
    effect: str | None = None  # produced only when this effect is on
    in_report: bool = True  # False: JSON and plots only, or shown by its adapter's own report lines
    column: str = ""  # header of its column in a per-element table (balls), where it is reported


@dataclasses.dataclass(frozen=True)
class Block:
    name: str
    bearing_types: tuple[str, ...]
    enabled_by: tuple[str, object] | None  # (effect key, value) that switches it on; None: always
    requires: tuple[str, ...]
    outputs: tuple[Output, ...]
    compute: Callable[[dict, dict, dict], dict]  # (inputs, settings, results so far) → {key: array}
    inputs: tuple[str, ...] = ()  # names of the input pytrees it reads
    uses: tuple[str, ...] = ()  # effects it reads as options (e.g. centrifugal inside the equilibrium)
    only_with: tuple[str, tuple] | None = None  # (effect key, values): another effect it refines must be one of these
    # swept point by point (`jax.lax.map`), not under `jax.vmap`: the numerical EHL solvers, whose
    # vmapped compiled batch of 1-D line solves ran past 150 s where one solve takes 0.03 s, and the
    # iterative contact solves of a whole roller bearing
    sequential_sweep: bool = False
    # data for the figure of a single run only (nothing requires it): a sweep leaves it out
    single_run: bool = False
    # values of one point (NumPy, SI) → (errors, warnings): one line each, with units; an error
    # means the result is outside the model (the CLI exits 3), a warning that a limit is passed
    checks: Callable[[dict], tuple[list[str], list[str]]] | None = None
    # (settings, inputs) → None, or ValueError for settings this block cannot run with (before compiling)
    validate: Callable[[dict, dict], None] | None = None
    plot: Callable | None = None  # (result, figure) → None: the figure of a single run
    sweep_plot: Callable | None = None  # (result, figure) → None: the figure of a sweep
    # scene keys that select this block's layout: it runs only in a scene holding every one of them
    # (module docstring); () serves every layout
    scene_keys: tuple[str, ...] = ()
    # settings → XLA compiler options for the program that holds this block ({}: XLA's defaults)
    compiler_options: Callable[[dict], dict] | None = None
    # a single run compiles it as a program of its own, apart from the blocks before and after it
    # (the numerical EHL solvers: XLA's compile memory for one program holding two of them is well
    # above that of each alone); a sweep compiles all blocks as one program
    own_program: bool = False

    def in_layout(self, present) -> bool:
        """Whether a scene holding the keys `present` has this block's layout."""
        return in_layout(self.scene_keys, present)


@dataclasses.dataclass(frozen=True)
class InputBuilder:
    """Builds the input pytrees `provides` from the scene's SI values (a `Reads` mapping; values
    may be JAX tracers in a sweep) and the inputs built before it (those in `after`); with
    `scene_keys`, only in a scene holding all of them (another builder may provide the same
    inputs in another layout)."""

    provides: tuple[str, ...]
    bearing_types: tuple[str, ...]
    build: Callable[[dict, dict], dict]
    after: tuple[str, ...] = ()
    scene_keys: tuple[str, ...] = ()

    def in_layout(self, present) -> bool:
        return in_layout(self.scene_keys, present)


def in_layout(scene_keys, present) -> bool:
    """Whether a scene holding the keys `present` holds every key of `scene_keys` and none of those
    written "!key" there."""
    return all((key[1:] not in present) if key.startswith("!") else (key in present) for key in scene_keys)


@dataclasses.dataclass(frozen=True)
class Mounting:
    """How a bearing type's `[[bearings]]` entries go on a scene's shaft (the type's adapter
    declares it): `parameters(reads)` → its parameter pytree from the entry's keys (a `Reads`);
    `support(parameters, position, offset, orientation, settings)` → its `AbstractSupport`;
    `describe(parameters)` → its line in the report; where its entries may give shoulder
    diameters, `shoulders(reads, parameters)` → their depths (or None) and
    `shoulder_outputs(support, displacement, speed, elements, constants, depths)` → the outputs."""

    parameters: Callable
    support: Callable
    describe: Callable
    shoulders: Callable | None = None
    shoulder_outputs: Callable | None = None


@dataclasses.dataclass(frozen=True)
class Adapter:
    name: str
    bearing_types: tuple[str, ...]
    keys: dict[str, Key] = dataclasses.field(default_factory=dict)
    required: dict[str, tuple] = dataclasses.field(default_factory=dict)  # bearing type → keys ("one of": a tuple)
    inputs: tuple[InputBuilder, ...] = ()
    blocks: tuple[Block, ...] = ()
    header: Callable | None = None  # (result) → lines at the top of the report
    report: Callable | None = None  # (result) → lines after the output tables
    sweep_columns: Callable | None = None  # ({key: (N, ...) values}) → [(header, cells)]
    mounting: Mounting | None = None  # a bearing type's: how its entries go on a shaft
    # a bearing type's: {(its type, scene key): why}, keys its model does not take (a scene of that
    # type holding one, with any value but false, is refused naming the key)
    refused: dict[tuple[str, str], str] = dataclasses.field(default_factory=dict)


ADAPTERS: dict[str, Adapter] = {}


def check_refused(bearing_type: str, values) -> None:
    """ValueError naming a scene key a bearing type's adapter refuses (`Adapter.refused`)."""
    for adapter in ADAPTERS.values():
        for (kind, key), why in adapter.refused.items():
            if kind == bearing_type and key in values and values[key] is not False:
                raise ValueError(f"{key}: {why}")


def register(adapter: Adapter) -> Adapter:
    """Add an adapter (its name and its block names must be new; a key it shares with another
    adapter must mean the same)."""
    if adapter.name in ADAPTERS:
        raise ValueError(f"adapter {adapter.name!r} is already registered")
    known = blocks_by_name()
    for block in adapter.blocks:
        if block.name in known:
            raise ValueError(f"block {block.name!r} is already registered")
    for dotted, key in adapter.keys.items():
        other = all_keys().get(dotted)
        if other is not None and not other.same_meaning(key):
            raise ValueError(f"scene key {dotted!r} is declared twice with different meanings")
    ADAPTERS[adapter.name] = adapter
    return adapter


def mountings() -> dict[str, Mounting]:
    """{bearing type: its `Mounting`} of the types a shaft can carry, from the registered adapters."""
    return {kind: adapter.mounting for adapter in ADAPTERS.values() if adapter.mounting is not None
            for kind in adapter.bearing_types}


def unregister(name: str) -> None:
    """Remove an adapter (tests register toy adapters and remove them again)."""
    del ADAPTERS[name]


def blocks_by_name() -> dict[str, Block]:
    return {block.name: block for adapter in ADAPTERS.values() for block in adapter.blocks}


def all_keys() -> dict[str, Key]:
    """{dotted key: Key} of every registered adapter."""
    keys: dict[str, Key] = {}
    for adapter in ADAPTERS.values():
        for dotted, key in adapter.keys.items():
            if dotted in keys:  # declared by several adapters: read by the blocks of each
                key = dataclasses.replace(keys[dotted], read_by=keys[dotted].read_by + key.read_by)
            keys[dotted] = key
    return keys


def adapters_for(bearing_type: str) -> list[Adapter]:
    return [adapter for adapter in ADAPTERS.values() if bearing_type in adapter.bearing_types]


def selectable(bearing_type: str, present=()) -> list[Block]:
    """The blocks of `bearing_type` a scene holding the keys `present` may run: those of its layout
    (`Block.scene_keys`) whose required blocks, and theirs, are of its layout too."""
    of_type = [block for adapter in adapters_for(bearing_type) for block in adapter.blocks
               if bearing_type in block.bearing_types]
    excluded = {block.name for block in of_type if not block.in_layout(present)}
    while True:
        more = {block.name for block in of_type if block.name not in excluded and excluded & set(block.requires)}
        if not more:
            return [block for block in of_type if block.name not in excluded]
        excluded |= more


def resolve(bearing_type: str, effects: dict, present=()) -> tuple[list[Block], list[str]]:
    """Blocks to run, in dependency order, and the named effects no registered block provides.

    `effects` maps effect names to their scene values (false / absent means off); `present` holds
    the scene's keys, which select the layout (`selectable`).
    """
    candidates = selectable(bearing_type, present)
    wanted = [block for block in candidates if block.enabled_by is None]
    provided = {effect for block in candidates for effect in block.uses}
    for block in candidates:
        if block.enabled_by is not None:
            effect, value = block.enabled_by
            refines = block.only_with is None or effects.get(block.only_with[0]) in block.only_with[1]
            if effect in effects and effects[effect] == value and type(effects[effect]) is type(value) and refines:
                wanted.append(block)
                provided.add(effect)
    missing = [name if value is True else f"{name} = {value!r}"
               for name, value in effects.items() if value is not False and name not in provided]
    by_name = blocks_by_name()
    ordered: list[Block] = []

    def visit(block: Block, chain: tuple[str, ...]):
        if block in ordered:
            return
        if block.name in chain:
            raise ValueError(f"blocks require each other in a cycle: {' → '.join(chain + (block.name,))}")
        for name in block.requires:
            visit(by_name[name], chain + (block.name,))
        ordered.append(block)

    for block in wanted:
        visit(block, ())
    return ordered, missing


def input_builders(bearing_type: str, names, present=()) -> list[InputBuilder]:
    """The builders of the inputs `names` (and of the inputs they are built after), in order, for
    a scene holding the keys `present` (a builder with `scene_keys` only in its layout)."""
    builders = {name: builder for adapter in adapters_for(bearing_type) for builder in adapter.inputs
                if bearing_type in builder.bearing_types and builder.in_layout(present) for name in builder.provides}
    ordered: list[InputBuilder] = []

    def visit(name):
        if name not in builders:
            raise ValueError(f"no adapter builds the input {name!r} for {bearing_type}")
        builder = builders[name]
        if builder in ordered:
            return
        for earlier in builder.after:
            visit(earlier)
        ordered.append(builder)

    for name in names:
        visit(name)
    return ordered


def convergence_checks(*flags: tuple[str, str]):
    """A block's `checks` from (output key of a converged flag, the solve it belongs to) pairs: an
    error for each flag that is false."""

    def checks(values: dict) -> tuple[list[str], list[str]]:
        return [f"{solve} did not converge (its outputs are the last iterate)" for key, solve in flags
                if not bool(values[key])], []

    return checks


def problems(blocks, values: dict, grid_shape: tuple[int, ...] = (), label: str = "sweep point"
             ) -> tuple[list[str], list[str]]:
    """(errors, warnings) of the blocks' checks over every point of a run (`grid_shape` () for one
    point), each line of a point prefixed by `label` and its number."""
    errors, warnings = [], []
    for number, index in enumerate(np.ndindex(grid_shape)):
        point = {key: np.asarray(value)[index] for key, value in values.items()}
        prefix = f"{label} {number}: " if grid_shape else ""
        for block in blocks:
            if block.checks is not None:
                found_errors, found_warnings = block.checks(point)
                errors += [prefix + line for line in found_errors]
                warnings += [prefix + line for line in found_warnings]
    return errors, warnings


def outputs_of(blocks, effects: dict | None = None) -> dict[str, Output]:
    """{key: Output} the given blocks produce (with `effects`, only those whose effect is on)."""
    return {out.key: out for block in blocks for out in block.outputs
            if effects is None or out.effect is None or effects.get(out.effect, False) is True}


def evaluate_after(blocks, settings: dict) -> Callable[[tuple[dict, dict]], dict]:
    """The pure function (inputs, results of the blocks before) → {output key: array} of `blocks`."""

    def run(arguments: tuple[dict, dict]) -> dict:
        inputs, earlier = arguments
        results, produced = dict(earlier), {}
        for block in blocks:
            produced |= block.compute(inputs, settings, results)
            results |= produced
        return produced

    return run


def evaluate(blocks, settings: dict) -> Callable[[dict], dict]:
    """The pure function inputs → {output key: array} that runs exactly `blocks` in order."""
    after = evaluate_after(blocks, settings)
    return lambda inputs: after((inputs, {}))


class Reads(Mapping):
    """The scene's {dotted key: SI value}, recording which keys the input builders ask for."""

    def __init__(self, values: dict):
        self._values = values
        self.asked: set[str] = set()

    def __getitem__(self, key):
        self.asked.add(key)
        return self._values[key]

    def get(self, key, default=None):
        self.asked.add(key)
        return self._values.get(key, default)

    def __contains__(self, key):
        return key in self._values

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)


# XLA's quick settings for a single run's programs on the CPU: LLVM at optimisation level 1 and the
# loop emitters in place of the fusion emitters (level 0 gave a NaN that level 1 does not). A single
# run is compile-bound: the default scene's program compiles in two thirds of the time and runs a
# millisecond or two longer (docs/benchmarks.md, §Compile times). Sweeps, whose batches are
# run-bound, and the programs of their own (the numerical EHL solvers, seconds of run at fine grids)
# keep XLA's defaults, with their blocks' own options.
QUICK_COMPILE = {"xla_backend_optimization_level": 1, "xla_cpu_use_fusion_emitters": False}


def compiler_options(blocks, settings: dict, quick: bool = False) -> dict:
    """The XLA compiler options the blocks ask for with these settings, merged (one program holds
    them all); with `quick`, on the CPU, over `QUICK_COMPILE`."""
    options: dict = dict(QUICK_COMPILE) if quick and jax.default_backend() == "cpu" else {}
    for block in blocks:
        if block.compiler_options is not None:
            options |= block.compiler_options(settings)
    return options


def programs(blocks) -> list[tuple[Block, ...]]:
    """The blocks, in order, split into the programs a single run compiles apart: each block with
    `own_program` alone, the blocks between them together."""
    groups: list[tuple[Block, ...]] = []
    for block in blocks:
        if block.own_program or not groups or groups[-1][-1].own_program:
            groups.append((block,))
        else:
            groups[-1] += (block,)
    return groups


_COMPILED: dict = {}


def program_key(blocks, settings: dict, inputs) -> str:
    """What a compiled program of `blocks` depends on besides the numbers: the blocks, the
    settings, and the structure, shapes and dtypes of its inputs (the key of `compiled` and of a
    stored model, `stored_models.compile_stored`)."""
    leaves, treedef = jax.tree.flatten(inputs)
    return repr((tuple(b.name for b in blocks), sorted((k, sorted(v.items())) for k, v in settings.items()),
                 str(treedef), tuple((jnp.shape(x), str(jnp.result_type(x))) for x in leaves)))


def compiled(blocks, settings: dict, inputs: dict, progress: bool = False):
    """(a callable inputs → {output key: array} of `blocks`, compiled ahead of time for `inputs`;
    whether it was cached).

    Each of `programs(blocks)` is `jax.jit` compiled on its own, with the options its blocks ask for
    (`compiler_options`), a program of its own (`Block.own_program`) between releases of the memory
    the compilers left (`stored_models.release_memory`), and the callable runs them in order.
    Compiled models are kept per process, keyed by the blocks, the settings and the structure,
    shapes and dtypes of the inputs: a second run of the same model with other numbers reuses them.
    Between processes they are kept on disk (stored_models.py) in the compilation cache
    (`use_compilation_cache`: switched on here unless JAX has a cache folder or DIFFBEARING_CACHE=off).
    With `progress`, each program's compilation is announced on stderr with the blocks it holds and
    then its wall time (a scene's first run compiles for seconds to minutes; later ones load it).
    """
    use_compilation_cache()
    key = program_key(blocks, settings, inputs)
    if key in _COMPILED:
        return _COMPILED[key], True
    executables, earlier = [], {}
    groups = programs(blocks)
    for number, group in enumerate(groups, 1):
        if progress:
            print(f"diffbearing: compiling program {number} of {len(groups)} ({', '.join(b.name for b in group)}; "
                  "later runs load it from the compilation cache) ...", end="", file=sys.stderr, flush=True)
            start = time.perf_counter()
        apart = group[0].own_program
        if apart:
            release_memory()  # the earlier programs' leftovers
        executable, produced = compile_stored(evaluate_after(group, settings), (inputs, earlier),
                                              repr((key, tuple(b.name for b in group))),
                                              compiler_options(group, settings, quick=not apart), release=apart)
        if apart:
            release_memory()  # the compiler's, before the run maps its buffers beside them
        executables.append(executable)
        earlier = earlier | produced
        if progress:
            print(f" {time.perf_counter() - start:.1f} s", file=sys.stderr, flush=True)

    def run(values: dict) -> dict:
        results: dict = {}
        for executable in executables:
            results |= executable((values, results))
        return results

    _COMPILED[key] = run
    return run, False
