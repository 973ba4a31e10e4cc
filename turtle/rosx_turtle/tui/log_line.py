"""`LogLine`: the latest of the simulator's log lines, coloured by severity."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rich.text import Text
from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx.node import ERROR, WARN
from rosx_turtle.tui.feed import Follows

if TYPE_CHECKING:
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.log import LogRecord


class LogLine(Follows["LogRecord"], Static):
    """The newest record `feed` offers: warnings in yellow, errors in red."""

    DEFAULT_CSS = """
    LogLine {
        height: 1;
        width: 1fr;
        padding: 0 1;
        background: $panel;
        color: $text-muted;
    }
    """

    def __init__(self, feed: Feed[LogRecord] | None = None, *, id: str | None = None) -> None:
        super().__init__("", id=id, markup=False)
        self.feed = feed
        self.record: LogRecord | None = None

    def show(self, value: LogRecord) -> None:
        """Show record ``value``."""
        if value == self.record:
            return
        self.record = value
        style = "bold red" if value.level >= ERROR else "yellow" if value.level >= WARN else ""
        self.update(Text(str(value), style=style, no_wrap=True, overflow="ellipsis"))
