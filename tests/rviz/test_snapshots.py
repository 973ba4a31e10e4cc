"""Pictures of rviz's window, one per display (pytest-textual-snapshot).

Deterministic by construction: tf and messages set by hand, a fixed clock, a source that
feeds nothing, a fixed terminal size. Update with ``pytest tests/rviz --snapshot-update``
after a deliberate change, and look at the pictures before committing.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from textual.pilot import Pilot

from rosx_commands.rviz.manager import Manager
from tests.rviz.support import app_of, config, occupancy, scan
from tests.rviz.test_displays import cloud

SnapCompare = Callable[..., bool]
SIZE = (72, 22)


def _scan(manager: Manager) -> None:
    manager.receive(manager.displays[0], scan(), 0.0)


def _map(manager: Manager) -> None:
    manager.receive(manager.displays[0], occupancy(), 0.0)


def _cloud(manager: Manager) -> None:
    points = [(x / 10, y / 10, 0.0, 0x3080FF) for x in range(-10, 11) for y in (-10, 10)]
    manager.receive(manager.displays[0], cloud(points), 0.0)


SCENES: dict[str, tuple[str, Callable[[Manager], None] | None]] = {
    "grid": ("{Class: rviz/Grid, Name: Grid, Cell Size: 0.5}", None),
    "map": ("{Class: rviz/Map, Name: Map, Topic: /map}", _map),
    "laser_scan": ("{Class: rviz/LaserScan, Name: Laser, Topic: /scan, Size (Pixels): 2}", _scan),
    "point_cloud2": ("{Class: rviz/PointCloud2, Name: Cloud, Topic: /points}", _cloud),
    "tf": ("{Class: rviz/TF, Name: TF}", None),
}


@pytest.mark.parametrize("name", sorted(SCENES))
def test_snapshot_of_each_display(name: str, snap_compare: SnapCompare) -> None:
    display, feed = SCENES[name]
    app = app_of(config(display))
    if feed is not None:
        feed(app.manager)

    async def settle(pilot: Pilot[Any]) -> None:
        await pilot.pause()
        await pilot.app.workers.wait_for_complete()
        await pilot.pause()

    assert snap_compare(app, terminal_size=SIZE, run_before=settle)
