"""rosx rosservice / rosparam next to ROS 1's, on ROS 1's roscore and on rosx's.

Each command runs twice against the same master, once with ROS 1's tool and once with rosx's,
and both must print the same words with the same exit status. The services are a rospy node's
(one handler raises, one is ``std_srvs/Empty``) and misbehaving fake servers (a roscpp-style
``ok=0`` with no text, a server that closes mid-call). Parameters set by either tool must read
back identically with either tool, with the same XML-RPC types, through get, dump and load.
"""

from __future__ import annotations

import sys
import xmlrpc.client
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port, port_open, running, wait_for
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ, run_ros1
from tests.support.services import FakeServices

pytestmark = needs_ros1

SERVICES = """
import os, sys, rospy
from std_srvs.srv import Empty, EmptyResponse, SetBool, SetBoolResponse, Trigger
from turtlesim.srv import Spawn, SpawnResponse
from nav_msgs.srv import GetPlan, GetPlanResponse
rospy.init_node('svc')
rospy.Service('/spawn', Spawn, lambda r: SpawnResponse(r.name or 'turtle2'))
rospy.Service('/empty', Empty, lambda r: EmptyResponse())
rospy.Service('/setbool', SetBool, lambda r: SetBoolResponse(r.data, 'got %s' % r.data))
def boom(r):
    raise Exception('boom went the handler')
rospy.Service('/boom', Trigger, boom)
def refuse(r):
    raise rospy.ServiceException('nope')
rospy.Service('/refuse', Trigger, refuse)
rospy.Service('/ns/inner', Empty, lambda r: EmptyResponse())
def plan(r):
    resp = GetPlanResponse()
    resp.plan.header.frame_id = 'map'
    resp.plan.poses = [r.start, r.goal]
    return resp
rospy.Service('/plan', GetPlan, plan)
rospy.spin()
"""
DYING = """
import os, sys, rospy
from std_srvs.srv import Empty
rospy.init_node('dier')
def die(r):
    os._exit(3)
rospy.Service(sys.argv[1], Empty, die)
rospy.spin()
"""


class Graph:
    """A master (ROS 1's or rosx's) with the rospy services and the fake servers."""

    def __init__(self, uri: str, kind: str) -> None:
        self.uri = uri
        self.kind = kind

    def ros1(self, *argv: str, stdin: str = "") -> tuple[str, str, int]:
        done = run_ros1(list(argv), stdin=stdin, ROS_MASTER_URI=self.uri)
        return done.stdout, done.stderr, done.returncode

    def rosx(self, *argv: str, stdin: str = "") -> tuple[str, str, int]:
        done = rosx(*argv, stdin=stdin, environ=clean_environ(ROS_MASTER_URI=self.uri))
        return done.out, done.err, done.status

    def stored(self, name: str) -> Any:
        reply: Any = xmlrpc.client.ServerProxy(self.uri).getParam("/test", name)
        code, status, value = reply
        assert code == 1, status
        return value


@pytest.fixture(scope="module", params=["ros1-roscore", "rosx-roscore"])
def graph(request: pytest.FixtureRequest) -> Iterator[Graph]:
    port = free_port()
    uri = f"http://localhost:{port}"
    if request.param == "ros1-roscore":
        core = ["/usr/bin/roscore", "-p", str(port)]
        core_env = ros1_environ(ROS_MASTER_URI=uri)
    else:
        core = [sys.executable, "-m", "rosx_commands", "roscore", "-p", str(port)]
        core_env = clean_environ(ROS_MASTER_URI=uri)
    with running(core, core_env):
        wait_for(lambda: port_open(port), what="roscore")
        with running([ROS1_PYTHON, "-c", SERVICES], ros1_environ(ROS_MASTER_URI=uri)):
            wait_for(
                lambda: "/plan" in run_ros1(["rosservice", "list"], ROS_MASTER_URI=uri).stdout,
                what="the rospy services",
            )
            fake = FakeServices()
            try:
                fake.register(uri, "/refuse_empty")
                fake.register(uri, "/close_mid_call")
                yield Graph(uri, request.param)
            finally:
                fake.close()


SERVICE_COMMANDS = [
    [],
    ["-h"],
    ["list"],
    ["list", "-n"],
    ["list", "/ns"],
    ["list", "-n", "ns"],
    ["list", "a", "b"],
    ["list", "-h"],
    ["call", "/spawn", "1", "2", "3", "abc"],
    ["call", "-v", "/spawn", "1", "2", "3", "abc"],
    ["call", "/spawn", "{x: 1, name: foo}"],
    ["call", "/spawn", "1", "2"],
    ["call", "/spawn", "1", "2", "3", "4", "5"],
    ["call", "/spawn", "{nosuch: 1}"],
    ["call", "/spawn", "x", "y", "z", "w"],
    ["call", "/spawn", "1", "2", "3", ""],
    ["call", "/empty"],
    ["call", "/setbool", "true"],
    ["call", "/plan", "{start: {header: {frame_id: a}, pose: {position: {x: 1}}}}", "{}", "0.5"],
    ["call", "/boom"],
    ["call", "/refuse"],
    ["call", "/refuse_empty"],
    ["call", "/close_mid_call"],
    ["call", "/nope"],
    ["call"],
    ["type", "/spawn"],
    ["type", "/refuse_empty"],
    ["type", "/nope"],
    ["type"],
    ["info", "/spawn"],
    ["info", "/nope"],
    ["args", "/plan"],
    ["args", "/empty"],
    ["args", "/nope"],
    ["uri", "/spawn"],
    ["uri", "/nope"],
    ["node", "/spawn"],
    ["node", "/nope"],
    ["find", "turtlesim/Spawn"],
    ["find", "nope/Nope"],
]


@pytest.mark.parametrize("argv", SERVICE_COMMANDS, ids=" ".join)
def test_rosservice_same_as_ros1(graph: Graph, argv: list[str]) -> None:
    assert graph.rosx("rosservice", *argv) == graph.ros1("rosservice", *argv)


def test_rosservice_call_help_adds_only_rosx_options(graph: Graph) -> None:
    ours, theirs = graph.rosx("rosservice", "call", "-h"), graph.ros1("rosservice", "call", "-h")
    assert ours[1:] == theirs[1:]
    options = [line.split()[0] for line in ours[0].splitlines() if line.startswith("  -")]
    assert options == ["-h,", "-v", "--wait", "--timeout=SECS", "--nostr", "--noarr"]
    assert [line.split()[0] for line in theirs[0].splitlines() if line.startswith("  -")] == [
        "-h,", "-v", "--wait"
    ]  # fmt: skip


def test_rosservice_call_from_stdin_same_as_ros1(graph: Graph) -> None:
    stdin = "{x: 1, y: 2, theta: 0, name: s1}\n---\n[1, 2, 3, s2]\n---\n"
    assert graph.rosx("rosservice", "call", "/spawn", stdin=stdin) == graph.ros1(
        "rosservice", "call", "/spawn", stdin=stdin
    )


def test_colon_without_space_is_explained(graph: Graph) -> None:
    ros1 = graph.ros1("rosservice", "call", "/spawn", "{x:1}")
    ours = graph.rosx("rosservice", "call", "/spawn", "{x:1}")
    hint = ": YAML needs a space after the colon, write {x: 1}"
    assert (ours[0], ours[1].replace(hint, ""), ours[2]) == ros1
    assert hint in ours[1]


def test_malformed_yaml_is_one_line_where_ros1_has_a_traceback(graph: Graph) -> None:
    ros1 = graph.ros1("rosservice", "call", "/spawn", "{x: [1")
    assert "Traceback" in ros1[1]
    out, err, status = graph.rosx("rosservice", "call", "/spawn", "{x: [1")
    assert (out, status) == ("", 2)
    assert err.count("\n") == 1 and err.startswith("ERROR: Invalid YAML in arguments:")


def test_a_service_dying_mid_call(graph: Graph) -> None:
    for name, tool in (("/die_ros1", graph.ros1), ("/die_rosx", graph.rosx)):
        argv = [ROS1_PYTHON, "-c", DYING, name]
        with running(argv, ros1_environ(ROS_MASTER_URI=graph.uri)):
            wait_for(lambda: graph.rosx("rosservice", "type", name)[2] == 0, what=name)  # noqa: B023
            out, err, status = tool("rosservice", "call", name)
        assert (out, status) == ("", 2), name
        assert err == (
            "ERROR: transport error completing service call: unable to receive data from "
            "sender, check sender's logs for details\n"
        )
    assert graph.rosx("rosservice", "call", "/setbool", "true")[2] == 0


# -- rosparam --------------------------------------------------------------------------------

VALUES = {
    "int": "5",
    "neg": "-3",
    "float": "-3.5",
    "exp": "1.0e+5",
    "small": "0.00001",
    "exp_str": "1e5",
    "bool": "true",
    "str": "hello world",
    "num_str": "'5'",
    "yes_str": "'yes'",
    "empty": "",
    "unicode": "h\xe9llo w\xf6rld",
    "list": "[1, 2.5, x, true, [a, b], {k: v}]",
    "dict": "{a: 1, b: {c: [1, 2], d: str}, e: 2.0}",
    "long": " ".join(f"word{i}" for i in range(30)),
    "octal": "010",
    "angle": "deg(180)",
    "inf": ".inf",
    "quote": '"it\'s"',
    "colon": "'a: b'",
}


def _types(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _types(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_types(v) for v in value]
    return type(value).__name__


def test_rosparam_set_and_get_round_trip_every_type(graph: Graph) -> None:
    for name, text in VALUES.items():
        assert graph.ros1("rosparam", "set", f"/rt/ros1/{name}", text)[2] == 0
        assert graph.rosx("rosparam", "set", f"/rt/rosx/{name}", text)[2] == 0
    assert graph.stored("/rt/rosx") == graph.stored("/rt/ros1")
    assert _types(graph.stored("/rt/rosx")) == _types(graph.stored("/rt/ros1"))
    for name in VALUES:
        for setter in ("ros1", "rosx"):
            for flag in ([], ["-p"]):
                argv = ["rosparam", "get", *flag, f"/rt/{setter}/{name}"]
                assert graph.rosx(*argv) == graph.ros1(*argv), argv
    for flag in ([], ["-p"]):
        assert graph.rosx("rosparam", "get", *flag, "/rt/ros1") == graph.ros1(
            "rosparam", "get", *flag, "/rt/rosx"
        )
    assert graph.rosx("rosparam", "list", "/rt") == graph.ros1("rosparam", "list", "/rt")


def test_rosparam_binary_values(graph: Graph, tmp_path: Path) -> None:
    data = tmp_path / "b.dat"
    data.write_bytes(bytes(range(256)))
    assert graph.ros1("rosparam", "set", "-b", str(data), "/bin/ros1")[2] == 0
    assert graph.rosx("rosparam", "set", "-b", str(data), "/bin/rosx")[2] == 0
    for name in ("/bin/ros1", "/bin/rosx"):
        stored = graph.stored(name)
        assert isinstance(stored, xmlrpc.client.Binary) and stored.data == bytes(range(256))
    out, err, status = graph.rosx("rosparam", "dump", str(tmp_path / "bin.yaml"), "/bin")
    assert (out, err, status) == ("", "", 0)
    assert graph.ros1("rosparam", "load", str(tmp_path / "bin.yaml"), "/bin2")[2] == 0
    assert graph.stored("/bin2") == graph.stored("/bin")


def test_rosparam_dump_and_load_across_tools(graph: Graph, tmp_path: Path) -> None:
    for name, text in VALUES.items():
        graph.ros1("rosparam", "set", f"/src/{name}", text)
    ros1_file, rosx_file = tmp_path / "ros1.yaml", tmp_path / "rosx.yaml"
    assert graph.ros1("rosparam", "dump", str(ros1_file), "/src")[2] == 0
    assert graph.rosx("rosparam", "dump", str(rosx_file), "/src")[2] == 0
    assert rosx_file.read_text() == ros1_file.read_text()
    assert graph.rosx("rosparam", "dump", "", "/src") == graph.ros1("rosparam", "dump", "", "/src")
    assert graph.rosx("rosparam", "load", str(ros1_file), "/back/rosx")[2] == 0
    assert graph.ros1("rosparam", "load", str(rosx_file), "/back/ros1")[2] == 0
    assert graph.stored("/back/rosx") == graph.stored("/src") == graph.stored("/back/ros1")
    assert _types(graph.stored("/back/rosx")) == _types(graph.stored("/src"))
    text = ros1_file.read_text()
    assert graph.rosx("rosparam", "load", "-v", "-", "/stdin/rosx", stdin=text) == graph.ros1(
        "rosparam", "load", "-v", "-", "/stdin/rosx", stdin=text
    )


def test_rosparam_load_angles_and_namespaces(graph: Graph, tmp_path: Path) -> None:
    source = tmp_path / "l.yaml"
    source.write_text(
        "a: !degrees 180\nb: deg(90)\nc: !radians pi/2\nd: rad(2*pi)\ne: 'deg(1)'\n"
        "---\n_ns: sub\nx: 1\n---\ny: [1, {k: v}]\n"
    )
    ours = graph.rosx("rosparam", "load", "-v", str(source), "/angles/rosx")
    theirs = graph.ros1("rosparam", "load", "-v", str(source), "/angles/rosx")
    assert ours == theirs
    assert graph.rosx("rosparam", "get", "/angles") == graph.ros1("rosparam", "get", "/angles")


ROSPARAM_COMMANDS = [
    [],
    ["-h"],
    ["nope"],
    ["set", "-h"],
    ["get", "-h"],
    ["load", "-h"],
    ["dump", "-h"],
    ["delete", "-h"],
    ["list", "-h"],
    ["get", "/nope"],
    ["delete", "/nope"],
    ["get"],
    ["get", "a", "b"],
    ["set"],
    ["set", "a"],
    ["set", "-t", "nofile", "/x"],
    ["set", "a", "b", "c"],
    ["set", "-t"],
    ["set", "/q", "-.5"],
    ["set", "-x", "/q", "1"],
    ["set", "/q", "deg(abc)"],
    ["load"],
    ["load", "a", "b", "c"],
    ["load", "/nonexistent.yaml"],
    ["dump", "a", "b", "c"],
    ["list", "a", "b"],
    ["delete"],
]


@pytest.mark.parametrize("argv", ROSPARAM_COMMANDS, ids=" ".join)
def test_rosparam_same_as_ros1(graph: Graph, argv: list[str]) -> None:
    assert graph.rosx("rosparam", *argv) == graph.ros1("rosparam", *argv)


@pytest.mark.parametrize(
    "value", ["null", "3000000000", "2002-12-14", "{x:5}", "a\tb", "{a: [1"], ids=repr
)
def test_rosparam_values_ros1_crashes_on_get_one_line_errors(graph: Graph, value: str) -> None:
    ros1 = graph.ros1("rosparam", "set", "/bad", value)
    assert ros1[2] == 1 and "Traceback" in ros1[1]
    out, err, status = graph.rosx("rosparam", "set", "/bad", value)
    assert (out, status) == ("", 1)
    assert err.count("\n") == 1 and err.startswith("ERROR: ") and "Traceback" not in err
    assert graph.rosx("rosparam", "set", "/after_bad", "1")[2] == 0


def test_private_params_of_a_rosx_node_read_by_ros1(graph: Graph) -> None:
    from rosx.names import parse_remap_args
    from rosx.node import Node

    args = parse_remap_args(["_rate:=10", "_frame:=map", "_gains:=[1.5, 2]"])
    node = Node(
        "controller", master_uri=graph.uri, namespace="/robot", environ={},
        private_params=args.params,
    )  # fmt: skip
    node.start()
    try:
        assert graph.ros1("rosparam", "get", "/robot/controller") == (
            "frame: map\ngains:\n- 1.5\n- 2\nrate: 10\n\n",
            "",
            0,
        )
    finally:
        node.shutdown("test over")


def test_private_params_of_a_rospy_node_read_by_rosx(graph: Graph) -> None:
    script = "import rospy; rospy.init_node('listener'); rospy.spin()"
    argv = [ROS1_PYTHON, "-c", script, "_rate:=10", "_frame:=map", "_gains:=[1.5, 2]", "__ns:=/r2"]
    with running(argv, ros1_environ(ROS_MASTER_URI=graph.uri)):
        wait_for(lambda: graph.rosx("rosparam", "get", "/r2/listener/rate")[2] == 0, what="params")
        expected = graph.ros1("rosparam", "get", "/r2/listener")
        assert graph.rosx("rosparam", "get", "/r2/listener") == expected
    rosx_node_args = ["_rate:=10", "_frame:=map", "_gains:=[1.5, 2]"]
    from rosx.names import parse_remap_args
    from rosx.node import Node

    node = Node(
        "listener", master_uri=graph.uri, namespace="/r3", environ={},
        private_params=parse_remap_args(rosx_node_args).params,
    )  # fmt: skip
    node.start()
    try:
        assert graph.rosx("rosparam", "get", "/r3/listener") == expected
    finally:
        node.shutdown("test over")
