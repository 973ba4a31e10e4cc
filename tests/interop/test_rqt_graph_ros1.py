"""rosx rqt_graph on a graph of rospy nodes: the connections come from rospy's getBusInfo."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from tests.support.cli import Result, clean_environ, rosx
from tests.support.graph_nodes import LISTENER, TALKER
from tests.support.procs import running, wait_for
from tests.support.ros1 import ROS1_PYTHON, ROSCORES, needs_ros1, ros1_environ, roscore

pytestmark = needs_ros1

EDGES = ('"n_/talker" -> "t_/chatter";', '"t_/chatter" -> "n_/listener";')


def graph_tool(uri: str, *argv: str) -> Result:
    return rosx("rqt_graph", *argv, environ=clean_environ(ROS_MASTER_URI=uri))


@pytest.fixture(scope="module", params=ROSCORES)
def master(request: pytest.FixtureRequest) -> Iterator[str]:
    """A roscore (ROS 1's or rosx's) with a rospy talker and listener, connected; its URI."""
    with roscore(request.param) as uri:
        env = ros1_environ(ROS_MASTER_URI=uri)
        with running([ROS1_PYTHON, "-c", TALKER], env), running([ROS1_PYTHON, "-c", LISTENER], env):
            # Active mode draws what the nodes report: wait for the listener's connection.
            wait_for(
                lambda: all(e in graph_tool(uri, "--dot", "--mode", "active").out for e in EDGES),
                timeout=30,
                what="the chatter connection in the listener's bus info",
            )
            yield uri


def test_text_active_draws_talker_chatter_listener(master: str) -> None:
    done = graph_tool(master, "--text", "--mode", "active")
    assert done.status == 0, done.err
    lines = done.out.splitlines()
    columns = {}
    for name in ("/talker", "/chatter", "/listener"):
        row = next(line for line in lines if f" {name} " in line)
        columns[name] = row.index(f" {name} ")
    # Left to right: the publisher, its topic, the subscriber; arrowheads on the way.
    assert columns["/talker"] < columns["/chatter"] < columns["/listener"]
    assert "╭" in done.out  # nodes are round boxes
    assert "┌" in done.out  # topics square ones
    assert "▶" in done.out


def test_dot_active_and_all_have_the_edges(master: str) -> None:
    for mode in ("active", "all"):
        done = graph_tool(master, "--dot", "--mode", mode)
        assert done.status == 0, done.err
        assert done.out.startswith("digraph graphname {")
        for edge in EDGES:
            assert edge in done.out, (mode, done.out)


def test_dot_nodes_only_labels_the_edge_with_its_topic(master: str) -> None:
    done = graph_tool(master, "--dot")
    assert done.status == 0, done.err
    assert '"n_/talker" -> "n_/listener" [label="/chatter"];' in done.out
