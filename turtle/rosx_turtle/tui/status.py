"""`PoseLine`: one line under the pond with every turtle's pose, updated as the turtles move."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows
from rosx_turtle.view.status import status_text

if TYPE_CHECKING:
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.scene import Scene


class PoseLine(Follows["Scene"], Static):
    """Each turtle's name, heading arrow, x, y and theta, from the scenes `feed` offers."""

    DEFAULT_CSS = """
    PoseLine {
        height: 1;
        width: 1fr;
        padding: 0 1;
        background: $panel;
        color: $text;
    }
    """

    def __init__(
        self,
        feed: Feed[Scene] | None = None,
        *,
        id: str | None = None,
    ) -> None:
        super().__init__("", id=id, markup=False)
        self.feed = feed
        self.text = ""

    def show(self, value: Scene) -> None:
        """Show the poses in scene ``value`` (nothing is redrawn if the text is the same)."""
        text = status_text(value.turtles)
        if text != self.text:
            self.text = text
            self.update(text)
