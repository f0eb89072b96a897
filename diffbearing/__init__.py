"""diffbearing: a differentiable rolling-bearing model in JAX (float64, SI units inside).

Enable float64 before use: ``jax.config.update("jax_enable_x64", True)``.

The physics blocks (pure functions of parameter pytrees) and the scene API (`load_scene`,
`build_model`, `run_model`, `run_sweep`, `examples`) are re-exported here.
"""

from importlib.metadata import version as _version

from .bearings.ball.ball_equilibrium import (
    BallModel as BallModel,
    BallResults as BallResults,
    ball_results as ball_results,
    ring_force as ring_force,
    solve_equilibrium as solve_equilibrium,
    solve_with_balls as solve_with_balls,
    stiffness_at_balls as stiffness_at_balls,
    stiffness_matrix as stiffness_matrix,
)
from .bearings.ball.ball_support import BallSupport as BallSupport
from .bearings.ball.double_row import DoubleRowSupport as DoubleRowSupport
from .bearings.ball.four_point import FourPointSupport as FourPointSupport
from .bearings.ball.thrust_ball import (
    ThrustBallSupport as ThrustBallSupport,
    minimum_axial_load as minimum_axial_load,
    thrust_ball_bearing as thrust_ball_bearing,
    thrust_ball_support as thrust_ball_support,
)
from .bearings.ball.self_aligning import (
    SelfAligningSupport as SelfAligningSupport,
    self_aligning_row as self_aligning_row,
    self_aligning_support as self_aligning_support,
)
from .bearings.ball.groove_chamfer import chamfer_height as chamfer_height, limit_point_angle as limit_point_angle
from .bearings.ball.raceway_contact import (
    contact_constants as contact_constants,
    inner_curvature as inner_curvature,
    outer_curvature as outer_curvature,
)
from .bearings.interface import (
    AbstractSupport as AbstractSupport,
    CondensedElements as CondensedElements,
    RingSection as RingSection,
)
from .bearings.roller.cylindrical_roller_thrust import (
    CylindricalRollerThrustSupport as CylindricalRollerThrustSupport,
    cylindrical_roller_thrust_bearing as cylindrical_roller_thrust_bearing,
    cylindrical_roller_thrust_support as cylindrical_roller_thrust_support,
)
from .bearings.roller.spherical_roller import (
    SphericalRoller as SphericalRoller,
    SphericalRollerRaceways as SphericalRollerRaceways,
    SphericalRollerSupport as SphericalRollerSupport,
    spherical_roller as spherical_roller,
    spherical_roller_raceways as spherical_roller_raceways,
    spherical_roller_support as spherical_roller_support,
)
from .bearings.roller.needle_roller import (
    NeedleRollerSupport as NeedleRollerSupport,
    needle_roller_bearing as needle_roller_bearing,
    needle_roller_raceways as needle_roller_raceways,
    needle_roller_support as needle_roller_support,
)
from .bearings.roller.roller_contact import RollerContact as RollerContact, roller_contact as roller_contact
from .bearings.roller.roller_equilibrium import (
    RollerEquilibrium as RollerEquilibrium,
    RollerModel as RollerModel,
    RollerOperating as RollerOperating,
    RollerRaceways as RollerRaceways,
    RollerResults as RollerResults,
    roller_contact_loadings as roller_contact_loadings,
    roller_raceways as roller_raceways,
    roller_results as roller_results,
    roller_stiffness_matrix as roller_stiffness_matrix,
    solve_roller_equilibrium as solve_roller_equilibrium,
)
from .bearings.roller.roller_geometry import (
    RollerBearing as RollerBearing,
    RollerLoading as RollerLoading,
    initial_gap as initial_gap,
    roller_bearing as roller_bearing,
)
from .bearings.roller.roller_profile import (
    RollerProfile as RollerProfile,
    crown_drop as crown_drop,
    roller_profile as roller_profile,
)
from .bearings.roller.roller_support import RollerSupport as RollerSupport
from .cage.cage_dynamics import (
    CageOrbit as CageOrbit,
    DynamicsSettings as DynamicsSettings,
    simulate_cage as simulate_cage,
)
from .cage.cage_forces import (
    CageForces as CageForces,
    cage_forces as cage_forces,
    epicyclic_cage_speed as epicyclic_cage_speed,
)
from .cage.cage_stability import CageStability as CageStability, cage_stability as cage_stability
from .contact.elliptic import complete_elliptic_integrals as complete_elliptic_integrals
from .contact.hertz import (
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
from .film.film_formulas import (
    dowson_higginson_line_minimum as dowson_higginson_line_minimum,
    film_parameter as film_parameter,
    hamrock_dowson_point as hamrock_dowson_point,
    moes_line_central as moes_line_central,
    pan_hamrock_line as pan_hamrock_line,
    starved_film as starved_film,
)
from .film.finite_line_ehl import FiniteLineFilm as FiniteLineFilm, finite_line_film as finite_line_film
from .film.line_ehl import (
    LineFilm as LineFilm,
    density_ratio as density_ratio,
    line_film as line_film,
    moes_load_parameter as moes_load_parameter,
    viscosity_ratio as viscosity_ratio,
)
from .newton import implicit_root as implicit_root, minimise_convex as minimise_convex, newton as newton
from .overrolling import (
    OverrollingFrequencies as OverrollingFrequencies,
    ball_bearing_frequencies as ball_bearing_frequencies,
    nominal_frequencies as nominal_frequencies,
    roller_bearing_frequencies as roller_bearing_frequencies,
)
from .params import (
    BEARING_STEEL as BEARING_STEEL,
    BallBearing as BallBearing,
    Cage as Cage,
    Lubricant as Lubricant,
    Material as Material,
    Operating as Operating,
    SILICON_NITRIDE as SILICON_NITRIDE,
    ball_bearing as ball_bearing,
    ball_cage as ball_cage,
    iso_vg_oil as iso_vg_oil,
    radial_clearance as radial_clearance,
    with_radial_clearance as with_radial_clearance,
)
from .ratings.life import (
    basic_dynamic_load_rating as basic_dynamic_load_rating,
    basic_rating_life as basic_rating_life,
    equivalent_dynamic_load as equivalent_dynamic_load,
    reference_rating_life as reference_rating_life,
    system_life as system_life,
)
from .ratings.load_distribution import (
    load_zone_parameter as load_zone_parameter,
    sjovall_integrals as sjovall_integrals,
    stribeck_max_ball_load as stribeck_max_ball_load,
)
from .ratings.minimum_load import minimum_load as minimum_load
from .ratings.radial_load_factors import load_factors as load_factors, relative_axial_load as relative_axial_load
from .ratings.reliability import reliability_factor as reliability_factor
from .ratings.roller_life import (
    roller_dynamic_load_rating as roller_dynamic_load_rating,
    roller_reference_rating_life as roller_reference_rating_life,
)
from .ratings.static_safety import (
    ball_equivalent_static_load as ball_equivalent_static_load,
    ball_static_load_rating as ball_static_load_rating,
    pressure_safety as pressure_safety,
    roller_equivalent_static_load as roller_equivalent_static_load,
    roller_static_load_rating as roller_static_load_rating,
)
from .systems.bearing_set import (
    bearing_set as bearing_set,
    clamped_offset as clamped_offset,
    preload_force as preload_force,
    preload_offset as preload_offset,
)
from .systems.flexible_shaft import (
    FlexibleShaft as FlexibleShaft,
    FlexibleShaftEquilibrium as FlexibleShaftEquilibrium,
    flexible_shaft as flexible_shaft,
    flexible_shaft_stiffness as flexible_shaft_stiffness,
    solve_flexible_shaft as solve_flexible_shaft,
)
from .systems.operating_clearance import (
    Mounting as Mounting,
    OperatingClearance as OperatingClearance,
    fit_pressure as fit_pressure,
    mounted_clearance_change as mounted_clearance_change,
    operating_clearance_change as operating_clearance_change,
)
from .systems.shaft_beam import ShaftSections as ShaftSections
from .systems.shaft_equilibrium import (
    Shaft as Shaft,
    ShaftEquilibrium as ShaftEquilibrium,
    ShaftLoads as ShaftLoads,
    shaft_force as shaft_force,
    shaft_stiffness as shaft_stiffness,
    solve_shaft as solve_shaft,
)
from .systems.static_capacity import (
    CapacityPoint as CapacityPoint,
    capacity_curve as capacity_curve,
    capacity_point as capacity_point,
)
from .thermal.bearing_thermal import (
    AbstractFrictionHeat as AbstractFrictionHeat,
    AbstractHeatedBearing as AbstractHeatedBearing,
    BearingHeat as BearingHeat,
    MountedBallBearing as MountedBallBearing,
    PalmgrenFactors as PalmgrenFactors,
    ThermalPaths as ThermalPaths,
    ThermalState as ThermalState,
    WaltherLine as WaltherLine,
    solve_thermal as solve_thermal,
)
from .thermal.mounting_paths import (
    Cooling as Cooling,
    MountingGeometry as MountingGeometry,
    mounting_paths as mounting_paths,
    shaft_paths as shaft_paths,
)
from .thermal.pair_thermal import MountedBallPair as MountedBallPair
from .thermal.shaft_thermal import MountedShaft as MountedShaft, shaft_factors as shaft_factors
from .thermal.skf_heat import SkfHeat as SkfHeat
from .friction.skf_friction import SkfBearing as SkfBearing
from .thermal.thermal_network import (
    ThermalNetwork as ThermalNetwork,
    boundary_heat_flows as boundary_heat_flows,
    edge_heat_flows as edge_heat_flows,
    node_temperatures as node_temperatures,
)
from .thermal.thermal_speed import (
    SpeedRating as SpeedRating,
    heat_balance_speed as heat_balance_speed,
    thermal_reference_speed as thermal_reference_speed,
    thermally_safe_speed as thermally_safe_speed,
)
from .catalog.designations import boundary_dimensions as boundary_dimensions, designations as designations
from .catalog.internal_geometry import estimate_ball_set as estimate_ball_set
from .app.model import build_model as build_model, run_model as run_model
from .app.rotor_handoff import (
    export_stiffness as export_stiffness,
    stiffness_over_speed as stiffness_over_speed,
    to_ross as to_ross,
)
from .app.scene import examples as examples, load_scene as load_scene
from .app.sweep import run_sweep as run_sweep

__version__ = _version("diffbearing")
