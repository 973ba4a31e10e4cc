"""Lab 1's graph, end to end: roscore, a headless turtlesim and a teleop node, then
``rosx rqt_graph --text`` and ``--dot`` in a subprocess (stdout not a terminal).

The teleop stand-in is a rosx node named ``/teleop_turtle`` publishing ``/turtle1/cmd_vel``;
when it shuts down, the next drawing no longer has it (Lab 1's third question).
"""

from __future__ import annotations

import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.cli import clean_environ
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.pty_terminal import on_a_terminal

README = Path(__file__).parents[2] / "README.md"
NODES_ONLY = (
    "╭────────────────╮                              ╭────────────╮\n"
    "│ /teleop_turtle │────── /turtle1/cmd_vel ─────▶│ /turtlesim │\n"
    "╰────────────────╯                              ╰────────────╯\n"
)


def readme_drawing() -> str:
    """The drawing the README shows for ``rosx rqt_graph --text --mode active``."""
    text = README.read_text(encoding="utf-8")
    after = text.split("`rosx rqt_graph --text --mode active` prints:", 1)[1]
    return after.split("```\n", 2)[1]


class World:
    def __init__(self, uri: str, env: dict[str, str]) -> None:
        self.uri = uri
        self.env = env

    def rqt_graph(self, *args: str) -> str:
        done = subprocess.run(
            [sys.executable, "-m", "rosx_commands", "rqt_graph", *args],
            env=self.env,
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
        assert done.returncode == 0, done.stderr
        return done.stdout

    def connected(self) -> bool:
        text = self.rqt_graph("--mode", "active")
        return "/teleop_turtle" in text and "/turtle1/cmd_vel" in text


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    env = clean_environ(ROS_MASTER_URI=uri)
    core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
    sim = [sys.executable, "-m", "rosx_turtle", "turtlesim_node", "--headless"]
    with running(core, env):
        wait_for(lambda: port_open(port), what="roscore")
        with running(sim, env):
            yield World(uri, env)


def test_teleop_to_turtlesim_and_gone_after_teleop_stops(world: World) -> None:
    teleop = Node("teleop_turtle", master_uri=world.uri, environ={}).start()
    try:
        teleop.advertise("/turtle1/cmd_vel", get_message_class("geometry_msgs/Twist"))
        wait_for(world.connected, what="teleop connected to turtlesim")
        active = world.rqt_graph("--text", "--mode", "active")
        assert active == readme_drawing()
        line = next(row for row in active.splitlines() if "/turtle1/cmd_vel" in row)
        assert line.index("/teleop_turtle") < line.index("/turtle1/cmd_vel")
        assert line.index("/turtle1/cmd_vel") < line.index("/turtlesim")
        assert world.rqt_graph() == NODES_ONLY  # no /rosout: Hide: Debug
        dot = world.rqt_graph("--dot", "--mode", "all")
        assert '"n_/teleop_turtle" -> "t_/turtle1/cmd_vel";' in dot
        assert '"t_/turtle1/cmd_vel" -> "n_/turtlesim";' in dot
    finally:
        teleop.shutdown("teleop stopped")
    after = world.rqt_graph("--mode", "active")
    assert "/teleop_turtle" not in after
    assert "/turtle1/cmd_vel" not in after  # a dead end now: nobody publishes
    everything = world.rqt_graph("--mode", "all", "--show-leaf-topics", "--show-dead-sinks")
    assert "/turtlesim" in everything
    assert "/turtle1/pose" in everything


def test_on_a_terminal_the_live_view_draws_the_graph_and_q_quits(world: World) -> None:
    teleop = Node("teleop_turtle", master_uri=world.uri, environ={}).start()
    try:
        teleop.advertise("/turtle1/cmd_vel", get_message_class("geometry_msgs/Twist"))
        wait_for(world.connected, what="teleop connected to turtlesim")
        args = [sys.executable, "-m", "rosx_commands", "rqt_graph", "--period", "0.5"]
        with on_a_terminal(args, ROS_MASTER_URI=world.uri) as terminal:
            terminal.read(20, until=b"/turtle1/cmd_vel")
            terminal.read(1)
            screen = re.sub(r"\x1b\[[0-9;?<>=$]*[A-Za-z]", "", terminal.output.decode())
            assert "Nodes only │ 2 nodes, 0 topics" in screen, screen[-2000:]
            assert "│ /teleop_turtle │" in screen
            terminal.type(b"q")
            assert terminal.wait(10) == 0
    finally:
        teleop.shutdown("teleop stopped")
