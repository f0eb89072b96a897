"""Sweeps: grids under vmap, batch axes in JSON, agreement with single runs, sharding over devices."""

import json
import os
import socket
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli, stored_models

from .helpers import BEARING_6411E, example_scene

SCENE = BEARING_6411E + textwrap.dedent("""
    [operating]
    force = ["5 kN", "0 N", "2 kN"]
    [effects]
    stiffness = true
    life = true
    [sweep]
    "operating.inner_speed" = [0, "3000 rpm"]
    "operating.force" = { start = ["2 kN", "0 N", "2 kN"], stop = ["8 kN", "0 N", "2 kN"], num = 3 }
""")


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("sweep") / "sweep.toml"
    path.write_text(SCENE)
    return path


@pytest.fixture(scope="module")
def swept(scene_file):
    return run_model(build_model(load_scene(str(scene_file))), progress=False)


def test_grid_shape_and_single_point_agreement(swept, scene_file):
    assert swept.values["displacement"].shape == (2, 3, 5)
    assert swept.values["stiffness"].shape == (2, 3, 5, 5)
    assert swept.values["balls.inner.load"].shape == (2, 3, 7)
    assert np.all(swept.values["converged"])
    # the (1, 2) point — 3000 r/min, Fx = 8 kN — equals a single run of that scene
    single_file = scene_file.parent / "single.toml"
    single_file.write_text(SCENE.split("[sweep]")[0])
    single = run_model(build_model(load_scene(str(single_file), [
        "operating.inner_speed=3000 rpm", 'operating.force=["8 kN", "0 N", "2 kN"]']))).values
    np.testing.assert_allclose(swept.values["displacement"][1, 2], single["displacement"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(swept.values["life.L10r"][1, 2], single["life.L10r"], rtol=1e-9)


def test_sweep_json_has_batch_axes(capsys, scene_file, tmp_path):
    path = tmp_path / "sweep.json"
    assert cli.main(["run", str(scene_file), "--json", str(path)]) == 0
    document = json.loads(path.read_text())
    assert np.shape(document["displacement"]) == (2, 3, 5)
    np.testing.assert_allclose(document["sweep"]["operating.inner_speed"], [0.0, 100 * np.pi])
    np.testing.assert_allclose(np.array(document["sweep"]["operating.force"])[:, 0], [2e3, 5e3, 8e3])
    assert "Sweep over 2 × 3 = 6 points" in capsys.readouterr().out


def test_a_sweep_is_stored_and_a_second_run_loads_it_without_tracing(swept, scene_file, monkeypatch):
    """The sweep's batch, stored by its first run (stored_models.py), is loaded by the next run of
    the same scene: nothing is traced and exported again, and the values are the same."""
    def no_export(*args, **kwargs):
        raise AssertionError("the stored sweep was traced again")

    monkeypatch.setattr(stored_models.export, "export", no_export)
    again = run_model(build_model(load_scene(str(scene_file))), progress=False)
    for key in ("displacement", "stiffness", "life.L10r"):
        np.testing.assert_array_equal(again.values[key], swept.values[key])


def test_bad_sweep_entries_exit_2(capsys, scene_file):
    for override, message in (("sweep.x=1", "sweep.x: unknown key 'x'"),):
        assert cli.main(["run", str(scene_file), "--set", override]) == 2
        assert message in capsys.readouterr().err
    bad = scene_file.parent / "bad.toml"
    bad.write_text(SCENE.replace('"operating.inner_speed" = [0, "3000 rpm"]', '"bearing.balls" = [7, 8]'))
    assert cli.main(["run", str(bad)]) == 2
    assert "sweep.bearing.balls: only numeric values can be swept" in capsys.readouterr().err


def test_sharded_sweep_matches_single_device(swept, scene_file):
    """The batch axis sharded over 4 forced host devices gives the same numbers (jax.sharding)."""
    code = textwrap.dedent(f"""
        import jax, numpy as np
        jax.config.update("jax_enable_x64", True)
        from diffbearing import build_model, load_scene, run_model
        assert len(jax.devices()) == 4
        result = run_model(build_model(load_scene({str(scene_file)!r})), progress=False)
        np.save({str(scene_file.parent / 'sharded.npy')!r}, result.values["displacement"])
    """)
    env = dict(os.environ, XLA_FLAGS=f"{os.environ.get('XLA_FLAGS', '')} --xla_force_host_platform_device_count=4")
    subprocess.run([sys.executable, "-c", code], check=True, env=env)
    sharded = np.load(scene_file.parent / "sharded.npy")
    np.testing.assert_allclose(sharded, swept.values["displacement"], rtol=1e-9, atol=1e-15)


@pytest.mark.slow
def test_sweep_of_the_starved_line_film_equals_single_runs(tmp_path):
    """A sweep through the iterative 1-D EHL solver (the starved-EHL paper's contact, line film,
    starved) runs its points one after another (`sequential_sweep`; the vmapped batch of two solves
    ran past 150 s) and each point equals a single run at that load."""
    scene = tmp_path / "line_sweep.toml"
    text = Path(example_scene("starved_roller")).read_text().replace('film = "finite_line"', 'film = "line"')
    scene.write_text(text.split("[fidelity]")[0] + '[sweep]\n"contact.load" = ["1000 N", "1600 N"]\n')
    swept = run_model(build_model(load_scene(str(scene))), progress=False).values
    assert swept["starvation.minimum"].shape == (2,) and np.all(swept["starvation.converged"])
    single_scene = tmp_path / "line_single.toml"
    single_scene.write_text(text.split("[fidelity]")[0])
    for index, load in enumerate(("1000 N", "1600 N")):
        single = run_model(build_model(load_scene(str(single_scene), [f'contact.load="{load}"'])),
                           progress=False).values
        for key in ("film.central", "starvation.central", "starvation.minimum"):
            np.testing.assert_allclose(swept[key][index], single[key], rtol=1e-9)


@pytest.mark.slow
def test_distributed_sweep_writes_the_single_process_json(scene_file, tmp_path):
    """Two processes under jax.distributed on this machine (CPU collectives through gloo) split the
    6-point grid 3 + 3 and process 0 writes the JSON of a one-process run (timings aside), bit for
    bit. All three run as a user runs them, without the tests' quick XLA settings (conftest.py):
    under those the batch of 3 and the batch of 6 differ in the last bits."""
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        port = probe.getsockname()[1]
    as_a_user = {key: value for key, value in os.environ.items() if key != "XLA_FLAGS"}
    single, distributed = tmp_path / "single.json", tmp_path / "distributed.json"
    run = [sys.executable, "-m", "diffbearing.app.cli", "run", str(scene_file), "--json"]
    subprocess.run(run + [str(single)], env=as_a_user, check=True, capture_output=True)
    command = run + [str(distributed), "--distributed", "--coordinator", f"localhost:{port}", "--processes", "2"]
    processes = [subprocess.Popen(command + ["--process-id", str(rank)], stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True, env=as_a_user) for rank in range(2)]
    outputs = [process.communicate(timeout=300)[0] for process in processes]
    assert [process.returncode for process in processes] == [0, 0], outputs
    expected, written = (json.loads(path.read_text()) for path in (single, distributed))
    assert set(written) == set(expected)
    written.pop("timing"), expected.pop("timing")
    assert written == expected


def test_a_sweep_leaves_out_the_plot_data_of_a_single_run():
    """The cage's f_inv-against-direction curves (144 cage-force evaluations, the figure's data) are
    computed in a single run but not at every point of a sweep; the swept restoring force equals
    the single run's at the same eccentricity."""
    from diffbearing import run_sweep

    single = run_model(build_model(load_scene("cage_b7005")))
    assert single.values["cage.offset_angle.restoring_force"].shape == (2, 72)
    model = build_model(load_scene("cage_b7005"))
    swept = run_sweep(model, {"cage.eccentricity": np.array([0.4, 0.8])}, progress=False)
    assert not any(key.startswith("cage.offset_angle") for key in swept.values)
    np.testing.assert_allclose(swept.values["cage.restoring_force"][1], single.values["cage.restoring_force"],
                               rtol=1e-12)
