"""The tutorial nodes mimic and draw_square, against simulators in this process."""

from __future__ import annotations

import io
from collections.abc import Callable, Iterator
from types import SimpleNamespace
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_turtle.console import Console
from rosx_turtle.engine import CENTRE
from rosx_turtle.roscpp import NodeArgs
from rosx_turtle.tutorials.draw_square import DrawSquare, SquareDriver
from rosx_turtle.tutorials.mimic import start_mimic
from tests.support.procs import wait_for
from tests.support.simulators import Sim

Twist = get_message_class("geometry_msgs/Twist")


@pytest.fixture
def stop_later() -> Iterator[Callable[[Any], Any]]:
    running: list[Any] = []
    yield running.append
    for item in running:
        item.shutdown("test over")


def test_mimic_copies_the_leader_into_the_other_pond(
    master: str,
    make_sim: Callable[..., Sim],
    make_node: Callable[[str], Node],
    stop_later: Callable[[Any], Any],
) -> None:
    leader = make_sim("__ns:=turtlesim1", "__name:=sim")
    follower = make_sim("__ns:=turtlesim2", "__name:=sim")
    args = NodeArgs.parse(
        ["input:=turtlesim1/turtle1", "output:=turtlesim2/turtle1"], "turtle_mimic"
    )
    stop_later(start_mimic(args, {"ROS_MASTER_URI": master}))
    driver = make_node("driver")
    publisher = driver.advertise("/turtlesim1/turtle1/cmd_vel", Twist, queue_size=1)
    wait_for(lambda: publisher.get_num_connections() == 1, what="the leader to subscribe")
    twist = Twist()
    twist.linear.x = -1.0  # backwards: the follower goes forwards
    publisher.publish(twist)

    def x_of(sim: Sim) -> float:
        return float(sim.node.snapshot(canvas=False).turtles.x[0])

    wait_for(lambda: x_of(follower) > CENTRE + 0.1, what="the follower to move")
    assert x_of(leader) < CENTRE


def test_draw_square_resets_and_sets_goals(
    master: str, make_sim: Callable[..., Sim], stop_later: Callable[[Any], Any]
) -> None:
    sim = make_sim()
    out = io.StringIO()
    square = DrawSquare(
        NodeArgs.parse([], "draw_square"), {"ROS_MASTER_URI": master}, Console(out, out, {})
    )
    stop_later(square)
    square.start()
    wait_for(lambda: "Resetting turtlesim." in sim.out.getvalue(), what="the reset")
    wait_for(lambda: "New goal" in out.getvalue(), what="a goal")
    assert out.getvalue().splitlines()[0].endswith("New goal [7.544445 5.544445, 0.000000]")
    wait_for(lambda: sim.node.snapshot(canvas=False).turtles.x[0] > CENTRE + 0.1, what="motion")


def test_square_driver_state_machine() -> None:
    sent: list[tuple[float, float]] = []
    logged: list[str] = []
    driver = SquareDriver(lambda lin, ang: sent.append((lin, ang)), logged.append)
    driver.step(None)
    assert not sent
    pose = SimpleNamespace(x=1.0, y=1.0, theta=0.0, linear_velocity=0.0, angular_velocity=0.0)
    driver.step(pose)
    assert logged == ["New goal [3.000000 1.000000, 0.000000]"]
    assert sent == [(1.0, 0.0)]
    pose.x = 2.95
    driver.step(pose)
    assert sent[-1] == (0.0, 0.0) and driver.state == "STOP_FORWARD"
    pose.linear_velocity = 1.0
    driver.step(pose)
    assert sent[-1] == (0.0, 0.0) and driver.state == "STOP_FORWARD"
    pose.linear_velocity = 0.0
    driver.step(pose)
    assert driver.state == "TURN"
    assert logged[-2:] == ["Reached goal", "New goal [2.950000 1.000000, 1.570796]"]
    driver.step(pose)
    assert sent[-1] == (0.0, 0.4)
    pose.theta = 3.14
    driver.state, driver.goal = "STOP_FORWARD", (0.0, 0.0, 0.0)
    driver.step(pose)  # theta + PI/2 wraps into [-PI, PI)
    assert logged[-1] == "New goal [2.950000 1.000000, -1.572388]"
