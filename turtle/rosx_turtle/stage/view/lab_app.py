"""`LabApp`: ``rosx sim --robot``'s screen: the world, the teleop pane and the live panels.

Composition only, on what ``rosx sim``'s screen has (`GraphScreenApp`: the keys, the notice,
the details; `Columns`: the world column first, the side column the rest, sized by
`rosx_turtle.view.layout.sim_layout`); the link does the ROS side. Tab and Shift-Tab move
the focus between the panes; the focused pane is lit and owns the keys (teleop_twist_keyboard's
in the teleop pane, the arrows' in the tables). Enter on a topic or a node opens its details;
Esc closes them.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from textual.containers import Vertical  # noqa: TID253 - TUI code
from textual.reactive import reactive  # noqa: TID253 - TUI code
from textual.widgets import Header, TabbedContent, TabPane  # noqa: TID253 - TUI code

from rosx_turtle.stage.view.robot_panel import RobotPanel
from rosx_turtle.stage.view.status import RobotLine
from rosx_turtle.stage.view.twist_pad import TwistPad
from rosx_turtle.stage.view.widget import WorldView
from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.quit import QuitFooter
from rosx_turtle.tui.sim_app import GraphScreenApp
from rosx_turtle.tui.sim_body import Columns
from rosx_turtle.tui.topics import TopicsPanel
from rosx_turtle.view.layout import CHROME_ROWS

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_turtle.stage.view.lab_link import LabLink
    from rosx_turtle.view.layout import SimLayout

#: The body rows the side column needs to stack teleop (8), topics (at least 9), nodes (8)
#: and the robot (6).
STACKED_ROWS = 31


class LabPanels(Vertical):
    """The topics, nodes and robot panels: stacked, or (``tabs``) one at a time under tabs."""

    DEFAULT_CSS = """
    LabPanels { height: 1fr; }
    LabPanels TabbedContent { height: 1fr; }
    LabPanels TabPane { padding: 0; height: 1fr; }
    LabPanels TabPane > * { height: 1fr; }
    """

    tabs: reactive[bool] = reactive(False, recompose=True)

    def __init__(self, link: LabLink, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.link = link

    def _robot(self) -> RobotPanel:
        link = self.link
        title = f"Robot: {link.names[0]}" if link.names else "Robot"
        return RobotPanel(
            link.steps, odom=link.odom_topic, scan_topic=link.scan_topic, title=title, id="robot"
        )

    @override
    def compose(self) -> ComposeResult:
        link = self.link
        if not self.tabs:
            yield TopicsPanel(link.graph, id="topics")
            yield NodesPanel(link.graph, id="nodes")
            yield self._robot()
            return
        with TabbedContent():
            with TabPane("Robot", id="tab-robot"):
                yield self._robot()
            with TabPane("Topics", id="tab-topics"):
                yield TopicsPanel(link.graph, id="topics")
            with TabPane("Nodes", id="tab-nodes"):
                yield NodesPanel(link.graph, id="nodes")


class LabBody(Columns):
    """The world, the robots' line and the log line beside the teleop pane and the panels."""

    def __init__(self, link: LabLink, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.link = link

    @override
    def world_column(self) -> ComposeResult:
        link = self.link
        assert link.world is not None and link.grid is not None
        yield WorldView(link.world, link.grid, link.steps, id="view")
        yield RobotLine(link.names, link.steps, id="robots")
        yield LogLine(link.logs, id="log")

    @override
    def side_column(self) -> ComposeResult:
        yield TwistPad(self.link.drive, topic=self.link.drive_topic, id="teleop")
        yield LabPanels(self.link, id="panels")

    @override
    def fold(self, layout: SimLayout) -> None:
        self.query_one(LabPanels).tabs = layout.height - CHROME_ROWS < STACKED_ROWS


class LabApp(GraphScreenApp):
    """``rosx sim --robot``'s terminal UI over a `LabLink`."""

    TITLE = "rosx sim --robot"

    def __init__(self, link: LabLink, *, notice: str | None = None) -> None:
        super().__init__(link, notice=notice)
        self.link = link

    @override
    def compose(self) -> ComposeResult:
        yield Header(icon="◉")
        yield LabBody(self.link, id="body")
        yield QuitFooter()


def make_lab_app(link: LabLink, *, notice: str | None = None) -> LabApp:
    """``rosx sim --robot``'s terminal UI over ``link``, the teleop pane focused; ``notice``
    shown for a while when it starts (the factory the command and the tests share)."""
    return LabApp(link, notice=notice)
