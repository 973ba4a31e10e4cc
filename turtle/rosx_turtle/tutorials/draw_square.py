"""draw_square: drive turtle1 round a 2 m square (node ``draw_square``, as in Noetic).

At start-up it calls ``reset`` (``std_srvs/Empty``) once without waiting for it to exist, then
every 0.016 s, once a pose has arrived on ``turtle1/pose``, runs a state machine publishing on
``turtle1/cmd_vel`` (queue 1):

* FORWARD: (1.0, 0) until within 0.1 m of the goal on x and y and 0.01 rad on theta, then a
  zero Twist and STOP_FORWARD;
* STOP_FORWARD and STOP_TURN: zero Twists until the pose's velocities are both below 0.0001;
  then ``Reached goal`` and the next goal: a quarter turn (theta + PI/2 wrapped into [-PI, PI),
  PI = 3.141592 here) or 2 m ahead;
* TURN: (0, 0.4) until the goal is reached.

Each new goal is logged as ``New goal [x y, theta]``. Goals are float32, as turtlesim/Pose.
"""

from __future__ import annotations

import contextlib
import math
import threading
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import INFO, NodeError
from rosx.transport.errors import TransportError
from rosx_turtle.console import Console, NodeLog
from rosx_turtle.engine.constants import f32
from rosx_turtle.env import ProcessEnv
from rosx_turtle.node.ticker import Ticker
from rosx_turtle.program import master_address, run_until_stopped
from rosx_turtle.roscpp import NodeArgs

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence

    from rosx.node import Node, Publisher
    from rosx_turtle.env import Env

DEFAULT_NAME = "draw_square"
PI = 3.141592
PERIOD = 0.016
FORWARD, STOP_FORWARD, TURN, STOP_TURN = "FORWARD", "STOP_FORWARD", "TURN", "STOP_TURN"


class SquareDriver:
    """The state machine; `step` is the timer callback (``pose`` is the latest pose or None)."""

    def __init__(self, command: Callable[[float, float], None], log: Callable[[str], None]):
        self.command = command
        self.log = log
        self.state = FORWARD
        self.goal: tuple[float, float, float] | None = None

    def step(self, pose: Any) -> None:
        """One timer tick."""
        if pose is None:
            return
        if self.goal is None:
            self.state = FORWARD
            self._goal_ahead(pose)
        if self.state == FORWARD:
            self._drive(pose, STOP_FORWARD, 1.0, 0.0)
        elif self.state == STOP_FORWARD:
            self._stop(pose, TURN)
        elif self.state == TURN:
            self._drive(pose, STOP_TURN, 0.0, 0.4)
        else:
            self._stop(pose, FORWARD)

    def _reached(self, pose: Any) -> bool:
        assert self.goal is not None
        x, y, theta = self.goal
        return (
            abs(f32(pose.x - x)) < 0.1
            and abs(f32(pose.y - y)) < 0.1
            and abs(f32(pose.theta - theta)) < 0.01
        )

    def _drive(self, pose: Any, then: str, linear: float, angular: float) -> None:
        if self._reached(pose):
            self.state = then
            self.command(0.0, 0.0)
        else:
            self.command(linear, angular)

    def _stop(self, pose: Any, then: str) -> None:
        if not (pose.angular_velocity < 0.0001 and pose.linear_velocity < 0.0001):
            self.command(0.0, 0.0)
            return
        self.log("Reached goal")
        self.state = then
        if then == TURN:
            theta = f32(math.fmod(pose.theta + PI / 2.0, 2 * PI))
            if theta >= PI:
                theta = f32(theta - 2 * PI)
            self._set_goal(pose.x, pose.y, theta)
        else:
            self._goal_ahead(pose)

    def _goal_ahead(self, pose: Any) -> None:
        self._set_goal(
            math.cos(pose.theta) * 2 + pose.x, math.sin(pose.theta) * 2 + pose.y, pose.theta
        )

    def _set_goal(self, x: float, y: float, theta: float) -> None:
        self.goal = (f32(x), f32(y), f32(theta))
        gx, gy, gt = self.goal
        self.log(f"New goal [{gx:f} {gy:f}, {gt:f}]")


class DrawSquare:
    """The draw_square node: started, it drives until `shutdown`."""

    def __init__(self, args: NodeArgs, environ: Mapping[str, str], console: Console | None):
        self.node: Node = args.make_node(environ)
        self.args = args
        self.log = NodeLog(self.node, console)
        self.pose: Any = None
        self._ticker = Ticker(PERIOD, self._tick, name="rosx-draw-square")
        self._publisher: Publisher | None = None
        self._driver: SquareDriver | None = None
        self._lock = threading.Lock()

    def start(self) -> DrawSquare:
        """Subscribe, advertise, call ``reset`` once and start the timer."""
        node = self.node.start()
        try:
            self.args.set_private_params(node)
            node.subscribe(
                "turtle1/pose", get_message_class("turtlesim/Pose"), self._on_pose, queue_size=1
            )
            twist_class = get_message_class("geometry_msgs/Twist")
            publisher = node.advertise("turtle1/cmd_vel", twist_class, queue_size=1)

            def command(linear: float, angular: float) -> None:
                twist = twist_class()
                twist.linear.x = f32(linear)
                twist.angular.z = f32(angular)
                publisher.publish(twist)

            self._driver = SquareDriver(command, lambda text: self.log(INFO, text))
            reset = node.service_client("reset", get_service_class("std_srvs/Empty"))
            with contextlib.suppress(NodeError, TransportError):  # roscpp's call returns false
                reset.call(reset.request_class())
            self._ticker.start()
        except BaseException:
            self.shutdown("start-up failed")
            raise
        return self

    def _on_pose(self, pose: Any) -> None:
        with self._lock:
            self.pose = pose

    def _tick(self) -> None:
        with self._lock:
            pose = self.pose
        if self._driver is not None:
            self._driver.step(pose)

    def shutdown(self, reason: str = "") -> None:
        """Stop the timer and leave the ROS graph."""
        self._ticker.stop()
        self.node.shutdown(reason)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until shut down; False if ``timeout`` passed first."""
        return self.node.wait_for_shutdown(timeout)


def run_draw_square(argv: Sequence[str], env: Env | None = None) -> int:
    """Run draw_square until SIGINT, SIGTERM or a shutdown; exit status."""
    env = env or ProcessEnv()
    args = NodeArgs.parse(argv, DEFAULT_NAME)
    console = Console(env.stdout, env.stderr, env.environ)
    return run_until_stopped(
        lambda: DrawSquare(args, env.environ, console).start(),
        console,
        master_address(args.master_uri, env.environ),
    )
