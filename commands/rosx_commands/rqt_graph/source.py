"""Where the live view gets its graph and its details: `LiveSource` asks the master and the
nodes; tests pass a source of their own with the same methods (`GraphSource`).

Every method may block (network calls) and is called from worker threads only.
"""

from __future__ import annotations

import threading
import time
from typing import Any, Protocol

from rosx.graph.state import GraphState
from rosx.graph.view import Kind, Vertex
from rosx_commands.context import MASTER_TIMEOUT, Environment, ExitStatus
from rosx_commands.errors import command_error

CALLER_ID = "/rqt_graph"
#: Seconds between two refreshes of the live view.
REFRESH_PERIOD = 1.5


class GraphSource(Protocol):
    """Where the live view gets its graph and details (`LiveSource`, or a test's)."""

    def snapshot(self) -> GraphState:
        """The master's registrations now (and the nodes' bus info when asked for); blocks on the
        network."""

    def describe(self, vertex: Vertex) -> str:
        """What the details panel shows for ``vertex`` (``rosnode info``/``rostopic info`` text)."""

    def rate(self, topic: str) -> str:
        """A line with ``topic``'s average message rate."""

    def close(self) -> None:
        """Release the source's node and connections."""


class RateCounter:
    """Messages received on one topic, and the rate over the last window."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._stamps: list[float] = []

    def __call__(self, _message: object) -> None:
        """Count one message's arrival; only the last 5 seconds' are kept."""
        now = time.monotonic()
        with self._lock:
            self._stamps.append(now)
            self._stamps = [t for t in self._stamps if now - t <= 5.0]

    def text(self) -> str:
        """The average rate over the last 5 seconds, as rqt_graph's topic tooltip, or "no
        messages yet"."""
        with self._lock:
            stamps = list(self._stamps)
        if len(stamps) < 2:
            return "rate: no messages yet"
        return f"average rate: {(len(stamps) - 1) / (stamps[-1] - stamps[0]):.3f} Hz"


class LiveSource:
    """A running master and its nodes; one hidden node of its own for topic rates."""

    def __init__(self, env: Environment, uri: str, caller_id: str, bus_info: bool) -> None:
        self.env = env
        self.uri = uri
        self.caller_id = caller_id
        self.bus_info = bus_info
        self._node: Any = None
        self._counters: dict[str, RateCounter] = {}

    def snapshot(self) -> GraphState:
        """The master's graph now, fetched as `rosx.graph.fetch.fetch_state` does (blocks)."""
        from rosx.graph.fetch import fetch_state  # noqa: PLC0415 - graph code loads only when asked for

        return fetch_state(self.uri, self.caller_id, bus_info=self.bus_info)

    def describe(self, vertex: Vertex) -> str:
        """What ``rosnode info`` or ``rostopic info`` prints of ``vertex``, errors included."""
        if vertex.kind is Kind.GROUP:
            return f"Group of topics: {vertex.label}"
        from rosx.graph import describe  # noqa: PLC0415 - graph code loads only when asked for
        from rosx.master.client import MasterClient  # noqa: PLC0415 - the master's code loads only to talk to one

        master = MasterClient(self.uri, self.caller_id, timeout=MASTER_TIMEOUT)
        text = ""
        try:
            if vertex.kind is Kind.TOPIC:
                return describe.topic_description(master, vertex.label)
            text = describe.node_description(master, vertex.label)
            uri = master.lookup_node(vertex.label)
            if uri is None:
                return text + f"\ncannot contact [{vertex.label}]: unknown node"
            text += f"\ncontacting node {uri} ...\n"
            return text + describe.node_connections(master, uri)
        except Exception as error:
            mapped = command_error(error, self.env, ExitStatus.ERROR)
            if mapped is None:
                raise
            return text + mapped.message
        finally:
            master.close()

    def rate(self, topic: str) -> str:
        """``topic``'s average rate; the first call subscribes (starting a hidden node if
        needed), so the rate builds up on later calls."""
        if topic not in self._counters:
            if self._node is None:
                from rosx.names.anonymous import anonymous_node_name  # noqa: PLC0415 - name rules load only when used
                from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node

                name = anonymous_node_name("rqt_graph")
                self._node = Node(
                    name, master_uri=self.uri, environ=self.env.environ, rosout_enabled=False
                ).start()
            counter = self._counters[topic] = RateCounter()
            self._node.subscribe(topic, None, counter)
        return self._counters[topic].text()

    def close(self) -> None:
        """Shut the hidden rate node down, if one was started."""
        if self._node is not None:
            self._node.shutdown("rqt_graph closed")
            self._node = None
