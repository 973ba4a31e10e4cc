"""The line after ROS 1's error that tells a user what went wrong and what to type instead.

ROS 1's tools answer a package they cannot find with ``[rospack] Error: package 'x' not
found`` whether ``x`` was mistyped, is one of the user's own that is not on the package path,
or is a package rosx does not provide (Gazebo, the TurtleBot3 packages…). rosx prints ROS 1's
text and status, then, on a terminal, one line more: the name the words make with ``_`` for
the spaces a printed sheet shows (``rosrun rqt graph rqt graph``), a close name, or that the
package is not part of rosx and what rosx has instead (`rosx.workspace.programs.lacking`).
Off a terminal the output stays ROS 1's, for the scripts that read it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx_commands.context import Environment

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable, Sequence

    from rosx.packages.index import PackageIndex


#: How alike (difflib's ratio) a known package's name must be to be suggested for another.
_CLOSE = 0.8


def close_name(name: str, known: Iterable[str]) -> str | None:
    """The one of ``known`` most like ``name``, if it is very like it. Closer than for a
    program's name: package and file names share many parts (``_msgs``, ``ros``, ``.launch``)."""
    import difflib  # noqa: PLC0415 - hints only

    close = difflib.get_close_matches(name, sorted(known), n=1, cutoff=_CLOSE)
    return close[0] if close else None


def rosx_tools() -> tuple[str, ...]:
    """The commands rosx has (``rosx TOOL``)."""
    from rosx_commands.main import TOOLS  # noqa: PLC0415 - the table of tools, no tool

    return tuple(TOOLS)


def known_packages(index: PackageIndex) -> set[str]:
    """The packages a command line may name: on the package path, and rosx's own."""
    from rosx.workspace.programs import provided_packages  # noqa: PLC0415 - hints only

    return {*index.packages, *provided_packages()}


def unknown_package(
    words: Sequence[str],
    index: PackageIndex,
    env: Environment,
    retyped: Callable[[list[str]], str],
    tool: str,
) -> None:
    """After ROS 1's error for the package ``words[0]``, on a terminal: the line that helps.

    Args:
        words: the package and the words after it on the command line.
        index: the package index the command used.
        env: where the line goes (stderr, on a terminal only).
        retyped: the command line to suggest, from the corrected ``words``.
        tool: the tool's name in brackets at the start of the line (``rosrun``).
    """
    line = unknown_package_line(words, index, retyped, tool)
    if line is not None and env.stderr_isatty:
        env.err(line)


def unknown_package_line(
    words: Sequence[str], index: PackageIndex, retyped: Callable[[list[str]], str], tool: str
) -> str | None:
    """The line `unknown_package` prints (None: nothing to add)."""
    from rosx.names.typos import rejoined  # noqa: PLC0415 - hints only
    from rosx.workspace.programs import COUNTERPARTS, lacking  # noqa: PLC0415 - hints only

    package = words[0]
    known = known_packages(index)
    fixed = rejoined(list(words), known)
    if fixed is not None:
        return f"[{tool}] Did you mean {fixed[0]}? ({retyped(fixed)})"
    if package not in COUNTERPARTS:
        close = close_name(package, known)
        if close is not None:
            return f"[{tool}] Did you mean {close}? ({retyped([close, *words[1:]])})"
    return lacking(package, rosx_tools())


__all__ = ["close_name", "known_packages", "rosx_tools", "unknown_package", "unknown_package_line"]
