"""`RvizPane`: rviz's window as a widget: the view, the Displays panel, a status line, the keys.

`RvizApp` (`rosx_commands.rviz.app`) runs it alone and ``rosx rqt`` as a tab. The view is
`viewport.Viewport`, the panel `panel.DisplaysPanel`,
the ROS side a `source.Source` started on a worker thread (threads reach the widgets only
through the feed and ``call_from_thread``). Keys: rviz's tool shortcuts ``g`` (2D Nav Goal),
``p`` (2D Pose Estimate), ``c`` (Publish Point), then Enter places the tool at the view's
centre (``[`` and ``]`` turn it) or a click places it where clicked (drag for the heading);
Escape puts it down. Arrows pan, ``+``/``-`` zoom, ``f`` follows a frame, ``1``…``9`` show
or hide a display, ``ctrl+s`` saves the config, ``o`` writes a PNG; ``q`` or Ctrl-C quit.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, ClassVar

from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Horizontal, Vertical, VerticalScroll  # noqa: TID253 - TUI code
from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_commands.rviz.image_pane import ImagePane
from rosx_commands.rviz.panel import DisplaysPanel
from rosx_commands.rviz.viewport import Placing, Viewport
from rosx_turtle.tui.feed import Feed

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Callable

    from textual.app import ComposeResult

    from rosx_commands.rviz.config import RvizConfig
    from rosx_commands.rviz.manager import Manager
    from rosx_commands.rviz.source import Source
    from rosx_commands.rviz.tools import Tool
    from rosx_commands.rviz.view import View

HEADING_STEP = math.radians(15.0)
#: Seconds between looks for markers and clouds that timed out.
EXPIRY_PERIOD = 0.5
#: Seconds between tries to reach a master that does not answer.
MASTER_RETRY = 1.0


@dataclass
class RvizSettings:
    """Where saving writes (the ``-d`` file, else rviz's ``~/.rviz/default.rviz``), where
    snapshots go, and the clock (seconds; tests fix it)."""

    save_path: Path
    snapshot_dir: Path
    clock: Callable[[], float] = time.monotonic


class RvizPane(Vertical):
    """rviz's window (see the module docstring)."""

    DEFAULT_CSS = """
    RvizPane #body { height: 1fr; }
    RvizPane #side { width: 32; height: 1fr; background: $panel; }
    RvizPane #side DisplaysPanel { width: 1fr; height: auto; }
    RvizPane #status { height: 1; padding: 0 1; background: $boost; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("g", "tool('Goal')", "Goal"),
        Binding("p", "tool('Pose')", "Pose"),
        Binding("c", "tool('Point')", "Point"),
        Binding("enter", "place", "Place", show=False),
        Binding("escape", "drop_tool", "Drop tool", show=False),
        Binding("left_square_bracket", "turn(1)", "Turn left", show=False),
        Binding("right_square_bracket", "turn(-1)", "Turn right", show=False),
        Binding("left", "pan(-4, 0)", "Pan", show=False),
        Binding("right", "pan(4, 0)", "Pan", show=False),
        Binding("up", "pan(0, -4)", "Pan", show=False),
        Binding("down", "pan(0, 4)", "Pan", show=False),
        Binding("plus,equals_sign", "zoom(1)", "Zoom in", show=False),
        Binding("minus", "zoom(-1)", "Zoom out", show=False),
        Binding("home", "reset_view", "Reset view", show=False),
        Binding("f", "follow", "Follow"),
        Binding("ctrl+s", "save", "Save"),
        Binding("o", "snapshot", "PNG"),
        *(
            Binding(str(n), f"toggle_display({n - 1})", f"Display {n}", show=False)
            for n in range(1, 10)
        ),
    ]

    def __init__(
        self,
        config: RvizConfig,
        manager: Manager,
        source: Source,
        view: View,
        tools: tuple[Tool, ...],
        settings: RvizSettings,
    ) -> None:
        super().__init__()
        self.config, self.manager, self.source = config, manager, source
        self.view, self.tools, self.settings = view, tools, settings
        self.changes: Feed[int] = Feed()
        self._count = itertools.count(1)
        self.heading = 0.0
        self.published: list[str] = []
        self.message = ""
        self._stopping = threading.Event()

    @override
    def compose(self) -> ComposeResult:
        with Horizontal(id="body"):
            yield Viewport(
                self.manager,
                self.view,
                self.config.background,
                self.changes,
                self.settings.clock,
                id="view",
            )
            with VerticalScroll(id="side"):
                yield DisplaysPanel(self.manager, id="displays")
                yield ImagePane(self.manager, id="image")
        yield Static("", id="status", markup=False)

    @property
    def viewport(self) -> Viewport:
        """The 3D view widget."""
        return self.query_one(Viewport)

    @property
    def panel(self) -> DisplaysPanel:
        """The Displays panel."""
        return self.query_one(DisplaysPanel)

    def on_mount(self) -> None:
        """Focus the view, start the source on a worker thread (it waits for the master), and
        expire old markers and clouds every `EXPIRY_PERIOD` seconds."""
        self.viewport.focus()
        self.run_worker(self._start, thread=True, name="rviz-start")
        self.set_interval(EXPIRY_PERIOD, self._expire)

    def changed(self) -> None:
        """Something arrived (any thread): the view redraws when it can."""
        self.changes.offer(next(self._count))

    def _start(self) -> None:
        """Start the source; while no master answers, say so and try again each second (as
        rviz waits for its master)."""
        from rosx.master.client import MasterUnreachable  # noqa: PLC0415 - the master's code loads only to talk to one

        while not self._stopping.is_set():
            try:
                self.source.start(self.manager, self.changed)
                self.source.advertise(self.tools)
            except MasterUnreachable:
                uri = getattr(self.source, "master_uri", "")
                self._tell(f"Waiting for the master {uri}".rstrip())
                self._stopping.wait(MASTER_RETRY)
                continue
            except Exception as error:  # shown, not raised: the view still works offline
                from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

                self._tell(f"rviz: {error_line(error)}")
            if self.message.startswith("Waiting for the master"):
                self._tell("")
            self.changed()
            return

    def _expire(self) -> None:
        if self.manager.expire(self.settings.clock()):
            self.viewport.schedule()

    def _tell(self, text: str) -> None:
        """`say` from another thread (nothing once the app has stopped)."""
        with contextlib.suppress(RuntimeError):
            self.app.call_from_thread(self.say, text)

    def say(self, text: str) -> None:
        """Show ``text`` on the status line."""
        self.message = text
        self.query_one("#status", Static).update(text)

    def on_unmount(self) -> None:
        """Stop waiting for the master and close the source (its node)."""
        self._stopping.set()
        self.source.close()

    # -- the panel ---------------------------------------------------------------------------

    def on_viewport_drawn(self, message: Viewport.Drawn) -> None:
        """After each drawing, bring the Displays panel and the image pane up to date."""
        self.panel.follow = self.viewport.follow
        self.panel.update_from()
        self.query_one(ImagePane).update_from()

    def on_displays_panel_toggle(self, message: DisplaysPanel.Toggle) -> None:
        """A click on a display's line in the panel toggles it, as its number key does."""
        self.action_toggle_display(message.index)

    def action_toggle_display(self, index: int) -> None:
        """1..9: show or hide the ``index``-th display, resubscribing on a worker thread."""
        display = self.manager.toggle(index)
        if display is None:
            return
        self.run_worker(self.source.sync, thread=True, group="sync")
        self.viewport.redraw()
        self.panel.update_from()

    # -- tools -------------------------------------------------------------------------------

    def _tool(self, word: str) -> Tool:
        return next(tool for tool in self.tools if tool.word == word)

    def action_tool(self, word: str) -> None:
        """G, P or C: take rviz's 2D Nav Goal, 2D Pose Estimate or Publish Point tool; the next
        click (or Enter) places it."""
        tool = self._tool(word)
        viewport = self.viewport
        if viewport.tool is None or viewport.tool.word != word:
            viewport.tool = Placing(word, self.view.x, self.view.y, self.heading, tool.heading)
        turn = " ([ ] turn)" if tool.heading else ""
        self.say(f"{tool.title}: click the view, or Enter at its centre{turn}; Esc drops it")
        viewport.redraw()

    def action_drop_tool(self) -> None:
        """Escape: put the tool down without publishing."""
        self.viewport.tool = None
        self.say("")
        self.viewport.redraw()

    def action_turn(self, direction: int) -> None:
        """[ and ]: turn the tool's heading by `HEADING_STEP` (left for +1)."""
        self.heading = math.remainder(self.heading + direction * HEADING_STEP, math.tau)
        tool = self.viewport.tool
        if tool is not None and tool.heading:
            tool.yaw = self.heading
            self.viewport.redraw()

    def action_place(self) -> None:
        """Enter: publish the tool's message at the view's centre."""
        tool = self.viewport.tool
        if tool is not None:
            self._publish(
                tool.word, self.view.x, self.view.y, self.heading if tool.heading else 0.0
            )

    def on_viewport_placed(self, message: Viewport.Placed) -> None:
        """Publish the tool's message where it was clicked (dragged for the heading)."""
        tool = self.viewport.tool
        if tool is not None:
            self._publish(tool.word, message.x, message.y, message.yaw if tool.heading else 0.0)

    def _publish(self, word: str, x: float, y: float, yaw: float) -> None:
        tool = self._tool(word)
        fixed = self.manager.fixed_frame
        self.viewport.tool = None
        self.viewport.redraw()

        def send() -> None:
            try:
                line = self.source.publish(tool, fixed, x, y, yaw)
            except Exception as error:  # a failed publish is shown, the app goes on
                from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

                line = f"{tool.title}: {error_line(error)}"
            self.published.append(line)
            self._tell(line)

        self.run_worker(send, thread=True, group="publish")

    # -- the view ----------------------------------------------------------------------------

    def _moved(self) -> None:
        tool = self.viewport.tool
        if tool is not None and not self.viewport.pressed:
            tool.x, tool.y = self.view.x, self.view.y
        self.viewport.redraw()

    def action_pan(self, columns: int, rows: int) -> None:
        """Arrow keys: pan the view by ``columns`` and ``rows`` cells; stops following a frame."""
        self.view.pan(-columns, -rows * 2)
        self.viewport.follow = None
        self._moved()

    def action_zoom(self, steps: int) -> None:
        """+ and -: zoom in or out by ``steps``."""
        self.view.zoom(steps)
        self._moved()

    def action_reset_view(self) -> None:
        """Home: back to the fixed frame's origin at the default reach; stops following a frame."""
        self.view.reset()
        self.viewport.follow = None
        self._moved()

    def action_follow(self) -> None:
        """Follow the next frame tf knows (after the last: stop following)."""
        frames = sorted(f for f in self.manager.frames.frames() if f != self.manager.fixed_frame)
        current = self.viewport.follow
        following = frames[0] if current not in frames else None
        if current in frames and frames.index(current) + 1 < len(frames):
            following = frames[frames.index(current) + 1]
        self.viewport.follow = following
        self.say(f"Following {following}" if following else "Not following a frame")
        self._moved()

    # -- files -------------------------------------------------------------------------------

    def action_save(self) -> None:
        """Ctrl+S: write the displays, view and tools to the config file (rviz's Save Config)."""
        from rosx_commands.rviz.save import save_config  # noqa: PLC0415 - this tool's parts load only when used

        path = self.settings.save_path
        try:
            save_config(
                path, self.config, self.manager, self.view, self.tools, self.viewport.follow
            )
        except OSError as error:
            self.say(f"Cannot save {path}: {error.strerror or error}")
            return
        self.say(f"Saved {path}")

    def action_snapshot(self) -> None:
        """O: write the view as a PNG in the snapshot folder, named by the time."""
        from rosx_commands.rviz.snapshot import write_png  # noqa: PLC0415 - this tool's parts load only when used

        stamp = time.strftime("%Y%m%d-%H%M%S")
        path = self.settings.snapshot_dir / f"rviz-{stamp}.png"
        try:
            width, height = write_png(
                self.manager, self.view, self.config.background, path, self.settings.clock()
            )
        except OSError as error:
            self.say(f"Cannot write {path}: {error.strerror or error}")
            return
        self.say(f"Wrote {path} ({width}x{height})")


__all__ = ["RvizPane", "RvizSettings"]
