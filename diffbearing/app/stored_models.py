"""Compiled models kept between processes: a second run of the same scene skips tracing.

JAX's persistent compilation cache keeps XLA executables, but a run still traces and lowers the
model first (seconds for the ball equilibrium with its implicit derivatives). Here the lowered
model is stored with `jax.export` beside that cache, under a key of the blocks, the settings, the
inputs' structure, shapes and dtypes, the JAX version and a digest of diffbearing's source (so an
edit of the code invalidates it); the next process deserializes it and gets the executable from
the persistent cache. Without a compilation cache folder (DIFFBEARING_CACHE=off, compilation_cache.py)
nothing is stored, nor is a model whose lowering holds host callbacks or LAPACK calls without a
stability guarantee (`jax.export` cannot serialize them: the cage dynamics' diffrax integration),
which is traced anew in each process.
"""

import ctypes
import ctypes.util
import functools
import gc
import hashlib
import tempfile
from pathlib import Path

import jax
from jax import export

PACKAGE = Path(__file__).resolve().parents[1]


@functools.cache
def source_digest() -> str:
    """sha256 of every .py file of the diffbearing package (path and content)."""
    digest = hashlib.sha256(jax.__version__.encode())
    for path in sorted(PACKAGE.rglob("*.py")):
        digest.update(str(path.relative_to(PACKAGE)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def release_memory() -> None:
    """Collect Python's garbage (traces and lowered modules that only cycles hold) and hand the
    heap's free pages back to the system (glibc's malloc_trim, where the C library has it), so that
    the next compilation does not start on top of the last one's leftovers. A full collection takes
    longer the more objects a process holds (a test session): for large programs only."""
    gc.collect()
    trim = getattr(_c_library(), "malloc_trim", None)
    if trim is not None:
        trim(0)


@functools.cache
def _c_library():
    name = ctypes.util.find_library("c")
    return ctypes.CDLL(name) if name else None


def _folder() -> Path | None:
    root = jax.config.jax_compilation_cache_dir
    return None if not root else Path(root) / "diffbearing-models"


def compile_stored(function, inputs, key: str, compiler_options: dict | None = None, release: bool = False):
    """(a compiled callable inputs → outputs of `function`, a pure function of the inputs pytree
    (arrays, or `jax.ShapeDtypeStruct`s standing for them); the outputs' `jax.ShapeDtypeStruct`s),
    loaded from the stored export of `key` where one exists, else exported, stored and compiled
    (with XLA's `compiler_options`, which the key must determine); with `release`, the memory the
    export's trace held is released before compiling (`release_memory`: a large program)."""
    leaves, treedef = jax.tree.flatten(inputs)
    options = compiler_options or None

    def plain():
        executable = jax.jit(function).lower(inputs).compile(options)
        return executable, executable.out_info

    folder = _folder()
    if folder is None:
        return plain()

    def flat(*arrays):
        return function(jax.tree.unflatten(treedef, arrays))

    path = folder / (hashlib.sha256((key + source_digest()).encode()).hexdigest() + ".jaxexport")
    if path.is_file():
        exported = export.deserialize(bytearray(path.read_bytes()))
    else:
        try:
            exported = export.export(jax.jit(flat))(*leaves)
        except (NotImplementedError, ValueError):
            # host callbacks (diffrax's cage dynamics) and LAPACK calls without a stability
            # guarantee cannot be serialized; a ValueError of the model itself is raised again by
            # the plain lowering
            return plain()
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=folder, suffix=".partial", delete=False) as temporary:
            temporary.write(exported.serialize())
        Path(temporary.name).replace(path)  # atomic: a process reading meanwhile sees all or nothing
        if release:
            release_memory()
    executable = jax.jit(exported.call).lower(*leaves).compile(options)
    return (lambda values: executable(*jax.tree.leaves(values))), executable.out_info
