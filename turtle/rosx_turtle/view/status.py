"""Poses as text: the line under the pond, and one pose as `rostopic echo` prints it."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Iterable

    from rosx_turtle.view.scene import TurtlePose

#: Arrows for the eight compass headings, counter-clockwise from +x (east).
ARROWS = "→↗↑↖←↙↓↘"


def arrow(theta: float) -> str:
    """The arrow nearest to heading ``theta`` (radians, CCW from +x)."""
    return ARROWS[round(theta / (2 * math.pi) * 8) % 8]


def pose_text(turtle: TurtlePose) -> str:
    """``turtle1 → x=5.54 y=5.54 θ=0.00``."""
    return (
        f"{turtle.name} {arrow(turtle.theta)} "
        f"x={turtle.x:.2f} y={turtle.y:.2f} θ={turtle.theta:.2f}"
    )


def status_text(turtles: Iterable[TurtlePose]) -> str:
    """Every turtle's pose on one line, or a note that the pond is empty."""
    text = "   ".join(pose_text(turtle) for turtle in turtles)
    return text or "no turtles (call /spawn or /reset)"


def pose_echo(turtle: TurtlePose) -> str:
    """The pose as ``rostopic echo`` prints a ``turtlesim/Pose`` (floats as Python prints them)."""
    fields = (
        ("x", turtle.x),
        ("y", turtle.y),
        ("theta", turtle.theta),
        ("linear_velocity", turtle.linear_velocity),
        ("angular_velocity", turtle.angular_velocity),
    )
    return "\n".join(f"{name}: {value}" for name, value in fields)
