"""`Graph`: the ROS graph as the side panels show it, and `GraphWatcher`, which keeps it fresh.

The watcher reads the graph state rqt_graph reads (`rosx.graph.fetch.fetch_state`: the master's
``getSystemState`` and ``getTopicTypes``, ROS wiki Master_API, without asking every node) on a
thread of its own, and offers the panels its summaries (`rosx.graph.describe`) only when they
differ from the last ones, so the panels redraw only when a node, topic or connection comes or
goes. A master that does not answer gives a `Graph` with ``error`` set, which the panels show
instead of stale lists.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rosx.graph.describe import NodeSummary, TopicSummary, node_summaries, topic_summaries
from rosx.graph.fetch import fetch_state
from rosx.master.client import MasterError
from rosx.transport.errors import TransportError

if TYPE_CHECKING:
    from rosx.graph.state import GraphState
    from rosx_turtle.tui.feed import Feed

CALLER_ID = "/rosx_sim_graph"
#: Seconds between two looks at the master.
POLL_PERIOD = 0.5


@dataclass(frozen=True)
class Graph:
    """Topics (sorted by name) and nodes (sorted), or why the master could not be asked."""

    topics: tuple[TopicSummary, ...] = ()
    nodes: tuple[NodeSummary, ...] = ()
    error: str = ""

    @classmethod
    def of(cls, state: GraphState) -> Graph:
        """The panels' view of ``state``."""
        return cls(topic_summaries(state), node_summaries(state))


def fetch_graph(master_uri: str) -> Graph:
    """The graph as the master at ``master_uri`` describes it now."""
    try:
        return Graph.of(fetch_state(master_uri, CALLER_ID, bus_info=False))
    except (TransportError, MasterError) as exc:
        return Graph(error=f"cannot reach the master at {master_uri}: {exc}")


class GraphWatcher:
    """Asks the master every `POLL_PERIOD` s on a daemon thread; offers changes to ``feed``."""

    def __init__(self, master_uri: str, feed: Feed[Graph], period: float = POLL_PERIOD) -> None:
        self.master_uri = master_uri
        self.feed = feed
        self.period = period
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

    def _run(self) -> None:
        last: Graph | None = None
        while not self._stop.is_set():
            graph = fetch_graph(self.master_uri)
            if graph != last:
                self.feed.offer(graph)
                last = graph
            self._stop.wait(self.period)
