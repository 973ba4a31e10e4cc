"""rosx's terminal UIs in real terminals of 80x24 and 120x40 (tmux): what shows, and that q
and Ctrl-C quit. Skipped where tmux is not installed."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx_turtle.sim.host import SimHost
from tests.support.procs import free_port
from tests.tui.tmux import Tmux, needs_tmux

SIZES = [(80, 24), (120, 40)]


def footer(rows: list[str]) -> list[str]:
    """The words of the last row that shows anything."""
    return next(row for row in reversed(rows) if row.strip()).split()


@pytest.fixture
def world() -> Iterator[SimHost]:
    needs_tmux()
    host = SimHost(free_port(), {}, seed=4, watch=False).start()
    try:
        yield host
    finally:
        host.stop()


@pytest.mark.parametrize("size", SIZES)
def test_rosx_sim_shows_how_to_quit_and_quits_on_ctrl_c(
    tmp_path: Path, size: tuple[int, int]
) -> None:
    with Tmux(tmp_path, size, ["sim", "--port", str(free_port())]) as term:
        term.wait_for("/turtle1/pose")  # the graph has come
        rows = term.wait_for("Quit")
        assert footer(rows)[:2] == ["q", "Quit"], rows
        assert any("Topics" in row for row in rows)
        # The pond comes first: a square of half blocks as wide as the body's rows allow
        # (the body is the screen less header and footer, less the pose and log lines).
        side = 2 * (size[1] - 4)
        pond = [row for row in rows if "\u2580" * side in row]
        assert len(pond) == side // 2, rows
        term.keys("C-c")
        assert term.ended()


@pytest.mark.parametrize("size", SIZES)
def test_rqt_console_columns_fit_the_terminal(
    tmp_path: Path, size: tuple[int, int], world: SimHost
) -> None:
    columns, _rows = size
    with Tmux(tmp_path, size, ["rqt_console"], ROS_MASTER_URI=world.master_uri) as term:
        term.wait_for("/rosout_agg at")
        rows = term.wait_for("Quit")
        header = next(row for row in rows if row.startswith("Time"))
        wide = ["Time", "Severity", "Node", "Message", "Topics", "Location"]
        assert header.split() == (wide if columns >= 120 else wide[:4])
        assert footer(rows)[:2] == ["q", "Quit"], rows
        world.drive(2.0, 0.0)
        assert all(len(row) <= columns for row in term.screen())
        term.keys("q")
        assert term.ended()


@pytest.mark.parametrize("size", SIZES)
def test_rqt_logger_level_lists_lab1s_nodes(
    tmp_path: Path, size: tuple[int, int], world: SimHost
) -> None:
    with Tmux(tmp_path, size, ["rqt_logger_level"], ROS_MASTER_URI=world.master_uri) as term:
        term.wait_for("/teleop_turtle")
        rows = term.wait_for("Quit")
        assert footer(rows)[:2] == ["q", "Quit"], rows
        term.keys("C-c")
        assert term.ended()
