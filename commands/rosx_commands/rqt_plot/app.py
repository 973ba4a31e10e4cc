"""`PlotPane`: rqt_plot in the terminal, live; `PlotApp` runs it alone, ``rosx rqt`` as a tab.

The pane draws its series over a time window that ends now (textual-plot's `PlotWidget`, in
braille). It redraws at most ``fps`` times a second and only when a sample arrived, the
window or the axes changed: idle, a tick costs a comparison of counters (rqt_common_plugins
#219). Each series is thinned to two points per column before drawing (`series.envelope`),
so a 1 kHz topic costs what a 10 Hz one does.

Keys: ``a`` adds a series (``TOPIC/FIELD``, rqt_plot's ``x:y`` shorthand too), ``x`` or
``delete`` removes the one selected in the legend, ``space`` pauses, ``c`` clears, ``s``
switches between autoscale and fixed y axes, ``[`` and ``]`` shorten and lengthen the time
window; ``q`` or ``ctrl+c`` quit.
"""

from __future__ import annotations

import itertools
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar

from rich.text import Text
from textual.app import ComposeResult  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code
from textual.containers import Vertical  # noqa: TID253 - TUI code
from textual.widgets import Input, OptionList, Static  # noqa: TID253 - TUI code
from textual.widgets.option_list import Option  # noqa: TID253 - TUI code

from rosx_commands.paneapp import PaneApp
from rosx_commands.rqt_plot.series import Series, SeriesError, envelope, expand_args

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from collections.abc import Sequence

    from textual_plot import PlotWidget

    from rosx_commands.context import Environment
    from rosx_commands.rqt_plot.feed import PlotFeed

#: Colours given to series in turn.
COLOURS = ("#4fc3f7", "#f06292", "#ffd54f", "#81c784", "#ff8a65", "#ba68c8", "#e0e0e0")
#: The time windows ``[`` and ``]`` step through, in seconds.
WINDOWS = (1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1800.0, 3600.0)
#: Seconds between two tries to attach series whose topics are not published yet.
RETRY_PERIOD = 1.0


@dataclass
class PlotSettings:
    """What the command line sets: the window, fixed y limits (None: autoscale), pause, fps."""

    window: float = 10.0
    ymin: float | None = None
    ymax: float | None = None
    paused: bool = False
    fps: float = 10.0


class PlotPane(Vertical):
    """The plot, its legend (the series, selectable), a status line and an entry line."""

    DEFAULT_CSS = """
    PlotPane #plot-status { height: 1; background: $boost; }
    PlotPane #plot { height: 1fr; min-height: 6; }
    PlotPane #legend { height: auto; max-height: 5; border: none; }
    PlotPane #add { display: none; }
    PlotPane #add.editing { display: block; }
    """
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("a", "add", "Add"),
        Binding("x,delete", "remove", "Remove"),
        Binding("space", "pause", "Pause"),
        Binding("c", "clear", "Clear"),
        Binding("s", "autoscale", "Autoscale"),
        Binding("left_square_bracket", "window(-1)", "Window -", show=False),
        Binding("right_square_bracket", "window(1)", "Window +", show=False),
    ]

    def __init__(
        self,
        feed: PlotFeed,
        names: Sequence[str] = (),
        settings: PlotSettings | None = None,
        *,
        id: str | None = None,
    ) -> None:
        super().__init__(id=id)
        self.feed = feed
        self.settings = settings or PlotSettings()
        self.series: list[Series] = []
        self.pending: list[Series] = []
        self.message = ""
        self._colours = itertools.cycle(COLOURS)
        self._initial = expand_args(names)
        self._shown: tuple[object, ...] | None = None
        self.frames = 0  # how often the plot was drawn (tests and the bench look)

    @override
    def compose(self) -> ComposeResult:
        from textual_plot import PlotWidget  # textual-plot only once a plot is drawn

        yield Static(id="plot-status")
        plot = PlotWidget(id="plot", allow_pan_and_zoom=False)
        plot.can_focus = False
        yield plot
        yield OptionList(id="legend")
        yield Input(id="add", placeholder="TOPIC/FIELD (e.g. /turtle1/pose/x, /scan/ranges[0])")

    @property
    def plot(self) -> PlotWidget:
        """The plot widget (textual-plot's)."""
        from textual_plot import PlotWidget  # textual-plot only once a plot is drawn

        return self.query_one("#plot", PlotWidget)

    def on_mount(self) -> None:
        """Lay the plot out, add the series given on the command line, and start redrawing at the
        settings' frame rate and retrying unpublished topics every `RETRY_PERIOD` seconds."""
        self.plot.margin_left = 8
        self.plot.margin_top = 0
        self.plot.margin_bottom = 2
        self.query_one("#legend", OptionList).focus()
        self._add_names(self._initial)
        self.set_interval(1 / self.settings.fps, self._tick)
        self.set_interval(RETRY_PERIOD, self._retry)
        self._status()

    # -- series ------------------------------------------------------------------------------

    def add_series(self, text: str) -> None:
        """Add the series ``text`` names (rqt_plot's shorthand allowed)."""
        try:
            names = expand_args([text])
        except SeriesError as error:
            self._say(str(error))
            return
        self._add_names(names)

    def _add_names(self, names: Sequence[str]) -> None:
        known = {s.name for s in self.series}
        for name in names:
            if name in known:
                continue
            known.add(name)
            series = Series(name, next(self._colours))
            series.status = "connecting"
            self.series.append(series)
            self.pending.append(series)
        self._legend()
        self._retry()

    def _retry(self) -> None:
        if self.pending and not any(w.group == "attach" and w.is_running for w in self.workers):
            self.run_worker(self._attach_pending, thread=True, group="attach")

    def _attach_pending(self) -> None:
        for series in list(self.pending):
            try:
                attached = self.feed.attach(series)
            except SeriesError as error:
                self.app.call_from_thread(self._refused, series, str(error))
                continue
            except Exception as error:
                self.app.call_from_thread(self._failed, error)
                return
            if attached:
                self.app.call_from_thread(self._attached, series)
        self.app.call_from_thread(self._legend)

    def _attached(self, series: Series) -> None:
        if series.status == "connecting":
            series.status = ""
        if series in self.pending:
            self.pending.remove(series)
        if series not in self.series:  # removed meanwhile
            self.run_worker(lambda: self.feed.detach(series), thread=True)

    def _refused(self, series: Series, message: str) -> None:
        for kept in (self.series, self.pending):
            if series in kept:
                kept.remove(series)
        self._say(message)
        self._legend()

    def _failed(self, error: Exception) -> None:
        from rosx_commands.errors import error_line  # noqa: PLC0415 - this tool's parts load only when used

        self._say(error_line(error))

    def remove_series(self, name: str) -> None:
        """Remove the series called ``name`` and unsubscribe from it on a worker thread; unknown
        names are ignored."""
        series = next((s for s in self.series if s.name == name), None)
        if series is None:
            return
        self.series.remove(series)
        if series in self.pending:
            self.pending.remove(series)
        else:
            self.run_worker(lambda: self.feed.detach(series), thread=True)
        self._legend()
        self._shown = None

    # -- actions -----------------------------------------------------------------------------

    def action_add(self) -> None:
        """A: open the line to type a series to add (``/topic/field``)."""
        line = self.query_one("#add", Input)
        line.value = ""
        line.add_class("editing")
        line.focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Add the typed series, if any, and close the line."""
        event.stop()
        self._close_entry()
        if event.value.strip():
            self.add_series(event.value.strip())

    def key_escape(self) -> None:
        """Escape closes the add line."""
        self._close_entry()

    def _close_entry(self) -> None:
        self.query_one("#add", Input).remove_class("editing")
        self.query_one("#legend", OptionList).focus()

    def action_remove(self) -> None:
        """X or Delete: remove the series highlighted in the legend."""
        legend = self.query_one("#legend", OptionList)
        if legend.highlighted is not None and legend.highlighted < len(self.series):
            self.remove_series(self.series[legend.highlighted].name)

    def action_pause(self) -> None:
        """Space: pause or resume the plot; samples keep arriving meanwhile."""
        self.settings.paused = not self.settings.paused
        self._shown = None
        self._status()

    def action_clear(self) -> None:
        """C: drop every series' samples."""
        for series in self.series:
            series.clear()

    def action_autoscale(self) -> None:
        """S: fix the y axis at the current range, or go back to autoscaling."""
        settings = self.settings
        if settings.ymin is None or settings.ymax is None:
            plot = self.plot
            settings.ymin, settings.ymax = plot._y_min, plot._y_max
        else:
            settings.ymin = settings.ymax = None
        self._shown = None
        self._status()

    def action_window(self, step: int) -> None:
        """[ and ]: the previous or next time window of `WINDOWS`."""
        window = self.settings.window
        if step > 0:
            self.settings.window = next((w for w in WINDOWS if w > window), WINDOWS[-1])
        else:
            self.settings.window = next((w for w in reversed(WINDOWS) if w < window), WINDOWS[0])
        self._shown = None
        self._status()

    # -- drawing -----------------------------------------------------------------------------

    def _tick(self) -> None:
        if self.settings.paused:
            return
        state = (
            tuple((id(s), s.received, s.status) for s in self.series),
            self.settings.window,
            self.settings.ymin,
            self.settings.ymax,
            self.plot.size,
        )
        if state == self._shown:
            return  # nothing new: no drawing at all while idle
        self._shown = state
        self.redraw()

    def redraw(self) -> None:
        """Draw the window ending now, and the legend's latest values."""
        settings = self.settings
        end = self.feed.now()
        start = end - settings.window
        plot = self.plot
        columns = 2 * max(plot.size.width, 1)  # braille: two dots a cell
        from textual_plot import HiResMode  # textual-plot only once a plot is drawn

        plot.clear()
        for series in self.series:
            times, values = series.window(start, end)
            xs, ys = envelope(times, values, start, end, columns)
            plot.plot(xs, ys, line_style=series.style, hires_mode=HiResMode.BRAILLE)
        plot.set_xlimits(start, end)
        plot.set_ylimits(settings.ymin, settings.ymax)
        self.frames += 1
        self._legend()

    def _legend(self) -> None:
        legend = self.query_one("#legend", OptionList)
        highlighted = legend.highlighted
        options = []
        for series in self.series:
            text = Text("━━ ", style=series.style)
            text.append(series.name)
            latest = series.latest
            if series.status:
                text.append(f"  ({series.status})", style="dim")
            elif latest is not None:
                text.append(f"  {latest:.6g}", style="bold")
            options.append(Option(text))
        legend.set_options(options)
        if options:
            legend.highlighted = min(highlighted or 0, len(options) - 1)
        legend.display = bool(options)

    def _status(self) -> None:
        settings = self.settings
        state = "paused" if settings.paused else "live"
        if settings.ymin is None or settings.ymax is None:
            axes = "y auto"
        else:
            axes = f"y {settings.ymin:.4g}…{settings.ymax:.4g}"
        text = f" {state} │ window {settings.window:g} s ([ ]) │ {axes}"
        if not self.series:
            text += " │ a: add a series (TOPIC/FIELD)"
        if self.message:
            text += f" │ {self.message}"
        self.query_one("#plot-status", Static).update(Text(text, no_wrap=True, overflow="fold"))

    def _say(self, message: str) -> None:
        self.message = message
        self._status()

    def on_unmount(self) -> None:
        """Close the feed (its node)."""
        self.feed.close()


class PlotApp(PaneApp[PlotPane]):
    """``rosx rqt_plot`` on its own: the pane and a footer."""


def make_plot_app(
    feed: PlotFeed, names: Sequence[str] = (), settings: PlotSettings | None = None
) -> PlotApp:
    """The app the CLI runs and the tests drive."""
    return PlotApp(PlotPane(feed, names, settings))


def plot_tab(env: Environment) -> PlotPane:
    """rqt_plot as a tab of ``rosx rqt``: no series until the user adds some."""
    from rosx_commands.rqt_plot.feed import LiveFeed  # noqa: PLC0415 - this tool's parts load only when used

    return PlotPane(LiveFeed(env))
