"""`RqtApp`: the rqt tools of `rosx_commands.rqt.tabs` as tabs of one terminal app.

A tab's pane is built by its factory the first time the tab is shown, so ``rosx rqt`` starts
as fast as one tool and a tool never opened never talks to the master. Switching tabs keeps
each pane as it was. ``ctrl+pageup``/``ctrl+pagedown`` (or ``f1``…``f9``) switch tabs; ``q``
or ``ctrl+c`` quit.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from rich.text import Text
from textual.app import App, ComposeResult  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.widgets import Static, TabbedContent, TabPane  # noqa: TID253 - TUI code

from rosx_commands.rqt.tabs import TABS, Tab
from rosx_turtle.tui.quit import QuitFooter

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_commands.context import Environment


class RqtApp(App[int]):
    """One `TabPane` per registered tab, filled on first show."""

    ENABLE_COMMAND_PALETTE = False
    CSS = "TabPane { padding: 0; }"
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
        Binding("ctrl+pagedown", "next_tab(1)", "Next tab", show=False, priority=True),
        Binding("ctrl+pageup", "next_tab(-1)", "Previous tab", show=False, priority=True),
        *(
            Binding(f"f{i}", f"show_tab({i - 1})", f"Tab {i}", show=False, priority=True)
            for i in range(1, 10)
        ),
    ]

    def __init__(self, env: Environment, tabs: Sequence[Tab] = TABS, first: str | None = None):
        super().__init__()
        self.env = env
        self.tabs = list(tabs)
        self.first = first or self.tabs[0].name
        self.built: dict[str, object] = {}

    @override
    def compose(self) -> ComposeResult:
        with TabbedContent(initial=f"tab-{self.first}"):
            for tab in self.tabs:
                yield TabPane(tab.title, id=f"tab-{tab.name}")
        yield QuitFooter()

    def on_mount(self) -> None:
        """Build the first tab's plugin; the others are built when first shown."""
        self._build(self.first)

    def on_tabbed_content_tab_activated(self, event: TabbedContent.TabActivated) -> None:
        """Build the activated tab's plugin on first showing."""
        self._build((event.pane.id or "tab-").removeprefix("tab-"))

    def _build(self, name: str) -> None:
        if name in self.built:
            return
        tab = next(t for t in self.tabs if t.name == name)
        holder = self.query_one(f"#tab-{name}", TabPane)
        try:
            pane = tab.load()(self.env)
        except Exception as error:
            from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

            pane = Static(Text(f"{tab.title} cannot start: {error_line(error)}"))
        self.built[name] = pane
        holder.mount(pane)
        self.call_after_refresh(pane.focus)

    @property
    def active(self) -> str:
        """The name of the tab shown."""
        return self.query_one(TabbedContent).active.removeprefix("tab-")

    def action_show_tab(self, index: int) -> None:
        """F1..F9: show the ``index``-th tab (counting from 0); out of range does nothing."""
        if 0 <= index < len(self.tabs):
            self.query_one(TabbedContent).active = f"tab-{self.tabs[index].name}"

    def action_next_tab(self, step: int) -> None:
        """Ctrl+PageDown/PageUp: show the tab ``step`` away, wrapping around."""
        names = [t.name for t in self.tabs]
        self.action_show_tab((names.index(self.active) + step) % len(names))


def make_rqt_app(env: Environment, tabs: Sequence[Tab] = TABS, first: str | None = None) -> RqtApp:
    """The app the CLI runs and the tests drive (tests pass tabs of their own)."""
    return RqtApp(env, tabs, first)
