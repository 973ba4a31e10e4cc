"""Stage's world-file syntax and what rosx builds from it (`rosx_turtle.stage.world`)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from rosx_turtle.stage.world.load import read_world
from rosx_turtle.stage.world.model import build
from rosx_turtle.stage.world.worldfile import WorldFileError, parse
from tests.support.stage_worlds import export_stage_ros_worlds, room


def world_of(text: str, name: str = "t.world"):  # type: ignore[no-untyped-def]
    return build(parse(text, name))


def test_defines_nest_and_instances_override_their_defaults() -> None:
    world = world_of(room('pose [ 1 2 0 90 ] name "alpha" color "blue"'))
    (robot,) = world.robots
    assert robot.name == "alpha"
    assert robot.color == "blue"
    assert robot.size == (0.3, 0.3, 0.2)
    assert robot.pose == pytest.approx((1.0, 2.0, math.pi / 2))
    (laser,) = robot.lasers
    assert (laser.samples, laser.range_min, laser.range_max) == (181, 0.05, 8.0)
    assert laser.fov == pytest.approx(math.pi)
    assert laser.angle_increment == pytest.approx(math.pi / 180)
    assert [b.name for b in world.blocks] == ["east", "west", "north", "south"]
    assert world.ignored == ()


def test_world_properties_and_defaults() -> None:
    world = world_of("resolution 0.05\ninterval_sim 50\nposition ( )\n")
    assert (world.resolution, world.interval_sim) == (0.05, 0.05)
    (robot,) = world.robots
    assert robot.token == "position:0"
    assert robot.size == (0.4, 0.4, 1.0)
    assert (robot.drive, robot.localization) == ("diff", "gps")


def test_the_window_is_read_and_ignored_and_the_unknown_is_named_with_its_line() -> None:
    text = "window ( size [ 600 400 ] scale 20 )\nposition ( wheels 4 )\ncamera ( )\nfoo 1\n"
    world = world_of(text)
    assert world.ignored == (
        "t.world:4 unknown property 'foo' of world",
        "t.world:2 unknown property 'wheels' of position",
        "t.world:3 camera (a camera: not simulated)",
    )


def test_a_define_used_twice_is_reported_once() -> None:
    text = "define cam camera ( )\ndefine bot position ( cam ( ) )\nbot ( )\nbot ( )\n"
    assert world_of(text).ignored == ("t.world:2 cam (a camera: not simulated)",)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("position ( pose [ 1 2 ", "t.world:1: '[' without a matching ']'"),
        ("position (\n  size [ 1 2 3 ]\n", "t.world:2: missing ')' at the end of the file"),
        ("size [ 1 ] )", "t.world:1: ')' without a matching '('"),
        ("define bot ( )", "t.world:1: expected 'define NAME PARENT ( ... )'"),
        ('position ( pose [ 1 "a" 0 0 ] )', "t.world:1: 'pose' needs 4 numbers"),
        (
            '\n\nposition ( drive "car" localization "magic" )',
            't.world:3: localization "magic" is not "gps" or "odom"',
        ),
        (
            "position ( ranger ( sensor ( samples 0 ) ) )",
            "t.world:1: a laser needs samples >= 1, range min < max and fov >= 0",
        ),
        (
            'include "other.world"',
            "t.world:1: cannot include 'other.world': includes are not available here (other.world)",
        ),
    ],
)
def test_errors_name_the_file_and_line(text: str, message: str) -> None:
    with pytest.raises(WorldFileError) as error:
        world_of(text)
    assert str(error.value) == message


def test_includes_are_read_next_to_the_including_file(tmp_path: Path) -> None:
    (tmp_path / "robot.inc").write_text('define bot position ( drive "omni" )\n')
    (tmp_path / "main.world").write_text('include "robot.inc"\nbot ( name "o" )\n')
    (robot,) = read_world(tmp_path / "main.world").robots
    assert (robot.name, robot.drive) == ("o", "omni")
    (tmp_path / "loop.world").write_text('include "loop.world"\n')
    with pytest.raises(WorldFileError, match=r"loop\.world:1: includes nested too deep"):
        read_world(tmp_path / "loop.world")


def test_stage_ros_example_worlds_load(tmp_path: Path) -> None:
    folder = export_stage_ros_worlds(tmp_path)
    if folder is None:
        pytest.skip("stage_ros was not fetched (github:ros-simulation/stage_ros)")
    from rosx_turtle.stage.world.load import load_world

    worlds = {
        name: load_world(folder / name)
        for name in (
            "willow-erratic.world",
            "intense.world",
            "willow-four-erratics.world",
            "willow-four-erratics-multisensor.world",
        )
    }
    world, grid = worlds["willow-erratic.world"]
    (era,) = world.robots
    assert era.name == "era"
    assert era.pose == pytest.approx((-11.277, 23.266, math.pi))
    assert (era.lasers[0].samples, era.lasers[0].range_max) == (1081, 30.0)
    assert era.lasers[0].fov == pytest.approx(math.radians(270.25))
    assert grid.solid.sum() > 10_000  # the floor plan's walls are there
    four, _ = worlds["willow-four-erratics.world"]
    assert [r.name for r in four.robots] == ["era", "era2", "era3", "era4"]
    multi, _ = worlds["willow-four-erratics-multisensor.world"]
    assert [len(r.lasers) for r in multi.robots] == [2, 2, 2, 2]
    assert any("mycamera (a camera: not simulated)" in item for item in multi.ignored)
    intense, _ = worlds["intense.world"]
    assert [b.ranger_return for b in intense.blocks] == [-1.0, 50, 100, 250, 4000, 80000, 1000000]
