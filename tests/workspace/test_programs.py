"""The programs rosx provides, read from its bundled tree: what rosrun runs, roslaunch starts and
completion offers, and the line that says a package is not part of rosx.

A package bundled as Noetic installs it (``share/<pkg>/package.xml``, programs in
``lib/<pkg>/<exe>``) is provided everywhere at once, with no list to edit; the "not part of
rosx" line for it disappears by itself.
"""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.launch.run.runner import provided_program
from rosx.packages import bundled, crawl
from rosx.workspace import programs
from rosx.workspace.programs import (
    bundled_program,
    is_provided,
    lacking,
    program_names,
    provided_packages,
)
from rosx_commands.context import Environment
from rosx_commands.rosrun import Launch, plan
from rosx_commands.tools import TOOLS
from tests.support.cli import clean_environ, rosx, rosx_process
from tests.support.packages import package
from tests.support.workspace_text import TerminalText

LIB = crawl.PREFIX / "lib"


def _every_lib_program() -> list[tuple[str, str]]:
    return sorted(
        (folder.name, file.name)
        for folder in LIB.iterdir()
        if folder.is_dir()
        for file in folder.iterdir()
        if file.is_file()
    )


@pytest.mark.parametrize(("package_name", "name"), _every_lib_program())
def test_every_program_in_lib_is_what_rosrun_roslaunch_and_completion_use(
    package_name: str, name: str
) -> None:
    path = LIB / package_name / name
    assert path.stat().st_mode & 0o111, f"{path} is not executable"
    assert bundled_program(package_name, name) == path
    assert provided_program(package_name, name) == [str(path)]
    assert name in program_names(package_name)
    assert is_provided(package_name) and lacking(package_name) is None
    started = plan([package_name, name], Environment(environ=clean_environ()))
    assert callable(started) and not isinstance(started, Launch)  # rosx's own: in this process
    completed = rosx("complete", "2", "rosrun", package_name, "")
    assert name in completed.out.split("\0")


def test_rosrun_of_a_ros_tool_runs_rosxs_tool() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "rosrun", "rosmsg", "rosmsg", "show", "std_msgs/Bool"],
        capture_output=True, text=True, env=clean_environ(), timeout=60, check=False,
    )  # fmt: skip
    assert (done.returncode, done.stdout, done.stderr) == (0, "bool data\n\n", "")


def test_rosrun_rosbag_play_is_rosbag_play(tmp_path: Path) -> None:
    """``rosbag record`` and ``play`` run rosbag's ``lib/`` programs in ROS 1; ``rosrun rosbag
    play`` is rosx's ``rosbag play``."""
    missing = tmp_path / "nosuch.bag"
    done = rosx_process("rosrun", "rosbag", "play", str(missing))
    assert done.status == 1
    assert done.err.endswith(f"]: Error opening file: {missing}\n")
    assert done.err.startswith("[FATAL] [")


def test_rosxs_program_wins_over_a_same_named_package_on_the_path(tmp_path: Path) -> None:
    """As roslaunch does: the system's turtlesim (or a message-only one) does not replace
    rosx's turtlesim_node."""
    other = package(tmp_path, "turtlesim")
    node = other / "turtlesim_node"
    node.write_text("#!/bin/sh\necho system\n")
    node.chmod(0o755)
    env = Environment(environ=clean_environ(ROS_PACKAGE_PATH=str(tmp_path)))
    started = plan(["turtlesim", "turtlesim_node"], env)
    assert callable(started) and not isinstance(started, Launch)
    assert plan(["--prefix", "nice", "turtlesim", "turtlesim_node"], env) == Launch(
        ["nice", *started_command(bundled_program("turtlesim", "turtlesim_node"))],
        shim_env(env),
    )


def test_a_workspace_python_script_overlays_rosxs_program(tmp_path: Path) -> None:
    """A clone of turtle_tf2 in a workspace runs its own scripts, as an overlay does in ROS 1
    (rospack finds the workspace's package, and rosrun and roslaunch run what it holds)."""
    clone = package(tmp_path, "turtle_tf2")
    script = clone / "nodes" / "turtle_tf2_broadcaster.py"
    script.parent.mkdir()
    script.write_text("#!/usr/bin/env python\nimport rospy\n")
    script.chmod(0o755)
    env = Environment(environ=clean_environ(ROS_PACKAGE_PATH=str(tmp_path)))
    planned = plan(["--prefix", "nice", "turtle_tf2", "turtle_tf2_broadcaster.py"], env)
    assert isinstance(planned, Launch)
    assert str(script) in planned.argv
    from rosx.packages.index import PackageIndex

    index = PackageIndex.from_environ(env.environ)
    assert provided_program("turtle_tf2", "turtle_tf2_broadcaster.py", index) is None
    assert provided_program("turtle_tf2", "turtle_tf2_broadcaster.py") == [
        str(bundled_program("turtle_tf2", "turtle_tf2_broadcaster.py"))
    ]


def started_command(path: Path | None) -> list[str]:
    from rosx_commands.invocation import script_command

    assert path is not None
    return [*script_command(), str(path)]


def shim_env(env: Environment) -> dict[str, str]:
    from rosx.client.script import shim_environ
    from rosx_commands.scripts import shim_dirs

    return shim_environ(env.environ, shim_dirs())


# -- a package bundled tomorrow ------------------------------------------------------------


@pytest.fixture
def prefix(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """rosx's bundled tree, copied with its packages' manifests, to bundle more into."""
    root = tmp_path / "noetic"
    share = root / "share"
    for directory in (crawl.PREFIX / "share").iterdir():
        if (directory / "package.xml").is_file():
            (share / directory.name).mkdir(parents=True)
            (share / directory.name / "package.xml").write_text(
                (directory / "package.xml").read_text()
            )
    monkeypatch.setattr(crawl, "PREFIX", root)
    monkeypatch.setattr(bundled, "PREFIX", str(root))
    _forget_the_tree()
    yield root
    _forget_the_tree()


def _forget_the_tree() -> None:
    """What a new process knows: the tree as it is now (a process reads it once)."""
    for cached in (crawl.bundled_packages, programs.provided_packages, programs._bundled_root):
        cached.cache_clear()


def _bundle(prefix: Path, name: str, program: str, text: str) -> Path:
    package(prefix / "share", name)
    wrapper = prefix / "lib" / name / program
    wrapper.parent.mkdir(parents=True)
    wrapper.write_text(f"#!/usr/bin/env python3\nprint({text!r})\n")
    wrapper.chmod(0o755)
    _forget_the_tree()
    return wrapper


def _terminal() -> tuple[Environment, io.StringIO]:
    """An environment whose stderr is a terminal, and that stderr."""
    err = TerminalText()
    return Environment(stdout=io.StringIO(), stderr=err, environ=clean_environ()), err


def test_a_package_bundled_is_provided_everywhere_with_no_list_to_edit(
    prefix: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    shutil.rmtree(prefix / "share" / "stage_ros", ignore_errors=True)  # bundled anew below
    _forget_the_tree()
    env, err = _terminal()
    assert plan(["stage_ros", "stageros", "w.world"], env) == 2
    assert err.getvalue() == (
        "[rospack] Error: package 'stage_ros' not found\n"
        "[rosx] stage_ros is not part of rosx ('rosx --help' lists the packages it provides)\n"
    )
    assert "stage" not in str(lacking("gazebo_ros", ()))

    wrapper = _bundle(prefix, "stage_ros", "stageros", "a stage")
    assert "stage_ros" in provided_packages() and lacking("stage_ros") is None
    assert bundled_program("stage_ros", "stageros") == wrapper
    assert rosx("rospack", "find", "stage_ros").out == f"{prefix}/share/stage_ros\n"
    assert rosx("complete", "2", "rosrun", "stage_ros", "").out == "stageros\0"
    started = plan(["stage_ros", "stageros", "w.world"], env)
    assert callable(started)
    # It runs in this process, as a script does: what it changes of the process is put back.
    monkeypatch.setattr(sys, "path", list(sys.path))
    monkeypatch.setattr(sys, "meta_path", list(sys.meta_path))  # rosx's finders of msg modules
    monkeypatch.setattr(sys, "argv", list(sys.argv))
    monkeypatch.setitem(sys.modules, "__main__", sys.modules["__main__"])
    monkeypatch.setenv("PYTHONPATH", os.environ.get("PYTHONPATH", ""))
    assert started() == 0
    assert capsys.readouterr().out == "a stage\n"
    # A counterpart is named once it is there.
    assert lacking("gazebo_ros", ()) == (
        "[rosx] gazebo_ros is not part of rosx; instead: rosx rosrun stage_ros stageros WORLD"
    )
    assert lacking("turtlebot3_gazebo", ()) == str(lacking("gazebo_ros", ())).replace(
        "gazebo_ros", "turtlebot3_gazebo"
    )


# -- the lines after ROS 1's errors ---------------------------------------------------------


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["rqt", "graph", "rqt", "graph"],
            "[rosrun] Did you mean rqt_graph? (rosrun rqt_graph rqt_graph)",
        ),
        (["turtlesm", "turtlesim_node"], "[rosrun] Did you mean turtlesim? (rosrun turtlesim turtlesim_node)"),
        # a name broken across a line: both words make it, and both go
        (["turtle", "sim", "turtlesim_node"], "[rosrun] Did you mean turtlesim? (rosrun turtlesim turtlesim_node)"),
        (["turtle", "sim", "turtle", "teleop", "key"],
         "[rosrun] Did you mean turtlesim? (rosrun turtlesim turtle_teleop_key)"),
        (["gazebo_ros", "gzserver"], "[rosx] gazebo_ros is not part of rosx"),
        (["turtlebot3_teleop", "x"], "[rosx] turtlebot3_teleop is not part of rosx"),
    ],
)  # fmt: skip
def test_rosrun_of_an_unknown_package_says_what_was_meant_on_a_terminal(
    argv: list[str], line: str
) -> None:
    env, err = _terminal()
    assert plan(argv, env) == 2
    first, second = err.getvalue().splitlines()
    assert first == f"[rospack] Error: package '{argv[0]}' not found"
    assert second.startswith(line)
    plain = rosx("rosrun", *argv)
    assert (plain.status, plain.out, plain.err) == (2, "", first + "\n")


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (["turtle", "teleop", "key"], "[rosrun] Did you mean turtle_teleop_key? (rosrun turtlesim turtle_teleop_key)"),
        (["turtlesim", "node", "__name:=a"], "[rosrun] Did you mean turtlesim_node? (rosrun turtlesim turtlesim_node __name:=a)"),
        (["turtle", "sim_node", "__name:=a"], "[rosrun] Did you mean turtlesim_node? (rosrun turtlesim turtlesim_node __name:=a)"),
    ],
)  # fmt: skip
def test_rosrun_of_an_executable_typed_with_spaces_names_it(argv: list[str], line: str) -> None:
    out, err = io.StringIO(), TerminalText()
    assert plan(["turtlesim", *argv], Environment(stdout=out, stderr=err)) == 3
    assert out.getvalue().startswith(f"[rosrun] Couldn't find executable named {argv[0]} below ")
    assert err.getvalue() == line + "\n"


def test_roslaunch_of_what_rosx_lacks_says_so_after_ros1s_error() -> None:
    from rosx_commands.roslaunch import roslaunch

    env, err = _terminal()
    assert roslaunch(["turtlebot3_gazebo", "turtlebot3_world.launch"], env) == 1
    assert err.getvalue().splitlines() == [
        "RLException: [turtlebot3_world.launch] is neither a launch file in package "
        "[turtlebot3_gazebo] nor is [turtlebot3_gazebo] a launch file name",
        "[rosx] turtlebot3_gazebo is not part of rosx; instead: "
        "rosx roslaunch turtlebot3_stage turtlebot3_world.launch",
    ]
    env, err = _terminal()
    assert roslaunch(["turtlesim", "multisim.lauch"], env) == 1
    assert err.getvalue().splitlines()[1] == (
        "[roslaunch] Did you mean multisim.launch? (roslaunch turtlesim multisim.launch)"
    )
    env, err = _terminal()
    assert roslaunch(["turtle", "sim", "multisim.launch"], env) == 1
    assert err.getvalue().splitlines()[1] == (
        "[roslaunch] Did you mean turtlesim? (roslaunch turtlesim multisim.launch)"
    )
    env, err = _terminal()
    assert roslaunch(["turtlesim", "turtlemimic.launch"], env) == 1
    assert (
        err.getvalue().splitlines()[1]
        == "[roslaunch] the launch files of turtlesim: multisim.launch"
    )
    plain = rosx("roslaunch", "turtlebot3_gazebo", "turtlebot3_world.launch")
    assert (plain.status, len(plain.err.splitlines())) == (1, 1)


def test_the_readme_lists_every_package_and_tool_that_comes_with_rosx() -> None:
    readme = " ".join((Path(__file__).parents[2] / "README.md").read_text().split())
    listed = ", ".join(provided_packages())
    assert f"list of the installed version): {listed}." in readme
    unnamed = [t for t in TOOLS if f"`rosx {t}" not in readme and f"`{t}`" not in readme]
    assert unnamed == []


def test_rosx_help_lists_the_packages_that_come_with_rosx() -> None:
    shown = " ".join(rosx_process("--help", COLUMNS="100").out.split())
    listed = ", ".join(provided_packages())
    assert (
        f"ROS packages that come with rosx (rospack, roscd, rosrun and roslaunch find them): {listed}."
        in shown
    )
