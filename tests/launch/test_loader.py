"""Launch XML to a plan: the model's content, the scope rules, and errors naming file:line:tag."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosx.launch import LaunchError, Node, load_launch, resolve_launch_arguments
from rosx.launch import Test as LaunchTest
from rosx.launch.model import RosparamCommand, Source
from rosx.packages.index import PackageIndex, bundled_packages
from tests.support.launch_plan import PACKAGE_XML, Load, Write


def values(plan: object) -> dict[str, object]:
    return plan.param_values()  # type: ignore[attr-defined, no-any-return]


def test_node_fields(load: Load, tmp_path: Path) -> None:
    plan = load(
        """<launch>
  <env name="OUTER" value="1" />
  <remap from="a" to="b" />
  <group ns="g">
    <node name="n" pkg="demo" type="run" args="--x $(arg v)" output="screen" respawn="true"
          respawn_delay="1.5" cwd="ros_home" launch-prefix="nice" clear_params="true">
      <remap from="a" to="c" />
      <remap from="d//e/" to="/f" />
      <env name="INNER" value="2" />
    </node>
  </group>
  <node name="m" pkg="demo" type="run" required="True" ns="/abs/x/" />
</launch>""",
        {"v": "7"},
    )
    first, second = plan.nodes
    assert first == Node(
        package="demo",
        type="run",
        name="n",
        namespace="/g/",
        args="--x 7",
        remappings=(("a", "c"), ("d/e", "/f")),
        env=(("OUTER", "1"), ("INNER", "2")),
        respawn=True,
        respawn_delay=1.5,
        output="screen",
        cwd="ROS_HOME",
        launch_prefix="nice",
        clear_params=True,
        source=Source(str(tmp_path / "main.launch"), 5),
    )
    assert first.resolved_name == "/g/n"
    assert (second.namespace, second.required, second.remappings) == (
        "/abs/x/",
        True,
        (("a", "b"),),
    )
    assert plan.clear_params == ["/g/n/"]


def test_params_private_global_and_node_local(load: Load) -> None:
    plan = load(
        """<launch>
  <param name="top" value="1" />
  <param name="~before" value="2" />
  <node name="a" pkg="demo" type="run">
    <param name="own" value="3" />
    <param name="/global_in_node" value="4" />
    <rosparam>{y: {z: 5}}</rosparam>
  </node>
  <group ns="g">
    <param name="~in_group" value="6" />
    <node name="b" pkg="demo" type="run" />
  </group>
  <node name="c" pkg="demo" type="run" />
</launch>"""
    )
    assert values(plan) == {
        "/top": 1,
        "/a/y/z": 5,
        "/a/before": 2,
        "/a/own": 3,
        "/a/global_in_node": 4,
        "/g/b/before": 2,
        "/g/b/in_group": 6,
        "/c/before": 2,
    }


def test_private_params_of_an_include_reach_the_includer(load: Load, write: Write) -> None:
    inner = write("inner.launch", '<launch><param name="~leak" value="1" /></launch>')
    plan = load(
        f"""<launch>
  <param name="~first" value="0" />
  <include file="{inner}" />
  <node name="after" pkg="demo" type="run" />
</launch>"""
    )
    assert values(plan) == {"/after/first": 0, "/after/leak": 1}


def test_rosparam_commands_and_values(load: Load, write: Write) -> None:
    yaml_file = write("p.yaml", "a: 1\nb: {c: [1, 2]}\nd: deg(180)\n")
    plan = load(
        f"""<launch>
  <rosparam file="{yaml_file}" ns="ns" />
  <rosparam command="delete" param="old" />
  <rosparam command="dump" file="/tmp/x.yaml" />
  <rosparam param="list">[1, two]</rosparam>
  <rosparam param="subst" subst_value="true">$(arg v)</rosparam>
</launch>""",
        {"v": "3"},
    )
    assert values(plan) == {
        "/ns/a": 1,
        "/ns/b/c": [1, 2],
        "/ns/d": pytest.approx(3.141592653589793),
        "/list": [1, "two"],
        "/subst": 3,
    }
    assert [(c.command, c.param, c.file) for c in plan.rosparam_commands] == [
        ("delete", "/old", ""),
        ("dump", "/", "/tmp/x.yaml"),
    ]
    assert isinstance(plan.rosparam_commands[0], RosparamCommand)


def test_textfile_binfile_and_command(load: Load, write: Write) -> None:
    text = write("t.txt", "12")
    blob = write("b.bin", "\x00\x01")
    seen: list[list[str]] = []

    def run(argv: list[str]) -> tuple[int, str]:
        seen.append(argv)
        return 0, "true\n"

    plan = load(
        f"""<launch>
  <param name="t" type="int" textfile="{text}" />
  <param name="b" binfile="{blob}" />
  <param name="c" type="bool" command="tool --flag 'two words'" />
</launch>""",
        run=run,
    )
    assert values(plan) == {"/t": 12, "/b": b"\x00\x01", "/c": True}
    assert seen == [["tool", "--flag", "two words"]]


def test_args_include_and_pass_all_args(load: Load, write: Write) -> None:
    inner = write(
        "inner.launch",
        """<launch>
  <arg name="needed" />
  <arg name="opt" default="d" />
  <param name="needed" value="$(arg needed)" />
  <param name="opt" value="$(arg opt)" />
</launch>""",
    )
    plan = load(
        f"""<launch>
  <arg name="needed" default="top" />
  <arg name="opt" value="fixed" />
  <include file="{inner}" ns="one"><arg name="needed" value="x" /></include>
  <include file="{inner}" ns="two" pass_all_args="true" />
  <include file="{inner}" ns="three" pass_all_args="true"><arg name="opt" value="o" /></include>
</launch>""",
        {"needed": "cli"},
    )
    assert values(plan) == {
        "/one/needed": "x",
        "/one/opt": "d",
        "/two/needed": "cli",
        "/two/opt": "fixed",
        "/three/needed": "cli",
        "/three/opt": "o",
    }


def test_a_given_arg_does_not_resolve_its_default(load: Load) -> None:
    # ros_comm#422: roslaunch resolves the default (and fails) even when the arg is given.
    plan = load(
        '<launch><arg name="p" default="$(find missing_pkg)" /><param name="p" value="$(arg p)" />'
        "</launch>",
        {"p": "given"},
    )
    assert values(plan) == {"/p": "given"}


def test_disabled_tags_are_not_resolved(load: Load) -> None:
    plan = load(
        """<launch>
  <group if="false"><param name="a" value="$(arg undeclared)" /></group>
  <node name="n" pkg="demo" type="run" unless="true" args="$(find nope)" />
  <include file="missing.launch" if="0" />
</launch>"""
    )
    assert (plan.params, plan.nodes) == ({}, [])


def test_tests_machines_files_and_warnings(load: Load, tmp_path: Path) -> None:
    plan = load(
        """<launch deprecated="old">
  <machine name="here" address="localhost" default="true" timeout="3" />
  <node name="n" pkg="demo" type="run" colour="red" />
  <test test-name="t" pkg="demo" type="run" time-limit="5" retry="2" />
  <strange />
</launch>"""
    )
    main = str(tmp_path / "main.launch")
    assert plan.nodes[0].machine == "here"
    assert plan.machines["here"].timeout == 3.0
    assert plan.tests == [
        LaunchTest(
            package="demo",
            type="run",
            name="t",
            output="log",
            machine="here",
            test_name="t",
            time_limit=5.0,
            retry=2,
            source=Source(main, 4),
        )
    ]
    assert plan.files == [main]
    assert plan.warnings == [
        f"{main}:1: <launch>: DEPRECATED: old",
        f"{main}:3: <node>: unknown <node> attribute 'colour'",
        f"{main}:5: <strange>: unrecognized tag strange",
    ]


def test_core_and_namespace(load: Load) -> None:
    plan = load(
        '<launch><param name="p" value="1" /><node name="n" pkg="demo" type="run" /></launch>',
        environ={"ROS_NAMESPACE": "/robot", "ROS_MASTER_URI": "http://h:1/"},
        with_core=True,
    )
    assert list(plan.param_values()) == ["/rosversion", "/rosdistro", "/robot/p"]
    assert plan.nodes[0].resolved_name == "/robot/n"
    assert plan.master.uri == "http://h:1/"


@pytest.mark.parametrize(
    ("body", "line", "tag", "message"),
    [
        (
            '<node name="n" pkg="demo" />',
            2,
            "node",
            "<node> tag is missing required attribute: 'type'",
        ),
        ('<param name="p" value="$(arg nope)" />', 2, "param", "requires the 'nope' arg to be set"),
        ('<arg name="a" default="$(arg nope)" />', 2, "arg", "arg 'nope' is not defined"),
        ('<param name="p" value="$(find nope)" />', 2, "param", "Resource not found: nope"),
        (
            '\n\n<group if="1" unless="0" />',
            4,
            "group",
            "cannot set both 'if' and 'unless' on the same tag",
        ),
        (
            '<node name="a/b" pkg="demo" type="run" />',
            2,
            "node",
            "Invalid <node> tag: node name cannot contain a namespace.",
        ),
        (
            "<rosparam>[1]</rosparam>",
            2,
            "rosparam",
            "'param' attribute must be set for non-dictionary values",
        ),
    ],
)
def test_errors_name_file_line_and_tag(
    load: Load, tmp_path: Path, body: str, line: int, tag: str, message: str
) -> None:
    with pytest.raises(LaunchError) as error:
        load(f"<launch>\n{body}\n</launch>")
    main = str(tmp_path / "main.launch")
    assert (error.value.file, error.value.line, error.value.tag) == (main, line, tag)
    assert error.value.message == message
    assert str(error.value) == f"{main}:{line}: <{tag}>: {message}"


def test_errors_inside_an_include_name_the_included_file(load: Load, write: Write) -> None:
    inner = write(
        "inner.launch", '<launch>\n  <node name="n" pkg="demo" type="run" cwd="x" />\n</launch>'
    )
    with pytest.raises(LaunchError) as error:
        load(f'<launch><include file="{inner}" /></launch>')
    assert str(error.value) == (
        f"{inner}:2: <node>: Invalid <node> tag: cwd must be one of 'ROS_HOME', 'node'."
    )


def test_xml_errors(write: Write, index: PackageIndex) -> None:
    path = write("bad.launch", "<launch>\n<node>\n</launch>\n")
    with pytest.raises(LaunchError) as error:
        load_launch([str(path)], {}, {}, index)
    assert str(error.value) == (
        f"{path}:3: Invalid roslaunch XML syntax: mismatched tag: line 3, column 2"
    )
    with pytest.raises(LaunchError, match="no root <launch> tag"):
        load_launch([str(write("x.launch", "<foo />"))], {}, {}, index)
    with pytest.raises(LaunchError, match=r"\[Errno 2\] No such file or directory"):
        load_launch([str(path) + ".missing"], {}, {}, index)


def test_duplicate_node_names(load: Load) -> None:
    with pytest.raises(LaunchError, match=r"multiple nodes named \[/a\]"):
        load(
            '<launch><node name="a" pkg="demo" type="run" /><node name="a" pkg="x" type="y" />'
            "</launch>"
        )


def test_a_file_including_itself_is_refused(load: Load, write: Write, tmp_path: Path) -> None:
    other = write(
        "other.launch", f'<launch>\n<include file="{tmp_path / "main.launch"}" />\n</launch>'
    )
    with pytest.raises(LaunchError) as error:
        load(f'<launch><include file="{other}" /></launch>')
    main = tmp_path / "main.launch"
    assert str(error.value) == (
        f"{other}:2: <include>: the file includes itself: {main} -> {other} -> {main}"
    )


def test_a_file_included_twice_is_read_twice(load: Load, write: Write) -> None:
    inner = write("inner.launch", '<launch><param name="p" value="1" /></launch>')
    plan = load(
        f'<launch><include file="{inner}" ns="a" /><include file="{inner}" ns="b" /></launch>'
    )
    assert plan.param_values() == {"/a/p": 1, "/b/p": 1}


def test_a_package_on_the_path_shadows_rosxs_only_for_the_files_it_has(
    write: Write, tmp_path: Path
) -> None:
    # A message-only turtlesim on the path, as ROS 1's message overlays have one.
    write("pkgs/turtlesim/package.xml", PACKAGE_XML.format(name="turtlesim"))
    write("pkgs/turtlesim/msg/Pose.msg", "float32 x\n")
    write("pkgs/turtlesim/launch/own.launch", "<launch/>")
    index = PackageIndex([tmp_path / "pkgs"])
    shipped = bundled_packages()["turtlesim"] / "launch" / "multisim.launch"
    files, _ = resolve_launch_arguments(["turtlesim", "multisim.launch"], index)
    assert files == [str(shipped)]
    files, _ = resolve_launch_arguments(["turtlesim", "own.launch"], index)
    assert files == [str(tmp_path / "pkgs/turtlesim/launch/own.launch")]
    main = write(
        "main.launch",
        '<launch><include file="$(find turtlesim)/launch/multisim.launch" />'
        '<param name="dir" value="$(find turtlesim)" />'
        '<param name="own" value="$(find turtlesim)/launch/own.launch" /></launch>',
    )
    plan = load_launch([str(main)], {}, {}, index, with_core=False)
    assert [n.namespace + n.name for n in plan.nodes] == ["/turtlesim1/sim", "/turtlesim2/sim"]
    assert plan.files == [str(main), str(shipped)]
    assert plan.param_values() == {
        "/dir": str(tmp_path / "pkgs/turtlesim"),
        "/own": str(tmp_path / "pkgs/turtlesim/launch/own.launch"),
    }
