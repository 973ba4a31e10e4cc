"""rviz's Marker and MarkerArray: ``visualization_msgs/Marker`` shapes kept by namespace and
id, drawn from above.

ADD (and MODIFY, the same action) replaces the marker of its ``(ns, id)``; DELETE removes it;
DELETEALL removes every marker of the display. A marker with a ``lifetime`` goes that long
after it came. Types drawn: ARROW (along the pose, or from ``points[0]`` to ``points[1]``),
CUBE, SPHERE, CYLINDER (their outlines, filled), LINE_STRIP, LINE_LIST, CUBE_LIST,
SPHERE_LIST, POINTS (``scale.x`` wide), TEXT_VIEW_FACING (the text), TRIANGLE_LIST (filled);
MESH_RESOURCE is listed as not drawn. ``Namespaces`` in the config turns namespaces off.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np  # noqa: TID253 - rviz's model is array work; only rviz imports it

from rosx.tf.stamps import nanos
from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.displays.shapes import arrow, box, cylinder, ellipsoid
from rosx_commands.rviz.frames import clean
from rosx_commands.rviz.geometry import apply, compose, pose_transform
from rosx_commands.rviz.primitives import Label, Layer, Points, Polygon, Segments

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    import numpy.typing as npt

    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform

(ARROW, CUBE, SPHERE, CYLINDER, LINE_STRIP, LINE_LIST, CUBE_LIST, SPHERE_LIST, POINTS,
 TEXT_VIEW_FACING, MESH_RESOURCE, TRIANGLE_LIST) = range(12)  # fmt: skip
ADD, DELETE, DELETEALL = 0, 2, 3
NAMES = {
    ARROW: "ARROW", CUBE: "CUBE", SPHERE: "SPHERE", CYLINDER: "CYLINDER",
    LINE_STRIP: "LINE_STRIP", LINE_LIST: "LINE_LIST", CUBE_LIST: "CUBE_LIST",
    SPHERE_LIST: "SPHERE_LIST", POINTS: "POINTS", TEXT_VIEW_FACING: "TEXT_VIEW_FACING",
    MESH_RESOURCE: "MESH_RESOURCE", TRIANGLE_LIST: "TRIANGLE_LIST",
}  # fmt: skip


def _rgb(colour: Any) -> tuple[int, int, int]:
    red, green, blue = (round(max(0.0, min(1.0, v)) * 255) for v in (colour.r, colour.g, colour.b))
    return (red, green, blue)


@dataclass
class Kept:
    """One marker as it came, and when it goes (None: never)."""

    msg: Any
    frame: str
    stamp: int
    pose: Transform
    points: npt.NDArray[np.float64]
    colours: npt.NDArray[np.uint8] | None
    expires: float | None


def shape(kept: Kept, to_fixed: Transform, metres_per_pixel: float) -> Layer:
    """What marker ``kept`` draws, its frame at ``to_fixed`` in the fixed frame."""
    msg = kept.msg
    pose = compose(to_fixed, kept.pose)
    colour = _rgb(msg.color)
    alpha = max(0.0, min(1.0, msg.color.a))
    scale = (msg.scale.x, msg.scale.y, msg.scale.z)
    kind = msg.type
    points = kept.points
    if kind == ARROW:
        if len(points) >= 2:
            start, end = apply(pose, points[:2])
            length = float(np.linalg.norm(end - start))
            direction = end - start
            yaw = float(np.arctan2(direction[1], direction[0]))
            tip = (
                start[0],
                start[1],
                start[2],
                0.0,
                0.0,
                float(np.sin(yaw / 2)),
                float(np.cos(yaw / 2)),
            )
            head = scale[2] or 0.23 * length
            return arrow(tip, length, head, scale[1] / 2, colour, alpha, 4 * metres_per_pixel)
        return arrow(
            pose, scale[0], 0.23 * scale[0], scale[1] / 2, colour, alpha, 4 * metres_per_pixel
        )
    if kind in (CUBE, SPHERE, CYLINDER):
        outline = {CUBE: box, SPHERE: ellipsoid, CYLINDER: cylinder}[kind](pose, scale)
        return Layer(polygons=[Polygon(outline, colour, alpha)])
    if kind == TEXT_VIEW_FACING:
        return Layer(labels=[Label(pose[0], pose[1], msg.text, colour, centred=True)])
    if len(points) == 0:
        return Layer()
    xy = apply(pose, points)[:, :2]
    colours = kept.colours
    if kind in (LINE_STRIP, LINE_LIST):
        if kind == LINE_STRIP:
            ends = np.stack([xy[:-1], xy[1:]], axis=1)
            per = colours[:-1] if colours is not None else None
        else:
            pairs = len(xy) // 2
            ends = xy[: 2 * pairs].reshape(pairs, 2, 2)
            per = colours[: 2 * pairs : 2] if colours is not None else None
        return Layer(segments=[Segments(ends, colour, per, alpha)])
    if kind in (POINTS, CUBE_LIST, SPHERE_LIST):
        return Layer(points=[Points(xy, colour, colours, 1, alpha, metres=scale[0])])
    if kind == TRIANGLE_LIST:
        layer = Layer()
        for i in range(len(xy) // 3):
            tint = tuple(int(v) for v in colours[3 * i]) if colours is not None else colour
            layer.polygons.append(Polygon(xy[3 * i : 3 * i + 3], tint, alpha))  # type: ignore[arg-type]
        return layer
    return Layer()


class Marker(Display):
    """rviz's Marker display: the markers of a topic, by namespace and id."""

    CLASSES = ("rviz/Marker",)
    MESSAGE_TYPE = "visualization_msgs/Marker"
    TOPIC_KEY = "Marker Topic"
    DEFAULT_TOPIC = "visualization_marker"

    @override
    def clear(self) -> None:
        self.markers: dict[tuple[str, int], Kept] = {}

    @override
    def take(self, msg: Any, now: float) -> None:
        self.apply(msg, now)

    def apply(self, msg: Any, now: float) -> None:
        """One marker's action."""
        key = (msg.ns, msg.id)
        if msg.action == DELETEALL:
            self.markers.clear()
            self.statuses.entries = {
                name: entry for name, entry in self.statuses.entries.items() if "/" not in name
            }
            return
        if msg.action == DELETE:
            self.markers.pop(key, None)
            self.statuses.delete(f"{msg.ns}/{msg.id}")
            return
        if msg.type == MESH_RESOURCE or msg.type not in NAMES:
            kind = NAMES.get(msg.type, str(msg.type))
            self.statuses.warn(f"{msg.ns}/{msg.id}", f"Marker type {kind} is not drawn here")
            return
        points = np.array([[p.x, p.y, p.z] for p in msg.points], dtype=np.float64).reshape(-1, 3)
        colours = None
        if len(msg.colors) == len(points) and len(points):
            colours = np.array([_rgb(c) for c in msg.colors], dtype=np.uint8)
        lifetime = msg.lifetime.secs + msg.lifetime.nsecs / 1e9
        self.markers[key] = Kept(
            msg,
            clean(msg.header.frame_id),
            0 if msg.frame_locked else nanos(msg.header.stamp),
            pose_transform(msg.pose),
            points,
            colours,
            now + lifetime if lifetime > 0 else None,
        )
        self.statuses.delete(f"{msg.ns}/{msg.id}")

    @override
    def expire(self, now: float) -> bool:
        gone = [
            key
            for key, kept in self.markers.items()
            if kept.expires is not None and now >= kept.expires
        ]
        for key in gone:
            del self.markers[key]
        if gone:
            self.version += 1
        return bool(gone)

    def _shown(self, namespace: str) -> bool:
        chosen = self.option("Namespaces", {}) or {}
        return not hasattr(chosen, "get") or chosen.get(namespace, True) is not False

    @override
    def draw(self, context: Context) -> Layer:
        layer = Layer()
        failed = None
        for kept in list(self.markers.values()):
            if kept.expires is not None and context.now >= kept.expires:
                continue
            if not self._shown(kept.msg.ns):
                continue
            answer = context.frames.lookup(kept.frame, kept.stamp)
            if isinstance(answer, str):
                failed = answer
                continue
            layer.extend(shape(kept, answer, context.metres_per_pixel))
        if failed is not None:
            self.statuses.error("Transform", failed)
        else:
            self.statuses.delete("Transform")
        return layer

    @property
    @override
    def summary(self) -> str:
        text = super().summary
        if text == "OK" and self.enabled and self.messages:
            return f"OK ({len(self.markers)} markers)"
        return text


class MarkerArray(Marker):
    """rviz's MarkerArray display: markers that come in arrays."""

    CLASSES = ("rviz/MarkerArray",)
    MESSAGE_TYPE = "visualization_msgs/MarkerArray"
    DEFAULT_TOPIC = "visualization_marker_array"

    @override
    def take(self, msg: Any, now: float) -> None:
        for marker in msg.markers:
            self.apply(marker, now)
