"""A steady thermal network: nodes joined by thermal conductances, some held at a given temperature.

Node i's heat balance (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., vol. 1, ch. 13, the
lumped network of a bearing and its surroundings):

    Σ_j G_ij (T_j − T_i) + Q_i = 0    for each free node,   T_b given for each boundary node,

with G_ij [W/K] the conductances of the edges (`conductance`: conduction, convection, a fluid's
flow) and Q_i [W] the heat generated at the node. With the network's Laplacian L (L_ii = Σ_j G_ij,
L_ij = −G_ij) it is the linear system L_ff T_f = Q_f − L_fb T_b over the free nodes f, solved by
LU (lineax); the heat that leaves through the boundary nodes, (L T)_b, sums to Σ Q (the energy
balance, to round-off). Every free node needs a path to a boundary node, else L_ff is singular: a
network without one is refused when it is built.
"""

import equinox as eqx
import jax
import jax.numpy as jnp
import lineax as lx
import numpy as np


class ThermalNetwork(eqx.Module):
    """Nodes `names`, edges `edges` ((i, j) index pairs) of conductances `conductances` [W/K], the
    nodes `boundary` held at `boundary_temperatures` [K]."""

    names: tuple[str, ...] = eqx.field(static=True)
    edges: tuple[tuple[int, int], ...] = eqx.field(static=True)
    boundary: tuple[int, ...] = eqx.field(static=True)
    conductances: jax.Array
    boundary_temperatures: jax.Array

    def __check_init__(self):
        count = len(self.names)
        if any(not (0 <= i < count and 0 <= j < count) or i == j for i, j in self.edges):
            raise ValueError("edges: each joins two different nodes of the network")
        if len(self.edges) != np.shape(self.conductances)[0]:
            raise ValueError("conductances: one per edge")
        if not self.boundary or len(self.boundary) != np.shape(self.boundary_temperatures)[0]:
            raise ValueError("boundary: at least one node held at a temperature, one temperature each")
        reached, frontier = set(self.boundary), list(self.boundary)
        while frontier:
            node = frontier.pop()
            for i, j in self.edges:
                for near, far in ((i, j), (j, i)):
                    if near == node and far not in reached:
                        reached.add(far)
                        frontier.append(far)
        cut = [self.names[node] for node in range(count) if node not in reached]
        if cut:
            raise ValueError(f"nodes {cut} have no path to a node held at a temperature (no steady state)")

    @property
    def free(self) -> tuple[int, ...]:
        return tuple(node for node in range(len(self.names)) if node not in self.boundary)

    def index(self, name: str) -> int:
        return self.names.index(name)


def laplacian(network: ThermalNetwork):
    """L [W/K] (N × N): L_ii = Σ_j G_ij, L_ij = −G_ij."""
    count = len(network.names)
    first = jnp.array([i for i, _ in network.edges])
    second = jnp.array([j for _, j in network.edges])
    conductances = network.conductances
    matrix = jnp.zeros((count, count))
    matrix = matrix.at[first, first].add(conductances).at[second, second].add(conductances)
    return matrix.at[first, second].add(-conductances).at[second, first].add(-conductances)


def node_temperatures(network: ThermalNetwork, sources):
    """Every node's steady temperature [K] (N,) for the heat `sources` [W] generated at the nodes (N,;
    a boundary node's source leaves with it)."""
    free, boundary = jnp.array(network.free), jnp.array(network.boundary)
    matrix = laplacian(network)
    right = jnp.asarray(sources)[free] - matrix[jnp.ix_(free, boundary)] @ network.boundary_temperatures
    operator = lx.MatrixLinearOperator(matrix[jnp.ix_(free, free)], lx.positive_semidefinite_tag)
    solved = lx.linear_solve(operator, right, lx.LU()).value
    return jnp.zeros(len(network.names)).at[free].set(solved).at[boundary].set(network.boundary_temperatures)


def edge_heat_flows(network: ThermalNetwork, temperatures):
    """The heat flow along each edge (i, j) [W], G (T_i − T_j): positive from i to j."""
    first = jnp.array([i for i, _ in network.edges])
    second = jnp.array([j for _, j in network.edges])
    return network.conductances * (temperatures[first] - temperatures[second])


def boundary_heat_flows(network: ThermalNetwork, temperatures, sources):
    """The heat leaving the network at each boundary node [W]: what its edges bring, −(L T)_b, and its
    own source. They sum to Σ sources (Σ over all nodes of L T vanishes)."""
    boundary = jnp.array(network.boundary)
    return -(laplacian(network) @ temperatures)[boundary] + jnp.asarray(sources)[boundary]
