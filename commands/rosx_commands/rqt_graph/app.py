"""`GraphApp`: rqt_graph in the terminal: the drawing, a details panel, a status line.

A timer starts a refresh on a worker thread every period (and ``r`` at once); the worker
fetches, builds and draws, and hands the result to the UI with ``call_from_thread``. ``tab`` /
``shift+tab`` select the next / previous node or topic, whose ``rosnode info`` /
``rostopic info`` (and a topic's live rate) show on the right; ``m`` cycles the modes, ``d``
toggles hiding debug names, ``q`` quits.
"""

from __future__ import annotations

import dataclasses
from typing import Any, ClassVar

from rich.text import Text
from textual.app import App, ComposeResult  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, VerticalScroll  # noqa: TID253 - TUI code
from textual.widgets import Footer, Static  # noqa: TID253 - TUI code

from rosx.graph.builder import build
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.text import Drawing, draw
from rosx.graph.view import Changes, Kind, ViewGraph, changes
from rosx_commands.rqt_graph.source import GraphSource
from rosx_commands.rqt_graph.view import GraphView

_MODES = list(Mode)


class GraphApp(App[int]):
    CSS = """
    #details { width: 48; border-left: solid $primary; padding: 0 1; }
    #status { height: 1; background: $boost; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("r", "refresh_graph", "Refresh"),
        Binding("tab", "select(1)", "Next", priority=True),
        Binding("shift+tab", "select(-1)", "Previous", priority=True),
        Binding("m", "next_mode", "Mode"),
        Binding("d", "toggle_debug", "Debug"),
        Binding("q", "quit", "Quit"),
    ]

    def __init__(
        self, source: GraphSource, options: GraphOptions, period: float | None = None
    ) -> None:
        super().__init__()
        self.source = source
        self.options = options
        self.period = period
        self.graph: ViewGraph | None = None
        self.drawing = Drawing()
        self.changes = Changes()
        self.selected: str | None = None
        self.error: str | None = None

    def compose(self) -> ComposeResult:
        yield Static(id="status")
        with Horizontal():
            yield GraphView(id="graph")
            with VerticalScroll(id="details"):
                yield Static("Select a node or topic with tab.", id="info")
        yield Footer()

    def on_mount(self) -> None:
        self.action_refresh_graph()
        if self.period:
            self.set_interval(self.period, self.action_refresh_graph)

    def action_refresh_graph(self) -> None:
        self.run_worker(self._refresh, thread=True, exclusive=True, group="refresh")

    def _refresh(self) -> None:
        options = self.options
        try:
            graph = build(self.source.snapshot(), options)
        except Exception as error:
            self.call_from_thread(self._failed, str(error) or type(error).__name__)
            return
        drawing = draw(graph)
        self.call_from_thread(self._show, graph, drawing, options)

    def _failed(self, message: str) -> None:
        self.error = message
        self._status()

    def _show(self, graph: ViewGraph, drawing: Drawing, options: GraphOptions) -> None:
        if options != self.options:
            return  # drawn for options changed since; a newer refresh is on its way
        self.changes = changes(self.graph, graph) or self.changes if self.graph else Changes()
        self.graph, self.drawing, self.error = graph, drawing, None
        if self.selected not in drawing.boxes:
            self.selected = None
        self._status()
        self.query_one(GraphView).show(drawing, self.changes, self.selected)
        self._details()

    def _status(self) -> None:
        graph = self.graph or ViewGraph()
        nodes = sum(v.kind is Kind.NODE for v in graph.vertices)
        topics = len(graph.vertices) - nodes
        text = f" {self.options.mode.caption} │ {nodes} nodes, {topics} topics"
        if self.changes:
            text += f" │ changed: {self.changes.summary()}"
        if self.error:
            text += f" │ ERROR: {self.error}"
        self.query_one("#status", Static).update(Text(text))

    def action_select(self, step: int) -> None:
        order = sorted(
            self.drawing.boxes, key=lambda i: (self.drawing.boxes[i].x, self.drawing.boxes[i].y)
        )
        if not order:
            return
        index = order.index(self.selected) + step if self.selected in order else 0
        self.selected = order[index % len(order)]
        self.query_one(GraphView).show(self.drawing, self.changes, self.selected)
        self._details()

    def _details(self) -> None:
        vertex = self.graph.vertex(self.selected) if self.graph and self.selected else None
        if vertex is None:
            return
        self.run_worker(lambda: self._describe(vertex), thread=True, exclusive=True, group="info")

    def _describe(self, vertex: Any) -> None:
        text = self.source.describe(vertex)
        if vertex.kind is Kind.TOPIC:
            text += "\n" + self.source.rate(vertex.label)
        self.call_from_thread(self._show_details, vertex.id, text)

    def _show_details(self, vertex_id: str, text: str) -> None:
        if vertex_id == self.selected:
            self.query_one("#info", Static).update(Text(text))

    def action_next_mode(self) -> None:
        mode = _MODES[(_MODES.index(self.options.mode) + 1) % len(_MODES)]
        self._set_options(dataclasses.replace(self.options, mode=mode))

    def action_toggle_debug(self) -> None:
        self._set_options(dataclasses.replace(self.options, hide_debug=not self.options.hide_debug))

    def _set_options(self, options: GraphOptions) -> None:
        self.options = options
        self.graph = None  # a new view, not a change of the graph
        self.action_refresh_graph()

    def on_unmount(self) -> None:
        self.source.close()


def make_graph_app(
    source: GraphSource, options: GraphOptions | None = None, period: float | None = None
) -> GraphApp:
    """The app the CLI runs and the tests drive."""
    return GraphApp(source, options or GraphOptions(), period)


def run_app(env: Any, uri: str, options: GraphOptions, period: float, bus_info: bool) -> int:
    from rosx_commands.rqt_graph import CALLER_ID  # noqa: PLC0415
    from rosx_commands.rqt_graph.source import LiveSource  # noqa: PLC0415

    app = make_graph_app(LiveSource(env, uri, CALLER_ID, bus_info), options, period)
    app.run()
    return 0
