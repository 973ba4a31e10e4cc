"""rospy_tutorials' and roscpp_tutorials' nodes under ``rosx rosrun``, as the tutorials run them
(ROS/Tutorials/ExaminingPublisherSubscriber, ExaminingServiceClient): names, topics, services
and the log lines of the originals (rospy's ``[INFO] [secs]: …``, roscpp's ``[ INFO] [secs.nsecs]: …``).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rosx_turtle.roscpp_tutorials.add_two_ints import atoi
from tests.support.procs import wait_for
from tests.support.tutorial_nodes import ROSCPP_LINE, ROSPY_LINE, Runs, lines


@pytest.fixture
def runs(master: str, tmp_path: Path) -> Runs:
    return Runs(master, tmp_path)


def test_rospy_talker_and_listener(runs: Runs) -> None:
    with (
        runs.node("rospy_tutorials", "talker") as talker,
        runs.node("rospy_tutorials", "listener") as listener,
    ):
        wait_for(lambda: len(lines(listener)) >= 2, what="the listener hearing the talker")
    assert re.fullmatch(ROSPY_LINE + r"hello world \d+\.\d+", lines(talker)[0])
    heard = lines(listener)[0]
    assert re.fullmatch(ROSPY_LINE + r"/listener_\d+_\d+I heard hello world \d+\.\d+", heard)
    assert heard.partition("I heard ")[2] in {line.partition("]: ")[2] for line in lines(talker)}


def test_rospy_add_two_ints(runs: Runs) -> None:
    with runs.node("rospy_tutorials", "add_two_ints_server") as server:
        client = runs.run("rospy_tutorials", "add_two_ints_client", "1", "3")
        assert (client.returncode, client.stdout) == (0, "Requesting 1+3\n1 + 3 = 4\n")
        wait_for(lambda: len(lines(server)) >= 2, what="the server's lines")
    assert lines(server) == ["Returning [1 + 3 = 4]"] * 2


def test_rospy_add_two_ints_client_usage(runs: Runs) -> None:
    client = runs.run("rospy_tutorials", "add_two_ints_client", "1")
    assert client.returncode == 1
    assert client.stdout.endswith("/rospy_tutorials/005_add_two_ints/add_two_ints_client [x y]\n")


def test_roscpp_talker_and_listener(runs: Runs) -> None:
    with (
        runs.node("roscpp_tutorials", "talker") as talker,
        runs.node("roscpp_tutorials", "listener") as listener,
    ):
        wait_for(lambda: len(lines(listener)) >= 2, what="the listener hearing the talker")
    assert re.fullmatch(ROSCPP_LINE + "hello world 0", lines(talker)[0])
    assert re.fullmatch(ROSCPP_LINE + "hello world 1", lines(talker)[1])
    assert re.fullmatch(ROSCPP_LINE + r"I heard: \[hello world \d+\]", lines(listener)[0])


def test_roscpp_add_two_ints_and_a_rospy_client_of_the_roscpp_server(runs: Runs) -> None:
    with runs.node("roscpp_tutorials", "add_two_ints_server") as server:
        wait_for(
            lambda: runs.run("roscpp_tutorials", "add_two_ints_client", "1", "3").returncode == 0,
            what="the roscpp server",
        )
        client = runs.run("roscpp_tutorials", "add_two_ints_client", "2", "5")
        assert client.returncode == 0
        assert re.fullmatch(ROSCPP_LINE + "Sum: 7\n", client.stdout)
        rospy = runs.run("rospy_tutorials", "add_two_ints_client", "4", "5")
        assert (rospy.returncode, rospy.stdout) == (0, "Requesting 4+5\n4 + 5 = 9\n")
    logged = [line.partition("]: ")[2] for line in lines(server)]
    assert logged[-6:-4] == ["request: x=2, y=5", "  sending back response: [7]"]
    assert logged[-4:] == ["request: x=4, y=5", "  sending back response: [9]"] * 2


def test_roscpp_add_two_ints_client_refusals(runs: Runs) -> None:
    usage = runs.run("roscpp_tutorials", "add_two_ints_client", "1")
    assert usage.returncode == 1
    assert re.fullmatch(ROSCPP_LINE + "usage: add_two_ints_client X Y\n", usage.stdout)
    failed = runs.run("roscpp_tutorials", "add_two_ints_client", "1", "2")
    assert failed.returncode == 1
    assert re.fullmatch(
        r"\[ERROR\] \[\d+\.\d{9}\]: Failed to call service add_two_ints\n", failed.stderr
    )


@pytest.mark.parametrize(
    ("text", "value"),
    [("3", 3), ("-4", -4), (" +7x", 7), ("abc", 0), ("", 0), ("2147483648", -2147483648)],
)
def test_client_arguments_are_read_as_atoi_reads_them(text: str, value: int) -> None:
    assert atoi(text) == value
