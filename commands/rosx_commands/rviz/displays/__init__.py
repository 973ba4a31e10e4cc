"""rviz's displays, one module each, and `make_display`: a config's display by its class.

Classes rosx cannot draw become `base.Unsupported` displays: listed as "unsupported", kept
for saving, never subscribed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_commands.rviz.displays.axes import Axes
from rosx_commands.rviz.displays.base import Display, Unsupported
from rosx_commands.rviz.displays.grid import Grid
from rosx_commands.rviz.displays.image import Image
from rosx_commands.rviz.displays.laser_scan import LaserScan
from rosx_commands.rviz.displays.map import Map
from rosx_commands.rviz.displays.markers import Marker, MarkerArray
from rosx_commands.rviz.displays.path import Path, Polygon
from rosx_commands.rviz.displays.point_cloud2 import PointCloud2
from rosx_commands.rviz.displays.poses import Odometry, Pose, PoseArray
from rosx_commands.rviz.displays.robot_model import RobotModel
from rosx_commands.rviz.displays.tf import TF

if TYPE_CHECKING:
    from rosx_commands.rviz.config import DisplaySpec

DISPLAYS: tuple[type[Display], ...] = (
    Grid, Axes, Map, LaserScan, PointCloud2, TF, Path, Polygon, Odometry, Pose, PoseArray,
    Marker, MarkerArray, RobotModel, Image,
)  # fmt: skip
#: rviz class name → display class.
CLASSES: dict[str, type[Display]] = {name: kind for kind in DISPLAYS for name in kind.CLASSES}
#: Message type → the class rviz offers for it ("Add" by topic).
BY_TYPE: dict[str, str] = {
    kind.MESSAGE_TYPE: kind.CLASSES[0] for kind in DISPLAYS if kind.MESSAGE_TYPE is not None
}


def make_display(spec: DisplaySpec) -> Display:
    """The display of ``spec`` (an `Unsupported` one for a class rosx cannot draw)."""
    return CLASSES.get(spec.class_id, Unsupported)(spec)


__all__ = ["BY_TYPE", "CLASSES", "DISPLAYS", "Display", "Unsupported", "make_display"]
