"""`PaneApp`: an rqt tool run on its own, its pane above a footer that names the quit key.

Each rqt tool is a pane (a widget) so that ``rosx rqt`` can show it as a tab; run alone it is
this app around the pane, quitting on ``q`` and Ctrl-C as every rosx terminal UI does.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar, Generic, TypeVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.widget import Widget  # noqa: TID253 - TUI code

from rosx_turtle.tui.quit import QUIT_BINDINGS, QuitFooter

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult
    from textual.binding import BindingType

PaneT = TypeVar("PaneT", bound=Widget)


class PaneApp(App[int], Generic[PaneT]):
    """``pane`` and a footer. The command palette is off: its footer entry would push
    ``q Quit`` off 80 columns."""

    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = list(QUIT_BINDINGS)

    def __init__(self, pane: PaneT) -> None:
        super().__init__()
        self.pane = pane

    @override
    def compose(self) -> ComposeResult:
        yield self.pane
        yield QuitFooter()
