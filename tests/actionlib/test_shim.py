"""``import actionlib`` in the scripts rosx runs: ROS 1's module paths and names over rosx's
modules; and, for a Python without rosx (ROS 1's own) given the same path, ROS 1's actionlib."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from rosx_commands.scripts import shim_dirs
from tests.support.cli import clean_environ
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ
from tests.support.scripts import script_command

SCRIPT = """
import json
import actionlib
from actionlib import action_client, goal_id_generator, handle_tracker_deleter
from actionlib.action_server import ActionServer
from actionlib.server_goal_handle import ServerGoalHandle
from actionlib.simple_action_client import SimpleActionClient, SimpleGoalState
from actionlib.simple_action_server import SimpleActionServer
from actionlib.status_tracker import StatusTracker
from actionlib.msg import TestAction, TestRequestGoal
from actionlib_msgs.msg import GoalStatus
print(json.dumps({
    "modules": [m.__name__ for m in (action_client, goal_id_generator, handle_tracker_deleter)],
    "same": actionlib.SimpleActionServer is SimpleActionServer and actionlib.GoalStatus is GoalStatus,
    "names": [GoalStatus.to_string(8), SimpleGoalState.to_string(1),
              actionlib.CommState.to_string(4), actionlib.TerminalState.to_string(5)],
    "md5": TestAction._md5sum,
    "constant": TestRequestGoal.TERMINATE_EXCEPTION,
}))
"""


def test_scripts_find_ros1s_modules_and_names(tmp_path: Path) -> None:
    script = tmp_path / "uses_actionlib.py"
    script.write_text(SCRIPT)
    done = subprocess.run(
        script_command(script),
        env=clean_environ(), capture_output=True, text=True, timeout=60, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == {
        "modules": [
            "rosx.actionlib.action_client",
            "rosx.actionlib.goal_id_generator",
            "rosx.actionlib.status_tracker",
        ],
        "same": True,
        "names": ["RECALLED", "ACTIVE", "WAITING_FOR_CANCEL_ACK", "REJECTED"],
        "md5": "991e87a72802262dfbe5d1b3cf6efc9a",
        "constant": 5,
    }


@needs_ros1
def test_ros1s_python_given_the_same_path_gets_ros1s_actionlib(tmp_path: Path) -> None:
    path = ":".join(str(d) for d in shim_dirs())
    done = subprocess.run(
        [ROS1_PYTHON, "-c", "import actionlib.simple_action_client as m; print(m.__file__)"],
        env=ros1_environ(PYTHONPATH=path), cwd=tmp_path, capture_output=True, text=True,
        timeout=60, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("/usr/lib/python3/dist-packages/actionlib/")
