"""``rosx rosrun PACKAGE EXECUTABLE [ARGS…]``: run a package's executable, as ROS 1's rosrun.

The package is found as ``rospack find`` finds it (``ROS_PACKAGE_PATH``, then the packages
shipped with rosx); the executable as rosrun finds it (`rosx.workspace.executables`). The texts
and statuses are rosrun's: usage and 0 with fewer than two arguments, rospack's
``[rospack] Error: package 'x' not found`` and 2 for an unknown package,
``[rosrun] Couldn't find executable named x below /dir`` (with the files found that are not
executable) and 3 for a missing executable; on a terminal, then, the executable most likely
meant (``turtlesim node`` typed for ``turtlesim_node``).

The programs rosx provides itself (`rosx.workspace.programs`: turtlesim's ``turtlesim_node``,
roscpp_tutorials' ``talker``, ``rosrun rqt_graph rqt_graph``…) are rosx's whatever else
``ROS_PACKAGE_PATH`` holds under the package's name. For an unknown package, on a terminal, a
line after rospack's names the package meant or says that rosx does not provide it
(`rosx_commands.hints`).

Then, as rosrun ``exec``s the program, this process becomes it, except that a Python script
runs with rosx's Python and ``rospy`` whatever its ``#!`` line says (``rosx run-script``), and
that rosx's own Python programs run in this process.
"""

from __future__ import annotations

import os
import shlex
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx_commands.cli import run_command
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.invocation import script_command

if TYPE_CHECKING:
    from rosx.packages.index import PackageIndex

USAGE = """\
Usage: rosrun [--prefix cmd] [--debug] PACKAGE EXECUTABLE [ARGS]
  rosrun will locate PACKAGE and try to find
  an executable named EXECUTABLE in the PACKAGE tree.
  If it finds it, it will run it with ARGS.
"""


class Launch(NamedTuple):
    """The program rosrun becomes: its argv and environment."""

    argv: list[str]
    environ: dict[str, str]


def _suggest(
    package: str, executable: str, rest: list[str], directory: Path, env: Environment
) -> None:
    """On a terminal, after rosrun's error: the executable the user most likely meant."""
    if not env.stderr_isatty:
        return  # off a terminal the output stays ROS 1's, for scripts that read it
    from rosx.workspace.executables import suggestion  # noqa: PLC0415 - a name not found

    found = suggestion(executable, rest, _program_names(package, directory))
    if found is None:
        return
    meant, words = found
    command = " ".join(["rosrun", package, meant, *rest[words - 1 :]])
    env.err(f"[rosrun] Did you mean {meant}? ({command})")


def _program_names(package: str, directory: Path | None) -> list[str]:
    """What ``rosrun PACKAGE <name>`` can run: rosx's programs and the package's files."""
    from rosx.workspace.executables import executable_names  # noqa: PLC0415 - hints only
    from rosx.workspace.programs import program_names  # noqa: PLC0415 - hints only

    found = executable_names(directory) if directory is not None else []
    return sorted({*program_names(package), *found})


def _unknown_package(words: list[str], index: PackageIndex, env: Environment) -> None:
    """On a terminal, after rospack's error: the package meant, or what rosx lacks."""
    if not env.stderr_isatty:
        return  # off a terminal the output stays ROS 1's, for scripts that read it
    from rosx.names.typos import rejoined  # noqa: PLC0415 - a package not found
    from rosx_commands.hints import unknown_package  # noqa: PLC0415 - a package not found

    def retyped(fixed: list[str]) -> str:
        package, *rest = fixed
        programs = _program_names(package, index.packages.get(package))
        rest = (rejoined(rest, programs) or rest) if rest and rest[0] not in programs else rest
        return " ".join(["rosrun", package, *rest])

    unknown_package(words, index, env, retyped, "rosrun")


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
    from rosx.workspace.cmake import cpp_targets  # noqa: PLC0415 - workspace code loads only when used

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
    from rosx.packages.index import PackageIndex, PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used
    from rosx.workspace.executables import find_executables  # noqa: PLC0415 - not for -h
    from rosx.workspace.programs import bundled_program, overlays  # noqa: PLC0415 - not for -h

    options = _options(argv)
    if options is None:
        env.stdout.write(USAGE)
        return ExitStatus.OK
    prefix, debug, (package, executable, *rest) = options
    if executable.endswith("/"):
        env.out(f"Invalid filename:  {executable}")
        return ExitStatus.ERROR
    index = PackageIndex.from_environ(env.environ)
    bundled = bundled_program(package, executable)
    if bundled is not None and not overlays(index.on_path(package), executable):
        if debug:
            env.out(f"[rosrun] Looking in rospack dir: {bundled.parent}")
        return _start(bundled, prefix, rest, debug, env)
    try:
        directory = index.find(package)
    except PackageNotFoundError as error:
        env.err(str(error))
        _unknown_package([package, executable, *rest], index, env)
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
    return _start(chosen, prefix, rest, debug, env)


def _start(
    path: Path, prefix: list[str], rest: list[str], debug: bool, env: Environment
) -> Launch | Callable[[], int]:
    """How ``path`` runs with ``rest``: a program to become, or, for one of rosx's own Python
    programs without a ``--prefix``, the same run in this process (no second start-up)."""
    from rosx.client.script import run_script, shim_environ  # noqa: PLC0415 - found a program
    from rosx.workspace.executables import is_python_script  # noqa: PLC0415 - found a program
    from rosx.workspace.programs import is_bundled_file  # noqa: PLC0415 - found a program
    from rosx_commands.scripts import shim_dirs  # noqa: PLC0415 - found a program

    python = is_python_script(path)
    command = [*script_command(), str(path)] if python else [str(path)]
    if debug:
        env.out(f"[rosrun] Running {' '.join([*prefix, *command, *rest])}")
    if python and not prefix and is_bundled_file(path):
        return lambda: run_script(str(path), rest, stderr=env.stderr, shim_dirs=shim_dirs())
    return Launch([*prefix, *command, *rest], shim_environ(env.environ, shim_dirs()))


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
