"""The beginner tutorials' small tools: rosed, roscp, rosversion, rosmsg-proto, roswtf and the
completer behind tab completion; golden texts, and ROS 1's own output where it is installed."""

from __future__ import annotations

import stat
import subprocess
import sys
import xmlrpc.client
from collections.abc import Callable
from pathlib import Path

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.workspace.environment import ROS_ROOT
from tests.support.cli import clean_environ, rosx
from tests.support.packages import package
from tests.support.procs import wait_for
from tests.support.ros1 import ROS1, needs_ros1, ros1_environ, run_ros1

WARNING = "\033[1mWARNING\033[0m"
ERROR = "\033[31m\033[1mERROR\033[0m"


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    src = tmp_path / "src"
    pkg = package(src, "beginner_tutorials", "rospy")
    (pkg / "scripts").mkdir()
    (pkg / "scripts" / "talker.py").write_text("print('talker')\n")
    (pkg / "launch").mkdir()
    (pkg / "launch" / "demo.launch").write_text(
        '<launch>\n  <arg name="rate" default="1"/>\n  <arg name="topic"/>\n'
        '  <node pkg="beginner_tutorials" type="talker.py" name="talker"/>\n</launch>\n'
    )
    (pkg / "msg").mkdir()
    (pkg / "msg" / "Num.msg").write_text("int64 num\n")
    return src


def env_of(src: Path, **extra: str) -> dict[str, str]:
    return clean_environ(**{"ROS_PACKAGE_PATH": str(src), "PWD": str(src), **extra})


# -- rosed and roscp --------------------------------------------------------------------------


def test_rosed_runs_the_editor_on_the_packages_file(workspace: Path, tmp_path: Path) -> None:
    editor = tmp_path / "editor"
    record = tmp_path / "edited"
    editor.write_text(f'#!/bin/sh\necho "$@" > {record}\n')
    editor.chmod(editor.stat().st_mode | stat.S_IXUSR)
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "rosed", "beginner_tutorials", "package.xml"],
        env=env_of(workspace, EDITOR=f"{editor}"),
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert record.read_text() == f"{workspace}/beginner_tutorials/package.xml\n"


def test_rosed_says_plainly_when_there_is_no_editor(workspace: Path, tmp_path: Path) -> None:
    env = env_of(workspace, PATH=str(tmp_path), EDITOR="")
    result = rosx("rosed", "beginner_tutorials", "package.xml", environ=env)
    assert result.status == 1
    assert result.err == (
        f"rosed: cannot edit {workspace}/beginner_tutorials/package.xml: vim (rosed's editor when "
        "$EDITOR is not set) is not installed; set EDITOR, e.g. export EDITOR=nano\n"
    )


def test_rosed_and_roscp_report_as_rosbash(workspace: Path, tmp_path: Path) -> None:
    env = env_of(workspace)
    missing = rosx("rosed", "nopkg", "x", environ=env)
    assert (missing.status, missing.out) == (1, "Couldn't find package [nopkg]\n")
    nofile = rosx("roscp", "beginner_tutorials", "nofile", "x", environ=env)
    assert (nofile.status, nofile.out) == (1, "That file does not exist in that package.\n")
    usage = rosx("roscp", "beginner_tutorials", environ=env)
    assert (usage.status, usage.out) == (
        0,
        "usage: roscp package filename target\n\nCopy a file from a package to target location.\n",
    )
    assert rosx("rosed", "--help", environ=env).out == (
        "usage: rosed [package] [file]\n\nEdit a file within a package.\n"
    )


def test_roscp_copies_and_picks_among_same_named_files(
    workspace: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    env = env_of(workspace, PWD=str(tmp_path))
    (workspace / "beginner_tutorials" / "launch" / "talker.py").write_text("other\n")
    result = rosx("roscp", "beginner_tutorials", "talker.py", "copy.py", stdin="2\n", environ=env)
    assert result.status == 0, result.err
    assert result.out == (
        "You have chosen a non-unique filename, please pick one of the following:\n"
    )
    assert result.err == (
        f"1) {workspace}/beginner_tutorials/launch/talker.py\n"
        f"2) {workspace}/beginner_tutorials/scripts/talker.py\n#? "
    )
    assert (tmp_path / "copy.py").read_text() == "print('talker')\n"


# -- rosversion -------------------------------------------------------------------------------


def test_rosversion(workspace: Path) -> None:
    env = env_of(workspace)
    assert rosx("rosversion", "beginner_tutorials", environ=env).out == "0.0.0\n"
    assert rosx("rosversion", "-s", "beginner_tutorials", environ=env).out == "0.0.0"
    assert rosx("rosversion", "-d", environ=env).out == "noetic\n"
    missing = rosx("rosversion", "nopkg", environ=env)
    assert (missing.status, missing.out) == (1, "Cannot locate [nopkg]\n")
    both = rosx("rosversion", "-d", "std_msgs", environ=env)
    assert both.status == 2
    assert both.err.endswith(
        "rosversion: error: argument package: not allowed with argument -d/--distro\n"
    )
    assert "beginner_tutorials: 0.0.0\n" in rosx("rosversion", "-a", environ=env).out


@needs_ros1
def test_rosversion_help_and_errors_read_as_ros1s() -> None:
    for args in (["-h"], [], ["-d", "std_msgs"], ["nopkg"], ["-d"]):
        ours = rosx("rosversion", *args, environ=clean_environ(ROS_DISTRO="noetic"))
        theirs = run_ros1(["/usr/bin/rosversion", *args], ROS_DISTRO="noetic")
        assert (ours.status, ours.out, ours.err) == (
            theirs.returncode,
            theirs.stdout,
            theirs.stderr,
        ), args


# -- rosmsg-proto -----------------------------------------------------------------------------

PROTO_CASES = [
    ["msg", "std_msgs/String"],
    ["msg", "geometry_msgs/Twist"],
    ["msg", "-f", "1", "geometry_msgs/Twist"],
    ["msg", "-s", "geometry_msgs/Twist"],
    ["msg", "sensor_msgs/JointState"],
    ["msg", "-e", "sensor_msgs/JointState"],
    ["msg", "sensor_msgs/CameraInfo"],
    ["msg", "sensor_msgs/Image"],
    ["msg", "geometry_msgs/PoseWithCovariance"],
    ["msg", "-f", "1", "geometry_msgs/PoseWithCovariance"],
    ["msg", "std_msgs/Float32MultiArray"],
    ["msg", "-H", "std_msgs/Header"],
    ["msg", "-p", "  ", "std_msgs/String"],
    ["msg", "-x", "position", "geometry_msgs/Pose"],
    ["srv", "std_srvs/SetBool"],
    ["srv", "std_srvs/Empty"],
    ["msg", "nosuch/Foo"],
    ["srv", "nosuch/Foo"],
    ["msg", "NoSuchName"],
    ["foo", "std_msgs/String"],
    ["msg"],
    ["msg", "std_msgs::String"],
]


def test_rosmsg_proto_golden() -> None:
    twist = rosx("rosmsg-proto", "msg", "geometry_msgs/Twist")
    assert (twist.status, twist.out) == (
        0,
        '"linear:\n  x: 0.0\n  y: 0.0\n  z: 0.0\nangular:\n  x: 0.0\n  y: 0.0\n  z: 0.0"\n',
    )
    joint = rosx("rosmsg-proto", "msg", "sensor_msgs/JointState")
    assert joint.out == (
        "\"header:\n  seq: 0\n  stamp: {secs: 0, nsecs: 0}\n  frame_id: ''\n"
        "name: ['']\nposition: [0]\nvelocity: [0]\neffort: [0]\"\n"
    )
    assert rosx("rossrv-proto", "srv", "std_srvs/SetBool").out == '"data: false"\n'
    short = rosx("rosmsg-proto")
    assert (short.status, short.out, short.err) == (64, "", "Insufficient arguments")
    assert rosx("rosmsg-proto", "msg", "-f", "1", "Twist").out == (
        '"{linear: {x: 0.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 0.0}}"\n'
    )
    unknown = rosx("rosmsg-proto", "msg", "nosuch/Foo")
    assert (unknown.status, unknown.err) == (1, "Unknown message class: nosuch/Foo")


@needs_ros1
@pytest.mark.parametrize("args", PROTO_CASES, ids=" ".join)
def test_rosmsg_proto_prints_what_ros1_prints(args: list[str]) -> None:
    theirs = run_ros1(["/usr/bin/rosmsg-proto", *args])
    ours = rosx("rosmsg-proto", *args, environ=ros1_environ())
    assert (ours.status, ours.out, ours.err) == (theirs.returncode, theirs.stdout, theirs.stderr)


# -- roswtf -----------------------------------------------------------------------------------

OFFLINE = (
    "No package or stack in the current directory\n" + "=" * 80 + "\n"
    "Static checks summary:\n\nNo errors or warnings\n" + "=" * 80 + "\n\n"
    "ROS Master does not appear to be running.\nOnline graph checks will not be run.\n"
    "ROS_MASTER_URI is [{uri}]\n"
)


def test_roswtf_offline_in_a_sound_environment(
    workspace: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    uri = "http://127.0.0.1:1"
    env = env_of(workspace, ROS_MASTER_URI=uri, PWD=str(tmp_path), ROS_ROOT=str(ROS_ROOT))
    result = rosx("roswtf", environ=env)
    assert (result.status, result.out, result.err) == (0, OFFLINE.format(uri=uri), "")
    monkeypatch.chdir(workspace / "beginner_tutorials")
    here = rosx(
        "roswtf", "--offline", environ={**env, "PWD": str(workspace / "beginner_tutorials")}
    )
    assert here.out.startswith("Package: beginner_tutorials\n")


def test_roswtf_reports_a_broken_environment(tmp_path: Path) -> None:
    env = clean_environ(
        ROS_PACKAGE_PATH=f"{tmp_path}/missing",
        ROS_MASTER_URI="http://127.0.0.1",
        PYTHONPATH="",
        PWD=str(tmp_path),
    )
    result = rosx("roswtf", environ=env)
    assert result.out.splitlines()[4:13] == [
        "Found 2 error(s).",
        "",
        f"{ERROR} Not all paths in ROS_PACKAGE_PATH [{tmp_path}/missing] point to an existing "
        "directory: ",
        f" * {tmp_path}/missing",
        "",
        f"{ERROR} ROS_MASTER_URI [http://127.0.0.1] is not a valid URL: port number is missing",
        "=" * 80,
        "",
        "ROS Master does not appear to be running.",
    ]
    bad_root = rosx("roswtf", environ={**env, "ROS_ROOT": str(tmp_path)})
    assert (bad_root.status, bad_root.out) == (
        1,
        f"ROS_ROOT is invalid: ROS_ROOT [{tmp_path}] must end in directory named 'ros'\n",
    )


def _graph(master: str, make_node: Callable[..., Node]) -> None:
    """A publisher of /hello, and a /ghost node that subscribes to /chatter and provides a
    service but cannot be reached."""
    talker = make_node("/talker", environ={"ROS_IP": "127.0.0.1"})
    talker.advertise("/hello", get_message_class("std_msgs/String"))
    proxy = xmlrpc.client.ServerProxy(master)
    proxy.registerSubscriber("/ghost", "/chatter", "std_msgs/String", "http://127.0.0.1:9/")
    proxy.registerService("/ghost", "/ghost/srv", "rosrpc://127.0.0.1:9", "http://127.0.0.1:9/")


ONLINE = f"""\
Beginning tests of your ROS graph. These may take a while...
analyzing graph...
... done analyzing graph
running graph rules...
... done running graph rules

Online checks summary:

Found 1 warning(s).
Warnings are things that may be just fine, but are sometimes at fault

{WARNING} The following node subscriptions are unconnected:
 * /ghost:
   * /chatter


Found 2 error(s).

{ERROR} Could not contact the following nodes:
 * /ghost

{ERROR} Errors connecting to the following services:
 * service [/ghost/srv] appears to be malfunctioning: Unable to communicate with service [/ghost/srv], address [rosrpc://127.0.0.1:9]

"""


def test_roswtf_online_checks_the_graph(
    master: str, make_node: Callable[..., Node], tmp_path: Path
) -> None:
    _graph(master, make_node)
    env = clean_environ(
        ROS_MASTER_URI=master, ROS_PACKAGE_PATH=str(tmp_path), PWD=str(tmp_path), PYTHONPATH=""
    )
    result = rosx("roswtf", environ=env)
    assert result.out.split("=" * 80 + "\n")[2] == ONLINE
    assert result.err == "ERROR: connection refused to [http://127.0.0.1:9/]\n"


@needs_ros1
def test_roswtf_prints_what_ros1s_prints(
    master: str, make_node: Callable[..., Node], tmp_path: Path
) -> None:
    _graph(master, make_node)
    home = tmp_path / "home"
    (home / ".ros" / "rosdep" / "sources.cache").mkdir(parents=True)
    (home / ".ros" / "rosdep" / "sources.cache" / "index").touch()  # rosx has no rosdep
    settings = {"ROS_MASTER_URI": master, "ROS_ROOT": str(ROS_ROOT), "HOME": str(home)}
    theirs = subprocess.run(
        ["/usr/bin/roswtf"],
        cwd=tmp_path,
        env=ros1_environ(**settings),
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    ours = rosx("roswtf", environ=ros1_environ(**settings, PWD=str(tmp_path)))
    assert ours.out == theirs.stdout
    # Debian's rospack adds a complaint about its rosdep installation.
    noise = "the rosdep view is empty: call 'sudo rosdep init' and 'rosdep update'\n"
    assert ours.err == theirs.stderr.replace(noise, "")


# -- completion -------------------------------------------------------------------------------


def candidates(*words: str, environ: dict[str, str]) -> list[str]:
    result = rosx("complete", str(len(words) - 1), *words, environ=environ)
    assert result.status == 0, result.err
    return [c for c in result.out.split("\0") if c]


def test_completion_of_packages_files_and_types(workspace: Path) -> None:
    env = env_of(workspace)
    assert candidates("roscd", "beginner", environ=env) == ["beginner_tutorials/"]
    assert candidates("roscd", "beginner_tutorials/", environ=env) == [
        "beginner_tutorials/launch/",
        "beginner_tutorials/msg/",
        "beginner_tutorials/scripts/",
    ]
    assert candidates("rosed", "beginner_tutorials", "", environ=env) == [
        "Num.msg",
        "demo.launch",
        "package.xml",
        "talker.py",
    ]
    assert candidates("roslaunch", "beginner_tutorials", "", environ=env) == ["demo.launch"]
    assert candidates("roslaunch", "beginner_tutorials", "demo.launch", "", environ=env) == [
        "rate:=",
        "topic:=",
    ]
    assert candidates("rosrun", "beginner_tutorials", "", environ=env) == []
    script = workspace / "beginner_tutorials" / "scripts" / "talker.py"
    script.chmod(0o755)
    assert candidates("rosrun", "--debug", "beginner_tutorials", "t", environ=env) == ["talker.py"]
    assert candidates("rosx", "rosms", environ=env) == ["rosmsg", "rosmsg-proto"]
    assert candidates("rosx", "rostopic", "e", environ=env) == ["echo"]
    assert candidates("rosmsg", "show", "beginner_tutorials/", environ=env) == [
        "beginner_tutorials/Num"
    ]
    assert "geometry_msgs/" in candidates("rosmsg", "show", "", environ=env)
    assert candidates("rostopic", "pub", "/x", "geometry_msgs/Vector3", "", environ=env) == [
        '"x: 0.0\ny: 0.0\nz: 0.0"'
    ]


def test_completion_asks_the_master(master: str, make_node: Callable[..., Node]) -> None:
    node = make_node("/talker", environ={"ROS_IP": "127.0.0.1"})
    node.advertise("/chatter", get_message_class("std_msgs/String"))
    env = clean_environ(ROS_MASTER_URI=master)
    wait_for(lambda: "/chatter" in candidates("rostopic", "echo", "", environ=env))
    assert candidates("rostopic", "echo", "/ch", environ=env) == ["/chatter"]
    assert candidates("rostopic", "pub", "/chatter", "", environ=env) == ["std_msgs/String"]
    assert candidates("rosnode", "info", "/t", environ=env) == ["/talker"]
    assert "/run_id" in candidates("rosparam", "get", "", environ=env)
    assert "/talker/get_loggers" in candidates("rosservice", "call", "", environ=env)
    assert candidates("rosservice", "call", "/talker/set_logger_level", "", environ=env) == [
        "\"logger: ''\nlevel: ''\""
    ]
    down = clean_environ(ROS_MASTER_URI="http://127.0.0.1:1")
    assert candidates("rostopic", "echo", "", environ=down) == []


@pytest.mark.parametrize("shell", ["bash", "zsh"])
def test_tab_completion_in_the_shell(workspace: Path, shell: str) -> None:
    """The shell function that shell-init installs fills the shell's completion, also of the
    command names that are programs on PATH."""
    import shutil

    if shutil.which(shell) is None:
        pytest.skip(f"{shell} is not installed")
    init = f'eval "$({sys.executable} -m rosx_commands shell-init {shell})"\n'
    if shell == "bash":
        script = init + (
            "COMP_WORDS=(roscd begin); COMP_CWORD=1; _rosx_complete; printf '%s\\n' \"${COMPREPLY[@]}\"\n"
            "COMP_WORDS=(rosed beginner_tutorials pack); COMP_CWORD=2; _rosx_complete;"
            " printf '%s\\n' \"${COMPREPLY[@]}\"\n"
            "complete -p rosrun roscd\n"
            "type -t rosrun\n"
        )
        expected = [
            "beginner_tutorials/",
            "package.xml",
            "complete -o default -F _rosx_complete rosrun",
            "complete -o nospace -F _rosx_complete roscd",
            "file",
        ]
    else:
        script = (
            "autoload -Uz compinit && compinit -u\n"
            + init
            + 'compadd() { print -r -- "compadd $*"; }\n'
            "words=(roscd begin); CURRENT=2; _rosx_complete\n"
            "words=(rosed beginner_tutorials pack); CURRENT=3; _rosx_complete\n"
            "print -r -- $_comps[rostopic]\n"
            "whence -w rostopic\n"
        )
        expected = [
            "compadd -Q -S  -- beginner_tutorials/",
            "compadd -Q -- package.xml",
            "_rosx_complete",
            "rostopic: command",
        ]
    done = subprocess.run(
        [shell, "-c", script],
        env={**env_of(workspace), "HOME": str(workspace.parent), "XDG_CACHE_HOME": ""},
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.stdout.splitlines() == expected, done.stderr


def test_tools_skip_cleanly_without_ros1() -> None:
    assert ROS1 in (True, False)
