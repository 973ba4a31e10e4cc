"""actionlib's own Python tests (github:ros/actionlib, ``actionlib/test``), run against rosx.

They are read from a copy of the repository named by ``UPSTREAM_ACTIONLIB`` (never copied
here) and skip without one. As their launch files pair them, each server script of theirs runs
under ``rosx run-script`` and the test module beside it in another, its ``unittest`` cases run
by a small runner after ``init_node`` (the node name their ``__main__`` would give).
"""

from __future__ import annotations

import contextlib
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for
from tests.support.upstream import export, needs_upstream

pytestmark = needs_upstream("actionlib")

#: Runs one test module's cases as rostest would, with a node of rostest's naming.
RUNNER = """
import importlib, sys, types, unittest
import rospy
module, node = sys.argv[1], sys.argv[2]
sys.argv = sys.argv[:1]
rospy.init_node(node)
sys.modules.setdefault("rostest", types.ModuleType("rostest"))  # imported, never used here
tests = unittest.defaultTestLoader.loadTestsFromModule(importlib.import_module(module))
outcome = unittest.TextTestRunner(verbosity=2).run(tests)
rospy.signal_shutdown("tests over")
sys.exit(0 if outcome.wasSuccessful() else 1)
"""


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("actionlib")
    export("actionlib", ["actionlib/test"], root)
    (root / "actionlib" / "test" / "run_tests.py").write_text(RUNNER)
    return root / "actionlib" / "test"


def _script(folder: Path, name: str, *argv: str) -> list[str]:
    return [sys.executable, "-m", "rosx_commands", "run-script", str(folder / name), *argv]


#: Each server script of theirs and the status topic that says it is up.
SERVERS = {
    "ref_server.py": "/reference_action/status",
    "ref_simple_server.py": "/reference_simple_action/status",
    "mock_simple_server.py": "/test_request_action/status",
}


@pytest.mark.parametrize(
    ("server", "module", "node"),
    [
        ("ref_server.py", "test_ref_action_server", "test_ref_simple_action_server"),
        ("ref_server.py", "simple_python_client_test", "simple_python_client_test"),
        ("ref_simple_server.py", "test_ref_simple_action_server", "test_ref_simple_action_server"),
        ("mock_simple_server.py", "exercise_simple_client", "exercise_simple_server"),
        (None, "test_server_components", "test_goal_id_generator"),
        (None, "test_imports", "test_imports"),
    ],
)
def test_actionlibs_own_tests_pass(
    master: str, folder: Path, tmp_path: Path, server: str | None, module: str, node: str
) -> None:
    env = clean_environ(ROS_MASTER_URI=master, HOME=str(tmp_path))
    log = tmp_path / "server.log"
    with log.open("w") as out, contextlib.ExitStack() as stack:
        if server is not None:
            stack.enter_context(
                running(_script(folder, server), env, stdout=out, stderr=subprocess.STDOUT)
            )
            status = SERVERS[server]
            wait_for(lambda: _published(env, status), 60, f"{server}'s {status}")
        done = subprocess.run(
            _script(folder, "run_tests.py", module, node),
            env=env, cwd=folder, capture_output=True, text=True, timeout=300, check=False,
        )  # fmt: skip
    assert done.returncode == 0, done.stderr + log.read_text()
    assert "\nOK" in done.stderr


def _published(env: dict[str, str], topic: str) -> bool:
    listed = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "rostopic", "list"],
        env=env, capture_output=True, text=True, timeout=60, check=False,
    )  # fmt: skip
    return topic in listed.stdout.split()
