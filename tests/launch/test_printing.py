"""The printing options' texts and the SUMMARY block."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosx.launch import (
    LaunchError,
    dump_params_text,
    files_text,
    find_node_text,
    node_args_text,
    nodes_text,
    ros_args_text,
    summary_text,
)
from rosx.launch.printing import summary_value
from rosx.packages.index import PackageIndex
from tests.support.launch_plan import Load, Write

LAUNCH = """<launch>
  <arg name="robot" default="r2" doc="Which robot." />
  <arg name="needed" />
  <param name="long" value="a value longer than twenty characters" />
  <param name="n" value="3" />
  <node name="b" pkg="demo" type="run" ns="g" />
  <node name="a" pkg="demo" type="run" ns="g" clear_params="true" />
  <node name="top" pkg="demo" type="run" args="--x 'y z'">
    <remap from="in" to="out" />
    <env name="EXTRA" value="two words" />
    <param name="~p" value="1" />
  </node>
  <test test-name="t" pkg="demo" type="run" />
</launch>"""


def test_summary(load: Load) -> None:
    plan = load(LAUNCH, {"needed": "x"})
    assert summary_text(plan) == (
        "\nSUMMARY\n========\n\n"
        "CLEAR PARAMETERS\n * /g/a/\n\n"
        "PARAMETERS\n * /long: a value longer th...\n * /n: 3\n * /top/p: 1\n\n"
        "NODES\n  /\n    top (demo/run)\n  /g/\n    a (demo/run)\n    b (demo/run)\n\n"
    )


@pytest.mark.parametrize(
    ("value", "shown"),
    [
        (True, "True"),
        (1.5, "1.5"),
        ([1, 2], "[1, 2]"),
        ({"a": 1}, "{'a': 1}"),
        ("noetic\n", "noetic"),
        ("tab\there", "<...>"),
        (b"\x00abc", "<...>"),
        ("x" * 30, "x" * 17 + "..."),
    ],
)
def test_summary_values(value: object, shown: str) -> None:
    assert summary_value(value) == shown


def test_nodes_and_files(load: Load, tmp_path: Path) -> None:
    plan = load(LAUNCH, {"needed": "x"})
    assert nodes_text(plan) == "/g/b\n/g/a\n/top\n/t\n"
    plan.files.append(plan.files[0])
    assert files_text(plan) == f"{tmp_path / 'main.launch'}\n"


def test_dump_params(load: Load, write: Write) -> None:
    blob = write("b.bin", "\x01")
    plan = load(
        f'<launch><rosparam>{{b: [1, x], a: {{c: "10"}}}}</rosparam><param name="bin" binfile="{blob}" />'
        "</launch>"
    )
    assert dump_params_text(plan) == "/a/c: '10'\n/b:\n- 1\n- x\n/bin: !!binary |-\n  AQ==\n\n"
    assert dump_params_text(load("<launch />")) == "{}\n\n"


def test_ros_args(load: Load) -> None:
    plan = load(LAUNCH, {"needed": "x"}, args_only=True)
    assert ros_args_text(plan) == (
        "Required Arguments:\n  needed: undocumented\n"
        'Optional Arguments:\n  robot (default "r2"): Which robot.\n'
    )
    assert ros_args_text(load("<launch />", args_only=True)) == "No arguments.\n"


def test_node_args(load: Load, index: PackageIndex) -> None:
    plan = load(LAUNCH, {"needed": "x"})
    program = index.find("demo") / "scripts" / "run"
    environ = {"EXTRA": "old", "ROS_MASTER_URI": "http://m:1/"}
    assert node_args_text(plan, "top", ["main.launch"], environ, index) == (
        f'EXTRA="two words" {program} --x y z in:=out __name:=top\n'
    )
    assert node_args_text(plan, "/g/a", ["main.launch"], {}, index) == (
        f'ROS_MASTER_URI="http://localhost:11311/" ROS_NAMESPACE="/g" {program} __name:=a\n'
    )
    environ = {"ROS_NAMESPACE": "/g", "ROS_MASTER_URI": "http://m:1/"}
    assert node_args_text(plan, "b", ["main.launch"], environ, index) == f"{program} __name:=b\n"


def test_node_args_of_an_unknown_node(load: Load, index: PackageIndex) -> None:
    plan = load(LAUNCH, {"needed": "x"})
    with pytest.raises(LaunchError) as error:
        node_args_text(plan, "nope", ["f.launch"], {}, index)
    assert str(error.value) == (
        "ERROR: Cannot find node named [/nope] in [f.launch].\nNode names are:\n"
        " * /g/b\n * /g/a\n * /top\n * /t"
    )
    assert error.value.status == 1


def test_find_node(load: Load, tmp_path: Path) -> None:
    plan = load(LAUNCH, {"needed": "x"})
    assert find_node_text(plan, "/top", ["f"], {}) == f"{tmp_path / 'main.launch'}\n"
    with pytest.raises(LaunchError) as error:
        find_node_text(plan, "nope", ["f"], {})
    assert error.value.status == 0
    assert str(error.value) == (
        "ERROR: cannot find node named [/nope]. Run \n\troslaunch --nodes <files>\n"
        "to see list of node names."
    )
