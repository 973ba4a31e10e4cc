"""`LabApp`: ``rosx sim --robot``'s screen: the world, the teleop pane and the live panels.

Composition and key bindings only, as ``rosx sim``'s `SimApp`: `LabBody` lays the panes out
for the terminal's size (`rosx_turtle.view.layout.sim_layout`: the world column first, the side
column the rest), the link does the ROS side. Tab and Shift-Tab move the focus between the
panes; the focused pane is lit and owns the keys (teleop_twist_keyboard's in the teleop pane,
the arrows' in the tables). Enter on a topic or a node opens its details; Esc closes them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Container, Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.reactive import reactive  # noqa: TID253 - TUI code
from textual.widgets import Header, Static, TabbedContent, TabPane  # noqa: TID253 - TUI code

from rosx_turtle.stage.view.robot_panel import RobotPanel
from rosx_turtle.stage.view.status import RobotLine
from rosx_turtle.stage.view.twist_pad import TwistPad
from rosx_turtle.stage.view.widget import WorldView
from rosx_turtle.tui.details import DetailsScreen
from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.quit import QuitFooter
from rosx_turtle.tui.topics import TopicsPanel
from rosx_turtle.view.layout import SimLayout, sim_layout

if TYPE_CHECKING:
    from textual import events
    from textual.app import ComposeResult
    from textual.widgets import DataTable

    from rosx_turtle.stage.view.lab_link import LabLink

#: The body rows the side column needs to stack teleop (8), topics (at least 9), nodes (8)
#: and the robot (6).
STACKED_ROWS = 31
#: How long the start-up notice stays (long enough to read it and type the command).
_NOTICE_SECONDS = 30


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


class LabBody(Container):
    """The world and side columns, sized by `sim_layout` at each resize."""

    DEFAULT_CSS = """
    LabBody { height: 1fr; layout: vertical; }
    LabBody > #columns { height: 1fr; }
    LabBody #side { width: 1fr; }
    LabBody > #too-small {
        display: none;
        height: 1fr;
        width: 1fr;
        content-align: center middle;
        text-align: center;
    }
    LabBody.-too-small > #columns { display: none; }
    LabBody.-too-small > #too-small { display: block; }
    """

    def __init__(self, link: LabLink, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.link = link
        #: The layout in force (None before the first resize).
        self.layout_now: SimLayout | None = None

    def compose(self) -> ComposeResult:
        link = self.link
        assert link.world is not None and link.grid is not None
        with Horizontal(id="columns"):
            with Vertical(id="world"):
                yield WorldView(link.world, link.grid, link.steps, id="view")
                yield RobotLine(link.names, link.steps, id="robots")
                yield LogLine(link.logs, id="log")
            with Vertical(id="side"):
                yield TwistPad(link.drive, topic=link.drive_topic, id="teleop")
                yield LabPanels(link, id="panels")
        yield Static("", id="too-small", markup=False)

    def on_resize(self, event: events.Resize) -> None:
        self.lay_out(*self.app.size)

    def lay_out(self, width: int, height: int) -> None:
        """Size the columns for a terminal of ``width`` x ``height``."""
        layout = sim_layout(width, height)
        if layout == self.layout_now:
            return
        self.layout_now = layout
        self.set_class(layout.too_small, "-too-small")
        self.query_one("#too-small", Static).update(layout.message)
        self.query_one("#world", Vertical).styles.width = layout.world
        body = height - 2
        self.query_one(LabPanels).tabs = body < STACKED_ROWS


class LabApp(App[None]):
    """``rosx sim --robot``'s terminal UI over a `LabLink`."""

    TITLE = "rosx sim --robot"
    AUTO_FOCUS = "#teleop"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("tab", "focus_next", "Next pane", priority=True),
        Binding("shift+tab", "focus_previous", "Previous pane", show=False, priority=True),
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]

    def __init__(self, link: LabLink, *, notice: str | None = None) -> None:
        super().__init__()
        self.link = link
        self.notice = notice
        self.sub_title = f"ROS_MASTER_URI={link.master_uri}"

    def on_mount(self) -> None:
        if self.notice:
            self.notify(self.notice, timeout=_NOTICE_SECONDS)

    def compose(self) -> ComposeResult:
        yield Header(icon="◉")
        yield LabBody(self.link, id="body")
        yield QuitFooter()

    def on_data_table_row_selected(self, event: DataTable.RowSelected) -> None:
        """Enter on a topic or a node: its details."""
        kind = "topic" if isinstance(event.data_table, TopicsPanel) else None
        if isinstance(event.data_table, NodesPanel):
            kind = "node"
        name = event.row_key.value
        if kind is not None and name:
            event.stop()
            self.push_screen(DetailsScreen(self.link, kind, name))


def make_lab_app(link: LabLink, *, notice: str | None = None) -> LabApp:
    """``rosx sim --robot``'s terminal UI over ``link``, the teleop pane focused; ``notice``
    shown for a while when it starts (the factory the command and the tests share)."""
    return LabApp(link, notice=notice)
