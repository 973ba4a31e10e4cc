"""`LabLink`: what the robot lab's screen needs from the ROS side, and nothing more.

`rosx_turtle.stage.lab.host.LabHost` is the real one; tests may hand the same app a link
with fixed feeds.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

from rosx_turtle.tui.link import Details

if TYPE_CHECKING:
    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.world.model import World
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph
    from rosx_turtle.tui.log import LogRecord


class LabLink(Details, Protocol):
    """The world, the feeds the panes show, the topics the robot pane names, and the way the
    teleop pane drives."""

    @property
    def world(self) -> World | None:
        """The simulated world (None before it is loaded)."""
        ...

    @property
    def grid(self) -> Grid | None:
        """The world's occupancy grid (None before it is loaded)."""
        ...

    @property
    def names(self) -> tuple[str, ...]:
        """The robots' names."""
        ...

    @property
    def steps(self) -> Feed[StepReport]:
        """The simulation after each step."""
        ...

    @property
    def graph(self) -> Feed[Graph]:
        """The ROS graph, whenever it changes."""
        ...

    @property
    def logs(self) -> Feed[LogRecord]:
        """The nodes' log lines."""
        ...

    @property
    def drive_topic(self) -> str:
        """The ``cmd_vel`` the teleop publishes on."""
        ...

    @property
    def odom_topic(self) -> str:
        """The driven robot's odometry topic."""
        ...

    @property
    def scan_topic(self) -> str:
        """The driven robot's laser topic."""
        ...

    def drive(self, linear_x: float, linear_y: float, linear_z: float, angular_z: float) -> None:
        """Publish one Twist on `drive_topic`."""
        ...
