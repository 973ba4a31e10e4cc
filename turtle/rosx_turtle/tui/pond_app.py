"""`PondApp`: turtlesim_node's window in a terminal: the pond, the poses and the keys."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code

from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.quit import QuitFooter
from rosx_turtle.tui.status import PoseLine

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.view.scene import Scene


class PondApp(App[None]):
    """The pond full-screen, with the poses and the latest log line; ``q`` or Ctrl-C quits."""

    TITLE = "TurtleSim"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]

    def __init__(self, scenes: Feed[Scene], logs: Feed[LogRecord] | None = None) -> None:
        super().__init__()
        self.scenes = scenes
        self.logs = logs

    @override
    def compose(self) -> ComposeResult:
        yield PondView(self.scenes, id="pond")
        yield PoseLine(self.scenes, id="poses")
        yield LogLine(self.logs, id="log")
        yield QuitFooter()
