"""tf's tools: ROS 1's usage texts and exit codes, tf_echo's text, view_frames' files.

The usage texts are compared with Debian's programs where they print them without a master
(tf_echo, tf's static_transform_publisher). tf_echo's numbers are checked against the lines
ROS 1's tf_echo prints for the same transforms (the interop tests compare whole runs).
"""

from __future__ import annotations

import io
import math
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from rosx.core import Core
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from rosx_commands.tf_tools.echo import USAGE, failure_text, transform_text
from rosx_commands.tf_tools.frames import NO_GRAPHVIZ, render, tf2_dot, tree_text
from rosx_commands.tf_tools.static import TF2_USAGE, TF_USAGE, tf_static_transform_publisher
from rosx_turtle.roscpp import atof
from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for
from tests.support.ros1 import needs_ros1, ros1_environ


def _run(tool: Callable[[list[str], Environment], int], *argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    status = tool(list(argv), Environment(stdout=out, stderr=err, environ=clean_environ()))
    return status, out.getvalue(), err.getvalue()


def _tool(name: str) -> Callable[[list[str], Environment], int]:
    return lambda argv, env: run_tool([name, *argv], env)


@pytest.mark.parametrize("argv", [[], ["a"], ["a", "b", "1", "x"]])
def test_tf_echo_with_a_wrong_command_line_prints_its_usage(argv: list[str]) -> None:
    assert _run(_tool("tf_echo"), *argv) == (255, USAGE, "")


def test_tf_echo_refuses_a_rate_of_zero() -> None:
    assert _run(_tool("tf_echo"), "a", "b", "0") == (255, "", "Echo rate must be > 0.0\n")
    assert _run(_tool("tf_echo"), "a", "b", "fast") == (255, "", "Echo rate must be > 0.0\n")


@needs_ros1
def test_the_usage_texts_are_debians() -> None:
    done = subprocess.run(
        ["/usr/lib/tf/tf_echo"], env=ros1_environ(), capture_output=True, text=True, check=False
    )
    assert (done.returncode, done.stdout) == (255, USAGE)
    done = subprocess.run(
        ["/usr/lib/tf/static_transform_publisher", "1"],
        env=ros1_environ(),
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stdout) == (255, TF_USAGE)
    assert done.stderr.endswith(
        "static_transform_publisher exited due to not having the right number of arguments\x1b[0m\n"
    )


@pytest.mark.parametrize("count", [0, 2, 10])
def test_static_transform_publisher_with_a_wrong_command_line(count: int) -> None:
    status, out, err = _run(_tool("static_transform_publisher"), *["0"] * count)
    assert (status, out) == (255, TF2_USAGE)
    assert err.startswith("[ERROR] [")
    assert err.endswith(
        "]: static_transform_publisher exited due to not having the right number of arguments\n"
    )


@pytest.mark.parametrize("count", [0, 8, 11])
def test_tfs_static_transform_publisher_with_a_wrong_command_line(count: int) -> None:
    status, out, _ = _run(tf_static_transform_publisher, *["0"] * count)
    assert (status, out) == (255, TF_USAGE)


def test_static_transform_publisher_refuses_one_frame_twice() -> None:
    status, out, err = _run(
        _tool("static_transform_publisher"), *["0", "0", "0", "0", "0", "0", "a", "a"]
    )
    assert (status, out) == (1, "")
    assert err.endswith("]: target_frame and source frame are the same (a, a) this cannot work\n")


def test_atof_reads_as_c_does() -> None:
    assert [atof(t) for t in ("1.5", "-2e1x", ".5", "abc", "", " 3")] == [1.5, -20, 0.5, 0, 0, 3]


def test_tf_echo_text_is_tf_echos() -> None:
    """The lines ROS 1's tf_echo printed for these transforms (Debian, tf 1.13.2)."""
    from rosx.tf.linear import from_rpy

    quarter = math.sqrt(0.5)
    # static_transform_publisher 1 2 3 0.1 0.2 0.3 world base, then tf_echo world laser (0.5 up)
    rotation = from_rpy(0.3, 0.2, 0.1)
    assert transform_text(0, (1.109, 1.862, 3.468, *rotation), 3) == (
        "At time 0.000\n"
        "- Translation: [1.109, 1.862, 3.468]\n"
        "- Rotation: in Quaternion [0.144, 0.106, 0.034, 0.983]\n"
        "            in RPY (radian) [0.300, 0.200, 0.100]\n"
        "            in RPY (degree) [17.189, 11.459, 5.730]\n"
    )
    # Pitch 90 degrees: tf's getRPY reads the locked roll from the first row.
    assert transform_text(1_500_000_000, (0, 0, 0, 0, quarter, 0, quarter), 3) == (
        "At time 1.500\n"
        "- Translation: [0.000, 0.000, 0.000]\n"
        "- Rotation: in Quaternion [0.000, 0.707, 0.000, 0.707]\n"
        "            in RPY (radian) [0.000, 1.571, 0.000]\n"
        "            in RPY (degree) [0.000, 90.000, 0.000]\n"
    )
    # static_transform_publisher -0 0 0 0 0 1 0 a b; tf_echo a b _precision:=2 (ROS 1's lines)
    from rosx.tf.core import BufferCore

    core = BufferCore()
    core.set("a", "b", 0, (-0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0), is_static=True)
    assert transform_text(*core.lookup("a", "b", 0), 2) == (
        "At time 0.00\n"
        "- Translation: [0.00, 0.00, 0.00]\n"
        "- Rotation: in Quaternion [0.00, 0.00, 1.00, 0.00]\n"
        "            in RPY (radian) [0.00, -0.00, 3.14]\n"
        "            in RPY (degree) [0.00, -0.00, 180.00]\n"
    )


def test_tf_echos_failure_lists_the_frames() -> None:
    from rosx.tf import LookupException

    error = LookupException('"b" passed to lookupTransform argument source_frame does not exist. ')
    assert failure_text(error, "Frame x exists with parent a.\n", 12_000_000_345) == (
        "Failure at 12.000000345\n"
        'Exception thrown:"b" passed to lookupTransform argument source_frame does not exist. \n'
        "The current list of frames is:\n"
        "Frame x exists with parent a.\n\n"
    )


def test_tf2_tools_dot_is_view_frames_pys() -> None:
    frames = {
        "base": {"parent": "world", "broadcaster": "/a", "rate": 10000.0, "buffer_length": 0.0,
                 "most_recent_transform": 0.0, "oldest_transform": 0.0},
        "laser": {"parent": "base", "broadcaster": "/b", "rate": 62.5, "buffer_length": 4.98,
                  "most_recent_transform": 100.5, "oldest_transform": 95.52},
    }  # fmt: skip
    assert tf2_dot(frames, 101.25) == (
        "digraph G {\n"
        '"world" -> "base"[label=" Broadcaster: /a\\nAverage rate: 10000.0\\nBuffer length: 0.0'
        '\\nMost recent transform: 0.0\\nOldest transform: 0.0\\n"];\n'
        '"base" -> "laser"[label=" Broadcaster: /b\\nAverage rate: 62.5\\nBuffer length: 4.98'
        '\\nMost recent transform: 100.5\\nOldest transform: 95.52\\n"];\n'
        "edge [style=invis];\n"
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        '"Recorded at time: 101.25"[ shape=plaintext ] ;\n'
        '}->"world";\n}'
    )
    assert tf2_dot({}, 1.0) == 'digraph G { "No tf data received" }'


def test_without_graphviz_view_frames_prints_the_tree(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("shutil.which", lambda name: None)
    out = io.StringIO()
    parents = {"base": "world", "laser": "base", "cam": "base", "t1": "world"}
    assert not render("digraph G {}", parents, out, tmp_path)
    assert (tmp_path / "frames.gv").read_text() == "digraph G {}"
    assert out.getvalue() == NO_GRAPHVIZ + tree_text(parents)
    assert tree_text(parents) == "world\n├── base\n│   ├── laser\n│   └── cam\n└── t1\n"


@pytest.fixture
def core() -> Iterator[dict[str, str]]:
    with Core(0, {"ROS_IP": "127.0.0.1"}) as running_core:
        yield {**clean_environ(), "ROS_MASTER_URI": running_core.uri}


def test_view_frames_py_asks_its_own_buffer(core: dict[str, str], tmp_path: Path) -> None:
    """tf2_tools' view_frames.py: 5 s of listening, its ~tf2_frames answer, frames.gv."""
    rosx = [sys.executable, "-m", "rosx_commands"]
    publisher = [
        *rosx,
        "static_transform_publisher",
        *["1", "0", "0", "0", "0", "0", "map", "odom"],
    ]
    with running(publisher, core):
        done = subprocess.run(
            [*rosx, "rosrun", "tf2_tools", "view_frames.py"],
            env=core, cwd=tmp_path, capture_output=True, text=True, timeout=60, check=False,
        )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].endswith("]: Listening to tf data during 5 seconds...")
    assert lines[1].endswith("]: Generating graph in frames.pdf file...")
    dot = (tmp_path / "frames.gv").read_text()
    assert dot.startswith('digraph G {\n"map" -> "odom"[label=" Broadcaster: /static_transform')
    assert "\\nAverage rate: 10000.0\\nBuffer length: 0.0\\n" in dot
    assert dot.endswith('"[ shape=plaintext ] ;\n}->"map";\n}')
    wait_for(lambda: (tmp_path / "frames.pdf").exists() or "the tree" in done.stdout)
