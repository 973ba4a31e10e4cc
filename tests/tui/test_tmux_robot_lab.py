"""``rosx sim --robot`` in real terminals of 80x24 and 120x40 (tmux): the arena drawn with the
laser's hits, the live panels, the teleop pane's keys driving the robot, every line within
the terminal, and Ctrl-C quitting without a traceback. Skipped where tmux is not installed."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rosx_turtle.stage.view.picture import HIT
from tests.support.procs import free_port
from tests.support.tmux import STARTUP, Tmux, fits_and_shows_how_to_quit, quits_on_ctrl_c

SIZES = [(80, 24), (120, 40)]
HIT_COLOUR = ";".join(str(part) for part in HIT)


def read_x(rows: list[str], pattern: str) -> float | None:
    """The x ``pattern`` (a regular expression with a group) finds on a row, if one shows."""
    for row in rows:
        found = re.search(pattern, row)
        if found:
            return float(found.group(1))
    return None


def odom_x(rows: list[str]) -> float | None:
    """The x the robot panel reads on /odom."""
    return read_x(rows, r"/odom  x=(-?\d+\.\d+)")


def world_x(rows: list[str]) -> float | None:
    """The robot's x in the world, on the line under the world."""
    return read_x(rows, r"burger x=(-?\d+\.\d+)")


@pytest.mark.parametrize("size", SIZES)
def test_the_robot_lab_draws_the_arena_and_i_drives_the_robot(
    tmp_path: Path, size: tuple[int, int]
) -> None:
    columns, _ = size
    with Tmux(tmp_path, size, ["sim", "--robot", "--port", str(free_port())]) as term:
        term.wait_for("keys drive the robot", STARTUP)
        rows = term.wait_until(lambda rows: odom_x(rows) is not None, "/odom in the robot pane")
        assert odom_x(rows) == 0.0
        assert any("Teleop → /cmd_vel" in row for row in rows), rows
        term.wait_for("/scan  nearest")
        # The laser's hits on the arena's walls are drawn.
        term.wait_until(
            lambda _: any(HIT_COLOUR in (cell.fg, cell.bg) for row in term.cells() for cell in row),
            "the laser's hits",
        )
        # The graph panel (tabbed at 80x24: the topics one tab away) lists the lab's topics.
        if columns < 120:
            term.keys("Tab", "Right")
        term.wait_until(
            lambda rows: any(re.search(r"/cmd_vel +geometry_m", row) for row in rows),
            "/cmd_vel in the topics panel",
        )
        if columns < 120:
            term.keys("BTab")
        term.wait_for("keys drive the robot")
        assert world_x(term.screen()) == -2.0
        term.keys(*"iiiii")
        term.wait_until(lambda rows: (world_x(rows) or -2.0) > -1.9, "the robot moving ahead")
        fits_and_shows_how_to_quit(term, columns)
        quits_on_ctrl_c(term)


def test_a_world_that_cannot_be_read_is_named(tmp_path: Path) -> None:
    world = tmp_path / "broken.world"
    world.write_text('define plan model ( )\nplan ( bitmap "missing.png" size [ 4 4 0.5 ] )\n')
    with Tmux(
        tmp_path, (80, 24), ["sim", "--robot", str(world), "--port", str(free_port())]
    ) as term:
        assert term.ended(STARTUP)
        lines = [line for line in term.lines() if line.strip()]
        assert "missing.png" in lines[0], lines
        assert not any("Traceback" in line for line in lines), lines
