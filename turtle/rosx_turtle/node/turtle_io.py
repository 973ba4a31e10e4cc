"""`TurtleIo`: one turtle's topics and services, as turtlesim's ``Turtle`` creates them.

Under ``ros::NodeHandle(<name>)``, i.e. relative to the node's namespace (``/turtle1/...``),
every name remappable: ``cmd_vel`` (subscribed, queue 1), ``pose`` and ``color_sensor``
(published every tick, queue 1), and the services ``set_pen``, ``teleport_relative`` and
``teleport_absolute``. Callbacks do nothing themselves: they hand the request to the
simulator's tick thread (`TurtleHost`), where turtlesim runs its callbacks too.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.names import ns_join
from rosx_turtle import roscpp

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message
    from rosx.node import Node, Publisher, ServiceHandle, Subscriber
    from rosx_turtle.engine import Simulation


class TurtleHost(Protocol):
    """What a turtle's callbacks need from the simulator node."""

    node: Node

    def log(self, level: int, message: str) -> None:
        """Log a record (console and /rosout)."""

    def post(self, action: Callable[[Simulation], object]) -> None:
        """Run ``action`` on the tick thread, before the next tick; don't wait."""

    def call(self, action: Callable[[Simulation], object]) -> object:
        """Run ``action`` on the tick thread, before the next tick, and return its result."""


class TurtleIo:
    """The topics and services of turtle ``name``; `close` removes them all."""

    def __init__(self, host: TurtleHost, name: str, wall_clock: Callable[[], float]) -> None:
        node = host.node
        self.name = name
        self.host = host
        self.alive = True
        self._clock = wall_clock
        self.namespace = node.resolve(name)
        self.pose_class = get_message_class("turtlesim/Pose")
        self.colour_class = get_message_class("turtlesim/Color")
        self._types = {
            service: get_service_class(f"turtlesim/{service_type(service)}")
            for service in ("set_pen", "teleport_relative", "teleport_absolute")
        }
        self._services: list[ServiceHandle] = []
        self._subscriber: Subscriber | None = None
        self._publishers: list[Publisher] = []
        try:
            self._subscriber = node.subscribe(
                self._topic("cmd_vel"),
                get_message_class("geometry_msgs/Twist"),
                self._on_cmd_vel,
                queue_size=1,
            )
            self.pose = node.advertise(self._topic("pose"), self.pose_class, queue_size=1)
            self.colour = node.advertise(
                self._topic("color_sensor"), self.colour_class, queue_size=1
            )
            self._publishers += [self.pose, self.colour]
            for service, handler in (
                ("set_pen", self._set_pen),
                ("teleport_relative", self._teleport_relative),
                ("teleport_absolute", self._teleport_absolute),
            ):
                self._services.append(
                    roscpp.advertise_service(
                        node,
                        self._topic(service),
                        self._types[service],
                        handler,
                        host.log,
                    )
                )
        except BaseException:
            self.close()
            raise

    def _topic(self, name: str) -> str:
        return ns_join(self.namespace, name)

    def publish(
        self, pose: tuple[float, float, float, float, float], colour: tuple[int, int, int]
    ) -> None:
        """Publish one tick's pose and colour reading."""
        self.pose.publish(self.pose_class(*pose))
        self.colour.publish(self.colour_class(*colour))

    def close(self) -> None:
        """Unregister the turtle's topics and services (it was killed, or the pond reset)."""
        self.alive = False
        handles: list[Subscriber | Publisher | ServiceHandle] = [*self._publishers, *self._services]
        if self._subscriber is not None:
            handles.insert(0, self._subscriber)
        for handle in handles:
            handle.unregister()

    # -- callbacks (receiver and service threads) --------------------------------------------

    def _on_cmd_vel(self, twist: Any) -> None:
        vx, vy, w = twist.linear.x, twist.linear.y, twist.angular.z

        def command(sim: Simulation) -> None:
            if self.alive:
                sim.command(self.name, vx, vy, w, self._clock())

        self.host.post(command)

    def _set_pen(self, request: Any) -> Message | None:
        r, g, b, width, off = request.r, request.g, request.b, request.width, request.off
        return self._run("set_pen", lambda sim: sim.set_pen(self.name, r, g, b, width, off))

    def _teleport_relative(self, request: Any) -> Message | None:
        linear, angular = request.linear, request.angular
        return self._run(
            "teleport_relative", lambda sim: sim.teleport_relative(self.name, linear, angular)
        )

    def _teleport_absolute(self, request: Any) -> Message | None:
        x, y, theta = request.x, request.y, request.theta
        return self._run(
            "teleport_absolute", lambda sim: sim.teleport_absolute(self.name, x, y, theta)
        )

    def _run(self, service: str, action: Callable[[Simulation], bool]) -> Message | None:
        done = self.host.call(lambda sim: self.alive and action(sim))
        return self._types[service]._response_class() if done else None


def service_type(service: str) -> str:
    """The ``turtlesim`` type of a turtle's service: ``set_pen`` → ``SetPen``."""
    return "".join(part.capitalize() for part in service.split("_"))
