"""`SimApp`: ``rosx sim``'s screen: the pond, the teleop pane and the live graph panels.

Composition and key bindings only; the panes do their own work, `SimBody` lays them out for the
terminal's size and the link does the ROS side. Tab and Shift-Tab move the focus between the
panes; the focused pane is lit and owns the keys (the arrow keys drive the turtle in the teleop
pane and move the cursor in the tables). Enter on a topic or a node opens its details
(`DetailsScreen`: ``rostopic info`` and echo, or ``rosnode info``); Esc closes them.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.widgets import Header  # noqa: TID253 - TUI code

from rosx_turtle.tui.details import DetailsScreen
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.quit import QuitFooter
from rosx_turtle.tui.sim_body import SimBody
from rosx_turtle.tui.topics import TopicsPanel

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult
    from textual.widgets import DataTable

    from rosx_turtle.tui.link import Details, SimLink


#: How long the start-up notice stays (long enough to read it and type the command).
_NOTICE_SECONDS = 30


class GraphScreenApp(App[None]):
    """What ``rosx sim``'s screens share: the keys (Tab between panes, ``q`` and Ctrl-C to
    quit), the master's URI under the title, a notice for a while, and Enter on a topic or a
    node for its details. Subclasses give the title and the body."""

    AUTO_FOCUS = "#teleop"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("tab", "focus_next", "Next pane", priority=True),
        Binding("shift+tab", "focus_previous", "Previous pane", show=False, priority=True),
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]

    def __init__(self, link: Details, *, notice: str | None = None) -> None:
        super().__init__()
        self.details = link
        self.notice = notice
        self.sub_title = f"ROS_MASTER_URI={link.master_uri}"

    def on_mount(self) -> None:
        """Show the start-up notice, if any, for `_NOTICE_SECONDS`."""
        if self.notice:
            self.notify(self.notice, timeout=_NOTICE_SECONDS)

    def on_data_table_row_selected(self, event: DataTable.RowSelected) -> None:
        """Enter on a topic or a node: its details."""
        kind = "topic" if isinstance(event.data_table, TopicsPanel) else None
        if isinstance(event.data_table, NodesPanel):
            kind = "node"
        name = event.row_key.value
        if kind is not None and name:
            event.stop()
            self.push_screen(DetailsScreen(self.details, kind, name))


class SimApp(GraphScreenApp):
    """``rosx sim``'s terminal UI over a `SimLink`."""

    TITLE = "rosx sim"

    def __init__(self, link: SimLink, *, notice: str | None = None) -> None:
        super().__init__(link, notice=notice)
        self.link = link

    @override
    def compose(self) -> ComposeResult:
        yield Header(icon="≈")
        yield SimBody(self.link, id="body")
        yield QuitFooter()
