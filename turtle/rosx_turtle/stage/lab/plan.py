"""`LabPlan`: what ``rosx sim --robot [WORLD]`` runs, decided before anything starts.

Without a world it runs what ``roslaunch turtlebot3_stage turtlebot3_map.launch`` and
``turtlebot3_teleop_key.launch`` run: the TurtleBot3-shaped arena, its laser on ``scan`` (a
TurtleBot3's topic), its map served by map_server, and ``map`` → ``odom`` where odometry
starts. With a world file it runs that world with stage_ros's own names (``base_scan``); the
map is the one ``--map`` names, else a ``.yaml`` of the world's name beside it, else none.
Teleop drives the first robot (``cmd_vel``, or ``robot_0/cmd_vel`` among several).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rosx.node import Node
    from rosx_turtle.stage.world.model import Robot

#: The bundled package whose world and map the lab runs by default.
PACKAGE = "turtlebot3_stage"
DEFAULT_WORLD = Path("worlds") / "turtlebot3_world.world"
DEFAULT_MAP = Path("maps") / "turtlebot3_world.yaml"


class LabError(Exception):
    """The lab's world or map cannot be read (stageros's or map_server's words)."""


@dataclass(frozen=True)
class LabPlan:
    """The world and map files, stageros's remapping arguments, and whether the world is the
    bundled arena."""

    world: Path
    map: Path | None
    remappings: tuple[str, ...]
    bundled: bool


def bundled_folder() -> Path:
    """The bundled ``turtlebot3_stage`` package's folder."""
    from rosx.packages.crawl import bundled_packages  # noqa: PLC0415 - only for the lab

    return bundled_packages()[PACKAGE]


def plan_lab(world: str | None, map_file: str | None, package: Path | None = None) -> LabPlan:
    """The plan for ``rosx sim --robot [WORLD] [--map MAP]`` (``package``: where the bundled
    arena is, found when None)."""
    if world is None:
        folder = package if package is not None else bundled_folder()
        chosen = Path(map_file) if map_file else folder / DEFAULT_MAP
        return LabPlan(folder / DEFAULT_WORLD, chosen, ("base_scan:=scan",), bundled=True)
    path = Path(world)
    if map_file:
        return LabPlan(path, Path(map_file), (), bundled=False)
    beside = path.with_suffix(".yaml")
    return LabPlan(path, beside if beside.is_file() else None, (), bundled=False)


def odom_origin(robot: Robot) -> tuple[float, float, float]:
    """Where a robot's ``odom`` frame is in the world (the map): its start pose (or
    ``localization_origin``) when its odometry is relative to it, else the world's origin."""
    if robot.localization != "odom":
        return (0.0, 0.0, 0.0)
    x, y, yaw = robot.localization_origin or robot.pose
    return (x, y, math.atan2(math.sin(yaw), math.cos(yaw)))


def driven_topics(node: Node, prefixes: list[str]) -> tuple[str, str, str]:
    """The first robot's ``cmd_vel``, ``odom`` and (first) laser's topics, as stageros's
    ``node`` resolves and remaps them (``prefixes``: the robots' namespaces)."""
    prefix = "/" + (prefixes[0] if prefixes else "")
    cmd_vel, odom, scan = (node.resolve(prefix + name) for name in ("cmd_vel", "odom", "base_scan"))
    return cmd_vel, odom, scan


__all__ = ["LabError", "LabPlan", "bundled_folder", "driven_topics", "odom_origin", "plan_lab"]
