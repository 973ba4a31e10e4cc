"""Scenes for rviz's tests: configs as text, tf filled by hand, messages built in place, and a
source that feeds nothing and records what the tools publish (no network, fixed clock)."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from rosx.msg.codec.classes import get_message_class
from rosx.tf.core import BufferCore
from rosx_commands.rviz.app import RvizApp, RvizSettings, make_rviz_app
from rosx_commands.rviz.config import RvizConfig, parse_config
from rosx_commands.rviz.manager import Manager
from rosx_commands.rviz.tools import Tool, configured
from rosx_commands.rviz.view import View

#: The time every test's displays see (seconds).
NOW = 100.0
#: The stamp of every transform and message (ns).
STAMP = 5_000_000_000


def config(*displays: str, fixed: str = "map", extra: str = "") -> RvizConfig:
    """A config whose displays are the flow mappings ``displays`` (``{Class: rviz/Grid,
    Name: Grid}``…)."""
    lines = "\n".join(f"    - {display}" for display in displays)
    text = (
        f"Visualization Manager:\n  Displays:\n{lines or '    []'}\n"
        f"  Global Options:\n    Fixed Frame: {fixed}\n{extra}"
    )
    return parse_config(text, "test.rviz")


def robot_tf() -> BufferCore:
    """map → odom (static, 1 m along x) → base_link (moving: (0.5, 0.5), facing +y) → laser
    (static, 0.1 m ahead)."""
    core = BufferCore()
    core.set("map", "odom", 0, (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), is_static=True)
    half = math.pi / 4
    core.set("odom", "base_link", STAMP, (0.5, 0.5, 0.0, 0.0, 0.0, math.sin(half), math.cos(half)))
    core.set("base_link", "laser", 0, (0.1, 0.0, 0.2, 0.0, 0.0, 0.0, 1.0), is_static=True)
    return core


def message(type_name: str, frame: str = "map", **fields: Any) -> Any:
    """A message of ``type_name`` with ``header.frame_id = frame`` stamped `STAMP`."""
    msg = get_message_class(type_name)()
    if hasattr(msg, "header"):
        msg.header.frame_id = frame
        msg.header.stamp.secs, msg.header.stamp.nsecs = divmod(STAMP, 1_000_000_000)
    for name, value in fields.items():
        setattr(msg, name, value)
    return msg


def scan(frame: str = "laser", beams: int = 181, reach: float = 2.0) -> Any:
    """A half-circle scan (-90°…90°) of ``beams`` beams all reading ``reach`` metres, with one
    beam beyond range_max and one NaN (neither is drawn)."""
    ranges = np.full(beams, reach, dtype=np.float32)
    ranges[0] = 50.0
    ranges[1] = np.nan
    return message(
        "sensor_msgs/LaserScan",
        frame,
        angle_min=-math.pi / 2,
        angle_max=math.pi / 2,
        angle_increment=math.pi / (beams - 1),
        range_min=0.1,
        range_max=30.0,
        ranges=ranges,
        intensities=np.linspace(0, 100, beams).astype(np.float32),
    )


def occupancy(width: int = 80, height: int = 60, resolution: float = 0.1) -> Any:
    """A map ``width`` by ``height`` cells from (-4, -3): free, walls round the edge, an
    unknown block in the lower left."""
    cells = np.zeros((height, width), dtype=np.int8)
    cells[0, :] = cells[-1, :] = 100
    cells[:, 0] = cells[:, -1] = 100
    cells[1:15, 1:20] = -1
    msg = message("nav_msgs/OccupancyGrid", "map", data=cells.ravel())
    msg.info.width, msg.info.height, msg.info.resolution = width, height, resolution
    msg.info.origin.position.x = -width * resolution / 2
    msg.info.origin.position.y = -height * resolution / 2
    msg.info.origin.orientation.w = 1.0
    return msg


class FakeSource:
    """A `Source` with nothing behind it: it records what the tools publish."""

    master_uri = "http://localhost:11311/"

    def __init__(self) -> None:
        self.published: list[tuple[str, str, float, float, float]] = []
        self.synced = 0
        self.started = False

    def start(self, manager: Manager, changed: Callable[[], object]) -> None:
        self.started = True

    def sync(self) -> None:
        self.synced += 1

    def advertise(self, tools: tuple[Tool, ...]) -> None:
        pass

    def publish(self, tool: Tool, fixed: str, x: float, y: float, yaw: float) -> str:
        self.published.append((tool.topic, fixed, round(x, 3), round(y, 3), round(yaw, 3)))
        return f"{tool.title} at {x:.3f} {y:.3f} {yaw:.3f} [frame={fixed}]"

    def param(self, name: str) -> Any:
        return None

    def close(self) -> None:
        pass


def app_of(
    conf: RvizConfig,
    core: BufferCore | None = None,
    *,
    tmp: Path | None = None,
    fixed: str | None = None,
    source: FakeSource | None = None,
) -> RvizApp:
    """rviz's app over ``conf`` and ``core`` with a `FakeSource` and a fixed clock."""
    manager = Manager(conf, core or robot_tf(), fixed)
    folder = tmp or Path("/nonexistent")
    settings = RvizSettings(folder / "saved.rviz", folder, clock=lambda: NOW)
    return make_rviz_app(
        conf, manager, source or FakeSource(), View.from_spec(conf.view), configured(conf.tools),
        settings,
    )  # fmt: skip


__all__ = [
    "NOW",
    "STAMP",
    "FakeSource",
    "app_of",
    "config",
    "message",
    "occupancy",
    "robot_tf",
    "scan",
]
