"""ISO/TS 16281:2008 basic reference rating life from a bearing's contacts (`ContactLoads`), inner
ring rotating: one formula for every bearing type, by contact kind.

Per contact column c (a raceway, or one half of a split raceway) with the lamina loads q_jck [N] of
element j (a point contact has one lamina carrying the element's load) and the column's rating q_c,c
[N] per lamina (the lamina load of a raceway life of 10⁶ revolutions, `AbstractSupport.contact_ratings`):

    rotating ring (inner):  (q_e,ck / q_c,c)^e = (Σ_j q_jck^p / Z)^{e/p} / q_c,c^e
    fixed ring (outer):     (q_e,ck / q_c,c)^e = (Σ_j q_jck^e / Z) / q_c,c^e
    L10r = (Σ_c Σ_k (q_e,ck / q_c,c)^e)^{−p/e}      [10⁶ revolutions]

with p = 3, e = 10/3 for point contacts (ISO/TS 16281 eqs. (24)–(29): the rotating ring's cubic
mean, the fixed ring's 10/3 mean, the raceways combined with exponent 10/9) and p = 4, e = 9/2 for
line contacts (eqs. (61)–(65): per lamina column k). Written in these powers no root of a zero sum
is taken: an unloaded lamina adds exactly 0 with a finite gradient, and a bearing with no load
anywhere has L10r = +inf with a zero gradient. `ratings.life.reference_rating_life` (balls) and
`ratings.roller_life.roller_reference_rating_life` (laminae) are its two cases.
"""

import jax.numpy as jnp

from ..bearings.interface import ContactLoads
from ..numerics import positive_power

# (p, e) per contact kind: the rotating ring's mean power and the life exponent of one raceway
EXPONENTS = {"point": (3.0, 10.0 / 3.0), "line": (4.0, 4.5)}


def contact_reference_life(contacts: ContactLoads, ratings):
    """L10r [10⁶ revolutions] of the bearing whose contacts are `contacts`, inner ring rotating,
    with each column's rating per lamina `ratings` (C,) [N] (module docstring)."""
    mean_power, exponent = EXPONENTS[contacts.kind]
    count = contacts.lamina_load.shape[0]
    damage = 0.0
    for column, raceway in enumerate(contacts.raceways):
        loads = contacts.lamina_load[:, column, :]
        if raceway == "inner":  # rotating
            mean = positive_power(jnp.sum(positive_power(loads, mean_power), axis=0) / count, exponent / mean_power)
        else:
            mean = jnp.sum(positive_power(loads, exponent), axis=0) / count
        damage = damage + jnp.sum(mean) / ratings[column] ** exponent
    loaded = damage > 0.0
    return jnp.where(loaded, jnp.where(loaded, damage, 1.0) ** (-mean_power / exponent), jnp.inf)
