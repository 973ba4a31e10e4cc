"""rviz's pose displays: Pose (``geometry_msgs/PoseStamped``; rviz saves the class as
``rviz/Pose``, older configs say ``rviz/PoseStamped``), PoseArray and Odometry (the last
``Keep`` poses, a new one kept when it moved more than ``Position Tolerance`` or turned more
than ``Angle Tolerance``). Each is an arrow (``Shape: Arrow``, rviz's sizes and colour) or
axes (``Shape: Axes``)."""

from __future__ import annotations

import math
import sys
from collections import deque
from typing import TYPE_CHECKING, Any

from rosx.tf.stamps import nanos
from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.displays.shapes import arrow, axes, flat_arrow
from rosx_commands.rviz.frames import clean
from rosx_commands.rviz.geometry import compose, pose_transform, valid_quaternion, yaw_of
from rosx_commands.rviz.primitives import Layer

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform

POSE_COLOUR = (255, 25, 0)
#: The shortest arrow drawn, in pixels.
MIN_ARROW_PIXELS = 5.0


class PoseShapes(Display):
    """What the three share: drawing one pose in the display's shape."""

    def shape(self, pose: Transform, context: Context) -> Layer:
        """``pose`` drawn as the ``Shape`` option says: rviz's arrow (shaft, head, radius,
        colour) or axes; an arrow is never shorter than `MIN_ARROW_PIXELS` on screen."""
        alpha = self.number("Alpha", 1.0)
        if str(self.option("Shape", "Arrow")) == "Axes":
            return axes(pose, self.number("Axes Length", 1.0), alpha)
        shaft = self.number("Shaft Length", 1.0)
        head = self.number("Head Length", 0.3)
        return arrow(
            pose,
            shaft + head,
            head,
            self.number("Head Radius", 0.1),
            self.colour("Color", POSE_COLOUR),
            alpha,
            MIN_ARROW_PIXELS * context.metres_per_pixel,
        )

    def placed(self, frame: str, stamp: int, pose: Transform, context: Context) -> Transform | None:
        """``pose`` (in ``frame`` at ``stamp``) in the fixed frame, or None when tf cannot place
        it (the display's Transform status says why)."""
        answer = context.frames.lookup(frame, stamp)
        if not self.transform_status(frame, answer) or isinstance(answer, str):
            return None
        return compose(answer, pose)


class Pose(PoseShapes):
    """rviz's Pose display: the latest pose as an arrow."""

    CLASSES = ("rviz/Pose", "rviz/PoseStamped")
    MESSAGE_TYPE = "geometry_msgs/PoseStamped"

    @override
    def clear(self) -> None:
        self.latest: tuple[str, int, Transform] | None = None

    @override
    def take(self, msg: Any, now: float) -> None:
        pose = pose_transform(msg.pose)
        if not valid_quaternion(*pose[3:]):
            self.statuses.error(
                "Topic", "Message contained invalid floating point values (nans or infs)"
            )
            return
        self.latest = (clean(msg.header.frame_id), nanos(msg.header.stamp), pose)

    @override
    def draw(self, context: Context) -> Layer:
        if self.latest is None:
            return Layer()
        placed = self.placed(*self.latest, context)
        return Layer() if placed is None else self.shape(placed, context)


class PoseArray(PoseShapes):
    """rviz's PoseArray display: each pose of the latest array as an arrow."""

    CLASSES = ("rviz/PoseArray",)
    MESSAGE_TYPE = "geometry_msgs/PoseArray"

    @override
    def clear(self) -> None:
        self.latest: tuple[str, int, list[Transform]] | None = None

    @override
    def take(self, msg: Any, now: float) -> None:
        poses = [pose_transform(p) for p in msg.poses]
        self.latest = (clean(msg.header.frame_id), nanos(msg.header.stamp), poses)

    @override
    def draw(self, context: Context) -> Layer:
        if self.latest is None:
            return Layer()
        frame, stamp, poses = self.latest
        answer = context.frames.lookup(frame, stamp)
        if not self.transform_status(frame, answer) or isinstance(answer, str):
            return Layer()
        shape = str(self.option("Shape", "Arrow (Flat)"))
        colour = self.colour("Color", POSE_COLOUR)
        alpha = self.number("Alpha", 1.0)
        length = max(self.number("Arrow Length", 0.3), MIN_ARROW_PIXELS * context.metres_per_pixel)
        layer = Layer()
        for pose in poses:
            placed = compose(answer, pose)
            if shape == "Axes":
                layer.extend(axes(placed, self.number("Axes Length", 0.3), alpha))
            elif shape == "Arrow (3D)":
                head = self.number("Head Length", 0.07)
                layer.extend(
                    arrow(placed, length, head, self.number("Head Radius", 0.03), colour, alpha)
                )
            else:
                layer.extend(flat_arrow(placed, length, colour, alpha))
        return layer


class Odometry(PoseShapes):
    """rviz's Odometry display: the last poses of an odometry topic as arrows."""

    CLASSES = ("rviz/Odometry",)
    MESSAGE_TYPE = "nav_msgs/Odometry"

    @override
    def clear(self) -> None:
        self.kept: deque[tuple[str, int, Transform]] = deque()

    @override
    def take(self, msg: Any, now: float) -> None:
        pose = pose_transform(msg.pose.pose)
        if not valid_quaternion(*pose[3:]):
            self.statuses.error(
                "Topic", "Message contained invalid floating point values (nans or infs)"
            )
            return
        frame, stamp = clean(msg.header.frame_id), nanos(msg.header.stamp)
        keep = max(0, int(self.number("Keep", 100)))
        if self.kept:
            _, _, last = self.kept[-1]
            moved = math.dist(last[:3], pose[:3])
            turned = abs(math.remainder(yaw_of(*pose[3:]) - yaw_of(*last[3:]), math.tau))
            if moved < self.number("Position Tolerance", 0.1) and turned < self.number(
                "Angle Tolerance", 0.1
            ):
                return
        self.kept.append((frame, stamp, pose))
        while keep and len(self.kept) > keep:
            self.kept.popleft()

    @override
    def draw(self, context: Context) -> Layer:
        layer = Layer()
        for frame, stamp, pose in self.kept:
            placed = self.placed(frame, stamp, pose, context)
            if placed is not None:
                layer.extend(self.shape(placed, context))
        return layer
