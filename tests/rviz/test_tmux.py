"""rosx rviz in real terminals of 80x24 and 120x40 (tmux) beside the robot simulator
(``turtlebot3_map.launch``) and the tf demo (``turtle_tf2_demo.launch``), each launched as a
user launches it: the map, the laser and the frames show, the footer names the tools, a goal is
placed, and q and Ctrl-C quit. Skipped where tmux is not installed."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.master.client import MasterClient
from rosx.packages.crawl import PREFIX
from tests.support.cli import ROSX_COMMAND, clean_environ
from tests.support.procs import free_port, running, wait_for
from tests.support.tmux import Tmux, needs_tmux

SIZES = [(80, 24), (120, 40)]
STARTUP = 60.0
CONFIG = PREFIX / "share" / "turtlebot3_stage" / "rviz" / "turtlebot3_stage.rviz"
#: The map's free space at rviz's 0.7 alpha over its background: 0.7 * 255 + 0.3 * 48.
FREE = "193;193;193"
LASER = "255;0;0"


def launched(*argv: str) -> Iterator[str]:
    """``rosx roslaunch ARGV…`` on a master of its own (it starts the core); its URI once
    ``/tf`` is published."""
    needs_tmux()
    uri = f"http://127.0.0.1:{free_port()}/"
    environ = clean_environ(ROS_MASTER_URI=uri)
    command = [*ROSX_COMMAND, "roslaunch"]
    with running([*command, *argv], environ):
        master = MasterClient(uri, "/rviz_test")

        def publishing() -> bool:
            try:
                return "/tf" in master.topic_types()
            except Exception:
                return False

        wait_for(publishing, STARTUP, "the launch's /tf")
        yield uri


@pytest.fixture(scope="module")
def robot() -> Iterator[str]:
    yield from launched("turtlebot3_stage", "turtlebot3_map.launch")


@pytest.fixture(scope="module")
def turtles() -> Iterator[str]:
    yield from launched("turtle_tf2", "turtle_tf2_demo.launch")


def words(rows: list[str]) -> str:
    return " ".join(" ".join(rows).split())


def colours(term: Tmux) -> set[str | None]:
    """Every foreground and background colour on the screen."""
    return {colour for row in term.cells() for cell in row for colour in (cell.fg, cell.bg)}


@pytest.mark.parametrize("size", SIZES)
def test_rviz_beside_the_robot_simulator(tmp_path: Path, size: tuple[int, int], robot: str) -> None:
    columns, _ = size
    argv = ["rviz", "-d", str(CONFIG)]
    with Tmux(tmp_path, size, argv, ROS_MASTER_URI=robot, HOME=str(tmp_path)) as term:
        rows = term.wait_until(
            lambda rows: "Showing [" in words(rows) and "No messages" not in words(rows),
            "the laser and the map",
            STARTUP,
        )
        assert "Fixed Frame: map" in words(rows)
        # The map and the scan are drawn in their colours once a frame after their messages
        # is on screen: a later capture than the text's on a loaded machine.
        wait_for(
            lambda: {FREE, LASER} <= colours(term), STARTUP, "the map's free space and the laser"
        )
        footer = rows[-1].split()
        assert footer[:2] == ["q", "Quit"]
        if columns >= 120:
            assert words(rows[-1:]).startswith("q Quit g Goal p Pose c Point")
        assert all(len(line) <= columns for line in term.lines())
        term.keys("g", "Enter")
        term.wait_for("Setting goal: Frame:map, Position(")
        term.keys("q")
        assert term.ended()


@pytest.mark.parametrize("size", SIZES)
def test_rviz_beside_the_tf_demo(tmp_path: Path, size: tuple[int, int], turtles: str) -> None:
    config = tmp_path / "tf.rviz"
    config.write_text(
        "Visualization Manager:\n  Displays:\n    - {Class: rviz/TF, Name: TF}\n"
        "  Global Options:\n    Fixed Frame: world\n"
        "  Views:\n    Current: {Class: rviz/TopDownOrtho, Scale: 40, X: 5.5, Y: 5.5}\n"
    )
    argv = ["rviz", "-d", str(config)]
    with Tmux(tmp_path, size, argv, ROS_MASTER_URI=turtles, HOME=str(tmp_path)) as term:
        rows = term.wait_until(
            lambda rows: "OK (3 frames)" in words(rows), "the turtles' frames", STARTUP
        )
        assert "turtle1" in words(rows) and "turtle2" in words(rows)
        assert all(len(line) <= size[0] for line in term.lines())
        term.keys("C-c")
        assert term.ended()
        assert not any("Traceback" in line for line in term.lines())
