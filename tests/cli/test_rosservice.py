"""``rosx rosservice``: golden texts and exit codes against a rosx master and rosx services."""

from __future__ import annotations

import re
import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest

from rosx.master.server import MasterThread
from rosx.msg.codec.classes import get_service_class
from rosx.node import Node, ServiceError
from tests.support.cli import Result, clean_environ, rosx
from tests.support.procs import free_port
from tests.support.services import FakeServices, register_dead

Spawn = get_service_class("turtlesim/Spawn")
Empty = get_service_class("std_srvs/Empty")
SetBool = get_service_class("std_srvs/SetBool")
Trigger = get_service_class("std_srvs/Trigger")
GetPlan = get_service_class("nav_msgs/GetPlan")

OVERVIEW = """Commands:
\trosservice args\tprint service arguments
\trosservice call\tcall the service with the provided args
\trosservice find\tfind services by service type
\trosservice info\tprint information about service
\trosservice list\tlist active services
\trosservice type\tprint service type
\trosservice uri\tprint service ROSRPC uri

Type rosservice <command> -h for more detailed usage, e.g. 'rosservice call -h'

"""
SPAWN_ARGS = "Service arguments are: [x y theta name]"


class Graph:
    """A master with a node ``/svc`` serving the services the tests call, and fake servers."""

    def __init__(self, master: str, node: Node, fake: FakeServices) -> None:
        self.master = master
        self.node = node
        self.fake = fake
        self.release = threading.Event()

    def run(self, *argv: str, stdin: str = "", **environ: str) -> Result:
        return rosx(
            *argv, stdin=stdin, environ=clean_environ(ROS_MASTER_URI=self.master, **environ)
        )


def _plan(request: Any) -> Any:
    response = GetPlan._response_class()
    response.plan.header.frame_id = "map"
    response.plan.poses = [request.start, request.goal]
    return response


def _boom(request: Any) -> Any:
    raise RuntimeError("boom went the handler")


def _refuse(request: Any) -> Any:
    raise ServiceError("nope")


@pytest.fixture(scope="module")
def graph() -> Iterator[Graph]:
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        node = Node("svc", master_uri=master.uri, environ={}).start()
        fake = FakeServices()
        graph = Graph(master.uri, node, fake)
        try:
            node.advertise_service(
                "/spawn", Spawn, lambda r: Spawn._response_class(r.name or "turtle2")
            )
            node.advertise_service("/empty", Empty, lambda r: [])
            node.advertise_service("/setbool", SetBool, lambda r: (r.data, f"got {r.data}"))
            node.advertise_service("/boom", Trigger, _boom)
            node.advertise_service("/refuse", Trigger, _refuse)
            node.advertise_service("/ns/inner", Empty, lambda r: [])
            node.advertise_service("/plan", GetPlan, _plan)
            node.advertise_service("/slow", Empty, lambda r: graph.release.wait(30) and [])
            fake.register(master.uri, "/refuse_empty")
            fake.register(master.uri, "/close_mid_call")
            fake.register(master.uri, "/silent")
            register_dead(master.uri, "/dead")
            yield graph
        finally:
            graph.release.set()
            fake.close()
            node.shutdown("tests over")


def _uri(graph: Graph) -> str:
    return graph.node.services["/spawn"].uri


# -- listing and introspection ---------------------------------------------------------------


def test_list_is_sorted(graph: Graph) -> None:
    done = graph.run("rosservice", "list")
    assert done.out.splitlines() == [
        "/boom", "/close_mid_call", "/dead", "/empty", "/ns/inner", "/plan", "/refuse",
        "/refuse_empty", "/setbool", "/silent", "/slow", "/spawn", "/svc/get_loggers",
        "/svc/set_logger_level",
    ]  # fmt: skip
    assert (done.err, done.status) == ("", 0)


def test_list_with_nodes_and_namespace(graph: Graph) -> None:
    assert graph.run("rosservice", "list", "-n", "/ns").out == "/ns/inner /svc\n"
    assert graph.run("rosservice", "list", "ns").out == "/ns/inner\n"
    lines = graph.run("rosservice", "list", "--nodes").out.splitlines()
    assert "/refuse_empty /fake" in lines and "/spawn /svc" in lines
    assert graph.run("rosservice", "list", "/nothing").out == ""
    namespaced = graph.run("rosservice", "list", "inner", ROS_NAMESPACE="/ns")
    assert namespaced.out == "/ns/inner\n"


@pytest.mark.parametrize(
    ("argv", "out", "err", "status"),
    [
        (["type", "/spawn"], "turtlesim/Spawn\n", "", 0),
        (["type", "spawn"], "turtlesim/Spawn\n", "", 0),
        (["type", "/nope"], "", "Unknown service [/nope]\n", 1),
        (["args", "/spawn"], "x y theta name\n", "", 0),
        (["args", "/plan"], "start goal tolerance\n", "", 0),
        (["args", "/empty"], "\n", "", 0),
        (["args", "/nope"], "", "ERROR: Service [/nope] is not available.\n", 2),
        (["node", "/spawn"], "/svc\n", "", 0),
        (["node", "/nope"], "", "Unknown service: /nope\n", 1),
        (["uri", "/nope"], "", "Unknown service: /nope\n", 1),
        (["info", "/nope"], "", "ERROR: unknown service\n", 1),
        (["find", "turtlesim/Spawn"], "/spawn\n", "", 0),
        (["find", "nope/Nope"], "\n", "", 0),
    ],
)
def test_queries(graph: Graph, argv: list[str], out: str, err: str, status: int) -> None:
    done = graph.run("rosservice", *argv)
    assert (done.out, done.err, done.status) == (out, err, status)


def test_uri_and_info(graph: Graph) -> None:
    uri = _uri(graph)
    assert re.fullmatch(r"rosrpc://[\w.]+:\d+", uri)
    assert graph.run("rosservice", "uri", "/spawn").out == uri + "\n"
    done = graph.run("rosservice", "info", "/spawn")
    assert done.out == f"Node: /svc\nURI: {uri}\nType: turtlesim/Spawn\nArgs: x y theta name\n"


def test_find_skips_servers_that_do_not_answer(graph: Graph) -> None:
    done = graph.run("rosservice", "find", "std_srvs/Empty")
    # In the master's order of registration, as ROS 1 prints them.
    assert sorted(done.out.splitlines()) == [
        "/close_mid_call", "/empty", "/ns/inner", "/refuse_empty", "/silent", "/slow"
    ]  # fmt: skip
    assert done.status == 0


def test_unreachable_server(graph: Graph) -> None:
    done = graph.run("rosservice", "info", "/dead")
    dead_uri = done.out.splitlines()[1].removeprefix("URI: ")
    assert done.out == f"Node: /fake\nURI: {dead_uri}\n"
    unreachable = f"ERROR: Unable to communicate with service [/dead], address [{dead_uri}]\n"
    assert (done.err, done.status) == (unreachable, 2)
    for command in ("type", "args", "call"):
        done = graph.run("rosservice", command, "/dead")
        assert (done.out, done.err, done.status) == ("", unreachable, 2)


# -- calls -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "out"),
    [
        (["/spawn", "1", "2", "3", "abc"], 'name: "abc"\n'),
        (["/spawn", "{x: 1, name: foo}"], 'name: "foo"\n'),
        (["/spawn", "1", "2", "3", ""], 'name: "turtle2"\n'),
        (["spawn", "1", "2", "3", "a", "__name:=other", "a:=b"], 'name: "a"\n'),
        (
            ["-v", "/spawn", "1", "2", "3", "abc"],
            'x: 1\ny: 2\ntheta: 3\nname: "abc"\n---\nname: "abc"\n',
        ),
        (["/empty"], "\n"),
        (["/setbool", "true"], 'success: True\nmessage: "got True"\n'),
        (["/setbool", "{data: false}"], 'success: False\nmessage: "got False"\n'),
        (["--nostr", "/spawn", "1", "2", "3", "abc"], 'name: "<string length: 3>"\n'),
    ],
)
def test_call_prints_the_response(graph: Graph, args: list[str], out: str) -> None:
    done = graph.run("rosservice", "call", *args)
    assert (done.out, done.err, done.status) == (out, "", 0)


def test_call_prints_nested_responses_as_echo_does(graph: Graph) -> None:
    done = graph.run(
        "rosservice", "call", "/plan", "{start: {header: {frame_id: a}, pose: {position: {x: 1}}}}"
    )
    pose = "\n".join(
        [
            "      pose: ",
            "        position: ",
            "          x: {x}",
            "          y: 0.0",
            "          z: 0.0",
            "        orientation: ",
            "          x: 0.0",
            "          y: 0.0",
            "          z: 0.0",
            "          w: 0.0",
        ]
    )
    stamp = "        stamp: \n          secs: 0\n          nsecs:         0\n"
    assert done.out == (
        "plan: \n  header: \n    seq: 0\n    stamp: \n      secs: 0\n      nsecs:         0\n"
        '    frame_id: "map"\n  poses: \n'
        f'    - \n      header: \n        seq: 0\n{stamp}        frame_id: "a"\n'
        + pose.format(x="1.0")
        + f"\n    - \n      header: \n        seq: 0\n{stamp}        frame_id: ''\n"
        + pose.format(x="0.0")
        + "\n"
    )
    short = graph.run("rosservice", "call", "--noarr", "/plan", "{}", "{}", "0")
    assert short.out.endswith('  poses: "<array type: geometry_msgs/PoseStamped, length: 2>"\n')


@pytest.mark.parametrize(
    ("args", "err"),
    [
        (
            ["/spawn", "{x:1}"],
            "ERROR: Incompatible arguments to call service:\n"
            "No field name [x:1]: YAML needs a space after the colon, write {x: 1}\n"
            "Provided arguments are:\n * {'x:1': None} (type dict)\n\n" + SPAWN_ARGS,
        ),
        (
            ["/spawn", "1", "2"],
            "ERROR: Incompatible arguments to call service:\nNot enough arguments:\n"
            " * Given: [1, 2]\n * Expected: ['x', 'y', 'theta', 'name']\n"
            "Provided arguments are:\n * 1 (type int)\n * 2 (type int)\n\n" + SPAWN_ARGS,
        ),
        (
            ["/spawn", "{nosuch: 1}"],
            "ERROR: Incompatible arguments to call service:\nNo field name [nosuch]\n"
            "Provided arguments are:\n * {'nosuch': 1} (type dict)\n\n" + SPAWN_ARGS,
        ),
        (
            ["/spawn", "x", "y", "z", "w"],
            "ERROR: Unable to send request. One of the fields has an incorrect type:\n"
            "  field x must be float type\n\nsrv file:\n"
            "float32 x\nfloat32 y\nfloat32 theta\nstring name\n---\nstring name\n",
        ),
        (
            ["/spawn", "{x: [1"],
            "ERROR: Invalid YAML in arguments: while parsing a flow sequence; expected ',' or "
            "']', but got '<stream end>' (line 1, column 7)",
        ),
        (
            ["/plan", "1", "2", "3"],
            "ERROR: Incompatible arguments to call service:\ninvalid msg_args type: 1\n"
            "Provided arguments are:\n * 1 (type int)\n * 2 (type int)\n * 3 (type int)\n\n"
            "Service arguments are: [start.header.seq start.header.stamp start.header.frame_id "
            "start.pose.position.x start.pose.position.y start.pose.position.z "
            "start.pose.orientation.x start.pose.orientation.y start.pose.orientation.z "
            "start.pose.orientation.w goal.header.seq goal.header.stamp goal.header.frame_id "
            "goal.pose.position.x goal.pose.position.y goal.pose.position.z "
            "goal.pose.orientation.x goal.pose.orientation.y goal.pose.orientation.z "
            "goal.pose.orientation.w tolerance]",
        ),
        (["/nope"], "ERROR: Service [/nope] is not available."),
        (
            ["/boom"],
            "ERROR: service [/boom] responded with an error: "
            "b'error processing request: boom went the handler'",
        ),
        (
            ["/refuse"],
            "ERROR: service [/refuse] responded with an error: b'service cannot process request: nope'",
        ),
        (["/refuse_empty"], "ERROR: service [/refuse_empty] responded with an error: b''"),
        (
            ["/close_mid_call"],
            "ERROR: transport error completing service call: unable to receive data from sender, "
            "check sender's logs for details",
        ),
    ],
)
def test_failed_calls_say_why_and_exit_2(graph: Graph, args: list[str], err: str) -> None:
    done = graph.run("rosservice", "call", *args)
    assert (done.out, done.err, done.status) == ("", err + "\n", 2)
    after = graph.run("rosservice", "call", "/setbool", "true")
    assert (after.out, after.status) == ('success: True\nmessage: "got True"\n', 0)


def test_call_reads_documents_from_stdin(graph: Graph) -> None:
    stdin = "{x: 1, y: 2, theta: 0, name: s1}\n---\n[1, 2, 3, s2]\n---\nx: [\n---\n{}\n---\n{name: s3}\n"
    done = graph.run("rosservice", "call", "/spawn", stdin=stdin)
    assert done.out == 'name: "s1"\nname: "s2"\n'
    assert done.err == (
        "Invalid YAML: while parsing a flow node; expected the node content, but found "
        "'<stream end>' (line 1, column 5)\n"
    )
    assert done.status == 0
    refused = graph.run("rosservice", "call", "/spawn", stdin="{nosuch: 1}\n---\n")
    assert refused.status == 2 and refused.err.startswith("ERROR: Incompatible arguments")


def test_timeout_bounds_a_call_that_hangs(graph: Graph) -> None:
    start = time.monotonic()
    done = graph.run("rosservice", "call", "--timeout", "0.5", "/silent")
    assert time.monotonic() - start < 5
    assert (done.err, done.status) == (
        "ERROR: service [/silent] did not respond within 0.5 seconds\n",
        2,
    )
    slow = graph.run("rosservice", "call", "--timeout", "0.3", "/slow")
    assert slow.err == "ERROR: service [/slow] did not respond within 0.3 seconds\n"
    assert graph.run("rosservice", "call", "/empty").status == 0


def test_wait_for_a_service_advertised_later(graph: Graph) -> None:
    timer = threading.Timer(
        0.5,
        graph.node.advertise_service,
        ("/later", Spawn, lambda r: Spawn._response_class("late")),
    )
    timer.start()
    try:
        done = graph.run(
            "rosservice", "call", "--wait", "--timeout", "10", "/later", "0", "0", "0", ""
        )
    finally:
        timer.join()
    assert (done.out, done.status) == ('name: "late"\n', 0)
    missing = graph.run("rosservice", "call", "--wait", "--timeout", "0.4", "/never")
    assert (missing.err, missing.status) == (
        "ERROR: timeout exceeded while waiting for service /never\n",
        2,
    )


# -- usage -----------------------------------------------------------------------------------


@pytest.mark.parametrize("argv", [[], ["-h"], ["nope"], ["a:=b"]])
def test_overview_exits_64(argv: list[str]) -> None:
    done = rosx("rosservice", *argv)
    assert (done.out, done.err, done.status) == (OVERVIEW, "", 64)


@pytest.mark.parametrize(
    ("argv", "err"),
    [
        (
            ["call"],
            "Usage: rosservice call /service [args...]\n\nrosservice: error: service must be specified\n",
        ),
        (
            ["type"],
            "Usage: rosservice type /service\n\nrosservice: error: service must be specified\n",
        ),
        (
            ["uri", "a", "b"],
            "Usage: rosservice uri /service\n\nrosservice: error: you may only specify one input service\n",
        ),
        (
            ["info"],
            "Usage: rosservice info /service\n\nrosservice: error: you must specify a service name\n",
        ),
        (
            ["info", "a", "b"],
            "Usage: rosservice info /service\n\nrosservice: error: you may only specify one service\n",
        ),
        (
            ["list", "a", "b"],
            "Usage: rosservice list [/namespace]\n\nrosservice: error: you may only specify one input namespace\n",
        ),
        (
            ["list", "-x"],
            "Usage: rosservice list [/namespace]\n\nrosservice: error: no such option: -x\n",
        ),
        (
            ["find"],
            "Usage: rosservice find msg-type\n\nrosservice: error: please specify a message type\n",
        ),
    ],
)
def test_usage_errors_exit_2(argv: list[str], err: str) -> None:
    done = rosx("rosservice", *argv)
    assert (done.out, done.err, done.status) == ("", err, 2)


def test_help_texts() -> None:
    assert rosx("rosservice", "list", "-h").out == (
        "Usage: rosservice list [/namespace]\n\nOptions:\n"
        "  -h, --help   show this help message and exit\n"
        "  -n, --nodes  print nodes that provide service(s)\n"
    )
    assert rosx("rosservice", "type", "-h").out == (
        "Usage: rosservice type /service\n\nOptions:\n  -h, --help  show this help message and exit\n"
    )
    call_help = rosx("rosservice", "call", "-h")
    assert call_help.status == 0
    assert call_help.out.startswith(
        "Usage: rosservice call /service [args...]\n\nOptions:\n"
        "  -h, --help      show this help message and exit\n"
        "  -v              print verbose output\n"
        "  --wait          wait for service to be advertised\n"
        "  --timeout=SECS  give up when the service"
    )


@pytest.mark.parametrize(
    "argv",
    [
        ["list"],
        ["info", "/x"],
        ["type", "/x"],
        ["call", "/x"],
        ["call", "--wait", "/x"],
        ["find", "a/B"],
    ],
)
def test_master_down_exits_2(argv: list[str]) -> None:
    done = rosx(
        "rosservice", *argv, environ=clean_environ(ROS_MASTER_URI=f"http://127.0.0.1:{free_port()}")
    )
    assert done.status == 2
    assert done.err.startswith("ERROR: Unable to communicate with master!\n")
    assert "Traceback" not in done.err
