"""What is wrong with a graph, as roswtf's graph rules find it, over a `GraphState`.

Pure functions of a state fetched with every node's bus info (`rosx.graph.fetch.fetch_state`):

- `expected_edges`: the connections the registrations call for (each subscriber of a topic to
  each of its publishers), and the subscriptions no publisher serves;
- `actual_edges`: the connections the nodes report (``getBusInfo``), peers named by node where
  their URI is known;
- `isolated_nodes`: nodes that answered with no connection at all and provide no service;
- `silent_nodes`: nodes that did not answer, or whose URI the master did not give.

An edge is ``(topic, publisher, subscriber)``. The words roswtf prints stay with roswtf.
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.graph.state import GraphState

Edge = tuple[str, str, str]  # topic, publisher, subscriber


def actual_edges(state: GraphState) -> set[Edge]:
    """The connections the nodes report; a peer URI of no known node is ``unknown (URI)``."""
    by_uri = {uri: node for node, uri in state.node_uris.items()}
    edges: set[Edge] = set()
    for node, links in (state.bus_info or {}).items():
        for link in links or ():
            peer = link.peer
            if peer.startswith("http://"):
                peer = by_uri.get(peer, f"unknown ({peer})")
            if link.direction == "i":
                edges.add((link.topic, peer, node))
            elif link.direction == "o":
                edges.add((link.topic, node, peer))
    return edges


def expected_edges(state: GraphState) -> tuple[set[Edge], dict[str, list[str]]]:
    """The connections the registrations call for, and each subscriber's topics that nobody
    publishes (in the master's order)."""
    edges: set[Edge] = set()
    unconnected: dict[str, list[str]] = {}
    for topic, subscribers in state.subscribers.items():
        for subscriber in subscribers:
            if topic in state.publishers:
                edges.update((topic, pub, subscriber) for pub in state.publishers[topic])
            else:
                unconnected.setdefault(subscriber, []).append(topic)
    return edges, unconnected


def isolated_nodes(state: GraphState) -> list[str]:
    """Nodes that reported no connection at all and provide no service, sorted."""
    providers = {node for nodes in state.services.values() for node in nodes}
    bus_info = state.bus_info or {}
    return [
        node
        for node in state.nodes
        if bus_info.get(node) is not None and not bus_info[node] and node not in providers
    ]


def silent_nodes(state: GraphState) -> list[str]:
    """Nodes that did not answer ``getBusInfo``, or that the master could not locate, sorted."""
    return [n for n in state.nodes if state.unreachable(n) or n not in state.node_uris]


__all__ = ["Edge", "actual_edges", "expected_edges", "isolated_nodes", "silent_nodes"]
