"""The terminal UI's test helpers: scripted ponds and a fixed link for snapshots.

Snapshots must not depend on timing, so they are taken of ponds built by stepping the engine
by hand (seeded sprites, fixed clock) and of a `StaticLink` whose graph never changes.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Any

from textual.app import App
from textual.pilot import Pilot

from rosx.graph.state import GraphState
from rosx.node import WARN
from rosx_turtle.engine import Simulation, wall_warning
from rosx_turtle.engine.constants import DEFAULT_BACKGROUND, TICK_PERIOD
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.graph import Graph
from rosx_turtle.tui.log import LogRecord
from rosx_turtle.view.adapt import SceneMaker
from rosx_turtle.view.scene import Scene
from tests.support.pilot import run

#: The terminal size of every snapshot (columns, rows).
SNAPSHOT_SIZE = (100, 32)


def running_after_key(
    app: App[Any], key: str, settle: Callable[[Pilot[Any]], Awaitable[None]]
) -> bool:
    """Run ``app`` on an 80x24 terminal, let ``settle`` bring it to rest, press ``key``:
    whether the app is still running after it."""

    async def drive() -> bool:
        async with app.run_test(size=(80, 24)) as pilot:
            await settle(pilot)
            await pilot.press(key)
            await pilot.pause()
            return app.is_running

    return run(drive())


class Pond:
    """A simulation stepped by hand: a fixed clock, seeded sprites, exact ticks."""

    def __init__(self) -> None:
        self.sim = Simulation(seed=4)
        self.sim.reset(DEFAULT_BACKGROUND)
        self.now = 100.0
        self._maker = SceneMaker()

    def drive(self, name: str, linear: float, angular: float, ticks: int = 63) -> None:
        """One cmd_vel for ``name``, then ``ticks`` ticks (63 ≈ the 1 s the command lasts)."""
        self.sim.command(name, linear, 0.0, angular, self.now)
        for _ in range(ticks):
            self.now += TICK_PERIOD
            self.sim.tick(self.now)

    def scene(self) -> Scene:
        return self._maker.make(self.sim)


def scripted_pond() -> Pond:
    """turtle1 draws a square corner with the default pen, then a thick red stroke with pen
    changes in between; turtle2 is spawned and drives an arc with its pen off, then on."""
    pond = Pond()
    pond.drive("turtle1", 2.0, 0.0)
    pond.drive("turtle1", 0.0, 1.5708 / 1.008)
    pond.sim.set_pen("turtle1", 255, 40, 40, 6, 0)
    pond.drive("turtle1", 2.0, 0.0)
    pond.sim.set_pen("turtle1", 0, 0, 0, 0, 1)
    pond.drive("turtle1", 1.0, 2.0)
    pond.sim.spawn(2.0, 2.0, 0.5, "turtle2")
    pond.sim.set_pen("turtle2", 0, 0, 0, 0, 1)
    pond.drive("turtle2", 1.5, 0.0)
    pond.sim.set_pen("turtle2", 255, 255, 0, 2, 0)
    pond.drive("turtle2", 2.5, -1.2)
    return pond


TOPIC_TYPES = {
    "/rosout": "rosgraph_msgs/Log",
    "/rosout_agg": "rosgraph_msgs/Log",
    "/turtle1/cmd_vel": "geometry_msgs/Twist",
    "/turtle1/color_sensor": "turtlesim/Color",
    "/turtle1/pose": "turtlesim/Pose",
}
LAB1_GRAPH = Graph.of(
    GraphState(
        publishers={
            "/rosout": ("/turtlesim", "/teleop_turtle"),
            "/rosout_agg": ("/rosout",),
            "/turtle1/cmd_vel": ("/teleop_turtle",),
            "/turtle1/color_sensor": ("/turtlesim",),
            "/turtle1/pose": ("/turtlesim",),
        },
        subscribers={"/rosout": ("/rosout",), "/turtle1/cmd_vel": ("/turtlesim",)},
        topic_types=TOPIC_TYPES,
    )
)


class StaticLink:
    """A `SimLink` with a fixed pond, Lab 1's graph and a wall warning; records what the
    teleop sends."""

    master_uri = "http://localhost:11311/"
    scales = (2.0, 2.0)

    def __init__(self, scene: Scene) -> None:
        self.scenes: Feed[Scene] = Feed(scene)
        self.graph: Feed[Graph] = Feed(LAB1_GRAPH)
        self.logs: Feed[LogRecord] = Feed(
            LogRecord(WARN, " WARN", wall_warning(11.120889, 5.544445))
        )
        self.sent: list[tuple[float, float]] = []
        self.echoes: dict[str, Callable[[str], object]] = {}

    def drive(self, linear: float, angular: float) -> None:
        self.sent.append((linear, angular))

    def describe_topic(self, topic: str) -> str:
        return f"Type: {TOPIC_TYPES.get(topic, 'unknown type')}\n\nPublishers: None\n"

    def describe_node(self, node: str) -> str:
        return f"Node [{node}]\n"

    def echo(self, topic: str, offer: Callable[[str], object]) -> Callable[[], None]:
        """Records ``offer`` in `echoes` (tests call it); stopping removes it."""
        self.echoes[topic] = offer
        return lambda: self.echoes.pop(topic, None) and None
