"""turtlesim_node's pond: followed live through the pilot, and drawn on a pseudo-terminal.

The pseudo-terminal tests run the program as a user does (stdout a terminal), which no CI job
has otherwise: they type ``q`` or Ctrl-C and check that the node left the graph.
"""

from __future__ import annotations

import contextlib
import re
import signal
import sys
from collections.abc import Iterator

import pytest

from rosx.master.server import MasterThread
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.transport.client import XmlRpcClient
from rosx_turtle.node import TurtlesimNode
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.tui.factory import make_pond_app
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.status import PoseLine
from rosx_turtle.view.adapt import follow
from rosx_turtle.view.scene import Scene
from rosx_turtle.view.status import status_text
from tests.support.pilot import run, until
from tests.support.procs import wait_for
from tests.support.pty_terminal import BLUE_BACKGROUND, Terminal, on_a_terminal

Twist = get_message_class("geometry_msgs/Twist")
#: The pose line once a turtle at the centre went east at 2 m/s for turtlesim's 1 s command
#: timeout: about 2 m on a quiet machine, less on a busy one, whose timer ticks fewer of its
#: fixed 16 ms steps in that second of wall time (as turtlesim's does).
STOPPED = re.compile(r"turtle1 → x=(\d+\.\d\d) y=5\.54 θ=0\.00")
PROGRAM = (
    "import sys\nfrom rosx_turtle.tui.pond_run import run_turtlesim_node\n"
    "sys.exit(run_turtlesim_node(sys.argv[1:]))"
)


@pytest.fixture
def master() -> Iterator[str]:
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as thread:
        yield thread.uri


def moving(scenes: Feed[Scene]) -> bool:
    scene = scenes.value
    return scene is None or any(t.linear_velocity or t.angular_velocity for t in scene.turtles)


def shown(scenes: Feed[Scene]) -> str:
    """The pose line of the latest scene."""
    scene = scenes.value
    return "" if scene is None else status_text(scene.turtles)


def nodes_on(uri: str) -> set[str]:
    client = XmlRpcClient(timeout=5.0)
    try:
        _, _, state = client.call(uri, "getSystemState", "/test")
    finally:
        client.close()
    return {node for entries in state for _, nodes in entries for node in nodes}


def test_the_pond_follows_a_running_turtlesim(master: str) -> None:
    sim = TurtlesimNode(NodeArgs.parse([], "turtlesim"), environ={"ROS_MASTER_URI": master})
    driver = Node("/driver", master_uri=master, environ={}).start()
    scenes: Feed[Scene] = Feed()
    unfollow = follow(sim.start(), scenes.offer)
    try:
        publisher = driver.advertise("/turtle1/cmd_vel", Twist, queue_size=1)
        wait_for(lambda: publisher.get_num_connections() == 1, what="turtlesim's subscription")
        app = make_pond_app(scenes)

        async def watch() -> tuple[str, str, int, int]:
            async with app.run_test(size=(80, 30)) as pilot:
                pond, poses = app.query_one(PondView), app.query_one(PoseLine)
                await until(pilot, lambda: poses.text.startswith("turtle1"), "the first pose")
                before, frames = poses.text, pond.frames
                twist = Twist()
                twist.linear.x = 2.0
                publisher.publish(twist)
                await until(pilot, lambda: poses.text != before, "the turtle to move")
                await until(pilot, lambda: not moving(scenes), "the turtle to stop")
                await until(pilot, lambda: poses.text == shown(scenes), "the last pose drawn")
                return before, poses.text, frames, pond.frames

        before, after, frames_before, frames_after = run(watch())
    finally:
        unfollow()
        driver.shutdown("test over")
        sim.shutdown("test over")
    assert before == "turtle1 → x=5.54 y=5.54 θ=0.00"
    stopped = STOPPED.fullmatch(after)
    assert stopped and 5.54 < float(stopped[1]) <= 7.6, after
    assert frames_after - frames_before >= 5  # the pond was redrawn as the turtle went


def turtlesim_on_a_terminal(uri: str, *args: str) -> contextlib.AbstractContextManager[Terminal]:
    return on_a_terminal([sys.executable, "-c", PROGRAM, *args], ROS_MASTER_URI=uri)


@pytest.mark.parametrize("key", [b"q", b"\x03"], ids=["q", "ctrl-c"])
def test_on_a_terminal_the_pond_is_drawn_until_the_user_quits(master: str, key: bytes) -> None:
    with turtlesim_on_a_terminal(master) as terminal:
        terminal.read(15, until=BLUE_BACKGROUND)
        wait_for(lambda: "/turtlesim" in nodes_on(master), what="turtlesim")
        terminal.read(0.5)
        terminal.type(key)
        assert terminal.wait(10) == 0
    assert "\u2580".encode() in terminal.output and BLUE_BACKGROUND in terminal.output
    assert b"turtle1 " in terminal.output  # the pose line
    assert b"Starting turtlesim" not in terminal.output  # no log lines over the pond
    assert "/turtlesim" not in nodes_on(master)


def test_on_a_terminal_rosnode_kill_closes_the_pond(master: str) -> None:
    with turtlesim_on_a_terminal(master) as terminal:
        terminal.read(15, until=BLUE_BACKGROUND)
        wait_for(lambda: "/turtlesim" in nodes_on(master), what="turtlesim")
        client = XmlRpcClient(timeout=5.0)
        _, _, uri = client.call(master, "lookupNode", "/test", "/turtlesim")
        client.call(uri, "shutdown", "/rosnode", "kill")
        client.close()
        assert terminal.wait(10) == 0


def test_headless_on_a_terminal_prints_log_lines(master: str) -> None:
    with turtlesim_on_a_terminal(master, "--headless") as terminal:
        terminal.read(15, until=b"Spawning turtle [turtle1]")
        terminal.process.send_signal(signal.SIGINT)  # what Ctrl-C sends from a cooked terminal
        assert terminal.wait(10) == 0
    assert b"Starting turtlesim with node name /turtlesim" in terminal.output
    assert BLUE_BACKGROUND not in terminal.output
