"""`RobotPanel`: the driven robot as its topics tell it: odometry, speeds, the nearest hit."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from textual.widgets import Static  # noqa: TID253 - TUI code

from rosx_turtle.tui.feed import Follows

if TYPE_CHECKING:
    from rosx_turtle.stage.engine.simulation import Scan, StepReport
    from rosx_turtle.tui.feed import Feed


def nearest_hit(scan: Scan) -> tuple[float, float] | None:
    """The shortest range of a scan below its ``range_max``, and its beam's angle (radians, in
    the laser's frame); None when every beam read nothing."""
    ranges = scan.ranges
    index = int(ranges.argmin())
    reading = float(ranges[index])
    if reading >= scan.spec.range_max:
        return None
    return reading, -scan.spec.fov / 2 + index * scan.spec.angle_increment


def robot_text(
    report: StepReport, robot: int, odom: str, scan_topic: str, scan: Scan | None
) -> str:
    """The panel's lines for ``robot``: what ``odom`` reads (pose, speeds) and the nearest
    obstacle on ``scan_topic`` (``scan``: its latest reading)."""
    x, y, yaw = report.odom[robot].tolist()
    forward, sideways, turn = report.velocity[robot].tolist()
    lines = [
        f"{odom}  x={x:.2f} y={y:.2f} θ={math.degrees(yaw):.0f}°",
        f"  linear.x={forward:.2f} angular.z={turn:.2f}"
        + (f" y={sideways:.2f}" if sideways else ""),
    ]
    hit = nearest_hit(scan) if scan is not None else None
    if scan is None:
        lines.append(f"{scan_topic}  no scan yet")
    elif hit is None:
        lines.append(f"{scan_topic}  nothing within {scan.spec.range_max:g} m")
    else:
        lines.append(f"{scan_topic}  nearest {hit[0]:.2f} m at {math.degrees(hit[1]):.0f}°")
    if report.stalled[robot]:
        lines.append("STALL: bumped into something")
    return "\n".join(lines)


class RobotPanel(Follows["StepReport"], Static):
    """Robot ``robot``'s odometry and laser, from the steps ``feed`` offers."""

    DEFAULT_CSS = """
    RobotPanel {
        height: 6;
        padding: 0 1;
        border: round $panel-lighten-2;
        border-title-color: $text-muted;
    }
    """

    def __init__(
        self,
        feed: Feed[StepReport] | None = None,
        *,
        robot: int = 0,
        odom: str = "/odom",
        scan_topic: str = "/base_scan",
        title: str = "Robot",
        id: str | None = None,
    ) -> None:
        super().__init__("", id=id, markup=False)
        self.feed = feed
        self.robot = robot
        self.odom = odom
        self.scan_topic = scan_topic
        self.scan: Scan | None = None
        self.text = ""
        self.border_title = title

    def show(self, value: StepReport) -> None:
        """Show the robot in step ``value`` (its laser's latest scan kept between scans)."""
        if self.robot >= value.pose.shape[0]:
            return
        for scan in value.scans:
            if scan.robot == self.robot and scan.laser == 0:
                self.scan = scan
        text = robot_text(value, self.robot, self.odom, self.scan_topic, self.scan)
        if text != self.text:
            self.text = text
            self.update(text)
