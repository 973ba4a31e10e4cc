"""``rosx rosed PKG FILE`` and ``rosx roscp PKG FILE DEST``: a package's file, edited or copied.

ROS 1's rosbash defines them as shell functions: the file is found anywhere below the package's
directory (and its ``lib/PKG`` folder), hidden folders and ``build/`` aside; several files of
that name are offered to pick from. rosed opens it with ``$EDITOR`` (default ``vim``); roscp
copies it. The texts are rosbash's (``Couldn't find package [x]``, ``That file does not exist in
that package.``). Neither changes the shell's state, so here they are plain commands; when no
editor can be run, rosed says so in one line instead of the shell's ``command not found``.
"""

from __future__ import annotations

import os
import shlex
import shutil
from collections.abc import Sequence
from pathlib import Path

from rosx_commands.context import Environment, ExitStatus

_ROSED_USAGE = "usage: rosed [package] [file]\n\nEdit a file within a package."
_ROSCP_USAGE = (
    "usage: roscp package filename target\n\nCopy a file from a package to target location."
)


def _files(package_dir: Path, name: str) -> list[Path]:
    from rosx.packages.crawl import libexec_dir  # noqa: PLC0415 - the package index loads only when used

    found: list[Path] = []
    roots = [r for r in (libexec_dir(package_dir), package_dir) if r is not None]
    for root in roots:
        for directory, subdirs, files in os.walk(root, followlinks=True):
            here = Path(directory)
            subdirs[:] = sorted(
                d for d in subdirs if not d.startswith(".") and not (here == root and d == "build")
            )
            found += [here / f for f in sorted(files) if f == name and not f.startswith(".")]
    return list(dict.fromkeys(found))


def _choose(paths: list[Path], env: Environment) -> Path | None:
    env.out("You have chosen a non-unique filename, please pick one of the following:")
    for number, path in enumerate(paths, start=1):
        env.stderr.write(f"{number}) {path}\n")
    env.stderr.write("#? ")
    env.stderr.flush()
    answer = env.stdin.readline().strip()
    if answer.isdigit() and 1 <= int(answer) <= len(paths):
        return paths[int(answer) - 1]
    return None


def find_file(package: str, name: str, env: Environment) -> Path | None:
    """The file ``name`` of ``package``, as rosbash's ``_roscmd`` finds it; None (with
    rosbash's message printed) when there is none."""
    from rosx.packages.index import PackageIndex, PackageNotFoundError  # noqa: PLC0415 - the package index loads only when used

    try:
        directory = PackageIndex.from_environ(env.environ).find(package)
    except PackageNotFoundError:
        env.out(f"Couldn't find package [{package}]")
        return None
    found = _files(directory, name)
    if not found:
        env.out("That file does not exist in that package.")
        return None
    if len(found) > 1:
        return _choose(found, env)
    return found[0]


def _editor(env: Environment) -> list[str] | None:
    words = shlex.split(env.environ.get("EDITOR") or "") or ["vim"]
    return words if shutil.which(words[0], path=env.environ.get("PATH")) else None


def rosed(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosed PACKAGE FILE``: open the file in ``$EDITOR`` (vim by default)."""
    args = list(argv)
    if args[:1] == ["--help"]:
        env.out(_ROSED_USAGE)
        return ExitStatus.OK
    if len(args) != 2:
        env.out(_ROSED_USAGE)
        return ExitStatus.ERROR
    path = find_file(args[0], args[1], env)
    if path is None:
        return ExitStatus.ERROR
    editor = _editor(env)
    if editor is None:
        given = env.environ.get("EDITOR")
        what = (
            f"the editor $EDITOR names ({given})"
            if given
            else "vim (rosed's editor when $EDITOR is not set)"
        )
        env.err(
            f"rosed: cannot edit {path}: {what} is not installed; "
            "set EDITOR, e.g. export EDITOR=nano"
        )
        return ExitStatus.ERROR
    env.stdout.flush()
    env.stderr.flush()
    os.execvpe(editor[0], [*editor, str(path)], dict(env.environ))
    return ExitStatus.ERROR  # not reached


def roscp(argv: Sequence[str], env: Environment) -> int:
    """Run ``roscp PACKAGE FILE TARGET``: copy the package's file to ``TARGET``."""
    args = list(argv)
    if args[:1] == ["--help"] or len(args) != 3:
        env.out(_ROSCP_USAGE)
        return ExitStatus.OK
    path = find_file(args[0], args[1], env)
    if path is None:
        return ExitStatus.ERROR
    from rosx_commands.invocation import working_directory  # noqa: PLC0415 - this tool's parts load only when used

    target = working_directory(env) / args[2]
    try:
        shutil.copy(path, target)
    except OSError as error:
        env.err(f"cp: cannot create regular file '{args[2]}': {error.strerror}")
        return ExitStatus.ERROR
    return ExitStatus.OK


__all__ = ["find_file", "roscp", "rosed"]
