"""Roller–raceway contact: Love's coefficients, DC-FFT, the Polonsky–Keer solver against Hertz,
edge effects, logarithmic profiles, the crowning paper's findings, derivatives and hard cases."""

from pathlib import Path

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import pytest
from scipy import integrate

from diffbearing import build_model, load_scene, run_model
from diffbearing.bearings.roller.roller_contact import roller_contact
from diffbearing.bearings.roller.roller_geometry import RollerLoading, roller_bearing, roller_modulus
from diffbearing.bearings.roller.roller_profile import roller_profile
from diffbearing.contact import hertz
from diffbearing.contact.influence import deflection, influence_coefficients, love_rectangle
from diffbearing.params import Material

from .helpers import assert_jvp_matches_central_difference, example_scene

GCR15 = Material(207e9, 0.29, 7830.0)  # the crowning paper: E = 207 GPa, ν = 0.29
LENGTH, DIAMETER, LOAD = 12e-3, 10e-3, 1000.0

solve = jax.jit(roller_contact, static_argnames=("grid", "method", "tolerance", "max_iterations"))


def cylindrical(kind="straight", length=LENGTH, **profile):
    return roller_bearing(kind="cylindrical_roller", length=length, diameter=DIAMETER, material=GCR15,
                          profile=roller_profile(kind, length=length, **profile))


def pressure_along(result):
    """Peak pressure across the contact (max over x) at each y [Pa]."""
    return np.asarray(result.pressure).max(axis=0)


# --- influence coefficients ----------------------------------------------------------------


@pytest.mark.parametrize("x, y", [(0.0, 0.0), (1.5e-3, 0.0), (0.7e-3, -2.3e-3), (-4e-3, 3e-3)])
def test_love_rectangle_matches_numerical_integration(x, y):
    a, b = 0.5e-3, 1.2e-3

    def strip(xp):  # ∫ dy'/r over −b..b in closed form; the x' quadrature is numerical
        gap = abs(x - xp)
        return np.arcsinh((y + b) / gap) - np.arcsinh((y - b) / gap)

    numeric, _ = integrate.quad(strip, -a, a, points=[x] if abs(x) < a else None, epsabs=1e-14, epsrel=1e-12,
                                limit=200)
    assert float(love_rectangle(x, y, a, b)) == pytest.approx(numeric, rel=1e-8)


def test_dc_fft_deflection_equals_direct_summation():
    nx, ny, dx, dy, modulus = 6, 9, 1e-5, 3e-5, 2.26e11
    pressure = jax.random.uniform(jax.random.PRNGKey(0), (nx, ny)) * 1e9
    coefficients = influence_coefficients(nx, ny, dx, dy, modulus)
    fast = deflection(jnp.fft.rfft2(coefficients), pressure)
    xs, ys = np.arange(nx) * dx, np.arange(ny) * dy
    direct = np.zeros((nx, ny))
    for i in range(nx):
        for j in range(ny):
            kernel = 2 / (np.pi * modulus) * love_rectangle(xs[i] - xs[:, None], ys[j] - ys[None, :], dx / 2, dy / 2)
            direct[i, j] = np.sum(kernel * pressure)
    np.testing.assert_allclose(fast, direct, rtol=1e-12)


# --- validation against Hertz ---------------------------------------------------------------


def test_fully_crowned_roller_matches_exact_hertz_point_contact():
    """A roller crowned over its whole length (flat length 0, Rc = 100 mm) on a flat raceway is a
    Hertz point contact with Rx = D/2, Ry = Rc (Johnson ch. 4): peak pressure and approach within
    1 % at ≥ 20 cells per semi-axis."""
    crown_radius = 0.1
    bearing = cylindrical("circular", flat_length=0.0, crown_radius=crown_radius)
    rx, ry = DIAMETER / 2, crown_radius
    exact = hertz.point_contact(LOAD, 1 / rx + 1 / ry, (1 / rx - 1 / ry) / (1 / rx + 1 / ry), roller_modulus(bearing))
    result = solve(bearing, RollerLoading(LOAD, 0.0, 0.0), grid=(64, 256))
    cell_x, cell_y = float(result.x[1] - result.x[0]), float(result.y[1] - result.y[0])
    assert float(exact.semi_minor_axis) / cell_x >= 20 and float(exact.semi_major_axis) / cell_y >= 20
    assert bool(result.converged)
    assert float(result.max_pressure) == pytest.approx(float(exact.max_pressure), rel=0.01)
    assert float(result.approach) == pytest.approx(float(exact.approach), rel=0.01)
    assert float(result.load) == pytest.approx(LOAD, rel=1e-12)  # the load constraint is exact


def test_long_crowned_roller_mid_length_matches_hertz_line_contact():
    """Mid-length of a 30 mm roller with a 24 mm flat: plane strain, so the pressure across x is
    Hertz's line contact for the local load per length w = Σ p dx (Johnson eq. 4.43), to 1 %."""
    bearing = cylindrical("circular", length=0.03, flat_length=0.024, crown_radius=0.05)
    result = solve(bearing, RollerLoading(3000.0, 0.0, 0.0), grid=(128, 256))
    middle = np.asarray(result.pressure)[:, 128]
    cell_x = float(result.x[1] - result.x[0])
    line = hertz.line_contact(middle.sum() * cell_x, DIAMETER / 2, roller_modulus(bearing))
    assert middle.max() == pytest.approx(float(line.max_pressure), rel=0.01)
    assert 0.5 * np.count_nonzero(middle) * cell_x == pytest.approx(float(line.half_width), rel=0.01)


def test_straight_roller_edge_peak_grows_with_refinement():
    """Edge loading (Johnson §5.5): at the end of a straight roller the pressure is singular, so the
    computed peak keeps growing as cells shrink (grid dependent, never converged) while the
    mid-length pressure converges."""
    peaks, middles = [], []
    for ny in (64, 128, 256):
        along = pressure_along(solve(cylindrical(), RollerLoading(LOAD, 0.0, 0.0), grid=(32, ny)))
        peaks.append(along.max())
        middles.append(along[ny // 2])
    assert peaks[1] / peaks[0] > 1.15 and peaks[2] / peaks[1] > 1.15
    assert middles[2] == pytest.approx(middles[0], rel=2e-3)
    assert peaks[0] > 1.3 * middles[0]


@pytest.mark.parametrize("kind", ["lundberg", "johns_gohar"])
def test_logarithmic_profile_at_its_design_load_is_nearly_uniform(kind):
    """Lundberg's profile is the deflection of a uniform finite line load, so at its design load
    the pressure along the roller is flat: within 1 % over the middle 90 % of the length."""
    bearing = cylindrical(kind, design_load=LOAD)
    result = solve(bearing, RollerLoading(LOAD, 0.0, 0.0), grid=(32, 256))
    along, y = pressure_along(result), np.asarray(result.y)
    inner = along[np.abs(y) <= 0.45 * LENGTH]
    assert inner.max() / inner.min() < 1.01
    line = hertz.line_contact(LOAD / LENGTH, DIAMETER / 2, roller_modulus(bearing))
    assert inner.mean() == pytest.approx(float(line.max_pressure), rel=0.01)  # Hertz p0 at Q/l


# --- the crowning paper through the scene layer ---------------------------------------------


@pytest.fixture(scope="module")
def crowning_paper_profiles():
    """The crowning paper's tapered roller at 1 kN with three profiles; circular: 6 mm flat + 100 mm arc."""
    results = {}
    for kind, extra in (("straight", []), ("circular", ['profile.flat_length="6 mm"', 'profile.crown_radius="100 mm"']),
                        ("johns_gohar", [])):
        scene = load_scene(example_scene("tapered_roller"), [f'profile.kind="{kind}"', *extra])
        results[kind] = run_model(build_model(scene), progress=False).values
    return results


def test_crowning_paper_findings(crowning_paper_profiles):
    """The crowning paper, Fig. 12: straight rollers show edge stress peaks; arc crowning raises the central
    peak above the straight and logarithmic rollers; the logarithmic profile is near uniform."""
    along = {kind: np.asarray(v["contact.pressure"]).max(axis=0) for kind, v in crowning_paper_profiles.items()}
    middle = {kind: a[len(a) // 2] for kind, a in along.items()}
    assert along["straight"].max() > 1.5 * middle["straight"]  # edge peak
    assert middle["circular"] > 1.2 * middle["straight"] and middle["circular"] > 1.2 * middle["johns_gohar"]
    assert float(crowning_paper_profiles["circular"]["contact.max_pressure"]) > float(
        crowning_paper_profiles["johns_gohar"]["contact.max_pressure"])
    y = np.asarray(crowning_paper_profiles["johns_gohar"]["contact.y"])
    inner = along["johns_gohar"][np.abs(y) <= 0.45 * LENGTH]
    assert inner.max() / inner.min() < 1.06  # near uniform; the small end carries a little more
    assert inner[0] > inner[-1]  # the crowning paper, Fig. 13: small end slightly above the large end
    for values in crowning_paper_profiles.values():
        assert bool(values["contact.converged"]) and float(values["contact.load"]) == pytest.approx(1000.0, rel=1e-12)


def test_crowned_roller_peak_is_grid_converged():
    """A crowned roller's peak converges with the grid, unlike a straight one (docs/theory.md,
    §Numerical notes)."""
    bearing = cylindrical("circular", flat_length=6e-3, crown_radius=0.1)
    peaks = [float(solve(bearing, RollerLoading(LOAD, 0.0, 0.0), grid=grid).max_pressure)
             for grid in ((32, 128), (64, 512))]
    assert peaks[1] == pytest.approx(peaks[0], rel=0.01)


def test_slices_level_matches_the_numerical_solution_where_the_roller_is_uniform():
    """The Hertz-slice level (Palmgren laminae) against the numerical solution at mid-length of a
    logarithmic roller: within 5 % in pressure and approach (benchmarks report the errors)."""
    bearing = cylindrical("johns_gohar", design_load=LOAD)
    loading = RollerLoading(LOAD, 0.0, 0.0)
    fine = solve(bearing, loading, grid=(32, 256))
    fast = solve(bearing, loading, grid=(32, 256), method="slices")
    assert pressure_along(fast)[128] == pytest.approx(pressure_along(fine)[128], rel=0.05)
    assert float(fast.approach) == pytest.approx(float(fine.approach), rel=0.15)
    assert float(fast.load) == pytest.approx(LOAD, rel=1e-10)


# --- derivatives ------------------------------------------------------------------------------


def _design_function(method, grid=(16, 64)):
    """(zm [µm], K1, load [kN], tilt [mrad]) → (peak pressure [GPa], approach [µm], one cell [GPa])."""
    base = cylindrical("fujiwara_kawase", design_load=LOAD, k1=1.0, k2=0.5, zm=0.5e-6)

    def function(parameters):
        zm, k1, load, tilt = parameters
        bearing = eqx.tree_at(lambda b: (b.profile.zm, b.profile.k1), base, (zm * 1e-6, k1))
        result = roller_contact(bearing, RollerLoading(load * 1e3, tilt * 1e-3, 0.0), grid, method)
        return jnp.stack([result.max_pressure / 1e9, result.approach * 1e6, result.pressure[8, 32] / 1e9])

    return jax.jit(function)


@pytest.mark.parametrize("method", ["influence", "slices"])
def test_gradients_match_central_differences(method):
    """Implicit derivative on the converged active set (influence) or through the lamina root
    (slices), forward and reverse, against central differences at a point where the active set
    does not change within the step."""
    function = _design_function(method)
    point = jnp.array([0.5, 1.0, 1.0, 0.2])
    for direction in jnp.eye(4):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-5, rtol=2e-4, atol=1e-9)


# --- hard cases -----------------------------------------------------------------------------


@pytest.mark.parametrize("case", ["one_end_lifted", "light_load", "concave_raceway", "straight_tilted"])
def test_hard_cases_converge_with_finite_gradients(case):
    """Tilt that unloads one end, a 1 N load, a concave raceway, a tilted straight roller: the
    solver converges inside its grid, values and gradients are finite. The 1 N load and the concave
    raceway are tilted by 1 µrad: at zero tilt symmetric cells share the maximum pressure, where
    d p_max/d tilt is a kink and forward and reverse mode may pick either side (they did under
    XLA's loop emitters, and on the concave raceway on a cold compilation cache)."""
    bearing, load, tilt, curvature = {
        "one_end_lifted": (cylindrical("johns_gohar", design_load=LOAD), 200.0, 2e-3, 0.0),
        "light_load": (cylindrical("circular", flat_length=4e-3, crown_radius=0.05), 1.0, 1e-6, 1 / 0.02),
        "concave_raceway": (cylindrical("lundberg", design_load=LOAD), LOAD, 1e-6, -1 / 0.03),
        "straight_tilted": (cylindrical(), LOAD, 5e-4, 0.0),
    }[case]

    for method in ("influence", "slices"):
        def peak(load_and_tilt):
            loading = RollerLoading(load_and_tilt[0], load_and_tilt[1], curvature)
            result = roller_contact(bearing, loading, (16, 64), method)
            return jnp.stack([result.max_pressure, result.approach]), result

        point = jnp.array([load, tilt])
        forward, result = jax.jit(jax.jacfwd(peak, has_aux=True))(point)
        reverse, _ = jax.jit(jax.jacrev(peak, has_aux=True))(point)
        values = jnp.stack([result.max_pressure, result.approach])
        assert bool(result.converged), method
        assert np.all(np.isfinite(np.asarray(values))) and np.all(np.asarray(result.pressure) >= 0)
        assert np.all(np.isfinite(np.asarray(forward))) and np.all(np.isfinite(np.asarray(reverse))), method
        # relative sensitivities (per unit relative load, per mrad of tilt) agree between modes
        scale = np.array([load, 1e-3])[None, :] / np.asarray(values)[:, None]
        np.testing.assert_allclose(forward * scale, reverse * scale, rtol=1e-8, atol=1e-9)
        if case == "one_end_lifted":
            assert float(result.contact_length) < LENGTH  # the +y end is out of contact


def test_bad_roller_input_names_the_parameter():
    with pytest.raises(ValueError, match="contact.load"):
        RollerLoading(-5.0, 0.0, 0.0)
    with pytest.raises(ValueError, match="profile.crown_radius"):
        roller_profile("circular", length=LENGTH, flat_length=4e-3, crown_radius=3e-3)
    with pytest.raises(ValueError, match="profile.zm"):
        roller_profile("fujiwara_kawase", length=LENGTH, design_load=LOAD, k1=1.0, k2=0.5)
    with pytest.raises(ValueError, match="bearing.roller_large_diameter"):
        roller_bearing(kind="tapered_roller", length=LENGTH, small_diameter=8e-3, large_diameter=7e-3,
                       cone_half_angle=0.04)



# --- the command ------------------------------------------------------------------------------


def test_cli_runs_tapered_roller_with_json_and_pressure_map(capsys, tmp_path):
    import json

    from diffbearing.app import cli

    scene, path, plot = example_scene("tapered_roller"), tmp_path / "c.json", tmp_path / "p.png"
    code = cli.main(["run", str(scene), "--json", str(path), "--plot", str(plot)])
    out = capsys.readouterr().out
    assert code == 0
    assert "peak contact pressure p_max" in out and "GPa" in out and "Polonsky–Keer): converged" in out
    contact = json.loads(path.read_text())["contact"]
    assert set(contact) == {"max_pressure", "approach", "load", "contact_length", "max_half_width", "pressure", "x",
                            "y", "converged", "iterations"}
    assert np.shape(contact["pressure"]) == (32, 256) and contact["load"] == pytest.approx(1000.0, rel=1e-12)
    assert plot.stat().st_size > 10_000
    code = cli.main(["run", str(scene), "--set", 'effects.contact="slices"'])
    assert code == 0 and "Hertz line-contact slices (Palmgren laminae, no interaction between slices): approach converged" \
        in capsys.readouterr().out


def test_cli_flat_and_concave_raceways(capsys):
    """raceway_radius = "inf" is a flat raceway; raceway = "outer" makes it concave (larger R)."""
    from diffbearing.app import cli

    scene = example_scene("tapered_roller")
    radii = {}
    for label, overrides in (("convex", []), ("flat", ['contact.raceway_radius="inf"']),
                             ("concave", ['contact.raceway="outer"'])):
        code = cli.main(["run", scene, *sum((["--set", o] for o in overrides), [])])
        out = capsys.readouterr().out
        assert code == 0
        radii[label] = float(out.split("equivalent radius R in rolling, at mid-length")[1].split()[0])
    assert radii["convex"] < radii["flat"] < radii["concave"]
    assert radii["flat"] == pytest.approx(7.5 / 2 / np.cos(np.radians(2.4)), rel=1e-4)  # R_k = D_mid/(2 cos θ)


@pytest.mark.parametrize("override, named", [
    ('contact.load="-1 kN"', "contact.load"),
    ("fidelity.grid=[32]", "fidelity.grid"),
    ("fidelity.grid=[2, 256]", "fidelity.grid"),
    ('profile.kind="circular"', "profile.flat_length"),
    ('contact.tilt="5 deg"', "contact.tilt"),
    ('effects.contact="fem"', "effects.contact"),
    ('contact.raceway_radius="-3 mm"', "contact.raceway_radius"),
])
def test_cli_bad_roller_input_exits_2(capsys, override, named):
    from diffbearing.app import cli

    code = cli.main(["run", example_scene("tapered_roller"), "--set", override])
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1


def test_roller_sweep_over_load_and_tilt(tmp_path):
    """A [sweep] over load and tilt runs as one vmapped batch: the peak grows with load and with
    tilt, every point converges and carries its own load."""
    text = Path(example_scene("tapered_roller")).read_text().replace("grid = [32, 256]", "grid = [16, 64]")
    scene_file = tmp_path / "sweep.toml"
    scene_file.write_text(text + '\n[sweep]\n"contact.load" = ["0.5 kN", "1 kN", "1.5 kN"]\n'
                                 '"contact.tilt" = ["0 deg", "0.01 deg"]\n')
    result = run_model(build_model(load_scene(str(scene_file))), progress=False)
    peak = np.asarray(result.values["contact.max_pressure"]).reshape(3, 2)
    assert np.all(np.diff(peak, axis=0) > 0) and np.all(peak[:, 1] > peak[:, 0])
    assert np.all(result.values["contact.converged"])
    np.testing.assert_allclose(np.asarray(result.values["contact.load"]).reshape(3, 2),
                               [[500.0] * 2, [1000.0] * 2, [1500.0] * 2], rtol=1e-12)


def test_raceway_edge_adds_its_curvature_to_the_crown():
    """`with_raceway_edge`: the gap beyond the flat is the circle of radius 1/(1/R_c + 1/R_e)
    (against the closed form at four points), and the drop's derivative with respect to R_e
    matches a central difference (the starved-roller example's
    10 mm crown, 12.7 mm flat, 100 mm edge)."""
    from diffbearing.bearings.roller.roller_profile import crown_drop, with_raceway_edge

    crown = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
    y = jnp.array([0.0, 6.0e-3, 6.6e-3, 7.3e-3])
    combined = 1.0 / (1.0 / 10e-3 + 1.0 / 100e-3)
    expected = combined - np.sqrt(combined**2 - np.maximum(np.abs(y) - 6.35e-3, 0.0) ** 2)
    drop = crown_drop(with_raceway_edge(crown, 100e-3), y, 14.7e-3, 2.26e11, 10e-3)
    np.testing.assert_allclose(drop, expected, rtol=1e-12, atol=1e-18)

    def drop_of_edge(edge):  # edge radius [0.1 m] → drop [µm]
        return crown_drop(with_raceway_edge(crown, 0.1 * edge), y, 14.7e-3, 2.26e11, 10e-3) * 1e6

    assert_jvp_matches_central_difference(drop_of_edge, jnp.asarray(1.0), jnp.asarray(1.0), step=1e-5, rtol=1e-6,
                                          atol=1e-12)
    with pytest.raises(ValueError, match="contact.raceway_edge_radius needs profile.kind"):
        with_raceway_edge(roller_profile("straight", length=14.7e-3), 100e-3)
