"""The adapters: one module per effect family, the only place that ties physics to scenes.

Each module builds one `registry.Adapter` and registers it. How to add an effect (say, friction
torque), touching its physics module, its adapter and nothing else (plus tests and docs):

1. Write the physics as pure JAX functions of parameter pytrees in `diffbearing/<idea>.py`
   (SI inside, docstrings with units and the equation's source). It imports nothing from `app`.
2. Add `diffbearing/app/adapters/<family>.py`:
   - `keys`: every scene key the effect reads, {"table.name": Key(...)}, with its
     `effects.<name>` switch (a boolean or a choice) and any `fidelity.<name>` keys (with
     `read_by` naming the blocks that read them);
   - `inputs`: `InputBuilder`s that turn the scene's SI values into parameter pytrees, validating
     them (ValueError naming the key and the allowed range);
   - `blocks`: `Block(name, bearing_types, enabled_by=("<effect>", value), requires, outputs,
     compute, inputs=...)`, `compute(inputs, settings, results) → {output key: array}` pure JAX;
     every `Output` with its SI unit, display unit and a description; `checks` for results
     outside the model; `plot` for the figure of a run; `own_program=True` for a large
     numerical solve (compiled apart from the other blocks), with `compiler_options` where
     XLA's defaults do not suit it;
   - `report` / `sweep_columns` for lines beyond the generic output tables.
3. Import the module below (the order here is the order of report sections).
4. Regenerate the key and output reference: `python -m diffbearing.app.reference > docs/reference.md`.
"""

from . import (  # noqa: F401  (each registers its adapter)
    materials, lubricant, mounting, ball, bearing_set, shaft, life, roller, roller_bearing, film, cage, frequencies, safety,
    friction,
)
