"""``rosx catkin_create_pkg``: the files, the output and the errors of catkin_pkg's tool."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.cli import clean_environ, rosx

REFERENCE = shutil.which("catkin_create_pkg", path="/usr/bin")
needs_catkin_pkg = pytest.mark.skipif(REFERENCE is None, reason="catkin_pkg is not installed")

LAB2_DEPENDS = """\
  <buildtool_depend>catkin</buildtool_depend>
  <build_depend>roscpp</build_depend>
  <build_depend>rospy</build_depend>
  <build_depend>std_msgs</build_depend>
  <build_export_depend>roscpp</build_export_depend>
  <build_export_depend>rospy</build_export_depend>
  <build_export_depend>std_msgs</build_export_depend>
  <exec_depend>roscpp</exec_depend>
  <exec_depend>rospy</exec_depend>
  <exec_depend>std_msgs</exec_depend>
"""


def create(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *argv: str) -> tuple[int, str, str]:
    monkeypatch.chdir(tmp_path)
    result = rosx(
        "catkin_create_pkg", *argv, environ=clean_environ(PWD=str(tmp_path), USER="student")
    )
    return result.status, result.out, result.err


def test_the_lab_sheets_package(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    status, out, err = create(tmp_path, monkeypatch, "lab2", "std_msgs", "rospy", "roscpp")
    assert (status, err) == (0, "")
    assert out == (
        "Created file lab2/package.xml\n"
        "Created file lab2/CMakeLists.txt\n"
        "Created folder lab2/include/lab2\n"
        "Created folder lab2/src\n"
        f"Successfully created files in {tmp_path}/lab2. Please adjust the values in package.xml.\n"
    )
    manifest = (tmp_path / "lab2" / "package.xml").read_text()
    assert manifest.startswith('<?xml version="1.0"?>\n<package format="2">\n  <name>lab2</name>\n')
    assert '  <maintainer email="student@todo.todo">student</maintainer>\n' in manifest
    assert "  <license>TODO</license>\n" in manifest
    assert LAB2_DEPENDS in manifest
    cmake = (tmp_path / "lab2" / "CMakeLists.txt").read_text()
    assert "project(lab2)\n" in cmake
    assert "find_package(catkin REQUIRED COMPONENTS\n  roscpp\n  rospy\n  std_msgs\n)\n" in cmake
    assert (tmp_path / "lab2" / "include" / "lab2").is_dir()


def test_an_existing_package_is_not_overwritten(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    create(tmp_path, monkeypatch, "lab2", "rospy")
    before = (tmp_path / "lab2" / "package.xml").read_text()
    status, out, err = create(tmp_path, monkeypatch, "lab2", "roscpp")
    assert (status, out) == (2, "")
    assert err.startswith("usage: catkin_create_pkg [-h] [--meta]")
    assert err.endswith(f"catkin_create_pkg: error: File exists: {tmp_path}/lab2/package.xml\n")
    assert (tmp_path / "lab2" / "package.xml").read_text() == before


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        ((), "the following arguments are required: name, dependencies"),
        (("x", "-V", "1.2"), 'Package version "1.2" does not follow version conventions'),
        (("x", "-m", "x!"), 'Invalid email "x!@todo.todo" for person "x!"'),
        (("bad name",), 'Package name "bad name" does not follow naming conventions'),
    ],
)
def test_invalid_requests_are_usage_errors(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, argv: tuple[str, ...], message: str
) -> None:
    status, out, err = create(tmp_path, monkeypatch, *argv)
    assert (status, out) == (2, "")
    assert err.endswith(f"catkin_create_pkg: error: {message}\n")
    assert "Traceback" not in err


def test_unconventional_names_are_warned_about(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    status, _, err = create(tmp_path, monkeypatch, "Lab2")
    assert status == 0
    assert err == (
        'WARNING: Package name "Lab2" does not follow the naming conventions. It should start '
        "with a lower case letter and only contain lower case letters, digits, underscores, "
        "and dashes.\n"
    )


@needs_catkin_pkg
@pytest.mark.parametrize(
    "argv",
    [
        ["lab2", "std_msgs", "rospy", "roscpp"],
        ["meta", "--meta"],
        ["gen", "genmsg", "sensor_msgs"],
        ["msgs", "message_runtime"],
        ["full", "rospy", "message_generation", "-s", "python-yaml", "eigen", "-b", "thread"],
        ["described", "-V", "1.2.3", "-D", "What it does", "-l", "MIT", "-l", "BSD"],
        ["people", "-a", "Ada Lovelace", "-a", "Alan Turing", "-m", "Jo Do", "-m", "Al Ex"],
        ["Caps"],
        ["-h"],
        ["x", "--bogus"],
    ],
)
def test_same_files_and_output_as_catkin_pkg(tmp_path: Path, argv: list[str]) -> None:
    ours, theirs = tmp_path / "rosx", tmp_path / "ros1"
    results = []
    for place, command in (
        (ours, [sys.executable, "-m", "rosx_commands", "catkin_create_pkg"]),
        (theirs, [str(REFERENCE)]),
    ):
        place.mkdir()
        env = clean_environ(PWD=str(place), USER="student", COLUMNS="80")
        env.pop("ROS_DISTRO", None)
        done = subprocess.run(
            [*command, *argv], cwd=place, env=env, capture_output=True, text=True, check=False
        )
        results.append(
            (done.returncode, done.stdout.replace(str(place), "DIR"), done.stderr, _files(place))
        )
    assert results[0] == results[1]


def _files(root: Path) -> dict[str, str]:
    return {
        str(p.relative_to(root)): p.read_text() if p.is_file() else "<dir>"
        for p in sorted(root.rglob("*"))
    }
