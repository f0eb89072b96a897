"""Thermal conductances G [W/K] of the paths in a bearing's thermal network (`thermal_network`):
closed forms of steady conduction, convection and a fluid's flow (Incropera, DeWitt, Bergman &
Lavine, Fundamentals of Heat and Mass Transfer, 6th ed., §3.1, §3.3, §3.6; Harris & Kotzalas,
Rolling Bearing Analysis, 5th ed., vol. 1, ch. 13)."""

import jax.numpy as jnp


def plane_wall(conductivity, area, thickness):
    """Conduction through a plane wall: G = k A / L (k [W/(m·K)], A [m²], L [m]); Incropera eq. 3.6."""
    return conductivity * area / thickness


def cylindrical_shell(conductivity, length, inner_radius, outer_radius):
    """Radial conduction through a cylindrical shell: G = 2π k L / ln(r₂/r₁); Incropera eq. 3.27."""
    return 2.0 * jnp.pi * conductivity * length / jnp.log(outer_radius / inner_radius)


def convection(heat_transfer_coefficient, area):
    """Convection from a surface: G = h A (h [W/(m²·K)], A [m²]); Incropera eq. 3.9."""
    return heat_transfer_coefficient * area


def fin(heat_transfer_coefficient, perimeter, conductivity, cross_section, length):
    """A fin of uniform cross-section with an adiabatic tip (a shaft end in air): G = √(h P k A) tanh(m L),
    m = √(h P/(k A)), the heat it sheds per kelvin of its base over the fluid; Incropera eq. 3.76."""
    m = jnp.sqrt(heat_transfer_coefficient * perimeter / (conductivity * cross_section))
    return jnp.sqrt(heat_transfer_coefficient * perimeter * conductivity * cross_section) * jnp.tanh(m * length)


def advection(volume_flow, volumetric_heat_capacity):
    """A fluid's flow from a held inlet temperature through a well-mixed node: G = ρc V̇ (V̇ [m³/s],
    ρc [J/(m³·K)]), the heat it carries out per kelvin of the node over the inlet."""
    return volumetric_heat_capacity * volume_flow


def in_series(*conductances):
    """Paths one after another: 1/G = Σ 1/Gᵢ (Incropera eq. 3.19)."""
    return 1.0 / sum(1.0 / g for g in conductances)


def rotating_cylinder_coefficient(speed, diameter, kinematic_viscosity, conductivity, prandtl):
    """h [W/(m²·K)] of a cylinder turning at `speed` Ω [rad/s] in a still fluid: Nu_D = 0.133 Re_D^{2/3}
    Pr^{1/3}, Re_D = Ω D²/ν, for Re_D < 4.3e5 and 0.7 < Pr < 670 (Incropera et al., 7th ed., problem 9.62,
    after Kays & Bjorklund); 0 at rest (the double `where` keeps the derivative finite there)."""
    reynolds = jnp.abs(speed) * diameter ** 2 / kinematic_viscosity
    turning = reynolds > 0.0
    safe = jnp.where(turning, reynolds, 1.0)
    return jnp.where(turning, 0.133 * safe ** (2.0 / 3.0) * prandtl ** (1.0 / 3.0) * conductivity / diameter, 0.0)
