"""diffbearing: a differentiable rolling-bearing model in JAX (float64, SI units inside).

Enable float64 before use: ``jax.config.update("jax_enable_x64", True)``.
"""

from .elliptic import complete_elliptic_integrals as complete_elliptic_integrals
from .hertz import (
    LineContact as LineContact,
    PointContact as PointContact,
    curvature_difference_of_ellipticity as curvature_difference_of_ellipticity,
    effective_modulus as effective_modulus,
    ellipticity as ellipticity,
    hertz_load as hertz_load,
    line_contact as line_contact,
    line_contact_approach_palmgren as line_contact_approach_palmgren,
    load_deflection_constant as load_deflection_constant,
    point_contact as point_contact,
)
from .params import (
    BEARING_STEEL as BEARING_STEEL,
    SILICON_NITRIDE as SILICON_NITRIDE,
    BallBearing as BallBearing,
    Lubricant as Lubricant,
    Material as Material,
    Operating as Operating,
    ball_bearing as ball_bearing,
    iso_vg_oil as iso_vg_oil,
    radial_clearance as radial_clearance,
)
from .raceway_contact import (
    contact_constants as contact_constants,
    inner_curvature as inner_curvature,
    outer_curvature as outer_curvature,
)
from .scene import build_model as build_model, load_scene as load_scene, run_model as run_model
