"""rviz's Path (``nav_msgs/Path``: the poses joined by a line, the last ``Buffer Length``
paths kept, each pose drawn as ``Pose Style`` says) and Polygon
(``geometry_msgs/PolygonStamped``: its outline, closed)."""

from __future__ import annotations

import sys
from collections import deque
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx.tf.stamps import nanos
from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.displays.shapes import arrow, axes
from rosx_commands.rviz.frames import clean
from rosx_commands.rviz.geometry import apply, compose, pose_transform
from rosx_commands.rviz.primitives import Layer, Segments

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform


class Path(Display):
    """rviz's Path display: the poses of a path as a line."""

    CLASSES = ("rviz/Path",)
    MESSAGE_TYPE = "nav_msgs/Path"

    @override
    def clear(self) -> None:
        self.paths: deque[tuple[str, int, list[Transform]]] = deque()

    @override
    def take(self, msg: Any, now: float) -> None:
        poses = [pose_transform(stamped.pose) for stamped in msg.poses]
        self.paths.append((clean(msg.header.frame_id), nanos(msg.header.stamp), poses))
        while len(self.paths) > max(1, int(self.number("Buffer Length", 1))):
            self.paths.popleft()

    @override
    def draw(self, context: Context) -> Layer:
        colour = self.colour("Color", (25, 255, 0))
        alpha = self.number("Alpha", 1.0)
        style = str(self.option("Pose Style", "None"))
        layer = Layer()
        for frame, stamp, poses in self.paths:
            answer = context.frames.lookup(frame, stamp)
            if not self.transform_status(frame, answer) or isinstance(answer, str) or not poses:
                continue
            xy = apply(answer, np.array([pose[:3] for pose in poses]))[:, :2]
            if len(xy) > 1:
                layer.segments.append(
                    Segments(np.stack([xy[:-1], xy[1:]], axis=1), colour, alpha=alpha)
                )
            for pose in poses if style != "None" else ():
                placed = compose(answer, pose)
                if style == "Axes":
                    layer.extend(axes(placed, self.number("Length", 0.3)))
                else:
                    length = self.number("Shaft Length", 0.1) + self.number("Head Length", 0.2)
                    layer.extend(
                        arrow(placed, length, self.number("Head Length", 0.2),
                              self.number("Head Diameter", 0.3) / 2,
                              self.colour("Pose Color", (255, 85, 255)))
                    )  # fmt: skip
        return layer


class Polygon(Display):
    """rviz's Polygon display: a polygon's outline."""

    CLASSES = ("rviz/Polygon",)
    MESSAGE_TYPE = "geometry_msgs/PolygonStamped"

    @override
    def clear(self) -> None:
        self.latest: tuple[str, int, npt.NDArray[np.float64]] | None = None

    @override
    def take(self, msg: Any, now: float) -> None:
        corners = np.array([[p.x, p.y, p.z] for p in msg.polygon.points], dtype=np.float64)
        self.latest = (clean(msg.header.frame_id), nanos(msg.header.stamp), corners.reshape(-1, 3))

    @override
    def draw(self, context: Context) -> Layer:
        if self.latest is None or len(self.latest[2]) == 0:
            return Layer()
        frame, stamp, corners = self.latest
        answer = context.frames.lookup(frame, stamp)
        if not self.transform_status(frame, answer) or isinstance(answer, str):
            return Layer()
        xy = apply(answer, corners)[:, :2]
        ends = np.stack([xy, np.roll(xy, -1, axis=0)], axis=1)
        return Layer(
            segments=[
                Segments(ends, self.colour("Color", (25, 255, 0)), alpha=self.number("Alpha", 1.0))
            ]
        )
