"""``rosx rosrun PACKAGE EXECUTABLE [ARGS…]``: run a package's executable, as ROS 1's rosrun.

The package is found as ``rospack find`` finds it (``ROS_PACKAGE_PATH``, then the packages
shipped with rosx); the executable as rosrun finds it (`rosx.workspace.executables`). The texts
and statuses are rosrun's: usage and 0 with fewer than two arguments, rospack's
``[rospack] Error: package 'x' not found`` and 2 for an unknown package,
``[rosrun] Couldn't find executable named x below /dir`` (with the files found that are not
executable) and 3 for a missing executable; on a terminal, then, the executable most likely
meant (``turtlesim node`` typed for ``turtlesim_node``).

Then, as rosrun ``exec``s the program, this process becomes it, except that a Python script
runs with rosx's Python and ``rospy`` whatever its ``#!`` line says (``rosx run-script``), and
that the programs rosx provides itself (turtlesim's ``turtlesim_node``, ``turtle_teleop_key``,
``draw_square``, ``mimic``; roscpp_tutorials' ``talker``, ``listener``, ``add_two_ints_server``,
``add_two_ints_client``; ``rosrun rostopic rostopic`` and the other ROS tools) run here.
"""

from __future__ import annotations

import os
import shlex
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import NamedTuple

from rosx_commands.cli import run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.invocation import script_command

USAGE = """\
Usage: rosrun [--prefix cmd] [--debug] PACKAGE EXECUTABLE [ARGS]
  rosrun will locate PACKAGE and try to find
  an executable named EXECUTABLE in the PACKAGE tree.
  If it finds it, it will run it with ARGS.
"""

#: ``rosrun PACKAGE EXECUTABLE`` of ROS 1's tools → the rosx tool of that name.
_TOOL_EXECUTABLES = {
    ("rostopic", "rostopic"): "rostopic",
    ("rosnode", "rosnode"): "rosnode",
    ("rosmsg", "rosmsg"): "rosmsg",
    ("rosmsg", "rossrv"): "rossrv",
    ("rosservice", "rosservice"): "rosservice",
    ("rosparam", "rosparam"): "rosparam",
    ("roslaunch", "roslaunch"): "roslaunch",
    ("rqt_graph", "rqt_graph"): "rqt_graph",
    ("rqt_console", "rqt_console"): "rqt_console",
    ("rqt_logger_level", "rqt_logger_level"): "rqt_logger_level",
    ("rqt_plot", "rqt_plot"): "rqt_plot",
    ("rqt_topic", "rqt_topic"): "rqt_topic",
    ("rqt_gui", "rqt_gui"): "rqt",
}


class Launch(NamedTuple):
    """The program rosrun becomes: its argv and environment."""

    argv: list[str]
    environ: dict[str, str]


def _provided(
    package: str, executable: str, args: list[str], env: Environment
) -> Callable[[], int] | None:
    """A program rosx runs in this process for ``rosrun PACKAGE EXECUTABLE``, if any."""
    if package in ("turtlesim", "roscpp_tutorials"):
        from rosx_turtle.executables import PROGRAMS, load  # noqa: PLC0415

        if executable in PROGRAMS[package]:
            return lambda: load(executable, package)(args, env)
    from rosx_commands.main import TOOLS, run_tool  # noqa: PLC0415

    tool = _TOOL_EXECUTABLES.get((package, executable))
    if tool is not None and tool in TOOLS:
        return lambda: run_tool([tool, *args], env)
    return None


def _suggest(
    package: str, executable: str, rest: list[str], directory: Path, env: Environment
) -> None:
    """On a terminal, after rosrun's error: the executable the user most likely meant."""
    if not env.stderr_isatty:
        return  # off a terminal the output stays ROS 1's, for scripts that read it
    from rosx.workspace.executables import executable_names, suggestion  # noqa: PLC0415

    known = executable_names(directory)
    if package == "turtlesim":
        from rosx_turtle.executables import EXECUTABLES  # noqa: PLC0415

        known += EXECUTABLES
    meant = suggestion(executable, rest, known)
    if meant is None:
        return
    args = rest[1:] if meant == f"{executable}_{rest[0] if rest else ''}" else rest
    command = " ".join(["rosrun", package, meant, *args])
    env.err(f"[rosrun] Did you mean {meant}? ({command})")


def _choose(paths: list[Path], env: Environment) -> Path | None:
    env.out("[rosrun] You have chosen a non-unique executable, please pick one of the following:")
    for number, path in enumerate(paths, start=1):
        env.stderr.write(f"{number}) {path}\n")
    env.stderr.write("#? ")
    env.stderr.flush()
    answer = env.stdin.readline().strip()
    if answer.isascii() and answer.isdigit() and 1 <= int(answer) <= len(paths):
        return paths[int(answer) - 1]
    return None


def _cpp_notice(executable: str, directory: Path, env: Environment) -> None:
    """Say once, plainly, when the executable is a C++ target of the package (never built)."""
    from rosx.workspace.cmake import cpp_targets  # noqa: PLC0415

    if executable in cpp_targets(directory / "CMakeLists.txt"):
        env.err(
            f"[rosx] {executable} is a C++ target of the package's CMakeLists.txt; rosx compiles "
            "no C++, so it was not built (write the node in Python to run it with rosx)"
        )


def _options(argv: list[str]) -> tuple[list[str], bool, list[str]] | None:
    """``(prefix, debug, [PACKAGE, EXECUTABLE, ARGS…])``, or None for the usage text."""
    prefix: list[str] = []
    debug = False
    args = list(argv)
    while args:
        if args[0] in ("--help", "-h"):
            return None
        if args[0] in ("--prefix", "-p"):
            prefix = shlex.split(args[1]) if len(args) > 1 else []
            args = args[2:]
        elif args[0] in ("--debug", "-d"):
            debug = True
            args = args[1:]
        else:
            break
    return (prefix, debug, args) if len(args) >= 2 else None


def plan(argv: list[str], env: Environment) -> Launch | Callable[[], int] | int:
    """What ``rosrun ARGV…`` does: a program to become, one to run here, or an exit status."""
    from rosx.client.script import shim_environ  # noqa: PLC0415
    from rosx.packages.index import PackageIndex, PackageNotFoundError  # noqa: PLC0415
    from rosx.workspace.executables import find_executables, is_python_script  # noqa: PLC0415
    from rosx_commands.scripts import shim_dirs  # noqa: PLC0415

    options = _options(argv)
    if options is None:
        env.stdout.write(USAGE)
        return ExitStatus.OK
    prefix, debug, (package, executable, *rest) = options
    if executable.endswith("/"):
        env.out(f"Invalid filename:  {executable}")
        return ExitStatus.ERROR
    provided = _provided(package, executable, rest, env)
    if provided is not None:
        return provided
    try:
        directory = PackageIndex.from_environ(env.environ).find(package)
    except PackageNotFoundError as error:
        env.err(str(error))
        return ExitStatus.USAGE
    if debug:
        env.out(f"[rosrun] Looking in rospack dir: {directory}")
    found = find_executables(directory, executable)
    if "/" in executable:
        if not found.executables:
            env.out(f"[rosrun] Couldn't find executable named {directory / executable}")
            return ExitStatus.NOT_FOUND
    elif not found.executables:
        env.out(f"[rosrun] Couldn't find executable named {executable} below {directory}")
        if found.not_executable:
            env.out("[rosrun] Found the following, but they're either not files,")
            env.out("[rosrun] or not executable:")
            for other in found.not_executable:
                env.out(f"[rosrun]   {other}")
        _cpp_notice(executable, directory, env)
        _suggest(package, executable, rest, directory, env)
        return ExitStatus.NOT_FOUND
    chosen = found.executables[0]
    if len(found.executables) > 1:
        picked = _choose(found.executables, env)
        if picked is None:
            return ExitStatus.NOT_FOUND
        chosen = picked
    path = chosen
    environ = shim_environ(env.environ, shim_dirs())
    command = [*script_command(), str(path)] if is_python_script(path) else [str(path)]
    if debug:
        env.out(f"[rosrun] Running {' '.join([*prefix, *command, *rest])}")
    return Launch([*prefix, *command, *rest], environ)


def _rosrun(argv: list[str], env: Environment) -> int:
    what = plan(argv, env)
    if isinstance(what, int):
        return what
    if not isinstance(what, Launch):
        return what()
    env.stdout.flush()
    env.stderr.flush()
    try:
        os.execvpe(what.argv[0], what.argv, what.environ)
    except OSError as error:
        env.err(f"{what.argv[0]}: {error.strerror}")
        return 126
    return ExitStatus.ERROR  # not reached: exec does not return


def rosrun(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosrun ARGV…``."""
    return run_command(_rosrun, list(argv), env)
