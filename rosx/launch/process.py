"""How a `Node` of a plan is started: its command line and its environment.

(Being written: the signatures are final.) Shared by ``--args`` and the runner so that what is
printed is what is run.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.launch.model import Node
    from rosx.workspace.index import PackageIndex


def node_command_line(node: Node, package_index: PackageIndex) -> list[str]:
    """``launch-prefix`` + the executable's path + ``args`` + ``from:=to`` + ``__name:=NAME``.

    Raises `LaunchError` (roslaunch's ``Cannot locate node of type [T] in package [P]…``).
    """
    raise NotImplementedError


def node_environment(node: Node, environ: Mapping[str, str], master_uri: str) -> dict[str, str]:
    """The variables a node's process gets on top of ``environ``: ``ROS_MASTER_URI``,
    ``ROS_NAMESPACE`` (for a namespaced node) and its ``<env>`` tags."""
    raise NotImplementedError
