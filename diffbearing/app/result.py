"""The result of a run: output values (NumPy, SI), timings, and the blocks' checks."""

import dataclasses
import functools

from .registry import problems


@dataclasses.dataclass
class RunResult:
    """Outputs of one run (NumPy arrays, SI) with compile and run times [s]."""

    model: object  # the model.Model that ran
    values: dict
    compile_s: float  # 0 when the compiled model was reused from an earlier run in this process
    run_s: float
    sweep_axes: dict = dataclasses.field(default_factory=dict)  # {dotted key: SI values} of a sweep
    duty: object = None  # the duty_cycle.DutyCycle of a [[duty]] run

    @functools.cached_property
    def problems(self) -> tuple[list[str], list[str]]:
        """(errors, warnings) of the blocks' checks, one line each (a sweep's name their point)."""
        if self.duty is not None:
            case_keys = [key for key in self.values if not key.startswith("duty.")]
            errors, warnings = problems(self.model.blocks, {key: self.values[key] for key in case_keys},
                                        (self.duty.count,), label="duty case")
        else:
            shape = tuple(len(values) for values in self.sweep_axes.values())
            errors, warnings = problems(self.model.blocks, self.values, shape)
        idle = [f"{key} is not used by this scene's effects (another level of the effect reads it)"
                for key in self.model.idle_settings]
        switched = ", ".join(self.model.scene.switched)
        unread = [f"{key} is not read with {switched} as set (the scene file's effects read it)"
                  for key in self.model.switched_off]
        return errors, idle + unread + warnings
