"""The life modification factor for reliability a₁ of ISO 281:2007 §9.2, Table 12 (GOST 18855-2013):
the life a population of bearings reaches with probability R instead of 90 %,

    L_nm = a₁ a_ISO L10,     a₁ = 0.95 (ln(100/R) / ln(100/90))^{2/3} + 0.05     (90 ≤ R ≤ 99.95 %)

the Weibull form behind the table (Weibull slope 1.5 above a floor of 0.05 L10, the standard's
life-reliability relation for R ≥ 90 %); Table 12's rows (`TABLE_12`) are this form to their printed
rounding (tests), and between them diffbearing uses the form itself. ISO/TS 16281 applies a₁ to
L10r and L10rm alike (L_nrm = a₁ a_ISO L10r).
"""

import jax.numpy as jnp

from ..params import check_range

# ISO 281:2007 Table 12: reliability R [%] → a₁, as printed
TABLE_12 = ((90.0, 1.0), (95.0, 0.64), (96.0, 0.55), (97.0, 0.47), (98.0, 0.37), (99.0, 0.25), (99.2, 0.22),
            (99.4, 0.19), (99.6, 0.16), (99.8, 0.12), (99.9, 0.093), (99.92, 0.087), (99.94, 0.080), (99.95, 0.077))
LOWEST, HIGHEST = 90.0, 99.95  # % : the reliabilities Table 12 covers


def reliability_factor(reliability):
    """a₁ [-] for the reliability R [%] (module docstring); ValueError naming `life.reliability`
    outside Table 12's 90–99.95 %."""
    check_range("life.reliability", reliability, low=LOWEST, high=HIGHEST, low_open=False, high_open=False, unit=" %",
                why="ISO 281 Table 12's reliabilities")
    return 0.95 * (jnp.log(100.0 / reliability) / jnp.log(100.0 / 90.0)) ** (2.0 / 3.0) + 0.05
