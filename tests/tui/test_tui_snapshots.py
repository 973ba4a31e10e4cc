"""Pictures of the pond and of ``rosx sim``'s screen (pytest-textual-snapshot).

Deterministic by construction: ponds stepped by hand with a fixed clock and seeded sprites, a
graph that never changes, fixed terminal sizes, nothing that blinks or tells the time. Update
the pictures with ``pytest tests/tui --snapshot-update`` after a deliberate change (or a textual
upgrade), and look at them before committing.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from textual.pilot import Pilot

from rosx_turtle.tui.factory import make_pond_app, make_sim_app
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.pond import PondView
from rosx_turtle.view.scene import Scene
from tests.support.pilot import run
from tests.support.tui import SNAPSHOT_SIZE, Pond, StaticLink, scripted_pond

SnapCompare = Callable[..., bool]


def test_pond_after_scripted_moves_and_pen_changes(snap_compare: SnapCompare) -> None:
    scenes: Feed[Scene] = Feed(scripted_pond().scene())
    assert snap_compare(make_pond_app(scenes), terminal_size=SNAPSHOT_SIZE)


def test_pond_stays_square_in_a_wide_short_terminal(snap_compare: SnapCompare) -> None:
    scenes: Feed[Scene] = Feed(scripted_pond().scene())
    assert snap_compare(make_pond_app(scenes), terminal_size=(120, 20))


def test_pond_shows_a_new_scene_and_a_new_size(snap_compare: SnapCompare) -> None:
    pond = Pond()
    scenes: Feed[Scene] = Feed(pond.scene())

    async def move_and_resize(pilot: Pilot[Any]) -> None:
        await pilot.pause()
        pond.drive("turtle1", 2.0, 1.0, ticks=120)  # the command times out after 1 s
        scenes.offer(pond.scene())
        await pilot.resize_terminal(60, 24)
        await pilot.pause()

    app = make_pond_app(scenes)
    assert snap_compare(app, terminal_size=SNAPSHOT_SIZE, run_before=move_and_resize)


def test_sim_screen_after_a_key_and_a_focus_change(snap_compare: SnapCompare) -> None:
    link = StaticLink(scripted_pond().scene())
    app = make_sim_app(link)
    assert snap_compare(app, press=["up", "left", "tab"], terminal_size=(120, 36))
    assert link.sent == [(2.0, 0.0), (0.0, 2.0)]


def test_sim_screen_at_80x24_pond_first_panels_in_tabs(snap_compare: SnapCompare) -> None:
    app = make_sim_app(StaticLink(scripted_pond().scene()))
    assert snap_compare(app, terminal_size=(80, 24))


def test_sim_screen_at_120x40_panels_stacked(snap_compare: SnapCompare) -> None:
    app = make_sim_app(StaticLink(scripted_pond().scene()))
    assert snap_compare(app, terminal_size=(120, 40))


def test_sim_screen_too_small_says_the_size_it_needs(snap_compare: SnapCompare) -> None:
    app = make_sim_app(StaticLink(scripted_pond().scene()))
    assert snap_compare(app, terminal_size=(50, 12))


def test_the_pond_survives_any_terminal_size() -> None:
    pond = scripted_pond()
    scenes: Feed[Scene] = Feed(pond.scene())
    app = make_pond_app(scenes)

    async def squeeze() -> list[int]:
        sides = []
        async with app.run_test(size=(80, 24)) as pilot:
            view = app.query_one(PondView)
            for size in ((1, 3), (3, 1), (2, 2), (7, 5), (301, 13), (80, 24)):
                await pilot.resize_terminal(*size)
                pond.drive("turtle1", 2.0, 1.0, ticks=5)
                scenes.offer(pond.scene())
                await pilot.pause()
                sides.append(view.renderer.fit.side)
        return sides

    assert run(squeeze()) == [0, 0, 0, 4, 20, 42]
