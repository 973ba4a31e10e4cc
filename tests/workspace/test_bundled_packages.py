"""The ROS packages shipped with rosx: Noetic's core, the standard messages, the tutorials'.

``rospack``, ``roscd`` and ``rosls`` find them as on Noetic (ROS/Tutorials/NavigatingTheFilesystem,
CreatingPackage), and their dependencies are Noetic's: compared with Debian's rospack run over
rosx's own package folders where the reference is installed.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from rosx.packages.crawl import PREFIX, bundled_packages
from rosx.packages.manifest import check_manifest, read_manifest
from tests.support.cli import clean_environ, rosx
from tests.support.workspace_text import TUTORIAL_DEPENDS

SHARE = PREFIX / "share"
DEBIAN_ROSPACK = shutil.which("rospack", path="/usr/bin")
needs_rospack = pytest.mark.skipif(DEBIAN_ROSPACK is None, reason="Debian's rospack is absent")

#: The packages of ROS/Tutorials that must exist (issue 15).
CORE = [
    "roscpp", "rospy", "roslib", "rosgraph", "genpy", "std_msgs", "geometry_msgs", "sensor_msgs",
    "rosgraph_msgs", "std_srvs", "roscpp_tutorials", "rospy_tutorials", "turtlesim",
]  # fmt: skip


def test_every_shipped_folder_is_the_package_it_is_named_after() -> None:
    for directory in sorted(SHARE.iterdir()):
        if directory.name == "ros":  # ROS_ROOT; Noetic's ros is a metapackage (a stack)
            assert not (directory / "package.xml").exists()
            continue
        manifest = read_manifest(directory)
        assert manifest.name == directory.name
        assert check_manifest(manifest) == []


@pytest.mark.parametrize("package", CORE)
def test_the_tutorials_packages_are_found(package: str) -> None:
    found = rosx("rospack", "find", package)
    assert (found.status, found.err) == (0, "")
    assert Path(found.out.strip()) == bundled_packages()[package]
    assert rosx("roscd", "--where", package).out == found.out


#: The packages whose programs rosx runs under ``rosrun`` (``lib/<package>/``).
WITH_PROGRAMS = sorted(path.name for path in (PREFIX / "lib").iterdir())


@pytest.mark.parametrize("package", WITH_PROGRAMS)
def test_a_package_rosrun_runs_is_found_as_on_noetic(package: str) -> None:
    """``rospack find rostopic`` and ``roscd rqt_graph`` find the packages of the programs
    rosx runs, as Noetic's installed packages."""
    found = rosx("rospack", "find", package)
    assert (found.status, found.out, found.err) == (0, f"{SHARE}/{package}\n", "")
    assert rosx("roscd", "--where", package).out == found.out
    assert "package.xml" in rosx("rosls", package).out.split()
    assert f"{package} {SHARE}/{package}\n" in rosx("rospack", "list").out


def test_rospack_depends1_of_the_tools_is_noetics() -> None:
    """As Noetic's rospack prints them, less roslaunch's rosclean, rosmaster, rosout and
    rosunit: rosx does not ship them, and rospack leaves out what it cannot find."""
    expected = {
        "rostopic": "genpy\nrosbag\nrospy\n",
        "rosnode": "rosgraph\nrostopic\n",
        "rosparam": "rosgraph\n",
        "rosservice": "genpy\nrosgraph\nroslib\nrospy\nrosmsg\n",
        "rosmsg": "catkin\ngenmsg\ngenpy\nrosbag\nroslib\n",
        "roslaunch": "rosgraph_msgs\nroslib\nrosparam\n",
    }
    for package, depends1 in expected.items():
        result = rosx("rospack", "depends1", package)
        assert (result.status, result.out, result.err) == (0, depends1, ""), package


def test_every_run_dependency_of_a_shipped_package_is_shipped() -> None:
    """``rospack depends`` of each is complete: only the Noetic packages rosx has no use for are
    missing (C++ libraries, Qt, test tools, the master's and roslaunch's own packages)."""
    allowed_missing = {
        "rosbag_migration_rule", "rosbag_storage", "topic_tools",
        "rosclean", "rosmaster", "rosout", "rosunit",
        "python_qt_binding", "qt_gui", "qt_gui_py_common", "qt_dotgraph", "qwt_dependency",
        "rqt_gui_py", "rqt_py_common",
    }  # fmt: skip
    for package in bundled_packages():
        for dependency in read_manifest(bundled_packages()[package]).run_depends():
            assert dependency in bundled_packages() or dependency in allowed_missing, (
                package,
                dependency,
            )


def test_rospack_depends1_rospy_is_noetics() -> None:
    result = rosx("rospack", "depends1", "rospy")
    assert (result.status, result.err) == (0, "")
    assert result.out == "genpy\nroscpp\nrosgraph\nrosgraph_msgs\nroslib\nstd_msgs\n"


def test_rospack_of_an_unknown_package_is_rospacks_error() -> None:
    for command in ("depends1", "depends", "depends-on1"):
        result = rosx("rospack", command, "no_such_package")
        assert (result.status, result.out) == (1, "")
        assert result.err == "[rospack] Error: no such package no_such_package\n"


def _beginner_tutorials(src: Path) -> dict[str, str]:
    """``catkin_create_pkg beginner_tutorials std_msgs rospy roscpp`` in ``src``."""
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(src)
        done = rosx(
            "catkin_create_pkg", "beginner_tutorials", "std_msgs", "rospy", "roscpp",
            environ=clean_environ(PWD=str(src)),
        )  # fmt: skip
    assert done.status == 0, done.err
    return clean_environ(ROS_PACKAGE_PATH=str(src))


def test_rospack_depends_beginner_tutorials_is_the_tutorials_list(tmp_path: Path) -> None:
    env = _beginner_tutorials(tmp_path)
    assert rosx("rospack", "depends1", "beginner_tutorials", environ=env).out == (
        "roscpp\nrospy\nstd_msgs\n"
    )
    assert rosx("rospack", "depends", "beginner_tutorials", environ=env).out == (
        "\n".join(TUTORIAL_DEPENDS) + "\n"
    )


def test_rosls_shows_the_tutorial_packages_as_noetic_installs_them() -> None:
    assert rosx("rosls", "roscpp_tutorials").out == "cmake\nlaunch\npackage.xml\nsrv\n"
    assert rosx("rosls", "rospy_tutorials").out.split() == [
        "001_talker_listener", "002_headers", "003_listener_with_user_data",
        "004_listener_subscribe_notify", "005_add_two_ints", "006_parameters",
        "007_connection_header", "008_on_shutdown", "009_advanced_publish",
        "010_publish_pointcloud2", "cmake", "msg", "package.xml", "srv",
    ]  # fmt: skip
    assert rosx("rosls", "std_msgs").out == "cmake\nmsg\npackage.xml\n"
    assert rosx("rosls", "roscpp").out == "cmake\nmsg\npackage.xml\nsrv\n"
    assert rosx("rosls", "nav_msgs").out == "action\ncmake\nmsg\npackage.xml\nsrv\n"
    assert rosx("roscd", "--where", "roscpp/cmake").out == f"{SHARE}/roscpp/cmake\n"
    # Noetic's has images/ too (the turtles' pictures): rosx draws its turtles as text.
    assert rosx("rosls", "turtlesim").out == "cmake\nlaunch\nmsg\npackage.xml\nsrv\n"
    assert rosx("roscd", "--where", "turtlesim").out == f"{SHARE}/turtlesim\n"


def test_every_shipped_package_has_noetics_cmake_folder_which_says_it_builds_nothing() -> None:
    """Noetic installs ``share/<pkg>/cmake/<pkg>Config.cmake`` for every catkin package; rosx's
    stops a CMake project that finds it with one clear message (no C++ to build against)."""
    for directory in sorted(SHARE.iterdir()):
        if not (directory / "package.xml").is_file():
            continue
        config = directory / "cmake" / f"{directory.name}Config.cmake"
        assert config.is_file(), f"{directory.name}: add cmake/{config.name} (see roscpp's)"
        assert "message(FATAL_ERROR" in config.read_text(), config


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake is not installed")
def test_a_cmake_project_that_finds_a_shipped_package_stops_with_one_message(
    tmp_path: Path,
) -> None:
    (tmp_path / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.10)\nproject(lab)\nfind_package(roscpp REQUIRED)\n"
    )
    done = subprocess.run(
        ["cmake", "-S", str(tmp_path), "-B", str(tmp_path / "build")],
        env=clean_environ(CMAKE_PREFIX_PATH=str(PREFIX)), capture_output=True, text=True,
        timeout=120, check=False,
    )  # fmt: skip
    assert done.returncode == 1
    assert " ".join(done.stderr.split()).startswith(
        f"CMake Error at {SHARE}/roscpp/cmake/roscppConfig.cmake:5 (message): roscpp in "
        f"{SHARE}/roscpp/cmake is rosx's, which has no C++ headers, libraries or CMake macros "
        "to build against: use a ROS 1 installation for CMake projects"
    )


def test_rossrv_show_add_two_ints_lists_both_tutorial_types(tmp_path: Path) -> None:
    env = _beginner_tutorials(tmp_path)
    srv = tmp_path / "beginner_tutorials" / "srv"
    srv.mkdir()
    (srv / "AddTwoInts.srv").write_text("int64 a\nint64 b\n---\nint64 sum\n")
    shown = rosx("rossrv", "show", "AddTwoInts", environ=env)
    body = "int64 a\nint64 b\n---\nint64 sum\n"
    assert shown.out == (
        f"[beginner_tutorials/AddTwoInts]:\n{body}\n[rospy_tutorials/AddTwoInts]:\n{body}\n"
    )
    refused = rosx("rosmsg", "show", "AddTwoInts", environ=env)
    assert (refused.status, refused.out) == (1, "")
    assert refused.err == "Could not find msg 'AddTwoInts'\n"


# -- against Debian's rospack, over the same folders ----------------------------------------


def _debian(*argv: str, package_path: str) -> str:
    assert DEBIAN_ROSPACK is not None
    done = subprocess.run(
        [DEBIAN_ROSPACK, *argv],
        capture_output=True,
        text=True,
        env=clean_environ(ROS_PACKAGE_PATH=package_path),
        timeout=60,
        check=False,
    )
    return done.stdout


@needs_rospack
def test_dependencies_are_what_debians_rospack_computes_over_the_same_manifests(
    tmp_path: Path,
) -> None:
    """Debian's rospack always adds ``/usr/share`` (its own ROS packages): where an answer
    names one rosx does not ship (roslaunch's rosout), that one is left out, and so, for
    ``depends``, is what only it brings in."""
    _beginner_tutorials(tmp_path)
    path = f"{tmp_path}:{SHARE}"
    env = clean_environ(ROS_PACKAGE_PATH=path)
    ours_too = {*bundled_packages(), "beginner_tutorials"}
    for package in [*bundled_packages(), "beginner_tutorials"]:
        for command in ("depends1", "depends"):
            theirs = _debian(command, package, package_path=path).splitlines()
            ours = rosx("rospack", command, package, environ=env).out.splitlines()
            shared = [name for name in theirs if name in ours_too]
            if shared != theirs and command == "depends":
                shared = [name for name in shared if name in ours]
            assert ours == shared, (command, package)
        ours_on = set(rosx("rospack", "depends-on1", package, environ=env).out.split())
        theirs_on = set(_debian("depends-on1", package, package_path=path).split())
        assert ours_on <= theirs_on, package
        assert all(name not in bundled_packages() for name in theirs_on - ours_on), package
