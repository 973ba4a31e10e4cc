"""With no master, every tool says ROS 1's one line, exactly, and exits as ROS 1's does.

ROS 1's own tests and users' scripts match ``ERROR: Unable to communicate with master!`` as the
whole of stderr; rosx adds how to get a master only when stderr is a terminal.
"""

from __future__ import annotations

import io

import pytest

from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.cli import clean_environ, rosx
from tests.support.procs import free_port

UNREACHABLE = "ERROR: Unable to communicate with master!\n"
RULE = "-" * 80 + "\n"

#: argv, what ROS 1 prints on stdout first, its exit status (measured with ROS 1 Noetic).
NO_MASTER = [
    (["rostopic", "list"], "", 1),
    (["rostopic", "info", "/x"], "", 1),
    (["rostopic", "type", "/x"], "", 1),
    (["rostopic", "find", "std_msgs/String"], "", 1),
    (["rostopic", "echo", "/x"], "", 1),
    (["rostopic", "pub", "/x", "std_msgs/Empty"], "", 1),
    (["rostopic", "hz", "/x"], "", 1),
    (["rosnode", "list"], "", 1),
    (["rosnode", "info", "/x"], RULE, 1),
    (["rosnode", "ping", "/x"], "rosnode: node is [/x]\n", 1),
    (["rosnode", "ping", "-a"], "", 1),
    (["rosnode", "machine"], "", 1),
    (["rosnode", "kill", "/x"], "", 1),
    (["rosnode", "cleanup"], "", 1),
    (["rosservice", "list"], "", 2),
    (["rosservice", "info", "/x"], "", 2),
    (["rosservice", "type", "/x"], "", 2),
    (["rosservice", "uri", "/x"], "", 2),
    (["rosservice", "node", "/x"], "", 2),
    (["rosservice", "args", "/x"], "", 2),
    (["rosservice", "call", "/x"], "", 2),
    (["rosservice", "find", "std_srvs/Empty"], "", 2),
    (["rosparam", "get", "/"], "", 1),
    (["rosparam", "list"], "", 1),
    (["rosparam", "set", "/a", "1"], "", 1),
    (["rosparam", "delete", "/a"], "", 1),
    (["rqt_graph", "--text"], "", 1),
    (["rqt_graph", "--dot"], "", 1),
]


def _no_master() -> dict[str, str]:
    return clean_environ(ROS_MASTER_URI=f"http://127.0.0.1:{free_port()}")


@pytest.mark.parametrize(
    ("argv", "out", "status"), NO_MASTER, ids=[" ".join(argv) for argv, _, _ in NO_MASTER]
)
def test_no_master_is_ros1s_one_line(argv: list[str], out: str, status: int) -> None:
    done = rosx(*argv, environ=_no_master())
    assert (done.out, done.err, done.status) == (out, UNREACHABLE, status)


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize("argv", [["rostopic", "list"], ["rosservice", "list"]])
def test_on_a_terminal_the_error_says_how_to_get_a_master(argv: list[str]) -> None:
    environ = _no_master()
    err = _Terminal()
    env = Environment(stdout=io.StringIO(), stderr=err, stdin=io.StringIO(), environ=environ)
    run_tool(argv, env)
    first, second = err.getvalue().splitlines()
    assert first == UNREACHABLE.strip()
    assert second.startswith(f"No master answers at ROS_MASTER_URI={environ['ROS_MASTER_URI']}")
    assert "rosx roscore" in second


def test_rosnode_ping_without_a_node_is_a_usage_error_without_a_master() -> None:
    done = rosx("rosnode", "ping", environ=_no_master())
    assert (done.out, done.err, done.status) == (
        "",
        "Usage: rosnode ping [options] <node>\n\nrosnode: error: Please enter a node to ping\n",
        2,
    )


def test_rosnode_ping_without_a_node_lists_the_nodes_then_gives_the_usage_error() -> None:
    from rosx.master.server import MasterThread
    from rosx.transport.client import XmlRpcClient

    usage = "Usage: rosnode ping [options] <node>\n\nrosnode: error: Please enter a node to ping"
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        with XmlRpcClient() as client:
            client.call(
                master.uri, "registerPublisher", "/fake", "/x", "std_msgs/Empty", "http://h:9/"
            )
        done = rosx("rosnode", "ping", environ=clean_environ(ROS_MASTER_URI=master.uri))
    # ROS 1's bare ``except`` catches the exit of its first usage error and gives a second.
    assert (done.out, done.err, done.status) == (
        "",
        f"{usage}. Available nodes are:\n/fake\n{usage}\n",
        2,
    )
