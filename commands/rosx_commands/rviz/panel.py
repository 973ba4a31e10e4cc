"""`DisplaysPanel`: rviz's Displays panel as text: the fixed frame, then each display in three
rows: its number (the key that shows or hides it) and config Name, its topic, its status in
rviz's words. A click on a display shows or hides it too.

`panel_lines` is the text, pure, so tests read exactly what a user sees.
"""

from __future__ import annotations

import textwrap
from typing import TYPE_CHECKING

from rich.text import Text
from textual.message import Message  # noqa: TID253 - TUI code
from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_commands.rviz.status import Level

if TYPE_CHECKING:
    from textual import events

    from rosx_commands.rviz.displays.base import Display
    from rosx_commands.rviz.manager import Manager

#: How each status level is marked and coloured.
MARKS = {Level.OK: ("✓", "green"), Level.WARN: ("⚠", "yellow"), Level.ERROR: ("✗", "red")}


def _cut(text: str, width: int) -> str:
    return text if len(text) <= width else text[: max(0, width - 1)] + "…"


def display_lines(number: int, display: Display, width: int) -> list[tuple[str, str]]:
    """A display's three rows (text and style), ``width`` columns wide."""
    key = str(number) if number <= 9 else " "
    box = "■" if display.enabled else "□"
    head = f"{key} {box} {display.name}"
    where = display.topic or display.class_id
    mark, colour = MARKS[display.level]
    status = f"{mark} {display.summary}" if display.enabled else f"  {display.summary}"
    style = colour if display.enabled else "dim"
    wrapped = textwrap.wrap(status, max(1, width - 2)) or [""]
    if len(wrapped) == 1:
        rows = [head, "  " + where, "  " + wrapped[0]]
    else:
        rows = [f"{head}  {where}", *("  " + line for line in wrapped[:2])]
    styles = ["bold" if display.enabled else "dim", "dim", style, style]
    return [(_cut(row, width), styles[min(i, 3)]) for i, row in enumerate(rows)]


def panel_lines(manager: Manager, width: int, follow: str | None = None) -> list[tuple[str, str]]:
    """The panel's rows: the fixed frame (and its problem), the target frame when following,
    then every display."""
    with manager.lock:
        rows = [(_cut(f"Fixed Frame: {manager.fixed_frame}", width), "bold")]
        problem = manager.fixed_frame_problem()
        if problem is not None:
            rows.extend(("  " + line, "red") for line in textwrap.wrap(problem, width - 2))
        if follow is not None:
            rows.append((_cut(f"Target Frame: {follow}", width), ""))
        rows.append(("─" * width, "dim"))
        for number, display in enumerate(manager.displays, 1):
            rows.extend(display_lines(number, display, width))
        return rows


class DisplaysPanel(Static):
    """The panel (see the module docstring); `update_from` refreshes it."""

    DEFAULT_CSS = """
    DisplaysPanel { width: 30; height: 1fr; padding: 0 0 0 1; background: $panel; }
    """

    class Toggle(Message):
        """The user clicked display ``index``."""

        def __init__(self, index: int) -> None:
            super().__init__()
            self.index = index

    def __init__(self, manager: Manager, *, id: str | None = None) -> None:
        super().__init__("", id=id, markup=False)
        self.manager = manager
        self.follow: str | None = None
        self.lines: list[tuple[str, str]] = []
        self._starts: list[int] = []

    def on_mount(self) -> None:
        """Show the displays."""
        self.update_from()

    def on_resize(self) -> None:
        """Re-wrap the displays' lines for the new width."""
        self.update_from()

    def update_from(self) -> None:
        """Show the manager's displays as they are now (only when the text changed)."""
        width = max(8, self.size.width - 1)
        lines = panel_lines(self.manager, width, self.follow)
        if lines == self.lines:
            return
        self.lines = lines
        top = next(i for i, (text, _) in enumerate(lines) if text.startswith("─")) + 1
        self._starts = [top + 3 * i for i in range(len(self.manager.displays))]
        text = Text()
        for i, (line, style) in enumerate(lines):
            if i:
                text.append("\n")
            text.append(line, style=style)
        self.update(text)

    def on_click(self, event: events.Click) -> None:
        """A click on a display's lines posts `Toggle` for it."""
        for index, start in enumerate(self._starts):
            if start <= event.y < start + 3:
                self.post_message(self.Toggle(index))
                return


__all__ = ["DisplaysPanel", "display_lines", "panel_lines"]
