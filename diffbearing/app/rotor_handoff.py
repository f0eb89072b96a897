"""Bearing stiffness for rotor-dynamics codes: the exact 5×5 stiffness of a scene's bearing over
speed (and load) as one vmapped sweep, exported with units (CSV, NPZ), or as a ROSS bearing element.

The stiffness is the scene's own `stiffness` output (K = dF/dΔ through the converged equilibrium,
rows [Fx, Fy, Fz, Mx, My], columns [δx, δy, δz, θx, θy]) with the inner ring turning at each speed
and the scene's other settings as they are (its speed effects, mounting, fidelity). x and y are the
bearing's radial axes, z its axis; ROSS takes x, y alike (y vertical), so k_xx = K[0, 0],
k_xy = K[0, 1], k_yx = K[1, 0], k_yy = K[1, 1] (the restoring force on the shaft is −K Δ in both).
Damping is not modelled: the ROSS element gets the damping the caller gives (default 0).
"""

import contextlib
import dataclasses
import os
import sys
import warnings
from pathlib import Path

import numpy as np

from .model import build_model
from .registry import SHAFT_TYPE
from .scene import Scene, load_scene
from .sweep import run_sweep

DOFS = ("x", "y", "z", "θx", "θy")
_ROW_UNITS, _COLUMN_UNITS = ("N", "N", "N", "N*m", "N*m"), ("m", "m", "m", "rad", "rad")


def _stiffness_scene(scene) -> Scene:
    """The scene (a path, a packaged example's name or a loaded `Scene`) with effects.stiffness on."""
    scene = scene if isinstance(scene, Scene) else load_scene(scene)
    if scene.sweep:
        raise ValueError("scene: give a scene without a [sweep] table (the speeds and loads are swept here)")
    if scene.bearing_type == SHAFT_TYPE or "bearing.arrangement" in scene.values:
        raise ValueError("scene: one bearing (a ball or whole roller bearing scene), not a set or a shaft")
    return dataclasses.replace(scene, values={**scene.values, "effects.stiffness": True})


@dataclasses.dataclass(frozen=True)
class StiffnessTable:
    """The 5×5 stiffness [N/m, N/rad, N·m/m, N·m/rad] of a bearing at each inner-ring speed `speeds`
    (n,) [rad/s] and force `forces` (m, 3) [N]: `stiffness` (n, m, 5, 5)."""

    speeds: np.ndarray
    forces: np.ndarray
    stiffness: np.ndarray

    def save(self, path) -> Path:
        """Write the table to `path`: ".npz" (arrays speeds, forces, stiffness and their units) or
        ".csv" (one row per speed and force, a column per entry K_ij with its unit in the header)."""
        path = _export_path(path)
        units = [_unit(i, j) for i in range(5) for j in range(5)]
        if path.suffix == ".npz":
            np.savez(path, speeds=self.speeds, forces=self.forces, stiffness=self.stiffness, speed_unit="rad/s",
                     force_unit="N", stiffness_units=np.array(units).reshape(5, 5))
            return path
        names = [f"K_{DOFS[i]}{DOFS[j]}" for i in range(5) for j in range(5)]
        header = ["speed [rad/s]", "Fx [N]", "Fy [N]", "Fz [N]"] + [f"{n} [{u}]" for n, u in zip(names, units)]
        rows = [[speed, *force, *matrix.ravel()] for speed, by_force in zip(self.speeds, self.stiffness)
                for force, matrix in zip(self.forces, by_force)]
        np.savetxt(path, np.asarray(rows), delimiter=",", header=",".join(header), comments="", fmt="%.10e")
        return path

    def ross_element(self, node: int, *, tag: str | None = None, damping: float = 0.0, force: int = 0):
        """A `ross.BearingElement` at rotor node `node` with k_xx, k_xy, k_yx, k_yy [N/m] over the
        speeds at force number `force` (ROSS interpolates them and evaluates them at the rotor
        speed). Damping is not modelled: c_xx = c_yy = `damping` [N·s/m]."""
        ross = import_ross()
        stiffness = self.stiffness[:, force]
        coefficient = {name: stiffness[:, i, j].tolist() for name, (i, j) in
                       (("kxx", (0, 0)), ("kxy", (0, 1)), ("kyx", (1, 0)), ("kyy", (1, 1)))}
        zeros = [float(damping)] * len(self.speeds)
        return ross.BearingElement(n=node, **coefficient, cxx=zeros, cyy=zeros, frequency=self.speeds.tolist(), tag=tag)


def stiffness_over_speed(scene, speeds, forces=None, progress: bool = False) -> StiffnessTable:
    """The `StiffnessTable` of the scene's bearing (a path, a packaged example's name or a loaded
    `Scene`) with the inner ring at each speed [rad/s] and under each force [Fx, Fy, Fz] [N] (default:
    the scene's), as one vmapped sweep; ValueError where an equilibrium did not converge."""
    scene = _stiffness_scene(scene)
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    if speeds.ndim != 1:
        raise ValueError(f"speeds: a list of inner-ring speeds [rad/s], got shape {speeds.shape}")
    forces = np.asarray(scene.values["operating.force"] if forces is None else forces, dtype=float).reshape(-1, 3)
    result = run_sweep(build_model(scene), {"operating.inner_speed": speeds, "operating.force": forces},
                       progress=progress)
    converged = np.asarray(result.values["converged"], dtype=bool)
    if not converged.all():
        failed = [f"{speeds[i]:g} rad/s with {forces[j].tolist()} N" for i, j in zip(*np.nonzero(~converged))]
        raise ValueError(f"the bearing's equilibrium did not converge at {', '.join(failed[:5])}"
                         + (f" and {len(failed) - 5} more" if len(failed) > 5 else ""))
    return StiffnessTable(speeds, forces, np.asarray(result.values["stiffness"]))


def _export_path(path) -> Path:
    path = Path(path)
    if path.suffix not in (".npz", ".csv"):
        raise ValueError(f"path: a .npz or .csv file, got {str(path)!r}")
    return path


def _unit(row: int, column: int) -> str:
    return f"{_ROW_UNITS[row]}/{_COLUMN_UNITS[column]}"


def export_stiffness(scene, speeds, path, forces=None) -> Path:
    """Write the scene's `StiffnessTable` over speeds [rad/s] and forces [N] to a .npz or .csv `path`."""
    path = _export_path(path)  # before the sweep
    return stiffness_over_speed(scene, speeds, forces).save(path)


@contextlib.contextmanager
def _quiet_stdout():
    """Silence file descriptor 1 (ROSS's compressor dependency prints a banner from C on import)."""
    sys.stdout.flush()
    saved, null = os.dup(1), os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(null)
        os.close(saved)


def import_ross():
    """The `ross` module (package ross-rotordynamics, extra "ross"), imported quietly."""
    try:
        with _quiet_stdout():
            import ross
    except ImportError as error:
        raise ImportError("to_ross needs ROSS: pip install -e \".[ross]\" (package ross-rotordynamics)") from error
    return ross


def to_ross(scene, speeds, node: int, *, tag: str | None = None, damping: float = 0.0):
    """A `ross.BearingElement` at rotor node `node` with the scene's exact speed-dependent k_xx, k_xy,
    k_yx, k_yy [N/m] at `speeds` [rad/s] under the scene's force (`StiffnessTable.ross_element`)."""
    return stiffness_over_speed(scene, speeds).ross_element(node, tag=tag, damping=damping)
