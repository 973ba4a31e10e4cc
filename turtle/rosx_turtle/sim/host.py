"""`SimHost`: Lab 1's whole ROS graph in one process, and the `SimLink` its screen shows.

It starts what Lab 1 starts in four terminals: roscore's core (`rosx.core.Core`), then
``/turtlesim`` (`TurtlesimNode`, the same node ``rosrun turtlesim turtlesim_node`` runs) and
``/teleop_turtle``, which publishes ``geometry_msgs/Twist`` on ``/turtle1/cmd_vel`` with queue 1
and reads ``scale_linear``/``scale_angular`` once, in its public namespace, as
``turtle_teleop_key`` does. The graph therefore looks the same to ``rostopic``, ``rosnode`` and
rqt_graph in other terminals. With ``join`` it starts no core: the two nodes register with
the master already running at that URI. With ``tf_demo`` it also runs turtle_tf2's demo
(`rosx_turtle.tutorials.tf_demo`): a broadcaster per turtle and the listener that spawns turtle2
and makes it follow turtle1. On top it runs the feeds the screen follows: a scene after each
tick that changes the pond, the graph whenever the master's lists change, and turtlesim's log.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.core import Core
from rosx.master.client import MasterClient
from rosx.msg.codec.classes import get_message_class
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.teleop import DEFAULT_NAME as TELEOP_NAME
from rosx_turtle.teleop import param_double

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.node import Node, Publisher
    from rosx_turtle.console import Console
    from rosx_turtle.node.turtlesim import TurtlesimNode
    from rosx_turtle.sim.inspect import Inspector
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.view.scene import Scene

#: Seconds the master to join has to answer.
JOIN_TIMEOUT = 3.0
#: Where the teleop publishes, relative to its namespace (turtle_teleop_key's name).
CMD_VEL = "turtle1/cmd_vel"


class SimHost:
    """Master, ``/rosout``, ``/turtlesim`` and ``/teleop_turtle``; `start`, use, `stop`.

    Args:
        port: The master's port (unused with ``join``).
        environ: The environment (``ROS_IP``, ``ROS_HOSTNAME``, ``ROSCONSOLE_FORMAT``...).
        console: Where turtlesim's log lines go besides ``/rosout`` (None: to `logs` when
            watching, else nowhere).
        seed: Seeds turtlesim's choice of sprites (None: unpredictable).
        watch: Whether to run the feeds for a screen (`scenes`, `graph` and `logs`).
        join: The URI of a master already running: start no core, register the nodes there.
        tf_demo: Also run turtle_tf2's demo (turtle2 follows turtle1 through tf).
    """

    def __init__(
        self,
        port: int,
        environ: Mapping[str, str],
        *,
        console: Console | None = None,
        seed: int | None = None,
        watch: bool = True,
        join: str | None = None,
        tf_demo: bool = False,
    ) -> None:
        self.core = Core(port, environ) if join is None else None
        self.tf_demo = tf_demo
        self.joined = join
        self.environ = environ
        self.console = console
        self.seed = seed
        self.watch = watch
        self.turtlesim: TurtlesimNode | None = None
        self.teleop: Node | None = None
        self.scales = (2.0, 2.0)
        self._scenes: Feed[Scene] | None = None
        self._graph: Feed[Graph] | None = None
        self._logs: Feed[LogRecord] | None = None
        #: The teleop's publisher of /turtle1/cmd_vel (after `start`).
        self.cmd_vel: Publisher | None = None
        self._twist: type[Any] = get_message_class("geometry_msgs/Twist")
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
    def scenes(self) -> Feed[Scene]:
        """The pond after each tick that changed it."""
        assert self._scenes is not None, "the host was started with watch=False"
        return self._scenes

    @property
    def graph(self) -> Feed[Graph]:
        """The ROS graph, when it changes."""
        assert self._graph is not None, "the host was started with watch=False"
        return self._graph

    @property
    def logs(self) -> Feed[LogRecord]:
        """turtlesim's log lines (unless a console was given)."""
        assert self._logs is not None, "the host was started with watch=False"
        return self._logs

    def start(self) -> SimHost:
        """Start everything; returns self.

        Raises:
            PortInUseError: the master's port is taken.
            MasterUnreachable: joining, and no master answers at ``join``.
        """
        if self.core is None:
            _check_master(self.master_uri)
        else:
            self.core.start()
            self._stops.append(self.core.stop)
        try:
            self._start_nodes()
        except BaseException:
            self.stop()
            raise
        return self

    def _start_nodes(self) -> None:
        from rosx_turtle.node.turtlesim import TurtlesimNode  # noqa: PLC0415 - loads numpy

        uri = self.master_uri
        environ = {**self.environ, "ROS_MASTER_URI": uri}
        console = self._open_feeds() if self.watch else self.console
        turtlesim = TurtlesimNode(
            NodeArgs.parse([], "turtlesim"), environ=environ, console=console, seed=self.seed
        )
        self.turtlesim = turtlesim.start()
        self._stops.append(lambda: turtlesim.shutdown("rosx sim is done"))
        teleop = NodeArgs.parse([], TELEOP_NAME).make_node(environ).start()
        self.teleop = teleop
        self._stops.append(lambda: teleop.shutdown("rosx sim is done"))
        self.scales = (
            param_double(teleop, "scale_linear", 2.0),
            param_double(teleop, "scale_angular", 2.0),
        )
        self.cmd_vel = teleop.advertise(CMD_VEL, self._twist, queue_size=1)
        if self.tf_demo:
            from rosx_turtle.tutorials.tf_demo import TfDemo  # noqa: PLC0415 - with the demo

            demo = TfDemo(environ).start()
            self._stops.append(demo.stop)
        if self.watch:
            self._start_watching(turtlesim, uri)

    def _open_feeds(self) -> Console:
        # The feeds post to textual widgets: imported only when there is a screen to feed.
        from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - turtlesim's parts load only when used
        from rosx_turtle.tui.log import ScreenConsole  # noqa: PLC0415 - turtlesim's parts load only when used

        self._scenes, self._graph, self._logs = Feed(), Feed(), Feed()
        return self.console or ScreenConsole(self._logs.offer, self.environ)

    def _start_watching(self, turtlesim: TurtlesimNode, uri: str) -> None:
        from rosx_turtle.tui.graph import GraphWatcher  # noqa: PLC0415 - turtlesim's parts load only when used
        from rosx_turtle.view.adapt import follow  # noqa: PLC0415 - turtlesim's parts load only when used

        self._stops.append(follow(turtlesim, self.scenes.offer))
        watcher = GraphWatcher(uri, self.graph).start()
        self._stops.append(watcher.stop)

    def drive(self, linear: float, angular: float) -> None:
        """Publish one Twist on ``/turtle1/cmd_vel``: ``linear.x`` and ``angular.z``, all else 0."""
        if self.cmd_vel is None:
            return
        twist = self._twist()
        twist.linear.x = linear
        twist.angular.z = angular
        self.cmd_vel.publish(twist)

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


def _check_master(uri: str) -> None:
    """Raise `MasterUnreachable` unless a master answers at ``uri``."""
    master = MasterClient(uri, "/rosx_sim", timeout=JOIN_TIMEOUT)
    try:
        master.check_online()
    finally:
        master.close()
