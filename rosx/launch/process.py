"""How a `Node` of a plan is started: its command line and its environment.

Shared by ``--args`` and the runner, so that what is printed is what is run. The rules are
roslaunch's (``node_args.create_local_process_args`` and ``core.setup_env``):

* command line: the ``launch-prefix`` split as a shell would, the executable found in the
  package as ``rosrun`` finds it, the ``args`` split as a shell would, one ``from:=to`` per
  remap, and ``__name:=NAME``;
* environment: the caller's, with ``ROS_MASTER_URI`` set, ``ROS_NAMESPACE`` set to the node's
  namespace (removed for the global one), then the node's ``<env>`` settings in order.
"""

from __future__ import annotations

import shlex
from typing import TYPE_CHECKING

from rosx.launch.errors import LaunchError, ResourceNotFoundError

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping
    from pathlib import Path

    from rosx.launch.model import Node
    from rosx.packages.index import PackageIndex

    #: A program rosx provides itself for ``(package, type)`` (turtlesim's nodes…): the
    #: command that runs it, or None to look for an executable file in the package.
    Provided = Callable[[str, str], list[str] | None]


def node_program(node: Node, package_index: PackageIndex) -> Path:
    """The executable file of ``node`` in its package (the first one ``rosrun`` would take).

    Raises:
        LaunchError: roslaunch's ``Cannot locate node of type [T] in package [P]…``, or
            `ResourceNotFoundError`: the package is not found; the error names the ``<node>``
            tag.
    """
    from rosx.packages.index import PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used
    from rosx.workspace.executables import find_executables  # noqa: PLC0415 - workspace code loads only when used

    tag = "test" if hasattr(node, "test_name") else "node"
    try:
        directory = package_index.find(node.package)
    except PackageNotFoundError:
        raise ResourceNotFoundError(node.source.file, node.source.line, tag, node.package) from None
    # roslaunch looks for a file *named* type: a type holding "/" is never found.
    found = find_executables(directory, node.type).executables if "/" not in node.type else []
    if not found:
        raise LaunchError(
            node.source.file,
            node.source.line,
            tag,
            f"Cannot locate node of type [{node.type}] in package [{node.package}]. Make sure "
            "file exists in package path and permission is set to executable (chmod +x)",
        )
    return found[0]


def node_arguments(node: Node) -> list[str]:
    """What follows the program: ``args`` (shell-split), ``from:=to`` remaps, ``__name:=``."""
    try:
        args = shlex.split(node.args)
    except ValueError as error:
        tag = "test" if hasattr(node, "test_name") else "node"
        raise LaunchError(
            node.source.file, node.source.line, tag, f"invalid args [{node.args}]: {error}"
        ) from None
    remaps = [f"{source}:={target}" for source, target in node.remappings]
    return [*args, *remaps, f"__name:={node.name}"]


def node_command_line(
    node: Node, package_index: PackageIndex, provided: Provided | None = None
) -> list[str]:
    """``launch-prefix`` + the program + `node_arguments`.

    ``provided`` lets the caller run programs rosx provides without a file; without it (or when
    it returns None) the executable is looked up with `node_program`.
    """
    prefix = shlex.split(node.launch_prefix) if node.launch_prefix else []
    program = provided(node.package, node.type) if provided else None
    if program is None:
        program = [str(node_program(node, package_index))]
    return [*prefix, *program, *node_arguments(node)]


def node_environment(node: Node, environ: Mapping[str, str], master_uri: str) -> dict[str, str]:
    """The whole environment of ``node``'s process: ``environ`` + ROS's settings + ``<env>``."""
    result = dict(environ)
    result["ROS_MASTER_URI"] = master_uri
    result.pop("ROS_NAMESPACE", None)
    namespace = node.namespace.removesuffix("/")
    if namespace:
        result["ROS_NAMESPACE"] = namespace
    for name, value in node.env:
        result[name] = value
    return result


__all__ = ["node_arguments", "node_command_line", "node_environment", "node_program"]
