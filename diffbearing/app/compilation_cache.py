"""Where compiled models are kept between processes: JAX's persistent compilation cache.

By default in ~/.cache/diffbearing/jax; DIFFBEARING_CACHE names another folder, and
DIFFBEARING_CACHE=off switches it off. A folder the user set for JAX's own cache
(`jax_compilation_cache_dir`, or JAX_COMPILATION_CACHE_DIR) is used as it is, with JAX's own
settings, and DIFFBEARING_CACHE is not read. `build_model`, `run_model` and `run_sweep` switch the
cache on before they first compile, from the CLI as from a script or notebook (which so reuses the programs of an
earlier process too); importing diffbearing changes nothing. JAX's cache is one per process: once switched
on here, it keeps every program the process compiles, the user's own included.
"""

import os

CACHE_VARIABLE = "DIFFBEARING_CACHE"


def compilation_cache_folder() -> str | None:
    """The folder diffbearing asks for ($DIFFBEARING_CACHE, else ~/.cache/diffbearing/jax; None
    when $DIFFBEARING_CACHE is "off")."""
    chosen = os.environ.get(CACHE_VARIABLE, "")
    if chosen.lower() == "off":
        return None
    return chosen or os.path.join(os.path.expanduser("~"), ".cache", "diffbearing", "jax")


def cache_folder_in_use() -> str | None:
    """The folder diffbearing keeps things in between processes, without switching anything on:
    JAX's cache folder where the user set one, else `compilation_cache_folder()`."""
    import jax

    return jax.config.jax_compilation_cache_dir or compilation_cache_folder()


def use_compilation_cache() -> str | None:
    """Switch JAX's persistent compilation cache on in `compilation_cache_folder()`, keeping every
    compiled program however quick its compilation, unless JAX already has a cache folder (the
    user's: left as it is). Returns the folder in use (None: no cache)."""
    import jax

    current = jax.config.jax_compilation_cache_dir
    if current:
        return current
    folder = compilation_cache_folder()
    if folder is None:
        return None
    jax.config.update("jax_compilation_cache_dir", folder)
    jax.config.update("jax_persistent_cache_min_compile_time_secs", 0.0)
    jax.config.update("jax_persistent_cache_min_entry_size_bytes", 0)
    return folder
