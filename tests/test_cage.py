"""Cage forces under combined guidance (the cage paper): land bearings, pocket contact, the
restoring force f_inv and the paper's trends through the CLI."""

import json

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from scipy.integrate import quad

from diffbearing.app import cli
from diffbearing.cage.cage_forces import cage_forces
from diffbearing.cage.cage_lands import land_force
from diffbearing.cage.cage_pocket import circumferential_force, seat_ball
from diffbearing.params import Lubricant, Operating, ball_bearing, ball_cage

from .helpers import assert_jvp_matches_central_difference, example_scene

# B7005-class internal geometry of the packaged example diffbearing/scenes/cage_b7005.toml; the cage geometry
# a scene leaves out is `ball_cage`'s default (land bore d_m + 0.8 D_w, land spacing D_w + L).
B7005 = ball_bearing(ball_diameter=5.556e-3, pitch_diameter=36e-3, balls=17, inner_groove_ratio=0.52,
                     outer_groove_ratio=0.53, contact_angle=np.radians(15.0))
OIL = Lubricant(0.01, 2e-8, 870.0)
GUIDE_RADIAL_CLEARANCE = 0.12e-3


def cage_paper_forces(pocket="outer_lock", rpm=20000.0, pocket_clearance=0.26e-3, pushing=3, resisting=4):
    """(x, y) [m] → CageForces of the cage paper's bearing."""
    cage = ball_cage(B7005, pocket=pocket, pocket_clearance=pocket_clearance, guide_clearance=0.24e-3,
                     land_width=2e-3, pushing_balls=pushing, resisting_balls=resisting)
    operating = Operating(rpm * np.pi / 30.0, 0.0, [1120.0, 0.0, 400.0], [0.0, 0.0])
    return lambda offset: cage_forces(cage, B7005, operating, OIL, offset)


def offset_at(eccentricity, degrees):
    angle = np.radians(degrees)
    return eccentricity * GUIDE_RADIAL_CLEARANCE * jnp.array([np.cos(angle), np.sin(angle)])


def test_land_force_is_the_integral_of_the_short_bearing_pressure():
    """Ocvirk's closed forms against a quadrature of the short-bearing (half-Sommerfeld) pressure
    (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, ch. 10). Cage offset e
    along +x, turning at +ω: with φ measured from the thinnest film against the rotation, the gap
    is h = C(1 − ε cos φ) and the positive pressure p = 3ηU ε C sin φ (L²/4 − z²)/(R h³) fills
    0 < φ < π; on the cage it gives F_x = −∫ p cos φ dA (against the offset) and
    F_y = +∫ p sin φ dA (a quarter turn ahead: forward whirl)."""
    viscosity, clearance, width, radius, speed = 0.01, 0.12e-3, 2e-3, 20.1e-3, 900.0
    for ratio in (0.1, 0.5, 0.8, 0.95):
        surface = radius * speed

        def pressure_integral(weight):
            def integrand(phi):
                gap = clearance * (1.0 - ratio * np.cos(phi))
                return 3 * viscosity * surface * ratio * clearance * np.sin(phi) / (radius * gap**3) * weight(phi)
            return quad(integrand, 0.0, np.pi, epsabs=0, epsrel=1e-12)[0] * width**3 / 6.0 * radius

        force, _, _, contact = land_force(jnp.array([ratio * clearance, 0.0]), clearance, width, radius, speed, 0.0,
                                          viscosity, 1e-9, 3e7, 0.1)
        np.testing.assert_allclose(np.asarray(force), [-pressure_integral(np.cos), pressure_integral(np.sin)],
                                   rtol=1e-9)
        assert float(contact) == 0.0


@pytest.fixture(scope="module")
def restoring_and_jacobian():
    """(x, y) [m] → (f_inv [N], ∂F_xy/∂(x, y) [N/m]) of the cage paper's outer-lock cage, compiled once."""
    forces = cage_paper_forces()

    def planar(offset):
        return forces(offset).force[:2]

    return jax.jit(lambda offset: (forces(offset).restoring_force, jax.jacfwd(planar)(offset)))


@pytest.mark.parametrize("eccentricity", [0.0, 0.6, 0.999, 1.0, 1.3])
def test_cage_force_and_gradient_stay_finite_up_to_and_into_the_land(restoring_and_jacobian, eccentricity):
    """Hard case: the short-bearing force diverges as ε → 1; below the 1 µm film threshold
    (ε_t = 0.99167) a metal contact takes over, so the force and its Jacobian are finite at the
    centred cage, at contact (ε = 1) and pressed 36 µm into the land (ε = 1.3)."""
    value, jacobian = restoring_and_jacobian(offset_at(eccentricity, 240.0))
    assert np.isfinite(float(value)) and np.all(np.isfinite(np.asarray(jacobian)))
    if eccentricity >= 1.0:  # in metal contact the land stiffness (2 × 3e7 N/m) dominates
        assert float(-jnp.trace(jacobian)) > 2 * 3e7


def test_land_force_is_continuous_where_metal_contact_takes_over():
    """At ε_t = 1 − h_t/C the held film force plus a vanishing metal contact equals the film force
    from below (continuity), and beyond it the force grows by k_m per metre of extra approach."""
    clearance, threshold, stiffness = 0.12e-3, 1e-6, 3e7
    limit = clearance - threshold

    def normal_force(offset):
        return -float(land_force(jnp.array([offset, 0.0]), clearance, 2e-3, 20.1e-3, 900.0, 0.0, 0.01, threshold,
                                 stiffness, 0.1)[0][0])

    below, above = normal_force(limit * (1 - 1e-12)), normal_force(limit * (1 + 1e-12))
    assert above == pytest.approx(below, rel=1e-8)
    assert normal_force(limit + 1e-6) - above == pytest.approx(stiffness * 1e-6, rel=1e-6)


@pytest.mark.parametrize("sphere_offset, axial_offset", [(0.0, 0.0), (80e-6, 0.0), (130e-6, 0.0), (150e-6, 20e-6)])
def test_seated_ball_carries_the_prescribed_circumferential_force(sphere_offset, axial_offset):
    """`seat_ball` solves Q(δ) n_y(δ) = F to rounding, also where the pocket holds the ball
    radially (x_s ≥ R_pok − R_b = 130 µm: the rigid-pocket force F/n_y would be infinite). There,
    at 0.05 N, δ − δ_lo ≈ 1e-12 m rides on δ_lo = 21 µm, so δ itself carries F to ~3e-9 only."""
    play, stiffness = 130e-6, 4.8e9
    for force in (0.05, 1.2, 40.0):
        approach = seat_ball(force, sphere_offset, axial_offset, play, stiffness)
        carried = circumferential_force(approach, sphere_offset, axial_offset, play, stiffness)
        assert float(carried) == pytest.approx(force, rel=1e-8)
        assert 0 <= float(approach) < 1e-4


def test_cage_at_rest_feels_no_force_and_has_finite_gradients():
    """At zero speed there is no drag, no film and no push: every force is exactly zero, and the
    derivative with respect to speed is finite."""
    def restoring(rpm):
        return cage_paper_forces(rpm=rpm)(offset_at(0.8, 240.0)).restoring_force

    assert float(restoring(0.0)) == 0.0
    assert np.isfinite(float(jax.grad(restoring)(0.0)))


def test_restoring_force_derivatives_match_central_differences():
    """f_inv and the resultant (F_x, F_y) against offset (x, y) [µm], diametral pocket clearance
    [µm] and inner-ring speed [krpm], forward and reverse, at the cage paper's point (ε = 0.8, 240°)."""
    def forces(p):
        solved = cage_paper_forces(rpm=p[3] * 1e3, pocket_clearance=p[2] * 1e-6)(p[:2] * 1e-6)
        return jnp.concatenate([solved.restoring_force[None], solved.force[:2]])

    point = jnp.concatenate([offset_at(0.8, 240.0) * 1e6, jnp.array([260.0, 20.0])])
    function = jax.jit(forces)
    for direction in jnp.eye(4):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-4, rtol=1e-6, atol=1e-9)


@pytest.fixture(scope="module")
def cage_paper_cli(tmp_path_factory):
    """f_inv [N] of the packaged cage_b7005 scene through `diffbearing run --json` with --set overrides
    (the outer-lock and cylindrical models compile once each; later runs reuse them)."""
    scene = example_scene("cage_b7005")
    path = tmp_path_factory.mktemp("cage") / "out.json"

    def restoring_force(*overrides):
        arguments = ["run", scene, "--json", str(path)]
        for override in overrides:
            arguments += ["--set", override]
        assert cli.main(arguments) == 0
        return json.loads(path.read_text())["cage"]["restoring_force"]

    return restoring_force


# Fig. 8 of the paper: the cage offset by half the guide clearance (ε = 0.5). Its offset angle,
# 150°, is given without a sense of measure; here the trends are tested at the scene's 240°
# (docs/validation/cage.md, §The paper's findings: at 150° measured with the rotation this model's
# f_inv is negative).
FIG8 = "cage.eccentricity=0.5"


def test_cage_paper_restoring_force_grows_with_speed_and_resisting_balls(cage_paper_cli, capsys):
    """Liu et al. 2020, Fig. 8 and conclusion 1 (ε = 0.5 at 240°, m = 3, n = 4): f_inv grows with
    speed (drag ∝ v², film ∝ ω) and with the number n of balls the cage drives."""
    speeds = [cage_paper_cli(FIG8, f'operating.inner_speed="{rpm} rpm"') for rpm in (5000, 20000, 40000, 60000)]
    resisting = [cage_paper_cli(FIG8, f"cage.resisting_balls={n}") for n in (1, 2, 3, 4, 5, 6)]
    capsys.readouterr()
    assert np.all(np.diff(speeds) > 0) and np.all(np.diff(resisting) > 0)


def test_cage_paper_restoring_force_falls_with_pushing_balls(cage_paper_cli, capsys):
    """Fig. 8, conclusion 1 (ε = 0.5 at 240°, n = 4): f_inv falls as more balls (m) share the push:
    their circumferential forces spread over a wider arc and partly cancel."""
    pushing = [cage_paper_cli(FIG8, f"cage.pushing_balls={m}") for m in (1, 2, 3, 4, 5, 6, 7)]
    capsys.readouterr()
    assert np.all(np.diff(pushing) < 0)


def test_cage_paper_restoring_force_rises_steeply_beyond_relative_eccentricity_0_6(cage_paper_cli, capsys):
    """Fig. 10 and conclusion 3: below ε = 0.6 f_inv changes little, above it the land film force
    ε²/(1 − ε²)² takes over; the slope over 0.6–0.9 is more than five times that over 0.2–0.6, and
    the outer-lock cage's f_inv is larger than the cylindrical one's at every ε."""
    eccentricities = (0.2, 0.4, 0.6, 0.75, 0.9)
    outer_lock = np.array([cage_paper_cli(f"cage.eccentricity={e}") for e in eccentricities])
    cylindrical = np.array([cage_paper_cli(f"cage.eccentricity={e}", 'cage.pocket="cylindrical"') for e in eccentricities])
    capsys.readouterr()
    for forces in (outer_lock, cylindrical):
        assert np.all(np.diff(forces) > 0)
        assert (forces[4] - forces[2]) / 0.3 > 5 * (forces[2] - forces[0]) / 0.4
    assert np.all(outer_lock > cylindrical)


def test_cage_paper_pocket_gap_widens_with_speed(cage_paper_cli, capsys):
    """Fig. 10, conclusion 3: the outer-lock cage's advantage over the cylindrical pocket grows
    with speed (the wall forces grow with the drag, and only the sphere turns them radial)."""
    gaps = [cage_paper_cli(f'operating.inner_speed="{rpm} rpm"')
            - cage_paper_cli(f'operating.inner_speed="{rpm} rpm"', 'cage.pocket="cylindrical"') for rpm in (5000, 20000, 60000)]
    capsys.readouterr()
    assert gaps[0] > 0 and np.all(np.diff(gaps) > 0)


def test_cage_paper_outer_lock_beats_cylindrical_at_most_offset_angles(cage_paper_cli, capsys):
    """Fig. 9 (20000 r/min, m = 4, n = 2, ε = 0.8): over offset angles every 15°, the outer-lock
    cage's f_inv exceeds the cylindrical one's at most angles (the paper: "at most angles"; this
    model: at all 24, see benchmarks/cage_forces.py)."""
    common = ("cage.pushing_balls=4", "cage.resisting_balls=2")
    angles = range(0, 360, 15)
    outer_lock = np.array([cage_paper_cli(*common, f'cage.offset_angle="{a} deg"') for a in angles])
    cylindrical = np.array([cage_paper_cli(*common, f'cage.offset_angle="{a} deg"', 'cage.pocket="cylindrical"')
                            for a in angles])
    capsys.readouterr()
    assert np.mean(outer_lock > cylindrical) > 0.5


def test_more_pushing_balls_than_the_load_zone_holds_exits_2(capsys):
    """Bad input: 12 pushing balls where the Sjövall load zone of the scene's load holds 11."""
    code = cli.main(["run", example_scene("cage_b7005"), "--set", "cage.pushing_balls=12"])
    error = capsys.readouterr().err
    assert code == 2 and "cage.pushing_balls" in error and "11 balls in the Sjövall load zone" in error


@pytest.mark.parametrize("eccentricity", [0.8, 1.1])
def test_cage_moment_land_and_pocket_force_derivatives_match_central_differences(eccentricity):
    """The other differentiable cage outputs — moment, land forces, eccentricities and metal
    contact, each ball's force, the push — against offset (x, y) [µm] and tilt (θx, θy) [mrad],
    forward and reverse, in full film (ε = 0.8) and pressed into the land (ε = 1.1)."""
    cage = ball_cage(B7005, pocket_clearance=0.26e-3, guide_clearance=0.24e-3, land_width=2e-3, pushing_balls=3,
                     resisting_balls=4)
    operating = Operating(20000.0 * np.pi / 30.0, 0.0, [1120.0, 0.0, 400.0], [0.0, 0.0])

    def outputs(p):
        solved = cage_forces(cage, B7005, operating, OIL, p[:2] * 1e-6, p[2:] * 1e-3)
        return jnp.concatenate([solved.moment * 1e3, solved.land_force.ravel(), solved.land_eccentricity,
                                solved.land_contact, solved.pocket_forces.ravel(), solved.push[None]])

    point = jnp.concatenate([offset_at(eccentricity, 240.0) * 1e6, jnp.array([0.3, -0.2])])
    function = jax.jit(outputs)
    for direction in jnp.eye(4):
        assert_jvp_matches_central_difference(function, point, direction, step=1e-4, rtol=1e-6, atol=1e-8)
