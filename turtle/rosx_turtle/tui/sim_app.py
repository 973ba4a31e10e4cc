"""`SimApp`: ``rosx sim``'s screen: the pond, the teleop pane and the live graph panels.

Composition and key bindings only; the panes do their own work and the link does the ROS side.
Tab and Shift-Tab move the focus between the panes; the focused pane is lit and owns the keys
(the arrow keys drive the turtle in the teleop pane and move the cursor in the tables).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.widgets import Header  # noqa: TID253 - TUI code

from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.pose import PosePanel
from rosx_turtle.tui.quit import QuitFooter
from rosx_turtle.tui.status import PoseLine
from rosx_turtle.tui.teleop import TeleopPad
from rosx_turtle.tui.topics import TopicsPanel

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_turtle.tui.link import SimLink


class SimApp(App[None]):
    """``rosx sim``'s terminal UI over a `SimLink`."""

    TITLE = "rosx sim"
    AUTO_FOCUS = "#teleop"
    ENABLE_COMMAND_PALETTE = False
    CSS = """
    #body { height: 1fr; }
    #world { width: 1fr; }
    #side { width: 58; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("tab", "focus_next", "Next pane", priority=True),
        Binding("shift+tab", "focus_previous", "Previous pane", show=False, priority=True),
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]

    def __init__(self, link: SimLink) -> None:
        super().__init__()
        self.link = link
        self.sub_title = f"ROS_MASTER_URI={link.master_uri}"

    def compose(self) -> ComposeResult:
        link = self.link
        scale_linear, scale_angular = link.scales
        yield Header(icon="≈")
        with Horizontal(id="body"):
            with Vertical(id="world"):
                yield PondView(link.scenes, id="pond")
                yield PoseLine(link.scenes, id="poses")
                yield LogLine(link.logs, id="log")
            with Vertical(id="side"):
                yield TeleopPad(
                    link.drive, scale_linear=scale_linear, scale_angular=scale_angular, id="teleop"
                )
                yield TopicsPanel(link.graph, id="topics")
                yield NodesPanel(link.graph, id="nodes")
                yield PosePanel(link.scenes, id="pose")
        yield QuitFooter()
