"""rosx rqt_plot on a live turtlesim: ``/turtle1/pose/x`` rises while a Twist drives the
turtle; and the real program on a terminal (tmux) at 80x24 and 120x40."""

from __future__ import annotations

import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterator

import numpy as np
import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_commands.context import Environment
from rosx_commands.rqt_plot.app import PlotSettings, make_plot_app
from rosx_commands.rqt_plot.feed import LiveFeed
from rosx_turtle.sim.host import SimHost
from tests.support.cli import clean_environ
from tests.support.pilot import run

#: Seconds each step may take (generous: a loaded machine starts, connects and ticks slowly).
WAIT = 60.0


def test_pose_x_rises_while_the_turtle_moves(
    host: SimHost, make_node: Callable[[str], Node]
) -> None:
    twist = get_message_class("geometry_msgs/Twist")
    driver = make_node("driver").advertise("/turtle1/cmd_vel", twist)
    feed = LiveFeed(Environment(environ={"ROS_MASTER_URI": host.master_uri}))
    # A window longer than the test: the samples of the turtle sitting still stay drawn however
    # long a loaded machine takes to connect and drive.
    app = make_plot_app(feed, ["/turtle1/pose/x"], PlotSettings(fps=20, window=3600.0))

    async def drive() -> None:
        async with app.run_test(size=(100, 32)) as pilot:
            pane = app.pane
            series = pane.series[0]
            deadline = time.monotonic() + WAIT
            while len(series) < 5:  # the pose arrives (62.5 Hz): the turtle still sits
                assert time.monotonic() < deadline, series.status
                await pilot.pause(0.05)
            still = series.latest
            assert still is not None and still == pytest.approx(5.544445, abs=1e-4)
            command = twist()
            command.linear.x = 2.0
            deadline = time.monotonic() + WAIT
            while series.latest is None or series.latest < still + 1.0:
                assert time.monotonic() < deadline, "x did not rise"
                driver.publish(command)
                await pilot.pause(0.1)
            times, values = series.all()
            moving = values[values > still]
            assert len(moving) > 10 and (np.diff(moving) >= 0).all()  # rising, never back
            assert (np.diff(times) >= 0).all()
            deadline = time.monotonic() + WAIT
            # The drawn data and the axis that fits it are two updates: wait for both.
            while (
                pane.frames == 0
                or pane.plot._datasets[0].y.max() < still + 1.0
                or pane.plot._y_max < still + 1.0
            ):
                assert time.monotonic() < deadline, "the plot did not draw the rise"
                await pilot.pause(0.05)
            drawn = pane.plot._datasets[0]
            assert drawn.y.min() == pytest.approx(still, abs=1e-4)
            assert pane.plot._y_max >= still + 1.0
            assert "/turtle1/pose/x" in str(pane.query_one("#legend").render_line(0).text)

    run(drive())
    assert feed._node is None  # the plot's node left with the app


def _tmux(*args: str) -> str:
    done = subprocess.run(["tmux", *args], capture_output=True, text=True, check=False)
    return done.stdout


@pytest.fixture
def tmux_session() -> Iterator[str]:
    if shutil.which("tmux") is None:
        pytest.skip("tmux is not installed")
    name = f"rqt_plot_{time.monotonic_ns()}"
    yield name
    _tmux("kill-session", "-t", name)


def _screen(session: str) -> str:
    return _tmux("capture-pane", "-p", "-t", session)


def _wait_for(session: str, text: str, timeout: float = 30) -> str:
    deadline = time.monotonic() + timeout
    screen = _screen(session)
    while text not in screen:
        if time.monotonic() > deadline:
            raise AssertionError(f"{text!r} never shown; the screen:\n{screen}")
        time.sleep(0.2)
        screen = _screen(session)
    return screen


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
def test_rqt_plot_in_tmux(host: SimHost, tmux_session: str, size: tuple[int, int]) -> None:
    environ = clean_environ(ROS_MASTER_URI=host.master_uri, TERM="xterm-256color")
    environ["PYTHONPATH"] = ":".join([".", "commands", "turtle"])
    command = f"{sys.executable} -m rosx_commands rqt_plot /turtle1/pose/x:y; echo EXITED $?"
    width, height = size
    subprocess.run(
        ["tmux", "new-session", "-d", "-s", tmux_session, "-x", str(width), "-y", str(height)],
        env=environ,
        check=True,
    )
    _tmux("send-keys", "-t", tmux_session, f"clear; {command}", "Enter")
    screen = _wait_for(tmux_session, "/turtle1/pose/y  5.54444")
    lines = screen.splitlines()
    assert lines[0].startswith(" live │ window 10 s")
    assert "━━ /turtle1/pose/x  5.54444" in screen
    assert "q Quit" in lines[-1]  # how to quit shows at 80 columns too
    assert all(len(line) <= width for line in lines)
    _tmux("send-keys", "-t", tmux_session, "C-c")
    _wait_for(tmux_session, "EXITED 0")
