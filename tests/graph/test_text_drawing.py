"""The text drawing's namespace frames and the stretches it records for each edge."""

from __future__ import annotations

from rosx.graph.builder import build
from rosx.graph.options import GraphOptions, Mode
from rosx.graph.state import GraphState
from rosx.graph.text import Drawing, draw
from rosx.graph.view import Edge
from tests.support.graph_states import lab1

#: A robot's arm and base in nested namespaces, a laser and two nodes at the root.
PUBS = {
    "/robot/arm/cmd": ("/robot/arm/ctl", "/teleop"),
    "/robot/base/cmd": ("/teleop",),
    "/robot/arm/state": ("/robot/arm/driver",),
    "/scan": ("/robot/laser",),
}
SUBS = {
    "/robot/arm/cmd": ("/robot/arm/driver",),
    "/robot/base/cmd": ("/robot/base/driver",),
    "/robot/arm/state": ("/robot/arm/ctl", "/viewer"),
    "/scan": ("/viewer",),
}


def robot(depth: int, mode: Mode = Mode.ALL) -> Drawing:
    return draw(build(GraphState(PUBS, SUBS), GraphOptions(mode=mode, group_depth=depth)))


def inside(outer: object, inner: object) -> bool:
    o, i = outer, inner
    return bool(
        o.x < i.x  # type: ignore[attr-defined]
        and o.y < i.y  # type: ignore[attr-defined]
        and i.x + i.width < o.x + o.width  # type: ignore[attr-defined]
        and i.y + i.height < o.y + o.height  # type: ignore[attr-defined]
    )


def test_each_vertex_sits_inside_a_frame_per_enclosing_namespace() -> None:
    drawing = robot(2)
    for vertex_id, box in drawing.boxes.items():
        name = vertex_id[2:]
        parts = name.split("/")
        expected = ["/".join(parts[:i]) for i in range(2, min(4, len(parts)))]
        holding = [f.namespace for f in drawing.frames if inside(f.box, box)]
        assert sorted(holding) == expected, name


def test_a_namespace_is_one_frame_per_column_with_its_members_together() -> None:
    drawing = robot(2)
    arm = [f for f in drawing.frames if f.namespace == "/robot/arm"]
    arm_topics = {"t:/robot/arm/cmd", "t:/robot/arm/state"}
    assert len(arm) == len({f.box.x for f in arm}) == 4  # one per column: cmd, driver, state, ctl
    for frame in arm:
        members = [i for i, b in drawing.boxes.items() if inside(frame.box, b)]
        assert members and all(i[2:].startswith("/robot/arm/") for i in members)
    assert sum(inside(f.box, drawing.boxes[t]) for f in arm for t in arm_topics) == 2


def test_frames_nest_and_carry_their_namespace_on_the_top_border() -> None:
    drawing = robot(2)
    robot_frames = [f for f in drawing.frames if f.namespace == "/robot"]
    for frame in (f for f in drawing.frames if f.namespace == "/robot/arm"):
        assert any(inside(outer.box, frame.box) for outer in robot_frames)
        top = drawing.lines[frame.box.y][frame.box.x : frame.box.x + frame.box.width]
        assert top.startswith("┌╌ /robot/arm ╌") and top.endswith("╌┐")


def test_group_depth_sets_how_deep_frames_go() -> None:
    assert {f.namespace for f in robot(1).frames} == {"/robot"}
    assert robot(0).frames == ()
    assert "╎" not in str(robot(0))
    assert set(robot(0).boxes) == set(robot(2).boxes)


def test_every_edge_has_the_stretches_it_is_drawn_along() -> None:
    drawing = draw(build(lab1(), GraphOptions(mode=Mode.ACTIVE, group_depth=0)))
    line = drawing.lines[1]
    into_topic = drawing.paths[Edge("n:/teleop_turtle", "t:/turtle1/cmd_vel")]
    columns = {x for y0, y1, x0, x1 in into_topic for x in range(x0, x1 + 1) if y0 == y1 == 1}
    assert "".join(line[x] for x in sorted(columns)) == "─────▶"
    assert set(drawing.paths) == {
        Edge("n:/teleop_turtle", "t:/turtle1/cmd_vel"),
        Edge("t:/turtle1/cmd_vel", "n:/turtlesim"),
    }


def test_a_labelled_edge_owns_its_label_and_both_halves() -> None:
    drawing = draw(build(lab1(), GraphOptions(mode=Mode.NODES)))
    (edge,) = drawing.paths
    assert edge == Edge("n:/teleop_turtle", "n:/turtlesim", "/turtle1/cmd_vel")
    line = drawing.lines[1]
    first = min(x0 for _, _, x0, _ in drawing.paths[edge])
    last = max(x1 for _, _, _, x1 in drawing.paths[edge])
    assert line[first : last + 1] == "────── /turtle1/cmd_vel ─────▶"
