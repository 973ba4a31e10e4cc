"""`RvizApp`: rviz in a terminal on its own: its pane (`rosx_commands.rviz.pane.RvizPane`)
above a footer that names the tools and the quit key; ``q`` or Ctrl-C quit."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code

from rosx_commands.rviz.pane import RvizPane, RvizSettings
from rosx_turtle.tui.quit import QUIT_BINDINGS, QuitFooter

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult
    from textual.binding import BindingType

    from rosx_commands.rviz.config import RvizConfig
    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.panel import DisplaysPanel
    from rosx_commands.rviz.source import Source
    from rosx_commands.rviz.tools import Tool
    from rosx_commands.rviz.view import View
    from rosx_commands.rviz.viewport import Viewport


class RvizApp(App[None]):
    """The pane and the footer. The command palette is off: its footer entry would push the
    tools off 80 columns."""

    TITLE = "rviz"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = list(QUIT_BINDINGS)

    def __init__(self, pane: RvizPane) -> None:
        super().__init__()
        self.pane = pane

    @override
    def compose(self) -> ComposeResult:
        yield self.pane
        yield QuitFooter()

    # What tests and the runner look at, through the pane.
    @property
    def manager(self) -> Manager:
        """The pane's display manager (for tests and snapshots)."""
        return self.pane.manager

    @property
    def view(self) -> View:
        """The pane's camera."""
        return self.pane.view

    @property
    def viewport(self) -> Viewport:
        """The pane's 3D view widget."""
        return self.pane.viewport

    @property
    def panel(self) -> DisplaysPanel:
        """The Displays panel."""
        return self.pane.panel

    @property
    def message(self) -> str:
        """The status line's text now (e.g. "Waiting for the master ...")."""
        return self.pane.message

    def changed(self) -> None:
        """Tell the pane that something arrived, as the source does (any thread)."""
        self.pane.changed()


def make_rviz_app(
    config: RvizConfig,
    manager: Manager,
    source: Source,
    view: View,
    tools: tuple[Tool, ...],
    settings: RvizSettings,
) -> RvizApp:
    """rviz's window as ``rosx rviz`` runs it and the tests drive it."""
    return RvizApp(RvizPane(config, manager, source, view, tools, settings))


__all__ = ["RvizApp", "RvizSettings", "make_rviz_app"]
