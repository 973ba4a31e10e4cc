"""Drawing a running stageros full-screen until the user quits or the node shuts down."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_turtle.stage.view.app import make_stage_app
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.running import run_app

if TYPE_CHECKING:
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.stage.node.stageros import StageNode
    from rosx_turtle.tui.log import LogRecord


def show_world(node: StageNode, logs: Feed[LogRecord] | None = None) -> None:
    """Draw ``node``'s world until ``q``, Ctrl-C, SIGTERM or a shutdown from outside."""
    steps: Feed[StepReport] = Feed()
    remove = node.add_step_listener(steps.offer)
    snapshot = node.snapshot()
    try:
        run_app(
            make_stage_app(snapshot.world, snapshot.grid, snapshot.names, steps, logs),
            gone=node.wait_for_shutdown,
        )
    finally:
        remove()
