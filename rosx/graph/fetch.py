"""`fetch_state`: ask the master, then every node, for a `GraphState`.

``getSystemState`` and ``getTopicTypes`` from the master, ``lookupNode`` and ``getBusInfo`` for
each node (ROS wiki Master_API and Slave_API), nodes asked in parallel with a short timeout so
one hung node cannot stall a refresh. A node that does not answer is recorded as unreachable;
a master that does not answer raises `rosx.master.client.MasterUnreachable`.
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

from rosx.graph.state import BusLink, GraphState
from rosx.master.client import MasterClient, MasterError
from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError

#: Seconds a node has to answer ``getBusInfo``.
NODE_TIMEOUT = 1.0
WORKERS = 16


def fetch_state(master_uri: str, caller_id: str, *, bus_info: bool = True) -> GraphState:
    """The graph as the master and (when ``bus_info``) the nodes report it.

    Raises:
        MasterUnreachable: the master does not answer.
        MasterError: the master refused a call.
    """
    master = MasterClient(master_uri, caller_id, XmlRpcClient(timeout=2.0))
    try:
        system = master.call("getSystemState")
        types = master.topic_types()
        state = GraphState.from_system_state(system, types)
        if not bus_info:
            return state
        nodes = state.nodes
        with ThreadPoolExecutor(max_workers=min(WORKERS, max(1, len(nodes)))) as pool:
            answers = list(pool.map(lambda n: _ask_node(master, n), nodes))
    finally:
        master.close()
    uris = {node: uri for node, (uri, _) in zip(nodes, answers, strict=True) if uri}
    links = {node: found for node, (_, found) in zip(nodes, answers, strict=True)}
    return GraphState(state.publishers, state.subscribers, state.services, types, uris, links)


def _ask_node(master: MasterClient, node: str) -> tuple[str | None, tuple[BusLink, ...] | None]:
    try:
        uri = str(master.call("lookupNode", node, timeout=NODE_TIMEOUT))
    except (TransportError, MasterError):
        return None, None
    try:
        info = master.node_call(uri, "getBusInfo", timeout=NODE_TIMEOUT)
    except (TransportError, FaultError, MasterError):
        return uri, None
    found = []
    for row in info:
        if len(row) > 5 and not row[5]:
            continue  # a connection that is no longer connected
        found.append(BusLink(str(row[4]), str(row[1]), str(row[2])))
    return uri, tuple(found)
