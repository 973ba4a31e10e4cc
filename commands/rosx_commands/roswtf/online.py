"""roswtf's graph checks, run when a master answers: unconnected subscriptions, unexpected and
missing connections, nodes that cannot be contacted or are connected to nothing, services that
do not answer a probe, ``/use_sim_time`` without ``/clock``; in roswtf's words and order.

The graph comes from `rosx.graph.fetch.fetch_state` (the master's registrations and every node's
``getBusInfo``) and is analysed by `rosx.graph.checks`; why a node does not answer is
`rosx.graph.nodes.contact_failure`, the service probes `rosx.node.service_client.probe_service`.
This module runs the rules and words what they find.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.graph.checks import actual_edges, expected_edges, isolated_nodes, silent_nodes
from rosx.graph.fetch import fetch_state
from rosx.graph.nodes import contact_failure
from rosx.master.client import MasterClient, MasterError
from rosx.node.errors import ServiceError
from rosx.node.service_client import probe_service
from rosx.transport.errors import TransportError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.graph.checks import Edge
    from rosx_commands.roswtf.report import Findings


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
    for node in isolated_nodes(state):
        findings.check("warning", f"Node [{node}] is not connected to anything", True)
    expected, unconnected = expected_edges(state)
    actual = actual_edges(state)

    def edges(which: set[Edge]) -> list[str]:
        return [f"{p}->{s} ({t})" for t, p, s in sorted(which)] if nodes else []

    def unpinged() -> list[str]:
        failed = silent_nodes(state)
        for node in failed:
            complain(contact_failure(node, state.node_uris.get(node)))
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
    from rosx_commands.roswtf.tf_checks import check_tf  # noqa: PLC0415 - tf's plugin

    check_tf(master_uri, sorted(state.publishers), findings, say)


__all__ = ["check_graph"]
