"""turtlesim_view's model: a pond rebuilt from poses and colour sensors; ponds found on a graph."""

from __future__ import annotations

from rosx_turtle.engine.constants import DEFAULT_BACKGROUND, DEFAULT_PEN
from rosx_turtle.view.remote import RemotePond
from rosx_turtle.view.scene import WORLD_SIZE, TurtlePose
from rosx_turtle.viewer import find_ponds

START = 5.544444561004639


def _pixel(pond: RemotePond, x: float, y: float) -> tuple[int, ...]:
    canvas = pond.scene().canvas
    return tuple(int(c) for c in canvas[round((WORLD_SIZE - y) * 45), round(x * 45)])


def test_a_turtle_seen_moving_with_its_pen_leaves_a_trail_in_the_sensors_colour() -> None:
    pond = RemotePond()
    pond.set_colour("turtle1", DEFAULT_PEN)
    pond.set_pose("turtle1", TurtlePose("turtle1", START, START, 0.0))
    pond.set_pose("turtle1", TurtlePose("turtle1", START + 0.5, START, 0.0))
    assert _pixel(pond, START + 0.25, START) == DEFAULT_PEN
    assert _pixel(pond, START + 0.25, START + 1.0) == DEFAULT_BACKGROUND
    scene = pond.scene()
    assert [t.x for t in scene.turtles] == [START + 0.5]
    assert pond.scene() is scene  # nothing changed: the same scene


def test_no_trail_with_the_pen_off_or_across_a_jump() -> None:
    pond = RemotePond((10, 20, 30))
    pond.set_colour("t", (10, 20, 30))  # the sensor sees the background: the pen is off
    pond.set_pose("t", TurtlePose("t", 1.0, 1.0, 0.0))
    pond.set_pose("t", TurtlePose("t", 1.5, 1.0, 0.0))
    assert _pixel(pond, 1.25, 1.0) == (10, 20, 30)
    pond.set_colour("t", (255, 0, 0))
    pond.set_pose("t", TurtlePose("t", 9.0, 9.0, 0.0))  # a teleport
    assert _pixel(pond, 5.0, 5.0) == (10, 20, 30)
    pond.forget("t")
    assert pond.turtles == [] and pond.scene().turtles == ()


def test_find_ponds_groups_turtles_by_the_turtlesim_publishing_them() -> None:
    types = [
        ["/turtlesim1/turtle1/pose", "turtlesim/Pose"],
        ["/turtlesim1/t2/pose", "turtlesim/Pose"],
        ["/turtlesim2/turtle1/pose", "turtlesim/Pose"],
        ["/other/pose", "geometry_msgs/Pose"],
        ["/rosout", "rosgraph_msgs/Log"],
    ]
    publishers = [
        ["/turtlesim1/turtle1/pose", ["/turtlesim1/sim"]],
        ["/turtlesim1/t2/pose", ["/turtlesim1/sim"]],
        ["/turtlesim2/turtle1/pose", ["/turtlesim2/sim"]],
        ["/other/pose", ["/robot"]],
        ["/rosout", ["/turtlesim1/sim"]],
    ]
    assert find_ponds(types, publishers) == {
        "/turtlesim1/sim": {"t2": "/turtlesim1/t2", "turtle1": "/turtlesim1/turtle1"},
        "/turtlesim2/sim": {"turtle1": "/turtlesim2/turtle1"},
    }
