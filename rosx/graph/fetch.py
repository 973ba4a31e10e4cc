"""`fetch_state`: ask the master, then every node, for a `GraphState`.

``getSystemState`` and ``getTopicTypes`` from the master, ``lookupNode`` and ``getBusInfo`` for
each node (ROS wiki Master_API and Slave_API), nodes asked in parallel with a short timeout so
one hung node cannot stall a refresh. A node that does not answer is recorded as unreachable.
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from typing import Any

from rosx.graph.state import BusLink, GraphState
from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError

#: Seconds a node has to answer ``getBusInfo``.
NODE_TIMEOUT = 1.0
WORKERS = 16


class MasterUnreachable(Exception):  # noqa: N818 - the name says what happened
    """The master did not answer or refused the call."""


def _value(reply: Any) -> Any:
    if not isinstance(reply, list) or len(reply) != 3 or reply[0] != 1:
        raise FaultError(0, f"call failed: {reply!r}")
    return reply[2]


def fetch_state(master_uri: str, caller_id: str, *, bus_info: bool = True) -> GraphState:
    """The graph as the master and (when ``bus_info``) the nodes report it."""
    client = XmlRpcClient(timeout=2.0)
    try:
        try:
            system = _value(client.call(master_uri, "getSystemState", caller_id))
            types = dict(_value(client.call(master_uri, "getTopicTypes", caller_id)))
        except (TransportError, FaultError, OSError) as error:
            raise MasterUnreachable(str(error)) from None
        state = GraphState.from_system_state(system, types)
        if not bus_info:
            return state
        nodes = state.nodes
        with ThreadPoolExecutor(max_workers=min(WORKERS, max(1, len(nodes)))) as pool:
            answers = list(pool.map(lambda n: _ask_node(master_uri, caller_id, n), nodes))
    finally:
        client.close()
    uris = {node: uri for node, (uri, _) in zip(nodes, answers, strict=True) if uri}
    links = {node: found for node, (_, found) in zip(nodes, answers, strict=True)}
    return GraphState(state.publishers, state.subscribers, state.services, types, uris, links)


def _ask_node(
    master_uri: str, caller_id: str, node: str
) -> tuple[str | None, tuple[BusLink, ...] | None]:
    with XmlRpcClient(timeout=NODE_TIMEOUT) as client:
        try:
            uri = str(_value(client.call(master_uri, "lookupNode", caller_id, node)))
        except (TransportError, FaultError, OSError):
            return None, None
        try:
            info = _value(client.call(uri, "getBusInfo", caller_id))
        except (TransportError, FaultError, OSError):
            return uri, None
    found = []
    for row in info:
        if len(row) > 5 and not row[5]:
            continue  # a connection that is no longer connected
        found.append(BusLink(str(row[4]), str(row[1]), str(row[2])))
    return uri, tuple(found)
