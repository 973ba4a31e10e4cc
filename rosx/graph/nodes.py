"""The nodes of a graph: which exist, which answer, and taking them out of the master.

What ``rosnode list/ping/kill/machine/cleanup`` and roswtf ask of the nodes, as functions of a
`rosx.master.client.MasterClient`:

- `node_names`: every node a registration names, in a namespace or all;
- `unreachable_nodes`: the nodes whose Slave API does not answer ``getPid`` (asked side by side,
  so hung nodes cost one timeout in all), or that the master cannot locate;
  `unreachable_reasons` with why each did not, in rosnode's words;
- `contact_failure`: why one node did not answer, in rosnode's words (unknown host, connection
  refused, timed out);
- `kill_node`: a ``shutdown`` call to a node (ROS wiki Slave_API);
- `purge_node`: every registration of a node unregistered from the master, as the node itself
  (``rosnode cleanup``).
"""

from __future__ import annotations

import contextlib
import errno
import socket
from urllib.parse import urlsplit

from rosx.graph.state import registrations
from rosx.master.client import MasterError
from rosx.names.resolution import make_global_ns
from rosx.transport.errors import CallTimeoutError, ConnectError, FaultError, TransportError

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.graph.state import GraphState
    from rosx.master.client import MasterClient

#: Seconds a node has to answer ``getPid`` (rosnode's ping timeout).
PING_TIMEOUT = 3.0
#: Nodes asked at once by `unreachable_nodes`.
WORKERS = 16


def node_names(master: MasterClient, namespace: str | None = None) -> list[str]:
    """Every node the master knows through a registration, in ``namespace`` (all when None),
    sorted."""
    nodes = registrations(master).nodes
    if not namespace:
        return nodes
    prefix = make_global_ns(namespace)
    return [n for n in nodes if n.startswith(prefix) or n == namespace]


def unreachable_nodes(
    master: MasterClient, nodes: list[str], timeout: float = PING_TIMEOUT
) -> list[str]:
    """The nodes of ``nodes`` whose Slave API does not answer ``getPid`` (or that the master
    cannot locate), in order; asked side by side, so hung nodes cost one timeout in all."""
    return list(unreachable_reasons(master, nodes, timeout))


def unreachable_reasons(
    master: MasterClient, nodes: list[str], timeout: float = PING_TIMEOUT
) -> dict[str, str]:
    """`unreachable_nodes`, each with why it did not answer, in the words rosnode's ping prints
    (what ``rosnode cleanup`` writes to stderr for each)."""
    from concurrent.futures import ThreadPoolExecutor  # noqa: PLC0415 - only these need threads

    def why(node: str) -> str | None:
        uri = master.lookup_node(node)
        if uri is None:
            return _failure_words(node, None, None)
        try:
            master.node_call(uri, "getPid", timeout=timeout)
        except (TransportError, FaultError) as error:
            return _failure_words(node, uri, error)
        except MasterError:
            return None  # it answered
        return None

    if not nodes:
        return {}
    with ThreadPoolExecutor(min(len(nodes), WORKERS)) as pool:
        reasons = list(pool.map(why, nodes))
    return {node: reason for node, reason in zip(nodes, reasons, strict=True) if reason}


def contact_failure(node: str, uri: str | None, timeout: float = PING_TIMEOUT) -> str:
    """Why ``node`` (at ``uri``, None when the master does not know it) did not answer, in the
    words rosnode's ping prints."""
    if uri is None:
        return _failure_words(node, None, None)
    parts = urlsplit(uri)
    try:
        with socket.create_connection((parts.hostname or "", parts.port or 80), timeout=timeout):
            pass
    except OSError as error:
        return _failure_words(node, uri, error)
    return _failure_words(node, uri, None)


def _failure_words(node: str, uri: str | None, error: BaseException | None) -> str:
    """rosnode ping's words for ``node`` not answering: unknown to the master (``uri`` None),
    its host unknown, the connection refused or timed out (``error``: a socket's or a call's),
    else failed."""
    if uri is None:
        return f"cannot ping [{node}]: unknown node"
    number = error.errno if isinstance(error, (OSError, ConnectError)) else None
    if isinstance(error, socket.gaierror) or number in (socket.EAI_NONAME, socket.EAI_AGAIN):
        return f"ERROR: Unknown host [{urlsplit(uri).hostname}] for node [{node}]"
    if isinstance(error, ConnectionRefusedError) or number == errno.ECONNREFUSED:
        return f"ERROR: connection refused to [{uri}]"
    if isinstance(error, (TimeoutError, CallTimeoutError)):
        return f"connection to [{node}] timed out"
    return f"connection to [{node}] failed"


def kill_node(master: MasterClient, node: str, reason: str = "user request") -> bool:
    """Ask ``node`` to shut down; False when the master does not know it. A node that does
    not answer the call counts as killed, as rosnode counts it."""
    uri = master.lookup_node(node)
    if uri is None:
        return False
    with contextlib.suppress(TransportError, FaultError):
        master.node_call(uri, "shutdown", reason)
    return True


def purge_node(master: MasterClient, node: str, state: GraphState) -> None:
    """Unregister every publication, subscription and service ``state`` gives ``node``, as
    the node itself (what ``rosnode cleanup`` does for a node that no longer answers).

    Raises:
        MasterUnreachable, MasterError: the master did not take a call.
    """
    uri = master.lookup_node(node)
    as_node = master.as_caller(node)
    for topic, nodes in state.publishers.items():
        if node in nodes:
            as_node.call("unregisterPublisher", topic, uri)
    for topic, nodes in state.subscribers.items():
        if node in nodes:
            as_node.call("unregisterSubscriber", topic, uri)
    for service, nodes in state.services.items():
        if node in nodes:
            as_node.call("unregisterService", service, master.call("lookupService", service))


__all__ = [
    "PING_TIMEOUT",
    "contact_failure",
    "kill_node",
    "node_names",
    "purge_node",
    "unreachable_nodes",
    "unreachable_reasons",
]
