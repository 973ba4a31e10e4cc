"""Driving rosx rqt_graph's live view with pilot: what the status line, the details panel
and the view show, and a scenario run on live graphs of rosx nodes and of rospy nodes."""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from typing import Any

from textual.pilot import Pilot
from textual.widgets import Static

from rosx.graph.fetch import fetch_state
from rosx.graph.options import GraphOptions, Mode
from rosx_commands.context import Environment
from rosx_commands.rqt_graph.app import GraphApp, make_graph_app
from rosx_commands.rqt_graph.source import CALLER_ID, LiveSource
from rosx_commands.rqt_graph.view import APPEARED, LINKED, NODE, SELECTED, VANISHED, GraphView

#: Wide enough for a three-vertex graph beside the details panel.
WIDE = (140, 32)


def status(app: GraphApp) -> str:
    return str(app.query_one("#status", Static).render())


def info(app: GraphApp) -> str:
    return str(app.query_one("#info", Static).render())


async def settle(pilot: Pilot[Any]) -> None:
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


MARKS = {"appeared": APPEARED, "vanished": VANISHED, "selected": SELECTED}
MARKS |= {"linked": LINKED, "node": NODE}


def mark_at(app: GraphApp, text: str, nth: int = 0) -> str | None:
    """How the view marks the ``nth`` ``text`` on screen: a name of `MARKS`, or None when it
    is plain."""
    view = app.query_one(GraphView)
    base = view.rich_style
    found = []
    for y in range(view.scrollable_content_region.height):
        strip = view.render_line(y)
        found += [seg.style for seg in strip for _ in range(seg.text.count(text))]
        if strip.text.count(text) > sum(seg.text.count(text) for seg in strip):
            raise AssertionError(f"{text!r} is split over several styles: {strip.text!r}")
    if len(found) <= nth:
        raise AssertionError(f"{text!r} not on screen {nth + 1} times")
    if found[nth] == base:
        return None
    return next(k for k, style in MARKS.items() if base + style == found[nth])


def chatter_rate(details: str) -> float:
    """The average rate the details give (0 before there is one)."""
    found = re.search(r"average rate: ([0-9.]+) Hz", details)
    return float(found[1]) if found else 0.0


async def until(
    pilot: Pilot[Any], done: Callable[[], bool], what: str, timeout: float = 20
) -> None:
    """Refresh (``r``) until ``done()``; fail naming ``what`` after ``timeout`` seconds."""
    app: GraphApp = pilot.app  # type: ignore[assignment]
    deadline = time.monotonic() + timeout
    while not done():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}; status: {status(app)}")
        await pilot.press("r")
        await settle(pilot)


async def talker_chatter_listener(uri: str, stop_talker: Callable[[], None]) -> None:
    """On a master with a talker publishing ``/chatter`` (std_msgs/String, about 10 Hz) to a
    listener: the view draws them left to right, the topic's details give its type and rate,
    a stopped talker is drawn faded and named, and the node filter takes effect."""
    env = Environment(environ={"ROS_MASTER_URI": uri})
    source = LiveSource(env, uri, CALLER_ID, bus_info=True)
    app = make_graph_app(source, GraphOptions(mode=Mode.ACTIVE))
    ids = {"n:/talker", "t:/chatter", "n:/listener"}
    async with app.run_test(size=WIDE) as pilot:
        await settle(pilot)
        await until(pilot, lambda: ids <= set(app.drawing.boxes), "talker → chatter → listener")
        boxes = app.drawing.boxes
        assert boxes["n:/talker"].x < boxes["t:/chatter"].x < boxes["n:/listener"].x
        # green if it came after the first refresh (the last change), else a node's colour
        assert mark_at(app, "/talker") == ("appeared" if "+ /talker" in status(app) else "node")
        while app.selected != "t:/chatter":
            await pilot.press("tab")
        assert mark_at(app, "/chatter") == "selected"
        # The first figure may rest on two messages that came together (a talker's writer
        # thread, held back on a loaded machine, sends what has queued): wait for the rate over
        # the window to come near the talker's 10 Hz; a wrong rate never does.
        await until(pilot, lambda: 5 < chatter_rate(info(app)) < 15, "/chatter at about 10 Hz")
        details = info(app)
        assert "Type: std_msgs/String" in details
        assert "Publishers: \n * /talker (http://" in details
        assert "Subscribers: \n * /listener (http://" in details
        stop_talker()
        await until(pilot, lambda: "- /talker" in status(app), "the talker to vanish")
        assert "n:/talker" in app.drawing.boxes  # still drawn, faded
        assert mark_at(app, "/talker") == "vanished"
        await pilot.press("n", "ctrl+u", *"-/listener", "enter")
        await settle(pilot)
        assert "n:/listener" not in app.drawing.boxes
        assert "Nodes/Topics (active) │ 0 nodes" in status(app)
    # the hidden node that counted /chatter's rate left the master with the view
    left = fetch_state(uri, "/check", bus_info=False).nodes
    assert not [name for name in left if name.startswith(CALLER_ID)], left
