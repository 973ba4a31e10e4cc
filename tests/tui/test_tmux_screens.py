"""rosx's terminal UIs in real terminals of 80x24 and 120x40 (tmux): what shows, that nothing
is wider than the terminal, and that q and Ctrl-C quit. Skipped where tmux is not installed."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx_turtle.engine.constants import DEFAULT_BACKGROUND
from rosx_turtle.sim.host import SimHost
from tests.support.procs import free_port
from tests.support.tmux import (
    STARTUP,
    Cell,
    Tmux,
    fits_and_shows_how_to_quit,
    footer,
    needs_tmux,
    quits_on_ctrl_c,
)

SIZES = [(80, 24), (120, 40)]
POND_BLUE = ";".join(str(part) for part in DEFAULT_BACKGROUND)
HALF_BLOCK = "\u2580"


def has_words(rows: list[str], *words: str) -> bool:
    """Whether a row shows ``words`` one after the other."""
    count = len(words)
    for row in rows:
        split = row.split()
        if any(tuple(split[at : at + count]) == words for at in range(len(split))):
            return True
    return False


def boxed(rows: list[str], text: str) -> bool:
    """Whether ``text`` is drawn in a box of its own (a rounded frame one cell around it)."""
    rule = "\u2500" * (len(text) + 2)
    for above, row, below in zip(rows, rows[1:], rows[2:], strict=False):
        at = row.find(f"\u2502 {text} \u2502")
        end = at + len(text) + 4
        if (
            at >= 0
            and above[at:end] == f"\u256d{rule}\u256e"
            and below[at:end] == f"\u2570{rule}\u256f"
        ):
            return True
    return False


def turtle_in_the_pond(screen: list[list[Cell]]) -> bool:
    """Whether the pond (a field of half blocks) shows, in its middle, cells of other colours
    than its blue: the turtle, which starts at the centre."""
    pond = [
        (y, x, cell)
        for y, row in enumerate(screen)
        for x, cell in enumerate(row)
        if cell.char == HALF_BLOCK
    ]
    turtle = [(y, x) for y, x, cell in pond if POND_BLUE not in (cell.fg, cell.bg)]
    if not pond or not turtle:
        return False
    middle_y = (pond[0][0] + pond[-1][0]) / 2
    middle_x = (min(x for _, x, _ in pond) + max(x for _, x, _ in pond)) / 2
    ys, xs = [y for y, _ in turtle], [x for _, x in turtle]
    # Within a cell: the middle may fall between two.
    return min(ys) - 1 <= middle_y <= max(ys) + 1 and min(xs) - 1 <= middle_x <= max(xs) + 1


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


@pytest.mark.parametrize("size", SIZES)
def test_rqt_graph_draws_turtlesim_in_a_box(
    tmp_path: Path, size: tuple[int, int], world: SimHost
) -> None:
    with Tmux(tmp_path, size, ["rqt_graph"], ROS_MASTER_URI=world.master_uri) as term:
        rows = term.wait_until(lambda rows: boxed(rows, "/turtlesim"), "/turtlesim", STARTUP)
        assert boxed(rows, "/teleop_turtle"), rows
        fits_and_shows_how_to_quit(term, size[0])
        quits_on_ctrl_c(term)


@pytest.mark.parametrize("size", SIZES)
def test_rqt_topic_lists_the_pose_with_its_type(
    tmp_path: Path, size: tuple[int, int], world: SimHost
) -> None:
    with Tmux(tmp_path, size, ["rqt_topic"], ROS_MASTER_URI=world.master_uri) as term:
        term.wait_until(
            lambda rows: has_words(rows, "/turtle1/pose", "turtlesim/Pose"),
            "/turtle1/pose with its type",
            STARTUP,
        )
        rows = term.screen()
        assert has_words(rows, "Topic", "Type", "Bandwidth", "Hz"), rows
        fits_and_shows_how_to_quit(term, size[0])
        quits_on_ctrl_c(term)


@pytest.mark.parametrize("size", SIZES)
def test_rqt_shows_its_tabs(tmp_path: Path, size: tuple[int, int], world: SimHost) -> None:
    with Tmux(tmp_path, size, ["rqt"], ROS_MASTER_URI=world.master_uri) as term:
        tabs = ("Graph", "Plot", "Topics", "Console", "Logger", "levels")
        term.wait_until(lambda rows: has_words(rows, *tabs), "the tabs", STARTUP)
        # The first tab is the graph.
        term.wait_until(lambda rows: boxed(rows, "/turtlesim"), "/turtlesim", STARTUP)
        fits_and_shows_how_to_quit(term, size[0])
        quits_on_ctrl_c(term)


@pytest.mark.parametrize("size", SIZES)
def test_turtlesim_node_draws_the_pond_with_the_turtle(
    tmp_path: Path, size: tuple[int, int], master: str
) -> None:
    argv = ["rosrun", "turtlesim", "turtlesim_node"]
    with Tmux(tmp_path, size, argv, ROS_MASTER_URI=master) as term:
        term.wait_until(lambda _: turtle_in_the_pond(term.cells()), "the turtle", STARTUP)
        term.wait_for("turtle1 \u2192 x=5.54 y=5.54 \u03b8=0.00")
        fits_and_shows_how_to_quit(term, size[0])
        quits_on_ctrl_c(term)


@pytest.mark.parametrize("size", SIZES)
def test_turtlesim_view_draws_the_running_turtlesim(
    tmp_path: Path, size: tuple[int, int], world: SimHost
) -> None:
    argv = ["rosrun", "turtlesim", "turtlesim_view"]
    with Tmux(tmp_path, size, argv, ROS_MASTER_URI=world.master_uri) as term:
        term.wait_until(lambda _: turtle_in_the_pond(term.cells()), "the turtle", STARTUP)
        rows = term.wait_for("turtle1 \u2192 x=5.54 y=5.54 \u03b8=0.00")
        assert "/turtlesim" in rows[0].split(), rows
        fits_and_shows_how_to_quit(term, size[0])
        quits_on_ctrl_c(term)


def teleop_pane(rows: list[str]) -> list[str]:
    """The teleop pane as drawn: its title row, its three lines and its bottom border, each
    without the box's corners and sides (stripped)."""
    top = next(i for i, row in enumerate(rows) if "Teleop → /turtle1/cmd_vel" in row)
    left = min(rows[top].find(corner) for corner in "╭┏" if corner in rows[top])
    box = [row[left:].rstrip() for row in rows[top : top + 5]]
    return [line.strip("╭╮┏┓╰╯┗┛│┃─━ ") for line in box]


def test_rosx_sim_at_80x24_says_in_words_whether_the_arrows_drive(tmp_path: Path) -> None:
    """At 80x24 the side column is at its narrowest: every line of the teleop pane is whole,
    and after Tab the pane says the arrows no longer drive the turtle, and how to get back."""
    with Tmux(tmp_path, (80, 24), ["sim", "--port", str(free_port())]) as term:
        rows = term.wait_for("arrow keys drive the turtle", STARTUP)
        assert teleop_pane(rows) == [
            "Teleop → /turtle1/cmd_vel",
            "↑ ↓  forward / back   linear.x ±2.0",
            "← →  turn left/right  angular.z ±2.0",
            "nothing sent yet",
            "arrow keys drive the turtle",
        ]
        term.keys("Up")
        term.wait_for("#1 linear.x=2.0 angular.z=0.0")
        term.keys("Tab")
        rows = term.wait_for("Arrow keys do not drive the turtle.")
        assert teleop_pane(rows) == [
            "Teleop → /turtle1/cmd_vel",
            "Arrow keys do not drive the turtle.",
            "To drive: Tab until this is lit.",
            "#1 linear.x=2.0 angular.z=0.0",
            "",
        ]
        term.keys("BTab")
        rows = term.wait_for("arrow keys drive the turtle")
        assert teleop_pane(rows)[3] == "#1 linear.x=2.0 angular.z=0.0"
        fits_and_shows_how_to_quit(term, 80)
