"""The ROS packages that come with rosx, found with ``os`` alone.

rosx ships them under one prefix laid out as Noetic's ``/opt/ros/noetic`` (`PREFIX`):
``share/<package>/`` holds a package's files (a folder is named as its package, and a test
keeps it so: no manifest is read to name it), ``lib/<package>/`` the programs rosrun finds
there (small scripts calling the code that implements them, turtlesim's in ``rosx_turtle``).
Strings here and no ``pathlib``: a shell's <TAB> lists these names in a
Python started for it alone (`rosx.packages.crawl.bundled_packages` gives them as paths).
"""

from __future__ import annotations

import os

#: The install prefix of the ROS packages shipped with rosx (``share/``, ``lib/``).
PREFIX = os.path.join(os.path.dirname(os.path.abspath(__file__)), "noetic")  # noqa: PTH100, PTH118, PTH120 - strings, no pathlib


def bundled_folders() -> dict[str, str]:
    """The ROS package folders shipped with rosx (`PREFIX`'s ``share/``), by name, sorted, as
    the tree is now (a listing and a ``stat`` a package: callers
    that ask often keep the answer, `rosx.packages.crawl.bundled_packages`)."""
    share = os.path.join(PREFIX, "share")  # noqa: PTH118 - strings, no pathlib
    # share/ros is ROS_ROOT, without a package.xml (see its README).
    found: dict[str, str] = {}
    for name in sorted(os.listdir(share)):  # noqa: PTH208 - strings, no pathlib
        folder = os.path.join(share, name)  # noqa: PTH118
        if _is_package(folder):
            found[name] = folder
    return found


def provided_names() -> list[str]:
    """The names of the ROS packages rosx provides, sorted: the bundled folders, and the
    packages with programs in ``lib/``."""
    try:
        with os.scandir(os.path.join(PREFIX, "lib")) as listing:  # noqa: PTH118
            with_programs = {entry.name for entry in listing if entry.is_dir()}
    except OSError:
        with_programs = set()
    return sorted(with_programs | set(bundled_folders()))


def _is_package(folder: str) -> bool:
    return os.path.isfile(os.path.join(folder, "package.xml"))  # noqa: PTH113, PTH118 - strings, no pathlib


__all__ = ["PREFIX", "bundled_folders", "provided_names"]
