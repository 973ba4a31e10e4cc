"""`LevelPane`: rqt_logger_level in the terminal; `LevelApp` runs it alone
(``rosx rqt_logger_level``), `logger_level_tab` as a tab of ``rosx rqt``.

Three lists side by side, as rqt_logger_level's: the nodes that serve ``~set_logger_level``,
the loggers of the node under the cursor (with their levels), and the five levels, the
logger's own marked. Enter on a level sets it (``~set_logger_level``) and reads the loggers
again, so what shows is what the node says. Network calls run on worker threads; a failure
shows in full on the status line. ``r`` reads the nodes again; tab moves between the lists;
``q`` or Ctrl-C quit.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical  # noqa: TID253 - TUI code
from textual.widgets import OptionList, Static  # noqa: TID253 - TUI code
from textual.widgets.option_list import Option  # noqa: TID253 - TUI code

from rosx_commands.errors import error_line
from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_logger_level.source import LEVELS, LiveSource

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_commands.rqt_logger_level.source import LevelSource


class LevelPane(Vertical):
    """Nodes → loggers → levels of a `LevelSource` (see the module docstring)."""

    DEFAULT_CSS = """
    LevelPane #status { height: auto; background: $boost; }
    LevelPane OptionList { height: 1fr; border: round $panel-lighten-2; }
    LevelPane OptionList:focus { border: heavy $accent; }
    LevelPane #nodes { width: 2fr; }
    LevelPane #loggers { width: 2fr; }
    LevelPane #levels { width: 1fr; min-width: 12; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [Binding("r", "refresh_nodes", "Refresh")]

    def __init__(self, source: LevelSource, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.source = source
        self.node_names: list[str] = []
        self.node: str | None = None
        self.logger_levels: list[tuple[str, str]] = []
        self.logger: str | None = None
        self.error: str | None = None
        self.note = "reading the nodes…"

    @override
    def compose(self) -> ComposeResult:
        yield Static(id="status")
        with Horizontal():
            nodes = OptionList(id="nodes")
            nodes.border_title = "Nodes"
            yield nodes
            loggers = OptionList(id="loggers")
            loggers.border_title = "Loggers"
            yield loggers
            levels = OptionList(*LEVELS, id="levels")
            levels.border_title = "Levels"
            yield levels

    def on_mount(self) -> None:
        """Focus the node list and fetch the nodes."""
        self.query_one("#nodes", OptionList).focus()
        self._status()
        self.action_refresh_nodes()

    def _status(self) -> None:
        text = f" {len(self.node_names)} nodes"
        if self.node:
            text += f" │ {self.node}"
            if self.logger:
                text += f" {self.logger}"
        if self.note:
            text += f" │ {self.note}"
        if self.error:
            text += f" │ {self.error}"
        self.query_one("#status", Static).update(Text(text))

    # -- workers: every network call runs on a thread, its result comes back by call_from_thread

    def _run(self, job: Any, group: str) -> None:
        self.run_worker(job, thread=True, exclusive=True, group=group)

    def _report(self, error: BaseException) -> None:
        self.app.call_from_thread(self._failed, error_line(error))

    def _failed(self, message: str) -> None:
        self.error, self.note = message, ""
        self._status()

    def action_refresh_nodes(self) -> None:
        """R: fetch again the nodes that serve the logger services, on a worker thread."""

        def job() -> None:
            try:
                nodes = self.source.nodes()
            except Exception as error:
                self._report(error)
                return
            self.app.call_from_thread(self._show_nodes, nodes)

        self._run(job, "nodes")

    def _show_nodes(self, nodes: list[str]) -> None:
        self.node_names, self.error, self.note = nodes, None, ""
        listing = self.query_one("#nodes", OptionList)
        listing.clear_options()
        listing.add_options(nodes)
        if self.node in nodes:
            listing.highlighted = nodes.index(self.node)
        elif nodes:
            listing.highlighted = 0
        else:
            self._show_loggers(None, [])
        self._status()

    def _load_loggers(self, node: str) -> None:
        def job() -> None:
            try:
                loggers = self.source.loggers(node)
            except Exception as error:
                self._report(error)
                return
            self.app.call_from_thread(self._show_loggers, node, loggers)

        self._run(job, "loggers")

    def _show_loggers(self, node: str | None, loggers: list[tuple[str, str]]) -> None:
        if node != self.node:
            return  # read for a node no longer under the cursor
        self.logger_levels, self.error = loggers, None
        listing = self.query_one("#loggers", OptionList)
        listing.clear_options()
        listing.add_options(
            Option(Text.assemble(name, " ", (level, "bold")), id=name) for name, level in loggers
        )
        names = [name for name, _ in loggers]
        if self.logger in names:
            listing.highlighted = names.index(self.logger)
        elif names:
            listing.highlighted = 0
        else:
            self.logger = None
        self._mark_level()
        self._status()

    def level_of(self, logger: str | None) -> str | None:
        """The level the node last said ``logger`` has (``DEBUG``…), or None."""
        return dict(self.logger_levels).get(logger or "")

    def _mark_level(self) -> None:
        levels = self.query_one("#levels", OptionList)
        current = (self.level_of(self.logger) or "").capitalize()
        levels.clear_options()
        levels.add_options(
            Option(Text(f"● {name}" if name == current else f"  {name}"), id=name)
            for name in LEVELS
        )
        if current in LEVELS:
            levels.highlighted = LEVELS.index(current)

    def on_option_list_option_highlighted(self, event: OptionList.OptionHighlighted) -> None:
        """Moving in the node list loads that node's loggers; in the logger list, marks its
        level."""
        which = event.option_list.id
        if which == "nodes":
            node = self.node_names[event.option_index]
            if node != self.node:
                self.node, self.logger = node, None
                self._status()
                self._load_loggers(node)
        elif which == "loggers":
            self.logger = self.logger_levels[event.option_index][0]
            self._mark_level()
            self._status()

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        """Enter moves on from nodes to loggers to levels; on a level, sets the highlighted
        logger to it."""
        which = event.option_list.id
        if which == "nodes":
            self.query_one("#loggers", OptionList).focus()
        elif which == "loggers":
            self.query_one("#levels", OptionList).focus()
        elif which == "levels" and self.node and self.logger:
            self.set_level(self.node, self.logger, LEVELS[event.option_index])

    def set_level(self, node: str, logger: str, level: str) -> None:
        """Set ``logger`` of ``node`` to ``level``, then read the node's loggers again."""
        self.note = f"setting {logger} to {level}…"
        self._status()

        def job() -> None:
            try:
                self.source.set_level(node, logger, level)
                loggers = self.source.loggers(node)
            except Exception as error:
                self._report(error)
                return
            self.app.call_from_thread(self._level_set, node, logger, level, loggers)

        self._run(job, "set")

    def _level_set(
        self, node: str, logger: str, level: str, loggers: list[tuple[str, str]]
    ) -> None:
        self.note = f"{node} {logger} set to {level}"
        self._show_loggers(node, loggers)

    def on_unmount(self) -> None:
        """Close the source (its master connection)."""
        self.source.close()


class LevelApp(PaneApp[LevelPane]):
    """``rosx rqt_logger_level`` on its own: the pane and a footer."""

    TITLE = "rqt_logger_level"


def make_level_app(source: LevelSource) -> LevelApp:
    """The app the CLI runs and the tests drive."""
    return LevelApp(LevelPane(source))


def logger_level_tab(env: Any) -> LevelPane:
    """rqt_logger_level as a tab of ``rosx rqt``: the nodes of ``env``'s master."""
    return LevelPane(LiveSource(env.master_uri))
