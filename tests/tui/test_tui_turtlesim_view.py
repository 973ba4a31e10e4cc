"""turtlesim_view: every turtlesim of a launched graph, drawn side by side on one terminal."""

from __future__ import annotations

import os
import re
import signal
import sys
from pathlib import Path

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_turtle.engine.constants import DEFAULT_PEN
from rosx_turtle.tui.factory import make_ponds_app
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.pond import PondView
from rosx_turtle.view.remote import RemotePond
from rosx_turtle.view.scene import Scene, TurtlePose
from tests.support.cli import clean_environ
from tests.support.pilot import run, until
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.pty_terminal import BLUE_BACKGROUND, on_a_terminal

MULTISIM = Path(__file__).resolve().parents[2] / "rosx/packages/noetic/share/turtlesim/launch"


def test_ponds_come_and_go_as_the_graph_says() -> None:
    pond = RemotePond()
    pond.set_colour("turtle1", DEFAULT_PEN)
    pond.set_pose("turtle1", TurtlePose("turtle1", 5.5, 5.5, 0.0))
    feed: Feed[Scene] = Feed(pond.scene())
    app = make_ponds_app()

    async def drive() -> tuple[int, bool, int]:
        async with app.run_test(size=(100, 30)) as pilot:
            app.add_pond("/turtlesim1/sim", feed)
            app.add_pond("/turtlesim2/sim", Feed(pond.scene()))
            await until(pilot, lambda: len(app.query(PondView)) == 2, "both ponds")
            shown = len(app.query(PondView))
            waiting = bool(app.query_one("#waiting").display)
            app.remove_pond("/turtlesim1/sim")
            await until(pilot, lambda: len(app.query(PondView)) == 1, "one pond left")
            return shown, waiting, len(app.query(PondView))

    assert run(drive()) == (2, False, 1)


def test_on_a_terminal_the_ponds_of_multisim_are_drawn_side_by_side(tmp_path: Path) -> None:
    port = free_port()
    uri = f"http://localhost:{port}"
    env = clean_environ(ROS_MASTER_URI=uri, ROS_HOME=str(tmp_path))
    env["PYTHONPATH"] = os.pathsep.join(
        str(Path(__file__).resolve().parents[2] / p) for p in (".", "commands", "turtle")
    )
    launch = [sys.executable, "-m", "rosx_commands", "roslaunch", str(MULTISIM / "multisim.launch")]
    with running(launch, env):
        wait_for(lambda: port_open(port), timeout=60, what="the launched core")
        viewer = [sys.executable, "-m", "rosx_commands", "rosrun", "turtlesim", "turtlesim_view"]
        with on_a_terminal(viewer, ROS_MASTER_URI=uri) as terminal:
            terminal.read(60, until=b"/turtlesim2/sim")
            terminal.read(30, until=BLUE_BACKGROUND)
            # The turtle of /turtlesim1 moves 2 m: its pond follows (the pose line says x=7.5…).
            driver = Node("/driver", master_uri=uri, environ={}).start()
            try:
                twist_type = get_message_class("geometry_msgs/Twist")
                cmd = driver.advertise("/turtlesim1/turtle1/cmd_vel", twist_type, queue_size=1)
                wait_for(lambda: cmd.get_num_connections() == 1, what="turtlesim1's subscription")
                twist = twist_type()
                twist.linear.x = 2.0
                cmd.publish(twist)
                terminal.read(30, until=b"x=7.5")
            finally:
                driver.shutdown("test over")
            terminal.read(0.5)
            terminal.type(b"q")
            assert terminal.wait(10) == 0
    text = _text(terminal.output)
    assert "/turtlesim1/sim" in text and "/turtlesim2/sim" in text, text
    assert BLUE_BACKGROUND in terminal.output
    assert "turtle1 → x=7.5" in text, text
    assert text.count("turtle1 → x=") >= 2, text  # a pose line under each pond


def _text(output: bytes) -> str:
    """What the terminal showed, without escape sequences and half blocks (for messages)."""
    plain = re.sub(rb"\x1b\[[0-9;?<>$]*[a-zA-Z~]|\x1b\][^\x07]*\x07", b"", output)
    return plain.decode(errors="replace").replace("\u2580", "")


def test_on_a_terminal_launched_turtlesims_log_instead_of_drawing(tmp_path: Path) -> None:
    """With --screen, both turtlesims write to roslaunch's terminal: as log lines, no pond."""
    port = free_port()
    launch = [
        sys.executable,
        "-m",
        "rosx_commands",
        "roslaunch",
        "--screen",
        str(MULTISIM / "multisim.launch"),
    ]
    with on_a_terminal(
        launch, ROS_MASTER_URI=f"http://localhost:{port}", ROS_HOME=str(tmp_path)
    ) as terminal:
        terminal.read(60, until=b"Starting turtlesim with node name /turtlesim2/sim")
        terminal.read(30, until=b"Starting turtlesim with node name /turtlesim1/sim")
        terminal.process.send_signal(signal.SIGINT)  # what Ctrl-C sends from a cooked terminal
        assert terminal.wait(30) == 0
    text = _text(terminal.output)
    assert "Spawning turtle [turtle1]" in text, text
    assert BLUE_BACKGROUND not in terminal.output
    assert "done" in text
