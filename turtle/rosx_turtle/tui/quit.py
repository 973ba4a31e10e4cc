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
    """textual's footer with the quit key first.

    textual leaves out a key that the focused widget types (``q`` in a text editor, such as
    axclient's goal), so the footer then names Ctrl-C, which quits from anywhere.
    """

    @override
    def compose(self) -> ComposeResult:
        keys = list(super().compose())
        if keys and not any(_is_quit(widget) for widget in keys):
            ctrl_c = self.screen.active_bindings.get("ctrl+c")
            if ctrl_c is not None and ctrl_c.binding.action in ("quit", "app.quit"):
                self.styles.grid_size_columns = len(keys) + 1
                key = FooterKey("ctrl+c", self.app.get_key_display(ctrl_c.binding), "Quit", "quit")
                keys.append(key.data_bind(compact=Footer.compact))
        yield from sorted(keys, key=lambda widget: not _is_quit(widget))
