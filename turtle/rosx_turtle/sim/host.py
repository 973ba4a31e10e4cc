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

from rosx.msg.codec.classes import get_message_class
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.sim.graph_host import GraphHost, await_subscriber
from rosx_turtle.teleop import DEFAULT_NAME as TELEOP_NAME
from rosx_turtle.teleop import param_double

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.node import Node, Publisher
    from rosx_turtle.console import Console
    from rosx_turtle.node.turtlesim import TurtlesimNode
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.scene import Scene

#: Where the teleop publishes, relative to its namespace (turtle_teleop_key's name).
CMD_VEL = "turtle1/cmd_vel"


class SimHost(GraphHost):
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
        super().__init__(port, environ, console=console, watch=watch, join=join)
        self.tf_demo = tf_demo
        self.seed = seed
        self.turtlesim: TurtlesimNode | None = None
        self.teleop: Node | None = None
        self.scales = (2.0, 2.0)
        self._scenes: Feed[Scene] | None = None
        #: The teleop's publisher of /turtle1/cmd_vel (after `start`).
        self.cmd_vel: Publisher | None = None
        self._twist: type[Any] = get_message_class("geometry_msgs/Twist")

    @property
    def scenes(self) -> Feed[Scene]:
        """The pond after each tick that changed it."""
        assert self._scenes is not None, "the host was started with watch=False"
        return self._scenes

    def start(self) -> SimHost:
        """Start everything; returns self once turtlesim listens to the teleop.

        Raises:
            PortInUseError: the master's port is taken.
            MasterUnreachable: joining, and no master answers at ``join``.
        """
        self._start_master()
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
        await_subscriber(self.cmd_vel, turtlesim.node.name)
        if self.tf_demo:
            from rosx_turtle.tutorials.tf_demo import TfDemo  # noqa: PLC0415 - with the demo

            demo = TfDemo(environ).start()
            self._stops.append(demo.stop)
        if self.watch:
            self._start_watching(turtlesim, uri)

    def _open_feeds(self) -> Console:
        from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - textual, for a screen

        self._scenes = Feed()
        return self._open_log_feeds()

    def _start_watching(self, turtlesim: TurtlesimNode, uri: str) -> None:
        from rosx_turtle.view.adapt import follow  # noqa: PLC0415 - numpy, for a screen

        self._stops.append(follow(turtlesim, self.scenes.offer))
        self._watch_graph()

    def drive(self, linear: float, angular: float) -> None:
        """Publish one Twist on ``/turtle1/cmd_vel``: ``linear.x`` and ``angular.z``, all else 0."""
        if self.cmd_vel is None:
            return
        twist = self._twist()
        twist.linear.x = linear
        twist.angular.z = angular
        self.cmd_vel.publish(twist)
