"""Cage dynamics and whirl stability (the cage paper, §4): the whirling land film, the simulated
orbit and its measures, the hard cases, and the gradient of the stability objective."""

import json

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from diffbearing.app import cli
from diffbearing.cage.cage_dynamics import DynamicsSettings, orbit_measures, simulate_cage
from diffbearing.cage.cage_lands import land_force, squeeze_film_force
from diffbearing.cage.cage_stability import cage_stability
from diffbearing.params import Operating, ball_cage

from .helpers import assert_jvp_matches_central_difference, central_difference_jvp, example_scene
from .test_cage import B7005, GUIDE_RADIAL_CLEARANCE, OIL

SCENE = example_scene("cage_b7005")


def cage_paper_scene(rpm, ratio=1.083, pocket="outer_lock"):
    """(cage, operating) of the cage paper's bearing (cage_b7005) at `rpm` and pocket / guide
    clearance `ratio`."""
    cage = ball_cage(B7005, pocket=pocket, pocket_clearance=ratio * 0.24e-3, guide_clearance=0.24e-3,
                     land_width=2e-3, pushing_balls=3, resisting_balls=4)
    return cage, Operating(rpm * np.pi / 30.0, 0.0, [1120.0, 0.0, 400.0], [0.0, 0.0])


@pytest.mark.parametrize("ratio", [0.3, 0.9, 0.99])
def test_whirling_land_film_is_the_integral_of_the_half_sommerfeld_pressure(ratio):
    """The split Gauss–Legendre arc against a brute-force midpoint sum of max(−S, 0)/h³ over
    400 000 angles (same short-bearing pressure, no knowledge of the arc), for a cage that both
    squeezes and whirls; the sum's error is O(kink), so 1e-6 relative."""
    clearance, width, radius, viscosity, speeds = 0.12e-3, 2e-3, 20.1e-3, 0.01, 900.0
    position = ratio * clearance * np.array([np.cos(0.7), np.sin(0.7)])
    velocity = np.array([-0.004, 0.011])
    theta = (np.arange(400_000) + 0.5) * 2 * np.pi / 400_000
    film = clearance - position[0] * np.cos(theta) - position[1] * np.sin(theta)
    source = (0.5 * speeds * (position[0] * np.sin(theta) - position[1] * np.cos(theta))
              - velocity[0] * np.cos(theta) - velocity[1] * np.sin(theta))
    line_load = viscosity * width**3 * np.maximum(-source, 0.0) / film**3
    want = -radius * np.array([np.sum(line_load * np.cos(theta)), np.sum(line_load * np.sin(theta))]) * 2 * np.pi / 400_000
    got = squeeze_film_force(jnp.asarray(position), jnp.asarray(velocity), clearance, width, radius, speeds, viscosity)
    np.testing.assert_allclose(np.asarray(got), want, rtol=1e-6)


@pytest.mark.parametrize("ratio", [1e-3, 0.5, 0.95, 0.99])
def test_land_film_at_rest_is_the_ocvirk_closed_form(ratio):
    """At zero velocity the arc quadrature equals the Ocvirk force of `land_force` (film only: a
    threshold too thin to reach), at any offset direction, to 1e-11 relative."""
    clearance, width, radius, viscosity, speed = 0.12e-3, 2e-3, 20.1e-3, 0.01, 900.0
    for angle in (0.3, 2.0, 4.5):
        position = ratio * clearance * jnp.array([np.cos(angle), np.sin(angle)])
        want, _, _, _ = land_force(position, clearance, width, radius, speed, 0.0, viscosity, 1e-12, 3e7, 0.1)
        got = squeeze_film_force(position, jnp.zeros(2), clearance, width, radius, speed, viscosity)
        np.testing.assert_allclose(np.asarray(got), np.asarray(want), rtol=1e-11)


@pytest.mark.parametrize("ratio", [0.0, 0.5, 0.99])
def test_whirling_land_film_derivatives_match_central_differences(ratio):
    """d(film force)/d(position, velocity) — the land stiffness and damping of `cage_stability`
    — forward and reverse against a central difference, at the centred cage (where the arc's
    phase and split angles switch to their guarded branches), at ε = 0.5 and at ε = 0.99."""
    clearance = 0.12e-3
    point = (ratio * clearance * jnp.array([np.cos(0.7), np.sin(0.7)]), jnp.array([-0.004, 0.011]))
    direction = (jnp.array([0.3e-6, -0.2e-6]), jnp.array([1e-3, 2e-3]))

    def force(point):
        return squeeze_film_force(point[0], point[1], clearance, 2e-3, 20.1e-3, 900.0, 0.01)

    assert_jvp_matches_central_difference(force, point, direction, 1e-3, rtol=1e-6, atol=1e-12)


def test_half_frequency_whirl_carries_no_load():
    """Exact identity of the short bearing: a centre whirling on a circle at ω_s/2 makes
    ∂h/∂t cancel the wedge (S ≡ 0), so the film force is exactly zero."""
    clearance, speeds = 0.12e-3, 900.0
    position = 0.6 * clearance * jnp.array([1.0, 0.0])
    velocity = 0.5 * speeds * jnp.array([-position[1], position[0]])
    force = squeeze_film_force(position, velocity, clearance, 2e-3, 20.1e-3, speeds, 0.01)
    np.testing.assert_array_equal(np.asarray(force), 0.0)


def test_orbit_measures_of_a_synthetic_whirl():
    """A circular forward whirl of radius 7 µm at 240 Hz about (3, −4) µm: the measures give the
    radius (RMS of |c − c̄|), the offset 5 µm and the frequency exactly (an FFT bin), and zero decay."""
    times = jnp.arange(1024) / 1024 * 0.05  # 25 ms second half, 40 Hz bins
    angle = 2 * np.pi * 240.0 * times
    centre = 1e-6 * jnp.stack([3 + 7 * jnp.cos(angle), -4 + 7 * jnp.sin(angle)], -1)
    measures = orbit_measures(times, centre)
    np.testing.assert_allclose(measures["whirl_radius"], 7e-6, rtol=1e-12)
    np.testing.assert_allclose(measures["mean_offset"], 5e-6, rtol=1e-12)
    assert float(measures["whirl_frequency"]) == pytest.approx(240.0, abs=1e-9)
    assert abs(float(measures["decay_rate"])) < 1e-6


@pytest.fixture(scope="module")
def short_orbit():
    """Compiled 20000 r/min orbit of 10 ms (1.4 cage revolutions) as a function of the start."""
    cage, operating = cage_paper_scene(20000.0)
    return jax.jit(lambda start, duration: simulate_cage(cage, B7005, operating, OIL, start, duration, 256))


@pytest.mark.parametrize("start_eccentricity", [0.0, 0.8, 1.05])
def test_orbit_converges_from_centred_offset_and_land_contact(short_orbit, start_eccentricity):
    """Hard cases: the centred cage, the scene's ε = 0.8, and a start pressed 6 µm into the land
    (ε = 1.05, metal contact): the integration reaches the end with finite values, and the cage
    stays within the guide clearance plus the metal contact's give."""
    start = start_eccentricity * GUIDE_RADIAL_CLEARANCE * jnp.array([np.cos(4.19), np.sin(4.19)])
    orbit = short_orbit(start, 0.01)
    assert bool(orbit.converged)
    for name in ("centre", "spin", "whirl_radius", "decay_rate", "land_contact"):
        assert np.all(np.isfinite(np.asarray(getattr(orbit, name)))), name
    radius = np.linalg.norm(np.asarray(orbit.centre), axis=1)
    assert radius.max() < 1.1 * GUIDE_RADIAL_CLEARANCE
    if start_eccentricity > 1:
        assert float(orbit.land_contact[0]) > 0.0  # the run starts in metal contact at the land


@pytest.mark.slow
def test_orbit_gradient_is_finite_in_land_contact():
    """Reverse mode through the integration from a start in metal contact (1 ms, 20000 r/min):
    finite, and equal to a central difference of the start offset. The gradient is that of the
    discrete solution for its step sequence, so the tolerance is tightened to 1e-10 (at the
    default 1e-5 the adaptive steps change under a finite-difference step and the difference
    scatters by 10 %). Even so the central difference still crosses changes of the step sequence,
    which rounding decides: they agreed to 0.1 % compiled with XLA's defaults, to 0.31 % with LLVM
    at level 0 and the loop emitters; the tolerance is 0.5 %."""
    cage, operating = cage_paper_scene(20000.0)
    settings = DynamicsSettings(rtol=1e-10, atol=1e-10)

    @jax.jit
    def mean_radius(start):
        orbit = simulate_cage(cage, B7005, operating, OIL, start, 0.001, 256, settings)
        return jnp.mean(jnp.linalg.norm(orbit.centre, axis=1))

    start = 1.05 * GUIDE_RADIAL_CLEARANCE * jnp.array([np.cos(4.19), np.sin(4.19)])
    gradient = jax.grad(mean_radius)(start)
    assert np.all(np.isfinite(np.asarray(gradient)))
    direction = jnp.array([1.0, 0.0])
    reference = central_difference_jvp(mean_radius, start, direction, 1e-8)
    np.testing.assert_allclose(float(gradient @ direction), float(reference), rtol=5e-3)


@pytest.fixture(scope="module")
def stability_decay():
    """Compiled whirl decay rate [1/s] at the equilibrium against (rpm, clearance ratio)."""
    def decay(rpm, ratio):
        cage, operating = cage_paper_scene(rpm, ratio)
        return cage_stability(cage, B7005, operating, OIL).decay_rate
    return jax.jit(decay)


@pytest.mark.parametrize("rpm", [pytest.param(1800.0, marks=pytest.mark.slow), 20000.0])
def test_stability_objective_gradient_matches_central_difference(stability_decay, rpm):
    """The design objective of the pocket-clearance notebook: d σ / d(c_p/c_g) by implicit
    differentiation through the equilibrium Newton and the eigenvalues, against a central
    difference (step 1e-4 of the ratio)."""
    ratio = 1.083
    gradient = jax.grad(stability_decay, argnums=1)(rpm, ratio)
    reference = (stability_decay(rpm, ratio + 1e-4) - stability_decay(rpm, ratio - 1e-4)) / 2e-4
    assert np.isfinite(float(gradient))
    np.testing.assert_allclose(float(gradient), float(reference), rtol=1e-5)


def test_stability_at_the_equilibrium_is_a_force_balance():
    """At c* the quasi-static resultant vanishes (to the Newton tolerance of 1e-10 C) and the
    equilibrium is stable at the scene's speed (σ > 0), the slowest mode real or complex."""
    from diffbearing.cage.cage_forces import cage_forces

    cage, operating = cage_paper_scene(20000.0)

    @jax.jit
    def solve(cage):
        stability = cage_stability(cage, B7005, operating, OIL)
        return stability, cage_forces(cage, B7005, operating, OIL, stability.equilibrium).force[:2]

    stability, resultant = solve(cage)
    assert bool(stability.converged)
    scale = np.abs(np.asarray(stability.stiffness)).max() * GUIDE_RADIAL_CLEARANCE
    assert np.abs(np.asarray(resultant)).max() < 1e-9 * scale
    assert float(stability.decay_rate) > 0.0


@pytest.mark.slow
def test_cli_dynamics_writes_the_orbit(tmp_path):
    """`effects.cage = "dynamics"` through the CLI with a short duration: JSON orbit arrays of
    the sample count, the stability measures, and a plot."""
    out = tmp_path / "dynamics.json"
    plot = tmp_path / "orbit.png"
    code = cli.main(["run", SCENE, "--set", "effects.cage=dynamics", "--set", "cage.duration=5 ms",
                     "--json", str(out), "--plot", str(plot)])
    assert code == 0
    cage = json.loads(out.read_text())["cage"]
    assert len(cage["orbit"]["x"]) == len(cage["orbit"]["t"]) == 1024
    assert cage["orbit"]["t"][-1] == pytest.approx(5e-3)
    assert cage["orbit"]["converged"]
    assert np.isfinite(cage["whirl_radius"]) and np.isfinite(cage["stability"]["decay_rate"])
    assert plot.stat().st_size > 0
