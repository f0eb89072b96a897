"""Thermal speed ratings: the speed at which a bearing's friction heat equals the heat carried away.

Both ratings solve one heat balance for the speed n (Palmgren's moments, `friction.friction_torque`):

    N(n) = (M₀(n) + M₁) ω = Φ,   M₀ = 10⁻⁷ f₀ (ν n)^{2/3} d_m³ (ν n ≥ 2000 mm²/s·r/min, else 160·10⁻⁷ f₀ d_m³),
    M₁ = f₁ P₁ d_m  [N·mm, catalogue units: ν mm²/s, n r/min, d_m mm]

with N the friction power and Φ the heat flow carried away (`heat_balance_speed`: Newton on ln n, the
implicit derivative through the root, optimistix).

* ISO 15312:2003 thermal reference speed n_θr (`thermal_reference_speed`) under the standard's
  reference conditions, as Schaeffler HR 1 (2006, "Speeds", pp. 62–64) transcribes them: outer ring at
  70 °C in 20 °C ambient; P₁r = 0.05 C₀r (radial) or 0.02 C₀a (thrust); ν_r = 12 mm²/s (ISO VG 32 at
  70 °C, radial) or 24 mm²/s (ISO VG 68, thrust); the heat flow Φ_r = q_r A_r through the reference
  surface A_r = π W (D + d) (radial: W the bearing's total width, a tapered bearing's T) or
  π/2 (D² − d²) (thrust), at q_r = 16 kW/m² (radial) or 20 kW/m² (thrust) up to A_r = 50 000 mm², and
  q_r (A_r/50 000 mm²)^−0.34 (radial) or ^−0.16 (thrust) above. The factors f₀r, f₁r are the
  bearing's oil-lubricated f₀ and f₁ = a (P₀/C₀)^b at P₀/C₀ = 0.05 (ISO 15312's own table of f₀r, f₁r
  was not to hand; with HR 1's factor tables this reproduces HR 1's printed n_θr, tests/
  test_thermal_speed.py).
* DIN 732:2010 thermally safe operating speed n_θ (`thermally_safe_speed`): the same balance at the
  actual load P₁, viscosity ν and the heat flows of the mounting — through the bearing seats
  Φ_S = k_q A_r ΔT_A (k_q about 0.2–1.0·10⁻³ W/(mm²·K), HR 1 p. 63) and carried by circulating oil
  Φ_L = ρc V̇ ΔT_L (0.0286 kW/(l/min·K), `OIL_HEAT_PER_FLOW`). DIN 732 writes it as n_θ = f_n n_θr with
  k_L f_n^{5/3} + k_P f_n = 1, k_L = N₀(n_θr)/Φ, k_P = N₁(n_θr)/Φ (the viscous and load powers at n_θr
  over the heat flow): the same root where ν n ≥ 2000 (`speed_ratio`).
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import optimistix as optx

from ..friction import friction_torque

RPM = jnp.pi / 30.0  # rad/s per r/min
# ISO 15312 reference conditions: arrangement → (P₁r/C₀, ν_r [m²/s], q_r [W/m²] up to A_r = `AREA_BREAK`,
# the exponent of (A_r/AREA_BREAK) above it)
REFERENCE_CONDITIONS = {"radial": (0.05, 12e-6, 16e3, -0.34), "thrust": (0.02, 24e-6, 20e3, -0.16)}
AREA_BREAK = 0.05  # m² (50 000 mm²)
# the friction kinds (`friction_torque.PALMGREN_CONSTANTS`) rated under the thrust conditions; all others radial
THRUST_KINDS = ("thrust_ball", "cylindrical_roller_thrust")


def reference_arrangement(kind: str) -> str:
    """The reference conditions ("radial" or "thrust", `REFERENCE_CONDITIONS`) of a friction kind."""
    return "thrust" if kind in THRUST_KINDS else "radial"

REFERENCE_OUTER_RING_TEMPERATURE = 343.15  # K (70 °C)
REFERENCE_AMBIENT_TEMPERATURE = 293.15  # K (20 °C)
OIL_HEAT_PER_FLOW = 0.0286e3 / (1e-3 / 60.0)  # W per (m³/s · K): DIN 732's 0.0286 kW/(l/min·K), ρc of mineral oil
SOLVER = optx.Newton(rtol=1e-12, atol=1e-12)
LOWEST_SPEED = 1e-6 * RPM  # rad/s: the search's floor (a heat flow no speed's friction stays under is below it)


class SpeedRating(eqx.Module):
    """A thermal speed rating (SI): the speed [rad/s], the heat flow it balances [W], the viscous and
    load-dependent friction powers at that speed [W], whether the root converged."""

    speed: jax.Array
    heat_flow: jax.Array
    viscous_power: jax.Array
    load_power: jax.Array
    converged: jax.Array


def reference_surface(bore, outside_diameter, width, arrangement: str = "radial"):
    """ISO 15312's heat-dissipating reference surface A_r [m²]: π W (D + d) of a radial bearing of
    total width W, π/2 (D² − d²) of a thrust bearing (d, D [m])."""
    if arrangement == "thrust":
        return 0.5 * jnp.pi * (outside_diameter**2 - bore**2)
    return jnp.pi * width * (outside_diameter + bore)


def reference_heat_flow_density(area, arrangement: str = "radial"):
    """ISO 15312's reference heat flow density q_r [W/m²] of a reference surface A_r [m²]."""
    _, _, density, exponent = REFERENCE_CONDITIONS[arrangement]
    return density * jnp.where(area > AREA_BREAK, (jnp.maximum(area, AREA_BREAK) / AREA_BREAK) ** exponent, 1.0)


def _powers(speed, f0, load_moment, kinematic_viscosity, pitch_diameter):
    """(viscous, load) friction powers [W] at the speed [rad/s]."""
    viscous = friction_torque.viscous_torque(f0, kinematic_viscosity, speed, pitch_diameter)
    return viscous * speed, load_moment * speed


def _balance(log_speed, args):
    """ln N(n) − ln Φ: smooth and increasing in ln n, its slope between 1 and 5/3."""
    f0, load_moment, kinematic_viscosity, pitch_diameter, heat_flow = args
    viscous, load = _powers(jnp.exp(log_speed), f0, load_moment, kinematic_viscosity, pitch_diameter)
    return jnp.log(viscous + load) - jnp.log(heat_flow)


def heat_balance_speed(f0, load_moment, kinematic_viscosity, pitch_diameter, heat_flow) -> SpeedRating:
    """The speed [rad/s] whose Palmgren friction power (M₀(n) + M₁) ω equals the heat flow Φ [W]
    (module docstring): f₀ [-], M₁ = f₁ P₁ d_m [N·m], ν [m²/s], d_m [m]. Differentiable in every
    input (implicit function theorem). A heat flow that is not positive has no such speed: the
    rating is 0, not converged."""
    flow = jnp.asarray(heat_flow, float)
    positive = flow > 0.0
    safe_flow = jnp.where(positive, flow, 1.0)
    args = (f0, load_moment, kinematic_viscosity, pitch_diameter, safe_flow)
    # start: the viscous moment alone at ν n ≥ 2000 (N ∝ n^{5/3}), then the load moment alone, the lower
    viscous_rpm = (safe_flow / (RPM * 1e-10 * f0 * (kinematic_viscosity * 1e6) ** (2.0 / 3.0)
                                * (pitch_diameter * 1e3) ** 3)) ** 0.6
    load_rpm = safe_flow / (RPM * jnp.maximum(load_moment, 1e-300))
    start = jnp.log(jnp.maximum(jnp.minimum(viscous_rpm, load_rpm) * RPM, LOWEST_SPEED))
    solution = optx.root_find(_balance, SOLVER, start, args=args, max_steps=60, throw=False,
                              adjoint=optx.ImplicitAdjoint())
    speed = jnp.exp(solution.value)
    viscous, load = _powers(speed, f0, load_moment, kinematic_viscosity, pitch_diameter)
    converged = (solution.result == optx.RESULTS.successful) & positive
    zero = jnp.zeros_like(speed)
    return SpeedRating(jnp.where(positive, speed, zero), flow, jnp.where(positive, viscous, zero),
                       jnp.where(positive, load, zero), converged)


def reference_friction_factor(coefficient, exponent, arrangement: str = "radial"):
    """f₁r = a (P₀/C₀)^b at ISO 15312's reference load P₀ = P₁r (0.05 C₀r radial, 0.02 C₀a thrust)."""
    share, _, _, _ = REFERENCE_CONDITIONS[arrangement]
    return coefficient * share**exponent if exponent else jnp.asarray(coefficient, float)


def thermal_reference_speed(f0, f1, static_rating, bore, outside_diameter, width, arrangement: str = "radial"
                            ) -> SpeedRating:
    """ISO 15312's thermal reference speed n_θr [rad/s] (module docstring) of a bearing of bore d,
    outside diameter D and total width W [m] (W unused for thrust bearings), static rating C₀ [N],
    with its reference factors f₀r (oil) and f₁r (`reference_friction_factor`)."""
    share, viscosity, _, _ = REFERENCE_CONDITIONS[arrangement]
    pitch = 0.5 * (bore + outside_diameter)
    area = reference_surface(bore, outside_diameter, width, arrangement)
    load_moment = friction_torque.load_torque(f1, share * static_rating, pitch)
    return heat_balance_speed(f0, load_moment, viscosity, pitch, reference_heat_flow_density(area, arrangement) * area)


def seat_heat_flow(heat_transfer_coefficient, area, temperature_difference):
    """DIN 732's heat flow through the bearing seats Φ_S = k_q A ΔT_A [W] (k_q [W/(m²·K)], A [m²], ΔT_A [K])."""
    return heat_transfer_coefficient * area * temperature_difference


def oil_heat_flow(volume_flow, temperature_difference):
    """DIN 732's heat flow carried by circulating oil Φ_L = 0.0286 kW/(l/min·K) V̇ ΔT_L [W] (V̇ [m³/s], ΔT_L [K])."""
    return OIL_HEAT_PER_FLOW * volume_flow * temperature_difference


def thermally_safe_speed(f0, f1, load, kinematic_viscosity, pitch_diameter, heat_flow) -> SpeedRating:
    """DIN 732's thermally safe operating speed n_θ [rad/s]: the heat balance at the actual load P₁ [N],
    viscosity ν [m²/s] and heat flow Φ = Φ_S + Φ_L [W] (`seat_heat_flow`, `oil_heat_flow`)."""
    return heat_balance_speed(f0, friction_torque.load_torque(f1, load, pitch_diameter), kinematic_viscosity,
                              pitch_diameter, heat_flow)


def speed_ratio(viscous_share, load_share):
    """DIN 732's f_n from k_L f_n^{5/3} + k_P f_n = 1 (k_L, k_P > 0: the viscous and load powers at n_θr
    over the actual heat flow); Newton on ln f_n."""
    def residual(log_ratio, args):
        k_viscous, k_load = args
        ratio = jnp.exp(log_ratio)
        return jnp.log(k_viscous * ratio ** (5.0 / 3.0) + k_load * ratio)

    start = -jnp.log(viscous_share + load_share)
    solution = optx.root_find(residual, SOLVER, start, args=(viscous_share, load_share), max_steps=60, throw=False,
                              adjoint=optx.ImplicitAdjoint())
    return jnp.exp(solution.value)
