"""The lab sheet's names printed with spaces for underscores: ROS 1's error and status, then, on
a terminal, one line naming the command meant (``rostopic info /turtle1/cmd vel``,
``rosmsg show geometry msgs/Twist``, ``rqt graph``, ``catkin make``). Off a terminal the output
stays ROS 1's."""

from __future__ import annotations

import io
from collections.abc import Callable
from pathlib import Path

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.cli import clean_environ, rosx
from tests.support.terminal import NewTerminal


class TerminalText(io.StringIO):
    def isatty(self) -> bool:
        return True


def on_a_terminal(argv: list[str], master: str) -> tuple[int, list[str]]:
    """``rosx ARGV…`` with stderr on a terminal: the status and stderr's lines."""
    err = TerminalText()
    env = Environment(
        stdout=io.StringIO(), stderr=err, environ=clean_environ(ROS_MASTER_URI=master)
    )
    return run_tool(argv, env), err.getvalue().splitlines()


@pytest.fixture
def graph(master: str, make_node: Callable[..., Node]) -> str:
    """Lab 1's names on the master: /turtle1/cmd_vel, /turtlesim/background_r."""
    node = make_node("/teleop_turtle", environ={"ROS_IP": "127.0.0.1"})
    node.advertise("/turtle1/cmd_vel", get_message_class("geometry_msgs/Twist"))
    assert rosx("rosparam", "set", "/turtlesim/background_r", "69",
                environ=clean_environ(ROS_MASTER_URI=master)).status == 0  # fmt: skip
    return master


@pytest.mark.parametrize(
    ("argv", "status", "error", "hint"),
    [
        (["rostopic", "info", "/turtle1/cmd", "vel"], 2,
         "rostopic: error: you may only specify one topic name",
         "[rostopic] Did you mean /turtle1/cmd_vel? (rostopic info /turtle1/cmd_vel)"),
        (["rostopic", "echo", "turtle1/cmd", "vel"], 2,
         "rostopic: error: you may only specify one input topic",
         "[rostopic] Did you mean turtle1/cmd_vel? (rostopic echo turtle1/cmd_vel)"),
        (["rosmsg", "show", "geometry", "msgs/Twist"], 2,
         "rosmsg: error: you may only specify one message type",
         "[rosmsg] Did you mean geometry_msgs/Twist? (rosmsg show geometry_msgs/Twist)"),
        (["rosparam", "get", "/turtlesim/background", "r"], 2,
         "rosparam: error: too many arguments",
         "[rosparam] Did you mean /turtlesim/background_r? (rosparam get /turtlesim/background_r)"),
        (["rqt", "graph"], 2, "rqt: error: unexpected argument 'graph'",
         "[rqt] Did you mean rqt_graph? (rqt_graph)"),
        (["rospack", "find", "turtle", "sim"], 1,
         "[rospack] Error: failed to parse command-line options: too many positional options "
         "have been specified on the command line",
         "[rospack] Did you mean turtlesim? (rospack find turtlesim)"),
    ],
)  # fmt: skip
def test_words_typed_with_spaces_name_the_command_meant(
    graph: str, argv: list[str], status: int, error: str, hint: str
) -> None:
    got, lines = on_a_terminal(argv, graph)
    assert (got, lines[-2:]) == (status, [error, hint])
    plain = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert (plain.status, plain.err.splitlines()[-1]) == (status, error)  # ROS 1's, alone


def test_no_line_where_the_words_make_no_name(graph: str) -> None:
    got, lines = on_a_terminal(["rostopic", "info", "/turtle1/cmd", "speed"], graph)
    assert (got, lines[-1]) == (2, "rostopic: error: you may only specify one topic name")


@pytest.mark.parametrize("shell", ["bash", "zsh"])
def test_the_shell_names_catkin_make_for_catkin_make_typed_with_a_space(
    tmp_path: Path, shell: str
) -> None:
    user = NewTerminal(tmp_path / "home")
    user.run(f"rosx shell-init --install {shell}", shell)
    done = user.run("catkin make -j4\necho status=$?", shell, interactive=True)
    assert done.stdout.splitlines()[-1] == "status=127"
    lines = done.stderr.splitlines()
    said = next(i for i, line in enumerate(lines) if "catkin" in line)
    assert "command not found" in lines[said]  # the shell's own words (or its handler's) first
    assert lines[said + 1] == "[rosx] Did you mean catkin_make? (catkin_make -j4)"
    glued = user.run(
        "ros launch turtlesim multisim.launch\necho status=$?", shell, interactive=True
    )
    assert glued.stdout.splitlines()[-1] == "status=127"
    assert glued.stderr.splitlines()[-1] == (
        "[rosx] Did you mean roslaunch? (roslaunch turtlesim multisim.launch)"
    )
    other = user.run("no_such_program here\necho status=$?", shell, interactive=True)
    assert other.stdout.splitlines()[-1] == "status=127" and "[rosx]" not in other.stderr


@pytest.mark.parametrize(
    ("argv", "error", "hint"),
    [
        (["rospack", "find", "gazebo_ros"], "[rospack] Error: package 'gazebo_ros' not found",
         "[rosx] gazebo_ros is not part of rosx; instead: "
         "rosx roslaunch turtlebot3_stage turtlebot3_world.launch"),
        (["roscd", "--where", "move_base/launch"], "roscd: No such package/stack 'move_base/launch'",
         "[rosx] move_base is not part of rosx ('rosx --help' lists the packages it provides)"),
        (["rospack", "find", "turtlesm"], "[rospack] Error: package 'turtlesm' not found",
         "[rospack] Did you mean turtlesim? (rospack find turtlesim)"),
    ],
)  # fmt: skip
def test_a_package_rosx_lacks_is_said_to_be_lacking(
    master: str, argv: list[str], error: str, hint: str
) -> None:
    status, lines = on_a_terminal(argv, master)
    assert (status, lines) == (1, [error, hint])
