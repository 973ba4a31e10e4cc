"""`DetailsScreen`: what Enter on a row of ``rosx sim``'s Topics or Nodes pane shows; Esc closes.

A topic shows ``rostopic info``'s text and, under it, its latest messages as ``rostopic echo``
prints them (the newest last, refreshed a few times a second); a node shows ``rosnode info``'s
text. The texts come from the link (`Details.describe_topic`, `describe_node`, `echo`) on worker
threads, so a slow node never freezes the screen.
"""

from __future__ import annotations

import sys
import threading
from collections import deque
from typing import TYPE_CHECKING, ClassVar

from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import VerticalScroll  # noqa: TID253 - TUI code
from textual.screen import ModalScreen  # noqa: TID253 - TUI code
from textual.widgets import Static  # noqa: TID253 - TUI code

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.app import ComposeResult

    from rosx_turtle.tui.link import Details

#: How many of a topic's latest messages are shown.
KEEP = 3
#: Seconds between two redraws of the echoed messages.
ECHO_PERIOD = 0.25


class DetailsScreen(ModalScreen[None]):
    """Info (and, for a topic, echo) of ``name``; ``kind`` is ``"topic"`` or ``"node"``."""

    DEFAULT_CSS = """
    DetailsScreen { align: center middle; }
    DetailsScreen > VerticalScroll {
        width: 90%;
        height: 90%;
        border: heavy $accent;
        border-title-color: $accent;
        background: $surface;
        padding: 0 1;
    }
    DetailsScreen #echo-title { margin-top: 1; text-style: bold; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape", "close", "Close"),
        Binding("q", "close", "Close", show=False),
    ]

    def __init__(self, link: Details, kind: str, name: str) -> None:
        super().__init__()
        self.link = link
        self.kind = kind
        self.name_shown = name
        #: The info text once it has come (empty before).
        self.info = ""
        self._latest: deque[str] = deque(maxlen=KEEP)
        self._lock = threading.Lock()
        self._changed = False
        self._stop: Callable[[], None] | None = None
        self._closed = False
        #: The echoed messages shown now (``rostopic echo``'s text).
        self.echoed = ""

    @override
    def compose(self) -> ComposeResult:
        command = "rostopic" if self.kind == "topic" else "rosnode"
        with VerticalScroll() as box:
            box.border_title = f"{command} info {self.name_shown}"
            box.border_subtitle = "Esc closes"
            yield Static("asking the master…", id="info", markup=False)
            if self.kind == "topic":
                yield Static(f"rostopic echo {self.name_shown}", id="echo-title", markup=False)
                yield Static("waiting for a message…", id="echo", markup=False)

    def on_mount(self) -> None:
        """Ask for the topic's or node's info in a worker thread; for a topic, also start echoing
        it and refresh the echo every `ECHO_PERIOD` seconds."""
        self.run_worker(self._describe, thread=True, exit_on_error=False)
        if self.kind == "topic":
            self.run_worker(self._start_echo, thread=True, exit_on_error=False)
            self.set_interval(ECHO_PERIOD, self._show_echo)

    def _describe(self) -> None:
        if self.kind == "topic":
            text = self.link.describe_topic(self.name_shown)
        else:
            text = self.link.describe_node(self.name_shown)
        self.app.call_from_thread(self._show_info, text)

    def _show_info(self, text: str) -> None:
        self.info = text
        self.query_one("#info", Static).update(text.rstrip("\n"))

    def _start_echo(self) -> None:
        stop = self.link.echo(self.name_shown, self._arrived)
        with self._lock:
            keep = not self._closed
            if keep:
                self._stop = stop
        if not keep:
            stop()  # closed while subscribing

    def _arrived(self, text: str) -> None:
        with self._lock:
            self._latest.append(text)
            self._changed = True

    def _show_echo(self) -> None:
        with self._lock:
            if not self._changed:
                return
            self._changed = False
            text = "".join(self._latest)
        self.echoed = text
        self.query_one("#echo", Static).update(text.rstrip("\n"))

    def action_close(self) -> None:
        """Close the details (stop echoing)."""
        self.dismiss()

    def on_unmount(self) -> None:
        """Stop the echo's subscription on a thread of its own, so closing the screen never waits
        on the network."""
        with self._lock:
            self._closed = True
            stop, self._stop = self._stop, None
        if stop is not None:
            threading.Thread(target=stop, name="rosx-sim-echo-stop", daemon=True).start()
