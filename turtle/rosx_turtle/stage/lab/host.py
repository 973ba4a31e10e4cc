"""`LabHost`: the robot lab's whole ROS graph in one process, and the feeds its screen follows.

It starts what the lab's launch files start in their terminals: roscore's core
(`rosx.core.Core`, unless it joins a running master), ``/stageros`` (`StageNode`, the node
``rosrun stage_ros stageros`` runs), ``/map_server`` (`MapServerNode`) when there is a map,
``/map_to_odom`` latching ``map`` → each robot's ``odom`` on ``/tf_static`` (as the launch
file's static_transform_publisher does), and ``/teleop_twist_keyboard``, which publishes
geometry_msgs/Twist on the first robot's ``cmd_vel`` (queue 1, as teleop_twist_keyboard).
The graph looks the same to ``rostopic``, ``rosnode``, rviz and rqt in other terminals.
On top it runs the feeds the screen follows: every simulation step, the graph whenever the
master's lists change, and the nodes' log lines.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.tf.broadcaster import StaticTransformBroadcaster
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.sim.graph_host import GraphHost, await_subscriber
from rosx_turtle.stage.lab.plan import LabError, driven_topics, odom_origin

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.node import Node, Publisher
    from rosx_turtle.console import Console
    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.lab.plan import LabPlan
    from rosx_turtle.stage.node.stageros import StageNode
    from rosx_turtle.stage.world.model import World
    from rosx_turtle.tui.feed import Feed

TELEOP_NAME = "teleop_twist_keyboard"


class LabHost(GraphHost):
    """Master, stageros, map_server, ``map`` → ``odom`` and teleop; `start`, use, `stop`.

    Args:
        plan: The world, map and remappings (`plan_lab`).
        port: The master's port (unused with ``join``).
        environ: The environment (``ROS_IP``, ``ROS_HOSTNAME``, ``ROSCONSOLE_FORMAT``...).
        console: Where the nodes' log lines go besides ``/rosout`` (None: to `logs` when
            watching, else nowhere).
        watch: Whether to run the feeds for a screen (`steps`, `graph` and `logs`).
        join: The URI of a master already running: start no core, register the nodes there.
    """

    def __init__(
        self,
        plan: LabPlan,
        port: int,
        environ: Mapping[str, str],
        *,
        console: Console | None = None,
        watch: bool = True,
        join: str | None = None,
    ) -> None:
        super().__init__(port, environ, console=console, watch=watch, join=join)
        self.plan = plan
        self.stage: StageNode | None = None
        self.teleop: Node | None = None
        #: The teleop's publisher of the first robot's cmd_vel (after `start`).
        self.cmd_vel: Publisher | None = None
        #: The topics of the driven robot (the first): its cmd_vel, odometry and laser.
        self.drive_topic = "/cmd_vel"
        self.odom_topic = "/odom"
        self.scan_topic = "/base_scan"
        self.world: World | None = None
        self.grid: Grid | None = None
        self.names: tuple[str, ...] = ()
        self._steps: Feed[StepReport] | None = None
        self._twist: type[Any] = get_message_class("geometry_msgs/Twist")

    @property
    def steps(self) -> Feed[StepReport]:
        """The simulation after each step."""
        assert self._steps is not None, "the host was started with watch=False"
        return self._steps

    def start(self) -> LabHost:
        """Load the world and the map, then start everything; returns self.

        Raises:
            LabError: the world or the map cannot be read.
            PortInUseError: the master's port is taken.
            MasterUnreachable: joining, and no master answers at ``join``.
        """
        from rosx_turtle.stage.world.load import load_world  # noqa: PLC0415 - numpy
        from rosx_turtle.stage.world.worldfile import WorldFileError  # noqa: PLC0415 - as load_world

        if not self.plan.world.is_file():
            raise LabError(f"The world file {self.plan.world} does not exist.")
        try:
            self.world, self.grid = load_world(self.plan.world)
        except WorldFileError as problem:
            raise LabError(str(problem)) from None
        grid_message = self._load_map()
        self._start_master()
        try:
            self._start_nodes(grid_message)
        except BaseException:
            self.stop()
            raise
        return self

    def _load_map(self) -> Any:
        if self.plan.map is None:
            return None
        from rosx_turtle.maps.server import load_map  # noqa: PLC0415 - numpy, images

        problems: list[str] = []
        grid = load_map(self.plan.map, lambda level, text: problems.append(text))
        if grid is None:
            raise LabError(problems[-1] if problems else f"cannot read the map {self.plan.map}")
        return grid

    def _start_nodes(self, map_message: Any) -> None:
        from rosx_turtle.stage.node.stageros import StageNode  # noqa: PLC0415 - numpy

        assert self.world is not None and self.grid is not None
        uri = self.master_uri
        environ = {**self.environ, "ROS_MASTER_URI": uri}
        console = self._open_feeds() if self.watch else self.console
        stage = StageNode(
            NodeArgs.parse(self.plan.remappings, "stageros"),
            self.world,
            self.grid,
            environ=environ,
            console=console,
        )
        self.stage = stage.start()
        self._stops.append(lambda: stage.shutdown("rosx sim is done"))
        self.names = stage.snapshot().names
        if map_message is not None:
            from rosx_turtle.maps.server import MapServerNode  # noqa: PLC0415 - with a map

            server = MapServerNode(
                NodeArgs.parse([], "map_server"), map_message, environ=environ, console=console
            ).start()
            self._stops.append(lambda: server.shutdown("rosx sim is done"))
        self._start_map_to_odom(environ, stage.prefixes)
        teleop = NodeArgs.parse([], TELEOP_NAME).make_node(environ).start()
        self.teleop = teleop
        self._stops.append(lambda: teleop.shutdown("rosx sim is done"))
        self.drive_topic, self.odom_topic, self.scan_topic = driven_topics(
            stage.node, stage.prefixes
        )
        self.cmd_vel = teleop.advertise(self.drive_topic, self._twist, queue_size=1)
        if self.world.robots:  # stageros listens on each robot's cmd_vel
            await_subscriber(self.cmd_vel, stage.node.name)
        if self.watch:
            self._stops.append(stage.add_step_listener(self.steps.offer))
            self._watch_graph()

    def _start_map_to_odom(self, environ: Mapping[str, str], prefixes: list[str]) -> None:
        """``map`` → each robot's ``odom`` where its odometry starts, latched on /tf_static."""
        assert self.world is not None
        node = NodeArgs.parse([], "map_to_odom").make_node(environ).start()
        self._stops.append(lambda: node.shutdown("rosx sim is done"))
        kind = get_message_class("geometry_msgs/TransformStamped")
        transforms = []
        for robot, prefix in zip(self.world.robots, prefixes, strict=True):
            x, y, yaw = odom_origin(robot)
            transform = kind()
            transform.header.frame_id = "map"
            transform.child_frame_id = prefix + "odom"
            transform.transform.translation.x = x
            transform.transform.translation.y = y
            transform.transform.rotation.z = math.sin(yaw / 2)
            transform.transform.rotation.w = math.cos(yaw / 2)
            transforms.append(transform)
        StaticTransformBroadcaster(node=node).sendTransform(transforms)

    def _open_feeds(self) -> Console:
        from rosx_turtle.tui.feed import Feed  # noqa: PLC0415 - textual, for a screen

        self._steps = Feed()
        return self._open_log_feeds()

    def drive(self, linear_x: float, linear_y: float, linear_z: float, angular_z: float) -> None:
        """Publish one Twist on the driven ``cmd_vel`` (what teleop_twist_keyboard sets)."""
        if self.cmd_vel is None:
            return
        twist = self._twist()
        twist.linear.x, twist.linear.y, twist.linear.z = linear_x, linear_y, linear_z
        twist.angular.z = angular_z
        self.cmd_vel.publish(twist)
