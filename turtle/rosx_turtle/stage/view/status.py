"""`RobotLine`: one line with each robot's name, pose and stall, updated as they move."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows

if TYPE_CHECKING:
    from rosx_turtle.stage.engine.simulation import StepReport
    from rosx_turtle.tui.feed import Feed


def robot_text(names: tuple[str, ...], report: StepReport) -> str:
    """``name x=… y=… θ=…°`` for each robot (``STALL`` when it bumped), and the clock."""
    parts = [f"t={report.time_ns / 1e9:.1f}s"]
    for name, (x, y, yaw), stalled in zip(
        names, report.pose.tolist(), report.stalled.tolist(), strict=True
    ):
        parts.append(
            f"{name} x={x:.2f} y={y:.2f} θ={math.degrees(yaw):.0f}°" + (" STALL" if stalled else "")
        )
    return "  ".join(parts)


class RobotLine(Follows["StepReport"], Static):
    """The robots' poses, from the steps ``feed`` offers."""

    DEFAULT_CSS = """
    RobotLine {
        height: 1;
        width: 1fr;
        padding: 0 1;
        background: $panel;
        color: $text;
    }
    """

    def __init__(
        self, names: tuple[str, ...], feed: Feed[StepReport] | None = None, *, id: str | None = None
    ) -> None:
        super().__init__("", id=id, markup=False)
        self.names = names
        self.feed = feed
        self.text = ""

    def show(self, value: StepReport) -> None:
        """Show the poses of step ``value``."""
        text = robot_text(self.names, value)
        if text != self.text:
            self.text = text
            self.update(text)
