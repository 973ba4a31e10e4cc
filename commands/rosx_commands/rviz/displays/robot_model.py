"""rviz's RobotModel, from above: each link's visual shapes (boxes, cylinders, spheres) of the
URDF in the ``Robot Description`` parameter, outlined at the link's tf frame (``TF Prefix``
before it). Meshes are not drawn; a link that tf cannot place says so, in rviz's words.

The description comes through `receive` as text (the live source reads the parameter), or
None when the parameter is not set.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rosx_commands.rviz import status
from rosx_commands.rviz.displays.base import Display
from rosx_commands.rviz.displays.shapes import box, cylinder, ellipsoid
from rosx_commands.rviz.geometry import IDENTITY, compose
from rosx_commands.rviz.primitives import Layer, Polygon

if sys.version_info >= (3, 12):
    from typing import override
else:
    from typing_extensions import override

if TYPE_CHECKING:
    from xml.etree.ElementTree import Element

    from rosx_commands.rviz.displays.base import Context
    from rosx_commands.rviz.geometry import Transform

DEFAULT_COLOUR = (200, 200, 200)


@dataclass
class Part:
    """One visual of a link: its kind (box, cylinder, sphere), size, pose and colour."""

    kind: str
    size: tuple[float, float, float]
    origin: Transform
    colour: tuple[int, int, int]


class UrdfError(ValueError):
    """A description that is not a URDF robot."""


def _numbers(text: str | None, count: int, default: float = 0.0) -> list[float]:
    values = [float(v) for v in (text or "").split()]
    return (values + [default] * count)[:count]


def _origin(element: Element | None) -> Transform:
    if element is None:
        return IDENTITY
    import math  # noqa: PLC0415 - math is not needed at start-up

    x, y, z = _numbers(element.get("xyz"), 3)
    roll, pitch, yaw = _numbers(element.get("rpy"), 3)
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        x, y, z,
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )  # fmt: skip


def _colour(
    material: Element | None, named: dict[str, tuple[int, int, int]]
) -> tuple[int, int, int]:
    if material is None:
        return DEFAULT_COLOUR
    rgba = material.find("color")
    if rgba is not None:
        r, g, b = _numbers(rgba.get("rgba"), 3, 0.8)
        return (round(r * 255), round(g * 255), round(b * 255))
    return named.get(material.get("name", ""), DEFAULT_COLOUR)


def parse_urdf(text: str, which: str = "visual") -> dict[str, list[Part]]:
    """The links of a URDF and their ``which`` (visual or collision) shapes."""
    import xml.etree.ElementTree as ET  # noqa: PLC0415 - only a robot model parses XML

    try:
        root = ET.fromstring(text)  # a parameter of the user's own master
    except ET.ParseError as error:
        raise UrdfError(str(error)) from None
    if root.tag != "robot":
        raise UrdfError("the root element is not <robot>")
    named = {m.get("name", ""): _colour(m, {}) for m in root.findall("material")}
    links: dict[str, list[Part]] = {}
    for link in root.findall("link"):
        parts = []
        for visual in link.findall(which):
            geometry = visual.find("geometry")
            if geometry is None or len(geometry) == 0:
                continue
            shape = geometry[0]
            if shape.tag == "box":
                size = tuple(_numbers(shape.get("size"), 3))
            elif shape.tag == "cylinder":
                radius, length = float(shape.get("radius", 0)), float(shape.get("length", 0))
                size = (2 * radius, 2 * radius, length)
            elif shape.tag == "sphere":
                size = (2 * float(shape.get("radius", 0)),) * 3
            else:
                continue
            colour = _colour(visual.find("material"), named)
            parts.append(Part(shape.tag, size, _origin(visual.find("origin")), colour))  # type: ignore[arg-type]
        links[link.get("name", "")] = parts
    return links


class RobotModel(Display):
    """rviz's RobotModel display: the robot description's links where tf places them."""

    CLASSES = ("rviz/RobotModel",)
    PREFER = ()

    @property
    def parameter(self) -> str:
        """The parameter holding the URDF."""
        return str(self.option("Robot Description", "robot_description") or "robot_description")

    @override
    def clear(self) -> None:
        self.links: dict[str, list[Part]] = {}

    def receive(self, msg: Any, now: float) -> None:
        """The description's text (None: the parameter is not set)."""
        self.links = {}
        self.statuses.clear()
        if msg is None:
            self.statuses.error(
                "URDF",
                f"Parameter [{self.parameter}] does not exist, and was not found by searchParam()",
            )
        elif not str(msg).strip():
            self.statuses.error("URDF", "URDF is empty")
        else:
            which = "collision" if self.flag("Collision Enabled", False) else "visual"
            try:
                self.links = parse_urdf(str(msg), which)
            except UrdfError:
                self.statuses.error("URDF", "Failed to parse URDF model")
            else:
                self.statuses.ok("URDF", "URDF parsed OK")
        self.version += 1

    @override
    def draw(self, context: Context) -> Layer:
        layer = Layer()
        prefix = str(self.option("TF Prefix", "") or "").strip("/")
        alpha = self.number("Alpha", 1.0)
        for name, parts in self.links.items():
            if not parts:
                continue
            frame = f"{prefix}/{name}" if prefix else name
            answer = context.frames.lookup(frame)
            if isinstance(answer, str):
                self.statuses.error(frame, answer)
                continue
            self.statuses.delete(frame)
            for part in parts:
                pose = compose(answer, part.origin)
                outline = {"box": box, "cylinder": cylinder, "sphere": ellipsoid}[part.kind](
                    pose, part.size
                )
                layer.polygons.append(Polygon(outline, part.colour, alpha))
        return layer

    @property
    @override
    def summary(self) -> str:
        text = super().summary
        if text == status.OK and self.enabled:
            return "No robot description yet" if not self.statuses.entries else "URDF parsed OK"
        return text
