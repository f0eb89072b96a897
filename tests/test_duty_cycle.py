"""Duty cycles ([[duty]]): the Palmgren–Miner rule and its equivalent load in closed form and
against central differences, a one-case cycle equal to the single run, a two-case cycle equal to the
Miner sum of the cases run alone, the derivative of a cycle's life through the solved bearing, and
bad cycles refused naming `duty`."""

import hypothesis
import hypothesis.strategies as st
import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import cli
from diffbearing.ratings import duty_cycle

from .helpers import assert_exits_2_naming, assert_jvp_matches_central_difference, example_scene

RPM = np.pi / 30
SCENE = example_scene("gearbox_6411_ratings")  # the 6411E in oil: L10, L10r, L10m, L10rm
CASES = '''
[[duty]]
time_share = 0.7
"operating.force" = ["8 kN", "0 N", "1.5 kN"]
"operating.inner_speed" = "3000 rpm"

[[duty]]
time_share = 0.3
"operating.force" = ["14 kN", "0 N", "3 kN"]
"operating.inner_speed" = "1500 rpm"
'''
LIVES = ("life.L10", "life.L10r", "life.L10m", "life.L10rm")


def _scene(tmp_path, cycle: str):
    path = tmp_path / "duty.toml"
    path.write_text(open(SCENE).read() + cycle)
    return str(path)


def test_miner_and_the_equivalent_load_in_closed_form():
    """Two cases, 0.7 of the time at 3000 r/min and 0.3 at 1500: u = (0.8235, 0.1765), 1/L = Σ u/L
    written out, n_m = 2550 r/min; the equivalent load gives the cycle's life, (C/P)^3 = L (1e-14)."""
    shares = duty_cycle.revolution_shares(jnp.array([0.7, 0.3]), jnp.array([3000.0, 1500.0]) * RPM)
    np.testing.assert_allclose(np.asarray(shares), [2100 / 2550, 450 / 2550], rtol=1e-15)
    assert float(duty_cycle.mean_speed(jnp.array([0.7, 0.3]), jnp.array([3000.0, 1500.0]) * RPM)) == pytest.approx(
        2550 * RPM, rel=1e-15)
    rating, loads = 101e3, jnp.array([8e3, 14e3])
    lives = (rating / loads) ** 3
    life = float(duty_cycle.miner_life(lives, shares))
    assert life == pytest.approx(float(1 / (shares[0] / lives[0] + shares[1] / lives[1])), rel=1e-14)
    assert (rating / float(duty_cycle.equivalent_load(loads, shares, 3.0))) ** 3 == pytest.approx(life, rel=1e-14)
    np.testing.assert_allclose(np.asarray(duty_cycle.damage_shares(lives, shares)), np.asarray(life * shares / lives), rtol=1e-14)


@hypothesis.settings(max_examples=40, deadline=None)
@hypothesis.given(loads=st.lists(st.floats(1e2, 1e6), min_size=1, max_size=6), data=st.data())
def test_a_random_cycles_equivalent_load_gives_its_miner_life(loads, data):
    """Random cycles of 1–6 cases: the equivalent load's (C/P)^p is the Miner life of the cases'
    (C/P_i)^p (p = 3 and 10/3, 1e-12), between the lightest and heaviest case's, damage shares sum to 1."""
    weights = np.asarray(data.draw(st.lists(st.floats(0.01, 1.0), min_size=len(loads), max_size=len(loads))))
    shares, loads = weights / weights.sum(), np.asarray(loads)
    for exponent in (3.0, 10 / 3):
        lives = (2e6 / loads) ** exponent
        life = float(duty_cycle.miner_life(lives, shares))
        equivalent = float(duty_cycle.equivalent_load(loads, shares, exponent))
        assert (2e6 / equivalent) ** exponent == pytest.approx(life, rel=1e-12)
        assert lives.min() * (1 - 1e-12) <= life <= lives.max() * (1 + 1e-12)
        assert float(jnp.sum(duty_cycle.damage_shares(lives, shares))) == pytest.approx(1.0, rel=1e-12)


def test_miner_life_derivatives_match_central_differences():
    lives, shares = jnp.array([2012.3, 375.5, 900.0]), jnp.array([0.5, 0.2, 0.3])
    assert_jvp_matches_central_difference(lambda x: duty_cycle.miner_life(x, shares), lives, jnp.array([1.0, -2.0, 0.5]),
                                          1e-3, rtol=1e-8)
    assert_jvp_matches_central_difference(lambda u: duty_cycle.miner_life(lives, u), shares, jnp.array([0.1, -0.05, 0.0]),
                                          1e-6, rtol=1e-8)


def test_a_one_case_cycle_is_the_single_run(tmp_path):
    """One case at the scene's own load, revolution_share = 1: every output of the case equals the
    single run's (1e-12, the vmapped batch against the single program), and each cycle life its life."""
    single = run_model(build_model(load_scene(SCENE)), progress=False).values
    cycle = run_model(build_model(load_scene(_scene(tmp_path, '[[duty]]\nrevolution_share = 1.0\n'
                                                               '"operating.inner_speed" = "3000 rpm"\n'))),
                      progress=False).values
    for key, value in single.items():
        np.testing.assert_allclose(np.asarray(cycle[key])[0], value, rtol=1e-12, atol=1e-12 * (1 + np.abs(value).max()),
                                   err_msg=key)
    for key in LIVES:
        assert float(cycle[f"duty.{key}"]) == pytest.approx(float(single[key]), rel=1e-12)


def test_a_two_case_cycle_is_the_miner_sum_of_its_cases_run_alone(tmp_path):
    """The two cases of CASES run alone (--set), their lives combined by 1/L = Σ u/L with the
    revolutions' shares 0.7·3000 : 0.3·1500, equal the cycle's lives (1e-10); the hours at 2550 r/min;
    (C/P_eq)³ is the cycle's L10 (1e-12); the damage shares sum to 1."""
    cycle = run_model(build_model(load_scene(_scene(tmp_path, CASES))), progress=False).values
    alone = [run_model(build_model(load_scene(SCENE, overrides=[f"operating.force={force}", f"operating.inner_speed={speed}"])),
                       progress=False).values
             for force, speed in (('["8 kN", "0 N", "1.5 kN"]', '"3000 rpm"'), ('["14 kN", "0 N", "3 kN"]', '"1500 rpm"'))]
    shares = np.array([2100.0, 450.0]) / 2550.0
    for key in LIVES:
        expected = 1.0 / sum(u / float(values[key]) for u, values in zip(shares, alone))
        assert float(cycle[f"duty.{key}"]) == pytest.approx(expected, rel=1e-10)
        assert float(cycle[f"duty.hours.{key}"]) == pytest.approx(expected * 1e6 / 2550 / 60, rel=1e-10)
    rating = float(alone[0]["life.basic_dynamic_load_rating"])
    assert (rating / float(cycle["duty.equivalent_load"])) ** 3 == pytest.approx(float(cycle["duty.life.L10"]), rel=1e-12)
    assert float(np.sum(cycle["duty.damage_share"])) == pytest.approx(1.0, rel=1e-12)


def test_the_cycles_life_derivative_through_the_solved_bearing(tmp_path):
    """d L10r(cycle) / d F_x of the heavier case, through each case's solved equilibrium (the model's
    function, its implicit derivative), against a central difference (1e-6)."""
    model = build_model(load_scene(_scene(tmp_path, CASES)))
    function, duty = model.function(), model.duty
    shares = jnp.asarray([2100.0, 450.0]) / 2550.0

    def cycle_life(heavy_radial):
        lives = []
        for number in range(duty.count):
            values = dict(model.scene.values)
            force = jnp.asarray(duty.cases["operating.force"][number])
            values["operating.force"] = force.at[0].set(heavy_radial) if number == 1 else force
            values["operating.inner_speed"] = float(duty.cases["operating.inner_speed"][number])
            lives.append(function(model.inputs_from_values(values))["life.L10r"])
        return duty_cycle.miner_life(jnp.stack(lives), shares)

    assert_jvp_matches_central_difference(jax.jit(cycle_life), jnp.asarray(14e3), jnp.asarray(1.0), 1.0, rtol=1e-6)


@pytest.mark.parametrize("cycle, named", [
    (CASES.replace("time_share = 0.3", "time_share = 0.2"), "duty: the cases' time_shares sum to 0.9, not 1"),
    (CASES.replace("time_share = 0.3", "revolution_share = 0.3"), "duty: every case gives one share, all of one kind"),
    (CASES.replace('"operating.inner_speed" = "1500 rpm"', '"operating.inner_sped" = "1500 rpm"'),
     "duty[1]: unknown key 'operating.inner_sped'"),
    (CASES.replace('"operating.inner_speed" = "1500 rpm"', '"bearing.type" = "tapered_roller"'), "duty[1].bearing.type"),
    (CASES.replace('"operating.inner_speed" = "1500 rpm"', '"operating.inner_speed" = "0 rpm"'), "duty[1]: a case at standstill"),
    (CASES.replace('"14 kN", "0 N", "3 kN"', '"14 kN", "0 N", "3 kN", "1 kN"'), "duty[1]"),
    (CASES + '[sweep]\n"operating.inner_speed" = ["1000 rpm", "2000 rpm"]\n', "not both"),
    ('[[duty]]\nrevolution_share = 1.0\n', "duty: no case sets a scene key"),
])
def test_a_bad_cycle_exits_2_naming_it(capsys, tmp_path, cycle, named):
    assert_exits_2_naming(capsys, ["run", _scene(tmp_path, cycle)], named)


@pytest.mark.slow
def test_a_shafts_cycle_is_its_bearings_miner_sums_and_their_system_life():
    """gearbox_shaft_duty_cycle (three cases setting loads[0].force, .moment and shaft.speed): the
    middle case, which sets nothing, is the gearbox_shaft example itself (1e-12); each bearing's cycle
    L10 and L10r are Miner's sums of its case lives over u_i ∝ t_i n_i (1e-12), the shaft's the
    bearings' cycle L10r combined, (Σ L^(−10/9))^(−9/10) (1e-12)."""
    cycle = run_model(build_model(load_scene(example_scene("gearbox_shaft_duty_cycle"))), progress=False).values
    single = run_model(build_model(load_scene(example_scene("gearbox_shaft"), overrides=["effects.stiffness=false"])),
                       progress=False).values
    for key in ("bearings.force", "bearings.L10r", "bearings.L10", "shaft.L10r"):
        np.testing.assert_allclose(np.asarray(cycle[key])[1], single[key], rtol=1e-12, atol=1e-9, err_msg=key)
    turns = np.array([0.5 * 3000, 0.4 * 3000, 0.1 * 1500])
    shares = (turns / turns.sum())[:, None]
    for key in ("bearings.L10", "bearings.L10r"):
        np.testing.assert_allclose(cycle[f"duty.{key}"], 1.0 / np.sum(shares / np.asarray(cycle[key]), axis=0), rtol=1e-12)
    bearings = np.asarray(cycle["duty.bearings.L10r"])
    assert float(cycle["duty.shaft.L10r"]) == pytest.approx(float(np.sum(bearings ** (-10 / 9)) ** (-9 / 10)), rel=1e-12)


@pytest.mark.parametrize("change, named", [
    (('"loads[0].moment" = ["0 N*m", "45 N*m"]', '"loads[1].moment" = ["0 N*m", "45 N*m"]'),
     "duty[0].loads[1].moment: the scene has no [[loads]] entry 1"),
    (('"loads[0].moment" = ["0 N*m", "45 N*m"]', '"loads[0].moment" = ["45 N*m"]'), "duty[0].loads[0].moment: expected a list"),
])
def test_a_bad_shaft_case_exits_2_naming_it(capsys, tmp_path, change, named):
    path = tmp_path / "shaft.toml"
    path.write_text(open(example_scene("gearbox_shaft_duty_cycle")).read().replace(*change))
    assert_exits_2_naming(capsys, ["run", str(path)], named)


@pytest.mark.slow
def test_a_sets_cycle_combines_its_bearings_cycle_lives(tmp_path):
    """spindle_pair over two cases by revolutions: each bearing's cycle L10r is the Miner sum of its
    case lives (1e-12), the set's the bearings' cycle lives combined, (Σ L^(−10/9))^(−9/10) (1e-12),
    which is not Miner's sum of the set's case lives."""
    path = tmp_path / "pair.toml"
    path.write_text(open(example_scene("spindle_pair")).read() + '''
[[duty]]
revolution_share = 0.6
"operating.force" = ["2 kN", "0 N", "1 kN"]

[[duty]]
revolution_share = 0.4
"operating.force" = ["4 kN", "0 N", "0.5 kN"]
''')
    values = run_model(build_model(load_scene(str(path), overrides=["effects.life=true"])), progress=False).values
    shares = np.array([0.6, 0.4])
    bearings = []
    for number in range(2):
        key = f"set.bearings.{number}.L10r"
        expected = 1.0 / float(np.sum(shares / np.asarray(values[key])))
        assert float(values[f"duty.{key}"]) == pytest.approx(expected, rel=1e-12)
        bearings.append(expected)
    system = float(np.sum(np.asarray(bearings) ** (-10 / 9)) ** (-9 / 10))
    assert float(values["duty.set.L10r"]) == pytest.approx(system, rel=1e-12)
    assert abs(system / (1.0 / float(np.sum(shares / np.asarray(values["set.L10r"])))) - 1) > 1e-3


def test_the_packaged_cycle_writes_its_json_and_plot(capsys, tmp_path):
    """`diffbearing run gearbox_duty_cycle --json --plot`: exit 0; the JSON holds the cases, their time
    shares, each case's lives and the cycle's (Miner's sum of the cases' over u_i ∝ t_i n_i, 1e-12),
    at 99 % the cycle's L_n = a₁ L10; the plot is written."""
    import json

    document_path, plot_path = tmp_path / "cycle.json", tmp_path / "cycle.png"
    code = cli.main(["run", "gearbox_duty_cycle", "--json", str(document_path), "--plot", str(plot_path)])
    out = capsys.readouterr().out
    assert code == 0 and "Cycle (Palmgren–Miner" in out
    document = json.loads(document_path.read_text())
    assert document["duty"]["time_share"] == [0.6, 0.3, 0.1] and len(document["duty"]["cases"]["operating.force"]) == 3
    turns = np.array([0.6 * 3000, 0.3 * 3000, 0.1 * 1500])
    shares = turns / turns.sum()
    np.testing.assert_allclose(document["duty"]["revolution_share"], shares, rtol=1e-14)
    cases = np.asarray(document["life"]["L10"])
    assert document["duty"]["life"]["L10"] == pytest.approx(1 / float(np.sum(shares / cases)), rel=1e-12)
    factor = 0.95 * (np.log(100 / 99) / np.log(100 / 90)) ** (2 / 3) + 0.05
    assert document["duty"]["life"]["Ln"] == pytest.approx(factor * document["duty"]["life"]["L10"], rel=1e-12)
    assert plot_path.stat().st_size > 10_000


def test_a_case_sets_its_oils_temperature(tmp_path):
    """A case of gearbox_duty_cycle at 90 °C instead of 70 °C: its viscosity, κ and L10rm are the single
    run's at that temperature and load (1e-12), the other cases' unchanged."""
    path = tmp_path / "hot.toml"
    path.write_text(open(example_scene("gearbox_duty_cycle")).read().replace(
        '"operating.force" = ["16 kN", "0 N", "3.2 kN"]', '"operating.force" = ["16 kN", "0 N", "3.2 kN"]\n'
                                                        '"lubricant.temperature" = "90 degC"'))
    cycle = run_model(build_model(load_scene(str(path))), progress=False).values
    alone = run_model(build_model(load_scene(example_scene("gearbox_duty_cycle"), overrides=[
        'lubricant.temperature="90 degC"', 'operating.force=["16 kN", "0 N", "3.2 kN"]', 'operating.inner_speed="1500 rpm"'])),
        progress=False).values
    for key in ("life.kinematic_viscosity", "life.viscosity_ratio", "life.L10rm"):
        assert float(np.asarray(cycle[key])[2]) == pytest.approx(float(np.asarray(alone[key])[2]), rel=1e-12)
    assert float(np.asarray(cycle["life.kinematic_viscosity"])[0]) > float(np.asarray(cycle["life.kinematic_viscosity"])[2])
