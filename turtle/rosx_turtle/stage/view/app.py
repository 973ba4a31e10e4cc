"""`StageApp`: stageros's window in a terminal: the world, the robots' poses, the latest log."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, ClassVar

from textual.app import App  # noqa: TID253 - TUI code
from textual.binding import Binding, BindingType  # noqa: TID253 - TUI code

from rosx_turtle.stage.view.status import RobotLine
from rosx_turtle.stage.view.widget import WorldView
from rosx_turtle.tui.log_line import LogLine
from rosx_turtle.tui.quit import QuitFooter

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.world.model import World
    from rosx_turtle.tui.feed import Feed
    from rosx_turtle.tui.log import LogRecord


class StageApp(App[None]):
    """The world full-screen, the poses and the latest log line; ``q`` or Ctrl-C quits."""

    TITLE = "Stage"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("q", "quit", "Quit"),
        Binding("ctrl+c", "quit", "Quit", show=False, priority=True),
    ]

    def __init__(
        self,
        world: World,
        grid: Grid,
        names: tuple[str, ...],
        steps: Feed[StepReport],
        logs: Feed[LogRecord] | None = None,
    ) -> None:
        super().__init__()
        self.world, self.grid, self.names = world, grid, names
        self.steps = steps
        self.logs = logs

    @override
    def compose(self) -> ComposeResult:
        yield WorldView(self.world, self.grid, self.steps, id="world")
        yield RobotLine(self.names, self.steps, id="robots")
        yield LogLine(self.logs, id="log")
        yield QuitFooter()


def make_stage_app(
    world: World,
    grid: Grid,
    names: tuple[str, ...],
    steps: Feed[StepReport],
    logs: Feed[LogRecord] | None = None,
) -> StageApp:
    """stageros's terminal window (the factory the program and the tests share)."""
    return StageApp(world, grid, names, steps, logs)
