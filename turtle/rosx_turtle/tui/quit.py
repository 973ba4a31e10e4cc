"""How every rosx terminal UI quits: ``q`` and Ctrl-C, and a footer that always says so.

The lab sheet teaches Ctrl-C, so Ctrl-C quits (a priority binding, before any widget sees it)
as ``q`` does. textual's footer lists the focused widget's keys first and the app's last, so
on an 80-column terminal the quit key is the one cut off; `QuitFooter` lists it first.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.widgets import Footer  # noqa: TID253 - TUI code
from textual.widgets._footer import FooterKey  # noqa: TID253 - TUI code

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

#: The bindings every app has.
QUIT_BINDINGS: list[BindingType] = [
    Binding("q", "quit", "Quit"),
    Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
]


def _is_quit(widget: object) -> bool:
    return isinstance(widget, FooterKey) and widget.action in ("quit", "app.quit")


class QuitFooter(Footer):
    """textual's footer with the quit key first."""

    @override
    def compose(self) -> ComposeResult:
        keys = list(super().compose())
        yield from sorted(keys, key=lambda widget: not _is_quit(widget))
