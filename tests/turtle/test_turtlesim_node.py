"""turtlesim_node in this process, driven through rosx's node API on an in-process master."""

from __future__ import annotations

import io
import re
import threading
import xmlrpc.client
from collections.abc import Callable
from types import SimpleNamespace
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node, ServiceError
from rosx_turtle.engine import CENTRE
from rosx_turtle.node import run_turtlesim
from tests.support.procs import wait_for
from tests.support.simulators import Sim

Pose = get_message_class("turtlesim/Pose")
Color = get_message_class("turtlesim/Color")
Twist = get_message_class("geometry_msgs/Twist")
Spawn = get_service_class("turtlesim/Spawn")
Kill = get_service_class("turtlesim/Kill")
SetPen = get_service_class("turtlesim/SetPen")
TeleportAbsolute = get_service_class("turtlesim/TeleportAbsolute")
TeleportRelative = get_service_class("turtlesim/TeleportRelative")
Empty = get_service_class("std_srvs/Empty")

LINE = re.compile(r"\[(DEBUG| INFO| WARN|ERROR|FATAL)\] \[\d+\.\d{9}\]: (.*)")


def messages(lines: list[str]) -> list[str]:
    """The messages of rosconsole lines (checking each line's shape)."""
    found = []
    for line in lines:
        match = LINE.fullmatch(line)
        assert match, line
        found.append(match.group(2))
    return found


def call(node: Node, service: str, kind: Any, **fields: Any) -> Any:
    client = node.service_client(service, kind)
    return client.call(kind._request_class(**fields), timeout=10)


class Latest:
    """The last message of a topic, and how many came."""

    def __init__(self, node: Node, topic: str, kind: Any) -> None:
        self.messages: list[Any] = []
        self.subscriber = node.subscribe(topic, kind, self.messages.append)

    def wait(self, count: int = 1) -> Any:
        start = len(self.messages)
        wait_for(lambda: len(self.messages) >= start + count, what=f"{count} messages")
        return self.messages[-1]


def graph(node: Node) -> tuple[list[str], list[str], list[str]]:
    publishers, subscribers, services = node.master.call("getSystemState")
    return (
        sorted(t for t, _ in publishers),
        sorted(t for t, _ in subscribers),
        sorted(s for s, _ in services),
    )


def test_start_up_logs_params_and_graph(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    sim = make_sim()
    assert messages(sim.lines()) == [
        "Starting turtlesim with node name /turtlesim",
        "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
    ]
    node = make_node("observer")
    assert [node.params.get(f"/turtlesim/background_{c}") for c in "rgb"] == [69, 86, 255]
    publishers, subscribers, services = graph(node)
    assert {"/turtle1/pose", "/turtle1/color_sensor", "/rosout"} <= set(publishers)
    assert "/turtle1/cmd_vel" in subscribers
    assert {
        "/clear",
        "/kill",
        "/reset",
        "/spawn",
        "/turtle1/set_pen",
        "/turtle1/teleport_absolute",
        "/turtle1/teleport_relative",
        "/turtlesim/get_loggers",
        "/turtlesim/set_logger_level",
    } <= set(services)


def test_pose_and_colour_every_tick(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    make_sim()
    node = make_node("observer")
    poses = Latest(node, "/turtle1/pose", Pose)
    colours = Latest(node, "/turtle1/color_sensor", Color)
    pose = poses.wait(3)
    assert (pose.x, pose.y, pose.theta, pose.linear_velocity, pose.angular_velocity) == (
        CENTRE,
        CENTRE,
        0.0,
        0.0,
        0.0,
    )
    colour = colours.wait(3)
    assert (colour.r, colour.g, colour.b) == (69, 86, 255)


def test_cmd_vel_moves_the_turtle_for_a_second(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    make_sim()
    node = make_node("driver")
    poses = Latest(node, "/turtle1/pose", Pose)
    publisher = node.advertise("/turtle1/cmd_vel", Twist, queue_size=1)
    wait_for(lambda: publisher.get_num_connections() == 1, what="turtlesim to subscribe")
    twist = Twist()
    twist.linear.x = 2.0
    publisher.publish(twist)
    wait_for(
        lambda: bool(poses.messages) and poses.messages[-1].linear_velocity == 2.0, what="motion"
    )
    wait_for(lambda: poses.messages[-1].linear_velocity == 0.0, what="the command to time out")
    travelled = poses.wait().x - CENTRE
    assert 1.0 < travelled <= 2.02  # 62 or 63 ticks of 0.032 m on an idle machine
    assert poses.messages[-1].y == CENTRE


def test_spawn_and_kill(make_sim: Callable[..., Sim], make_node: Callable[[str], Node]) -> None:
    sim = make_sim()
    node = make_node("caller")
    assert call(node, "/spawn", Spawn, x=2.0, y=3.0, theta=0.5, name="").name == "turtle2"
    assert call(node, "/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="leo").name == "leo"
    assert "/turtle2/pose" in graph(node)[0]
    assert "/leo/teleport_absolute" in graph(node)[2]
    pose = Latest(node, "/turtle2/pose", Pose).wait()
    assert (pose.x, pose.y, pose.theta) == pytest.approx((2.0, 3.0, 0.5))
    call(node, "/kill", Kill, name="turtle2")
    assert "/turtle2/pose" not in graph(node)[0]
    assert "/turtle2/set_pen" not in graph(node)[2]
    assert call(node, "/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="").name == "turtle3"
    assert messages(sim.lines())[2:] == [
        "Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.500000]",
        "Spawning turtle [leo] at x=[1.000000], y=[1.000000], theta=[0.000000]",
        "Spawning turtle [turtle3] at x=[1.000000], y=[1.000000], theta=[0.000000]",
    ]


def test_failed_calls_answer_as_roscpp_does(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    sim = make_sim()
    node = make_node("caller")
    with pytest.raises(ServiceError) as failed:
        call(node, "/kill", Kill, name="nobody")
    assert str(failed.value) == "service [/kill] responded with an error: "
    with pytest.raises(ServiceError) as failed:
        call(node, "/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="turtle1")
    assert str(failed.value) == "service [/spawn] responded with an error: "
    invalid = (
        "Character [ ] at element [2] is not valid in Graph Resource Name [my turtle].  "
        "Valid characters are a-z, A-Z, 0-9, / and _."
    )
    with pytest.raises(ServiceError) as failed:
        call(node, "/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="my turtle")
    assert str(failed.value) == f"service [/spawn] responded with an error: {invalid}"
    with pytest.raises(ServiceError):
        call(node, "/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="1abc")
    assert messages(sim.errors()) == [
        "Tried to kill turtle [nobody], which does not exist",
        "A turtled named [turtle1] already exists",
        f"Exception thrown while processing service call: {invalid}",
        "Exception thrown while processing service call: Character [1] is not valid as the first "
        "character in Graph Resource Name [1abc].  Valid characters are a-z, A-Z, / and in some "
        "cases ~.",
    ]
    assert sim.node.snapshot(canvas=False).turtles.names == ("turtle1",)


def test_teleports_and_pen(make_sim: Callable[..., Sim], make_node: Callable[[str], Node]) -> None:
    sim = make_sim()
    node = make_node("caller")
    poses = Latest(node, "/turtle1/pose", Pose)
    call(node, "/turtle1/set_pen", SetPen, r=255, g=0, b=0, width=0, off=0)
    call(node, "/turtle1/teleport_absolute", TeleportAbsolute, x=1.0, y=2.0, theta=0.25)
    pose = poses.wait(2)
    assert (pose.x, pose.y, pose.theta) == pytest.approx((1.0, 2.0, 0.25))
    call(node, "/turtle1/teleport_relative", TeleportRelative, linear=1.0, angular=0.0)
    pose = poses.wait(2)
    assert pose.x == pytest.approx(1.0 + 0.9689124)
    turtles = sim.node.snapshot(canvas=False).turtles
    assert (tuple(turtles.pen_rgb[0]), int(turtles.pen_width[0]), bool(turtles.pen_on[0])) == (
        (255, 0, 0),
        1,
        True,
    )
    call(node, "/turtle1/set_pen", SetPen, r=0, g=0, b=0, width=0, off=1)
    assert not sim.node.snapshot(canvas=False).turtles.pen_on[0]


def test_teleport_draws_and_clear_erases(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    sim = make_sim()
    node = make_node("caller")
    call(node, "/turtle1/teleport_absolute", TeleportAbsolute, x=1.0, y=CENTRE, theta=0.0)
    wait_for(lambda: sim.node.snapshot(canvas=False).turtles.x[0] == 1.0, what="the teleport")
    row = round(CENTRE * 45)
    canvas = sim.node.snapshot().canvas
    assert canvas is not None
    assert tuple(canvas[row, 100]) == (179, 184, 255)  # the jump's trail
    node.params.set("/turtlesim/background_r", 255)
    call(node, "/clear", Empty)
    canvas = sim.node.snapshot().canvas
    assert canvas is not None
    assert tuple(canvas[row, 100]) == (255, 86, 255)
    assert "Clearing turtlesim." in messages(sim.lines())


def test_reset_starts_over(make_sim: Callable[..., Sim], make_node: Callable[[str], Node]) -> None:
    sim = make_sim()
    node = make_node("caller")
    call(node, "/spawn", Spawn, x=2.0, y=3.0, theta=0.5, name="")
    call(node, "/turtle1/teleport_absolute", TeleportAbsolute, x=1.0, y=1.0, theta=0.0)
    call(node, "/reset", Empty)
    snapshot = sim.node.snapshot(canvas=False)
    assert snapshot.turtles.names == ("turtle1",)
    assert snapshot.turtles.x[0] == CENTRE
    assert "/turtle2/pose" not in graph(node)[0]
    assert "/turtle1/pose" in graph(node)[0]
    assert call(node, "/spawn", Spawn, x=2.0, y=3.0, theta=0.5, name="").name == "turtle2"
    assert messages(sim.lines())[3:5] == [
        "Resetting turtlesim.",
        "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
    ]


def test_walls_warn_on_stderr(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    sim = make_sim()
    node = make_node("caller")
    call(node, "/turtle1/teleport_absolute", TeleportAbsolute, x=-1.0, y=CENTRE, theta=0.0)
    wait_for(lambda: bool(sim.errors()), what="the warning")
    assert (
        messages(sim.errors())[0]
        == "Oh no! I hit the wall! (Clamping from [x=-1.000000, y=5.544445])"
    )
    assert sim.errors()[0].startswith("[ WARN] [")


def test_two_simulators_side_by_side(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    first = make_sim("__ns:=turtlesim1", "__name:=sim")
    make_sim("__ns:=turtlesim2", "__name:=sim", "turtle1/cmd_vel:=/steer", "_background_b:=7")
    assert messages(first.lines())[0] == "Starting turtlesim with node name /turtlesim1/sim"
    node = make_node("caller")
    publishers, subscribers, services = graph(node)
    assert {"/turtlesim1/turtle1/pose", "/turtlesim2/turtle1/pose"} <= set(publishers)
    assert {"/turtlesim1/turtle1/cmd_vel", "/steer"} <= set(subscribers)
    assert {"/turtlesim1/spawn", "/turtlesim2/spawn", "/turtlesim2/sim/get_loggers"} <= set(
        services
    )
    assert node.params.get("/turtlesim1/sim/background_b") == 255
    assert node.params.get("/turtlesim2/sim/background_b") == 7
    assert (
        call(node, "/turtlesim2/spawn", Spawn, x=1.0, y=1.0, theta=0.0, name="").name == "turtle2"
    )
    assert "/turtlesim2/turtle2/pose" in graph(node)[0]


def test_views_observe_ticks(make_sim: Callable[..., Sim]) -> None:
    sim = make_sim()
    reports: list[Any] = []
    remove = sim.node.add_tick_listener(reports.append)
    wait_for(lambda: len(reports) >= 3, what="ticks")
    remove()
    assert reports[-1].turtles.names == ("turtle1",)
    snapshot = sim.node.snapshot()
    assert snapshot.ticks >= 3
    assert snapshot.canvas is not None and snapshot.canvas.shape == (500, 500, 3)
    assert snapshot.turtles.world_y[0] == pytest.approx(CENTRE)


def test_run_turtlesim_until_rosnode_kill(master: str, make_node: Callable[[str], Node]) -> None:
    out, err = io.StringIO(), io.StringIO()
    env = SimpleNamespace(
        stdout=out, stderr=err, stdin=io.StringIO(), environ={"ROS_MASTER_URI": master}
    )
    status: list[int] = []
    runner = threading.Thread(
        target=lambda: status.append(run_turtlesim(["__name:=killme"], env)), daemon=True
    )
    runner.start()
    node = make_node("killer")
    try:
        Latest(node, "/turtle1/pose", Pose).wait()  # started: it ticks
        uri = node.master.call("lookupNode", "/killme")
        xmlrpc.client.ServerProxy(uri).shutdown("/killer", "user request")
        runner.join(10)
    finally:
        if runner.is_alive():  # stop it whatever failed above
            xmlrpc.client.ServerProxy(node.master.call("lookupNode", "/killme")).shutdown("/t", "")
            runner.join(10)
    assert status == [0]
    assert messages(err.getvalue().splitlines()) == [
        "Shutdown request received.",
        "Reason given for shutdown: [user request]",
    ]
    assert "/turtle1/pose" not in graph(node)[0]  # it left the master before returning


def test_debug_lines_once_the_logger_says_so(
    make_sim: Callable[..., Sim], make_node: Callable[[str], Node]
) -> None:
    sim = make_sim()
    node = make_node("caller")
    loggers = call(node, "/turtlesim/get_loggers", get_service_class("roscpp/GetLoggers"))
    assert ("ros.turtlesim", "INFO") in [(lg.name, lg.level) for lg in loggers.loggers]
    call(
        node,
        "/turtlesim/set_logger_level",
        get_service_class("roscpp/SetLoggerLevel"),
        logger="ros.turtlesim",
        level="debug",
    )
    wait_for(lambda: len(sim.lines()) > 3, what="debug lines")
    assert messages(sim.lines())[2] == "[/turtle1]: pos_x: 5.544445 pos_y: 5.544445 theta: 0.000000"
    assert sim.lines()[2].startswith("[DEBUG] [")
