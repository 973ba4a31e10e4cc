"""The programs rosx provides: the one answer rosrun, roslaunch, completion and the hints ask.

rosx ships ROS packages as Noetic installs them (`rosx.packages.crawl.PREFIX`): a package's
files in ``share/<package>/``, its programs in ``lib/<package>/<program>`` (catkin's libexec
folder: small Python files that start rosx's implementation, as
``lib/roscpp_tutorials/talker``) or as executable scripts in the package folder itself
(rospy_tutorials' ``talker.py``, turtlesim's ``bin/``). What rosx provides is read from that
tree and nowhere else, so a package bundled tomorrow is provided at once, with no list to edit:

- `bundled_program`: the file ``rosrun PACKAGE PROGRAM`` and a launch file's ``<node>`` start.
  rosx's program wins over a same-named package of a system's ROS 1 on ``ROS_PACKAGE_PATH``
  (under ``/usr`` or ``/opt/ros``): rosx's turtlesim is the one drawn in the terminal, and a
  C++ program of that package would not be rosx's. A user's workspace is an overlay, as in
  ROS 1: a package there named like one of rosx's runs its own Python scripts (`overlays`).
- `program_names`: the programs of a bundled package (completion, the typo hints).
- `provided_packages` / `is_provided`: the packages rosx has (a ``share/`` folder with a
  ``package.xml``, or programs in ``lib/``).
- `lacking`: for a package rosx does not provide, the line that says so and, for the packages
  a ROS course reaches for next (Gazebo, the TurtleBot3 packages, move_base…), what rosx has
  instead (`COUNTERPARTS`), named only when it is there.
- `is_bundled_file`: whether a program is one of rosx's own files (rosrun runs those in its
  own process rather than starting Python again).
"""

from __future__ import annotations

import os
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx.packages import crawl
from rosx.packages.bundled import provided_names
from rosx.packages.crawl import bundled_libexec, bundled_packages
from rosx.workspace.executables import executable_names, find_executables, is_python_script

if TYPE_CHECKING:
    from collections.abc import Collection


def bundled_program(package: str, name: str) -> Path | None:
    """The program ``name`` of the package ``package`` that rosx ships, if it has one."""
    if "/" in name or not name:
        return None
    # As catkin's rosrun: the package's libexec folder (``lib/<package>``) first.
    for directory in (bundled_libexec(package), bundled_packages().get(package)):
        found = find_executables(directory, name).executables if directory else []
        if found:
            return found[0]
    return None


#: Where a system's ROS 1 installs packages; anywhere else on the package path is a workspace.
SYSTEM_PREFIXES = ("/usr/", "/opt/ros/")


def overlays(directory: Path | None, name: str) -> bool:
    """Whether the package at ``directory`` (found on ``ROS_PACKAGE_PATH``) runs its own
    program ``name`` rather than rosx's: a Python script of a user's workspace package (a
    clone of a tutorial's package, say). A system's ROS 1 and other programs (a compiled
    turtlesim_node, which is not rosx's) leave rosx's in place."""
    if directory is None or is_bundled_file(directory):
        return False
    if str(directory.resolve()).startswith(SYSTEM_PREFIXES):
        return False
    found = find_executables(directory, name).executables
    return bool(found) and is_python_script(found[0])


def program_names(package: str) -> list[str]:
    """The names of the programs rosx ships for ``package``, sorted (none if it has none)."""
    names: set[str] = set()
    for directory in (bundled_libexec(package), bundled_packages().get(package)):
        if directory is not None:
            names.update(executable_names(directory))
    return sorted(names)


@cache
def provided_packages() -> tuple[str, ...]:
    """The ROS packages rosx provides: bundled folders, and packages with programs in ``lib/``
    (`rosx.packages.bundled.provided_names`)."""
    return tuple(provided_names())


def is_provided(package: str) -> bool:
    """Whether rosx provides the package ``package`` (`provided_packages`)."""
    return package in provided_packages()


@cache
def _bundled_root() -> str:
    return str(crawl.PREFIX.resolve()) + os.sep


def is_bundled_file(path: Path) -> bool:
    """Whether ``path`` is one of the files rosx ships (not a user's or a system's program)."""
    return str(path.resolve()).startswith(_bundled_root())


class Counterpart(NamedTuple):
    """What rosx offers in place of a package it lacks: a command, shown only when what it
    runs is there (``requires``: a bundled ``(package, program)`` or ``(package, file.launch)``,
    or a rosx tool as ``("rosx", TOOL)``)."""

    command: str
    requires: tuple[str, str]


_STAGE_WORLD = Counterpart(
    "rosx roslaunch turtlebot3_stage turtlebot3_world.launch",
    ("turtlebot3_stage", "turtlebot3_world.launch"),
)
_STAGE = Counterpart("rosx rosrun stage_ros stageros WORLD", ("stage_ros", "stageros"))
_MAP = Counterpart(
    "rosx roslaunch turtlebot3_stage turtlebot3_map.launch",
    ("turtlebot3_stage", "turtlebot3_map.launch"),
)
_TELEOP = Counterpart(
    "rosx rosrun teleop_twist_keyboard teleop_twist_keyboard.py",
    ("teleop_twist_keyboard", "teleop_twist_keyboard.py"),
)
_RQT = Counterpart("rosx rqt", ("rosx", "rqt"))

#: Well-known ROS 1 packages that rosx does not provide, by name or by name prefix (ending in
#: ``*``): what it offers instead, in order of preference.
COUNTERPARTS: dict[str, tuple[Counterpart, ...]] = {
    **dict.fromkeys(
        (
            "gazebo",
            "gazebo_ros",
            "gazebo_ros_pkgs",
            "gazebo_plugins",
            "turtlebot3_gazebo",
            "turtlebot3_fake",
            "turtlebot3_bringup",
            "turtlebot3_simulations",
            "stage",
        ),
        (_STAGE_WORLD, _STAGE),
    ),
    "turtlebot3_teleop": (
        Counterpart(
            "rosx roslaunch turtlebot3_stage turtlebot3_teleop_key.launch",
            ("turtlebot3_stage", "turtlebot3_teleop_key.launch"),
        ),
        _TELEOP,
    ),
    **dict.fromkeys(("turtlebot3_slam", "gmapping", "slam_gmapping", "cartographer_ros"), (_MAP,)),
    "turtlebot3_navigation": (_MAP,),
    "move_base": (),
    "amcl": (),
    "navigation": (),
    "turtlebot3_*": (_STAGE_WORLD,),
    "rqt_tf_tree": (Counterpart("rosx rqt_tf_tree", ("rosx", "rqt_tf_tree")),),
    "rqt_bag": (Counterpart("rosx rosbag info BAG", ("rosx", "rosbag")),),
    "rqt_publisher": (Counterpart("rosx rostopic pub TOPIC TYPE ARGS", ("rosx", "rostopic")),),
    "rqt_service_caller": (
        Counterpart("rosx rosservice call SERVICE ARGS", ("rosx", "rosservice")),
    ),
    "rqt_reconfigure": (Counterpart("rosx rosparam set NAME VALUE", ("rosx", "rosparam")),),
    "rqt_*": (_RQT,),
}


def _counterparts(package: str) -> tuple[Counterpart, ...]:
    found = COUNTERPARTS.get(package)
    if found is not None:
        return found
    for pattern, counterparts in COUNTERPARTS.items():
        if pattern.endswith("*") and package.startswith(pattern[:-1]):
            return counterparts
    return ()


def _available(counterpart: Counterpart, tools: Collection[str]) -> bool:
    owner, name = counterpart.requires
    if owner == "rosx":
        return name in tools
    if name.endswith(".launch"):
        directory = bundled_packages().get(owner)
        return directory is not None and any(directory.rglob(name))
    return bundled_program(owner, name) is not None


def lacking(package: str, tools: Collection[str] = ()) -> str | None:
    """The line saying that rosx does not provide ``package``, with what it has instead; None
    when rosx provides it.

    Args:
        package: the package asked for.
        tools: the rosx commands there are (``rosx TOOL``), for the counterparts that are tools.
    """
    if is_provided(package):
        return None
    offered = [c.command for c in _counterparts(package) if _available(c, tools)]
    if offered:
        return f"[rosx] {package} is not part of rosx; instead: {offered[0]}"
    return f"[rosx] {package} is not part of rosx ('rosx --help' lists the packages it provides)"


__all__ = [
    "COUNTERPARTS",
    "SYSTEM_PREFIXES",
    "Counterpart",
    "bundled_program",
    "is_bundled_file",
    "is_provided",
    "lacking",
    "overlays",
    "program_names",
    "provided_packages",
]
