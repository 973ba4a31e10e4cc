"""The part of ``rospkg`` that ROS 1 scripts use: ``RosPack`` and ``ResourceNotFound``.

``rospkg.RosPack().get_path('my_pkg')`` is how scripts find their package's files (a map, a
YAML file beside the script). Here it asks rosx's package index (`rosx.packages.index`), so it
finds the packages on ``ROS_PACKAGE_PATH`` and those shipped with rosx, as ``rospack find``
does. ``get_ros_paths`` and friends read the environment as rospkg's do.
"""

from __future__ import annotations

import builtins
import os
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.packages.index import PackageIndex


class ResourceNotFound(Exception):  # noqa: N818 - rospkg's name, which scripts catch
    """A package (or stack) was not found; ``str()`` lists the paths searched, as rospkg's."""

    def __init__(self, msg: str, ros_paths: Sequence[str] | None = None) -> None:
        super().__init__(msg)
        self.ros_paths = list(ros_paths) if ros_paths is not None else None

    def __str__(self) -> str:
        from rosx.packages.index import ros_path_lines  # noqa: PLC0415 - only when printed

        return "\n".join([str(self.args[0]), *ros_path_lines(self.ros_paths or [])])


def get_ros_root(env: Mapping[str, str] | None = None) -> str | None:
    """``ROS_ROOT``, or None."""
    return (os.environ if env is None else env).get("ROS_ROOT")


def get_ros_package_path(env: Mapping[str, str] | None = None) -> str | None:
    """``ROS_PACKAGE_PATH``, or None."""
    return (os.environ if env is None else env).get("ROS_PACKAGE_PATH")


def get_ros_paths(env: Mapping[str, str] | None = None) -> list[str]:
    """Where packages are looked for: ``ROS_ROOT``, then each entry of ``ROS_PACKAGE_PATH``
    (empty entries and repeats left out)."""
    paths: list[str] = []
    entries = (get_ros_package_path(env) or "").split(os.pathsep)
    for path in [get_ros_root(env) or "", *entries]:
        if path and path not in paths:
            paths.append(path)
    return paths


class RosPack:
    """The packages on ``ros_paths`` (`get_ros_paths` by default) and rosx's own."""

    def __init__(self, ros_paths: Sequence[str] | None = None) -> None:
        from pathlib import Path  # noqa: PLC0415 - only for scripts that make one

        from rosx.cache import ros_home  # noqa: PLC0415 - only when made
        from rosx.packages.index import PackageIndex  # noqa: PLC0415 - only when made

        self._ros_paths = list(get_ros_paths() if ros_paths is None else ros_paths)
        self._index: PackageIndex = PackageIndex(
            [Path(p) for p in self._ros_paths], cache_folder=ros_home(os.environ)
        )

    def get_ros_paths(self) -> list[str]:
        """The paths searched."""
        return list(self._ros_paths)

    def list(self) -> list[str]:
        """The names of every package."""
        return list(self._index.packages)

    def get_path(self, name: str) -> str:
        """The directory of package ``name``; `ResourceNotFound` if there is none."""
        directory = self._index.packages.get(name)
        if directory is None:
            raise ResourceNotFound(name, ros_paths=self._ros_paths)
        return str(directory)

    def get_depends(self, name: str, implicit: bool = True) -> builtins.list[str]:
        """``name``'s dependencies: all of them (``implicit``), or its manifest's own."""
        self.get_path(name)
        return self._index.depends(name) if implicit else self._index.depends1(name)

    def get_depends_on(self, name: str, implicit: bool = True) -> builtins.list[str]:
        """The packages that depend on ``name``: at any depth (``implicit``), or directly."""
        if not implicit:
            return self._index.depends_on1(name)
        return [p for p in self._index.packages if name in self._index.depends(p)]


__all__ = [
    "ResourceNotFound",
    "RosPack",
    "get_ros_package_path",
    "get_ros_paths",
    "get_ros_root",
]
