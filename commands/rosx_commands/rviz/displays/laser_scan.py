"""rviz's LaserScan: each ``sensor_msgs/LaserScan`` as the points its beams hit. As
laser_geometry projects for rviz, a beam gives no point when it is not finite, below
``range_min``, or at ``range_max`` and beyond (a beam that hit nothing)."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx.tf.stamps import nanos
from rosx_commands.rviz.displays.clouds import Cloud, CloudDisplay
from rosx_commands.rviz.frames import clean

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt


def scan_points(msg: Any) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64] | None]:
    """The points (``(n, 3)``, in the scan's frame) and intensities of a scan's valid beams."""
    ranges = np.asarray(msg.ranges, dtype=np.float64)
    angles = msg.angle_min + np.arange(ranges.size) * msg.angle_increment
    valid = np.isfinite(ranges) & (ranges >= msg.range_min) & (ranges < msg.range_max)
    r, a = ranges[valid], angles[valid]
    xyz = np.column_stack([r * np.cos(a), r * np.sin(a), np.zeros(r.size)])
    intensities = np.asarray(msg.intensities, dtype=np.float64)
    return xyz, (intensities[valid] if intensities.size == ranges.size else None)


class LaserScan(CloudDisplay):
    """rviz's LaserScan display: the points of the latest scans."""

    CLASSES = ("rviz/LaserScan",)
    MESSAGE_TYPE = "sensor_msgs/LaserScan"
    DEFAULT_TOPIC = ""

    @override
    def take(self, msg: Any, now: float) -> None:
        xyz, intensity = scan_points(msg)
        header = msg.header
        self.keep(Cloud(clean(header.frame_id), nanos(header.stamp), now, xyz, intensity), now)
