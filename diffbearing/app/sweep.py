"""Sweeps: a scene's [sweep] table evaluated as one batch under `jax.vmap`, in chunks.

    [sweep]
    "operating.inner_speed" = { start = "0 rpm", stop = "20000 rpm", num = 201 }
    "operating.force" = [["0 N", "0 N", "5 kN"], ["0 N", "0 N", "10 kN"]]

Each entry is {start, stop, num} (scalars, or vectors interpolated componentwise) or an explicit
list; several entries form a grid (first key = first axis). Each point's parameter pytrees are
built inside the vmapped function from the swept SI values, so any numeric key can be swept; keys
that change array shapes (`bearing.balls`) or choices cannot. Blocks marked `sequential_sweep`
(the numerical EHL solvers, the influence-coefficient contacts of a roller bearing) are mapped
over the points one after another inside the compiled function (`jax.lax.map`) instead. The
batch runs in chunks of `CHUNK` points through one compiled function (a tqdm bar counts the
chunks); with several local JAX devices each chunk is sharded over them along the batch axis
(`jax.sharding`). Output arrays gain the grid's leading axes. On one device of one process the
compiled batch is kept between processes as a single run's programs are (stored_models.py): a
second run of the same sweep loads it without tracing.

Under `jax.distributed` (several processes, e.g. one per host; docs/distributed_sweeps.md) each
process evaluates a contiguous block of the chunks on its own devices and the blocks are gathered
into every process (`multihost_utils.process_allgather`, CPU collectives through gloo): every
process returns the whole grid, the same numbers as one process computes.
"""

import itertools
import time

import jax
import jax.numpy as jnp
import numpy as np
from jax.sharding import Mesh, NamedSharding, PartitionSpec
from tqdm import tqdm

from .compilation_cache import use_compilation_cache
from .registry import compiler_options, program_key
from .registry import evaluate as evaluate_blocks
from .result import RunResult
from .schema import convert, lookup
from .stored_models import compile_stored

CHUNK = 64


def sweep_axes(sweep: dict) -> dict[str, np.ndarray]:
    """{dotted key: (n, ...) SI values} of a [sweep] table; ValueError names a bad entry."""
    axes = {}
    for key, spec in sweep.items():
        entry = lookup(key)
        if entry.kind not in ("quantity", "quantities", "number"):
            raise ValueError(f"sweep.{key}: only numeric values can be swept (this key is {entry.kind})")
        if isinstance(spec, dict):
            unknown = set(spec) - {"start", "stop", "num"}
            if unknown or not {"start", "stop", "num"} <= set(spec):
                raise ValueError(f"sweep.{key}: expected {{start, stop, num}}, got keys {sorted(spec)}")
            num = spec["num"]
            if isinstance(num, bool) or not isinstance(num, int) or num < 1:
                raise ValueError(f"sweep.{key}.num must be an integer ≥ 1, got {num!r}")
            start = np.asarray(convert(key, spec["start"]), dtype=float)
            stop = np.asarray(convert(key, spec["stop"]), dtype=float)
            axes[key] = np.linspace(start, stop, num)
        elif isinstance(spec, list) and spec:
            axes[key] = np.asarray([convert(key, item) for item in spec], dtype=float)
        else:
            raise ValueError(f"sweep.{key}: expected {{start, stop, num}} or a non-empty list, got {spec!r}")
    return axes


def grid_points(axes: dict) -> tuple[tuple[int, ...], dict[str, np.ndarray]]:
    """(grid shape, {key: (N, ...) values}) of the full grid, first key slowest."""
    shape = tuple(len(values) for values in axes.values())
    index = np.array(list(itertools.product(*(range(n) for n in shape)))).reshape(-1, len(shape))
    return shape, {key: values[index[:, k]] for k, (key, values) in enumerate(axes.items())}


def check_corners(scene_values: dict, axes: dict, inputs_from_values) -> None:
    """Validate the parameters at every corner of the grid (ValueError names the parameter)."""
    for corner in itertools.product(*[(values[0], values[-1]) for values in axes.values()]):
        values = dict(scene_values)
        for key, value in zip(axes, corner):
            values[key] = value.tolist() if np.ndim(value) else float(value)
        inputs_from_values(values)


def run_sweep(model, axes: dict, *, chunk: int = CHUNK, progress: bool = True):
    """Evaluate `model` (a model.Model) over the grid `axes`; returns a RunResult with batched values."""
    check_corners(model.scene.values, axes, model.inputs_from_values)
    shape, points = grid_points(axes)
    values, compile_s, run_s = run_points(model, shape, points, chunk=chunk, progress=progress)
    return RunResult(model, values, compile_s, run_s, sweep_axes=axes)


def run_points(model, shape: tuple[int, ...], points: dict, *, chunk: int = CHUNK, progress: bool = True,
               place=None):
    """({key: array of `shape` + the output's}, compile time [s], run time [s]) of `model` at the
    points {key: (N, ...) SI values}, N = prod(shape), as one vmapped batch in chunks (module docstring);
    `place(values, point)` sets a point's values into the scene's (default: `dict.update`)."""
    count = int(np.prod(shape))
    # process p evaluates points [p·share, (p + 1)·share): gathered in process order the blocks are
    # the grid in order, followed by padding that is cut off
    processes, rank = jax.process_count(), jax.process_index()
    share = -(-count // processes)
    devices = jax.local_devices()
    chunk = max(len(devices), min(chunk, share))
    chunk = -(-chunk // len(devices)) * len(devices)  # a multiple of the device count
    blocks = [block for block in model.blocks if not block.single_run]  # a single run's plot data
    evaluate = evaluate_blocks(blocks, model.settings)
    base = dict(model.scene.values)

    place = place or (lambda values, swept: {**values, **swept})

    def point(swept):
        return evaluate(model.inputs_from_values(place(base, swept)))

    sequential = any(block.sequential_sweep for block in blocks)  # iterative solvers: one point after another
    batch = (lambda swept: jax.lax.map(point, swept)) if sequential else jax.vmap(point)
    sharding = NamedSharding(Mesh(np.array(devices), ("batch",)), PartitionSpec("batch")) if len(devices) > 1 else None

    def chunk_inputs(start):
        start = min(start, count - 1)  # a block past the grid's end repeats its last point
        stop = min(start + chunk, (rank + 1) * share, count)
        pad = chunk - (stop - start)
        arrays = {key: jnp.asarray(np.concatenate([v[start:stop], np.repeat(v[stop - 1:stop], pad, axis=0)]))
                  for key, v in points.items()}
        return (jax.device_put(arrays, sharding) if sharding is not None else arrays), stop - start

    first, _ = chunk_inputs(rank * share)
    use_compilation_cache()  # a sweep's program is kept between processes too (compilation_cache.py)
    options = compiler_options(blocks, model.settings) or None
    start_time = time.perf_counter()
    if sharding is None and processes == 1:  # stored between processes: a second run skips tracing
        # the key: the program's (the chunk's swept keys and shapes), and the scene's values every point
        # shares, which are traced into it as constants
        key = repr(("sweep", program_key(blocks, model.settings, first), sorted(base.items()), sequential))
        executable, _ = compile_stored(batch, first, key, options)
    else:
        executable = jax.jit(batch).lower(first).compile(options)
    compile_s = time.perf_counter() - start_time
    pieces = []
    run_start = time.perf_counter()
    starts = range(rank * share, (rank + 1) * share, chunk)
    for start in tqdm(starts, desc="sweep", unit="chunk", disable=not progress or rank > 0 or len(starts) < 2):
        arrays, valid = chunk_inputs(start)
        out = jax.block_until_ready(executable(arrays))
        pieces.append({key: np.asarray(value)[:max(valid, 0)] for key, value in out.items()})
    block = {key: np.concatenate([p[key] for p in pieces]) for key in pieces[0]}
    if processes > 1:  # every block padded to `share` points, as the gather needs equal shapes
        from jax.experimental import multihost_utils

        block = {key: np.concatenate([value, np.repeat(value[-1:], share - len(value), axis=0)])
                 for key, value in block.items()}
        block = multihost_utils.process_allgather(block, tiled=True)
    run_s = time.perf_counter() - run_start
    values = {key: np.asarray(value)[:count].reshape(shape + value.shape[1:]) for key, value in block.items()}
    return values, compile_s, run_s
