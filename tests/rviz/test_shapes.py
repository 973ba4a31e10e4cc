"""The displays of poses, paths, polygons, markers, robot models, images and axes: what each
draws in the fixed frame and its status, from messages and tf set by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rosx.msg.codec.classes import get_message_class
from rosx_commands.rviz.displays.image import to_rgb
from rosx_commands.rviz.displays.markers import CUBE, DELETE, DELETEALL, LINE_STRIP
from rosx_commands.rviz.manager import Manager
from rosx_commands.rviz.primitives import Layer
from tests.support.rviz import NOW, config, message, robot_tf
from tests.support.rviz_messages import URDF, image, marker, pose_msg


def drawn(manager: Manager, index: int = 0, metres_per_pixel: float = 0.01) -> Layer:
    return manager.layers(NOW, metres_per_pixel)[index]


def one(display: str) -> Manager:
    return Manager(config(display), robot_tf())


@pytest.mark.parametrize("name", ["rviz/Pose", "rviz/PoseStamped"])
def test_pose_is_an_arrow_in_the_fixed_frame(name: str) -> None:
    manager = one(f"{{Class: {name}, Name: Goal, Topic: /goal}}")
    manager.receive(manager.displays[0], pose_msg(1.0, 2.0, math.pi / 2), NOW)
    layer = drawn(manager)
    (shaft,) = layer.segments
    (head,) = layer.polygons
    # odom is 1 m along map's x: the arrow starts at (2, 2) and points up +y, 1.3 m long.
    assert shaft.ends[0].tolist() == [pytest.approx([2.0, 2.0]), pytest.approx([2.0, 3.0])]
    assert head.corners[0] == pytest.approx([2.0, 3.3])
    assert shaft.colour == (255, 25, 0)
    assert manager.displays[0].summary == "OK"


def test_pose_array_draws_flat_arrows() -> None:
    manager = one("{Class: rviz/PoseArray, Name: Particles, Topic: /particlecloud}")
    msg = message("geometry_msgs/PoseArray", "map")
    pose_class = get_message_class("geometry_msgs/Pose")
    for x in range(3):
        pose = pose_class()
        pose.position.x, pose.orientation.w = float(x), 1.0
        msg.poses.append(pose)
    manager.receive(manager.displays[0], msg, NOW)
    segments = drawn(manager).segments
    assert len(segments) == 3  # each arrow: a line and two barbs
    assert segments[2].ends[0].tolist() == [[2.0, 0.0], [pytest.approx(2.3), 0.0]]


def test_odometry_keeps_poses_that_moved_enough() -> None:
    manager = one("{Class: rviz/Odometry, Name: Odom, Topic: /odom, Keep: 3}")
    display = manager.displays[0]
    for x in (0.0, 0.05, 0.2, 0.4, 0.6):  # 0.05 is within the 0.1 m tolerance
        msg = message("nav_msgs/Odometry", "odom")
        msg.pose.pose.position.x, msg.pose.pose.orientation.w = x, 1.0
        manager.receive(display, msg, NOW)
    starts = [round(float(layer.ends[0, 0, 0]), 6) for layer in drawn(manager).segments]
    assert starts == [1.2, 1.4, 1.6]  # the last three kept, in map (odom is at x = 1)


def test_path_joins_its_poses() -> None:
    manager = one("{Class: rviz/Path, Name: Plan, Topic: /plan}")
    msg = message("nav_msgs/Path", "map")
    for x, y in ((0, 0), (1, 0), (1, 1)):
        stamped = pose_msg(float(x), float(y), 0.0, "map")
        msg.poses.append(stamped)
    manager.receive(manager.displays[0], msg, NOW)
    (line,) = drawn(manager).segments
    assert line.ends.tolist() == [[[0, 0], [1, 0]], [[1, 0], [1, 1]]]
    assert line.colour == (25, 255, 0)


def test_polygon_is_closed() -> None:
    manager = one("{Class: rviz/Polygon, Name: Footprint, Topic: /footprint}")
    msg = message("geometry_msgs/PolygonStamped", "base_link")
    point_class = get_message_class("geometry_msgs/Point32")
    for x, y in ((0.2, 0.1), (0.2, -0.1), (-0.2, -0.1)):
        msg.polygon.points.append(point_class(x=x, y=y, z=0.0))
    manager.receive(manager.displays[0], msg, NOW)
    (outline,) = drawn(manager).segments
    assert len(outline.ends) == 3
    assert outline.ends[2, 1] == pytest.approx(outline.ends[0, 0])  # back to the start


def test_marker_shapes_from_above() -> None:
    manager = one("{Class: rviz/Marker, Name: Markers, Marker Topic: /visualization_marker}")
    display = manager.displays[0]
    assert display.topic == "/visualization_marker"
    point_class = get_message_class("geometry_msgs/Point")
    for kind in range(12):
        msg = marker(kind, kind)
        msg.pose.position.x = float(kind)
        msg.points = [point_class(x=0.0, y=0.0, z=0.0), point_class(x=0.0, y=1.0, z=0.0),
                      point_class(x=1.0, y=1.0, z=0.0)]  # fmt: skip
        msg.text = "hello"
        manager.receive(display, msg, NOW)
    layer = drawn(manager)
    cube = layer.polygons[1]  # after the arrow's head
    assert sorted(map(tuple, cube.corners.tolist())) == [
        (0.5, -0.5),
        (0.5, 0.5),
        (1.5, -0.5),
        (1.5, 0.5),
    ]
    assert [label.text for label in layer.labels] == ["hello"]
    assert layer.labels[0].x == 9.0 and layer.labels[0].centred
    assert display.summary == "Marker type MESH_RESOURCE is not drawn here"


def test_marker_lifetimes_delete_and_deleteall() -> None:
    manager = one("{Class: rviz/MarkerArray, Name: Markers, Marker Topic: /markers}")
    display = manager.displays[0]
    array = message("visualization_msgs/MarkerArray")
    short = marker(CUBE, 1)
    short.lifetime.secs = 2
    array.markers = [short, marker(CUBE, 2), marker(LINE_STRIP, 3)]
    manager.receive(display, array, NOW)
    assert len(drawn(manager).polygons) == 2
    assert display.summary == "OK (3 markers)"
    assert manager.expire(NOW + 2.5)
    assert len(drawn(manager).polygons) == 1
    array.markers = [marker(CUBE, 2, DELETE)]
    manager.receive(display, array, NOW)
    assert drawn(manager).polygons == []
    array.markers = [marker(CUBE, 4), marker(0, 0, DELETEALL)]
    manager.receive(display, array, NOW)
    assert drawn(manager) == Layer()


def test_robot_model_outlines_links_at_their_frames() -> None:
    manager = one("{Class: rviz/RobotModel, Name: Robot}")
    display = manager.displays[0]
    manager.receive(display, URDF, NOW)
    (body,) = drawn(manager).polygons  # the wheel has no frame in tf; the mesh is not drawn
    assert body.colour == (51, 51, 51)
    assert body.corners.mean(axis=0) == pytest.approx((1.5, 0.5 - 0.032))  # base_link faces +y
    assert display.summary == "No transform from [wheel] to [map]"


def test_robot_model_without_a_description_says_rvizs_words() -> None:
    manager = one("{Class: rviz/RobotModel, Name: Robot, Robot Description: my_robot}")
    manager.receive(manager.displays[0], None, NOW)
    assert manager.displays[0].summary == (
        "Parameter [my_robot] does not exist, and was not found by searchParam()"
    )
    manager.receive(manager.displays[0], "<robot", NOW)
    assert manager.displays[0].summary == "Failed to parse URDF model"


def test_images_become_rgb() -> None:
    rgb = np.array([[[255, 0, 0], [0, 0, 255]]], dtype=np.uint8)
    assert to_rgb(image("rgb8", rgb)).tolist() == rgb.tolist()
    assert to_rgb(image("bgr8", rgb)).tolist() == [[[0, 0, 255], [255, 0, 0]]]
    depth = np.array([[1.0, 3.0, np.nan]], dtype=np.float32)
    assert to_rgb(image("32FC1", depth))[0, :, 0].tolist() == [0, 255, 0]


def test_the_image_display_keeps_the_latest_and_names_bad_encodings() -> None:
    manager = one("{Class: rviz/Image, Name: Camera, Image Topic: /camera/image_raw}")
    display = manager.displays[0]
    assert display.topic == "/camera/image_raw"
    assert display.summary == "No messages received"
    manager.receive(display, image("mono8", np.zeros((4, 6), dtype=np.uint8)), NOW)
    assert display.summary == "OK (6x4)"
    manager.receive(display, image("bayer_rggb8", np.zeros((4, 6), dtype=np.uint8)), NOW)
    assert display.summary == "Unsupported image encoding [bayer_rggb8]"


def test_axes_at_the_reference_frame() -> None:
    manager = one("{Class: rviz/Axes, Name: Base, Reference Frame: base_link, Length: 0.5}")
    x_axis, y_axis = drawn(manager).segments
    assert x_axis.ends[0].tolist() == [pytest.approx([1.5, 0.5]), pytest.approx([1.5, 1.0])]
    assert y_axis.colour == (0, 255, 0)
