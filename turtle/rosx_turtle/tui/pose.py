"""`PosePanel`: the latest pose of one turtle, as ``rostopic echo /turtle1/pose`` prints it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows
from rosx_turtle.view.status import pose_echo

if TYPE_CHECKING:
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.scene import Scene


class PosePanel(Follows["Scene"], Static):
    """The pose of turtle ``turtle`` in each scene (what it publishes on ``<turtle>/pose``)."""

    DEFAULT_CSS = """
    PosePanel {
        height: 7;
        padding: 0 1;
        border: round $panel-lighten-2;
        border-title-color: $text-muted;
    }
    """

    def __init__(
        self, feed: Feed[Scene] | None = None, *, turtle: str = "turtle1", id: str | None = None
    ) -> None:
        super().__init__("", id=id, markup=False)
        self.feed = feed
        self.turtle = turtle
        self.text = ""
        self.border_title = f"/{turtle}/pose"

    def show(self, value: Scene) -> None:
        """Show the pose of the turtle in scene ``value``, or that there is no such turtle."""
        pose = next((t for t in value.turtles if t.name == self.turtle), None)
        text = pose_echo(pose) if pose is not None else f"no turtle named {self.turtle}"
        if text != self.text:
            self.text = text
            self.update(text)
