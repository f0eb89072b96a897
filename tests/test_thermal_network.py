"""The steady thermal network (`diffbearing.thermal.thermal_network`) and its conductances against
closed forms: one conduction path, walls in series and in parallel, the thin cylindrical shell as a
plane wall, a convective fin discretised into a chain of nodes against Incropera's tanh(mL); the
energy balance to round-off over random networks; derivatives against central differences; a node
with no path to a held temperature refused."""

import jax.numpy as jnp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from diffbearing.thermal import conductance
from diffbearing.thermal.thermal_network import (
    ThermalNetwork,
    boundary_heat_flows,
    edge_heat_flows,
    node_temperatures,
)

from .helpers import assert_jvp_matches_central_difference

AMBIENT = 293.15


def test_one_conduction_path():
    """A 50 W source behind a 10 mm steel wall of 0.01 m² (k 45 W/(m·K), G = 45 W/K) to a 20 °C
    boundary: T = 20 °C + Q/G = 21.111 °C (1e-13), the boundary takes the 50 W."""
    wall = conductance.plane_wall(45.0, 0.01, 0.01)
    network = ThermalNetwork(("source", "ambient"), ((0, 1),), (1,), jnp.array([wall]), jnp.array([AMBIENT]))
    temperatures = node_temperatures(network, jnp.array([50.0, 0.0]))
    assert float(temperatures[0]) == pytest.approx(AMBIENT + 50.0 / 45.0, rel=1e-13)
    assert float(boundary_heat_flows(network, temperatures, jnp.array([50.0, 0.0]))[0]) == pytest.approx(50.0, rel=1e-12)


def test_walls_in_series_and_in_parallel():
    """Three conductances in series rise by Q Σ 1/G_i; two paths in parallel by Q/(G₁ + G₂) (1e-12)."""
    series = jnp.array([3.0, 5.0, 7.0])
    chain = ThermalNetwork(("a", "b", "c", "ambient"), ((0, 1), (1, 2), (2, 3)), (3,), series, jnp.array([AMBIENT]))
    rise = node_temperatures(chain, jnp.array([10.0, 0.0, 0.0, 0.0]))[0] - AMBIENT
    assert float(rise) == pytest.approx(10.0 * float(jnp.sum(1.0 / series)), rel=1e-12)
    both = ThermalNetwork(("a", "ambient"), ((0, 1), (1, 0)), (1,), jnp.array([3.0, 5.0]), jnp.array([AMBIENT]))
    rise = node_temperatures(both, jnp.array([10.0, 0.0]))[0] - AMBIENT
    assert float(rise) == pytest.approx(10.0 / 8.0, rel=1e-12)


def test_a_thin_cylindrical_shell_is_a_plane_wall():
    """2π k L/ln(r₂/r₁) → k (2π r̄ L)/(r₂ − r₁) as the shell thins: below it by x²/3, x = t/(r₁ + r₂)
    (ln((1 + x)/(1 − x)) = 2x (1 + x²/3 + …))."""
    for thickness in (1e-3, 1e-4):
        inner, outer = 0.05, 0.05 + thickness
        shell = float(conductance.cylindrical_shell(45.0, 0.02, inner, outer))
        wall = float(conductance.plane_wall(45.0, 2 * np.pi * 0.5 * (inner + outer) * 0.02, thickness))
        assert shell / wall - 1.0 == pytest.approx(-((thickness / (inner + outer)) ** 2) / 3.0, rel=2e-3)


@pytest.mark.parametrize("segments", [40, 160])
def test_a_convective_fin_as_a_chain_of_nodes(segments):
    """A steel rod (Ø 20 mm, 100 mm, k 45 W/(m·K)) in air (h 25 W/(m²·K)), adiabatic at its tip, cut into
    N segments (axial conduction between their centres, convection from each side surface): the base
    conductance Q/(T_base − T_∞) approaches Incropera's √(hPkA) tanh(mL) as 1/N² (within 2/N²)."""
    diameter, length, k, h = 0.02, 0.1, 45.0, 25.0
    area, perimeter = np.pi * diameter**2 / 4, np.pi * diameter
    step = length / segments
    # nodes: base (held at T_b), segment centres 1..N, ambient (held); the base to the first centre is half a step
    names = ("base", *(f"s{i}" for i in range(segments)), "ambient")
    ambient = segments + 1
    edges, values = [(0, 1)], [conductance.plane_wall(k, area, step / 2)]
    for i in range(1, segments):
        edges.append((i, i + 1))
        values.append(conductance.plane_wall(k, area, step))
    for i in range(1, segments + 1):
        edges.append((i, ambient))
        values.append(conductance.convection(h, perimeter * step))
    network = ThermalNetwork(names, tuple(edges), (0, ambient), jnp.array(values), jnp.array([AMBIENT + 50.0, AMBIENT]))
    temperatures = node_temperatures(network, jnp.zeros(len(names)))
    base_flow = float(boundary_heat_flows(network, temperatures, jnp.zeros(len(names)))[0])
    exact = float(conductance.fin(h, perimeter, k, area, length))
    assert -base_flow / 50.0 == pytest.approx(exact, rel=2.0 / segments**2)


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(st.integers(2, 8), st.integers(1, 3), st.randoms(use_true_random=False))
def test_the_energy_balance_holds_over_random_networks(free, held, rng):
    """40 random connected networks (a spanning chain plus random extra edges, conductances 0.01–100 W/K,
    sources −50–200 W, held temperatures 0–150 °C): the heat leaving at the held nodes sums to the heat
    generated, and every free node balances, to round-off (1e-12 of the largest G T and Q)."""
    count = free + held
    edges = [(i, i + 1) for i in range(count - 1)] + [tuple(rng.sample(range(count), 2)) for _ in range(count)]
    values = jnp.array([10 ** rng.uniform(-2, 2) for _ in edges])
    held_nodes = tuple(range(free, count))
    network = ThermalNetwork(tuple(f"n{i}" for i in range(count)), tuple(edges), held_nodes, values,
                             jnp.array([273.15 + rng.uniform(0, 150) for _ in held_nodes]))
    sources = jnp.array([rng.uniform(-50, 200) for _ in range(count)])
    temperatures = node_temperatures(network, sources)
    flows = edge_heat_flows(network, temperatures)
    scale = float(jnp.max(values)) * float(jnp.max(temperatures)) + float(jnp.max(jnp.abs(sources)))
    assert float(jnp.sum(boundary_heat_flows(network, temperatures, sources)) - jnp.sum(sources)) == \
        pytest.approx(0.0, abs=1e-12 * scale)
    for node in range(free):
        inflow = sum(float(flow) * (1 if j == node else -1 if i == node else 0) for (i, j), flow in zip(edges, flows))
        assert inflow + float(sources[node]) == pytest.approx(0.0, abs=1e-12 * scale)


def test_temperatures_derivatives_are_central_differences():
    """∂T/∂(G, T_held, Q) of a three-node network against central differences (1e-7)."""
    def temperatures(x):
        network = ThermalNetwork(("ring", "housing", "ambient"), ((0, 1), (1, 2), (0, 2)), (2,), x[:3], x[3:4])
        return node_temperatures(network, jnp.array([x[4], 0.0, 0.0]))

    point = jnp.array([4.0, 2.0, 0.5, AMBIENT, 80.0])
    for index, step in enumerate((1e-4, 1e-4, 1e-5, 1e-3, 1e-3)):
        assert_jvp_matches_central_difference(temperatures, point, jnp.zeros(5).at[index].set(1.0), step, rtol=1e-7)


def test_a_node_without_a_path_to_a_held_temperature_is_refused():
    with pytest.raises(ValueError, match=r"nodes \['island'\] have no path"):
        ThermalNetwork(("ring", "ambient", "island"), ((0, 1),), (1,), jnp.array([1.0]), jnp.array([AMBIENT]))
    with pytest.raises(ValueError, match="at least one node held"):
        ThermalNetwork(("a", "b"), ((0, 1),), (), jnp.array([1.0]), jnp.array([]))
