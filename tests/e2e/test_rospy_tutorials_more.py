"""The rest of rospy_tutorials under ``rosx rosrun`` and ``rosx roslaunch``: headers, callback
arguments, parameters, connection headers, a shutdown hook and publishing by fields, with the
names, topics and printed lines of the originals."""

from __future__ import annotations

import ast
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.procs import stop, wait_for
from tests.support.tutorial_nodes import ROSPY_LINE, Runs, lines


@pytest.fixture
def runs(master: str, tmp_path: Path) -> Runs:
    return Runs(master, tmp_path)


def test_headers_are_numbered_by_the_publisher(runs: Runs) -> None:
    with (
        runs.node("rospy_tutorials", "talker_header.py") as talker,
        runs.node("rospy_tutorials", "listener_header.py") as listener,
    ):
        wait_for(lambda: len(lines(listener)) >= 3, what="the listener hearing the talker")
    assert lines(talker)[:2] == ["hello world 0", "hello world 1"]
    for line in lines(listener)[:3]:
        found = re.fullmatch(
            r"/listener_header_\d+_\d+ (\d+) I just heard that hello world (\d+) at +0\.000000",
            line,
        )
        assert found is not None, line
        assert int(found[1]) == int(found[2]) + 1  # the first message is number 1


def test_each_subscription_gets_its_own_callback_argument(runs: Runs) -> None:
    with (
        runs.node("rospy_tutorials", "listener_with_user_data.py") as listener,
        runs.node("rospy_tutorials", "talker") as _talker,
    ):
        kinds = ("#1: I heard [hello world ", "#2: I heard [hello world ", "I heard [hello world ")
        wait_for(
            lambda: all(any(line.startswith(k) for line in lines(listener)) for k in kinds),
            what="each subscription's line",
        )
    userdata = [line for line in lines(listener) if line.startswith("I heard")]
    assert re.fullmatch(
        r"I heard \[hello world [\d.]+\] with userdata \[\('chatter1', 4\)\]", userdata[0]
    )


def test_param_talker_launch_reads_sets_and_uses_its_parameters(runs: Runs) -> None:
    with runs.tool("roslaunch", "rospy_tutorials", "param_talker.launch") as log:
        wait_for(lambda: "]: Hello World" in log.read_text(), what="the first utterance")
        listed = runs_tool(runs, "rosparam", "get", "/foo")
    said = [
        line.partition("]: ")[2]
        for line in log.read_text().splitlines()
        if re.match(ROSPY_LINE, line)
    ]
    assert said[: said.index("Hello World") + 1] == [
        "/global_example is global value",
        "/foo/utterance is Hello World",
        "/foo/param_talker/topic_name is chatter",
        "/foo/default_param is default_value",
        "gains are 1.0, 2.0, 3.0",
        "setting parameters...",
        "...parameters have been set",
        "deleted /foo/to_delete parameter",
        "found global_example parameter under key: /global_example",
        "Hello World",
    ]
    assert "bool_True: true" in listed and "list_of_floats:" in listed
    assert "to_delete" not in listed
    assert "private_bar: 3" in listed


def runs_tool(runs: Runs, *argv: str) -> str:
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", *argv],
        env=runs.env, capture_output=True, text=True, timeout=60, check=False,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_connection_headers_carry_the_cookies(runs: Runs) -> None:
    with (
        runs.node("rospy_tutorials", "listener_connection_header.py") as listener,
        runs.node("rospy_tutorials", "talker_connection_header.py") as _talker,
    ):
        wait_for(lambda: len(lines(listener)) >= 1, what="the listener hearing the talker")
    assert re.fullmatch(r"/talker_\d+_\d+ just offered me oreo cookies", lines(listener)[0])

    with runs.node("rospy_tutorials", "server_connection_header.py") as server:
        client = runs.run("rospy_tutorials", "client_connection_header.py", "3", "4")
        wait_for(lambda: len(lines(server)) >= 3, what="the server's lines")
    said = client.stdout.splitlines()
    assert (client.returncode, said[0], said[2]) == (
        0,
        "Requesting 3+4 with cookies=peanut butter",
        "3 + 4 = 7",
    )
    prefix = "Server's connection headers were "
    assert said[1].startswith(prefix)
    header = ast.literal_eval(said[1][len(prefix) :])
    assert (header["callerid"], header["service"], header["type"]) == (
        "/add_two_ints_server",
        "/add_two_ints",
        "rospy_tutorials/AddTwoInts",
    )
    assert lines(server) == [
        "Request from /unnamed",
        "Request gave me peanut butter cookies",
        "Returning [3 + 4 = 7]",
    ]


def test_the_shutdown_hook_publishes_last_words(runs: Runs, tmp_path: Path) -> None:
    log = tmp_path / "shutdown.log"
    with (
        runs.node("rospy_tutorials", "listener") as listener,
        log.open("w") as out,
    ):
        talker = subprocess.Popen(
            runs.command("rospy_tutorials", "publish_on_shutdown.py"),
            env=runs.env, stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
            start_new_session=True,
        )  # fmt: skip
        try:
            wait_for(lambda: "Hit ctrl-C" in log.read_text(), what="the talker waiting")
            talker_name = _talker_name(runs)
            wait_for(
                lambda: "* to: /listener_" in runs_tool(runs, "rosnode", "info", talker_name),
                what="the listener connected",
            )
            os.killpg(talker.pid, signal.SIGINT)
            talker.wait(30)
            wait_for(
                lambda: any("I heard I'm dead!" in line for line in lines(listener)),
                what="the last words",
            )
        finally:
            stop(talker)
    assert log.read_text().splitlines() == ["Hit ctrl-C to see on_shutdown example", "I'm dead!"]


def _talker_name(runs: Runs) -> str:
    nodes = runs_tool(runs, "rosnode", "list").split()
    return next(name for name in nodes if name.startswith("/talker_"))


def test_advanced_publish_fills_messages_from_arguments(runs: Runs) -> None:
    with runs.node("rospy_tutorials", "advanced_publish.py") as talker:
        echo = runs_tool(runs, "rostopic", "echo", "-n", "2", "/color")
    assert lines(talker)[:7] == [
        "",
        "",
        "Node running. To see messages, please type",
        "\t'rostopic echo /color'",
        "In another window",
        "",
        "",
    ]
    assert echo in (
        "r: 1.0\ng: 2.0\nb: 3.0\na: 4.0\n---\nr: 0.0\ng: 0.0\nb: 0.0\na: 1.0\n---\n",
        "r: 0.0\ng: 0.0\nb: 0.0\na: 1.0\n---\nr: 1.0\ng: 2.0\nb: 3.0\na: 4.0\n---\n",
    )


def said_besides_hello(talker: Path) -> list[str]:
    """The talker's lines other than its ``hello world N``: it prints from two threads, and a
    print writes its text and its newline apart, so a greeting can land inside a hello's line."""
    text = re.sub(r"hello world \d+", "", talker.read_text())
    return [line for line in text.splitlines() if line]


def test_a_subscribe_listener_greets_each_subscriber(runs: Runs) -> None:
    greetings = {'data: "Hey everyone, we have a new friend!"',
                 'data: "greetings. welcome to topic /chatter"'}  # fmt: skip
    with runs.node("rospy_tutorials", "listener_subscribe_notify.py") as talker:
        wait_for(lambda: "hello world 0" in lines(talker), what="the talker")
        # Read until both greetings came: the talker's own messages may come between (its
        # listener runs on a thread of its own, as each connection's is in rospy).
        with runs.tool("rostopic", "echo", "/chatter") as heard:
            wait_for(lambda: greetings <= set(lines(heard)), what="both greetings at the echo")
        wait_for(
            lambda: "I have no friends" in said_besides_hello(talker), what="the echo to leave"
        )
    assert said_besides_hello(talker) == [
        "a peer subscribed to topic [/chatter]",
        "Hey everyone, we have a new friend!",
        "greetings. welcome to topic /chatter",
        "a peer unsubscribed from topic [/chatter]",
        "I have no friends",
    ]


def test_publish_pointcloud2_builds_its_cloud_with_the_helper(runs: Runs) -> None:
    with runs.node("rospy_tutorials", "publish_pointcloud2.py"):
        echo = runs_tool(runs, "rostopic", "echo", "-n", "1", "--noarr", "/points2")
    body = echo.split('  frame_id: "map"\n', 1)[1]
    assert body == (
        "height: 1\nwidth: 10000\n"
        'fields: "<array type: sensor_msgs/PointField, length: 4>"\n'
        "is_bigendian: False\npoint_step: 16\nrow_step: 160000\n"
        'data: "<array type: uint8, length: 160000>"\nis_dense: False\n---\n'
    )
