"""Windows and macOS can import rosx: POSIX-only modules and names live in named, guarded modules.

The shipped packages are read as source (AST), not imported, so the check holds on any machine.
A POSIX-only import (termios, fcntl, pty, …) or name (``os.setsid``, ``signal.SIGKILL``, …) may
appear only in a module of `GUARDED`, and there only under a guard: inside a function (for an
import), a ``try`` block, or an ``if`` that tests ``sys.platform``, ``os.name`` or ``hasattr``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("rosx", "commands/rosx_commands", "turtle/rosx_turtle")

#: Standard-library modules that Windows lacks.
POSIX_MODULES = frozenset(
    {"termios", "tty", "pty", "fcntl", "resource", "pwd", "grp", "posix", "crypt", "spwd", "nis"}
    | {"syslog", "curses", "readline", "_posixsubprocess"}
)
#: Names of ``os`` and ``signal`` that Windows lacks.
POSIX_NAMES = {
    "os": frozenset(
        {"setsid", "killpg", "getpgid", "setpgid", "setpgrp", "getpgrp", "fork", "forkpty"}
        | {"openpty", "getuid", "geteuid", "getgid", "getegid", "setuid", "setgid", "mkfifo"}
        | {"WNOHANG", "wait3", "wait4", "sysconf", "statvfs", "getloadavg", "nice", "chown"}
        | {"lchown", "uname", "pipe2", "sched_getaffinity", "posix_spawn", "tcgetpgrp"}
        | {"sched_getscheduler", "SCHED_OTHER", "SCHED_BATCH", "getpriority", "PRIO_PROCESS"}
        | {"sched_yield"}
    ),
    "signal": frozenset(
        {"SIGKILL", "SIGHUP", "SIGQUIT", "SIGTSTP", "SIGCONT", "SIGSTOP", "SIGCHLD", "SIGUSR1"}
        | {"SIGUSR2", "SIGPIPE", "SIGALRM", "SIGWINCH", "SIGTTIN", "SIGTTOU", "alarm"}
        | {"setitimer", "pthread_kill", "pthread_sigmask", "siginterrupt", "sigwait"}
    ),
}
#: ``subprocess`` arguments that Windows refuses.
POSIX_KEYWORDS = frozenset({"preexec_fn"})

#: The modules allowed to use POSIX-only names, and why they need them.
GUARDED = {
    "rosx/node/subscription.py": "FIONREAD (fcntl, termios): what a drained subscription waits for",
    "commands/rosx_commands/rosbag/play.py": "space and s keys read in cbreak mode (termios, tty)",
    "turtle/rosx_turtle/keyboard.py": "turtle_teleop_key's raw keys (termios)",
    "rosx/launch/run/monitor.py": "roslaunch stops each node's process group (killpg, SIGKILL)",
    "rosx/launch/run/zygote.py": "roslaunch's fork server for Python nodes (fork, setsid, SIGCHLD)",
    "rosx/node/unixros.py": "a publisher asks what its subscriber has not read (fcntl's ioctl)",
    "rosx/node/slices.py": "short time slices and hand-offs (uname, sched_getscheduler, sched_yield)",
    "rosx/transport/descriptors.py": "the descriptor limit its servers keep a reserve under (resource)",
}

_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)


def _uses(tree: ast.AST) -> list[tuple[ast.AST, str, bool]]:
    """Each POSIX-only use in ``tree``: the node, what it is, and whether it is an import."""
    found: list[tuple[ast.AST, str, bool]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node, a.name, True) for a in node.names if _top(a.name) in POSIX_MODULES]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if _top(node.module) in POSIX_MODULES:
                found.append((node, node.module, True))
            banned = POSIX_NAMES.get(node.module, frozenset())
            found += [
                (node, f"{node.module}.{a.name}", True) for a in node.names if a.name in banned
            ]
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.attr in POSIX_NAMES.get(node.value.id, frozenset()):
                found.append((node, f"{node.value.id}.{node.attr}", False))
        elif isinstance(node, ast.keyword) and node.arg in POSIX_KEYWORDS:
            found.append((node, f"{node.arg}=", False))
    return found


def _top(module: str) -> str:
    return module.partition(".")[0]


def _parents(tree: ast.AST) -> dict[ast.AST, ast.AST]:
    return {child: node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)}


def _is_platform_test(test: ast.expr) -> bool:
    text = ast.unparse(test)
    return any(probe in text for probe in ("sys.platform", "os.name", "hasattr("))


def _guarded(node: ast.AST, parents: dict[ast.AST, ast.AST], is_import: bool) -> bool:
    child, parent = node, parents.get(node)
    while parent is not None:
        if isinstance(parent, ast.Try) and child in parent.body:
            return True
        if isinstance(parent, ast.If | ast.IfExp) and _is_platform_test(parent.test):
            return True
        if is_import and isinstance(parent, _FUNCTIONS):
            return True
        child, parent = parent, parents.get(parent)
    return False


def _sources() -> list[Path]:
    return sorted(p for package in PACKAGES for p in (ROOT / package).rglob("*.py"))


def _scan(path: Path) -> tuple[ast.AST, list[tuple[ast.AST, str, bool]]]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    return tree, _uses(tree)


def test_the_scan_finds_each_kind_of_use() -> None:
    code = (
        "import os, signal, subprocess\nimport termios\nfrom tty import setraw\n"
        "from os import setsid\nos.killpg(1, signal.SIGKILL)\nsubprocess.Popen([], preexec_fn=f)\n"
        "os.kill(1, signal.SIGTERM)\nimport sys, select\n"
    )
    names = [name for _, name, _ in _uses(ast.parse(code))]
    assert sorted(names) == sorted(
        ["termios", "tty", "os.setsid", "os.killpg", "signal.SIGKILL", "preexec_fn="]
    )


def test_guards_are_recognised() -> None:
    code = (
        "import sys\nif sys.platform != 'win32':\n    import termios\n"
        "try:\n    import fcntl\nexcept ImportError:\n    fcntl = None\n"
        "def f():\n    import pty\n    return os.setsid\n"
        "import resource\n"
    )
    tree = ast.parse(code)
    parents = _parents(tree)
    guarded = {name: _guarded(node, parents, is_import) for node, name, is_import in _uses(tree)}
    assert guarded == {
        "termios": True,
        "fcntl": True,
        "pty": True,
        "os.setsid": False,  # a function may be called on Windows too
        "resource": False,
    }


def test_posix_only_names_appear_only_in_the_guarded_modules() -> None:
    outside = [
        f"{path.relative_to(ROOT)}:{node.lineno}: {name}"  # type: ignore[attr-defined]
        for path in _sources()
        if path.relative_to(ROOT).as_posix() not in GUARDED
        for node, name, _ in _scan(path)[1]
    ]
    assert outside == [], "move these into a guarded module (tests/test_portability.py GUARDED)"


@pytest.mark.parametrize("module", sorted(GUARDED))
def test_each_guarded_module_guards_every_use(module: str) -> None:
    tree, uses = _scan(ROOT / module)
    assert uses, f"{module} no longer needs a place in GUARDED"
    parents = _parents(tree)
    unguarded = [
        f"{node.lineno}: {name}"  # type: ignore[attr-defined]
        for node, name, is_import in uses
        if not _guarded(node, parents, is_import)
    ]
    assert unguarded == []
