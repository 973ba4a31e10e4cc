"""How a node is started: command line and environment."""

from __future__ import annotations

import pytest

from rosx.launch import LaunchError, Node, node_command_line, node_environment
from rosx.launch.model import Source
from rosx.packages.index import PackageIndex


def node(**fields: object) -> Node:
    fields.setdefault("source", Source("/f.launch", 3))
    return Node(package="demo", type="run", name="n", **fields)  # type: ignore[arg-type]


def test_command_line(index: PackageIndex) -> None:
    program = str(index.find("demo") / "scripts" / "run")
    started = node(
        args="a 'b c' \"d\"", remappings=(("x", "y"), ("~p", "/q")), launch_prefix="gdb --args"
    )
    assert node_command_line(started, index) == [
        "gdb",
        "--args",
        program,
        "a",
        "b c",
        "d",
        "x:=y",
        "~p:=/q",
        "__name:=n",
    ]


def test_provided_programs_need_no_file(index: PackageIndex) -> None:
    def provided(package: str, type_: str) -> list[str] | None:
        return ["rosx", "rosrun", package, type_] if package == "turtlesim" else None

    turtle = Node(package="turtlesim", type="turtlesim_node", name="sim")
    assert node_command_line(turtle, index, provided) == [
        "rosx",
        "rosrun",
        "turtlesim",
        "turtlesim_node",
        "__name:=sim",
    ]


@pytest.mark.parametrize(
    ("package", "type_", "message"),
    [
        (
            "demo",
            "nothere",
            "Cannot locate node of type [nothere] in package [demo]. Make sure "
            "file exists in package path and permission is set to executable (chmod +x)",
        ),
        (
            "demo",
            "scripts/run",
            "Cannot locate node of type [scripts/run] in package [demo]. Make "
            "sure file exists in package path and permission is set to executable (chmod +x)",
        ),
        ("nopkg", "run", "Resource not found: nopkg"),
    ],
)
def test_programs_not_found(index: PackageIndex, package: str, type_: str, message: str) -> None:
    with pytest.raises(LaunchError) as error:
        node_command_line(
            Node(package=package, type=type_, name="n", source=Source("/f.launch", 3)), index
        )
    assert str(error.value) == f"/f.launch:3: <node>: {message}"


def test_environment() -> None:
    environ = {"A": "1", "ROS_NAMESPACE": "/old", "ROS_MASTER_URI": "http://x:1/"}
    namespaced = node(namespace="/a/b/", env=(("A", "2"), ("B", "3"), ("A", "4")))
    assert node_environment(namespaced, environ, "http://m:2/") == {
        "A": "4",
        "ROS_MASTER_URI": "http://m:2/",
        "ROS_NAMESPACE": "/a/b",
        "B": "3",
    }
    assert node_environment(node(), environ, "http://m:2/") == {
        "A": "1",
        "ROS_MASTER_URI": "http://m:2/",
    }
