"""Launch files to a `LaunchPlan`, as roslaunch's ``XmlLoader`` reads them.

(Being written: the signatures are final.)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.launch.model import LaunchPlan
    from rosx.workspace.index import PackageIndex


def resolve_launch_arguments(
    argv: Sequence[str], package_index: PackageIndex
) -> tuple[list[str], dict[str, str]]:
    """Split roslaunch's positional arguments into launch files and ``name:=value`` args.

    ``PKG FILE.launch`` is looked up in the package first, then a path is taken as it is; the
    ``name:=value`` arguments (anywhere) become the second item. Raises `LaunchError` with
    roslaunch's texts (``[X] is neither a launch file in package [P] nor is [P] a launch file
    name``, ``multiple files named…``).
    """
    raise NotImplementedError


def load_launch(
    targets: Sequence[str],
    cli_args: Mapping[str, str] | None = None,
    environ: Mapping[str, str] | None = None,
    package_index: PackageIndex | None = None,
    *,
    resolve_anon: bool = True,
    roscore_params: bool = False,
) -> LaunchPlan:
    """Read launch files (paths, or ``"-"`` never: pass text via a file) into one plan.

    Args:
        targets: The launch files, in order (as `resolve_launch_arguments` gives them).
        cli_args: ``name:=value`` from the command line, for ``<arg>``.
        environ: The environment for ``$(env)``/``$(optenv)`` and ``ROS_MASTER_URI``
            (default: ``os.environ``).
        package_index: For ``$(find)`` (default: built from ``environ``).
        resolve_anon: False keeps ``$(anon x)`` in node names as written, as ``--nodes``,
            ``--args`` and ``--find-node`` do.
        roscore_params: Add what roscore.xml sets (``/rosdistro``, ``/rosversion``), as the
            running launch and its SUMMARY do.

    Raises:
        LaunchError: Anything wrong in any file; nothing of the plan is returned.
    """
    raise NotImplementedError
