"""Each display's state from messages and tf: what it draws in the fixed frame and its status
in rviz's words (no terminal, no network)."""

from __future__ import annotations

import numpy as np
import pytest

from rosx_commands.rviz.displays.map import PALETTES
from rosx_commands.rviz.manager import Manager
from rosx_commands.rviz.primitives import Layer
from tests.support.rviz import NOW, config, occupancy, robot_tf, scan
from tests.support.rviz_messages import cloud


def drawn(manager: Manager, index: int = 0, metres_per_pixel: float = 0.05) -> Layer:
    return manager.layers(NOW, metres_per_pixel)[index]


def test_a_silent_topic_says_no_messages_received() -> None:
    manager = Manager(config("{Class: rviz/LaserScan, Name: Scan, Topic: /scan}"), robot_tf())
    drawn(manager)
    assert manager.displays[0].summary == "No messages received"


def test_a_frame_without_a_transform_says_so_in_rviz_words() -> None:
    manager = Manager(config("{Class: rviz/LaserScan, Name: Scan, Topic: /scan}"), robot_tf())
    display = manager.displays[0]
    manager.receive(display, scan("camera_link"), NOW)
    assert drawn(manager).points == []
    assert display.summary == "No transform from [camera_link] to [map]"
    manager.set_fixed_frame("base_link")  # rviz starts over when the fixed frame changes
    assert display.summary == "No messages received"


def test_laser_scan_points_land_in_the_fixed_frame() -> None:
    manager = Manager(config("{Class: rviz/LaserScan, Name: Scan, Topic: /scan}"), robot_tf())
    display = manager.displays[0]
    manager.receive(display, scan(), NOW)
    layer = drawn(manager)
    (points,) = layer.points
    assert len(points.xy) == 179  # the beam beyond range_max and the NaN are not drawn
    assert display.summary == "Showing [179] points from [1] messages"
    # The robot faces +y at (1.5, 0.5) in map; the laser is 0.1 m ahead of it: the beam
    # straight ahead (index 90) hits 2 m further along +y, the last one 2 m to its left.
    assert points.xy[88] == pytest.approx((1.5, 0.5 + 0.1 + 2.0), abs=1e-9)
    assert points.xy[-1] == pytest.approx((1.5 - 2.0, 0.6), abs=1e-9)
    assert points.colours is not None  # intensities, in rviz's rainbow
    assert tuple(points.colours[0]) == (255, 0, 255)
    assert tuple(points.colours[-1]) == (255, 0, 0)


def test_decay_time_keeps_older_scans() -> None:
    text = "{Class: rviz/LaserScan, Name: Scan, Topic: /scan, Decay Time: 1}"
    manager = Manager(config(text), robot_tf())
    display = manager.displays[0]
    manager.receive(display, scan(), NOW)
    manager.receive(display, scan(), NOW + 0.5)
    assert len(drawn(manager).points) == 2
    assert manager.expire(NOW + 1.2)
    assert len(drawn(manager).points) == 1


def test_map_samples_rvizs_palettes_at_the_view() -> None:
    manager = Manager(config("{Class: rviz/Map, Name: Map, Topic: /map, Alpha: 1}"), robot_tf())
    display = manager.displays[0]
    assert display.summary == "No messages received"
    manager.receive(display, occupancy(), NOW)
    (image,) = drawn(manager).images
    x = np.array([0.0, -3.95, 10.0, -3.5])
    y = np.array([0.0, 0.0, 0.0, -2.5])
    colours, alphas = image.sample(x, y, 0.05)
    assert colours.tolist() == [[255, 255, 255], [0, 0, 0], [255, 255, 255], [0x70, 0x89, 0x86]]
    assert alphas.tolist() == [1.0, 1.0, 0.0, 1.0]  # outside the map nothing shows
    assert display.summary == "OK"


def test_a_zoomed_out_map_keeps_its_walls() -> None:
    manager = Manager(config("{Class: rviz/Map, Name: Map, Topic: /map}"), robot_tf())
    manager.receive(manager.displays[0], occupancy(), NOW)
    (image,) = drawn(manager).images
    # 0.8 m pixels: the one-cell wall at x = -3.95 still shows in the pixel over it.
    colours, alphas = image.sample(np.array([-3.7]), np.array([0.5]), 0.8)
    assert colours.tolist() == [[0, 0, 0]]
    assert alphas.tolist() == [pytest.approx(0.7)]  # rviz's default Alpha


def test_costmap_colours() -> None:
    assert PALETTES["costmap"][0][100].tolist() == [255, 0, 255]
    assert PALETTES["costmap"][0][99].tolist() == [0, 255, 255]
    assert PALETTES["costmap"][1][0] == 0.0  # free space is see-through


def test_a_map_of_the_wrong_size_is_an_error() -> None:
    manager = Manager(config("{Class: rviz/Map, Name: Map, Topic: /map}"), robot_tf())
    msg = occupancy()
    msg.info.width = 81
    manager.receive(manager.displays[0], msg, NOW)
    assert manager.displays[0].summary.startswith("Data size doesn't match width*height")


def test_grid_lines_around_its_reference_frame() -> None:
    text = (
        "{Class: rviz/Grid, Name: Grid, Plane Cell Count: 4, Cell Size: 0.5, Reference Frame: odom}"
    )
    manager = Manager(config(text), robot_tf())
    (segments,) = drawn(manager).segments
    assert segments.ends.shape == (10, 2, 2)
    xs = sorted({round(float(x), 6) for x in segments.ends[:5, :, 0].ravel()})
    assert xs == [0.0, 0.5, 1.0, 1.5, 2.0]  # odom is 1 m along x of map
    assert segments.colour == (160, 160, 164)
    assert segments.alpha == 0.5


def test_tf_draws_every_frame_with_its_name() -> None:
    manager = Manager(config("{Class: rviz/TF, Name: TF}"), robot_tf())
    layer = drawn(manager)
    labels = {label.text: (round(label.x, 6), round(label.y, 6)) for label in layer.labels}
    assert labels == {"map": (0, 0), "odom": (1, 0), "base_link": (1.5, 0.5), "laser": (1.5, 0.6)}
    assert manager.displays[0].summary == "OK (4 frames)"


@pytest.mark.parametrize("everything", ["false", "true"])
def test_tf_hides_only_the_frames_its_config_turns_off(everything: str) -> None:
    # rviz saves "All Enabled: false" once any frame was unticked (turtle_tf2's own config
    # has it, listing none): frames discovered later start enabled all the same.
    frames = f"{{All Enabled: {everything}, odom: {{Value: false}}, laser: {{Value: true}}}}"
    manager = Manager(config(f"{{Class: rviz/TF, Name: TF, Frames: {frames}}}"), robot_tf())
    assert {label.text for label in drawn(manager).labels} == {"map", "base_link", "laser"}
    assert manager.displays[0].summary == "OK (3 frames)"


def test_tf_warns_about_frames_it_cannot_place() -> None:
    core = robot_tf()
    core.set("world", "elsewhere", 0, (0, 0, 0, 0, 0, 0, 1), is_static=True)
    manager = Manager(config("{Class: rviz/TF, Name: TF}"), core)
    drawn(manager)
    assert manager.displays[0].summary == "No transform from [elsewhere] to frame [map]"


def test_point_cloud2_projects_and_colours_its_points() -> None:
    manager = Manager(config("{Class: rviz/PointCloud2, Name: Cloud, Topic: /points}"), robot_tf())
    display = manager.displays[0]
    pts = [(1.0, 0.0, 5.0, 0xFF0000), (float("nan"), 0.0, 0.0, 0), (0.0, 2.0, 0.0, 0x00FF00)]
    manager.receive(display, cloud(pts), NOW)
    (points,) = drawn(manager).points
    # base_link is at (1.5, 0.5) facing +y: its x is map's +y, its y map's -x.
    assert points.xy.tolist() == [pytest.approx([1.5, 1.5]), pytest.approx([-0.5, 0.5])]
    assert points.colours is not None
    assert points.colours.tolist() == [[255, 0, 0], [0, 255, 0]]
    assert display.summary == "Showing [2] points from [1] messages"


def test_a_cloud_without_xyz_is_an_error() -> None:
    manager = Manager(config("{Class: rviz/PointCloud2, Name: Cloud, Topic: /points}"), robot_tf())
    msg = cloud([(0.0, 0.0, 0.0, 0)])
    msg.fields = msg.fields[1:]  # type: ignore[attr-defined]
    manager.receive(manager.displays[0], msg, NOW)
    drawn(manager)
    assert manager.displays[0].summary == "PointCloud2 message has no x, y and z fields"


def test_a_disabled_display_draws_nothing() -> None:
    manager = Manager(config("{Class: rviz/TF, Name: TF, Enabled: false}"), robot_tf())
    assert drawn(manager) == Layer()
    assert manager.displays[0].summary == "disabled"
    manager.toggle(0)
    assert drawn(manager).labels
