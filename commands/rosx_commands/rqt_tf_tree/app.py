"""`TfTreePane`: rqt_tf_tree in the terminal; `TfTreeApp` runs it alone, ``rosx rqt`` as a tab.

The tree's rows are the frames, each under its parent, labelled as rqt_tf_tree labels the
edges: the broadcaster, the average rate, the delay of the newest transform (``static`` for a
static frame) and the buffer's length. The frames are read every `PERIOD` seconds on a worker
thread; ``q`` or ``ctrl+c`` quit.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from rich.text import Text
from textual.containers import Vertical  # noqa: TID253 - TUI code
from textual.widgets import Static, Tree  # noqa: TID253 - TUI code

from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_tf_tree.source import Row, tree_rows

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from textual.app import ComposeResult
    from textual.widgets.tree import TreeNode

    from rosx.tf.core import FrameInfo
    from rosx_commands.context import Environment
    from rosx_commands.rqt_tf_tree.source import TfSource

#: Seconds between two readings of the buffer (rqt_tf_tree refreshes on demand; one second
#: keeps the rates and delays current at no cost).
PERIOD = 1.0


def label(row: Row) -> Text:
    """A frame's line: its name in bold, then its edge's figures."""
    text = Text(row.frame, style="bold")
    if row.rate is None:
        return text
    text.append(f"  {row.broadcaster}", style="cyan")
    text.append(f"  {row.rate:.2f} Hz" if not row.static else "  static", style="green")
    if row.delay is not None:
        text.append(f"  delay {row.delay:.3f} s")
    if not row.static:
        text.append(f"  buffer {row.buffer_length:.2f} s", style="dim")
    return text


class TfTreePane(Vertical):
    """The tree of frames and a status line."""

    DEFAULT_CSS = """
    TfTreePane #tf-frames { height: 1fr; }
    TfTreePane #tf-status { height: 1; background: $boost; }
    """

    def __init__(
        self,
        source: TfSource,
        *,
        periodic: bool = True,
        clock: Callable[[], float] | None = None,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.source = source
        self.periodic = periodic
        self.clock = source.now if clock is None else clock
        self.rows: list[Row] = []
        self.error: str | None = None

    @override
    def compose(self) -> ComposeResult:
        tree: Tree[str] = Tree("frames", id="tf-frames")
        tree.show_root = False
        tree.guide_depth = 3
        yield tree
        yield Static(id="tf-status")

    @property
    def frame_tree(self) -> Tree[str]:
        """The tree of frames."""
        return self.query_one("#tf-frames", Tree)

    def on_mount(self) -> None:
        """Focus the tree and read the frames now, then every `PERIOD` seconds."""
        self.frame_tree.focus()
        self.refresh_frames()
        if self.periodic:
            self.set_interval(PERIOD, self.refresh_frames)
        self._status()

    def refresh_frames(self) -> None:
        """Read the frames on a worker thread, unless a read is still under way."""
        if not any(w.group == "frames" and w.is_running for w in self.workers):
            self.run_worker(self._read, thread=True, group="frames")

    def _read(self) -> None:
        try:
            frames = self.source.frames()
        except Exception as error:
            self.app.call_from_thread(self._failed, error)
            return
        self.app.call_from_thread(self.show, frames)

    def _failed(self, error: Exception) -> None:
        from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

        self.error = error_line(error)
        self._status()

    def show(self, frames: Sequence[FrameInfo]) -> None:
        """Show ``frames``: the tree rebuilt when its shape changed, relabelled otherwise."""
        self.error = None
        rows = tree_rows(frames, self.clock())
        shape = [(r.depth, r.frame) for r in rows]
        if shape != [(r.depth, r.frame) for r in self.rows]:
            self._rebuild(rows)
        else:
            for node, row in zip(self._frame_nodes(), rows, strict=True):
                node.set_label(label(row))
        self.rows = rows
        self._status()

    def _rebuild(self, rows: list[Row]) -> None:
        tree = self.frame_tree
        tree.clear()
        parents: list[TreeNode[str]] = [tree.root]
        for row in rows:
            del parents[row.depth + 1 :]
            node = parents[-1].add(label(row), row.frame, expand=True)
            parents.append(node)
        for node in self._frame_nodes():
            if not node.children:
                node.allow_expand = False

    def _frame_nodes(self) -> list[TreeNode[str]]:
        found: list[TreeNode[str]] = []
        pending = list(reversed(self.frame_tree.root.children))
        while pending:
            node = pending.pop()
            found.append(node)
            pending.extend(reversed(node.children))
        return found

    def _status(self) -> None:
        frames = sum(1 for r in self.rows if r.rate is not None)
        roots = sum(1 for r in self.rows if r.depth == 0)
        text = f" {frames} frames, {roots} {'tree' if roots == 1 else 'trees'}"
        if roots > 1:
            text += " (not connected)"
        if self.error:
            text += f" │ {self.error}"
        self.query_one("#tf-status", Static).update(Text(text, no_wrap=True))

    def on_unmount(self) -> None:
        """Close the source (its node)."""
        self.source.close()


class TfTreeApp(PaneApp[TfTreePane]):
    """``rosx rqt_tf_tree`` on its own: the pane and a footer."""


def make_tf_tree_app(source: TfSource, *, periodic: bool = True) -> TfTreeApp:
    """The app the CLI runs and the tests drive (``periodic=False``: no timer, the test calls
    `TfTreePane.refresh_frames` itself)."""
    return TfTreeApp(TfTreePane(source, periodic=periodic))


def tf_tree_tab(env: Environment) -> TfTreePane:
    """rqt_tf_tree as a tab of ``rosx rqt``."""
    from rosx_commands.rqt_tf_tree.source import LiveTfSource  # noqa: PLC0415 - this tool's parts load only when used

    return TfTreePane(LiveTfSource(env))
