"""The simulator's engine: grid, lasers, motion, watchdog, stalls, resets (`rosx_turtle.stage.engine`)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rosx_turtle.stage.engine.grid import Grid, distance_transform, rasterise
from rosx_turtle.stage.engine.laser import cast
from rosx_turtle.stage.engine.simulation import StageSim
from rosx_turtle.stage.world.model import build
from rosx_turtle.stage.world.worldfile import parse
from tests.support.stage_worlds import room


def sim_of(text: str, watchdog: float = 0.2) -> StageSim:
    world = build(parse(text, "t.world"))
    return StageSim(world, rasterise(world), watchdog=watchdog)


def test_beams_read_the_distances_to_the_walls() -> None:
    sim = sim_of(room())
    (scan,) = sim.step(scan_all=True).scans
    assert scan.ranges.shape == (181,)
    beams = -math.pi / 2 + np.arange(181) * math.pi / 180
    # The inner faces are 4.9 m away along the axes; a beam at angle a meets the nearer one.
    expected = np.minimum(
        4.9 / np.maximum(np.abs(np.cos(beams)), 1e-9), 4.9 / np.maximum(np.abs(np.sin(beams)), 1e-9)
    )
    expected = np.minimum(expected, 8.0)
    assert np.abs(scan.ranges - expected).max() < 0.03  # within a cell and a half of 0.02 m
    assert scan.ranges[90] == pytest.approx(4.9, abs=0.021)  # straight ahead, east
    assert np.all(scan.intensities[expected < 8.0] == 1.0)
    assert np.all((scan.ranges >= 0.05) & (scan.ranges <= 8.0))


def test_a_beam_that_meets_nothing_reads_range_max() -> None:
    sim = sim_of(room().replace("range [ 0.05 8.0 ]", "range [ 0.05 3.0 ]"))
    (scan,) = sim.step(scan_all=True).scans
    assert np.all(scan.ranges == np.float32(3.0))
    assert np.all(scan.intensities == 0.0)


def test_other_robots_are_seen_and_invisible_blocks_are_not() -> None:
    text = room('pose [ 0 0 0 0 ] name "a"', 'pose [ 2 0 0 180 ] name "b"',
                extra='wall ( pose [ 0 2 0 0 ] size [ 1 0.2 0.5 ] ranger_return -1 )\n')  # fmt: skip
    sim = sim_of(text)
    scans = sim.step(scan_all=True).scans
    ahead = scans[0].ranges[90]
    assert ahead == pytest.approx(2.0 - 0.15, abs=0.01)  # b's body is 0.3 m wide
    assert scans[0].ranges[180] == pytest.approx(
        4.9, abs=0.021
    )  # north: the hidden wall is not seen
    assert scans[1].ranges[90] == pytest.approx(2.0 - 0.15, abs=0.01)


def test_a_diff_robot_drives_and_turns_as_stage_integrates() -> None:
    sim = sim_of(room(), watchdog=0)
    sim.set_command(0, 0.5, 0.3, 0.0)  # a diff robot ignores the sideways speed
    for _ in range(10):
        report = sim.step()
    assert report.pose[0] == pytest.approx([0.5, 0.0, 0.0])
    assert report.velocity[0] == pytest.approx([0.5, 0.0, 0.0])
    sim.set_command(0, 0.0, 0.0, 5.0)  # clipped to Stage's bound, π/2 rad/s
    report = sim.step()
    assert report.pose[0][2] == pytest.approx(math.pi / 20)
    assert report.time_ns == 11 * 100_000_000


def test_an_omni_robot_moves_sideways() -> None:
    sim = sim_of(room().replace('drive "diff"', 'drive "omni"'), watchdog=0)
    sim.set_command(0, 0.0, 0.5, 0.0)
    for _ in range(4):
        report = sim.step()
    assert report.pose[0] == pytest.approx([0.0, 0.2, 0.0])


def test_the_watchdog_stops_a_robot_whose_commands_stopped() -> None:
    sim = sim_of(room('pose [ 0 0 0 0 ] name "a"', 'pose [ 0 2 0 0 ] name "b"'))
    sim.set_command(0, 1.0, 0.0, 0.0)
    sim.set_command(1, 1.0, 0.0, 0.0)
    poses = [sim.step().pose[:, 0].copy() for _ in range(2)]
    assert poses[0] == pytest.approx([0.1, 0.1])
    assert poses[1] == pytest.approx([0.2, 0.2])  # this step reached 0.2 s: stopped after it
    assert sim.step().pose[:, 0] == pytest.approx([0.2, 0.2])
    sim.set_command(1, 1.0, 0.0, 0.0)  # b is commanded again; a stays stopped
    assert sim.step().pose[:, 0] == pytest.approx([0.2, 0.3])


def test_a_robot_stalls_against_a_wall_and_reset_puts_it_back() -> None:
    sim = sim_of(room(), watchdog=0)
    sim.set_command(0, 1.0, 0.0, 0.0)
    stalled = [bool(sim.step().stalled[0]) for _ in range(60)]
    x = sim.pose[0, 0]
    assert stalled[0] is False and stalled[-1] is True
    assert 4.9 - 0.15 - 0.1 <= x <= 4.9 - 0.15  # stopped within one step of the wall
    assert sim.step().velocity[0] == pytest.approx([0.0, 0.0, 0.0])
    sim.set_command(0, -0.5, 0.0, 0.0)  # backing away frees it
    assert not sim.step().stalled[0]
    sim.reset()
    report = sim.step()
    assert report.pose[0] == pytest.approx([-0.05, 0.0, 0.0])
    assert not report.stalled[0]


def test_robots_bump_into_each_other() -> None:
    sim = sim_of(room('pose [ 0 0 0 0 ] name "a"', 'pose [ 1 0 0 0 ] name "b"'), watchdog=0)
    sim.set_command(0, 1.0, 0.0, 0.0)
    for _ in range(20):
        report = sim.step()
    assert report.stalled[0]
    assert report.pose[0][0] < 1.0 - 0.3 + 1e-9


def test_odometry_follows_stage_localization() -> None:
    gps = sim_of(room('pose [ 1 2 0 90 ] name "g"'))
    assert gps.step().odom[0] == pytest.approx([1.0, 2.0, math.pi / 2])
    odom = sim_of(room('pose [ 1 2 0 90 ] name "o" localization "odom"'), watchdog=0)
    odom.set_command(0, 1.0, 0.0, 0.0)
    report = odom.step()
    assert report.pose[0] == pytest.approx([1.0, 2.1, math.pi / 2])
    assert report.odom[0] == pytest.approx([0.1, 0.0, 0.0])


@pytest.mark.parametrize(
    ("shape", "density"), [((40, 50), 0.02), ((30, 80), 0.5), ((60, 60), 0.001), ((1, 9), 0.2)]
)
def test_the_distance_transform_is_exact(shape: tuple[int, int], density: float) -> None:
    rng = np.random.default_rng(3)
    seen = rng.random(shape) < density
    seen[0, 0] = True
    distance = distance_transform(seen)
    rows, cols = np.nonzero(seen)
    yy, xx = np.mgrid[0 : shape[0], 0 : shape[1]]
    exact = np.sqrt((yy[..., None] - rows) ** 2 + (xx[..., None] - cols) ** 2).min(axis=2)
    assert np.abs(distance - exact).max() < 1e-4


def first_cell_on_ray(solid: np.ndarray, res: float, x: float, y: float, angle: float) -> float:
    """Where a ray from (x, y) (the grid's corner at 0, 0) enters its first solid cell, found
    by visiting the cells it crosses one by one; inf for none."""
    rows, cols = solid.shape
    dx, dy = math.cos(angle), math.sin(angle)
    col, row = math.floor(x / res), math.floor(y / res)
    step_x, step_y = (1 if dx > 0 else -1), (1 if dy > 0 else -1)
    next_x = ((col + (dx > 0)) * res - x) / dx if dx else math.inf
    next_y = ((row + (dy > 0)) * res - y) / dy if dy else math.inf
    while 0 <= row < rows and 0 <= col < cols:
        if next_x < next_y:
            t, col, next_x = next_x, col + step_x, next_x + res / abs(dx)
        else:
            t, row, next_y = next_y, row + step_y, next_y + res / abs(dy)
        if 0 <= row < rows and 0 <= col < cols and solid[row, col]:
            return t
    return math.inf


def test_every_beam_reads_where_it_enters_its_first_wall_cell() -> None:
    """Rays that graze walls, pass by corners or run along a cell's edges read the distance at
    which they enter the first cell they cross, as a cell-by-cell walk finds it."""
    rng = np.random.default_rng(7)
    solid = rng.random((60, 80)) < 0.03
    solid[[0, -1], :] = solid[:, [0, -1]] = True
    grid = Grid(solid, solid.astype(np.float32), (0.0, 0.0), 0.05)
    free_rows, free_cols = np.nonzero(~solid)
    pick = rng.integers(0, free_rows.size, 2000)
    x = (free_cols[pick] + rng.random(2000)) * 0.05
    y = (free_rows[pick] + rng.random(2000)) * 0.05
    angle = rng.random(2000) * 2 * math.pi
    angle[:200] = rng.choice([0.0, math.pi / 2, math.pi, -math.pi / 2, math.pi / 4], 200)
    ranges, intensity = cast(grid, x, y, angle, np.full(2000, 3.0))
    rays = zip(x.tolist(), y.tolist(), angle.tolist(), strict=True)
    expected = [min(first_cell_on_ray(solid, 0.05, *ray), 3.0) for ray in rays]
    assert ranges == pytest.approx(expected, abs=1e-6)
    assert np.array_equal(intensity > 0, np.array(expected) < 3.0)
