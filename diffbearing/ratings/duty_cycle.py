"""A duty cycle's life by the Palmgren–Miner rule (ISO 281:2007 §7 on variable loads and speeds;
ISO/TS 16281 §12 likewise for L10r): load cases i, each run for a share of the revolutions u_i
(Σ u_i = 1), wear the bearing as their damages add,

    1 / L = Σ u_i / L_i                      (any of L10, L10r, L10m, L10rm, L_n …)
    P = (Σ u_i P_i^p)^{1/p}                  the equivalent load with the same basic life (C/P)^p
    u_i = t_i |n_i| / Σ_j t_j |n_j|          from shares of time t_i at the speeds n_i
    n_m = Σ t_i |n_i|                        the mean speed, for the life in hours L / (60 n_m)

and case i's share of the damage is (u_i / L_i) · L. Pure JAX, differentiable in every argument.
"""

import jax.numpy as jnp


def revolution_shares(time_shares, speeds):
    """u_i [-] (Σ = 1) from shares of time t_i [-] (Σ = 1) at relative ring speeds n_i [rad/s]."""
    turns = jnp.asarray(time_shares) * jnp.abs(jnp.asarray(speeds))
    return turns / jnp.sum(turns)


def mean_speed(time_shares, speeds):
    """n_m = Σ t_i |n_i| [rad/s]."""
    return jnp.sum(jnp.asarray(time_shares) * jnp.abs(jnp.asarray(speeds)))


def miner_life(lives, shares):
    """L = 1 / Σ u_i / L_i, in the lives' unit, from the cases' lives L_i and revolution shares u_i
    (leading axis the cases)."""
    shares = jnp.reshape(jnp.asarray(shares), (-1,) + (1,) * (jnp.ndim(lives) - 1))
    return 1.0 / jnp.sum(shares / jnp.asarray(lives), axis=0)


def damage_shares(lives, shares):
    """Each case's share of the cycle's damage, (u_i / L_i) / Σ_j u_j / L_j [-]."""
    shares = jnp.reshape(jnp.asarray(shares), (-1,) + (1,) * (jnp.ndim(lives) - 1))
    damage = shares / jnp.asarray(lives)
    return damage / jnp.sum(damage, axis=0)


def equivalent_load(loads, shares, exponent):
    """P = (Σ u_i P_i^p)^{1/p} [N] of the cases' equivalent loads P_i [N] at revolution shares u_i,
    p the life exponent (3 ball, 10/3 roller bearings)."""
    return jnp.sum(jnp.asarray(shares) * jnp.asarray(loads) ** exponent) ** (1.0 / exponent)
