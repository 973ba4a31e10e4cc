"""With no master, every tool prints ROS 1's one line (and its exit status) when stderr is not a
terminal; the line on how to start a master follows only on a terminal."""

from __future__ import annotations

import io

import pytest

from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port

ROS1_LINE = "ERROR: Unable to communicate with master!\n"

COMMANDS = [
    (["rosparam", "list"], 1),
    (["rosparam", "set", "/x", "1"], 1),
    (["rostopic", "list"], 1),
    (["rostopic", "echo", "chatter"], 1),
    (["rostopic", "pub", "chatter", "std_msgs/String", "hello"], 1),
    (["rostopic", "type", "std_msgs/String"], 1),
    (["rostopic", "find", "std_msgs/String"], 1),
    (["rosnode", "list"], 1),
    (["rosnode", "info", "/x"], 1),
    (["rosservice", "list"], 2),
    (["rosservice", "call", "--wait", "add_two_ints", "1", "2"], 2),
    (["rosservice", "find", "test_ros/AddTwoInts"], 2),
]


def _no_master() -> dict[str, str]:
    return clean_environ(ROS_MASTER_URI=f"http://127.0.0.1:{free_port()}")


@pytest.mark.parametrize(("argv", "status"), COMMANDS, ids=[" ".join(a) for a, _ in COMMANDS])
def test_stderr_is_ros1s_line_alone(argv: list[str], status: int) -> None:
    done = rosx(*argv, environ=_no_master())
    assert (done.status, done.err) == (status, ROS1_LINE)


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_terminal_also_gets_how_to_start_a_master() -> None:
    err = _Terminal()
    environ = _no_master()
    env = Environment(stdout=io.StringIO(), stderr=err, stdin=io.StringIO(), environ=environ)
    assert run_tool(["rosparam", "list"], env) == 1
    first, hint, *rest = err.getvalue().splitlines()
    assert first == ROS1_LINE.strip()
    assert hint.startswith(f"No master answers at ROS_MASTER_URI={environ['ROS_MASTER_URI']}")
    assert "rosx roscore" in hint
    assert rest == []
