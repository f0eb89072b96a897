"""Life modification factor a_ISO of ISO 281:2007 §9.3: lubrication (viscosity ratio κ),
contamination (e_C) and the fatigue load limit C_u.

* `reference_viscosity` — the rated viscosity ν₁ [mm²/s] at the pitch diameter D_pw [mm] and speed
  n [r/min] (ISO 281 eqs. (28)–(29)): ν₁ = 45000 n^{−0.83} D_pw^{−0.5} below 1000 r/min,
  ν₁ = 4500 n^{−0.5} D_pw^{−0.5} from 1000 r/min; κ = ν/ν₁.
* `contamination_factor` — ISO 281 Annex A: e_C = a (1 − c₂ D_pw^{−1/3}), a = min(1, c₁ κ^{0.68} D_pw^{0.55}),
  clipped to [0, 1], with (c₁, c₂) of the lubrication and cleanliness (`CONTAMINATION_CONSTANTS`).
* `fatigue_load_limit` — ISO 281 Annex B's simplified estimate: C_u = C₀/22 (ball), C₀/8.2 (roller),
  times (100/D_pw)^{0.5} (ball) or (100/D_pw)^{0.3} (roller) above D_pw = 100 mm.
* `life_modification_factor` — ISO 281 eqs. (31)–(36), x = e_C C_u / P:
      ball    a_ISO = 0.1 [1 − (2.5671 − c/κ^p)^{0.83} x^{1/3}]^{−9.3}
      roller  a_ISO = 0.1 [1 − (1.5859 − c/κ^p) x^{0.4}]^{−9.185}
  (c, p) = (2.2649, 0.054381), (1.9987, 0.19087), (1.9987, 0.071739) for the ball and (1.3993,
  0.054381), (1.2348, 0.19087), (1.2348, 0.071739) for the roller over 0.1 ≤ κ < 0.4, 0.4 ≤ κ < 1,
  1 ≤ κ ≤ 4; κ above 4 is taken as 4, below 0.1 (outside the standard) as 0.1; a_ISO ≤ 50.
* `life_modification_factor_ep` — with a lubricant of proven effective EP additives, where κ < 1
  and e_C ≥ 0.2: a_ISO at κ = 1, at most 3 and not below a_ISO at the actual κ (DIN ISO 281
  Beiblatt 1:2003, as SKF's catalogue states it, "Consideration of EP additives").

Sources: ISO 281 is not public; its equations are taken from open implementations that agree on
every constant used here (two Python, one Rust, two MATLAB; two Python copies carry a typo 0.019087
for 0.19087, which breaks the continuity at κ = 0.4 that the tests check) and from MESYS's and
SKF's manuals; ν₁, e_C and C_u are checked against MASTA's values for an NSK HR30306J as published
with the Rust implementation (docs/validation.md). The e_C constants of the oil tables come from one
implementation (a MATLAB transcription of all of Annex A) and are the least confirmed numbers here.
"""

import jax.numpy as jnp

from ..numerics import positive_power

KAPPA_RANGE = (0.1, 4.0)
A_ISO_CAP = 50.0
EP_ADDITIVE_CAP = 3.0  # a_ISO with EP additives where they count (κ < 1, e_C ≥ 0.2)
EP_ADDITIVE_CLEANLINESS = 0.2  # the least e_C where EP additives count

# ISO 281 Annex A: (c₁, c₂) of e_C by lubrication and cleanliness; oil by its ISO 4406 code.
CONTAMINATION_CONSTANTS = {
    "circulating": {  # circulating oil with on-line filters
        "-/13/10": (0.0864, 0.5663), "-/15/12": (0.0432, 0.9987), "-/17/14": (0.0288, 1.6329),
        "-/19/16": (0.0216, 2.3362)},
    "oil_bath": {  # oil bath, or circulating oil without filters
        "-/15/12": (0.0864, 0.6796), "-/17/14": (0.0288, 1.141), "-/19/16": (0.0133, 1.67),
        "-/21/18": (0.00864, 2.5164), "-/23/20": (0.00411, 3.8974)},
    "grease": {
        "high": (0.0864, 0.6796), "normal": (0.0432, 1.141), "slight_to_typical": (0.0177, 1.677),
        "severe": (0.0115, 2.662), "very_severe": (0.00617, 4.06)},
}

# ISO 281 eqs. (31)–(36): per rolling element, the constant term, the exponent of its bracket, the
# load exponent, the outer exponent, and (c, p) of the three κ bands.
_A_ISO = {
    "ball": (2.5671, 0.83, 1.0 / 3.0, -9.3, ((2.2649, 0.054381), (1.9987, 0.19087), (1.9987, 0.071739))),
    "roller": (1.5859, 1.0, 0.4, -9.185, ((1.3993, 0.054381), (1.2348, 0.19087), (1.2348, 0.071739))),
}


def reference_viscosity(speed, pitch_diameter):
    """Rated kinematic viscosity ν₁ [m²/s] at relative speed `speed` [rad/s] and D_pw [m]
    (ISO 281 eqs. (28)–(29)); infinite at standstill."""
    rpm = jnp.abs(speed) * 30.0 / jnp.pi
    diameter_mm = pitch_diameter * 1e3
    turning = rpm > 0.0
    safe_rpm = jnp.where(turning, rpm, 1.0)
    slow, fast = 45000.0 * safe_rpm**-0.83, 4500.0 * safe_rpm**-0.5
    return jnp.where(turning, jnp.where(rpm < 1000.0, slow, fast) * diameter_mm**-0.5 * 1e-6, jnp.inf)


def contamination_factor(viscosity_ratio, pitch_diameter, constants):
    """ISO 281 Annex A contamination factor e_C [-] at κ and D_pw [m] for (c₁, c₂) of
    `CONTAMINATION_CONSTANTS`."""
    c1, c2 = constants
    diameter_mm = pitch_diameter * 1e3
    a = jnp.minimum(1.0, c1 * positive_power(viscosity_ratio, 0.68) * diameter_mm**0.55)
    return jnp.clip(a * (1.0 - c2 * diameter_mm ** (-1.0 / 3.0)), 0.0, 1.0)


def fatigue_load_limit(static_load_rating, pitch_diameter, rolling_element: str):
    """ISO 281 Annex B simplified fatigue load limit C_u [N] from C₀ [N] and D_pw [m]."""
    divisor, exponent = {"ball": (22.0, 0.5), "roller": (8.2, 0.3)}[rolling_element]
    large = jnp.maximum(pitch_diameter * 1e3, 100.0)
    return static_load_rating / divisor * (100.0 / large) ** exponent


def life_modification_factor(viscosity_ratio, contamination_load_ratio, rolling_element: str):
    """a_ISO [-] of ISO 281 eqs. (31)–(36) at κ and x = e_C C_u / P [-] (module docstring), ≤ 50."""
    if rolling_element not in _A_ISO:
        raise ValueError(f"rolling_element must be one of {tuple(_A_ISO)}, got {rolling_element!r}")
    base, bracket_exponent, load_exponent, outer_exponent, bands = _A_ISO[rolling_element]
    kappa = jnp.clip(viscosity_ratio, *KAPPA_RANGE)
    band = jnp.where(kappa < 0.4, 0, jnp.where(kappa < 1.0, 1, 2))
    c = jnp.array([b[0] for b in bands])[band]
    p = jnp.array([b[1] for b in bands])[band]
    lubrication = positive_power(base - c / kappa**p, bracket_exponent)
    bracket = 1.0 - lubrication * positive_power(contamination_load_ratio, load_exponent)
    capped = bracket <= (A_ISO_CAP / 0.1) ** (1.0 / outer_exponent)
    return jnp.where(capped, A_ISO_CAP, 0.1 * jnp.where(capped, 1.0, bracket) ** outer_exponent)


def life_modification_factor_ep(viscosity_ratio, contamination_load_ratio, contamination_factor, rolling_element: str):
    """a_ISO [-] with a lubricant of proven effective EP additives at κ, x = e_C C_u / P and e_C [-]
    (module docstring): where κ < 1 and e_C ≥ 0.2, max(a_ISO(κ), min(a_ISO(κ = 1), 3)); elsewhere
    a_ISO(κ)."""
    actual = life_modification_factor(viscosity_ratio, contamination_load_ratio, rolling_element)
    at_unit = life_modification_factor(jnp.ones_like(viscosity_ratio), contamination_load_ratio, rolling_element)
    counts = (viscosity_ratio < 1.0) & (contamination_factor >= EP_ADDITIVE_CLEANLINESS)
    return jnp.where(counts, jnp.maximum(actual, jnp.minimum(at_unit, EP_ADDITIVE_CAP)), actual)
