"""Noetic's environment from ``rosx shell-init`` and setup files; ``catkin_make install``; the
one-line notice about C++ targets."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rosx.workspace.environment import ROS_ETC_DIR, ROS_ROOT, SHARE
from tests.support.cli import clean_environ, rosx
from tests.support.packages import package

ROSX = f"{sys.executable} -m rosx_commands"


def shell(name: str, script: str, cwd: Path, **extra: str) -> subprocess.CompletedProcess[str]:
    if shutil.which(name) is None:
        pytest.skip(f"{name} is not installed")
    env = clean_environ(HOME=str(cwd), **extra)
    env.pop("CMAKE_PREFIX_PATH", None)
    env.pop("ROSLISP_PACKAGE_DIRECTORIES", None)
    env.pop("XDG_CACHE_HOME", None)  # shell-init writes to HOME's cache folder, in tmp
    for key in [k for k in env if k.startswith("ROS1_")]:  # the test run's ROS 1 reference
        env.pop(key)
    return subprocess.run(
        [name, "-c", script],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def _set_by(name: str, script: str, cwd: Path, **extra: str) -> list[str]:
    """``NAME=value`` of each variable named ``ROS…`` that ``script`` sets or changes in shell
    ``name``: what was there before (a user's own ``ROSCONSOLE_FORMAT``, the test run's
    ``ROSX_…``) is not the script's doing."""
    done = shell(name, f"env -0\nprintf '\\0'\n{script}\nenv -0", cwd, **extra)
    assert done.returncode == 0, done.stderr
    before, after = (
        dict(entry.split("=", 1) for entry in part.split("\0") if entry)
        for part in done.stdout.split("\0\0", 1)
    )
    return sorted(
        f"{key}={value}"
        for key, value in after.items()
        if key.startswith("ROS") and before.get(key) != value
    )


@pytest.mark.parametrize("name", ["bash", "zsh"])
def test_shell_init_exports_what_noetic_exports(tmp_path: Path, name: str) -> None:
    exported = _set_by(
        name,
        f'eval "$({ROSX} shell-init {name})"',
        tmp_path,
        ROSCONSOLE_FORMAT="[${severity}] ${message}",  # set by the user: not shell-init's
    )
    assert exported == [
        "ROSLISP_PACKAGE_DIRECTORIES=",
        "ROS_DISTRO=noetic",
        f"ROS_ETC_DIR={ROS_ETC_DIR}",
        "ROS_MASTER_URI=http://localhost:11311",
        f"ROS_PACKAGE_PATH={SHARE}",
        "ROS_PYTHON_VERSION=3",
        f"ROS_ROOT={ROS_ROOT}",
        "ROS_VERSION=1",
    ]
    assert ROS_ROOT.is_dir() and ROS_ROOT.name == "ros" and ROS_ETC_DIR.is_dir()


def test_a_set_master_uri_is_kept_and_a_mixed_distro_is_named(tmp_path: Path) -> None:
    done = shell(
        "bash",
        f'eval "$({ROSX} shell-init bash)"\necho "$ROS_MASTER_URI $ROS_DISTRO"',
        tmp_path,
        ROS_MASTER_URI="http://127.0.0.1:1234",
        ROS_DISTRO="melodic",
    )
    assert done.stdout.splitlines() == [
        "ROS_DISTRO was set to 'melodic' before. Please make sure that the environment does "
        "not mix paths from different distributions.",
        "http://127.0.0.1:1234 noetic",
    ]


def _workspace(tmp_path: Path) -> Path:
    src = tmp_path / "catkin_ws" / "src"
    pkg = package(src, "beginner_tutorials", "rospy", "std_msgs")
    (pkg / "msg").mkdir()
    (pkg / "msg" / "Num.msg").write_text("int64 num\n")
    (pkg / "scripts").mkdir()
    talker = pkg / "scripts" / "talker.py"
    talker.write_text("#!/usr/bin/env python\nprint('installed talker')\n")
    talker.chmod(0o755)
    (pkg / "launch").mkdir()
    (pkg / "launch" / "demo.launch").write_text("<launch/>\n")
    (pkg / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.0.2)\nproject(beginner_tutorials)\n"
        "# add_executable(commented src/commented.cpp)\n"
        "catkin_install_python(PROGRAMS scripts/talker.py\n"
        "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}\n)\n"
        "install(DIRECTORY launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})\n"
        "add_executable(talker src/talker.cpp)\nadd_executable(listener src/listener.cpp)\n"
    )
    return tmp_path / "catkin_ws"


def test_catkin_make_install_writes_an_install_space_used_like_devel(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    build = shell("bash", f"cd {ws} && {ROSX} catkin_make install", tmp_path)
    assert build.returncode == 0, build.stderr
    install = ws / "install"
    lines = build.stdout.splitlines()
    assert lines[lines.index("Install the project...") :] == [
        "Install the project...",
        f"-- Installing: {install}/setup.sh",
        f"-- Installing: {install}/setup.bash",
        f"-- Installing: {install}/setup.zsh",
        f"-- Installing: {install}/share/beginner_tutorials/package.xml",
        f"-- Installing: {install}/share/beginner_tutorials/msg/Num.msg",
        f"-- Installing: {install}/lib/beginner_tutorials/talker.py",
        f"-- Installing: {install}/share/beginner_tutorials/launch/demo.launch",
    ]
    assert (install / ".catkin").read_text() == ""
    used = shell(
        "bash",
        "source catkin_ws/install/setup.bash\n"
        'echo "$ROS_PACKAGE_PATH"\n'
        'rospack() { rosx rospack "$@"; }\n'
        "rospack find beginner_tutorials\n"
        "rosx rosrun beginner_tutorials talker.py\n"
        "roscd beginner_tutorials/launch && pwd\n"
        "rosx rosmsg show beginner_tutorials/Num\n",
        tmp_path,
    )
    assert used.stdout.splitlines() == [
        f"{install}/share:{SHARE}",
        f"{install}/share/beginner_tutorials",
        "installed talker",
        f"{install}/share/beginner_tutorials/launch",
        "int64 num",
        "",
    ], used.stderr


def test_cpp_targets_are_named_once_as_not_built(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    build = shell("bash", f"cd {ws} && {ROSX} catkin_make", tmp_path)
    notices = [line for line in build.stdout.splitlines() if "C++" in line]
    assert notices == [
        "-- rosx compiles no C++: these C++ targets are not built (rosx runs Python nodes "
        "only): beginner_tutorials (talker, listener)"
    ]
    assert build.returncode == 0


def test_devel_setup_exports_noetic_with_the_workspace_first(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    done = shell(
        "bash",
        f"cd {ws} && {ROSX} catkin_make >/dev/null && cd .. && source catkin_ws/devel/setup.bash"
        " && printenv | grep -E '^ROS(LISP)?_' | sort",
        tmp_path,
    )
    assert done.stdout.splitlines() == [
        f"ROSLISP_PACKAGE_DIRECTORIES={ws}/devel/share/common-lisp",
        "ROS_DISTRO=noetic",
        f"ROS_ETC_DIR={ROS_ETC_DIR}",
        "ROS_MASTER_URI=http://localhost:11311",
        f"ROS_PACKAGE_PATH={ws}/src:{SHARE}",
        "ROS_PYTHON_VERSION=3",
        f"ROS_ROOT={ROS_ROOT}",
        "ROS_VERSION=1",
    ], done.stderr


def test_install_rules_that_rosx_cannot_evaluate_are_skipped(tmp_path: Path) -> None:
    from rosx.workspace.cmake import InstallRule, install_rules

    cmake = tmp_path / "CMakeLists.txt"
    cmake.write_text(
        'install(FILES "a file.txt" b.yaml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/cfg)\n'
        "install(PROGRAMS ${MY_SCRIPTS} DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n"
        "install(FILES x DESTINATION ${UNKNOWN})  # not evaluated\n"
    )
    assert install_rules("pkg", cmake) == [
        InstallRule("FILES", ("a file.txt", "b.yaml"), "share/pkg/cfg")
    ]
    assert rosx("catkin_make", "--help").status == 0


def test_rosrun_of_a_cpp_target_says_it_was_not_built(tmp_path: Path) -> None:
    ws = _workspace(tmp_path)
    env = clean_environ(ROS_PACKAGE_PATH=str(ws / "src"))
    result = rosx("rosrun", "beginner_tutorials", "listener", environ=env)
    assert result.status == 3
    assert result.out.startswith(
        f"[rosrun] Couldn't find executable named listener below {ws}/src/beginner_tutorials\n"
    )
    assert result.err == (
        "[rosx] listener is a C++ target of the package's CMakeLists.txt; rosx compiles no C++, "
        "so it was not built (write the node in Python to run it with rosx)\n"
    )
