"""What the app needs of the ROS side (`Source`): `rosx_commands.rviz.live.LiveSource` on a
master, or a test's own with the same methods."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.tools import Tool


class Source(Protocol):
    """Where rviz's displays get their messages and transforms (the live node, or a test's)."""

    def start(self, manager: Manager, changed: Callable[[], object]) -> None:
        """Begin feeding ``manager`` (may block: the app calls it from a worker thread)."""
        ...

    def sync(self) -> None:
        """Subscribe what the displays now want (after one was shown or hidden)."""
        ...

    def advertise(self, tools: tuple[Tool, ...]) -> None:
        """Advertise the tools' topics (by default ``/move_base_simple/goal``, ``/initialpose``
        and ``/clicked_point``), as rviz does when it starts."""

    def publish(self, tool: Tool, fixed: str, x: float, y: float, yaw: float) -> str:
        """Publish the tool's message; the line rviz logs."""
        ...

    def param(self, name: str) -> Any:
        """A parameter's value, or None when it is not set."""

    def close(self) -> None:
        """Stop the node and drop its subscriptions."""


__all__ = ["Source"]
