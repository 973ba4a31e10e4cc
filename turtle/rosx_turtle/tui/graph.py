"""`Graph`: the ROS graph as the side panels show it, and `GraphWatcher`, which keeps it fresh.

The watcher asks the master what ``rostopic list`` and ``rosnode list`` ask it
(``getSystemState`` and ``getTopicTypes``, ROS wiki Master_API) on a thread of its own, and
offers the answer to a `Feed` only when it differs from the last one, so the panels redraw only
when a node, topic or connection comes or goes. A master that does not answer gives a `Graph`
with ``error`` set, which the panels show instead of stale lists.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError

if TYPE_CHECKING:
    from rosx_turtle.tui.feed import Feed

CALLER_ID = "/rosx_sim_graph"
#: Seconds between two looks at the master.
POLL_PERIOD = 0.5


@dataclass(frozen=True)
class Topic:
    """A topic with its type and the nodes that publish and subscribe to it."""

    name: str
    type: str
    publishers: tuple[str, ...]
    subscribers: tuple[str, ...]


@dataclass(frozen=True)
class Graph:
    """Topics (sorted by name) and nodes (sorted), or why the master could not be asked."""

    topics: tuple[Topic, ...] = ()
    nodes: tuple[str, ...] = ()
    error: str = ""


def fetch_graph(client: XmlRpcClient, master_uri: str) -> Graph:
    """The graph as the master at ``master_uri`` describes it now."""
    try:
        state = _value(client.call(master_uri, "getSystemState", CALLER_ID))
        types = dict(_value(client.call(master_uri, "getTopicTypes", CALLER_ID)))
    except (TransportError, FaultError, OSError, ValueError) as exc:
        return Graph(error=f"cannot reach the master at {master_uri}: {exc}")
    publishers = {topic: tuple(sorted(nodes)) for topic, nodes in state[0]}
    subscribers = {topic: tuple(sorted(nodes)) for topic, nodes in state[1]}
    names = sorted(publishers.keys() | subscribers.keys())
    topics = tuple(
        Topic(name, types.get(name, "?"), publishers.get(name, ()), subscribers.get(name, ()))
        for name in names
    )
    nodes = {node for entries in state for _, members in entries for node in members}
    return Graph(topics, tuple(sorted(nodes)))


def _value(reply: Any) -> Any:
    if not isinstance(reply, list) or len(reply) != 3 or reply[0] != 1:
        raise ValueError(f"unexpected reply {reply!r}")
    return reply[2]


class GraphWatcher:
    """Asks the master every `POLL_PERIOD` s on a daemon thread; offers changes to ``feed``."""

    def __init__(self, master_uri: str, feed: Feed[Graph], period: float = POLL_PERIOD) -> None:
        self.master_uri = master_uri
        self.feed = feed
        self.period = period
        self._client = XmlRpcClient(timeout=2.0)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="rosx-sim-graph", daemon=True)

    def start(self) -> GraphWatcher:
        """Start polling; returns self."""
        self._thread.start()
        return self

    def stop(self) -> None:
        """Stop polling and wait for the thread."""
        self._stop.set()
        if self._thread.is_alive():
            self._thread.join(timeout=5.0)
        self._client.close()

    def _run(self) -> None:
        last: Graph | None = None
        while not self._stop.is_set():
            graph = fetch_graph(self._client, self.master_uri)
            if graph != last:
                self.feed.offer(graph)
                last = graph
            self._stop.wait(self.period)
