"""`PondsApp`: turtlesim_view's window: one pond per turtlesim of the graph, side by side.

Each pond is a column: the turtlesim's node name, its `PondView` and its `PoseLine`, all fed
by the pond's `Feed` of scenes (`rosx_turtle.viewer` fills them from the graph). Ponds are
added and removed while the app runs, from the watcher's thread through `call_from_thread`.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.widgets import Footer, Static  # noqa: TID253 - TUI code

from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.status import PoseLine

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.app import ComposeResult

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.view.scene import Scene

WAITING = "Looking for turtlesims on the graph…"


class PondsApp(App[None]):
    """Every turtlesim's pond; ``q`` or Ctrl-C quits. ``started`` runs once the app is up."""

    TITLE = "turtlesim_view"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]
    DEFAULT_CSS = """
    #ponds { height: 1fr; }
    .pond { width: 1fr; height: 1fr; }
    .pond-name { height: 1; width: 1fr; content-align: center middle; text-style: bold; }
    #waiting { width: 1fr; height: 1fr; content-align: center middle; }
    """

    def __init__(self, started: Callable[[], object] | None = None) -> None:
        super().__init__()
        self.started = started
        self.ponds: dict[str, Vertical] = {}

    @override
    def compose(self) -> ComposeResult:
        with Horizontal(id="ponds"):
            yield Static(WAITING, id="waiting")
        yield Footer()

    def on_mount(self) -> None:
        """Tell whoever started the app that it is up (`started`), e.g. to connect the nodes."""
        if self.started is not None:
            self.started()

    def add_pond(self, name: str, feed: Feed[Scene]) -> None:
        """Show the turtlesim ``name``, drawn from the scenes offered to ``feed``."""
        if name in self.ponds:
            return
        column = Vertical(
            Static(name, classes="pond-name", markup=False),
            PondView(feed),
            PoseLine(feed),
            classes="pond",
        )
        self.ponds[name] = column
        self.query_one("#waiting").display = False
        self.query_one("#ponds").mount(column)

    def remove_pond(self, name: str) -> None:
        """The turtlesim ``name`` left the graph."""
        column = self.ponds.pop(name, None)
        if column is not None:
            column.remove()
        if not self.ponds:
            self.query_one("#waiting").display = True
