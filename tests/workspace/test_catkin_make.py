"""``rosx catkin_make``: layout checks, manifests and types checked, ``devel/`` written."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from rosx.workspace.environment import SHARE
from tests.support.cli import Result, clean_environ, rosx
from tests.support.packages import MANIFEST, package


def catkin_make(where: Path, monkeypatch: pytest.MonkeyPatch, *argv: str) -> Result:
    monkeypatch.chdir(where)
    return rosx("catkin_make", *argv, environ=clean_environ(PWD=str(where)))


def test_a_workspace_builds_in_topological_order(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    src = tmp_path / "src"
    package(src, "zeta")
    package(src, "alpha", "zeta", "std_msgs")
    result = catkin_make(tmp_path, monkeypatch)
    assert (result.status, result.err) == (0, "")
    assert result.out == (
        f"Base path: {tmp_path}\n"
        f"Source space: {src}\n"
        f"Build space: {tmp_path}/build\n"
        f"Devel space: {tmp_path}/devel\n"
        f"Install space: {tmp_path}/install\n"
        f"-- Using CATKIN_DEVEL_PREFIX: {tmp_path}/devel\n"
        "-- ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~\n"
        "-- ~~  traversing 2 packages in topological order:\n"
        "-- ~~  - zeta\n"
        "-- ~~  - alpha\n"
        "-- ~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~\n"
        "-- +++ processing catkin package: 'zeta'\n"
        "-- ==> add_subdirectory(zeta)\n"
        "-- +++ processing catkin package: 'alpha'\n"
        "-- ==> add_subdirectory(alpha)\n"
        "-- Configuring done\n"
        "-- Generating done\n"
        f"-- Build files have been written to: {tmp_path}/build\n"
    )
    devel = tmp_path / "devel"
    assert (devel / ".catkin").read_text() == str(src)
    assert {"setup.sh", "setup.bash", "setup.zsh"} <= {p.name for p in devel.iterdir()}
    assert (tmp_path / "build" / "CATKIN_IGNORE").exists()


def test_message_and_service_types_are_built(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    lab2 = package(tmp_path / "src", "lab2")
    (lab2 / "msg").mkdir()
    (lab2 / "msg" / "Num.msg").write_text("int64 num\nHeader header\ngeometry_msgs/Twist t\n")
    (lab2 / "srv").mkdir()
    (lab2 / "srv" / "AddTwoInts.srv").write_text("int64 a\nint64 b\n---\nint64 sum\n")
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 0, result.err
    assert "-- lab2: 1 messages, 1 services\n" in result.out
    assert result.out.endswith(
        "[ 50%] Generating Python from MSG lab2/Num\n"
        "[100%] Generating Python code from SRV lab2/AddTwoInts\n"
        "[100%] Built target lab2_generate_messages_py\n"
    )


@pytest.mark.parametrize(
    ("kind", "file", "text", "problem"),
    [
        ("msg", "Bad.msg", "int32 num\nint32 x y\n", "line 2:\nInvalid declaration: int32 x y"),
        ("msg", "Bad.msg", "int32 num\n\nFoo bar\n", "line 3:\nCannot locate message [lab2/Foo]"),
        (
            "msg",
            "Bad.msg",
            "uint8 X=300\n",
            "line 1:\ncannot coerce [300] to uint8 (out of bounds)",
        ),
        ("msg", "Bad-Name.msg", "int32 x\n", ":\n[Bad-Name] is not a legal message name"),
        ("srv", "Bad.srv", "int64 a\n---\nint64 sum extra\n", "line 3:\nInvalid declaration"),
    ],
)
def test_a_broken_type_names_its_file_and_line(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    kind: str,
    file: str,
    text: str,
    problem: str,
) -> None:
    lab2 = package(tmp_path / "src", "lab2")
    (lab2 / kind).mkdir()
    (lab2 / kind / file).write_text(text)
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 1
    what = "message" if kind == "msg" else "service"
    assert result.err.startswith(f"Error(s) in {what} file '{lab2 / kind / file}'")
    assert problem in result.err
    assert "Traceback" not in result.err
    assert not (tmp_path / "devel" / "setup.bash").exists()


def test_a_broken_manifest_is_reported_as_catkin_reports_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    lab2 = package(tmp_path / "src", "lab2")
    manifest = lab2 / "package.xml"
    manifest.write_text(manifest.read_text().replace("</name>", "</nme>"))
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 1
    assert result.out.endswith(f"Install space: {tmp_path}/install\n")
    assert result.err == (
        f"Error(s) in package '{manifest}':\n"
        "The manifest contains invalid XML:\nmismatched tag: line 3, column 14\n"
    )
    manifest.write_text(
        MANIFEST.format(name="lab2", depends="").replace("<license>TODO</license>", "")
    )
    result = catkin_make(tmp_path, monkeypatch)
    assert result.err == (
        f"Error(s) in package '{manifest}':\n"
        'The package node must contain at least one "license" tag\n'
    )


def test_two_packages_with_one_name_are_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    package(tmp_path / "src" / "a", "same")
    package(tmp_path / "src" / "b", "same")
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 1
    assert result.err == (
        'Multiple packages found with the same name "same":\n'
        f"- {tmp_path}/src/a/same\n- {tmp_path}/src/b/same\n"
    )


def test_catkin_make_must_run_at_the_workspace_root(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    lab2 = package(tmp_path / "src", "lab2")
    result = catkin_make(tmp_path / "src", monkeypatch)
    assert (result.status, result.out) == (1, f"Base path: {tmp_path}/src\n")
    assert result.err == f'The specified source space "{tmp_path}/src/src" does not exist\n'
    result = catkin_make(lab2, monkeypatch)
    assert result.err == (
        f'The specified base path "{lab2}" contains a package but "catkin_make" must be '
        "invoked in the root of workspace\n"
    )


def test_make_and_cmake_arguments_are_accepted(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    package(tmp_path / "src", "lab2")
    result = catkin_make(tmp_path, monkeypatch, "-j4", "-DCMAKE_BUILD_TYPE=Release", "install")
    assert result.status == 0, result.err


def test_sourcing_devel_setup_lets_python_import_the_workspace(tmp_path: Path) -> None:
    lab2 = package(tmp_path / "ws" / "src", "lab2", "std_msgs")
    (lab2 / "msg").mkdir()
    (lab2 / "msg" / "Num.msg").write_text("int64 num\n")
    env = clean_environ(HOME=str(tmp_path))
    build = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "catkin_make"],
        cwd=tmp_path / "ws",
        env={**env, "PWD": str(tmp_path / "ws")},
        capture_output=True,
        text=True,
        check=False,
    )
    assert build.returncode == 0, build.stderr
    script = (
        "import json, rospy\nfrom lab2.msg import Num\nfrom std_msgs.msg import String\n"
        "print(json.dumps([Num._type, String._type]))\n"
    )
    done = subprocess.run(
        [
            "bash",
            "-c",
            'source ws/devel/setup.bash && source ws/devel/setup.bash && echo "$ROS_PACKAGE_PATH"'
            ' && "$0" -c "$1" && roscd lab2 && pwd && roscd && pwd',
            sys.executable,
            script,
        ],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    path, types, package_dir, devel = done.stdout.splitlines()
    # once, however often it is sourced; then the packages rosx ships, as /opt/ros/noetic/share
    assert path == f"{tmp_path / 'ws' / 'src'}:{SHARE}"
    assert json.loads(types) == ["lab2/Num", "std_msgs/String"]
    assert (package_dir, devel) == (str(lab2), str(tmp_path / "ws" / "devel"))


def test_only_pkg_with_deps_builds_a_package_and_what_it_needs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    src = tmp_path / "src"
    package(src, "base")
    package(src, "user", "base")
    package(src, "other")
    result = catkin_make(tmp_path, monkeypatch, "--only-pkg-with-deps", "user")
    assert result.status == 0, result.err
    assert "Whitelisted packages: base, user\n" in result.out
    assert "traversing 2 packages" in result.out and "'other'" not in result.out
    missing = catkin_make(tmp_path, monkeypatch, "--only-pkg-with-deps", "nope")
    assert (missing.status, missing.err) == (1, 'Packages "nope" not found in the workspace\n')
