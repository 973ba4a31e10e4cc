"""`GraphPane`: rqt_graph in the terminal: the drawing, a details panel, a status line.
`GraphApp` runs it alone (``rosx rqt_graph``), `graph_tab` as a tab of ``rosx rqt``.

A timer starts a refresh on a worker thread every period (and ``r`` at once); the worker
fetches, builds and draws, and hands the result to the UI with ``call_from_thread``, so the
view pans and answers keys while a large graph is laid out. What appeared since the refresh
before is green; what vanished stays drawn, faded red and labelled "(gone)", until the graph
changes again or `GHOST_SECONDS` pass; the status line names both, and shows an error whole.

``tab`` / ``shift+tab`` select the next / previous node or topic: its edges light up (as
rqt_graph's highlight), and its ``rosnode info`` / ``rostopic info`` (and a topic's live rate)
show in a panel on the right, which ``escape`` closes. rqt_graph's controls are keys: ``m``
cycles the modes, ``n`` and ``t`` edit the namespace and topic filters, ``g`` the depth of
namespace groups, ``d`` toggles hiding debug names; ``q`` or ``ctrl+c`` quit.
"""

from __future__ import annotations

import dataclasses
import sys
import time
from dataclasses import dataclass, field
from typing import Any, ClassVar

from rich.text import Text
from textual.app import ComposeResult  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical, VerticalScroll  # noqa: TID253 - TUI code
from textual.widgets import Input, Static  # noqa: TID253 - TUI code
from textual.worker import get_current_worker  # noqa: TID253 - TUI code

from rosx.graph.builder import build
from rosx.graph.options import GraphOptions, Mode, NameFilter
from rosx.graph.text import Drawing, draw
from rosx.graph.view import Changes, Kind, ViewGraph, changes, vanished, with_ghosts
from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_graph.source import CALLER_ID, REFRESH_PERIOD, GraphSource, LiveSource
from rosx_commands.rqt_graph.view import GraphView, Marks

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

_MODES = list(Mode)
#: Seconds the last changes stay marked (what vanished drawn as gone) on an unchanged graph.
GHOST_SECONDS = 10.0
#: Deepest namespace groups ``g`` steps through before going back to none.
MAX_GROUP_DEPTH = 3
_FILTERS = {"namespace_filter": "Namespace filter", "topic_filter": "Topic filter"}


@dataclass(frozen=True)
class History:
    """The last graph shown, the changes it brought (and when) and what vanished with them."""

    graph: ViewGraph | None = None
    changes: Changes = field(default_factory=Changes)
    ghosts: ViewGraph = field(default_factory=ViewGraph)
    since: float = 0.0

    def after(self, graph: ViewGraph, now: float | None = None) -> History:
        """The history once ``graph`` is shown at ``now`` (monotonic seconds); an unchanged
        graph keeps the marks for `GHOST_SECONDS`, then drops them and what vanished."""
        now = time.monotonic() if now is None else now
        if self.graph is None:
            return History(graph, since=now)
        diff = changes(self.graph, graph)
        if diff:
            return History(graph, diff, vanished(self.graph, graph), now)
        if self.changes and now - self.since >= GHOST_SECONDS:
            return History(graph, since=now)
        return dataclasses.replace(self, graph=graph)


class GraphPane(Vertical):
    """rqt_graph's pane: the drawing, the details panel and the status line, refreshed live."""

    DEFAULT_CSS = """
    #details { width: 40; border-left: solid $primary; padding: 0 1; display: none; }
    #details.open { display: block; }
    #status { height: auto; background: $boost; }
    #filter { display: none; }
    #filter.editing { display: block; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("r", "refresh_graph", "Refresh"),
        Binding("tab", "select(1)", "Select", priority=True),
        Binding("shift+tab", "select(-1)", "Previous", priority=True, show=False),
        Binding("m", "next_mode", "Mode"),
        Binding("n", "edit_filter('namespace_filter')", "Node filter"),
        Binding("t", "edit_filter('topic_filter')", "Topic filter"),
        Binding("g", "next_group_depth", "Groups"),
        Binding("d", "toggle_debug", "Debug"),
    ]

    def __init__(
        self,
        source: GraphSource,
        options: GraphOptions,
        period: float | None = None,
        *,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.source = source
        self.options = options
        self.period = period
        self.history = History()
        self.drawing = Drawing()
        self.selected: str | None = None
        self.error: str | None = None
        self._editing: str | None = None

    @property
    def graph(self) -> ViewGraph | None:
        """The graph last shown (what vanished from it not included)."""
        return self.history.graph

    @property
    def changes(self) -> Changes:
        """What the last refresh changed (marked in the drawing until they age out)."""
        return self.history.changes

    @override
    def compose(self) -> ComposeResult:
        yield Static(id="status")
        with Horizontal():
            yield GraphView(id="graph")
            with VerticalScroll(id="details"):
                yield Static(id="info")
        yield Input(id="filter")

    def on_mount(self) -> None:
        """Focus the drawing and fetch the graph now, then every ``period`` seconds."""
        self.query_one(GraphView).focus()
        self._status()
        self.action_refresh_graph()
        if self.period:
            self.set_interval(self.period, self._tick)

    def _tick(self) -> None:
        """The timer's refresh; skipped while one is under way, so a graph that takes longer
        than a period to lay out does not pile up refreshes."""
        if not any(w.group == "refresh" and w.is_running for w in self.workers):
            self.action_refresh_graph()

    def action_refresh_graph(self) -> None:
        """R: fetch the graph again on a worker thread, replacing a fetch still under way."""
        self.run_worker(self._refresh, thread=True, exclusive=True, group="refresh")

    def _refresh(self) -> None:
        options, history = self.options, self.history
        try:
            graph = build(self.source.snapshot(), options)
        except Exception as error:
            self.app.call_from_thread(self._failed, str(error) or type(error).__name__)
            return
        history = history.after(graph)
        drawing = draw(with_ghosts(graph, history.ghosts))
        if not get_current_worker().is_cancelled:
            self.app.call_from_thread(self._show, history, drawing, options)

    def _failed(self, message: str) -> None:
        self.error = message
        self._status()

    def _show(self, history: History, drawing: Drawing, options: GraphOptions) -> None:
        if options != self.options:
            return  # drawn for options changed since; a newer refresh is on its way
        self.history, self.drawing, self.error = history, drawing, None
        if self.selected not in drawing.boxes:
            self.selected = None
        self._status()
        self._redraw()
        self._details()

    def _redraw(self) -> None:
        self.query_one(GraphView).show(self.drawing, Marks(self.changes, self.selected))

    def _status(self) -> None:
        graph = self.graph or ViewGraph()
        nodes = sum(v.kind is Kind.NODE for v in graph.vertices)
        topics = len(graph.vertices) - nodes
        text = f" {self.options.mode.caption} │ {nodes} nodes, {topics} topics"
        if self.graph is None and self.error is None:
            text += " │ reading the graph…"
        if self.changes:
            text += f" │ changed: {self.changes.summary()}"
        if self.error:
            text += f" │ ERROR: {self.error}"
        self.query_one("#status", Static).update(Text(text))

    def action_select(self, step: int) -> None:
        """Tab/Shift+Tab: select the next or previous box, left to right then top to bottom, and
        show its details; ignored while a filter line is open."""
        if self._editing:
            return
        boxes = self.drawing.boxes
        order = sorted(boxes, key=lambda i: (boxes[i].x, boxes[i].y))
        if not order:
            return
        if self.selected in order:
            index = order.index(self.selected) + step
        else:
            index = 0 if step > 0 else -1
        self.selected = order[index % len(order)]
        self._redraw()
        self._details()

    def _details(self) -> None:
        self.query_one("#details").set_class(self.selected is not None, "open")
        vertex = self.graph.vertex(self.selected) if self.graph and self.selected else None
        if vertex is None:
            if self.selected:  # a vertex that vanished, still drawn faded
                self.query_one("#info", Static).update(Text(f"{self.selected[2:]}: gone"))
            return
        self.run_worker(lambda: self._describe(vertex), thread=True, exclusive=True, group="info")

    def _describe(self, vertex: Any) -> None:
        text = self.source.describe(vertex)
        if vertex.kind is Kind.TOPIC:
            text += "\n" + self.source.rate(vertex.label)
        self.app.call_from_thread(self._show_details, vertex.id, text)

    def _show_details(self, vertex_id: str, text: str) -> None:
        if vertex_id == self.selected:
            self.query_one("#info", Static).update(Text(text))

    def action_next_mode(self) -> None:
        """M: the next of rqt_graph's modes (nodes only, nodes/topics active, nodes/topics all)."""
        mode = _MODES[(_MODES.index(self.options.mode) + 1) % len(_MODES)]
        self._set_options(dataclasses.replace(self.options, mode=mode))

    def action_toggle_debug(self) -> None:
        """D: show or hide the debug nodes and topics (``/rosout``, rqt's own), as rqt_graph's
        "Hide Debug" checkbox."""
        self._set_options(dataclasses.replace(self.options, hide_debug=not self.options.hide_debug))

    def action_next_group_depth(self) -> None:
        """G: group by one more namespace level, back to none after `MAX_GROUP_DEPTH`."""
        depth = (self.options.group_depth + 1) % (MAX_GROUP_DEPTH + 1)
        self._set_options(dataclasses.replace(self.options, group_depth=depth))

    def action_edit_filter(self, which: str) -> None:
        """Open the filter line for ``namespace_filter`` or ``topic_filter``."""
        self._editing = which
        line = self.query_one("#filter", Input)
        line.border_title = f"{_FILTERS[which]} (comma list, -name excludes; enter applies)"
        line.value = getattr(self.options, which)
        line.cursor_position = len(line.value)  # older textual keeps the previous text's cursor
        line.add_class("editing")
        line.focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Apply the typed node or topic filter; a bad pattern leaves the line open with the
        error."""
        which, text = self._editing, event.value.strip() or "/"
        if which is None:
            return
        try:
            NameFilter.parse(text)
        except ValueError as error:
            self.error = str(error)
            self._status()
            return  # the line stays open for a fix
        self._close_filter()
        if which == "namespace_filter":
            self._set_options(dataclasses.replace(self.options, namespace_filter=text))
        else:
            self._set_options(dataclasses.replace(self.options, topic_filter=text))

    def key_escape(self) -> None:
        """Escape closes the filter line if open, else drops the selection (the drawing widens
        again)."""
        if self._editing:
            self._close_filter()
        elif self.selected:
            self.selected = None  # the drawing gets the whole width again
            self._redraw()
            self._details()

    def _close_filter(self) -> None:
        self._editing = None
        self.query_one("#filter", Input).remove_class("editing")
        self.query_one(GraphView).focus()

    def _set_options(self, options: GraphOptions) -> None:
        self.options = options
        self.history = History()  # a new view, not a change of the graph
        self.error = None
        self._status()
        self.action_refresh_graph()

    def on_unmount(self) -> None:
        """Close the source (its rate node, if any)."""
        self.source.close()


class GraphApp(PaneApp[GraphPane]):
    """``rosx rqt_graph`` on its own: the pane and a footer; the pane's state reads through."""

    ENABLE_COMMAND_PALETTE = True  # its footer has always offered the palette

    @property
    def drawing(self) -> Drawing:
        """The pane's current drawing (for tests and snapshots)."""
        return self.pane.drawing

    @property
    def selected(self) -> str | None:
        """The id of the selected box, or None."""
        return self.pane.selected

    @property
    def options(self) -> GraphOptions:
        """The pane's graph options (mode, filters, grouping)."""
        return self.pane.options

    @property
    def graph(self) -> ViewGraph | None:
        """The graph last fetched, or None before the first fetch."""
        return self.pane.graph


def graph_tab(env: Any) -> GraphPane:
    """rqt_graph as a tab of ``rosx rqt``: live, with rqt_graph's defaults."""
    source = LiveSource(env, env.master_uri, CALLER_ID, True)
    return GraphPane(source, GraphOptions(), REFRESH_PERIOD)


def make_graph_app(
    source: GraphSource, options: GraphOptions | None = None, period: float | None = None
) -> GraphApp:
    """The app the CLI runs and the tests drive."""
    return GraphApp(GraphPane(source, options or GraphOptions(), period))


def run_app(env: Any, uri: str, options: GraphOptions, period: float, bus_info: bool) -> int:
    """Run the live view of the graph at ``uri`` until the user quits; the exit status."""
    app = make_graph_app(LiveSource(env, uri, CALLER_ID, bus_info), options, period)
    app.run()
    return 0
