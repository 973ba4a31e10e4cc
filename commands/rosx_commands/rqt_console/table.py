"""`LogTable`: the shown entries as a table that draws only the rows on screen.

A table widget that keeps a row object per entry (textual's ``DataTable``) slows down with tens
of thousands of rows; this one keeps nothing per row. Its height is the number of shown entries
(`Log.shown_count`), and each visible line is cut from its entry when painted (textual's line
API), so scrolling, filtering and adding rows cost the rows on screen, whatever the log's size.

The cursor row is the selected entry. While the cursor is on the last row (or there is none)
the table follows new entries, as a terminal follows its output; moving the cursor up stops
that, ``end`` resumes it.
"""

from __future__ import annotations

import sys
from typing import ClassVar

from rich.segment import Segment
from rich.style import Style
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.geometry import Size  # noqa: TID253 - TUI code
from textual.message import Message  # noqa: TID253 - TUI code
from textual.scroll_view import ScrollView  # noqa: TID253 - TUI code
from textual.strip import Strip  # noqa: TID253 - TUI code

from rosx_commands.rqt_console.model import Entry, Log, Rules, clock_text

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

SEVERITY_STYLES = {
    1: Style(color="bright_black"),
    2: Style(),
    4: Style(color="yellow"),
    8: Style(color="red"),
    16: Style(color="red", bold=True),
}
HIGHLIGHT = Style(bgcolor="dark_blue", bold=True)
CURSOR = Style(reverse=True)
HEADER = Style(bold=True, underline=True)

#: Columns and their widths; the message takes what is left. Topics and location only show
#: where the terminal is wide enough for them.
FIXED = (("Time", 12), ("Severity", 8), ("Node", 16))
WIDE = (("Topics", 20), ("Location", 22))
#: The table width from which the topics and location columns show (a 120-column terminal
#: less the scroll bar).
WIDE_FROM = 110


def columns(width: int) -> list[tuple[str, int]]:
    """The columns and their widths for a table ``width`` cells wide (one space between)."""
    chosen = list(FIXED)
    extra = list(WIDE) if width >= WIDE_FROM else []
    used = sum(w for _, w in chosen + extra) + len(chosen) + len(extra)
    message = max(10, width - used)
    return [*chosen, ("Message", message), *extra]


def _cell(text: str, width: int) -> str:
    if len(text) > width:
        return text[: max(0, width - 1)] + "…"
    return text.ljust(width)


def row_text(entry: Entry, width: int) -> str:
    """``entry`` as one line of the table, ``width`` cells wide."""
    message = entry.message.replace("\n", "⏎")
    if entry.count > 1:
        message = f"({entry.count} times) {message}"
    values = {
        "Time": clock_text(entry.stamp),
        "Severity": entry.severity,
        "Node": entry.node,
        "Message": message,
        "Topics": ", ".join(entry.topics),
        "Location": entry.location,
    }
    return " ".join(_cell(values[name], w) for name, w in columns(width))[:width].ljust(width)


def header_text(width: int) -> str:
    """The table's header row, ``width`` columns wide."""
    return " ".join(_cell(name, w) for name, w in columns(width))[:width].ljust(width)


class LogTable(ScrollView, can_focus=True):
    """The rows of a `Log` (see the module docstring)."""

    DEFAULT_CSS = "LogTable { height: 1fr; }"
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("up", "move(-1)", "Up", show=False),
        Binding("down", "move(1)", "Down", show=False),
        Binding("pageup", "move(-20)", show=False),
        Binding("pagedown", "move(20)", show=False),
        Binding("home", "first", show=False),
        Binding("end", "last", show=False),
    ]

    class Selected(Message):
        """The cursor moved to ``row`` (None: no row)."""

        def __init__(self, row: int | None) -> None:
            super().__init__()
            self.row = row

    def __init__(self, log: Log, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.entries = log
        self.cursor: int | None = None
        self.follow = True

    @property
    def rules(self) -> Rules:
        """The rules in force (the log's)."""
        return self.entries.rules

    def refresh_rows(self) -> None:
        """The log changed: resize, keep the cursor in range, follow the tail."""
        count = self.entries.shown_count
        self.virtual_size = Size(self.size.width, count + 1)
        if self.cursor is not None and self.cursor >= count:
            self.cursor = count - 1 if count else None
            self.post_message(self.Selected(self.cursor))
        if self.follow:
            self.call_after_refresh(self._follow)
        self.refresh()

    def _follow(self) -> None:
        if self.follow:
            self.scroll_end(animate=False, immediate=True, x_axis=False)

    def on_resize(self) -> None:
        """Fit the scroll area to the new size, keeping the cursor in range."""
        self.refresh_rows()

    def select(self, row: int | None) -> None:
        """Put the cursor on ``row`` (clamped; None clears it), scroll it into view and post
        `Selected`; the table follows new entries while the cursor is on the last row or none."""
        count = self.entries.shown_count
        if row is not None:
            row = min(max(row, 0), count - 1) if count else None
        self.cursor = row
        self.follow = row is None or row == count - 1
        if row is not None:
            height = self.scrollable_content_region.height - 1
            top = self.scroll_offset.y
            if row < top:
                self.scroll_to(y=row, animate=False, immediate=True)
            elif row >= top + height:
                self.scroll_to(y=row - height + 1, animate=False, immediate=True)
        self.refresh()
        self.post_message(self.Selected(row))

    def action_move(self, step: int) -> None:
        """Up/Down/PageUp/PageDown: move the cursor ``step`` rows; with no cursor, start at an
        end."""
        if self.cursor is None:
            self.select(self.entries.shown_count - 1 if step < 0 else 0)
        else:
            self.select(self.cursor + step)

    def action_first(self) -> None:
        """Home: select the first row."""
        self.select(0)

    def action_last(self) -> None:
        """End: select the last row (and follow new entries)."""
        self.select(self.entries.shown_count - 1)

    def visible_text(self) -> list[str]:
        """The characters on screen, row by row (for tests)."""
        height = self.scrollable_content_region.height
        return [self.render_line(y).text.rstrip() for y in range(height)]

    @override
    def render_line(self, y: int) -> Strip:
        width = self.scrollable_content_region.width
        base = self.rich_style
        if y == 0:
            return Strip([Segment(header_text(width), base + HEADER)], width)
        row = self.scroll_offset.y + y - 1
        log = self.entries
        if row >= log.shown_count:
            return Strip.blank(width, base)
        entry = log.shown(row)
        style = base + SEVERITY_STYLES.get(entry.level, Style())
        if log.rules.highlights(entry):
            style += HIGHLIGHT
        if row == self.cursor:
            style += CURSOR
        return Strip([Segment(row_text(entry, width), style)], width)
