r"""`GraphTable`: a table of the ROS graph that refills itself from a `Feed` of `Graph`\ s."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.widgets import DataTable  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows

if TYPE_CHECKING:
    from collections.abc import Iterable

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.graph import Graph


class GraphTable(Follows["Graph"], DataTable[str]):
    """Rows from each new graph; subclasses name the `COLUMNS` and give the `rows_of` a graph."""

    COLUMNS: tuple[str, ...] = ()
    #: What the rows are, for the count under the table ("3 nodes").
    NOUN = "rows"

    DEFAULT_CSS = """
    GraphTable {
        border: round $panel-lighten-2;
        border-title-color: $text-muted;
        &:focus { border: heavy $accent; border-title-color: $accent; }
    }
    """

    def __init__(
        self, title: str, feed: Feed[Graph] | None = None, *, id: str | None = None
    ) -> None:
        super().__init__(id=id, cursor_type="row")
        self.feed = feed
        self.border_title = title
        self.graph: Graph | None = None

    def on_mount(self) -> None:
        """Add the columns (`Follows.on_mount` runs too and starts the feed)."""
        self.add_columns(*self.COLUMNS)

    def rows_of(self, graph: Graph) -> Iterable[tuple[str, ...]]:
        """The table's rows for ``graph``; the first cell is the row's key."""
        raise NotImplementedError

    def show(self, value: Graph) -> None:
        """Refill the table from ``value`` (the cursor stays on the same row number)."""
        if value == self.graph:
            return
        self.graph = value
        cursor = self.cursor_row
        self.clear()
        if value.error:
            self.border_subtitle = "master unreachable"
            return
        rows = list(self.rows_of(value))
        for row in rows:
            self.add_row(*row, key=row[0])
        self.border_subtitle = f"{len(rows)} {self.NOUN}"
        if rows:
            self.move_cursor(row=min(cursor, len(rows) - 1))
