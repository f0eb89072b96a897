"""Starved line-contact EHL from an inlet oil layer and the starvation and Moes formulas."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.film.film_formulas import moes_line_central, starved_film
from diffbearing.film.line_ehl import density_ratio, line_film, moes_load_parameter

from .helpers import assert_jvp_matches_central_difference
from .test_film_formulas import STARVED_EHL_LINE, STARVED_EHL_LOAD_PER_LENGTH, starved_ehl_entrainment_speed

NODES = 129  # one compiled starved solver serves every test of this module


@pytest.fixture(scope="module")
def starved():
    """The starved-EHL paper's contact at 129 nodes as a function of (oil layer [µm], speed factor)."""
    speed = starved_ehl_entrainment_speed()

    @jax.jit
    def solve(oil_layer, speed_factor):
        return line_film(STARVED_EHL_LOAD_PER_LENGTH, speed=speed * speed_factor, nodes=NODES,
                         oil_layer=oil_layer * 1e-6, **STARVED_EHL_LINE)

    return solve


@pytest.fixture(scope="module")
def flooded():
    return jax.jit(lambda: line_film(STARVED_EHL_LOAD_PER_LENGTH, speed=starved_ehl_entrainment_speed(), nodes=NODES,
                                     **STARVED_EHL_LINE))()


def test_supply_above_the_flooded_flux_leaves_the_film_flooded(starved, flooded):
    """Mass conservation in steady pure rolling: the contact passes ρ̄h − (ρh³/12ηu)p' = h_oil.
    A flooded contact passes q_ff; a layer above q_ff gives the flooded film (to round-off: the two
    are separate compilations, whose floating-point reductions may differ in the last bit), a layer
    below moves the meniscus inside the domain and thins the film."""
    central_pressure = float(jnp.max(flooded.pressure))
    flux = float(density_ratio(central_pressure)) * float(flooded.central)  # ≈ q_ff, within a few %
    above = starved(1.1 * flux * 1e6, 1.0)
    assert float(above.central) == pytest.approx(float(flooded.central), rel=1e-13)
    assert float(above.meniscus) == float(flooded.meniscus)
    below = starved(0.8 * flux * 1e6, 1.0)
    assert bool(below.converged) and float(below.meniscus) > float(flooded.meniscus)
    assert float(below.central) < 0.9 * float(flooded.central)


def test_starved_film_follows_the_supply_and_never_exceeds_it(starved, flooded):
    """The starved-EHL paper's trends (docs/papers.md §The starved-EHL paper): less oil → thinner
    film and a pressure build-up that starts closer to the Hertz zone; more speed under starvation → the film approaches but never
    exceeds the supply layer. Here h_oil = 0.8 µm, speeds ×1 and ×4."""
    films = [starved(layer, 1.0) for layer in (1.2, 0.8, 0.4)]
    assert all(bool(film.converged) for film in films)
    centrals = [float(film.central) for film in films]
    menisci = [float(film.meniscus) for film in films]
    assert centrals[0] > centrals[1] > centrals[2] and menisci[0] < menisci[1] < menisci[2]
    fast = starved(0.8, 4.0)
    assert centrals[1] < float(fast.central) < 0.8e-6


@pytest.mark.slow  # a 2-D film's hard case: CI's slow suite (the default run's time)
def test_severe_starvation_converges_with_finite_gradients(starved, flooded):
    """Hard case: an oil layer a tenth of the flooded film. The film is about the layer over the
    density ratio; values and gradients (oil layer, speed) are finite."""
    layer = 0.1 * float(flooded.central) * 1e6
    result = starved(layer, 1.0)
    assert bool(result.converged) and np.all(np.isfinite(np.asarray(result.pressure)))
    assert 0.5 * layer * 1e-6 < float(result.central) < layer * 1e-6
    gradient = jax.jit(jax.grad(lambda x: starved(x[0], x[1]).minimum))(jnp.array([layer, 1.0]))
    assert np.all(np.isfinite(np.asarray(gradient))) and float(gradient[0]) > 0


@pytest.mark.slow
def test_starved_film_derivatives_match_central_differences():
    """Implicit derivative (the meniscus joins the unknowns with the flux equation) of central and
    minimum film with respect to load, speed, viscosity and oil layer, forward and reverse."""
    def films(x):  # (w [1e5 N/m], u [m/s], η0 [Pa·s], h_oil [µm]) → (h_c, h_min) [µm]
        result = line_film(x[0] * 1e5, STARVED_EHL_LINE["radius"], x[1], x[2], 2.2e-8, 2.26e11, nodes=NODES,
                           oil_layer=x[3] * 1e-6)
        return jnp.stack([result.central, result.minimum]) * 1e6

    point = jnp.array([0.80945, 2.63, 0.08, 0.8])
    function = jax.jit(films)
    for direction in jnp.eye(4):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-6, atol=1e-8)


def test_starvation_formula_limits_are_exact():
    """Chevalier's h/h_ff = r/(1 + r^γ)^{1/γ}: exactly h_ff/2^{1/γ} at r = 1, → r·h_ff for r ≪ 1,
    → h_ff for r ≫ 1."""
    flooded_film, density = 1.2e-6, 1.15
    at_one = starved_film(flooded_film, density * flooded_film, density, sharpness=2.5)
    assert float(at_one) == pytest.approx(flooded_film / 2 ** 0.4, rel=1e-14)
    assert float(starved_film(flooded_film, 1e-12, density)) == pytest.approx(1e-12 / density, rel=1e-12)
    assert float(starved_film(flooded_film, 1.0, density)) == pytest.approx(flooded_film, rel=1e-12)


def test_moes_formula_depends_on_m_and_l_only():
    """Moes' formula is H(M, L) with H = (h/R)(2U)^−½: scaling speed, viscosity, load, α and R so
    that M and L stay fixed scales h by R(2U)^½ exactly; the rigid–isoviscous limit (M ≪ 1,
    L → 0) tends to H = 3/M (Martin)."""
    radius, speed, viscosity, alpha, modulus, load = STARVED_EHL_LINE["radius"], 2.63, 0.08, 2.2e-8, 2.26e11, 8.1e4
    film = moes_line_central(load, radius, speed, viscosity, alpha, modulus)
    # U ×4 (speed ×4): keep M = W'(2U)^−½ with load ×2 and L = G(2U)^¼ with α/√2
    scaled = moes_line_central(2 * load, radius, 4 * speed, viscosity, alpha / np.sqrt(2), modulus)
    assert float(scaled) == pytest.approx(2 * float(film), rel=1e-13)
    slow_root = np.sqrt(2 * viscosity * speed / (modulus * radius))
    martin = moes_line_central(1e-4 * modulus * radius * slow_root, radius, speed, viscosity, 1e-16, modulus)
    assert float(martin) / (radius * slow_root) == pytest.approx(3.0 / 1e-4, rel=1e-3)


def test_formula_derivatives_match_central_differences():
    """Moes' central film (w, u, η₀, α) and Chevalier's starved film (h_ff, h_oil, ρ̄), forward and
    reverse, against central differences."""
    def films(x):  # (w [1e5 N/m], u [m/s], η₀ [Pa·s], α [1e-8 1/Pa], h_oil [µm]) → films [µm]
        central = moes_line_central(x[0] * 1e5, STARVED_EHL_LINE["radius"], x[1], x[2], x[3] * 1e-8, 2.26e11)
        return jnp.stack([central, starved_film(central, x[4] * 1e-6, 1.15, sharpness=20.0)]) * 1e6

    point = jnp.array([0.80945, 2.63, 0.08, 2.2, 1.3])
    for direction in jnp.eye(5):
        assert_jvp_matches_central_difference(jax.jit(films), point, direction, step=1e-6, rtol=1e-6)


@pytest.mark.slow  # 46 s with a cold compilation cache (2 cores)
def test_finite_line_derivatives_match_central_differences():
    """Implicit derivative (lax.custom_root) of the 2-D central and minimum film with respect to
    load, speed and viscosity, forward and reverse, on a small 17 × 16 grid (it converges there)."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)

    def films(x):  # (W [kN], u [m/s], η₀ [Pa·s]) → (h_c, h_min) [µm]
        result = finite_line_film(x[0] * 1e3, STARVED_EHL_LINE["radius"], x[1], x[2], 2.2e-8, 2.26e11, profile, 14.7e-3,
                                  12.7e-3, grid=(17, 16))
        return jnp.stack([result.central, result.minimum]) * 1e6

    point = jnp.array([1.028, 2.63, 0.08])
    function = jax.jit(films)
    for direction in jnp.eye(3):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-5)


@pytest.fixture(scope="module")
def starved_finite_line():
    """The starved-EHL paper's starved 2-D film on a 25 × 16 grid: (W [kN], h_oil [µm], speed factor) →
    (h_c [µm], h_min [µm], converged)."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)

    def films(x):
        result = finite_line_film(x[0] * 1e3, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed() * x[2], 0.08, 2.2e-8,
                                  2.26e11, profile, 14.7e-3, 12.7e-3, grid=(25, 16), oil_layer=x[1] * 1e-6)
        return jnp.stack([result.central * 1e6, result.minimum * 1e6, result.converged.astype(float)])

    return films


@pytest.mark.slow
def test_starved_finite_line_derivatives_match_central_differences(starved_finite_line):
    """Implicit derivative of the starved 2-D central and minimum film (a meniscus per y cell)
    with respect to load and oil layer, forward and reverse, on a 25 × 16 grid (it converges there)."""
    point = jnp.array([1.028, 0.8, 1.0])
    function = jax.jit(starved_finite_line)
    assert float(function(point)[2]) == 1.0
    for direction in jnp.eye(3)[:2]:
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-5)


@pytest.mark.slow
@pytest.mark.parametrize("load, oil_layer, speed_factor", [(2.471, 0.8, 1.0), (1.028, 0.12, 1.0), (2.471, 0.8, 5e-4)],
                         ids=["paper-heaviest-load", "tenth-of-flooded-film", "M-above-200"])
def test_starved_finite_line_hard_cases_say_so_and_stay_finite(starved_finite_line, load, oil_layer, speed_factor):
    """Hard cases of the 2-D starved solve on 25 × 16: the paper's heaviest load, an oil layer of
    0.12 µm (a tenth of the flooded film), and that load at 1/2000 of the speed (Moes M ≈ 225
    on the flat's length). Where Newton does not converge the result says so (converged = 0), and
    values and derivatives (load, oil layer, speed) are still finite numbers."""
    load_per_length = STARVED_EHL_LOAD_PER_LENGTH * load / 1.028
    moes_m = moes_load_parameter(load_per_length, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed() * speed_factor,
                                 0.08, 2.26e11)
    assert float(moes_m) > (200 if speed_factor < 1 else 0)
    point = jnp.array([load, oil_layer, speed_factor])
    values = jax.jit(starved_finite_line)(point)
    jacobian = jax.jit(jax.jacfwd(starved_finite_line))(point)
    assert float(values[2]) in (0.0, 1.0)
    assert bool(jnp.all(jnp.isfinite(values))) and bool(jnp.all(jnp.isfinite(jacobian)))


@pytest.mark.slow
@pytest.mark.parametrize("oil_layer, side_inflow", [(None, 0.0), (0.8e-6, 0.0), (0.8e-6, 1.0)],
                         ids=["flooded", "starved", "starved-side-inflow"])
def test_finite_line_jacobian_assembly_equals_forward_mode(monkeypatch, oil_layer, side_inflow):
    """The Newton's Jacobian, assembled from colored local derivatives and the influence matrix
    (`local_and_elastic_jacobian`), equals jax.jacfwd of the residual to round-off (an exact
    identity), at a perturbed start on a 17 × 9 grid, flooded and starved (meniscus unknowns),
    the meniscus balance with and without the side inflow (which couples it to the neighbours)."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film import finite_line_ehl

    newton, differences = finite_line_ehl.newton, []

    def compare_then_solve(function, unknowns, args=None, **options):
        point = unknowns * (1.0 + 0.01 * jnp.sin(jnp.arange(unknowns.size)))  # off the solution, every entry moved
        forward = jax.jacfwd(function)(point, args)
        error = jnp.max(jnp.abs(options["jacobian"](point, args) - forward)) / jnp.max(jnp.abs(forward))
        jax.debug.callback(lambda value: differences.append(float(value)), error)
        return newton(function, unknowns, args, **(options | {"max_steps": 1}))

    monkeypatch.setattr(finite_line_ehl, "newton", compare_then_solve)
    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
    jax.block_until_ready(finite_line_ehl.finite_line_film(1028.0, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed(),
                                                           0.08, 2.2e-8, 2.26e11, profile, 14.7e-3, 12.7e-3,
                                                           grid=(17, 9), oil_layer=oil_layer,
                                                           side_inflow=side_inflow))
    assert differences and max(differences) < 1e-13  # one per Newton stage run (one step each: continued)


@pytest.mark.parametrize("load_path", [(), (0.5, 0.9), (0.8, 0.6, 1.0), (0.0, 1.0)])
def test_finite_line_load_path_outside_its_range_raises(load_path):
    """A load continuation path that is not increasing fractions in (0, 1] ending at 1 is a
    ValueError naming `load_path`, raised before any solve."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
    with pytest.raises(ValueError, match="load_path"):
        finite_line_film(1028.0, STARVED_EHL_LINE["radius"], 2.63, 0.08, 2.2e-8, 2.26e11, profile, 14.7e-3, 12.7e-3,
                         grid=(17, 16), load_path=load_path)


@pytest.mark.slow
def test_finite_line_warm_start_reaches_the_cold_solution_and_carries_no_derivative():
    """A Newton started from a neighbouring solution (`start=`, 17 × 16, starved at 0.85 µm, solved
    at 0.8 µm) converges to the solution from the 1-D start, films and menisci to 1e-8, and gives
    the same ∂h_min/∂h_oil (the start is not differentiated; the derivative is the implicit one)."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)

    def solve(oil_layer, start=None):  # oil layer [µm]
        return finite_line_film(1028.0, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed(), 0.08, 2.2e-8, 2.26e11,
                                profile, 14.7e-3, 12.7e-3, grid=(17, 16), oil_layer=oil_layer * 1e-6, start=start)

    cold = jax.jit(solve)(0.8)
    neighbour = jax.jit(solve)(0.85)
    warm = jax.jit(solve)(0.8, neighbour)
    assert bool(cold.converged) and bool(warm.converged)
    assert float(neighbour.minimum) != pytest.approx(float(cold.minimum), rel=1e-3)  # the start is elsewhere
    for name in ("central", "minimum", "meniscus", "pressure"):
        np.testing.assert_allclose(getattr(warm, name), getattr(cold, name), rtol=1e-8, atol=1e-8 * float(
            jnp.max(jnp.abs(getattr(cold, name)))), err_msg=name)
    slope_cold = jax.grad(lambda h: solve(h).minimum * 1e6)(0.8)
    slope_warm = jax.grad(lambda h: solve(h, neighbour).minimum * 1e6)(0.8)
    assert float(slope_warm) == pytest.approx(float(slope_cold), rel=1e-8)
    with pytest.raises(ValueError, match="start"):
        finite_line_film(1028.0, STARVED_EHL_LINE["radius"], 2.63, 0.08, 2.2e-8, 2.26e11, profile, 14.7e-3, 12.7e-3,
                         grid=(17, 17), oil_layer=0.8e-6, start=cold)


@pytest.mark.slow  # about 80 s (2 cores)
@pytest.mark.parametrize("load", [1607.0, pytest.param(2471.0, marks=pytest.mark.extended)])
def test_finite_line_converges_flooded_from_the_coarse_grid_at_the_papers_heavier_loads(load):
    """The starved-EHL paper's roller with its raceway edge (the `starved_roller` scene), flooded,
    on 65 × 65 (the scene's default grid): from the 1-D start Newton stalls (scaled residual 2.4 at
    1607 N, and through the load stages); from the 33 × 65 solution (`coarse_grid_start`) it
    converges, with the minimum film at the roller end past the flat (6.35 mm) and the central
    film within 6 % of Pan and Hamrock's line-contact formula at the load per flat length (the
    middle of the roller is nearly an infinite line: −3.2 % at 1028 N, +2.0 % at 1607 N, +5.0 %
    at 2471 N on this grid)."""
    from diffbearing.film.film_formulas import pan_hamrock_line
    from diffbearing.film.finite_line_ehl import finite_line_film

    from .test_starved_finite_line import PAPERS_PROFILE

    speed = starved_ehl_entrainment_speed()
    film = jax.jit(lambda w: finite_line_film(w, STARVED_EHL_LINE["radius"], speed, 0.08, 2.2e-8, 2.26e11,
                                              PAPERS_PROFILE, 14.7e-3, 12.7e-3, grid=(65, 65)))(load)
    central, _ = pan_hamrock_line(load / 12.7e-3, STARVED_EHL_LINE["radius"], speed, 0.08, 2.2e-8, 2.26e11)
    assert bool(film.converged) and 0.0 < float(film.minimum) < float(film.central)
    assert 6.35e-3 < float(film.minimum_position) < 7.35e-3
    assert float(film.central) == pytest.approx(float(central), rel=0.06)


def test_clustered_axial_cells_span_the_half_roller_and_halve_on_refinement():
    """`axial_cells` with a clustering β (the sinh map of Farrashkhalvat & Miles 2003, eqs. 4.90–4.91)
    on the starved-EHL paper's half roller (flat end 6.35 mm, roller end 7.35 mm): the edges run from 0 to the
    roller end and increase; the smallest cell touches the flat's end; and one map serves every
    count, so every other edge of 2n cells is an edge of n cells (refining halves every cell)."""
    from diffbearing.film.finite_line_ehl import axial_cells

    flat_end, roller_end = 6.35e-3, 7.35e-3
    coarse, fine = (np.asarray(axial_cells(count, flat_end, roller_end, 8.0)) for count in (32, 64))
    assert coarse[0] == 0.0 and coarse[-1] == pytest.approx(roller_end, rel=1e-14) and np.all(np.diff(coarse) > 0)
    widths = np.diff(fine)
    smallest = np.argmin(widths)
    assert abs(0.5 * (fine[smallest] + fine[smallest + 1]) - flat_end) <= widths[smallest]
    np.testing.assert_allclose(fine[::2], coarse, rtol=1e-13, atol=1e-18)


@pytest.mark.parametrize("clustering", [-1e-3, -8.0])
def test_finite_line_axial_clustering_outside_its_range_raises(clustering):
    """A clustering β < 0 would put zero-width cells on the roller (0 means uniform cells):
    ValueError naming axial_clustering, before any solve."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
    with pytest.raises(ValueError, match="axial_clustering"):
        finite_line_film(1028.0, STARVED_EHL_LINE["radius"], 2.63, 0.08, 2.2e-8, 2.26e11, profile, 14.7e-3, 12.7e-3,
                         grid=(17, 16), axial_clustering=clustering)


@pytest.mark.parametrize("side_inflow", [-0.1, 1.5])
def test_finite_line_side_inflow_outside_its_range_raises(side_inflow):
    """The fraction of the side inflow in the meniscus balance lies in [0, 1]: ValueError naming
    side_inflow, before any solve."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)
    with pytest.raises(ValueError, match="side_inflow"):
        finite_line_film(1028.0, STARVED_EHL_LINE["radius"], 2.63, 0.08, 2.2e-8, 2.26e11, profile, 14.7e-3, 12.7e-3,
                         grid=(17, 16), oil_layer=0.8e-6, side_inflow=side_inflow)


@pytest.mark.slow
def test_mass_conserving_meniscus_balance_keeps_mid_length_and_its_derivatives_are_implicit():
    """With the side inflow counted in full (side_inflow = 1, mass conserving across the meniscus),
    the starved-EHL paper's roller starved at 0.8 µm on 25 × 16 converges from the 1-D start; the central film at
    mid-length, where side flow is nil on a 14.7 mm roller with b = 0.12 mm, equals the column
    model's to 0.01 %; the derivatives of central and minimum film with respect to load and oil
    layer match central differences, forward and reverse."""
    from diffbearing.bearings.roller.roller_profile import roller_profile
    from diffbearing.film.finite_line_ehl import finite_line_film

    profile = roller_profile("circular", length=14.7e-3, flat_length=12.7e-3, crown_radius=10e-3)

    def films(x, side_inflow=1.0):  # load [kN], oil layer [µm] → central, minimum [µm], converged
        result = finite_line_film(x[0] * 1e3, STARVED_EHL_LINE["radius"], starved_ehl_entrainment_speed(), 0.08, 2.2e-8,
                                  2.26e11, profile, 14.7e-3, 12.7e-3, grid=(25, 16), oil_layer=x[1] * 1e-6,
                                  side_inflow=side_inflow)
        return jnp.stack([result.central * 1e6, result.minimum * 1e6, result.converged.astype(float)])

    point = jnp.array([1.028, 0.8])
    function = jax.jit(films)
    values, column_model = function(point), jax.jit(lambda x: films(x, 0.0))(point)
    assert float(values[2]) == 1.0 and float(column_model[2]) == 1.0
    assert float(values[0]) == pytest.approx(float(column_model[0]), rel=1e-4)
    for direction in jnp.eye(2):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-6, rtol=1e-5)
