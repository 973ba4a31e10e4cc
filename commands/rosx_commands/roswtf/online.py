"""roswtf's graph checks, run when a master answers: unconnected subscriptions, unexpected and
missing connections, nodes that cannot be contacted or are connected to nothing, services that
do not answer a probe, ``/use_sim_time`` without ``/clock``; in roswtf's words and order.

The graph comes from `rosx.graph.fetch.fetch_state` (the master's registrations and every node's
``getBusInfo``), the service probes from `rosx.node.service_client.probe_service`.
"""

from __future__ import annotations

import socket
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

from rosx.graph.fetch import fetch_state
from rosx.master.client import MasterClient, MasterError
from rosx.node.errors import ServiceError
from rosx.node.service_client import probe_service
from rosx.transport.errors import TransportError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.graph.state import GraphState
    from rosx_commands.roswtf.report import Findings

Edge = tuple[str, str, str]  # topic, publisher, subscriber


def _actual_edges(state: GraphState) -> set[Edge]:
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


def _expected(state: GraphState) -> tuple[set[Edge], dict[str, list[str]]]:
    edges: set[Edge] = set()
    unconnected: dict[str, list[str]] = {}
    for topic, subscribers in state.subscribers.items():
        for subscriber in subscribers:
            if topic in state.publishers:
                edges.update((topic, pub, subscriber) for pub in state.publishers[topic])
            else:
                unconnected.setdefault(subscriber, []).append(topic)
    return edges, unconnected


def _unconnected_text(unconnected: dict[str, list[str]], sim_time: bool) -> str:
    ignored = ("/reset_time",) if sim_time else ("/time", "/clock")
    text = ""
    for subscriber, topics in unconnected.items():
        kept = [t for t in topics if t not in ignored]
        if kept:
            text += f" * {subscriber}:\n" + "".join(f"   * {t}\n" for t in kept)
    return text


def _probe(master: MasterClient, services: list[str]) -> list[str]:
    problems = []
    for name in services:
        try:
            header = probe_service(master, name)
        except ServiceError as error:
            problems.append(f"service [{name}] appears to be malfunctioning: {error}")
            continue
        if not header:
            problems.append(f"service [{name}] did not return service headers")
    return problems


def _ping_failure(node: str, uri: str | None) -> str:
    """What rosnode's ping prints (to stderr) about a node that did not answer."""
    if uri is None:
        return f"cannot ping [{node}]: unknown node"
    parts = urlsplit(uri)
    try:
        with socket.create_connection((parts.hostname or "", parts.port or 80), timeout=3.0):
            pass
    except socket.gaierror:
        return f"ERROR: Unknown host [{parts.hostname}] for node [{node}]"
    except ConnectionRefusedError:
        return f"ERROR: connection refused to [{uri}]"
    except TimeoutError:
        return f"connection to [{node}] timed out"
    except OSError:
        return f"connection to [{node}] failed"
    return f"connection to [{node}] failed"


def check_graph(
    master_uri: str,
    findings: Findings,
    say: Callable[[str], None],
    complain: Callable[[str], None],
) -> None:
    """Analyse the graph at ``master_uri`` and record roswtf's graph findings; ``say`` prints
    roswtf's progress lines, ``complain`` what its node pings print to stderr.

    Raises:
        MasterUnreachable: the master stopped answering.
    """
    master = MasterClient(master_uri, "/roswtf", timeout=3.0)
    say("analyzing graph...")
    try:
        sim_time = bool(master.getParam("/use_sim_time"))
    except (MasterError, TransportError):
        sim_time = False
    state = fetch_state(master_uri, "/roswtf")
    say("... done analyzing graph")
    nodes = state.nodes
    providers = {node for nodes_ in state.services.values() for node in nodes_}
    for node in nodes:
        links = (state.bus_info or {}).get(node)
        if links is not None and not links and node not in providers:
            findings.check("warning", f"Node [{node}] is not connected to anything", True)
    expected, unconnected = _expected(state)
    actual = _actual_edges(state)

    def edges(which: set[Edge]) -> list[str]:
        return [f"{p}->{s} ({t})" for t, p, s in sorted(which)] if nodes else []

    def unpinged() -> list[str]:
        failed = [n for n in nodes if state.unreachable(n) or n not in state.node_uris]
        for node in failed:
            complain(_ping_failure(node, state.node_uris.get(node)))
        return failed

    def clock_missing() -> bool:
        return sim_time and not ({"/clock", "/time"} & set(state.publishers))

    say("running graph rules...")
    findings.run(
        [
            (
                "warning",
                lambda: _unconnected_text(unconnected, sim_time),
                "The following node subscriptions are unconnected:\n",
            ),
            (
                "warning",
                lambda: edges(actual - expected),
                "The following nodes are unexpectedly connected:",
            ),
            (
                "error",
                clock_missing,
                "/use_sim_time is set but no publisher of /clock is present",
            ),
            (
                "error",
                unpinged,
                "Could not contact the following nodes:",
            ),
            (
                "error",
                lambda: edges(expected - actual),
                "The following nodes should be connected but aren't:",
            ),
            (
                "error",
                lambda: _probe(master, list(state.services)),
                "Errors connecting to the following services:",
            ),
        ]
    )
    say("... done running graph rules")
    master.close()


__all__ = ["check_graph"]
