"""``rosx catkin_make`` and a package's CMakeLists.txt: ``.action`` files become seven messages
each, the files it names are the ones built, and no command is ignored silently."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from tests.support.cli import Result, clean_environ, rosx
from tests.support.packages import package
from tests.support.ros1 import ROS1_PYTHON, needs_ros1, ros1_environ

CMAKELISTS = """\
cmake_minimum_required(VERSION 3.0.2)
project(lab3)

find_package(catkin REQUIRED COMPONENTS actionlib message_generation)

## the actions
add_action_files(DIRECTORY action FILES Drive.action)
generate_messages(DEPENDENCIES std_msgs actionlib_msgs)

catkin_package(CATKIN_DEPENDS message_runtime actionlib)
include_directories(${catkin_INCLUDE_DIRS})
"""

DRIVE = "# the goal\nfloat32 distance\n---\nfloat32 travelled\n---\nfloat32 left\n"


def catkin_make(where: Path, monkeypatch: pytest.MonkeyPatch) -> Result:
    monkeypatch.chdir(where)
    return rosx("catkin_make", environ=clean_environ(PWD=str(where)))


def lab3(tmp_path: Path, cmakelists: str = CMAKELISTS) -> Path:
    directory = package(tmp_path / "src", "lab3", "actionlib", "actionlib_msgs")
    (directory / "CMakeLists.txt").write_text(cmakelists)
    (directory / "action").mkdir()
    (directory / "action" / "Drive.action").write_text(DRIVE)
    return directory


def test_an_action_is_generated_as_genaction_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    directory = lab3(tmp_path)
    result = catkin_make(tmp_path, monkeypatch)
    assert (result.status, result.err) == (0, "")
    action = directory / "action" / "Drive.action"
    assert (
        "-- +++ processing catkin package: 'lab3'\n"
        "-- ==> add_subdirectory(lab3)\n"
        f"-- Generating .msg files for action lab3/Drive {action}\n"
        "Generating for action Drive\n"
        "-- lab3: 7 messages, 0 services\n"
    ) in result.out
    assert result.out.endswith(
        "[ 14%] Generating Python from MSG lab3/DriveAction\n"
        "[ 28%] Generating Python from MSG lab3/DriveActionGoal\n"
        "[ 42%] Generating Python from MSG lab3/DriveActionResult\n"
        "[ 57%] Generating Python from MSG lab3/DriveActionFeedback\n"
        "[ 71%] Generating Python from MSG lab3/DriveGoal\n"
        "[ 85%] Generating Python from MSG lab3/DriveResult\n"
        "[100%] Generating Python from MSG lab3/DriveFeedback\n"
        "[100%] Built target lab3_generate_messages_py\n"
    )


GENACTION = Path("/usr/lib/actionlib_msgs/genaction.py")


@needs_ros1
@pytest.mark.skipif(not GENACTION.exists(), reason="Debian's actionlib_msgs is not installed")
def test_the_generated_messages_are_in_devel_share_as_genaction_writes_them(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # The actionlib tutorial checks its build with `ls devel/share/actionlib_tutorials/msg/`.
    directory = lab3(tmp_path)
    assert catkin_make(tmp_path, monkeypatch).status == 0
    theirs = tmp_path / "genaction"
    subprocess.run(
        [ROS1_PYTHON, str(GENACTION), "-o", str(theirs), str(directory / "action" / "Drive.action")],
        env=ros1_environ(), capture_output=True, timeout=60, check=True,
    )  # fmt: skip
    ours = tmp_path / "devel" / "share" / "lab3" / "msg"
    names = sorted(p.name for p in theirs.iterdir())
    assert len(names) == 7
    assert sorted(p.name for p in ours.iterdir()) == names
    for name in names:
        assert (ours / name).read_bytes() == (theirs / name).read_bytes(), name


def test_the_files_cmakelists_names_are_the_ones_built(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    directory = lab3(tmp_path)
    (directory / "action" / "Unlisted.action").write_text("int8 x\n---\n---\n")
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 0, result.err
    assert "Unlisted" not in result.out


def test_commands_rosx_does_not_carry_out_are_named_with_file_and_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    lab3(
        tmp_path,
        CMAKELISTS
        + "\n"
        + "if(CATKIN_ENABLE_TESTING)\n  add_subdirectory(test)\nendif()\n"
        + "generate_dynamic_reconfigure_options(cfg/Drive.cfg)\n"
        + "# my_macro(commented out)\n"
        + 'my_macro(lab3 "a b")\n',
    )
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 0
    assert result.err == (
        "CMake Warning at lab3/CMakeLists.txt:14 (add_subdirectory):\n"
        "  rosx reads no CMakeLists.txt but the package's own: what test/ adds is not built\n"
        "CMake Warning at lab3/CMakeLists.txt:16 (generate_dynamic_reconfigure_options):\n"
        "  rosx generates no dynamic_reconfigure config modules\n"
        "CMake Warning at lab3/CMakeLists.txt:18 (my_macro):\n"
        "  rosx does not run this command\n"
    )


def test_type_folders_elsewhere_are_not_ignored_silently(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    directory = lab3(tmp_path, CMAKELISTS.replace("DIRECTORY action", "DIRECTORY actions"))
    missing = catkin_make(tmp_path, monkeypatch)
    assert (missing.status, missing.err) == (
        1,
        "CMake Error at lab3/CMakeLists.txt:7 (add_action_files):\n"
        f"  add_action_files() directory not found: {directory / 'actions'}\n",
    )
    (directory / "actions").mkdir()
    elsewhere = catkin_make(tmp_path, monkeypatch)
    assert elsewhere.status == 0
    assert elsewhere.err == (
        "CMake Warning at lab3/CMakeLists.txt:7 (add_action_files):\n"
        "  rosx finds action files in action/ only: those in actions/ are not built\n"
    )


def test_a_named_file_that_is_missing_is_cmakes_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    directory = lab3(tmp_path, CMAKELISTS.replace("Drive.action", "Drive.action Fly.action"))
    result = catkin_make(tmp_path, monkeypatch)
    assert (result.status, result.err) == (
        1,
        "CMake Error at lab3/CMakeLists.txt:7 (add_action_files):\n"
        f"  add_action_files() file not found: {directory / 'action' / 'Fly.action'}\n",
    )
    assert not (tmp_path / "devel" / "setup.bash").exists()


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("float32 distance\n---\nfloat32 travelled\n", "wrong number of pieces, 2"),
        ("float32 distance\n---\nfloat32 x y\n---\n", "line 3:\nInvalid declaration: float32 x y"),
        ("float32 d\n---\n---\nPoint p\n", "line 4:\nCannot locate message [lab3/Point]"),
    ],
)
def test_a_broken_action_names_its_file_and_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, text: str, problem: str
) -> None:
    directory = lab3(tmp_path)
    (directory / "action" / "Drive.action").write_text(text)
    result = catkin_make(tmp_path, monkeypatch)
    assert result.status == 1
    assert result.err.startswith(f"Error(s) in action file '{directory / 'action/Drive.action'}'")
    assert problem in result.err
    assert "Traceback" not in result.err
