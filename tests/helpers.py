"""The one finite-difference helper every derivative test uses, the test scenes' shared bearing, the
spindle tests' bearing, and the path of a packaged example scene."""

import functools
import importlib.resources

import jax
import jax.numpy as jnp
import numpy as np

from diffbearing.params import BEARING_STEEL, ball_bearing


def central_difference_jvp(function, point, direction, step):
    """(f(x + h v) − f(x − h v)) / (2h) for pytrees `point`, `direction`; truncation error O(h²).

    Choose h ≈ (ε_machine)^(1/3) × (scale of x) ≈ 6e-6 × scale: that balances the O(h²)
    truncation error against the O(ε/h) rounding error of the difference.
    """
    plus = jax.tree.map(lambda x, v: x + step * v, point, direction)
    minus = jax.tree.map(lambda x, v: x - step * v, point, direction)
    return jax.tree.map(lambda a, b: (a - b) / (2.0 * step), function(plus), function(minus))


def assert_jvp_matches_central_difference(function, point, direction, step, rtol=1e-6, atol=0.0):
    """Forward-mode JVP and reverse-mode VJP of `function` against a central finite difference.

    Two compiled programs: the JVP, whose primal values also give the difference, and the whole VJP
    (forward and backward pass in one), not four (a primal, a JVP and the VJP's two passes apart):
    the compile time of a derivative test is most of its time. A test that checks several directions
    of one `function` compiles them once (`_derivative_programs`)."""
    jvp, vjp = _derivative_programs(function)
    outputs, tangent = jvp(point, direction)
    reference = central_difference_jvp(lambda x: jvp(x, direction)[0], point, direction, step)
    for name, got, want in zip(_names(tangent), jax.tree.leaves(tangent), jax.tree.leaves(reference)):
        np.testing.assert_allclose(got, want, rtol=rtol, atol=atol, err_msg=f"forward mode, output {name}")
    # reverse mode: ⟨w, J v⟩ from the VJP with w = ones must equal Σ of the forward tangent
    (cotangent,) = vjp(point, jax.tree.map(jnp.ones_like, outputs))
    reverse = sum(jnp.vdot(c, v) for c, v in zip(jax.tree.leaves(cotangent), jax.tree.leaves(direction)))
    forward = sum(jnp.sum(t) for t in jax.tree.leaves(tangent))
    magnitude = sum(float(jnp.sum(jnp.abs(t))) for t in jax.tree.leaves(tangent))
    np.testing.assert_allclose(reverse, forward, rtol=1e-10, atol=1e-10 * magnitude + 1e-14)


@functools.lru_cache(maxsize=4)  # a few functions' programs held at a time (memory maps: tests/conftest.py)
def _derivative_programs(function):
    """The jitted JVP (x, v) → (f(x), J v) and VJP (x, w) → wᵀJ of `function`."""
    return (jax.jit(lambda x, v: jax.jvp(function, (x,), (v,))),
            jax.jit(lambda x, w: jax.vjp(function, x)[1](w)))


def _names(tree):
    return [jax.tree_util.keystr(path) for path, _ in jax.tree_util.tree_flatten_with_path(tree)[0]]


# The 6411E deep-groove ball bearing (D_w = 26.9875 mm, d_m = 97.5 mm, 7 balls) as a scene's [bearing] table.
# the spindle_pair example's 7014 C type angular contact ball bearing (SI)
SPINDLE_7014C = ball_bearing(kind="angular_contact_ball", ball_diameter=11.112e-3, pitch_diameter=90e-3, balls=21,
                             inner_groove_ratio=0.52, outer_groove_ratio=0.53, contact_angle=np.radians(15.0),
                             bore=70e-3, outer_diameter=110e-3, ball_material=BEARING_STEEL, ring_material=BEARING_STEEL)

BEARING_6411E = """
[bearing]
type = "deep_groove_ball"
ball_diameter = "26.9875 mm"
pitch_diameter = "97.5 mm"
balls = 7
inner_groove_radius = "13.9 mm"
outer_groove_radius = "14.17 mm"
radial_clearance = "0.028 mm"
"""

# A 6208 deep-groove ball bearing as the catalogues' usual internal geometry (9 balls of 15/32 in,
# d_m the mean of bore and outside diameter) with ISO 76's groove ratios, as a scene's [bearing]
# table without its clearance.
BEARING_6208 = """
[bearing]
type = "deep_groove_ball"
ball_diameter = "11.906 mm"
pitch_diameter = "60 mm"
balls = 9
inner_groove_ratio = 0.52
outer_groove_ratio = 0.53
"""


def example_scene(name: str) -> str:
    """Filesystem path of the packaged example scene `diffbearing/scenes/<name>.toml`."""
    return str(importlib.resources.files("diffbearing.scenes").joinpath(f"{name}.toml"))


def palmgren_moment(f0, f1, load, kinematic_viscosity, rpm, pitch_diameter):
    """Palmgren's M₀ + M₁ [N·m] written out in the catalogue's units (Schaeffler HR 1, "Friction and
    increases in temperature"): M₀ = 10⁻⁷ f₀ (ν n)^{2/3} d_m³ for ν n ≥ 2000, 160·10⁻⁷ f₀ d_m³ below;
    M₁ = f₁ P₁ d_m [N·mm] with ν [m²/s], n [r/min], d_m [m], P₁ [N]."""
    product, dm = kinematic_viscosity * 1e6 * rpm, pitch_diameter * 1e3
    viscous = 1e-7 * f0 * product ** (2 / 3) * dm**3 if product >= 2000 else 160e-7 * f0 * dm**3
    return (viscous + f1 * load * dm) * 1e-3


def assert_exits_2_naming(capsys, arguments, named):
    """`diffbearing ARGUMENTS` exits 2 with one line on stderr that names `named` (a bad input)."""
    from diffbearing.app import cli

    code = cli.main(arguments)
    err = capsys.readouterr().err
    assert code == 2 and named in err and len(err.strip().splitlines()) == 1, err
