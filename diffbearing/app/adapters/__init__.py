"""The adapters: one module per bearing type (`bearings/`), per mounting (`systems/`) and per effect
family (`effects/`), plus the scene's materials and lubricant: the only place that ties physics to scenes.

Each module builds one `registry.Adapter` and registers it. How to add an effect (say, friction
torque), touching its physics module, its adapter and nothing else (plus tests and docs):

1. Write the physics as pure JAX functions of parameter pytrees in `diffbearing/<family>/<idea>.py`
   (SI inside, docstrings with units and the equation's source). It imports nothing from `app`.
2. Add `diffbearing/app/adapters/effects/<family>.py`:
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
3. Import the module below (the order here is the order of registration: of report sections,
   of the reference's tables and of blocks that do not depend on each other).
4. Regenerate the key and output reference: `python -m diffbearing.app.reference > docs/reference.md`.
"""

# each import registers its adapter, in this order (an adapter that imports another registers
# after it: the order here is also the order those imports give)
from . import materials, lubricant, designation  # noqa: F401
from .systems import mounting  # noqa: F401
from .bearings import ball  # noqa: F401
from .systems import bearing_set  # noqa: F401
from .bearings import roller, roller_bearing, double_row, four_point, self_aligning, thrust_ball, needle_roller  # noqa: F401
from .bearings import cylindrical_roller_thrust, spherical_roller  # noqa: F401
from .effects import life  # noqa: F401
from .systems import shaft  # noqa: F401
from .effects import reliability  # noqa: F401
from .effects import film, cage, frequencies, safety, friction  # noqa: F401
from .effects import thermal_speed, thermal, grease_life  # noqa: F401
