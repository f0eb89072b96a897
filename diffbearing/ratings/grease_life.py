"""Grease life of a greased-for-life single-row deep groove ball bearing: the manufacturers'
published closed forms of the average life t [h] of the grease packed into it (no relubrication).

NSK, *Rolling Bearings*, CAT. No. E1102, §12.2.1 (4) "Grease Life of Totally Enclosed Ball
Bearings", eqs. (12.1) and (12.2):

    log t = a − b n/N_max − (c − e n/N_max) T

with n the speed and N_max the bearing's limiting speed with grease lubrication (the ZZ/VV values
of NSK's bearing tables) [r/min], T the operating temperature [°C]; general-purpose grease
(mineral base, lithium soap) a, b, c, e = 6.54, 2.6, 0.025, 0.012 for 70 ≤ T ≤ 110 °C; wide-range
grease (synthetic base) 6.12, 1.4, 0.018, 0.006 for 70 ≤ T ≤ 130 °C. It applies for
0.25 ≤ n/N_max ≤ 1 (below, n/N_max = 0.25 is taken), T < 70 °C is taken as 70 °C, and "the bearing
loads should be about 1/10 or less of the basic load rating C_r".

JTEKT (Koyo), *Ball & Roller Bearings*, CAT. No. BS004, eq. (12-1), shielded and sealed deep groove
ball bearings, and FYH, *Ball Bearing Units*, CAT. No. 3300, eq. (4.7) (JTEKT's ball bearing
units catalogue prints the same), one form with their own load term:

    log L = 6.10 − 4.40·10⁻⁶ d_m n − k (P_r/C_r − p₀) − (0.021 − 1.80·10⁻⁸ d_m n) T

with d_m = (D + d)/2 [mm], n [r/min], P_r the dynamic equivalent radial load and C_r the basic
dynamic radial load rating, T the bearing's operating temperature [°C]. Sealed bearings (BS004):
k = 3.125, p₀ = 0.04, for T ≤ 120 °C (T < 50 taken as 50), 125·10³ ≤ d_m n ≤ 500·10³ (below, taken
as 125·10³), 0.04 ≤ P_r/C_r ≤ 0.16 (below, 0.04). Bearing units (FYH): k = 2.50, p₀ = 0.05, for
T ≤ 100 °C (T < 50 taken as 50), d_m n ≤ 300·10³ (below, 125·10³), P_r/C_r ≤ 0.2 (below, 0.05).
Beyond the upper limits the catalogues say to consult the manufacturer: the model does not hold.

The logarithms are decadic (the catalogues' charts plot t on a decadic scale; FYH's worked
example 8, log L = 4.542 → L ≈ 34 800 h, is one). Every input in SI, the life in seconds.
"""

import abc
import math
from typing import NamedTuple

import equinox as eqx
import jax
import jax.numpy as jnp

HOUR = 3600.0  # s
CELSIUS_ZERO = 273.15  # K


class GreaseLife(eqx.Module):
    """The grease life and the operating point it was taken at (after the method's floors)."""

    life: jax.Array  # average grease life [s]
    temperature: jax.Array  # T the formula read [K]: the operating temperature, raised to the method's floor
    speed_term: jax.Array  # n/N_max (NSK) or d_m n [mm·r/min] (JTEKT, FYH) the formula read
    load_ratio: jax.Array  # P_r/C_r of the operating point (not floored)


class GreaseLifeLimits(NamedTuple):
    """A method's upper bounds: temperature [K], its speed term (named `speed_name`, in
    `speed_unit`), P_r/C_r; `load_is_guide`: the load bound is a guide ("about"), not a bound."""

    temperature: float
    speed: float
    load_ratio: float
    load_is_guide: bool
    speed_name: str
    speed_unit: str


class AbstractGreaseLife(eqx.Module):
    """One published grease-life formula: `grease_life(...)` and its envelope `limits()`."""

    @abc.abstractmethod
    def grease_life(self, speed, limiting_speed, bore, outer_diameter, equivalent_load, dynamic_load_rating,
                    temperature) -> GreaseLife:
        """The grease life at the relative ring `speed` [rad/s] (its magnitude), the bearing's grease
        `limiting_speed` [rad/s] (read by NSK's form only), its `bore` and `outer_diameter` [m], its
        `equivalent_load` P_r and `dynamic_load_rating` C_r [N] and its operating `temperature` [K]."""

    @abc.abstractmethod
    def limits(self) -> GreaseLifeLimits:
        """The bounds the catalogue states."""


class NskGreaseLife(AbstractGreaseLife):
    """NSK's eq. (12.1) or (12.2) (module docstring): `constant` a, `speed_factor` b,
    `temperature_factor` c, `coupling_factor` e, up to `upper_temperature` [K]."""

    constant: float = eqx.field(static=True)
    speed_factor: float = eqx.field(static=True)
    temperature_factor: float = eqx.field(static=True)
    coupling_factor: float = eqx.field(static=True)
    upper_temperature: float = eqx.field(static=True)

    def grease_life(self, speed, limiting_speed, bore, outer_diameter, equivalent_load, dynamic_load_rating,
                    temperature) -> GreaseLife:
        ratio = jnp.maximum(jnp.abs(speed) / limiting_speed, 0.25)
        celsius = jnp.maximum(temperature - CELSIUS_ZERO, 70.0)
        exponent = (self.constant - self.speed_factor * ratio
                    - (self.temperature_factor - self.coupling_factor * ratio) * celsius)
        return GreaseLife(10.0 ** exponent * HOUR, celsius + CELSIUS_ZERO, ratio, equivalent_load / dynamic_load_rating)

    def limits(self) -> GreaseLifeLimits:
        return GreaseLifeLimits(self.upper_temperature, 1.0, 0.1, True, "n/N_max", "")


class JtektGreaseLife(AbstractGreaseLife):
    """JTEKT's and FYH's form (module docstring): load term `load_factor` k (P_r/C_r − `load_floor`
    p₀), up to `upper_temperature` [K], d_m n up to `upper_speed` [mm·r/min] and P_r/C_r up to
    `upper_load_ratio`."""

    load_factor: float = eqx.field(static=True)
    load_floor: float = eqx.field(static=True)
    upper_temperature: float = eqx.field(static=True)
    upper_speed: float = eqx.field(static=True)
    upper_load_ratio: float = eqx.field(static=True)

    def grease_life(self, speed, limiting_speed, bore, outer_diameter, equivalent_load, dynamic_load_rating,
                    temperature) -> GreaseLife:
        mean_diameter = (bore + outer_diameter) / 2 * 1e3  # d_m [mm]
        dmn = jnp.maximum(mean_diameter * jnp.abs(speed) * 30.0 / math.pi, 125e3)
        load_ratio = equivalent_load / dynamic_load_rating
        celsius = jnp.maximum(temperature - CELSIUS_ZERO, 50.0)
        exponent = (6.10 - 4.40e-6 * dmn - self.load_factor * (jnp.maximum(load_ratio, self.load_floor) - self.load_floor)
                    - (0.021 - 1.80e-8 * dmn) * celsius)
        return GreaseLife(10.0 ** exponent * HOUR, celsius + CELSIUS_ZERO, dmn, load_ratio)

    def limits(self) -> GreaseLifeLimits:
        return GreaseLifeLimits(self.upper_temperature, self.upper_speed, self.upper_load_ratio, False, "d_m n",
                                " mm·r/min")


# option string → method, once (module docstring; the scene's grease_life.method)
GREASE_LIFE_METHODS = {
    "nsk_general_purpose": NskGreaseLife(6.54, 2.6, 0.025, 0.012, 110.0 + CELSIUS_ZERO),
    "nsk_wide_range": NskGreaseLife(6.12, 1.4, 0.018, 0.006, 130.0 + CELSIUS_ZERO),
    "jtekt_sealed": JtektGreaseLife(3.125, 0.04, 120.0 + CELSIUS_ZERO, 500e3, 0.16),
    "fyh_bearing_unit": JtektGreaseLife(2.50, 0.05, 100.0 + CELSIUS_ZERO, 300e3, 0.2),
}
# what a report says of each: the source and its grease
GREASE_LIFE_SOURCES = {
    "nsk_general_purpose": "NSK CAT. E1102 eq. (12.1), general-purpose (mineral-oil, lithium soap) grease",
    "nsk_wide_range": "NSK CAT. E1102 eq. (12.2), wide-range (synthetic-oil) grease",
    "jtekt_sealed": "JTEKT CAT. BS004 eq. (12-1), shielded and sealed deep groove ball bearings",
    "fyh_bearing_unit": "FYH CAT. 3300 eq. (4.7), ball bearing units",
}


def envelope_problems(method: AbstractGreaseLife, found: GreaseLife, where: str = "") -> tuple[list[str], list[str]]:
    """(errors, warnings) of an operating point against `method`'s limits (concrete values): beyond
    its temperature, speed or load bound the formula does not hold (an error); NSK's "about 1/10 of
    C_r" is a warning. `where` prefixes each line (a shaft's bearings[i])."""
    limits = method.limits()
    errors, warnings = [], []
    temperature = float(found.temperature)
    if temperature > limits.temperature:
        errors.append(f"{where}grease_life: the operating temperature {temperature - CELSIUS_ZERO:.4g} °C is above the "
                      f"method's {limits.temperature - CELSIUS_ZERO:.4g} °C")
    speed = float(found.speed_term)
    if speed > limits.speed:
        errors.append(f"{where}grease_life: {limits.speed_name} = {speed:.4g}{limits.speed_unit} is above the "
                      f"method's {limits.speed:.4g}{limits.speed_unit}")
    load = float(found.load_ratio)
    if load > limits.load_ratio:
        line = f"{where}grease_life: P_r/C_r = {load:.3g} is above the method's {limits.load_ratio:.3g}"
        if limits.load_is_guide:
            warnings.append(line + " (its \"about 1/10 or less\" of C_r: the life leans on it)")
        else:
            errors.append(line)
    return errors, warnings
