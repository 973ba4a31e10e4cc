"""`ConsolePane`: rqt_console in the terminal; `ConsoleApp` runs it alone (``rosx rqt_console``),
`console_tab` as a tab of ``rosx rqt``.

A status line (how many entries are shown of how many kept, the rules, pause, errors in full),
the table (`LogTable`), the selected entry's details, and a line for typing a rule. A timer
takes what the source's inbox holds ten times a second and adds it in one batch, so the screen
does one update per period whatever the rate of records; with nothing arriving it does nothing.

Keys: ``i`` / ``x`` / ``h`` add an include / exclude / highlight rule (``FIELD:PATTERN``, field
one of severity, node, text, topic, location; ``severity:warn+``; a bare pattern is on the
text), ``u`` removes the last rule, ``r`` all of them; ``p`` or space pauses (what arrives
meanwhile waits), ``c`` clears; the arrow keys move the selection, ``escape`` drops it (the
table follows new entries again). ``q`` or Ctrl-C quit.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any, ClassVar

from rich.text import Text
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Vertical  # noqa: TID253 - TUI code
from textual.widgets import Input, Static  # noqa: TID253 - TUI code

from rosx_commands.errors import error_line
from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_console.model import (
    DEFAULT_LIMIT,
    Kind,
    Log,
    Rule,
    RuleError,
    Rules,
    details,
)
from rosx_commands.rqt_console.table import LogTable

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_commands.rqt_console.model import Rules
    from rosx_commands.rqt_console.source import ConsoleSource

#: Seconds between two looks at the inbox.
INGEST_PERIOD = 0.1
_PROMPTS = {
    Kind.INCLUDE: "Include",
    Kind.EXCLUDE: "Exclude",
    Kind.HIGHLIGHT: "Highlight",
}


class ConsolePane(Vertical):
    """rqt_console's view of a `ConsoleSource` (see the module docstring)."""

    DEFAULT_CSS = """
    ConsolePane #status { height: auto; background: $boost; }
    ConsolePane #details {
        height: 7; border-top: solid $primary; padding: 0 1; display: none;
    }
    ConsolePane #details.open { display: block; }
    ConsolePane #rule { display: none; }
    ConsolePane #rule.editing { display: block; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("i", "edit_rule('include')", "Include"),
        Binding("x", "edit_rule('exclude')", "Exclude"),
        Binding("h", "edit_rule('highlight')", "Highlight"),
        Binding("u", "drop_rule", "Undo rule"),
        Binding("r", "clear_rules", "No rules", show=False),
        Binding("p", "pause", "Pause"),
        Binding("space", "pause", "Pause", show=False),
        Binding("c", "clear", "Clear"),
    ]

    def __init__(
        self,
        source: ConsoleSource,
        rules: Rules | None = None,
        *,
        limit: int = DEFAULT_LIMIT,
        period: float | None = INGEST_PERIOD,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.source = source
        self.entries = Log(limit)
        if rules is not None:
            self.entries.set_rules(rules)
        self.period = period
        self.paused = False
        self.origin = ""
        self.error: str | None = None
        self._editing: Kind | None = None
        self._waiting = 0

    @override
    def compose(self) -> ComposeResult:
        yield Static(id="status")
        yield LogTable(self.entries, id="table")
        yield Static(id="details")
        yield Input(id="rule")

    @property
    def table(self) -> LogTable:
        """The message table."""
        return self.query_one(LogTable)

    def on_mount(self) -> None:
        """Focus the table and start the source on a worker thread; new entries are taken in
        every ``period`` seconds."""
        self.table.focus()
        self._status()
        self.run_worker(self._start, thread=True, group="source")
        if self.period:
            self.set_interval(self.period, self.ingest)

    def _start(self) -> None:
        try:
            origin = self.source.start()
        except Exception as error:
            self.app.call_from_thread(self._failed, error_line(error))
            return
        self.app.call_from_thread(self._started, origin)

    def _started(self, origin: str) -> None:
        self.origin = origin
        self._status()

    def _failed(self, message: str) -> None:
        self.error = message
        self._status()

    def ingest(self) -> int:
        """Add what waits in the inbox (unless paused); how many entries were taken."""
        waiting = len(self.source.inbox)
        if self.paused:
            if waiting != self._waiting:
                self._waiting = waiting
                self._status()
            return 0
        if not waiting:
            return 0
        entries = self.source.inbox.take()
        self.entries.add(entries)
        self.table.refresh_rows()
        self._status()
        if self.table.cursor is not None:
            self._details(self.table.cursor)
        return len(entries)

    def _status(self) -> None:
        log = self.entries
        text = f" {log.shown_count} of {len(log)} messages"
        if log.rules.rules:
            text += " │ " + "; ".join(map(str, log.rules.rules))
        if self.paused:
            text += f" │ PAUSED ({self._waiting} waiting)"
        if self.origin:
            text += f" │ {self.origin}"
        elif self.error is None:
            text += " │ connecting…"
        if self.error:
            text += f" │ {self.error}"
        self.query_one("#status", Static).update(Text(text))

    def on_log_table_selected(self, message: LogTable.Selected) -> None:
        """Show the selected row's message in full below the table."""
        self._details(message.row)

    def _details(self, row: int | None) -> None:
        panel = self.query_one("#details", Static)
        panel.set_class(row is not None, "open")
        if row is not None and row < self.entries.shown_count:
            panel.update(Text(details(self.entries.shown(row))))

    def key_escape(self) -> None:
        """Escape closes the rule line if it is open, else clears the selection."""
        if self._editing is not None:
            self._close_rule()
        else:
            self.table.select(None)

    def action_pause(self) -> None:
        """P or space: pause or resume taking in entries; those arriving meanwhile wait in the
        inbox."""
        self.paused = not self.paused
        self._waiting = len(self.source.inbox)
        self._status()
        if not self.paused:
            self.ingest()

    def action_clear(self) -> None:
        """C: drop every entry shown so far (rules stay)."""
        self.entries.clear()
        self.table.select(None)
        self.table.refresh_rows()
        self._status()

    def action_edit_rule(self, kind: str) -> None:
        """I, X or H: open the rule line for an include, exclude or highlight rule of ``kind``."""
        which = Kind(kind)
        self._editing = which
        line = self.query_one("#rule", Input)
        line.border_title = f"{_PROMPTS[which]} FIELD:PATTERN (severity node text topic location)"
        line.value = ""
        line.add_class("editing")
        line.focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Add the typed rule; a bad one leaves the line open with the error on the status line."""
        kind = self._editing
        if kind is None:
            return
        try:
            rule = Rule.parse(kind, event.value)
        except RuleError as error:
            self.error = f"ERROR: {error}"
            self._status()
            return  # the line stays open for a fix
        self._close_rule()
        self.add_rule(rule)

    def add_rule(self, rule: Rule) -> None:
        """Add ``rule`` after the others and filter the entries again."""
        self.set_rules(self.entries.rules.with_rule(rule))

    def set_rules(self, rules: Rules) -> None:
        """Use ``rules`` from now on, refiltering every entry and keeping the selection in range."""
        self.error = None
        self.entries.set_rules(rules)
        self.table.refresh_rows()
        self.table.select(self.table.cursor)
        self._status()

    def action_drop_rule(self) -> None:
        """U: drop the last rule added."""
        self.set_rules(Rules(self.entries.rules.rules[:-1]))

    def action_clear_rules(self) -> None:
        """R: drop every rule."""
        self.set_rules(self.entries.rules.without())

    def _close_rule(self) -> None:
        self._editing = None
        self.query_one("#rule", Input).remove_class("editing")
        self.table.focus()

    def on_unmount(self) -> None:
        """Close the source (its node), so no entries arrive for a closed pane."""
        self.source.close()


class ConsoleApp(PaneApp[ConsolePane]):
    """``rosx rqt_console`` on its own: the pane and a footer."""

    TITLE = "rqt_console"


def make_console_app(
    source: ConsoleSource,
    rules: Rules | None = None,
    *,
    limit: int = DEFAULT_LIMIT,
    period: float | None = INGEST_PERIOD,
) -> ConsoleApp:
    """The app the CLI runs and the tests drive."""
    return ConsoleApp(ConsolePane(source, rules, limit=limit, period=period))


def console_tab(env: Any) -> ConsolePane:
    """rqt_console as a tab of ``rosx rqt``: ``/rosout_agg`` of ``env``'s master."""
    from rosx_commands.rqt_console.source import LiveSource  # noqa: PLC0415 - this tool's parts load only when used

    return ConsolePane(LiveSource(env, env.master_uri))
