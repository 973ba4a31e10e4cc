"""`LiveSource`: rviz's node on a master: tf, the displays' topics, the tools' publishers.

The node (``/rviz_<pid>_<ms>``, anonymous as rviz's) starts in `start`, from a worker thread.
tf comes through rosx.tf's `TransformListener` into the manager's buffer core. Each enabled
display with a topic gets one subscription (`sync` follows the Displays panel); messages are
decoded with numpy arrays (a 4 000 by 4 000 map is one array, not sixteen million numbers) on
the subscription's thread and handed to the manager there, and ``changed`` is called so the
view redraws. Nothing here touches a widget.

With ``/use_sim_time`` set (the robot simulator sets it), the tools stamp their messages with
``/clock``'s time, as rviz's ``ros::Time::now()`` does.
"""

from __future__ import annotations

import sys
import threading
import time
from typing import TYPE_CHECKING, Any

from rosx_commands.rviz.displays.robot_model import RobotModel
from rosx_commands.toolnode import ToolNode

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import Publisher, Subscriber
    from rosx_commands.context import Environment
    from rosx_commands.rviz.displays.base import Display
    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.tools import Tool


class LiveSource(ToolNode):
    """A master's topics and tf, for one `Manager` (see the module docstring)."""

    def __init__(self, env: Environment, clock: Callable[[], float] = time.monotonic) -> None:
        super().__init__(env, "rviz")
        self.clock = clock
        self.manager: Manager | None = None
        self.changed: Callable[[], object] = lambda: None
        self._subscribers: dict[int, tuple[str, Subscriber]] = {}
        self._publishers: dict[str, Publisher] = {}
        self._listener: Any = None
        self._lock = threading.Lock()

    @property
    def master_uri(self) -> str:
        """The master this source talks to (shown while waiting for it)."""
        return self.env.master_uri

    def start(self, manager: Manager, changed: Callable[[], object]) -> None:
        """Start the node, listen to tf and subscribe the enabled displays (blocks on the
        master: call it from a worker)."""
        from rosx.node.simtime import follow_sim_time  # noqa: PLC0415 - the node runtime loads with the first node
        from rosx.tf.listener import TransformListener  # noqa: PLC0415 - tf code loads only when used

        self.manager, self.changed = manager, changed
        node = self._started()
        core: Any = manager.frames.core
        core.add_listener(changed)
        self._listener = TransformListener(core, node=node)  # it stores with .set and .clear
        follow_sim_time(node)
        self.sync()

    def sync(self) -> None:
        """Subscribe the displays that want their topic, unsubscribe the others; give the
        robot models their description."""
        manager = self.manager
        if manager is None:
            return
        with manager.lock:
            wanted = {id(display): display for display in manager.displays if display.subscribes}
            models = [d for d in manager.displays if isinstance(d, RobotModel) and d.enabled]
        for model in models:
            text = self._started().params.get(model.parameter, None)
            manager.receive(model, None if text is None else str(text), self.clock())
            self.changed()
        with self._lock:
            for key in list(self._subscribers):
                topic, subscriber = self._subscribers[key]
                display = wanted.get(key)
                if display is None or display.topic != topic:
                    subscriber.unregister()
                    del self._subscribers[key]
            for key, display in wanted.items():
                if key not in self._subscribers:
                    self._subscribers[key] = (display.topic, self._subscribe(display))

    def _subscribe(self, display: Display) -> Subscriber:
        import numpy  # numpy only on this path

        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

        manager = self.manager
        assert manager is not None
        message_type = display.MESSAGE_TYPE or ""
        msg_class = get_message_class(message_type, self._types())
        clock, changed = self.clock, self.changed

        def arrived(raw: Any) -> None:
            if raw.type not in ("*", message_type):
                with manager.lock:
                    display.statuses.error(
                        "Topic", f"Messages of type [{raw.type}], not [{message_type}]"
                    )
                changed()
                return
            msg = msg_class().deserialize_numpy(raw._buff, numpy)
            manager.receive(display, msg, clock())
            changed()

        return self._started().subscribe(display.topic, None, arrived)

    def publish(self, tool: Tool, fixed: str, x: float, y: float, yaw: float) -> str:
        """Publish what ``tool`` places at (``x``, ``y``, ``yaw``) in ``fixed``; the log line."""
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use
        from rosx.node import INFO  # noqa: PLC0415 - the node runtime loads with the first node
        from rosx_commands.rviz.tools import fill, log_line  # noqa: PLC0415 - this tool's parts load only when used

        node = self._started()
        msg_class = get_message_class(tool.message_type, self._types())
        with self._lock:
            publisher = self._publishers.get(tool.topic)
            if publisher is None:
                publisher = node.advertise(tool.topic, msg_class, queue_size=1)
                self._publishers[tool.topic] = publisher
        msg = fill(tool, msg_class(), fixed, self.stamp(), x, y, yaw)
        publisher.publish(msg)
        line = log_line(tool, fixed, x, y, yaw)
        node.log(INFO, line)
        return line

    def advertise(self, tools: tuple[Tool, ...]) -> None:
        """Advertise the tools' topics now, as rviz does when it starts."""
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

        node = self._started()
        with self._lock:
            for tool in tools:
                if tool.topic not in self._publishers:
                    msg_class = get_message_class(tool.message_type, self._types())
                    self._publishers[tool.topic] = node.advertise(
                        tool.topic, msg_class, queue_size=1
                    )

    def stamp(self) -> Any:
        """Now, as ROS time (``/clock``'s under simulated time)."""
        return self._started().clock.now()

    def param(self, name: str) -> Any:
        """A parameter's value (None when unset)."""
        return self._started().params.get(name, None)

    @override
    def close(self) -> None:
        if self.manager is not None:
            self.manager.frames.core.remove_listener(self.changed)
        super().close()


__all__ = ["LiveSource"]
