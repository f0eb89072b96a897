"""The figure of a run (matplotlib, Agg backend): drawn by the plot of the last block that has one
(for a sweep, its sweep plot), from the run's outputs only."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def save_plot(result, path: str) -> None:
    """Draw the plot of the run's main block into `path` (PNG, PDF or SVG by extension)."""
    field = "sweep_plot" if result.sweep_axes else "plot"
    plotters = [getattr(block, field) for block in result.model.blocks if getattr(block, field) is not None]
    if not plotters:
        raise ValueError("--plot: this scene has nothing to plot yet")
    figure = plt.figure(figsize=(13 if not result.sweep_axes else 11, 4.5), layout="constrained")
    plotters[-1](result, figure)
    figure.savefig(path, dpi=120)
    plt.close(figure)
