"""`SimBody`: ``rosx sim``'s screen between header and footer, laid out for the terminal's size.

The sizes come from `rosx_turtle.view.layout.sim_layout`: the world column (pond, pose line, log
line) gets the pond's width first, the side column (teleop pane, graph panels) the rest. The
graph panels (`GraphPanels`) are stacked where the side column is tall enough, else folded into
tabs. In a terminal too small for any of it, the body shows which size it needs instead.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from textual.containers import Container, Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.reactive import reactive  # noqa: TID253 - TUI code
from textual.widgets import Static, TabbedContent, TabPane  # noqa: TID253 - TUI code

from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.pose import PosePanel
from rosx_turtle.tui.status import PoseLine
from rosx_turtle.tui.teleop import TeleopPad
from rosx_turtle.tui.topics import TopicsPanel
from rosx_turtle.view.layout import SimLayout, sim_layout

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual import events
    from textual.app import ComposeResult

    from rosx_turtle.tui.link import SimLink


class GraphPanels(Vertical):
    """The topics, nodes and pose panels: stacked, or (``tabs``) one at a time under tabs."""

    DEFAULT_CSS = """
    GraphPanels { height: 1fr; }
    GraphPanels TabbedContent { height: 1fr; }
    GraphPanels TabPane { padding: 0; height: 1fr; }
    GraphPanels TabPane > * { height: 1fr; }
    """

    tabs: reactive[bool] = reactive(False, recompose=True)

    def __init__(self, link: SimLink, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.link = link

    @override
    def compose(self) -> ComposeResult:
        link = self.link
        if not self.tabs:
            yield TopicsPanel(link.graph, id="topics")
            yield NodesPanel(link.graph, id="nodes")
            yield PosePanel(link.scenes, id="pose")
            return
        with TabbedContent():
            with TabPane("Topics", id="tab-topics"):
                yield TopicsPanel(link.graph, id="topics")
            with TabPane("Nodes", id="tab-nodes"):
                yield NodesPanel(link.graph, id="nodes")
            with TabPane("Pose", id="tab-pose"):
                yield PosePanel(link.scenes, id="pose")


class Columns(Container):
    """A world column beside a side column, sized by `sim_layout` at each resize, and in a
    terminal too small for them the size it needs. Subclasses give the columns' widgets
    (`world_column`, `side_column`) and fold their panels into tabs where they must (`fold`)."""

    DEFAULT_CSS = """
    Columns { height: 1fr; layout: vertical; }
    Columns > #columns { height: 1fr; }
    Columns #side { width: 1fr; }
    Columns > #too-small {
        display: none;
        height: 1fr;
        width: 1fr;
        content-align: center middle;
        text-align: center;
    }
    Columns.-too-small > #columns { display: none; }
    Columns.-too-small > #too-small { display: block; }
    """

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        #: The layout in force (None before the first resize).
        self.layout_now: SimLayout | None = None

    @override
    def compose(self) -> ComposeResult:
        with Horizontal(id="columns"):
            with Vertical(id="world"):
                yield from self.world_column()
            with Vertical(id="side"):
                yield from self.side_column()
        yield Static("", id="too-small", markup=False)

    def world_column(self) -> ComposeResult:
        """The world column's widgets, top to bottom."""
        raise NotImplementedError

    def side_column(self) -> ComposeResult:
        """The side column's widgets, top to bottom."""
        raise NotImplementedError

    def fold(self, layout: SimLayout) -> None:
        """Stack or fold the side column's panels for ``layout``."""
        raise NotImplementedError

    def on_resize(self, event: events.Resize) -> None:
        """Lay the columns out again for the terminal's new size."""
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
        self.fold(layout)


class SimBody(Columns):
    """The pond, its pose and log lines beside the teleop pane and the graph panels."""

    def __init__(self, link: SimLink, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.link = link

    @override
    def world_column(self) -> ComposeResult:
        link = self.link
        yield PondView(link.scenes, id="pond")
        yield PoseLine(link.scenes, id="poses")
        yield LogLine(link.logs, id="log")

    @override
    def side_column(self) -> ComposeResult:
        link = self.link
        scale_linear, scale_angular = link.scales
        yield TeleopPad(
            link.drive, scale_linear=scale_linear, scale_angular=scale_angular, id="teleop"
        )
        yield GraphPanels(link, id="panels")

    @override
    def fold(self, layout: SimLayout) -> None:
        self.query_one(GraphPanels).tabs = layout.tabs
