"""Launch files to a `LaunchPlan`: roslaunch's command-line arguments and its entry point.

`resolve_launch_arguments` turns ``PKG FILE`` or paths into launch files and ``name:=value``
args; `load_launch` reads them (`rosx.launch.reader`, tag by tag in `rosx.launch.tags`) with
roscore's parameters first. The tags and attributes are roslaunch's (wiki roslaunch/XML):
``launch``, ``node``, ``test``, ``param``, ``rosparam``, ``remap``, ``env``, ``arg``,
``include``, ``group``, ``machine`` and ``if``/``unless`` on each.

Every error is a `LaunchError` naming the file, the line and the tag, with roslaunch's words
for what is wrong; nothing is returned for a file set with any error. One deliberate
difference: an ``<arg>``'s ``default`` is not resolved when the arg already has a value
(ros_comm#422: ``default="$(find pkg)"`` failed even when the arg was given).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.launch import substitution
from rosx.launch.errors import LaunchError
from rosx.launch.model import LaunchPlan, MasterSettings
from rosx.launch.reader import AbortError, Reader

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, Sequence

    from rosx.launch.values import CommandRunner
    from rosx.packages.index import PackageIndex


def resolve_launch_arguments(
    argv: Sequence[str], package_index: PackageIndex
) -> tuple[list[str], dict[str, str]]:
    """Split roslaunch's positional arguments into launch files and ``name:=value`` args.

    ``PKG FILE`` names a file found anywhere in package ``PKG`` (as ``roslaunch`` and
    ``roslib.packages.find_resource`` look, hidden directories skipped; in rosx's own package of
    that name when the package path's has no such file); otherwise the first
    word is a path (or ``-``). The ``name:=value`` arguments may stand anywhere.

    Raises:
        LaunchError: roslaunch's ``[F] is neither a launch file in package [P] nor is [P] a
            launch file name``, ``[F] is not a launch file name`` or ``multiple files
            named [F] in package [P]…``.
    """
    words = [a for a in argv if ":=" not in a]
    cli_args = load_mappings(argv)
    if not words:
        return [], cli_args
    if len(words) >= 2:
        found = _find_in_package(words[0], words[1], package_index)
        if len(found) > 1:
            listing = "".join(f"\n- {path}" for path in found)
            raise LaunchError(
                "",
                0,
                "",
                f"multiple files named [{words[1]}] in package [{words[0]}]:{listing}\n"
                "Please specify full path instead",
            )
        if found:
            return [found[0], *words[2:]], cli_args
    if words[0] == "-" or Path(words[0]).is_file():
        return words, cli_args
    if len(words) >= 2:
        message = (
            f"[{words[1]}] is neither a launch file in package [{words[0]}] nor is "
            f"[{words[0]}] a launch file name"
        )
    else:
        message = f"[{words[0]}] is not a launch file name"
    raise LaunchError("", 0, "", message)


def load_mappings(argv: Sequence[str]) -> dict[str, str]:
    """The ``name:=value`` arguments of a command line (rosgraph's ``load_mappings``).

    ``_param:=value`` private-parameter arguments are left out; ``__ns:=`` and the like stay.
    """
    from rosx.names.remap_args import is_legal_remap  # noqa: PLC0415 - name rules load only when used

    mappings: dict[str, str] = {}
    for arg in argv:
        if not is_legal_remap(arg) or arg.count(":=") != 1:
            continue
        source, target = (side.strip() for side in arg.split(":="))
        if source and target and not (len(source) > 1 and source[0] == "_" and source[1] != "_"):
            mappings[source] = target
    return mappings


def _find_in_package(package: str, name: str, package_index: PackageIndex) -> list[str]:
    from rosx.packages.index import PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used

    try:
        package_index.find(package)
    except PackageNotFoundError:
        return []
    for root in package_index.directories(package):
        found: list[str] = []
        for directory, subdirs, files in os.walk(root, followlinks=True):
            subdirs[:] = sorted(d for d in subdirs if not d.startswith("."))
            if name in files:
                path = os.path.normpath(Path(directory, name).absolute())
                if path not in found:
                    found.append(path)
        if found:
            return found
    return []


def load_launch(
    targets: Sequence[str],
    cli_args: Mapping[str, str] | None = None,
    environ: Mapping[str, str] | None = None,
    package_index: PackageIndex | None = None,
    *,
    with_core: bool = True,
    core_params: Mapping[str, Any] | None = None,
    args_only: bool = False,
    anonymous: Callable[[str], str] | None = None,
    run: CommandRunner | None = None,
    argv: Sequence[str] = (),
) -> LaunchPlan:
    """Read launch files into one plan.

    Args:
        targets: The launch files, in order (as `resolve_launch_arguments` gives them).
        cli_args: ``name:=value`` from the command line, for ``<arg>``.
        environ: For ``$(env)``, ``$(optenv)``, ``ROS_NAMESPACE`` and ``ROS_MASTER_URI``
            (default: ``os.environ``).
        package_index: For ``$(find)`` (default: built from ``environ``).
        with_core: Read roscore's part first, as every roslaunch except ``--dump-params``
            does: its parameters (``core_params``), and ``/rosout``'s name taken.
        core_params: The parameters roscore sets from ``roscore.xml`` (name -> value); None
            for rosx's core's ``/rosversion`` and ``/rosdistro`` (`roscore_params`). The
            printing options, which do not show them, pass ``{}`` and skip importing the core.
        args_only: Read ``<arg>`` tags only (``--ros-args``).
        anonymous: Makes ``$(anon id)`` names (default: rosgraph's ``anonymous_name``).
        run: Runs ``<param command=…>`` commands (`rosx.launch.run.command.run_command`
            for a real launch); None: a file with one is refused, as the plan runs nothing.
        argv: The command line, searched for ``__ns:=`` (the namespace of everything).

    Raises:
        LaunchError: Anything wrong in any file; nothing of the plan is returned.
    """
    from rosx.names.anonymous import anonymous_name  # noqa: PLC0415 - name rules load only when used
    from rosx.names.script import ros_namespace  # noqa: PLC0415 - name rules load only when used

    environ = os.environ if environ is None else environ
    if package_index is None:
        from rosx.packages.index import PackageIndex  # noqa: PLC0415 - the package index loads only when used

        package_index = PackageIndex.from_environ(environ)
    world = substitution.World(environ, package_index, anonymous or anonymous_name)
    plan = LaunchPlan()
    plan.master = MasterSettings(environ.get("ROS_MASTER_URI") or plan.master.uri)
    reader = Reader(plan, world, run, args_only)
    if with_core:
        reader.add_core(roscore_params() if core_params is None else core_params)
    try:
        namespace = ros_namespace(environ, argv)
    except ValueError as error:
        raise LaunchError("", 0, "", str(error)) from None
    for target in targets:
        try:
            reader.load_file(target, namespace, dict(cli_args or {}))
        except AbortError as abort:
            raise abort.error from None
    return plan


def roscore_params() -> dict[str, Any]:
    """What roslaunch's ``roscore.xml`` sets: ``/rosversion`` and ``/rosdistro``, as rosx's core."""
    from rosx.core.params import ROSDISTRO, ROSVERSION  # noqa: PLC0415 - the core loads only when one starts

    return {"/rosversion": ROSVERSION, "/rosdistro": ROSDISTRO}


__all__ = ["load_launch", "load_mappings", "resolve_launch_arguments", "roscore_params"]
