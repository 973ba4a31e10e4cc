"""Pictures of rviz's window, one per display (pytest-textual-snapshot).

Deterministic by construction: tf and messages set by hand, a fixed clock, a source that
feeds nothing, a fixed terminal size. Update with ``pytest tests/rviz --snapshot-update``
after a deliberate change, and look at the pictures before committing.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from textual.pilot import Pilot

from rosx.msg.codec.classes import get_message_class
from rosx_commands.rviz.displays.markers import (
    ARROW,
    CUBE,
    CYLINDER,
    LINE_STRIP,
    SPHERE,
    TEXT_VIEW_FACING,
)
from rosx_commands.rviz.manager import Manager
from tests.support.rviz import app_of, config, message, occupancy, scan
from tests.support.rviz_messages import URDF, cloud, image, marker, pose_msg

SnapCompare = Callable[..., bool]
SIZE = (72, 22)


def _scan(manager: Manager) -> None:
    manager.receive(manager.displays[0], scan(), 0.0)


def _map(manager: Manager) -> None:
    manager.receive(manager.displays[0], occupancy(), 0.0)


def _cloud(manager: Manager) -> None:
    points = [(x / 10, y / 10, 0.0, 0x3080FF) for x in range(-10, 11) for y in (-10, 10)]
    manager.receive(manager.displays[0], cloud(points), 0.0)


def _pose(manager: Manager) -> None:
    manager.receive(manager.displays[0], pose_msg(-2.0, 1.0, math.pi / 4), 0.0)


def _poses(manager: Manager) -> None:
    msg = message("geometry_msgs/PoseArray", "map")
    pose_class = get_message_class("geometry_msgs/Pose")
    for i in range(12):
        pose = pose_class()
        a = i * math.tau / 12
        pose.position.x, pose.position.y = 2 * math.cos(a), 2 * math.sin(a)
        pose.orientation.z, pose.orientation.w = math.sin(a / 2 + 0.8), math.cos(a / 2 + 0.8)
        msg.poses.append(pose)
    manager.receive(manager.displays[0], msg, 0.0)


def _odometry(manager: Manager) -> None:
    for i in range(8):
        msg = message("nav_msgs/Odometry", "odom")
        a = i * 0.4
        msg.pose.pose.position.x, msg.pose.pose.position.y = -3 + 0.6 * i, math.sin(a)
        msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = math.sin(a / 2), math.cos(a / 2)
        manager.receive(manager.displays[0], msg, 0.0)


def _path(manager: Manager) -> None:
    msg = message("nav_msgs/Path", "map")
    for i in range(30):
        msg.poses.append(pose_msg(-3 + i * 0.2, 1.5 * math.sin(i / 5), 0.0, "map"))
    manager.receive(manager.displays[0], msg, 0.0)


def _polygon(manager: Manager) -> None:
    msg = message("geometry_msgs/PolygonStamped", "base_link")
    point_class = get_message_class("geometry_msgs/Point32")
    for x, y in ((1.0, 0.6), (1.0, -0.6), (-1.0, -0.6), (-1.0, 0.6)):
        msg.polygon.points.append(point_class(x=x, y=y, z=0.0))
    manager.receive(manager.displays[0], msg, 0.0)


def _markers(manager: Manager) -> None:
    point_class = get_message_class("geometry_msgs/Point")
    kinds = [(ARROW, -3.0, 2.0), (CUBE, -1.0, 2.0), (SPHERE, 1.0, 2.0), (CYLINDER, 3.0, 2.0)]
    msgs = []
    for n, (kind, x, y) in enumerate(kinds):
        msg = marker(kind, n)
        msg.pose.position.x, msg.pose.position.y = x, y
        msg.color.g = 0.25 * n
        msgs.append(msg)
    strip = marker(LINE_STRIP, 10)
    strip.scale.x = 0.05
    strip.points = [point_class(x=-3.0 + i * 0.5, y=-1.0 + (i % 2), z=0.0) for i in range(13)]
    text = marker(TEXT_VIEW_FACING, 11)
    text.pose.position.y, text.text = -2.5, "rosx"
    msgs += [strip, text]
    display = manager.displays[0]
    if display.MESSAGE_TYPE == "visualization_msgs/MarkerArray":
        array = message("visualization_msgs/MarkerArray")
        array.markers = msgs
        manager.receive(display, array, 0.0)
    else:
        for msg in msgs:
            manager.receive(display, msg, 0.0)


def _robot(manager: Manager) -> None:
    manager.receive(manager.displays[0], URDF.replace("0.14 0.14 0.14", "1.4 0.9 0.2"), 0.0)


def _image(manager: Manager) -> None:
    y, x = np.mgrid[0:48, 0:64]
    pixels = np.stack([x * 4, y * 5, np.full_like(x, 128)], axis=2).astype(np.uint8)
    manager.receive(manager.displays[0], image("rgb8", pixels), 0.0)


SCENES: dict[str, tuple[str, Callable[[Manager], None] | None]] = {
    "grid": ("{Class: rviz/Grid, Name: Grid, Cell Size: 0.5}", None),
    "map": ("{Class: rviz/Map, Name: Map, Topic: /map}", _map),
    "laser_scan": ("{Class: rviz/LaserScan, Name: Laser, Topic: /scan, Size (Pixels): 2}", _scan),
    "point_cloud2": ("{Class: rviz/PointCloud2, Name: Cloud, Topic: /points}", _cloud),
    "tf": ("{Class: rviz/TF, Name: TF}", None),
    "axes": ("{Class: rviz/Axes, Name: Axes, Reference Frame: base_link}", None),
    "pose": ("{Class: rviz/Pose, Name: Goal, Topic: /goal}", _pose),
    "pose_array": ("{Class: rviz/PoseArray, Name: Particles, Topic: /particlecloud}", _poses),
    "odometry": (
        "{Class: rviz/Odometry, Name: Odometry, Topic: /odom, Shaft Length: 0.4}",
        _odometry,
    ),
    "path": ("{Class: rviz/Path, Name: Plan, Topic: /plan}", _path),
    "polygon": ("{Class: rviz/Polygon, Name: Footprint, Topic: /footprint}", _polygon),
    "marker": ("{Class: rviz/Marker, Name: Marker}", _markers),
    "marker_array": ("{Class: rviz/MarkerArray, Name: Markers}", _markers),
    "robot_model": ("{Class: rviz/RobotModel, Name: Robot}", _robot),
    "image": ("{Class: rviz/Image, Name: Camera, Image Topic: /image}", _image),
}


@pytest.mark.parametrize("name", sorted(SCENES))
def test_snapshot_of_each_display(name: str, snap_compare: SnapCompare) -> None:
    display, feed = SCENES[name]
    app = app_of(config(display))
    if feed is not None:
        feed(app.manager)

    async def settle(pilot: Pilot[Any]) -> None:
        await pilot.pause()
        await pilot.app.workers.wait_for_complete()
        await pilot.pause()

    assert snap_compare(app, terminal_size=SIZE, run_before=settle)
