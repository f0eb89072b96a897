"""The axial thermal growth between the bearings that locate a shaft: the parts between two bearings'
inner rings (the shaft, or a matched pair's inner rings and spacer) and those between their outer
rings (the housing, or the outer rings and spacer) grow by their own expansion at their own
temperatures, so the inner rings move axially against the outer rings and each bearing's preload
offset changes.

Along the bearings' axial positions z_k the inner rings' side grows, from the first bearing on, by
u_i(z_k) = Σ_{j<k} α_i (T̄_i,j − T_ref) Δz_j and the outer rings' side by u_o(z_k) likewise (T̄ the
mean of the two neighbours' temperatures over the span Δz_j between them; a linear temperature
between seats). Bearing k's inner ring then sits u_k = u_i − u_o further along +z against its outer
ring than when cold, and its offset along its own axis (orientation o_k, `AbstractSupport`) becomes
e_k + o_k u_k. A shift common to every bearing is the shaft's own axial displacement, which the
equilibrium solves, so u_k is taken about its mean. Only the bearings that locate axially
(`locates_axially`) take it: a floating bearing's rings slide.

A back-to-back pair's preload pushes its inner rings towards each other (each along its own
axis), so when its inner side runs warmer this growth pulls them apart and the pair loses preload,
against the preload the warmer inner rings' radial growth adds; a face-to-face pair gains preload
from both.
"""

import equinox as eqx
import jax.numpy as jnp

from ..systems.operating_clearance import Mounting


def axial_growth(positions, inner_side_temperatures, outer_side_temperatures, inner_side_expansion,
                 outer_side_expansion, reference_temperature):
    """u_k [m] (K,): each bearing's inner ring's axial displacement against its outer ring by the
    growth of the parts between the bearings (module docstring), about the mean. `positions` z_k
    [m] (K,), in any order; the inner and outer sides' temperatures [K] (K,) at each bearing; their
    linear expansion coefficients [1/K]; the temperature at
    which the bearings were located [K]."""
    positions = jnp.asarray(positions, float)
    order = jnp.argsort(positions)  # the spans between neighbours along z, whatever the bearings' order
    spans = jnp.diff(positions[order])

    def grown(temperatures, expansion):
        temperatures = jnp.asarray(temperatures, float)[order]
        strain = expansion * (0.5 * (temperatures[1:] + temperatures[:-1]) - reference_temperature)
        return jnp.concatenate([jnp.zeros(1), jnp.cumsum(strain * spans)])

    relative = grown(inner_side_temperatures, inner_side_expansion) - grown(outer_side_temperatures, outer_side_expansion)
    return jnp.zeros_like(relative).at[order].set(relative - jnp.mean(relative))


def grown_supports(supports, growth) -> tuple:
    """The supports with each axially locating bearing's offset moved by o_k u_k for the growth
    u_k [m] (`axial_growth`); the others as they are."""
    return tuple(eqx.tree_at(lambda s: s.offset, support, support.offset + support.orientation * shift)
                 if support.locates_axially() else support for support, shift in zip(supports, growth))


def mounted_axial_growth(positions, mountings: tuple[Mounting, ...]):
    """`axial_growth` of the bearings at `positions` [m], bearing k in `mountings[k]`: the shaft's
    growth at each one's shaft temperature against the housing's at its housing temperature, with
    the first mounting's expansion coefficients and reference temperature (one shaft, one housing)."""
    located = mountings[0]
    return axial_growth(positions, jnp.stack([jnp.asarray(m.shaft_temperature, float) for m in mountings]),
                        jnp.stack([jnp.asarray(m.housing_temperature, float) for m in mountings]),
                        located.shaft_expansion, located.housing_expansion, located.reference_temperature)


def pair_growth(spacing, axial_strain):
    """u [m] (2,) of a matched pair whose bearing centres are `spacing` [m] apart (at ∓spacing/2):
    its inner rings and spacer grow against its outer rings and spacer by the strain
    `axial_strain` (`OperatingClearance.axial_strain`: α (T_inner ring − T_outer ring)) over
    that length; `axial_growth` of two bearings whose stacks are at their rings' temperatures."""
    return jnp.array([-0.5, 0.5]) * spacing * axial_strain
