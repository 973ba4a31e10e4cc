"""teleop_twist_keyboard end to end on a terminal: the upstream script (fetched, run by ``rosx
run-script`` on rosx's rospy and roslib) and the one rosx ships (``rosx rosrun``) publish
teleop_twist_keyboard's Twists on ``/cmd_vel`` for its keys."""

from __future__ import annotations

import signal
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.fetched import fetched_file
from tests.support.procs import wait_for
from tests.support.pty_terminal import Terminal, on_a_terminal

Twist = get_message_class("geometry_msgs/Twist")
ROSX = [sys.executable, "-m", "rosx_commands"]


class Commands:
    """The Twists on /cmd_vel, as (linear.x, linear.y, angular.z)."""

    def __init__(self, node: Node) -> None:
        self.seen: list[tuple[float, float, float]] = []
        self.lock = threading.Lock()
        node.subscribe("/cmd_vel", Twist, self._add, queue_size=100)

    def _add(self, twist: Any) -> None:
        with self.lock:
            self.seen.append((twist.linear.x, twist.linear.y, twist.angular.z))

    def after(self, terminal: Terminal, key: bytes, command: tuple[float, float, float]) -> None:
        """Type ``key`` (again each second: upstream's script flushes what was typed while it
        was not reading, as ``tty.setraw`` does); wait until ``command`` is published."""
        typed = [0.0]

        def published() -> bool:
            if time.monotonic() - typed[0] > 1.0:
                terminal.type(key)
                typed[0] = time.monotonic()
            terminal.read(0.05)
            with self.lock:
                return any(seen == pytest.approx(command) for seen in self.seen)

        wait_for(published, what=f"{command} after {key!r}; output: {terminal.output[-300:]!r}")
        with self.lock:
            self.seen.clear()


def drive(terminal: Terminal, commands: Commands, help_text: bytes, *, raw: bool) -> None:
    """teleop_twist_keyboard's keys, as a user types them, and what they publish; then Ctrl-C,
    which a terminal in raw mode (``raw``: upstream's) hands the program as a key, and one that
    keeps ISIG turns into SIGINT (the test's terminal controls no process group: it is sent)."""
    terminal.read(60, until=b"currently:")  # the help, then the speeds: it reads keys now
    assert help_text in terminal.output, terminal.output
    commands.after(terminal, b"i", (0.5, 0.0, 0.0))
    commands.after(terminal, b"j", (0.0, 0.0, 1.0))
    commands.after(terminal, b"L", (0.0, -0.5, 0.0))  # Shift: strafing
    commands.after(terminal, b"k", (0.0, 0.0, 0.0))
    commands.after(terminal, b".", (-0.5, 0.0, 1.0))  # back, turning as it goes
    if raw:
        terminal.type(b"\x03")
    else:
        terminal.process.send_signal(signal.SIGINT)
    assert terminal.wait(30) == 0, terminal.output


@pytest.fixture
def commands(make_node: Callable[[str], Node]) -> Commands:
    return Commands(make_node("/robot"))


def test_the_upstream_script_runs_under_rosx(
    tmp_path: Path, master: str, commands: Commands
) -> None:
    script = fetched_file("ros-teleop/teleop_twist_keyboard", "teleop_twist_keyboard.py", tmp_path)
    with on_a_terminal([*ROSX, "run-script", str(script)], ROS_MASTER_URI=master) as terminal:
        drive(terminal, commands, b"Reading from the keyboard  and Publishing to Twist!", raw=True)


def test_the_bundled_program_runs_as_rosrun_starts_it(master: str, commands: Commands) -> None:
    argv = [*ROSX, "rosrun", "teleop_twist_keyboard", "teleop_twist_keyboard.py"]
    with on_a_terminal(argv, ROS_MASTER_URI=master) as terminal:
        drive(terminal, commands, b"each key sets the Twist published on cmd_vel", raw=False)
