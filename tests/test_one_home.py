"""Each concept has one home (ARCHITECTURE.md, "One home per concept"), and stays there.

The shipped packages are read as source (AST), not imported: a second definition of the
master's default address, a signal handler installed outside `rosx.signals`, a master asked
"are you up?" outside its client, or the master's graph unpacked outside `rosx.graph`, fails
here with the file and line to move. Docstrings are prose and are not searched.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("rosx", "commands/rosx_commands", "turtle/rosx_turtle")
#: The ROS packages rosx ships: users' programs, not rosx's code.
SHIPPED = ROOT / "rosx" / "packages" / "noetic"


def _sources() -> Iterator[tuple[str, ast.Module]]:
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if SHIPPED not in path.parents:
                yield path.relative_to(ROOT).as_posix(), ast.parse(path.read_text(), str(path))


SOURCES = dict(_sources())


def _docstrings(tree: ast.Module) -> set[int]:
    """The ids of the docstring nodes of a module, its classes and functions."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                found.add(id(body[0].value))
    return found


_CODE: dict[str, list[ast.AST]] = {}


def _code(name: str) -> list[ast.AST]:
    """The nodes of file ``name`` that have a line, docstrings left out (walked once)."""
    nodes = _CODE.get(name)
    if nodes is None:
        tree = SOURCES[name]
        prose = _docstrings(tree)
        nodes = _CODE[name] = [
            n for n in ast.walk(tree) if hasattr(n, "lineno") and id(n) not in prose
        ]
    return nodes


def _found(match: Callable[[ast.AST], bool], homes: set[str]) -> list[str]:
    """``file:line`` of each node ``match`` accepts, outside ``homes`` and docstrings."""
    return [
        f"{name}:{node.lineno}"  # type: ignore[attr-defined]
        for name in SOURCES
        if name not in homes
        for node in _code(name)
        if match(node)
    ]


def _call_of(node: ast.AST, *names: str) -> bool:
    """Whether ``node`` calls a function or method named one of ``names``."""
    if not isinstance(node, ast.Call):
        return False
    func = node.func
    name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
    return name in names


def _signal_signal(node: ast.AST) -> bool:
    """Whether ``node`` is a call of ``signal.signal``."""
    if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
        return False
    owner = node.func.value
    return node.func.attr == "signal" and isinstance(owner, ast.Name) and owner.id == "signal"


def _string_argument(node: ast.AST, value: str) -> bool:
    return isinstance(node, ast.Call) and any(
        isinstance(arg, ast.Constant) and arg.value == value for arg in node.args
    )


def test_the_masters_default_address_is_defined_once() -> None:
    def port_or_uri(node: ast.AST) -> bool:
        if not isinstance(node, ast.Constant):
            return False
        return node.value == 11311 or (isinstance(node.value, str) and "11311" in node.value)

    assert _found(port_or_uri, {"rosx/master/defaults.py"}) == []


def test_signal_handlers_are_installed_by_rosx_signals_only() -> None:
    # The zygote sets its forked children's dispositions back to the defaults, which is not
    # handling a signal.
    assert _found(_signal_signal, {"rosx/signals.py", "rosx/launch/run/zygote.py"}) == []


def test_only_the_master_client_asks_whether_a_master_is_up() -> None:
    def asks_pid(node: ast.AST) -> bool:
        # A node's pid is asked with ``node_call(uri, "getPid")``; the master's is the question.
        if _call_of(node, "getPid"):
            return True
        return _call_of(node, "call") and _string_argument(node, "getPid")

    # rosgraph's Master (rospy's API) has getPid as a method scripts call; the master watch
    # asks for the pid to tell a restarted master from the same one.
    homes = {"rosx/master/client.py", "rosx/client/rosgraph.py", "rosx/node/watchdog.py"}
    assert _found(asks_pid, homes) == []


def test_only_rosx_terminal_asks_whether_a_stream_is_a_terminal() -> None:
    assert _found(lambda node: _call_of(node, "isatty"), {"rosx/terminal.py"}) == []


def test_only_the_graph_and_the_master_client_read_the_masters_graph() -> None:
    def reads_system_state(node: ast.AST) -> bool:
        if _call_of(node, "system_state", "getSystemState"):
            return True
        return _call_of(node, "call") and _string_argument(node, "getSystemState")

    # rosgraph's Master (rospy's API) has getSystemState as a method scripts call; the master
    # answers it.
    homes = {"rosx/master/client.py", "rosx/client/rosgraph.py", "rosx/master/api.py"}
    found = [place for place in _found(reads_system_state, homes) if "rosx/graph/" not in place]
    assert found == []


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("import signal\nsignal.signal(signal.SIGINT, f)\n", ["x.py:2"]),
        ('"""signal.signal(x) in a docstring"""\n', []),
        ("URI = 'http://localhost:11311'\n", ["x.py:1"]),
    ],
)
def test_the_search_finds_code_and_skips_prose(source: str, expected: list[str]) -> None:
    saved = dict(SOURCES)
    SOURCES.clear()
    SOURCES["x.py"] = ast.parse(source)
    _CODE.pop("x.py", None)
    try:
        installs = _found(_signal_signal, set())
        port = _found(
            lambda node: isinstance(node, ast.Constant) and "11311" in str(node.value), set()
        )
    finally:
        SOURCES.clear()
        SOURCES.update(saved)
    assert sorted(installs + port) == expected
