"""``rosx catkin_make``: build a catkin workspace (see `rosx.workspace.build`).

Parsed with argparse, as ROS 1's catkin_make is. The make target ``install`` writes the install
space. Arguments rosx has no use for (``-j4``, ``-DCMAKE_BUILD_TYPE=Release``, ``--use-ninja``,
other make targets…) are accepted and ignored, so
command lines written for ROS 1 work unchanged. Errors are printed as catkin_make prints them;
the exit status is then 1.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

_DESCRIPTION = (
    "Creates the catkin workspace layout and builds the message and service types of its "
    "packages, as catkin_make does for ROS 1 (rosx has no C++ to compile); the target "
    "'install' writes the install space. Other arguments meant for cmake or make are accepted "
    "and ignored."
)


def _catkin_make(argv: list[str], env: Environment) -> int:
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - this tool's parts load only when used

    parser = ToolArgumentParser(env, "catkin_make")
    parser.description = _DESCRIPTION
    add = parser.add_argument
    add("-C", "--directory", default=".", help="The base path of the workspace (default '.')")
    add("--source", help="The path to the source space (default 'workspace_base/src')")
    add("--build", help="The path to the build space (default 'workspace_base/build')")
    add("--use-ninja", action="store_true", help="Use 'ninja' instead of 'make'")
    add("--use-nmake", action="store_true", help="Use 'nmake' instead of 'make'")
    add("--use-gmake", action="store_true", help="Use 'gmake' instead of 'make'")
    add(
        "--force-cmake",
        action="store_true",
        help="Invoke 'cmake' even if it has been executed before",
    )
    add(
        "--no-color",
        action="store_true",
        help="Disables colored output (only for catkin_make and CMake)",
    )
    add("--pkg", nargs="+", help="Invoke 'make' on specific packages only")
    add(
        "--only-pkg-with-deps",
        nargs="+",
        help="Whitelist only the specified packages and their dependencies",
    )
    add(
        "--cmake-args",
        dest="cmake_args",
        nargs="*",
        type=str,
        help="Arbitrary arguments which are passed to CMake.",
    )
    add(
        "--make-args",
        dest="make_args",
        nargs="*",
        type=str,
        help="Arbitrary arguments which are passes to make.",
    )
    add(
        "--override-build-tool-check",
        action="store_true",
        help="use to override failure due to using different build tools on the same workspace.",
    )
    args, targets = parser.parse_known_args(argv)

    from rosx.workspace.build import CatkinMake, workspace_layout  # noqa: PLC0415 - workspace code loads only when used
    from rosx.workspace.errors import BuildError  # noqa: PLC0415 - workspace code loads only when used
    from rosx_commands.invocation import complete_command, self_command, working_directory  # noqa: PLC0415 - this tool's parts load only when used
    from rosx_commands.scripts import shim_dirs  # noqa: PLC0415 - this tool's parts load only when used

    layout = workspace_layout(working_directory(env), args.directory, args.source, args.build)
    # --pkg only narrows what make builds; rosx builds every package's types (it is cheap).
    only = list(args.only_pkg_with_deps or [])
    from rosx.workspace.shell import ROS_COMMANDS  # noqa: PLC0415 - the names to write
    from rosx_commands.tools import TOOLS  # noqa: PLC0415 - the table of tools, no tool

    make = CatkinMake(
        layout,
        env.environ,
        shim_dirs=shim_dirs(),
        rosx=self_command(),
        commands=[name for name in ROS_COMMANDS if name in TOOLS],
        only=only,
        install="install" in targets,
        complete=complete_command(),
    )
    try:
        if not layout.base.exists():
            make.check_layout()
        env.out(f"Base path: {layout.base}")
        make.check_layout()
        for line in make.header()[1:]:
            env.out(line)
        lines = make.run()
        for line in lines:
            env.out(line)
            env.stdout.flush()
    except BuildError as error:
        env.stdout.flush()
        raise CommandError(str(error), ExitStatus.ERROR) from None
    finally:
        for warning in make.warnings:
            env.err(warning)
    return ExitStatus.OK


def catkin_make(argv: Sequence[str], env: Environment) -> int:
    """Run ``catkin_make ARGV…``."""
    return run_command(_catkin_make, list(argv), env)
