"""`StageSim`: Stage's world in numpy — robots, their lasers and the clock, one step at a time.

State in, state out: `step` advances the simulated time by the world's ``interval_sim``,
moves the robots (`motion`), stops those whose last command is now as old as the watchdog
timeout (stage_ros's order: a command lasts through the step that reaches it),
and casts the lasers that are due (each at its ``update_interval``) in one call (`laser`).
It returns a `StepReport` the node turns into messages. Commands, resets and teleports are
method calls between steps. Time is an integer count of nanoseconds from 0, as Stage's
simulated clock.

What each robot's odometry reads follows Stage's ``localization``: ``gps`` (the default) the
true pose; ``odom`` the pose relative to ``localization_origin`` (the start pose by default),
without Stage's random odometry error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np  # noqa: TID253 - the engine is numpy through and through

from rosx_turtle.stage.engine.laser import cast, cast_bodies
from rosx_turtle.stage.engine.motion import Bodies, advance, clip_command

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy.typing as npt

    from rosx_turtle.stage.engine.grid import Grid
    from rosx_turtle.stage.world.model import Laser, Robot, World

    Floats = npt.NDArray[np.float64]

_NS = 1_000_000_000


@dataclass(frozen=True, eq=False)
class Scan:
    """One laser's reading: ``ranges`` and ``intensities`` from angle -fov/2 upwards."""

    robot: int
    laser: int
    spec: Laser
    ranges: npt.NDArray[np.float32]
    intensities: npt.NDArray[np.float32]


@dataclass(frozen=True, eq=False)
class StepReport:
    """What a step produced, all arrays indexed by robot.

    ``pose`` the true pose (x, y, yaw); ``odom`` what odometry reads; ``velocity`` the robot's
    own (forward, sideways, turn) speeds during the step; ``world_velocity`` the true pose's
    rate of change in the world's frame; ``stalled`` who bumped into something; ``scans`` the
    lasers cast this step.
    """

    time_ns: int
    pose: Floats
    odom: Floats
    velocity: Floats
    world_velocity: Floats
    stalled: npt.NDArray[np.bool_]
    scans: tuple[Scan, ...]


class StageSim:
    """The simulation of ``world`` over ``grid`` (see the module docstring)."""

    def __init__(self, world: World, grid: Grid, *, watchdog: float = 0.2) -> None:
        self.world = world
        self.grid = grid
        self.watchdog_ns = round(watchdog * _NS)
        self.step_ns = round(world.interval_sim * _NS)
        robots = world.robots
        self.robots: tuple[Robot, ...] = robots
        count = len(robots)
        self.start = np.array([r.pose for r in robots], dtype=np.float64).reshape(count, 3)
        self.pose = self.start.copy()
        self.command = np.zeros((count, 3))
        self.velocity = np.zeros((count, 3))
        self.world_velocity = np.zeros((count, 3))
        self.stalled = np.zeros(count, dtype=np.bool_)
        self.last_command_ns = np.full(count, -(2**62), dtype=np.int64)
        self.omni = np.array([r.drive == "omni" for r in robots], dtype=np.bool_)
        self.time_ns = 0
        sizes = np.array([r.size[:2] for r in robots], dtype=np.float64).reshape(count, 2)
        offsets = np.array([r.origin[:2] for r in robots], dtype=np.float64).reshape(count, 2)
        self.bodies = Bodies.boxes(sizes, offsets, grid.resolution / 2)
        # The distance fields, once per world, before the first step needs them.
        grid.clearance, grid.room  # noqa: B018
        self.visible = np.array([r.ranger_return > 0 for r in robots], dtype=np.bool_)
        self.odom_origin = np.array(
            [r.localization_origin or r.pose for r in robots], dtype=np.float64
        ).reshape(count, 3)
        self.gps = np.array([r.localization == "gps" for r in robots], dtype=np.bool_)
        self.lasers = [
            (k, j, laser) for k, r in enumerate(robots) for j, laser in enumerate(r.lasers)
        ]
        self.next_scan_ns = [0 for _ in self.lasers]
        self._beams = [_beam_angles(laser) for _, _, laser in self.lasers]

    # -- between steps --------------------------------------------------------------------

    def set_command(self, robot: int, vx: float, vy: float, w: float) -> None:
        """Robot ``robot``'s velocity command (its own frame), from now on."""
        self.command[robot] = (vx, vy, w)
        self.last_command_ns[robot] = self.time_ns

    def set_pose(self, robot: int, x: float, y: float, yaw: float) -> None:
        """Put a robot at a pose (it keeps its command; its stall is cleared)."""
        self.pose[robot] = (x, y, math.atan2(math.sin(yaw), math.cos(yaw)))
        self.stalled[robot] = False

    def reset(self) -> None:
        """Every robot back to its start pose, unstalled (stage_ros's ``reset_positions``)."""
        self.pose[:] = self.start
        self.stalled[:] = False

    # -- a step ---------------------------------------------------------------------------

    def step(self, *, scan_all: bool = False) -> StepReport:
        """Advance the time by ``interval_sim``; cast the lasers that are due (all of them
        with ``scan_all``)."""
        self.time_ns += self.step_ns
        dt = self.step_ns / _NS
        vx, vy, w = clip_command(
            self.command[:, 0], self.command[:, 1], self.command[:, 2], self.omni
        )
        before = self.pose.copy()
        x, y, yaw, stalled = advance(
            self.grid, self.bodies, (before[:, 0], before[:, 1], before[:, 2]), (vx, vy, w), dt
        )
        self.pose = np.stack([x, y, yaw], axis=1)
        self.stalled = stalled
        if self.watchdog_ns > 0:  # as stage_ros: after the step that reached the timeout
            idle = self.time_ns - self.last_command_ns >= self.watchdog_ns
            self.command[idle] = 0.0
        moving = ~stalled
        self.velocity = np.stack([vx * moving, vy * moving, w * moving], axis=1)
        turn = np.arctan2(np.sin(yaw - before[:, 2]), np.cos(yaw - before[:, 2]))
        self.world_velocity = np.stack(
            [(x - before[:, 0]) / dt, (y - before[:, 1]) / dt, turn / dt], axis=1
        )
        due = [i for i, at in enumerate(self.next_scan_ns) if scan_all or at <= self.time_ns]
        for i in due:
            interval = round(self.lasers[i][2].interval * _NS)
            self.next_scan_ns[i] = self.time_ns + max(interval, self.step_ns) - self.step_ns // 2
        return StepReport(
            self.time_ns,
            self.pose.copy(),
            self.odometry(),
            self.velocity.copy(),
            self.world_velocity.copy(),
            stalled.copy(),
            self.scan(due),
        )

    def odometry(self) -> Floats:
        """What each robot's odometry reads now (see the module docstring)."""
        origin = self.odom_origin
        dx = self.pose[:, 0] - origin[:, 0]
        dy = self.pose[:, 1] - origin[:, 1]
        cos, sin = np.cos(origin[:, 2]), np.sin(origin[:, 2])
        rel = np.stack(
            [
                dx * cos + dy * sin,
                dy * cos - dx * sin,
                np.arctan2(
                    np.sin(self.pose[:, 2] - origin[:, 2]), np.cos(self.pose[:, 2] - origin[:, 2])
                ),
            ],
            axis=1,
        )
        result: Floats = np.where(self.gps[:, None], self.pose, rel)
        return result

    def scan(self, which: Sequence[int]) -> tuple[Scan, ...]:
        """Cast lasers ``which`` (indices into `lasers`) from the robots' current poses."""
        if not which:
            return ()
        xs, ys, angles, limits, sizes = [], [], [], [], []
        origins, firsts, increments, owners = [], [], [], []
        for i in which:
            robot, _, laser = self.lasers[i]
            px, py, pa = self.pose[robot]
            lx, ly, la = laser.pose
            ox = px + lx * math.cos(pa) - ly * math.sin(pa)
            oy = py + lx * math.sin(pa) + ly * math.cos(pa)
            count = laser.samples
            xs.append(np.full(count, ox))
            ys.append(np.full(count, oy))
            beams = self._beams[i]
            angles.append(beams + pa + la)
            limits.append(np.full(count, laser.range_max))
            sizes.append(count)
            origins.append((ox, oy))
            firsts.append(beams[0] + pa + la)
            increments.append(laser.angle_increment if count > 1 else 0.0)
            owners.append(robot)
        x, y, angle = np.concatenate(xs), np.concatenate(ys), np.concatenate(angles)
        limit = np.concatenate(limits)
        ranges, intensity = cast(self.grid, x, y, angle, limit)
        if self.visible.any():
            seen = np.flatnonzero(self.visible)
            centres = self.bodies.centres(
                self.pose[seen, 0], self.pose[seen, 1], self.pose[seen, 2]
            )
            # A fan's own robot among the visible ones (past the end: it is not one of them).
            where = np.full(len(self.robots), len(seen), dtype=np.intp)
            where[seen] = np.arange(len(seen))
            bodies, nearest = cast_bodies(
                np.array(origins, dtype=np.float64).reshape(-1, 2),
                np.array(firsts, dtype=np.float64),
                np.array(increments, dtype=np.float64),
                np.array(sizes, dtype=np.intp),
                where[np.array(owners, dtype=np.intp)],
                centres,
                self.pose[seen, 2],
                self.bodies.half[seen],
            )
            closer = bodies < ranges
            if closer.any():
                returns = np.array([r.ranger_return for r in self.robots], dtype=np.float32)
                ranges = np.where(closer, bodies, ranges)
                intensity = np.where(closer, returns[seen][nearest], intensity).astype(np.float32)
        scans: list[Scan] = []
        at = 0
        for i, count in zip(which, sizes, strict=True):
            robot, j, laser = self.lasers[i]
            part = ranges[at : at + count]
            part = np.maximum(part, laser.range_min)  # Stage never reads below range_min
            scans.append(
                Scan(
                    robot,
                    j,
                    laser,
                    part.astype(np.float32),
                    intensity[at : at + count].astype(np.float32),
                )
            )
            at += count
        return tuple(scans)


def _beam_angles(laser: Laser) -> Floats:
    """The beams' angles in the laser's frame: -fov/2 + i * increment."""
    if laser.samples == 1:
        return np.zeros(1)
    return -laser.fov / 2 + np.arange(laser.samples, dtype=np.float64) * laser.angle_increment


__all__ = ["Scan", "StageSim", "StepReport"]
