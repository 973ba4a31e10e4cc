"""How ``rosx sim``'s screen shares a terminal: the pond first, the panels in what is left.

The screen is a header row, a body and a footer row. The body holds the world column (the pond,
then a pose line and a log line) beside the side column (the teleop pane, then the graph
panels). The pond is square (`fit.fit_square`: ``side`` columns take ``side / 2`` rows), so its
width follows from the body's height; it takes that much first, leaving the side column at least
`SIDE_MIN` columns, and never more than `SIDE_MAX` (past that the pond only gains margins). The
panels are stacked when the side column is tall enough for all of them, else folded into tabs.
Below `MIN_SIZE` nothing useful fits, and the screen says which size it needs.
"""

from __future__ import annotations

from dataclasses import dataclass

#: Rows of the screen besides the body: the header and the footer.
CHROME_ROWS = 2
#: Rows of the world column besides the pond: the pose line and the log line.
WORLD_LINES = 2
#: The side column's narrowest and widest (the teleop pane's lines fit in the narrowest).
SIDE_MIN = 40
SIDE_MAX = 64
#: The body rows the side column needs to stack teleop (5), topics (at least 9), nodes (8) and
#: the pose (7).
STACKED_ROWS = 29
#: The smallest pond drawn, in columns (half as many rows).
POND_MIN = 20
#: The smallest terminal (columns, rows) the screen is drawn in: the smallest pond beside the
#: narrowest side column, and the teleop pane above a tab bar and a few rows of a panel.
MIN_SIZE = (POND_MIN + SIDE_MIN, CHROME_ROWS + max(POND_MIN // 2 + WORLD_LINES, 5 + 2 + 5))


@dataclass(frozen=True)
class SimLayout:
    """Where things go in a terminal of ``width`` x ``height`` cells.

    Attributes:
        width: The terminal's columns.
        height: The terminal's rows.
        world: The world column's width (the pond's side is at most this, even).
        side: The side column's width.
        tabs: Whether the graph panels are folded into tabs (else stacked).
    """

    width: int
    height: int
    world: int
    side: int
    tabs: bool

    @property
    def too_small(self) -> bool:
        """Whether the terminal is below `MIN_SIZE` (nothing but a message is drawn)."""
        return self.width < MIN_SIZE[0] or self.height < MIN_SIZE[1]

    @property
    def message(self) -> str:
        """What a terminal below `MIN_SIZE` shows instead of the screen."""
        need_w, need_h = MIN_SIZE
        return (
            f"rosx sim needs at least {need_w}x{need_h}; "
            f"this terminal is {self.width}x{self.height}"
        )


def sim_layout(width: int, height: int) -> SimLayout:
    """The layout of ``rosx sim``'s screen in a terminal of ``width`` x ``height`` cells."""
    body = max(height - CHROME_ROWS, 0)
    pond = 2 * max(body - WORLD_LINES, 0)
    world = min(pond, width - SIDE_MIN)
    world = max(world, width - SIDE_MAX, 0)
    world -= world % 2
    return SimLayout(width, height, world, width - world, tabs=body < STACKED_ROWS)
