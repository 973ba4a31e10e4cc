"""rosx rviz's window driven by pilot: the Displays panel, the tools' keys and clicks, showing
and hiding displays, saving the config and a PNG (a source that records, a fixed clock)."""

from __future__ import annotations

import asyncio
import math
from pathlib import Path
from typing import Any

import pytest
from textual.pilot import Pilot

from rosx_commands.rviz.app import RvizApp
from rosx_commands.rviz.config import load_config
from tests.support.pilot import run
from tests.support.rviz import FakeSource, app_of, config, scan

SCAN_AND_TF = config(
    "{Class: rviz/Grid, Name: Grid}",
    "{Class: rviz/LaserScan, Name: Front laser, Topic: /scan}",
    "{Class: rviz/TF, Name: TF}",
    "{Class: rviz/Camera, Name: Camera}",
)


async def settle(pilot: Pilot[Any]) -> None:
    await pilot.pause()
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


def panel_text(app: RvizApp) -> list[str]:
    return [line for line, _ in app.panel.lines]


def test_the_panel_shows_the_fixed_frame_and_each_display_in_three_rows() -> None:
    app = app_of(SCAN_AND_TF)

    async def drive() -> None:
        async with app.run_test(size=(120, 40)) as pilot:
            await settle(pilot)
            lines = panel_text(app)
            assert lines[0] == "Fixed Frame: map"
            assert lines[2:] == [
                "1 ■ Grid",
                "  rviz/Grid",
                "  ✓ OK",
                "2 ■ Front laser",
                "  /scan",
                "  ⚠ No messages received",
                "3 ■ TF",
                "  rviz/TF",
                "  ✓ OK (4 frames)",
                "4 ■ Camera",
                "  rviz/Camera",
                "  ⚠ unsupported",
            ]
            app.manager.receive(app.manager.displays[1], scan("base_scan"), 0.0)
            app.changed()
            await settle(pilot)
            assert panel_text(app)[5:8] == [
                "2 ■ Front laser  /scan",
                "  ✗ No transform from",
                "  [base_scan] to [map]",
            ]

    run(drive())


def test_dash_f_overrides_the_configs_fixed_frame() -> None:
    app = app_of(SCAN_AND_TF, fixed="odom")

    async def drive() -> None:
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot)
            assert panel_text(app)[0] == "Fixed Frame: odom"

    run(drive())


def test_the_footer_names_the_tools_at_120_columns() -> None:
    app = app_of(SCAN_AND_TF)

    async def drive() -> None:
        async with app.run_test(size=(120, 40)) as pilot:
            await settle(pilot)
            footer = app.screen.get_widget_at(10, 39)[0]
            words = (
                " ".join(str(w.render()) for w in footer.parent.children) if footer.parent else ""
            )
            for key, word in (("q", "Quit"), ("g", "Goal"), ("p", "Pose"), ("c", "Point")):
                assert f"{key} {word}" in " ".join(words.split()), words

    run(drive())


def test_keys_place_each_tool_at_the_view_centre() -> None:
    source = FakeSource()
    app = app_of(SCAN_AND_TF, source=source)

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            await pilot.press("g", "g")  # pressed again: still the goal tool
            assert app.viewport.tool is not None and app.viewport.tool.word == "Goal"
            await pilot.press("left_square_bracket", "left_square_bracket", "enter")
            await settle(pilot)
            await pilot.press("p", "enter", "c", "enter")
            await settle(pilot)
            await pilot.press("escape")
            assert app.viewport.tool is None  # placing puts the tool down, as in rviz

    run(drive())
    turn = round(math.radians(30), 3)
    assert source.published == [
        ("/move_base_simple/goal", "map", 0.0, 0.0, turn),
        ("/initialpose", "map", 0.0, 0.0, turn),
        ("/clicked_point", "map", 0.0, 0.0, 0.0),
    ]


def test_a_click_places_and_a_drag_turns() -> None:
    source = FakeSource()
    app = app_of(SCAN_AND_TF, source=source)

    async def drive() -> tuple[float, float]:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            view = app.view
            await pilot.press("c")
            await pilot.click("#view", offset=(20, 5))
            await settle(pilot)
            clicked = view.point_at(20, 10.5)
            await pilot.press("g")
            await pilot.mouse_down("#view", offset=(20, 5))
            await pilot.hover("#view", offset=(20, 1))  # straight up the screen: +y
            await pilot.mouse_up("#view", offset=(20, 1))
            await settle(pilot)
            return clicked

    x, y = run(drive())
    assert source.published == [
        ("/clicked_point", "map", round(x, 3), round(y, 3), 0.0),
        ("/move_base_simple/goal", "map", round(x, 3), round(y, 3), round(math.pi / 2, 3)),
    ]


def test_number_keys_hide_and_show_displays() -> None:
    source = FakeSource()
    app = app_of(SCAN_AND_TF, source=source)

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            await pilot.press("3")
            await settle(pilot)
            assert panel_text(app)[8:11] == ["3 □ TF", "  rviz/TF", "    disabled"]
            assert not app.manager.displays[2].enabled
            assert source.synced == 1  # the subscriptions follow
            await pilot.click("#displays", offset=(3, 9))  # TF's rows: back on
            await settle(pilot)
            assert app.manager.displays[2].enabled

    run(drive())


def test_ctrl_s_saves_a_config_that_loads_back(tmp_path: Path) -> None:
    app = app_of(SCAN_AND_TF, tmp=tmp_path, fixed="odom")

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            await pilot.press("2", "plus", "right", "ctrl+s")
            await settle(pilot)
            assert app.message == f"Saved {tmp_path / 'saved.rviz'}"

    run(drive())
    saved = load_config(str(tmp_path / "saved.rviz"))
    assert saved.fixed_frame == "odom"
    assert [(d.class_id, d.name, d.enabled) for d in saved.displays] == [
        ("rviz/Grid", "Grid", True),
        ("rviz/LaserScan", "Front laser", False),
        ("rviz/TF", "TF", True),
        ("rviz/Camera", "Camera", True),  # kept, though rosx does not draw it
    ]
    assert saved.displays[1].get("Topic") == "/scan"
    assert saved.view is not None and saved.view.class_id == "rviz/TopDownOrtho"
    assert saved.view.x == pytest.approx(app.view.x)
    assert saved.view.scale == pytest.approx(app.view.rviz_scale)


def test_o_writes_a_png_of_the_view(tmp_path: Path) -> None:
    from PIL import Image

    app = app_of(SCAN_AND_TF, tmp=tmp_path)

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            await pilot.press("o")
            await settle(pilot)

    run(drive())
    (png,) = tmp_path.glob("rviz-*.png")
    assert app.message == f"Wrote {png} ({app.view.width * 8}x{app.view.height * 8})"
    with Image.open(png) as image:
        assert image.size == (app.view.width * 8, app.view.height * 8)
        assert image.getpixel((0, 0)) == (48, 48, 48)  # rviz's background


def test_follow_centres_the_view_on_a_frame() -> None:
    app = app_of(SCAN_AND_TF)

    async def drive() -> None:
        async with app.run_test(size=(100, 30)) as pilot:
            await settle(pilot)
            await pilot.press("f")  # the first frame in order: base_link
            await settle(pilot)
            assert (app.view.x, app.view.y) == pytest.approx((1.5, 0.5))
            assert "Target Frame: base_link" in panel_text(app)

    run(drive())


def test_rviz_is_a_tab_of_rqt_and_waits_for_its_master(tmp_path: Path) -> None:
    from rosx_commands.context import Environment
    from rosx_commands.rqt.app import make_rqt_app
    from rosx_commands.rviz.pane import RvizPane
    from tests.support.cli import clean_environ
    from tests.support.procs import free_port

    uri = f"http://127.0.0.1:{free_port()}/"  # nobody answers there
    env = Environment(environ=clean_environ(ROS_MASTER_URI=uri, HOME=str(tmp_path)))
    app = make_rqt_app(env, first="rviz")

    async def drive() -> None:
        async with app.run_test(size=(120, 40)) as pilot:
            pane = app.query_one(RvizPane)

            def shown() -> list[str]:
                return [line for line, _ in pane.panel.lines][:5]

            def laid_out() -> bool:
                # On a loaded machine the panel may first be drawn before its final width.
                lines = shown()
                return len(lines) > 1 and lines[1] == "─" * (pane.panel.size.width - 1)

            deadline = asyncio.get_running_loop().time() + 30
            while not (pane.message and laid_out()):
                if asyncio.get_running_loop().time() > deadline:
                    break
                await pilot.pause(0.05)
            assert pane.message == f"Waiting for the master {uri}"
            assert shown() == [
                "Fixed Frame: map",
                "─" * (pane.panel.size.width - 1),
                "1 ■ Grid",
                "  rviz/Grid",
                "  ✓ OK",
            ]

    run(drive())
