"""``rosx roscd`` and ``rosx rosls``: where a package is, for the ``roscd``/``rosls`` functions.

Changing the shell's directory is something only the shell can do, so ``roscd`` is a shell
function (``eval "$(rosx shell-init bash)"`` or a workspace's ``devel/setup.bash`` define it),
as in ROS 1. The function asks ``rosx roscd --where TARGET``, which prints the directory, or
rosbash's error text (``roscd: No such package/stack 'x'``, status 1). Run without the function,
``rosx roscd`` explains how to get it. ``rosx rosls`` lists the directory itself.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.context import Environment, ExitStatus

_ROSCD_USAGE = "usage: roscd package\n\nJump to target package."
_ROSLS_USAGE = "usage: rosls [package]\n\nLists contents of a package directory."
_NO_FUNCTION = (
    "roscd changes your shell's directory, which only a shell function can do. Define it with\n"
    '  eval "$(rosx shell-init bash)"     (or zsh; or source a workspace\'s devel/setup.bash)\n'
    "then run roscd (or rosx roscd) again."
)


def roscd(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx roscd [--where] [TARGET]``."""
    args = list(argv)
    where = bool(args) and args[0] == "--where"
    if where:
        args = args[1:]
    if (args and args[0] == "--help") or len(args) > 1:
        (env.stderr if where else env.stdout).write(_ROSCD_USAGE + "\n")
        return ExitStatus.OK

    from rosx.workspace.locate import LocateError, locate  # noqa: PLC0415 - workspace code loads only when used

    notes: list[str] = []
    try:
        directory = locate(args[0] if args else "", env.environ, notes)
    except LocateError as error:
        env.out(str(error)) if not where else env.err(str(error))
        return ExitStatus.ERROR
    for note in notes:
        env.err(note)
    if not where:
        env.err(_NO_FUNCTION)
        env.out(str(directory))
        return ExitStatus.ERROR
    env.out(str(directory))
    return ExitStatus.OK


def rosls(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rosls [TARGET]``: list the directory's entries, one a line."""
    args = list(argv)
    if args and args[0] == "--help":
        env.out(_ROSLS_USAGE)
        return ExitStatus.OK

    from rosx.workspace.locate import LocateError, locate  # noqa: PLC0415 - workspace code loads only when used

    try:
        directory = locate(args[0] if args else "", env.environ)
        entries = sorted(p.name for p in directory.iterdir())
    except LocateError as error:
        env.err(str(error))
        return ExitStatus.ERROR
    except OSError as error:
        env.err(f"rosls: cannot access '{error.filename}': {error.strerror}")
        return ExitStatus.USAGE
    for name in entries:
        env.out(name)
    return ExitStatus.OK
