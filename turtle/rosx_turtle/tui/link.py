"""`SimLink`: what the sim's terminal UI needs from the ROS side, and nothing more.

`rosx_turtle.sim.host.SimHost` is the real one (a master, ``/rosout``, ``/turtlesim`` and
``/teleop_turtle`` in this process); tests may hand the same app a link with fixed feeds.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.view.scene import Scene


class SimLink(Protocol):
    """The feeds the panes show and the way the teleop pane drives."""

    @property
    def master_uri(self) -> str:
        """The master other terminals attach to (their ``ROS_MASTER_URI``)."""
        ...

    @property
    def scenes(self) -> Feed[Scene]:
        """The pond, one scene per simulation tick."""
        ...

    @property
    def graph(self) -> Feed[Graph]:
        """The ROS graph, whenever it changes."""
        ...

    @property
    def logs(self) -> Feed[LogRecord]:
        """turtlesim's log lines."""
        ...

    @property
    def scales(self) -> tuple[float, float]:
        """The teleop's ``scale_linear`` and ``scale_angular``."""
        ...

    def drive(self, linear: float, angular: float) -> None:
        """Publish one command for turtle1: ``linear.x`` and ``angular.z``, all else 0."""
        ...
