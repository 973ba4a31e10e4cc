"""`SimLink`: what the sim's terminal UI needs from the ROS side, and nothing more.

`Details` is the part the details screen asks of any host (the robot lab's too).
`rosx_turtle.sim.host.SimHost` is the real `SimLink` (a master, ``/rosout``, ``/turtlesim`` and
``/teleop_turtle`` in this process); tests may hand the same app a link with fixed feeds.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.view.scene import Scene


class Details(Protocol):
    """The master, and the details of a topic or node that Enter on a row of the graph panels
    shows."""

    @property
    def master_uri(self) -> str:
        """The master other terminals attach to (their ``ROS_MASTER_URI``)."""
        ...

    def describe_topic(self, topic: str) -> str:
        """What ``rostopic info TOPIC`` prints (may block: called from a worker thread)."""
        ...

    def describe_node(self, node: str) -> str:
        """What ``rosnode info NODE`` prints (may block: called from a worker thread)."""
        ...

    def echo(self, topic: str, offer: Callable[[str], object]) -> Callable[[], None]:
        """Call ``offer(text)`` with each message of ``topic`` as ``rostopic echo`` prints it,
        from any thread, until the returned function is called (may block: a worker thread)."""
        ...


class SimLink(Details, Protocol):
    """The feeds the panes show, the way the teleop pane drives, and the details of a topic
    or node."""

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
