"""turtle_teleop_key on a pseudo-terminal: help lines, arrow bytes to Twists, quitting cleanly
with the terminal restored; plus the read-error and end-of-input paths in this process."""

from __future__ import annotations

import contextlib
import io
import os
import pty
import select
import signal
import subprocess
import sys
import termios
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_turtle.teleop import HELP, run_teleop
from tests.support.procs import stop, wait_for

Twist = get_message_class("geometry_msgs/Twist")

# Takes the pty as controlling terminal first, so that Ctrl-C typed on it raises SIGINT.
TELEOP = (
    "import fcntl, sys, termios; fcntl.ioctl(0, termios.TIOCSCTTY, 0); "
    "from rosx_turtle.executables import main; sys.exit(main(sys.argv[1:]))"
)


@dataclass
class Teleop:
    process: subprocess.Popen[bytes]
    master_fd: int
    slave_fd: int
    cooked: list[Any]
    twists: list[Any] = field(default_factory=list)
    output: bytes = b""

    def read_until(self, text: bytes) -> None:
        def arrived() -> bool:
            ready, _, _ = select.select([self.master_fd], [], [], 0.05)
            if ready:
                try:
                    self.output += os.read(self.master_fd, 4096)
                except OSError:  # the child closed the terminal
                    return True
            return text in self.output

        wait_for(arrived, what=f"{text!r} on the terminal")

    def type(self, keys: bytes) -> None:
        os.write(self.master_fd, keys)


@contextlib.contextmanager
def running_teleop(master: str, listener: Node) -> Iterator[Teleop]:
    """turtle_teleop_key on a fresh pty, its Twists collected by ``listener``."""
    master_fd, slave_fd = pty.openpty()
    cooked = termios.tcgetattr(slave_fd)
    process = subprocess.Popen(
        [sys.executable, "-c", TELEOP, "turtle_teleop_key"],
        stdin=slave_fd,
        stdout=slave_fd,
        stderr=slave_fd,
        env={**os.environ, "ROS_MASTER_URI": master},
        start_new_session=True,
    )
    running = Teleop(process, master_fd, slave_fd, cooked)
    subscriber = listener.subscribe("/turtle1/cmd_vel", Twist, running.twists.append)
    try:
        running.read_until(b"'q' to quit.")
        wait_for(lambda: subscriber.get_num_connections() == 1, what="the teleop's publisher")
        yield running
    finally:
        stop(process)
        subscriber.unregister()
        os.close(master_fd)
        os.close(slave_fd)


@pytest.fixture
def teleop(master: str, make_node: Callable[[str], Node]) -> Iterator[Teleop]:
    with running_teleop(master, make_node("listener")) as running:
        yield running


def send(teleop: Teleop, keys: bytes) -> Any:
    """Type ``keys`` and wait for the Twist they publish."""
    count = len(teleop.twists)
    teleop.type(keys)
    wait_for(lambda: len(teleop.twists) > count, what="a Twist")
    return teleop.twists[-1]


def vector(twist: Any) -> tuple[float, ...]:
    return (
        twist.linear.x,
        twist.linear.y,
        twist.linear.z,
        twist.angular.x,
        twist.angular.y,
        twist.angular.z,
    )


def test_help_lines_and_raw_mode(teleop: Teleop) -> None:
    assert teleop.output.replace(b"\r\n", b"\n") == HELP.encode()
    assert HELP.splitlines()[1] == "-" * 27
    lflag = termios.tcgetattr(teleop.slave_fd)[3]
    assert not lflag & (termios.ICANON | termios.ECHO)
    assert lflag & termios.ISIG


def test_arrow_bytes_publish_one_twist_each_and_q_quits(teleop: Teleop) -> None:
    expected = [
        (b"\x1b[A", (2.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        (b"\x1b[B", (-2.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        (b"\x1b[D", (0.0, 0.0, 0.0, 0.0, 0.0, 2.0)),
        (b"\x1b[C", (0.0, 0.0, 0.0, 0.0, 0.0, -2.0)),
        (b"xQ[A", (2.0, 0.0, 0.0, 0.0, 0.0, 0.0)),  # capital A drives too; others are ignored
    ]
    for keys, twist in expected:
        assert vector(send(teleop, keys)) == twist
    assert len(teleop.twists) == len(expected)
    teleop.type(b"q")
    assert teleop.process.wait(15) == 0
    assert termios.tcgetattr(teleop.slave_fd) == teleop.cooked
    assert teleop.output.replace(b"\r\n", b"\n") == HELP.encode()  # nothing else printed


def test_ctrl_c_restores_the_terminal(teleop: Teleop) -> None:
    teleop.type(b"\x03")
    assert teleop.process.wait(15) == 0
    assert termios.tcgetattr(teleop.slave_fd) == teleop.cooked


def test_sigterm_restores_the_terminal(teleop: Teleop) -> None:
    teleop.process.send_signal(signal.SIGTERM)
    assert teleop.process.wait(15) == 0
    assert termios.tcgetattr(teleop.slave_fd) == teleop.cooked


def test_scales_come_from_the_public_namespace(
    master: str, make_node: Callable[[str], Node]
) -> None:
    listener = make_node("listener")
    listener.params.set("/scale_linear", 0.5)
    listener.params.set("/teleop_turtle/scale_angular", 9.0)  # private: not read
    try:
        with running_teleop(master, listener) as teleop:
            assert vector(send(teleop, b"A")) == (0.5, 0.0, 0.0, 0.0, 0.0, 0.0)
            assert vector(send(teleop, b"D")) == (0.0, 0.0, 0.0, 0.0, 0.0, 2.0)
    finally:
        listener.params.delete("/scale_linear")
        listener.params.delete("/teleop_turtle/scale_angular")


def test_end_of_input_ends_it(master: str) -> None:
    read, write = os.pipe()
    os.close(write)
    out = io.StringIO()
    env = SimpleNamespace(
        stdout=out,
        stderr=io.StringIO(),
        stdin=SimpleNamespace(fileno=lambda: read),
        environ={"ROS_MASTER_URI": master},
    )
    try:
        assert run_teleop([], env) == 0
    finally:
        os.close(read)
    assert out.getvalue() == HELP


def test_a_failed_read_prints_perror_and_fails(master: str) -> None:
    directory = os.open("/", os.O_RDONLY)
    err = io.StringIO()
    env = SimpleNamespace(
        stdout=io.StringIO(),
        stderr=err,
        stdin=SimpleNamespace(fileno=lambda: directory),
        environ={"ROS_MASTER_URI": master},
    )
    try:
        assert run_teleop([], env) == 255
    finally:
        os.close(directory)
    assert err.getvalue() == "read():: Is a directory\n"
