"""`StageNode`: stage_ros's ``stageros``, the engine's `StageSim` behind ROS 1 interfaces.

What it offers, as stage_ros does: per robot ``odom`` and ``base_pose_ground_truth``
(nav_msgs/Odometry), ``base_scan`` (sensor_msgs/LaserScan; ``base_scan_N`` for a robot with
several lasers), ``cmd_vel`` (geometry_msgs/Twist, subscribed); tf odom → base_footprint →
base_link → base_laser_link on ``/tf``; ``/clock`` on every step, after setting
``/use_sim_time``; the ``reset_positions`` service; the private parameter
``~base_watchdog_timeout`` (0.2 s: a robot without a command for that long stops). With
several robots (or ``-u``), names go under ``/robot_N/`` (or ``/<model name>/``); frames
likewise, without the leading slash tf2 rejects.

Where stage_ros's users asked for more: odometry's ``child_frame_id`` is set
(``base_footprint``), its twist carries the robot's velocities, and ``cmd_pose``
(geometry_msgs/Pose) and ``cmd_pose_stamped`` put a robot at a pose (the topics of stage_ros's
unreleased ``add_pose_sub``). The watchdog stops only the robot whose commands stopped.

Threads: a `Ticker` steps the simulation every ``interval_sim`` (divided by ``speed``); the
callbacks post to the tick thread (`Inbox`). Views read `snapshot` or listen to steps.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.codec.rostime import Time
from rosx.node import ERROR, INFO, WARN
from rosx.tf.broadcaster import TransformBroadcaster
from rosx_turtle import roscpp
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.node.inbox import Inbox
from rosx_turtle.node.ticker import Ticker
from rosx_turtle.stage.engine.simulation import StageSim

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message
    from rosx.node import Publisher, ServiceHandle, Subscriber
    from rosx_turtle.roscpp import NodeArgs
    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.world.model import Robot, World

#: stage_ros's default watchdog (seconds of simulated time without a command).
DEFAULT_WATCHDOG = 0.2
_NS = 1_000_000_000


@dataclass(frozen=True, eq=False)
class StageSnapshot:
    """The simulation at one step, safe to keep (see `StepReport`; None before the first)."""

    report: StepReport | None
    world: World
    grid: Grid
    names: tuple[str, ...]


def robot_prefixes(world: World, use_model_names: bool) -> list[str]:
    """Each robot's namespace as stage_ros's ``mapName`` gives it ("" for a lone robot),
    without a leading slash."""
    robots = world.robots
    if len(robots) <= 1 and not use_model_names:
        return ["" for _ in robots]
    return [
        f"{robot.name}/" if use_model_names and robot.name else f"robot_{index}/"
        for index, robot in enumerate(robots)
    ]


def _stamp(nanos: int) -> Time:
    return Time(nanos // _NS, nanos % _NS)


class _RobotIo:
    """One robot's publishers and subscribers."""

    def __init__(self, host: StageNode, index: int, robot: Robot, prefix: str) -> None:
        node = host.node
        self.prefix = prefix
        topic = ("/" + prefix) if prefix else ""
        self.odom = node.advertise(topic + "odom", host.odometry, queue_size=10)
        self.truth = node.advertise(topic + "base_pose_ground_truth", host.odometry, queue_size=10)
        lasers = len(robot.lasers)
        self.scans: list[Publisher] = [
            node.advertise(
                topic + ("base_scan" if lasers == 1 else f"base_scan_{j}"),
                host.laser_scan,
                queue_size=10,
            )
            for j in range(lasers)
        ]
        self.laser_frames = [
            prefix + ("base_laser_link" if lasers == 1 else f"base_laser_link_{j}")
            for j in range(lasers)
        ]
        twist = get_message_class("geometry_msgs/Twist")
        self.subscribers: list[Subscriber] = [
            node.subscribe(topic + "cmd_vel", twist, host.on_cmd_vel(index), queue_size=10),
            node.subscribe(
                topic + "cmd_pose",
                get_message_class("geometry_msgs/Pose"),
                host.on_cmd_pose(index, stamped=False),
                queue_size=10,
            ),
            node.subscribe(
                topic + "cmd_pose_stamped",
                get_message_class("geometry_msgs/PoseStamped"),
                host.on_cmd_pose(index, stamped=True),
                queue_size=10,
            ),
        ]


class StageNode:
    """stageros as a library object: `start`, observe, `shutdown`.

    Args:
        args: The node's name, namespace, remappings and private parameters.
        world, grid: The world to simulate and its occupancy grid (`load_world`).
        environ: The environment (``ROS_MASTER_URI``...).
        console: Where log lines are printed (None: only ``/rosout``).
        use_model_names: ``-u``: robots' topics under their model names.
        speed: How many times faster than real time the simulated clock runs.
    """

    def __init__(
        self,
        args: NodeArgs,
        world: World,
        grid: Grid,
        *,
        environ: dict[str, str] | Any,
        console: Console | None = None,
        use_model_names: bool = False,
        speed: float = 1.0,
    ) -> None:
        self.args = args
        self.world = world
        self.grid = grid
        self.node = args.make_node(environ)
        self._log = NodeLog(self.node, console, logger="ros.stage_ros")
        self.sim = StageSim(world, grid)
        self.speed = speed
        self.prefixes = robot_prefixes(world, use_model_names)
        self.odometry = get_message_class("nav_msgs/Odometry")
        self.laser_scan = get_message_class("sensor_msgs/LaserScan")
        self._transform = get_message_class("geometry_msgs/TransformStamped")
        self._clock_message = get_message_class("rosgraph_msgs/Clock")
        self._inbox: Inbox[StageSim] = Inbox()
        self._ios: list[_RobotIo] = []
        self._services: list[ServiceHandle] = []
        self._listeners: list[Callable[[StepReport], object]] = []
        self._lock = threading.Lock()
        self._last: StepReport | None = None
        self.steps = 0
        self._ticker = Ticker(
            world.interval_sim / speed,
            self._tick,
            name=f"rosx-stage{self.node.name}",
            on_error=lambda exc: self.log(ERROR, f"stage step failed: {exc}"),
        )

    # -- lifecycle ----------------------------------------------------------------------------

    def start(self) -> StageNode:
        """Register with the master, set ``/use_sim_time``, advertise, and start stepping.

        Raises:
            TransportError: the master cannot be reached.
        """
        node = self.node
        node.start()
        node.on_shutdown(lambda reason: self._stop())
        try:
            self.args.set_private_params(node)
            timeout = node.params.get("~base_watchdog_timeout", DEFAULT_WATCHDOG)
            if isinstance(timeout, (int, float)) and not isinstance(timeout, bool):
                self.sim.watchdog_ns = round(float(timeout) * _NS)
            node.params.set("/use_sim_time", True)
            if self.world.ignored:
                self.log(WARN, "Not simulated (ignored): " + "; ".join(self.world.ignored))
            for index, robot in enumerate(self.world.robots):
                token = robot.name or robot.token
                self.log(INFO, f'Subscribed to Stage position model "{token}"')
                for j, _laser in enumerate(robot.lasers):
                    self.log(INFO, f'subscribed to Stage ranger "{token}.ranger:{j}"')
                self.log(INFO, f"Robot {token} provided {len(robot.lasers)} rangers and 0 cameras")
                self._ios.append(_RobotIo(self, index, robot, self.prefixes[index]))
            self.clock = node.advertise("/clock", self._clock_message, queue_size=10)
            self.tf = TransformBroadcaster(node=node)
            self._services.append(
                roscpp.advertise_service(
                    node,
                    "reset_positions",
                    get_service_class("std_srvs/Empty"),
                    self._reset,
                    self.log,
                )
            )
            self._ticker.start()
        except BaseException:
            self.shutdown("start-up failed")
            raise
        return self

    def shutdown(self, reason: str = "") -> None:
        """Stop stepping and leave the ROS graph."""
        self._stop()
        self.node.shutdown(reason)

    def _stop(self) -> None:
        self._ticker.stop()
        self._inbox.close()

    def is_shutdown(self) -> bool:
        """Whether the node has shut down."""
        return self.node.is_shutdown()

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)

    # -- for callbacks and views --------------------------------------------------------------

    def log(self, level: int, message: str) -> None:
        """Log a record to the console and ``/rosout``."""
        self._log(level, message)

    def post(self, action: Callable[[StageSim], object]) -> None:
        """Run ``action(simulation)`` on the tick thread before the next step."""
        self._inbox.post(action)

    def call(self, action: Callable[[StageSim], object]) -> object:
        """As `post`, waiting for the result (not from the tick thread)."""
        return self._inbox.call(action)

    def snapshot(self) -> StageSnapshot:
        """The simulation after its latest step; callable from any thread."""
        names = tuple(r.name or r.token for r in self.world.robots)
        with self._lock:
            return StageSnapshot(self._last, self.world, self.grid, names)

    def add_step_listener(self, listener: Callable[[StepReport], object]) -> Callable[[], None]:
        """Call ``listener(report)`` on the tick thread after every step; returns a remover."""
        self._listeners = [*self._listeners, listener]

        def remove() -> None:
            self._listeners = [item for item in self._listeners if item is not listener]

        return remove

    def on_cmd_vel(self, index: int) -> Callable[[Any], None]:
        """The ``cmd_vel`` callback of robot ``index``."""

        def callback(twist: Any) -> None:
            vx, vy, w = twist.linear.x, twist.linear.y, twist.angular.z
            self.post(lambda sim: sim.set_command(index, vx, vy, w))

        return callback

    def on_cmd_pose(self, index: int, *, stamped: bool) -> Callable[[Any], None]:
        """The ``cmd_pose`` (or ``cmd_pose_stamped``) callback of robot ``index``."""

        def callback(message: Any) -> None:
            pose = message.pose if stamped else message
            q = pose.orientation
            yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
            x, y = pose.position.x, pose.position.y
            self.post(lambda sim: sim.set_pose(index, x, y, yaw))

        return callback

    def _reset(self, request: Any) -> object:
        def reset(sim: StageSim) -> object:
            self.log(INFO, "Resetting stage!")
            sim.reset()
            return {}

        return self.call(reset)

    # -- a step -------------------------------------------------------------------------------

    def _tick(self) -> None:
        sim = self.sim
        self._inbox.drain(sim)
        with self._lock:
            report = sim.step()
            self._last = report
            self.steps += 1
        self._publish(report)
        for listener in self._listeners:
            listener(report)

    def _publish(self, report: StepReport) -> None:
        stamp = _stamp(report.time_ns)
        odometry = self.odometry
        transforms: list[Message] = []
        odom = report.odom.tolist()
        pose = report.pose.tolist()
        velocity = report.velocity.tolist()
        world_velocity = report.world_velocity.tolist()
        for io, robot, (ox, oy, oyaw), (gx, gy, gyaw), (vx, vy, w), (wx, wy, ww) in zip(
            self._ios, self.world.robots, odom, pose, velocity, world_velocity, strict=True
        ):
            prefix = io.prefix
            footprint = prefix + "base_footprint"
            message = odometry()
            message.header.stamp = stamp
            message.header.frame_id = prefix + "odom"
            message.child_frame_id = footprint
            _set_pose(message.pose.pose, ox, oy, oyaw)
            message.twist.twist.linear.x = vx
            message.twist.twist.linear.y = vy
            message.twist.twist.angular.z = w
            io.odom.publish(message)
            truth = odometry()
            truth.header.stamp = stamp
            truth.header.frame_id = prefix + "odom"
            truth.child_frame_id = footprint
            _set_pose(truth.pose.pose, gx, gy, gyaw)
            truth.twist.twist.linear.x = wx
            truth.twist.twist.linear.y = wy
            truth.twist.twist.angular.z = ww
            io.truth.publish(truth)
            transforms.append(self._tf(stamp, prefix + "odom", footprint, ox, oy, 0.0, oyaw))
            transforms.append(self._tf(stamp, footprint, prefix + "base_link", 0.0, 0.0, 0.0, 0.0))
            for j, laser in enumerate(robot.lasers):
                lx, ly, la = laser.pose
                transforms.append(
                    self._tf(
                        stamp, prefix + "base_link", io.laser_frames[j], lx, ly, laser.height, la
                    )
                )
        for scan in report.scans:
            io = self._ios[scan.robot]
            spec = scan.spec
            message = self.laser_scan()
            message.header.stamp = stamp
            message.header.frame_id = io.laser_frames[scan.laser]
            message.angle_min = -spec.fov / 2
            message.angle_max = spec.fov / 2
            message.angle_increment = spec.angle_increment
            message.scan_time = spec.interval
            message.range_min = spec.range_min
            message.range_max = spec.range_max
            message.ranges = scan.ranges
            message.intensities = scan.intensities
            io.scans[scan.laser].publish(message)
        if transforms:
            self.tf.sendTransform(transforms)
        self.clock.publish(self._clock_message(clock=stamp))

    def _tf(
        self, stamp: Time, parent: str, child: str, x: float, y: float, z: float, yaw: float
    ) -> Message:
        transform = self._transform()
        transform.header.stamp = stamp
        transform.header.frame_id = parent
        transform.child_frame_id = child
        translation = transform.transform.translation
        translation.x, translation.y, translation.z = x, y, z
        rotation = transform.transform.rotation
        rotation.z, rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        return transform


def _set_pose(pose: Any, x: float, y: float, yaw: float) -> None:
    pose.position.x, pose.position.y = x, y
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)


__all__ = ["DEFAULT_WATCHDOG", "StageNode", "StageSnapshot", "robot_prefixes"]
