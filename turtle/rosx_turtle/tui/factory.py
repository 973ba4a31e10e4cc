"""The apps as the commands run them and the tests drive them: one factory each."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.link import SimLink
    from rosx_turtle.tui.log import LogRecord
    from rosx_turtle.tui.pond_app import PondApp
    from rosx_turtle.tui.ponds_app import PondsApp
    from rosx_turtle.tui.sim_app import SimApp
    from rosx_turtle.view.scene import Scene


def make_pond_app(scenes: Feed[Scene], logs: Feed[LogRecord] | None = None) -> PondApp:
    """turtlesim_node's terminal window: the scenes offered to ``scenes``, the latest log line."""
    from rosx_turtle.tui.pond_app import PondApp  # noqa: PLC0415 - textual only when drawn

    return PondApp(scenes, logs)


def make_ponds_app(started: Callable[[], object] | None = None) -> PondsApp:
    """turtlesim_view's window (ponds are added as the graph shows them); ``started`` runs once
    it is up."""
    from rosx_turtle.tui.ponds_app import PondsApp  # noqa: PLC0415 - textual only when drawn

    return PondsApp(started)


def make_sim_app(link: SimLink, *, notice: str | None = None) -> SimApp:
    """``rosx sim``'s terminal UI over ``link``, the teleop pane focused; ``notice`` shown
    for a while when it starts."""
    from rosx_turtle.tui.sim_app import SimApp  # noqa: PLC0415 - textual only when drawn

    return SimApp(link, notice=notice)
