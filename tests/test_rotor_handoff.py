"""Stiffness for rotor-dynamics codes: the 5×5 over speed and load equals the scene's own runs,
its CSV and NPZ exports carry it with units, and a ROSS rotor on two diffbearing bearings runs its
static and modal analyses with that stiffness."""

import dataclasses

import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app.rotor_handoff import export_stiffness, import_ross, stiffness_over_speed

from .helpers import BEARING_6208

RPM = np.pi / 30.0
SCENE = 'title = "6208 on a rotor"' + BEARING_6208 + """radial_clearance = "0 um"
[operating]
inner_speed = "0 rpm"
force = ["0 N", "500 N", "200 N"]
[effects]
centrifugal = true
gyroscopic = true
"""
SPEEDS = np.array([0.0, 500.0, 1000.0, 1500.0])  # rad/s


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    path = tmp_path_factory.mktemp("rotor") / "bearing.toml"
    path.write_text(SCENE)
    return load_scene(str(path))


@pytest.fixture(scope="module")
def table(scene):
    return stiffness_over_speed(scene, SPEEDS, forces=[[0.0, 500.0, 200.0], [0.0, 1000.0, 200.0]])


def test_stiffness_over_speed_is_the_scenes_own(scene, table):
    """Each point equals a plain run of the scene at that speed and force (1e-10)."""
    assert table.stiffness.shape == (4, 2, 5, 5)
    for i, j in ((2, 0), (3, 1)):
        values = dict(scene.values, **{"effects.stiffness": True, "operating.inner_speed": SPEEDS[i],
                                       "operating.force": table.forces[j]})
        single = run_model(build_model(dataclasses.replace(scene, values=values)), progress=False).values
        np.testing.assert_allclose(table.stiffness[i, j], single["stiffness"], rtol=1e-10,
                                   atol=1e-10 * np.abs(single["stiffness"]).max())
    assert not np.allclose(table.stiffness[0, 0, :2, :2], table.stiffness[3, 0, :2, :2], rtol=1e-3)


def test_exports_carry_the_matrices_with_units(scene, table, tmp_path):
    npz = np.load(table.save(tmp_path / "k.npz"))
    np.testing.assert_array_equal(npz["stiffness"], table.stiffness)
    assert str(npz["stiffness_units"][0, 3]) == "N/rad" and str(npz["stiffness_units"][3, 0]) == "N*m/m"
    path = table.save(tmp_path / "k.csv")
    header = path.read_text().splitlines()[0].split(",")
    assert header[:4] == ["speed [rad/s]", "Fx [N]", "Fy [N]", "Fz [N]"] and header[4] == "K_xx [N/m]"
    rows = np.loadtxt(path, delimiter=",", skiprows=1)
    assert rows.shape == (8, 4 + 25)
    np.testing.assert_allclose(rows[:, 4:].reshape(4, 2, 5, 5), table.stiffness, rtol=1e-10)
    with pytest.raises(ValueError, match="path"):
        export_stiffness(scene, SPEEDS, tmp_path / "k.txt")
    with pytest.raises(ValueError, match="without a \\[sweep\\]"):
        stiffness_over_speed(dataclasses.replace(scene, sweep={"operating.inner_speed": [0.0]}), SPEEDS)


@pytest.mark.slow
def test_ross_rotor_on_two_diffbearing_bearings(scene, table):
    """A 0.5 m, Ø40 mm steel shaft with a 7.8 kg disk on two 6208s: ROSS's bearing elements hold the
    exact k_xx, k_xy, k_yx, k_yy at the given speeds (its spline, 1e-6); the static analysis carries
    the weight; the first bending mode lies below the same rotor's on rigid supports and above
    its on bearings half as stiff."""
    ross = import_ross()
    steel = ross.materials.steel
    shaft = [ross.ShaftElement(L=0.5 / 6, idl=0.0, odl=0.04, material=steel) for _ in range(6)]
    width = 7.8 / (steel.rho * np.pi * (0.2**2 - 0.04**2) / 4)
    disk = ross.DiskElement.from_geometry(n=3, material=steel, width=width, i_d=0.04, o_d=0.2)
    bearings = [table.ross_element(node, tag=f"6208 at node {node}") for node in (0, 6)]
    for speed, matrix in zip(SPEEDS, table.stiffness[:, 0]):
        np.testing.assert_allclose(bearings[0].K(speed)[:2, :2], matrix[:2, :2], rtol=1e-6)
    rotor = ross.Rotor(shaft, [disk], bearings)
    rotor.run_static()
    reactions = sum(abs(float(v)) for v in rotor.bearing_forces_nodal.values())
    assert reactions == pytest.approx(rotor.m * 9.8065, rel=1e-6)

    def first_mode(elements):
        return float(ross.Rotor(shaft, [disk], elements).run_modal(speed=0.0, num_modes=8).wn[0])

    def scaled(factor):
        k = table.stiffness[:, 0] * factor
        return [ross.BearingElement(n=node, kxx=k[:, 0, 0].tolist(), kxy=k[:, 0, 1].tolist(), kyx=k[:, 1, 0].tolist(),
                                    kyy=k[:, 1, 1].tolist(), cxx=[0.0] * 4, frequency=SPEEDS.tolist()) for node in (0, 6)]

    ours = float(rotor.run_modal(speed=0.0, num_modes=8).wn[0])
    assert first_mode(scaled(0.5)) < ours < first_mode(scaled(1e4))
    assert ours == pytest.approx(first_mode(scaled(1.0)), rel=1e-9)
