"""The figure of a run (matplotlib, Agg backend): drawn by the plot of the last block that has one
(for a sweep, its sweep plot; for a duty cycle, its cases' shares of the damage), from the run's
outputs only."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def duty_plot(result, figure) -> None:
    """A duty cycle's cases: their shares of the revolutions and of the damage (`duty.damage_share`)."""
    from .duty_cycle import damage_life

    values, cases = result.values, range(result.duty.count)
    axes = figure.add_subplot(1, 1, 1)
    width = 0.4
    axes.bar([case - width / 2 for case in cases], 100 * values["duty.revolution_share"], width, label="revolutions")
    damaged = damage_life(values)
    if damaged is not None:
        axes.bar([case + width / 2 for case in cases], 100 * values["duty.damage_share"], width,
                 label=f"damage ({damaged.rpartition('.')[2]})")
    axes.set_xticks(list(cases))
    axes.set_xlabel("load case")
    axes.set_ylabel("share [%]")
    axes.set_title(f"{result.model.scene.title}: duty cycle of {result.duty.count} cases")
    axes.legend()


def has_plot(result) -> bool:
    """Whether the run has a figure (`save_plot`)."""
    field = "sweep_plot" if result.sweep_axes else "plot"
    return result.duty is not None or any(getattr(block, field) is not None for block in result.model.blocks)


def save_plot(result, path) -> None:
    """Draw the plot of the run's main block into `path` (a file name, PNG, PDF or SVG by extension,
    or a binary file object, PNG)."""
    if result.duty is not None:
        figure = plt.figure(figsize=(8, 4.5), layout="constrained")
        duty_plot(result, figure)
    else:
        field = "sweep_plot" if result.sweep_axes else "plot"
        plotters = [getattr(block, field) for block in result.model.blocks if getattr(block, field) is not None]
        if not plotters:
            raise ValueError("--plot: this scene has nothing to plot yet")
        figure = plt.figure(figsize=(13 if not result.sweep_axes else 11, 4.5), layout="constrained")
        plotters[-1](result, figure)
    figure.savefig(path, dpi=120, **({} if isinstance(path, str) else {"format": "png"}))
    plt.close(figure)
