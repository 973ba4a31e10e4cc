"""The line after ROS 1's error that tells a user what went wrong and what to type instead.

ROS 1's tools answer a package they cannot find with ``[rospack] Error: package 'x' not
found`` whether ``x`` was mistyped, is one of the user's own that is not on the package path,
or is a package rosx does not provide (Gazebo, the TurtleBot3 packages…). rosx prints ROS 1's
text and status, then, on a terminal, one line more: the name the words make with ``_`` for
the spaces a printed sheet shows (``rosrun rqt graph rqt graph``), a close name, or that the
package is not part of rosx and what rosx has instead (`rosx.workspace.programs.lacking`).
Off a terminal the output stays ROS 1's, for the scripts that read it.

`spaced_words` does the same for every tool that fails (``rostopic info /turtle1/cmd vel``,
``rosmsg show geometry msgs/Twist``, ``rqt graph``): `rosx_commands.main` asks it after a
tool's error, on a terminal. What a name may be depends on the tool: a topic, node, service or
parameter of the running graph, a message or service type, a package, a rosx command.
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
    from rosx_commands.tools import TOOLS  # noqa: PLC0415 - the table of tools, no tool

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


#: What each tool's arguments may name, for `spaced_words`.
_KINDS: dict[str, tuple[str, ...]] = {
    "rostopic": ("topics", "msg"),
    "rosmsg": ("msg",),
    "rossrv": ("srv",),
    "rosnode": ("nodes",),
    "rosparam": ("params",),
    "rosservice": ("services", "srv"),
    "rosbag": ("topics",),
    "rospack": ("packages",),
    "roscd": ("packages",),
    "rosls": ("packages",),
    "rosed": ("packages",),
    "roscp": ("packages",),
    "rosversion": ("packages",),
    "rqt": ("tools",),
}


class _Names:
    """Whether a name exists, asked of the sources a tool's arguments may name (each asked
    once, and only when a name is to be checked)."""

    def __init__(self, kinds: tuple[str, ...], env: Environment) -> None:
        self.kinds = kinds
        self.env = env
        self._graph: set[str] | None = None
        self._packages: set[str] | None = None

    def __call__(self, name: str) -> bool:
        return any(self._has(kind, name) for kind in self.kinds)

    def _has(self, kind: str, name: str) -> bool:
        if kind in ("msg", "srv"):
            return "/" in name and self._has_type(kind, name)
        if kind == "packages":
            return name in self.packages()
        if kind == "tools":
            return name in rosx_tools()
        graph = self.graph(kind)
        return name in graph or f"/{name}" in graph

    def _has_type(self, kind: str, name: str) -> bool:
        from rosx.msg.store import TypeStore  # noqa: PLC0415 - hints only

        store = TypeStore.from_environ(self.env.environ)
        return store.has_msg(name) if kind == "msg" else store.has_srv(name)

    def packages(self) -> set[str]:
        if self._packages is None:
            from rosx.packages.index import PackageIndex  # noqa: PLC0415 - hints only

            self._packages = known_packages(PackageIndex.from_environ(self.env.environ))
        return self._packages

    def graph(self, kind: str) -> set[str]:
        """The running graph's topics, nodes, services and parameters (none without a master)."""
        if self._graph is None:
            self._graph = set()
            from rosx.graph.fetch import fetch_state  # noqa: PLC0415 - hints only
            from rosx.master.client import MasterError, MasterUnreachable  # noqa: PLC0415 - the master's code loads only to talk to one

            try:
                state = fetch_state(self.env.master_uri, "/rosx_hints", bus_info=False)
                self._graph.update([*state.topics, *state.nodes, *state.services])
                if "params" in self.kinds:
                    master = self.env.master("/rosx_hints")
                    try:
                        self._graph.update(str(p) for p in master.getParamNames())
                    finally:
                        master.close()
            except (MasterUnreachable, MasterError, OSError):
                pass
        return self._graph


#: The tools whose argument names a package, and which of their words it is (rospack's sub-
#: command comes first).
_PACKAGE_WORD = {"rospack": 1, "roscd": 0, "rosls": 0, "rosed": 0, "roscp": 0, "rosversion": 0}


def after_error(tool: str, args: Sequence[str], env: Environment) -> str | None:
    """The line that helps after ``tool ARGS…`` failed: the names typed with spaces meant
    (`spaced_words`), else, for a package that is nowhere, what rosx has instead of it."""
    line = spaced_words(tool, args, env)
    if line is not None or tool not in _PACKAGE_WORD:
        return line
    words = [a for a in args if not a.startswith("-")]
    at = _PACKAGE_WORD[tool]
    if len(words) <= at:
        return None
    from rosx.packages.index import PackageIndex  # noqa: PLC0415 - hints only

    package = words[at].partition("/")[0]
    index = PackageIndex.from_environ(env.environ)
    if not package or package == "log" or package in known_packages(index):
        return None
    return unknown_package_line(
        [package, *words[at + 1 :]],
        index,
        lambda fixed: " ".join([tool, *words[:at], *fixed]),
        tool,
    )


def spaced_words(tool: str, args: Sequence[str], env: Environment) -> str | None:
    """For ``tool ARGS…`` that failed: the name two or more of the arguments make joined with
    ``_``, if one exists (see the module docstring), as a line naming the command meant."""
    from rosx.names.typos import joined  # noqa: PLC0415 - hints only

    kinds = _KINDS.get(tool)
    if kinds is None:
        return None
    words = [tool, *args] if kinds == ("tools",) else list(args)
    exists = _Names(kinds, env)
    for start in range(len(words) - 1):
        run = []
        for word in words[start:]:
            if word.startswith("-") or ":=" in word:
                break
            run.append(word)
        found = joined(run, exists) if len(run) > 1 else None
        if found is not None:
            name, count = found
            fixed = [*words[:start], name, *words[start + count :]]
            command = " ".join(fixed if kinds == ("tools",) else [tool, *fixed])
            return f"[{tool}] Did you mean {name}? ({command})"
    return None


__all__ = [
    "close_name",
    "known_packages",
    "rosx_tools",
    "spaced_words",
    "unknown_package",
    "unknown_package_line",
]
