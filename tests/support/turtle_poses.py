"""Turtle poses followed from ``turtleN/pose``, for the tf demos' tests."""

from __future__ import annotations

import functools
import math
import threading

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node

Pose = get_message_class("turtlesim/Pose")


class Poses:
    """The latest pose of each turtle, from its ``pose`` topic."""

    def __init__(self, node: Node, turtles: tuple[str, ...]) -> None:
        self.latest: dict[str, tuple[float, float]] = {}
        self.lock = threading.Lock()
        for turtle in turtles:
            node.subscribe(f"/{turtle}/pose", Pose, functools.partial(self._put, turtle))

    def _put(self, turtle: str, pose: object) -> None:
        with self.lock:
            self.latest[turtle] = (pose.x, pose.y)  # type: ignore[attr-defined]

    def distance(self) -> float:
        with self.lock:
            if len(self.latest) < 2:
                return math.inf
            (x1, y1), (x2, y2) = self.latest["turtle1"], self.latest["turtle2"]
        return math.hypot(x1 - x2, y1 - y2)

    def moved(self, start: tuple[float, float]) -> float:
        with self.lock:
            x, y = self.latest.get("turtle1", start)
        return math.hypot(x - start[0], y - start[1])
