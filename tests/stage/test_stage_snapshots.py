"""Pictures of stageros's window and of ``rosx sim --robot``'s screen (pytest-textual-snapshot).

Deterministic by construction: worlds stepped by hand (no clock), a graph that never changes,
fixed terminal sizes. Update the pictures with ``pytest tests/stage --snapshot-update`` after a
deliberate change (or a textual upgrade), and look at them before committing.
"""

from __future__ import annotations

from collections.abc import Callable

from rosx.graph.describe import NodeSummary, TopicSummary
from rosx.node import INFO
from rosx_turtle.stage.engine.grid import Grid, rasterise
from rosx_turtle.stage.engine.simulation import StageSim, StepReport
from rosx_turtle.stage.lab.plan import plan_lab
from rosx_turtle.stage.view.app import make_stage_app
from rosx_turtle.stage.view.lab_app import make_lab_app
from rosx_turtle.stage.world.load import load_world
from rosx_turtle.stage.world.model import World, build
from rosx_turtle.stage.world.worldfile import parse
from rosx_turtle.tui.feed import Feed
from rosx_turtle.tui.graph import Graph
from rosx_turtle.tui.log import LogRecord
from tests.support.stage_worlds import room

SnapCompare = Callable[..., bool]

LAB_GRAPH = Graph(
    topics=(
        TopicSummary("/cmd_vel", "geometry_msgs/Twist", ("/teleop_twist_keyboard",), ("/stageros",)),
        TopicSummary("/map", "nav_msgs/OccupancyGrid", ("/map_server",), ()),
        TopicSummary("/odom", "nav_msgs/Odometry", ("/stageros",), ()),
        TopicSummary("/scan", "sensor_msgs/LaserScan", ("/stageros",), ()),
    ),
    nodes=(
        NodeSummary("/map_server", 3, 0),
        NodeSummary("/stageros", 6, 3),
        NodeSummary("/teleop_twist_keyboard", 2, 0),
    ),
)  # fmt: skip


def stepped(world: World, grid: Grid, *, forward: float, steps: int) -> StepReport:
    """The first robot driven ``forward`` m/s for ``steps`` steps, every laser cast at the last."""
    sim = StageSim(world, grid, watchdog=0)
    sim.set_command(0, forward, 0.0, 0.3)
    for _ in range(steps - 1):
        sim.step()
    return sim.step(scan_all=True)


class StaticLabLink:
    """A `LabLink` with the bundled arena a few steps in, a fixed graph and log line."""

    master_uri = "http://localhost:11311/"
    drive_topic, odom_topic, scan_topic = "/cmd_vel", "/odom", "/scan"
    names = ("burger",)

    def __init__(self) -> None:
        self.world, self.grid = load_world(plan_lab(None, None).world)
        self.steps: Feed[StepReport] = Feed(stepped(self.world, self.grid, forward=0.2, steps=8))
        self.graph: Feed[Graph] = Feed(LAB_GRAPH)
        self.logs: Feed[LogRecord] = Feed(LogRecord(INFO, " INFO", "Resetting stage!"))
        self.sent: list[tuple[float, float, float, float]] = []

    def drive(self, linear_x: float, linear_y: float, linear_z: float, angular_z: float) -> None:
        self.sent.append((linear_x, linear_y, linear_z, angular_z))

    def describe_topic(self, topic: str) -> str:
        return f"Type: {topic}\n"

    def describe_node(self, node: str) -> str:
        return f"Node [{node}]\n"

    def echo(self, topic: str, offer: Callable[[str], object]) -> Callable[[], None]:
        return lambda: None


def test_stageros_window_two_robots_and_their_lasers(snap_compare: SnapCompare) -> None:
    text = room('pose [ -2 0 0 0 ] name "a"', 'pose [ 2 1 0 135 ] name "b" color "green"')
    world = build(parse(text, "t.world"))
    grid = rasterise(world)
    steps: Feed[StepReport] = Feed(stepped(world, grid, forward=0.5, steps=4))
    app = make_stage_app(world, grid, ("a", "b"), steps)
    assert snap_compare(app, terminal_size=(80, 24))


def test_robot_lab_after_a_key(snap_compare: SnapCompare) -> None:
    link = StaticLabLink()
    app = make_lab_app(link)
    assert snap_compare(app, press=["i"], terminal_size=(120, 40))
    assert link.sent[0] == (0.5, 0.0, 0.0, 0.0)


def test_robot_lab_at_80x24_robot_panel_first(snap_compare: SnapCompare) -> None:
    assert snap_compare(make_lab_app(StaticLabLink()), terminal_size=(80, 24))
