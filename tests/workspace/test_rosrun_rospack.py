"""``rosx rosrun``, ``rosx rospack``, ``rosx roscd`` and ``rosx shell-init``: finding packages
and executables with ROS 1's texts and exit statuses, and the commands shell-init provides."""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rosx.bag import SHIM_DIR as BAG_SHIM_DIR
from rosx.client.script import SHIM_DIR
from rosx_commands.context import Environment
from rosx_commands.rosrun import Launch, plan
from tests.support.cli import clean_environ, rosx
from tests.support.packages import package
from tests.support.workspace_text import TUTORIAL_DEPENDS, TerminalText


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A source space with lab2 (a script in ``scripts/``) and a package depending on it."""
    src = tmp_path / "src"
    lab2 = package(src, "lab2", "std_msgs", "rospy", "roscpp", "not_a_package")
    (lab2 / "scripts").mkdir()
    script = lab2 / "scripts" / "pub.py"
    script.write_text("#!/usr/bin/python3\nimport sys, rospy\nprint(rospy.myargv())\n")
    script.chmod(0o755)
    (lab2 / "scripts" / "notes.py").write_text("print('not executable')\n")
    package(src, "user", "lab2")
    return src


def env_of(src: Path) -> dict[str, str]:
    return clean_environ(ROS_PACKAGE_PATH=str(src))


def test_rospack_finds_lists_and_follows_dependencies(workspace: Path) -> None:
    env = env_of(workspace)
    assert rosx("rospack", "find", "lab2", environ=env).out == f"{workspace}/lab2\n"
    listing = rosx("rospack", "list", environ=env).out.splitlines()
    assert f"lab2 {workspace}/lab2" in listing and listing == sorted(listing)
    assert any(line.startswith("turtlesim ") for line in listing)
    assert rosx("rospack", "depends1", "lab2", environ=env).out == "std_msgs\nrospy\nroscpp\n"
    # Noetic's closure of std_msgs, rospy and roscpp, then lab2 (the order: tests below).
    depends = rosx("rospack", "depends", "user", environ=env).out.split()
    assert depends[-1] == "lab2" and sorted(depends) == sorted([*TUTORIAL_DEPENDS, "lab2"])
    assert rosx("rospack", "depends-on1", "lab2", environ=env).out == "user\n"


@pytest.mark.parametrize(
    ("argv", "status", "err"),
    [
        (["find", "nopkg"], 1, "[rospack] Error: package 'nopkg' not found\n"),
        (["depends", "nopkg"], 1, "[rospack] Error: no such package nopkg\n"),
        (["bogus"], 1, "[rospack] Error: command bogus not implemented\n"),
        ([], 0, "[rospack] Error: no command given.  Try 'rospack help'\n"),
        (["-q", "find", "nopkg"], 1, ""),
    ],
)
def test_rospack_errors(workspace: Path, argv: list[str], status: int, err: str) -> None:
    result = rosx("rospack", *argv, environ=env_of(workspace))
    assert (result.status, result.out, result.err) == (status, "", err)


def test_rosrun_of_an_unknown_package_is_rospacks_error_and_status_2(workspace: Path) -> None:
    result = rosx("rosrun", "nopkg", "talker.py", environ=env_of(workspace))
    assert (result.status, result.out) == (2, "")
    assert result.err == "[rospack] Error: package 'nopkg' not found\n"


def test_rosrun_of_a_missing_executable_is_status_3(workspace: Path) -> None:
    result = rosx("rosrun", "lab2", "sub.py", environ=env_of(workspace))
    assert (result.status, result.err) == (3, "")
    assert result.out == f"[rosrun] Couldn't find executable named sub.py below {workspace}/lab2\n"


def test_rosrun_names_scripts_without_the_run_bit(workspace: Path) -> None:
    result = rosx("rosrun", "lab2", "notes.py", environ=env_of(workspace))
    assert result.status == 3
    assert result.out == (
        f"[rosrun] Couldn't find executable named notes.py below {workspace}/lab2\n"
        "[rosrun] Found the following, but they're either not files,\n"
        "[rosrun] or not executable:\n"
        f"[rosrun]   {workspace}/lab2/scripts/notes.py\n"
    )


def test_rosrun_usage_and_invalid_names(workspace: Path) -> None:
    usage = rosx("rosrun", "lab2", environ=env_of(workspace))
    assert usage.status == 0
    assert usage.out.startswith(
        "Usage: rosrun [--prefix cmd] [--debug] PACKAGE EXECUTABLE [ARGS]\n"
    )
    invalid = rosx("rosrun", "lab2", "scripts/", environ=env_of(workspace))
    assert (invalid.status, invalid.out) == (1, "Invalid filename:  scripts/\n")


@pytest.mark.parametrize("answer", ["x", "²", "3"])
def test_rosrun_refuses_a_choice_that_is_not_a_listed_number(workspace: Path, answer: str) -> None:
    for folder in ("bin", "scripts"):
        (workspace / "lab2" / folder).mkdir(exist_ok=True)
        (workspace / "lab2" / folder / "twice").write_text("#!/bin/sh\n")
        (workspace / "lab2" / folder / "twice").chmod(0o755)
    result = rosx("rosrun", "lab2", "twice", stdin=answer + "\n", environ=env_of(workspace))
    assert result.status == 3
    assert result.err.endswith("2) " + str(workspace / "lab2" / "scripts" / "twice") + "\n#? ")


def test_rosrun_runs_python_scripts_with_rosxs_python(workspace: Path) -> None:
    env = Environment(environ=env_of(workspace))
    launch = plan(["lab2", "pub.py", "a", "x:=y"], env)
    assert isinstance(launch, Launch)
    script = str(workspace / "lab2" / "scripts" / "pub.py")
    assert launch.argv == [sys.executable, "-m", "rosx_commands", "run-script", script, "a", "x:=y"]
    shims = launch.environ["PYTHONPATH"].split(os.pathsep)[:2]
    assert shims == [str(SHIM_DIR), str(BAG_SHIM_DIR)]
    prefixed = plan(["--prefix", "nice -n 5", "lab2", "scripts/pub.py"], env)
    assert isinstance(prefixed, Launch) and prefixed.argv[:3] == ["nice", "-n", "5"]


def test_rosrun_runs_the_script(workspace: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "rosrun", "lab2", "pub.py", "a", "x:=y"],
        env=env_of(workspace),
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout == f"['{workspace}/lab2/scripts/pub.py', 'a']\n"


def test_turtlesims_programs_are_rosxs_own(workspace: Path) -> None:
    what = plan(["turtlesim", "turtlesim_node"], Environment(environ=env_of(workspace)))
    assert callable(what) and not isinstance(what, (int, Launch))


def test_roscd_where_and_its_errors(workspace: Path, tmp_path: Path) -> None:
    env = env_of(workspace)
    assert rosx("roscd", "--where", "lab2/scripts", environ=env).out == (
        f"{workspace}/lab2/scripts\n"
    )
    missing = rosx("roscd", "--where", "nopkg", environ=env)
    assert (missing.status, missing.err) == (1, "roscd: No such package/stack 'nopkg'\n")
    alone = rosx("roscd", "--where", environ=env)
    assert alone.status == 1 and "Neither ROS_WORKSPACE is set" in alone.err
    home = rosx("roscd", "--where", environ={**env, "ROS_WORKSPACE": str(tmp_path)})
    assert home.out == f"{tmp_path}\n"
    bare = rosx("roscd", "lab2", environ=env)
    assert bare.status == 1 and 'eval "$(rosx shell-init bash)"' in bare.err
    assert rosx("rosls", "lab2", environ=env).out == "package.xml\nscripts\n"


@pytest.mark.parametrize("shell", ["bash", "zsh"])
def test_shell_init_defines_the_ros_commands(workspace: Path, shell: str, tmp_path: Path) -> None:
    if shutil.which(shell) is None:
        pytest.skip(f"{shell} is not installed")
    script = (
        f'eval "$({sys.executable} -m rosx_commands shell-init {shell})"\n'
        "roscd lab2 && pwd\n"
        "rosx roscd lab2/scripts && pwd\n"
        "rospack find lab2\n"
        "rosrun lab2 nothing.py; echo status=$?\n"
    )
    done = subprocess.run(
        [shell, "-c", script],
        env={**env_of(workspace), "XDG_CACHE_HOME": str(tmp_path / "cache")},
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.stdout.splitlines() == [
        f"{workspace}/lab2",
        f"{workspace}/lab2/scripts",
        f"{workspace}/lab2",
        f"[rosrun] Couldn't find executable named nothing.py below {workspace}/lab2",
        "status=3",
    ], done.stderr


def test_shell_init_refuses_unknown_shells() -> None:
    result = rosx("shell-init", "fish")
    assert result.status == 2 and "unknown shell 'fish'" in result.err


def test_rosrun_turtlesim_node_typo_suggests_turtlesim_node_on_a_terminal() -> None:
    out, err = io.StringIO(), TerminalText()
    env = Environment(stdout=out, stderr=err, environ=clean_environ())
    assert plan(["turtlesim", "turtlesim", "node"], env) == 3
    assert out.getvalue().startswith("[rosrun] Couldn't find executable named turtlesim below ")
    assert err.getvalue() == (
        "[rosrun] Did you mean turtlesim_node? (rosrun turtlesim turtlesim_node)\n"
    )


def test_rosrun_suggests_a_close_name_and_stays_ros1s_off_a_terminal(workspace: Path) -> None:
    out, err = io.StringIO(), TerminalText()
    env = Environment(stdout=out, stderr=err, environ=env_of(workspace))
    assert plan(["lab2", "pubb.py", "x"], env) == 3
    assert err.getvalue() == "[rosrun] Did you mean pub.py? (rosrun lab2 pub.py x)\n"
    result = rosx("rosrun", "turtlesim", "turtlesim", "node", environ=env_of(workspace))
    assert (result.status, result.err) == (3, "")
    assert result.out.startswith("[rosrun] Couldn't find executable named turtlesim below ")
