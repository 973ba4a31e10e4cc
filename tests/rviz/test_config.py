"""rviz's ``.rviz`` files read: displays (groups too), the fixed frame, the tools and the view;
broken files refused in one line; rviz's own example configs loaded with their unsupported
displays listed (skipped without the fetched rviz repository)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosx.packages.crawl import PREFIX
from rosx.tf.core import BufferCore
from rosx_commands.rviz.config import ConfigError, load_config, parse_config
from rosx_commands.rviz.manager import Manager
from rosx_commands.rviz.tools import configured
from rosx_commands.rviz.view import View
from tests.support.fetched import fetched_file

TEXT = """\
Panels:
  - Class: rviz/Displays
Visualization Manager:
  Class: ""
  Displays:
    - Class: rviz/Grid
      Name: Floor
      Enabled: true
    - Class: rviz/Group
      Name: Robot
      Enabled: false
      Displays:
        - Class: rviz/LaserScan
          Name: Laser
          Topic: /base_scan
          Enabled: true
    - Class: rviz/Camera
      Name: Front camera
      Enabled: true
  Global Options:
    Background Color: 10; 20; 30
    Fixed Frame: /odom
  Tools:
    - Class: rviz/SetGoal
      Topic: /goal_here
  Views:
    Current:
      Class: rviz/TopDownOrtho
      Scale: 40
      X: 1.5
      Y: -2
      Angle: 0
"""


def test_displays_groups_fixed_frame_tools_and_view() -> None:
    config = parse_config(TEXT, "a.rviz")
    assert [(d.class_id, d.name, d.enabled, d.groups) for d in config.displays] == [
        ("rviz/Grid", "Floor", True, ()),
        ("rviz/LaserScan", "Laser", False, ("Robot",)),  # its group is off
        ("rviz/Camera", "Front camera", True, ()),
    ]
    assert config.displays[1].get("Topic") == "/base_scan"
    assert config.fixed_frame == "odom"  # tf2 has no leading slash; rviz strips it
    assert config.background == (10, 20, 30)
    assert [tool.topic for tool in configured(config.tools)] == [
        "/goal_here",
        "/initialpose",
        "/clicked_point",
    ]
    view = View.from_spec(config.view)
    view.resize(100, 60)
    assert (view.x, view.y, view.pixels_per_metre) == (1.5, -2.0, 5.0)  # Scale 40 / 8


def test_unsupported_classes_are_listed_and_never_subscribe() -> None:
    manager = Manager(parse_config(TEXT, "a.rviz"), BufferCore())
    camera = manager.displays[2]
    assert camera.summary == "unsupported"
    assert not camera.subscribes


def test_the_default_view_shows_at_least_three_metres_each_way() -> None:
    view = View.from_spec(None)
    for size in ((78, 44), (160, 70), (40, 200)):
        view = View.from_spec(None)
        view.resize(*size)
        reach_x = size[0] / 2 / view.pixels_per_metre
        reach_y = size[1] / 2 / view.pixels_per_metre
        assert min(reach_x, reach_y) >= 3.0
        assert view.point_at(size[0] / 2, size[1] / 2 - 1) == pytest.approx(
            (0.5 / view.pixels_per_metre, 0.5 / view.pixels_per_metre)
        )  # centred on the origin, x right and y up


@pytest.mark.parametrize(
    ("text", "line"),
    [
        ("Visualization Manager:\n  Displays:\n    - Class: rviz/Grid\n   Name: x\n", "(line 4)"),
        ("Visualization Manager: [unclosed\n", "(line 2)"),
        ("- just\n- a list\n", ""),
        ("Visualization Manager:\n  Displays: 3\n", "(line 2)"),
        ("Visualization Manager:\n  Displays:\n    - Name: no class\n", "(line 3)"),
    ],
)
def test_a_broken_file_is_one_line_naming_it(text: str, line: str) -> None:
    with pytest.raises(ConfigError) as raised:
        parse_config(text, "my config.rviz")
    message = str(raised.value)
    assert message.startswith("cannot load my config.rviz")
    assert "\n" not in message
    assert line in message


def test_a_missing_file_names_the_file(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match=r"^cannot load nothere\.rviz: no such file$"):
        load_config("nothere.rviz")
    with pytest.raises(ConfigError, match=r"it is a directory$"):
        load_config(str(tmp_path))


EXAMPLES = {
    # file in ros-visualization/rviz → (classes drawn, classes listed as unsupported)
    "default.rviz": ({"rviz/Grid"}, set()),
    "src/test/rviz_logo.rviz": (
        {"rviz/Grid", "rviz/Marker", "rviz/RobotModel", "rviz/TF"},
        {"rviz/InteractiveMarkers"},
    ),
    "src/test/tf_sync_frame.rviz": ({"rviz/TF", "rviz/Grid", "rviz/Axes"}, set()),
    "src/test/tf_sync_display.rviz": (
        {"rviz/TF", "rviz/Grid", "rviz/Axes", "rviz/PointCloud2"},
        set(),
    ),
}


@pytest.mark.parametrize("path", sorted(EXAMPLES))
def test_rvizs_example_configs_load_with_unsupported_displays_listed(
    path: str, tmp_path: Path
) -> None:
    file = fetched_file("ros-visualization/rviz", path, tmp_path)
    config = load_config(str(file))
    manager = Manager(config, BufferCore())
    drawn = {d.class_id for d in manager.displays if d.summary != "unsupported"}
    unsupported = {d.class_id for d in manager.displays if d.summary == "unsupported"}
    expected_drawn, expected_unsupported = EXAMPLES[path]
    assert expected_drawn <= drawn
    assert unsupported == expected_unsupported
    assert config.fixed_frame and not config.fixed_frame.startswith("/")


#: The configs the bundled packages install, as Noetic's (``rviz/`` of each package), and the
#: fixed frame each shows: ``rosrun rviz rviz -d `rospack find turtle_tf2`/rviz/turtle_rviz.rviz``
#: is the tf2 introduction's step.
BUNDLED = {
    "turtle_tf2/rviz/turtle_rviz.rviz": "world",
    "turtle_tf/rviz/turtle_rviz.rviz": "world",
    "turtlebot3_stage/rviz/turtlebot3_stage.rviz": "map",
}


def test_every_bundled_config_is_known() -> None:
    found = {str(p.relative_to(PREFIX / "share")) for p in (PREFIX / "share").glob("*/rviz/*.rviz")}
    assert found == set(BUNDLED)


@pytest.mark.parametrize("path", sorted(BUNDLED))
def test_the_bundled_configs_draw_every_display(path: str) -> None:
    config = load_config(str(PREFIX / "share" / path))
    assert config.fixed_frame == BUNDLED[path]
    core = BufferCore()
    core.set("world", "turtle1", 0, (5.5, 5.5, 0, 0, 0, 0, 1), is_static=True)
    core.set("world", "turtle2", 0, (4.0, 2.0, 0, 0, 0, 0, 1), is_static=True)
    manager = Manager(config, core)
    manager.layers(0.0, 0.05)
    assert [d.summary for d in manager.displays if d.summary == "unsupported"] == []
    if config.fixed_frame == "world":
        (tf,) = [d for d in manager.displays if d.class_id == "rviz/TF"]
        assert tf.summary == "OK (3 frames)"
