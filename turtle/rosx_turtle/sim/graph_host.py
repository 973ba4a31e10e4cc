"""`GraphHost`: what ``rosx sim``'s hosts (turtlesim's, the robot lab's) share.

The core to start (`rosx.core.Core`), or the master to join; the stops to run, in reverse
order; the graph's feed and the log lines' feed for a screen; and the details a screen asks
for (``rostopic info``, ``rosnode info``, echo) through one `Inspector` made when first asked;
and `await_subscriber`, with which a host's ``start`` returns only once its teleop is heard.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from rosx.core import Core
from rosx.master.client import MasterClient

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.node import Publisher
    from rosx_turtle.console import Console
    from rosx_turtle.sim.inspect import Inspector
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph
    from rosx_turtle.tui.log import LogRecord

#: Seconds the master to join has to answer.
JOIN_TIMEOUT = 3.0

#: Seconds a host's ``start`` waits, at most, for its simulator to subscribe to the teleop.
LINK_TIMEOUT = 10.0


def await_subscriber(publisher: Publisher, callerid: str) -> None:
    """Return once ``callerid`` subscribes to ``publisher``, or after `LINK_TIMEOUT`.

    A subscriber connects when the master tells it of the publisher, a few milliseconds after
    ``advertise`` returns; a Twist published before then would reach no one, so the first key
    pressed on a screen that came up quickly would be lost.
    """
    deadline = time.monotonic() + LINK_TIMEOUT
    while callerid not in publisher.subscriber_ids():
        if time.monotonic() > deadline:
            return
        time.sleep(0.002)


class GraphHost:
    """A core on ``port`` (or the master at ``join``), and what every host does around it."""

    def __init__(
        self,
        port: int,
        environ: Mapping[str, str],
        *,
        console: Console | None = None,
        watch: bool = True,
        join: str | None = None,
    ) -> None:
        self.core = Core(port, environ) if join is None else None
        self.joined = join
        self.environ = environ
        self.console = console
        self.watch = watch
        self._graph: Feed[Graph] | None = None
        self._logs: Feed[LogRecord] | None = None
        self._stops: list[Callable[[], object]] = []
        self._inspecting: Inspector | None = None

    @property
    def master_uri(self) -> str:
        """The master's URI (what other terminals set ``ROS_MASTER_URI`` to)."""
        if self.core is None:
            assert self.joined is not None
            return self.joined
        return self.core.uri

    @property
    def graph(self) -> Feed[Graph]:
        """The ROS graph, when it changes."""
        assert self._graph is not None, "the host was started with watch=False"
        return self._graph

    @property
    def logs(self) -> Feed[LogRecord]:
        """The nodes' log lines (unless a console was given)."""
        assert self._logs is not None, "the host was started with watch=False"
        return self._logs

    def _start_master(self) -> None:
        """Start the core, or check that the master to join answers.

        Raises:
            PortInUseError: the master's port is taken.
            MasterUnreachable: joining, and no master answers at ``join``.
        """
        if self.core is None:
            master = MasterClient(self.master_uri, "/rosx_sim", timeout=JOIN_TIMEOUT)
            try:
                master.check_online()
            finally:
                master.close()
        else:
            self.core.start()
            self._stops.append(self.core.stop)

    def _open_log_feeds(self) -> Console:
        """The graph's and the log lines' feeds; the console the nodes log to."""
        from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - textual, for a screen
        from rosx_turtle.tui.log import ScreenConsole  # noqa: PLC0415 - textual, for a screen

        self._graph, self._logs = Feed(), Feed()
        return self.console or ScreenConsole(self._logs.offer, self.environ)

    def _watch_graph(self) -> None:
        from rosx_turtle.tui.graph import GraphWatcher  # noqa: PLC0415 - for a screen

        watcher = GraphWatcher(self.master_uri, self.graph).start()
        self._stops.append(watcher.stop)

    def describe_topic(self, topic: str) -> str:
        """``rostopic info TOPIC``'s text (blocks: call from a worker thread)."""
        return self._inspector().describe_topic(topic)

    def describe_node(self, node: str) -> str:
        """``rosnode info NODE``'s text (blocks: call from a worker thread)."""
        return self._inspector().describe_node(node)

    def echo(self, topic: str, offer: Callable[[str], object]) -> Callable[[], None]:
        """Offer each message of ``topic`` as ``rostopic echo`` text; returns how to stop."""
        return self._inspector().echo(topic, offer)

    def _inspector(self) -> Inspector:
        if self._inspecting is None:
            from rosx_turtle.sim.inspect import Inspector  # noqa: PLC0415 - when asked

            self._inspecting = Inspector(self.master_uri, self.environ)
            self._stops.append(self._inspecting.close)
        return self._inspecting

    def stop(self) -> None:
        """Stop everything started, in reverse order (nodes unregister from the master first)."""
        while self._stops:
            self._stops.pop()()
