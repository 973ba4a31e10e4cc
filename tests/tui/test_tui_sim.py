"""``rosx sim``'s screen driven with the keyboard over the live world (textual's pilot).

A command lasts one second of wall time and each 16 ms tick moves the turtle by its speed times
16 ms (as turtlesim does), so a busy machine, running fewer ticks in that second, moves it less
far: distances are asserted as a whole number of ticks at the commanded speed, up to one second's
worth, and the motion as lasting the second, after waiting for it to start and to stop.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from typing import Any

from textual.message import Message
from textual.pilot import Pilot
from textual.widgets import Static, TabbedContent

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx_turtle.engine.constants import COMMAND_TIMEOUT, DT
from rosx_turtle.sim.host import SimHost
from rosx_turtle.tui.details import DetailsScreen
from rosx_turtle.tui.factory import make_sim_app
from rosx_turtle.tui.graph import fetch_graph
from rosx_turtle.tui.nodes import NodesPanel
from rosx_turtle.tui.pond import PondView
from rosx_turtle.tui.pose import PosePanel
from rosx_turtle.tui.teleop import TeleopPad
from rosx_turtle.tui.topics import TopicsPanel
from rosx_turtle.view.scene import TurtlePose
from tests.support.cli import clean_environ, rosx
from tests.support.pilot import run
from tests.support.procs import wait_for
from tests.support.tui import Pond, StaticLink, scripted_pond

Twist = get_message_class("geometry_msgs/Twist")
SIZE = (120, 36)


def turtle1(host: SimHost) -> TurtlePose:
    scene = host.scenes.value
    assert scene is not None
    return next(t for t in scene.turtles if t.name == "turtle1")


def _still(pose: TurtlePose) -> bool:
    return pose.linear_velocity == 0.0 and pose.angular_velocity == 0.0


async def settle(
    pilot: Pilot[Any], host: SimHost, since: TurtlePose | None = None, timeout: float = 20.0
) -> TurtlePose:
    """Wait (letting the app run) until turtle1 rests; its pose.

    With ``since``, the pose before a key press, first wait for the motion that key starts (the
    turtle moving or moved): on a loaded machine the command may reach the pond late.
    """
    deadline = time.monotonic() + timeout
    started = since is None
    while time.monotonic() < deadline:
        if host.scenes.value is None:  # the pond has not drawn its first scene yet
            await pilot.pause(0.05)
            continue
        pose = turtle1(host)
        if not started and since is not None:
            started = not _still(pose) or (pose.x, pose.y, pose.theta) != (
                since.x,
                since.y,
                since.theta,
            )
        if started and _still(pose):
            return pose
        await pilot.pause(0.05)
    raise AssertionError("turtle1 kept moving" if started else "turtle1 never moved")


async def press_and_settle(
    pilot: Pilot[Any], host: SimHost, key: str, before: TurtlePose
) -> TurtlePose:
    """Press ``key`` and wait for the motion it starts to end; the pose then.

    The command lasts its second of wall time (turtlesim's timeout): the turtle stops no
    sooner than a second after the press, however few ticks a loaded machine ran in it.
    """
    pressed = time.monotonic()
    await pilot.press(key)
    after = await settle(pilot, host, since=before)
    assert time.monotonic() - pressed > COMMAND_TIMEOUT
    return after


def ticks(change: float, speed: float) -> int:
    """How many 16 ms ticks at ``speed`` make ``change``: a whole number, up to a second's
    worth."""
    count = change / (speed * DT)
    assert math.isclose(count, round(count), abs_tol=1e-3), change  # float32 poses
    # A tick less than a period late is made up for at once: a second can hold a few more. A
    # loaded machine runs fewer: the command lasts a second of wall time, and ticks more than a
    # period late are lost, as turtlesim's timer loses them (46 of 62 seen at a load of 9 on two
    # cores; 10 and 4, in full CI runs, the engine's thread held off for most of the second).
    assert 1 <= round(count) <= 1 / DT + 3, change
    return round(count)


def spy(node: Node, host: SimHost) -> list[Any]:
    """Record every Twist on /turtle1/cmd_vel once connected to the teleop."""
    received: list[Any] = []
    node.subscribe("/turtle1/cmd_vel", Twist, received.append)
    publisher = host.cmd_vel
    assert publisher is not None
    wait_for(lambda: publisher.get_num_connections() >= 2, what="the spy's connection")
    return received


def test_up_arrow_drives_turtle1_two_metres_forward(
    host: SimHost, make_node: Callable[[str], Node]
) -> None:
    twists = spy(make_node("/twist_spy"), host)
    # teleop → turtlesim (and the spy, in this process too) without a socket or serializing
    assert host.cmd_vel is not None
    publication = host.cmd_vel.publication
    assert {link.callerid for link in publication.local_links} == {"/turtlesim", "/twist_spy"}
    assert publication.links == ()
    sent: list[Message] = []
    app = make_sim_app(host)

    async def drive() -> tuple[TurtlePose, TurtlePose, str]:
        async with app.run_test(size=SIZE, message_hook=sent.append) as pilot:
            before = await settle(pilot, host)
            after = await press_and_settle(pilot, host, "up", before)
            await pilot.pause(0.1)
            return before, after, app.query_one(PosePanel).text

    before, after, panel = run(drive())
    ticks(after.x - before.x, 2.0)  # one Twist lasts 1 s: about 2 m (less if ticks lag)
    assert after.y == before.y and after.theta == before.theta == 0.0
    assert f"x: {after.x}" in panel.splitlines()
    wait_for(lambda: len(twists) >= 1, what="the Twist")
    (twist,) = twists
    assert (twist.linear.x, twist.linear.y, twist.linear.z) == (2.0, 0.0, 0.0)
    assert (twist.angular.x, twist.angular.y, twist.angular.z) == (0.0, 0.0, 0.0)
    # The hook sees a message at each widget it bubbles through: count each message once.
    pad_sent = {id(m): m for m in sent if isinstance(m, TeleopPad.Sent)}.values()
    assert [(m.linear, m.angular) for m in pad_sent] == [(2.0, 0.0)]


def test_left_and_right_turn_in_place(host: SimHost, make_node: Callable[[str], Node]) -> None:
    twists = spy(make_node("/twist_spy"), host)
    app = make_sim_app(host)

    async def turn() -> tuple[TurtlePose, TurtlePose, TurtlePose]:
        async with app.run_test(size=SIZE) as pilot:
            start = await settle(pilot, host)
            left = await press_and_settle(pilot, host, "left", start)
            right = await press_and_settle(pilot, host, "right", left)
            return start, left, right

    start, left, right = run(turn())
    ticks(left.theta - start.theta, 2.0)  # about 2 rad counter-clockwise
    ticks(left.theta - right.theta, 2.0)  # and about as much back
    assert (left.x, left.y) == (start.x, start.y) == (right.x, right.y)
    wait_for(lambda: len(twists) >= 2, what="two Twists")
    assert [(t.linear.x, t.angular.z) for t in twists] == [(0.0, 2.0), (0.0, -2.0)]


def test_the_first_twist_after_start_moves_turtle1(host: SimHost) -> None:
    # start() returned (the fixture): turtlesim already listens, so nothing sent now is lost.
    assert host.cmd_vel is not None
    assert "/turtlesim" in host.cmd_vel.subscriber_ids()
    wait_for(lambda: host.scenes.value is not None, what="the first scene")
    before = turtle1(host)
    host.drive(-2.0, 0.0)
    wait_for(lambda: turtle1(host).x < before.x, what="turtle1 backing up")


def test_down_arrow_backs_up(host: SimHost) -> None:
    app = make_sim_app(host)

    async def back() -> tuple[TurtlePose, TurtlePose]:
        async with app.run_test(size=SIZE) as pilot:
            start = await settle(pilot, host)
            return start, await press_and_settle(pilot, host, "down", start)

    start, end = run(back())
    ticks(start.x - end.x, 2.0)
    assert math.isclose(end.y, start.y)


def test_panels_show_lab1_graph(host: SimHost) -> None:
    app = make_sim_app(host)

    async def look() -> tuple[dict[str, list[str]], list[str]]:
        async with app.run_test(size=SIZE) as pilot:
            topics, nodes = app.query_one(TopicsPanel), app.query_one(NodesPanel)
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline:
                if topics.row_count >= 5 and nodes.row_count >= 3:
                    break
                await pilot.pause(0.1)
            rows = {str(k.value): [str(c) for c in topics.get_row(k)] for k in topics.rows}
            return rows, [str(key.value) for key in nodes.rows]

    topics, nodes = run(look())
    assert topics["/turtle1/cmd_vel"][:4] == ["/turtle1/cmd_vel", "geometry_msgs/Twist", "1", "1"]
    assert topics["/turtle1/pose"][:2] == ["/turtle1/pose", "turtlesim/Pose"]
    assert {"/rosout", "/rosout_agg", "/turtle1/color_sensor"} <= topics.keys()
    assert nodes == ["/rosout", "/teleop_turtle", "/turtlesim"]


def test_focused_pane_owns_the_arrow_keys(host: SimHost) -> None:
    app = make_sim_app(host)

    async def switch() -> list[tuple[str | None, int, bool]]:
        seen = []
        async with app.run_test(size=SIZE) as pilot:
            pad = app.query_one(TeleopPad)

            def state() -> tuple[str | None, int, bool]:
                bindings = app.screen.active_bindings
                return (
                    app.focused.id if app.focused else None,
                    pad.sent,
                    bindings["up"].binding.description == "Forward",
                )

            await pilot.pause()
            seen.append(state())
            await pilot.press("tab")
            await pilot.press("up", "down")  # the topic table's cursor, not the turtle
            seen.append(state())
            await pilot.press("tab")
            seen.append(state())
            await pilot.press("shift+tab", "shift+tab")
            await pilot.press("up")
            seen.append(state())
            assert pad.border_subtitle == "arrow keys drive the turtle"
        return seen

    assert run(switch()) == [
        ("teleop", 0, True),
        ("topics", 0, False),
        ("nodes", 0, False),
        ("teleop", 1, True),
    ]


def test_q_quits(host: SimHost) -> None:
    app = make_sim_app(host)

    async def quit_app() -> bool:
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("q")
            await pilot.pause()
            return app.is_running

    assert run(quit_app()) is False


def test_keys_send_what_turtle_teleop_key_sends() -> None:
    link = StaticLink(Pond().scene())
    app = make_sim_app(link)

    async def type_keys() -> None:
        async with app.run_test(size=SIZE) as pilot:
            # Arrows, then the bytes that end their escape sequences; other keys send nothing.
            await pilot.press("up", "down", "left", "right", "A", "B", "D", "C", "x", "a")

    run(type_keys())
    arrows = [(2.0, 0.0), (-2.0, 0.0), (0.0, 2.0), (0.0, -2.0)]
    assert link.sent == arrows + arrows


async def wait_until(pilot: Pilot[Any], ready: Callable[[], object], what: str) -> None:
    """Let the app run until ``ready()`` is true (a generous deadline)."""
    deadline = time.monotonic() + 30
    while not ready():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        await pilot.pause(0.05)


def test_enter_on_a_topic_shows_its_info_and_latest_messages(host: SimHost) -> None:
    app = make_sim_app(host)

    async def look() -> tuple[str, str, bool, bool]:
        async with app.run_test(size=SIZE) as pilot:
            topics = app.query_one(TopicsPanel)
            await wait_until(pilot, lambda: "/turtle1/pose" in topics.rows, "the topic list")
            topics.focus()
            topics.move_cursor(row=topics.get_row_index("/turtle1/pose"))
            await pilot.press("enter")
            details = app.screen
            assert isinstance(details, DetailsScreen)
            await wait_until(pilot, lambda: details.info and details.echoed, "info and echo")
            info, echoed = details.info, details.echoed
            await pilot.press("escape")
            await pilot.pause()
            return info, echoed, app.screen is not details, app.focused is topics

    info, echoed, closed, refocused = run(look())
    lines = info.splitlines()
    assert lines[:3] == ["Type: turtlesim/Pose", "", "Publishers: "]
    assert lines[3].startswith(" * /turtlesim (http://")
    # The latest messages, as rostopic echo prints them (turtle1 sits where it started).
    assert echoed.splitlines()[-6:] == [
        "x: 5.544444561004639",
        "y: 5.544444561004639",
        "theta: 0.0",
        "linear_velocity: 0.0",
        "angular_velocity: 0.0",
        "---",
    ]
    assert closed and refocused
    # The echo's node leaves with the details.
    wait_for(
        lambda: not any("rosx_sim_echo" in n.name for n in fetch_graph(host.master_uri).nodes),
        what="the echo node gone",
    )


def test_enter_on_a_node_shows_rosnode_info(host: SimHost) -> None:
    app = make_sim_app(host)

    async def look() -> str:
        async with app.run_test(size=SIZE) as pilot:
            nodes = app.query_one(NodesPanel)
            await wait_until(pilot, lambda: "/teleop_turtle" in nodes.rows, "the node list")
            nodes.focus()
            nodes.move_cursor(row=nodes.get_row_index("/teleop_turtle"))
            await pilot.press("enter")
            details = app.screen
            assert isinstance(details, DetailsScreen)
            await wait_until(pilot, lambda: details.info, "the node's info")
            return details.info

    info = run(look())
    environ = clean_environ(ROS_MASTER_URI=host.master_uri)
    printed = rosx("rosnode", "info", "/teleop_turtle", environ=environ).out
    # Everything up to the live connections is what rosnode info prints.
    assert info.split("Pid:")[0] == printed.split("Pid:")[0]
    assert f"Pid: {os.getpid()}" in info.splitlines()


def test_details_at_80x24_from_the_topics_tab_echo_and_close() -> None:
    link = StaticLink(Pond().scene())
    app = make_sim_app(link)

    async def look() -> tuple[str, str, bool]:
        async with app.run_test(size=(80, 24)) as pilot:
            await pilot.pause()
            topics = app.query_one(TopicsPanel)
            await wait_until(pilot, lambda: topics.row_count == 5, "the topic list")
            await pilot.press("tab", "tab")  # teleop → the tabs → the Topics table
            assert app.focused is topics
            await pilot.press("down", "down", "enter")
            details = app.screen
            assert isinstance(details, DetailsScreen)
            await wait_until(pilot, lambda: "/turtle1/cmd_vel" in link.echoes, "the echo")
            link.echoes["/turtle1/cmd_vel"]("linear: \n  x: 2.0\n---\n")
            await wait_until(pilot, lambda: details.echoed, "the message shown")
            info, echoed = details.info, details.echoed
            await pilot.press("escape")
            await pilot.pause()
            return info, echoed, "/turtle1/cmd_vel" in link.echoes

    info, echoed, still_echoing = run(look())
    assert info == "Type: geometry_msgs/Twist\n\nPublishers: None\n"
    assert echoed == "linear: \n  x: 2.0\n---\n"
    assert not still_echoing


def test_the_pond_gets_its_space_first() -> None:
    app = make_sim_app(StaticLink(scripted_pond().scene()))

    async def squeeze() -> list[tuple[int, int, bool] | str]:
        seen: list[tuple[int, int, bool] | str] = []
        async with app.run_test(size=(80, 24)) as pilot:
            for size in ((80, 24), (120, 40), (60, 16), (59, 30), (100, 13)):
                await pilot.resize_terminal(*size)
                await pilot.pause(0.1)
                await pilot.pause()
                if not app.query_one("#columns").display:
                    seen.append(str(app.query_one("#too-small", Static).render()))
                    continue
                fit = app.query_one(PondView).renderer.fit
                seen.append((fit.side, fit.rows, bool(app.query(TabbedContent))))
        return seen

    assert run(squeeze()) == [
        (40, 20, True),  # 80x24: a 40x20 pond, the panels in tabs
        (72, 36, False),  # 120x40: the panels stacked
        (20, 10, True),  # 60x16: still a pond
        "rosx sim needs at least 60x14; this terminal is 59x30",
        "rosx sim needs at least 60x14; this terminal is 100x13",
    ]
