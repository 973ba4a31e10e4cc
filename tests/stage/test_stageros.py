"""stageros in this process: its topics, frames, services and parameters, seen through rosx's node API."""

from __future__ import annotations

import math
import threading
from collections.abc import Callable
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from rosx_turtle.stage.node.stageros import StageNode
from tests.support.procs import wait_for
from tests.support.stage_worlds import room

Odometry = get_message_class("nav_msgs/Odometry")
LaserScan = get_message_class("sensor_msgs/LaserScan")
TFMessage = get_message_class("tf2_msgs/TFMessage")
Clock = get_message_class("rosgraph_msgs/Clock")
Twist = get_message_class("geometry_msgs/Twist")
Pose = get_message_class("geometry_msgs/Pose")
Empty = get_service_class("std_srvs/Empty")

MakeStage = Callable[..., tuple[StageNode, Any]]


class Inbox:
    """Messages of one topic as they arrive."""

    def __init__(self, node: Node, topic: str, kind: Any) -> None:
        self.items: list[Any] = []
        self.lock = threading.Lock()
        node.subscribe(topic, kind, self._add, queue_size=100)

    def _add(self, message: Any) -> None:
        with self.lock:
            self.items.append(message)

    def wait(self, count: int = 1, predicate: Callable[[Any], bool] = lambda m: True) -> Any:
        def ready() -> bool:
            with self.lock:
                return sum(1 for m in self.items if predicate(m)) >= count

        wait_for(ready, what="messages")
        with self.lock:
            return [m for m in self.items if predicate(m)][-1]


def yaw_of(q: Any) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def test_topics_frames_and_use_sim_time(
    make_stage: MakeStage, make_node: Callable[..., Node]
) -> None:
    _, out = make_stage(room('pose [ 1 2 0 90 ] name "era"'))
    client = make_node("/probe")
    assert client.params.get("/use_sim_time") is True
    odom = Inbox(client, "/odom", Odometry)
    scans = Inbox(client, "/base_scan", LaserScan)
    clock = Inbox(client, "/clock", Clock)
    truth = Inbox(client, "/base_pose_ground_truth", Odometry)
    message = odom.wait()
    assert (message.header.frame_id, message.child_frame_id) == ("odom", "base_footprint")
    assert (message.pose.pose.position.x, message.pose.pose.position.y) == pytest.approx((1.0, 2.0))
    assert yaw_of(message.pose.pose.orientation) == pytest.approx(math.pi / 2)
    assert truth.wait().header.frame_id == "odom"
    assert clock.wait(2).clock.to_sec() > 0
    scan = scans.wait()
    assert scan.header.frame_id == "base_laser_link"
    # The LaserScan's fields agree with each other.
    count = round((scan.angle_max - scan.angle_min) / scan.angle_increment) + 1
    assert len(scan.ranges) == count == len(scan.intensities) == 181
    assert scan.angle_min == pytest.approx(-math.pi / 2)
    assert all(scan.range_min <= r <= scan.range_max or math.isinf(r) for r in scan.ranges)
    assert (scan.range_min, scan.range_max) == pytest.approx((0.05, 8.0))
    assert out.getvalue().splitlines()[0].endswith('Subscribed to Stage position model "era"')


def test_odometry_and_tf_agree(make_stage: MakeStage, make_node: Callable[..., Node]) -> None:
    make_stage(room('pose [ -1 0.5 0 30 ] name "era"'))
    client = make_node("/probe")
    odom = Inbox(client, "/odom", Odometry)
    tf = Inbox(client, "/tf", TFMessage)
    message = tf.wait()
    stamp = message.transforms[0].header.stamp
    frames = {(t.header.frame_id, t.child_frame_id): t for t in message.transforms}
    assert set(frames) == {
        ("odom", "base_footprint"),
        ("base_footprint", "base_link"),
        ("base_link", "base_laser_link"),
    }
    same = odom.wait(predicate=lambda m: m.header.stamp == stamp)
    moved = frames["odom", "base_footprint"].transform
    assert (moved.translation.x, moved.translation.y) == pytest.approx(
        (same.pose.pose.position.x, same.pose.pose.position.y)
    )
    assert yaw_of(moved.rotation) == pytest.approx(yaw_of(same.pose.pose.orientation))
    assert frames["base_link", "base_laser_link"].transform.translation.z == pytest.approx(0.2)


def test_cmd_vel_moves_the_robot_and_the_watchdog_stops_it(
    make_stage: MakeStage, make_node: Callable[..., Node]
) -> None:
    make_stage(room(), "_base_watchdog_timeout:=0.5")
    client = make_node("/driver")
    odom = Inbox(client, "/odom", Odometry)
    odom.wait()
    publisher = client.advertise("/cmd_vel", Twist, queue_size=1)
    wait_for(lambda: publisher.get_num_connections() > 0, what="stageros subscribed")
    publisher.publish(Twist(linear=get_message_class("geometry_msgs/Vector3")(x=0.4)))
    moving = odom.wait(predicate=lambda m: m.twist.twist.linear.x == pytest.approx(0.4))
    assert moving.child_frame_id == "base_footprint"
    stopped = odom.wait(
        predicate=lambda m: m.header.stamp > moving.header.stamp and m.twist.twist.linear.x == 0.0
    )
    # 0.5 s of simulated time at 0.4 m/s, in 0.1 s steps: 0.2 m.
    assert stopped.pose.pose.position.x == pytest.approx(0.2, abs=1e-6)


def test_reset_positions_and_cmd_pose(
    make_stage: MakeStage, make_node: Callable[..., Node]
) -> None:
    _, out = make_stage(room())
    client = make_node("/teleporter")
    odom = Inbox(client, "/odom", Odometry)
    odom.wait()
    publisher = client.advertise("/cmd_pose", Pose, queue_size=1)
    wait_for(lambda: publisher.get_num_connections() > 0, what="stageros subscribed")
    target = Pose()
    target.position.x, target.position.y = 2.0, -1.0
    target.orientation.z, target.orientation.w = math.sin(0.5), math.cos(0.5)
    publisher.publish(target)
    there = odom.wait(predicate=lambda m: m.pose.pose.position.x == pytest.approx(2.0))
    assert yaw_of(there.pose.pose.orientation) == pytest.approx(1.0)
    client.service_client("/reset_positions", Empty).call(Empty._request_class(), timeout=10)
    back = odom.wait(
        predicate=lambda m: m.header.stamp > there.header.stamp and m.pose.pose.position.x == 0.0
    )
    assert back.pose.pose.position.y == 0.0
    assert "Resetting stage!" in out.getvalue()


def test_several_robots_under_robot_n_or_model_names(
    make_stage: MakeStage, make_node: Callable[..., Node]
) -> None:
    two = room('pose [ 0 0 0 0 ] name "era"', 'pose [ 2 0 0 0 ] name "era2"')
    make_stage(two)
    client = make_node("/probe")
    scans = Inbox(client, "/robot_1/base_scan", LaserScan)
    odom = Inbox(client, "/robot_1/odom", Odometry)
    assert scans.wait().header.frame_id == "robot_1/base_laser_link"
    message = odom.wait()
    assert (message.header.frame_id, message.child_frame_id) == (
        "robot_1/odom",
        "robot_1/base_footprint",
    )
    assert message.pose.pose.position.x == pytest.approx(2.0)
    make_stage(
        two.replace('"era"', '"alpha"'), "__name:=named", "__ns:=/other", use_model_names=True
    )
    named = Inbox(client, "/alpha/odom", Odometry)
    assert named.wait().child_frame_id == "alpha/base_footprint"


def test_speed_runs_the_clock_faster(make_stage: MakeStage, make_node: Callable[..., Node]) -> None:
    make_stage(room(), speed=20.0)
    client = make_node("/probe")
    clock = Inbox(client, "/clock", Clock)
    first = clock.wait()
    later = clock.wait(predicate=lambda m: m.clock.to_sec() >= first.clock.to_sec() + 2.0)
    assert later.clock.to_sec() >= first.clock.to_sec() + 2.0


def test_a_wander_script_never_enters_an_obstacle(
    make_stage: MakeStage, make_node: Callable[..., Node]
) -> None:
    """A course's first obstacle-avoidance node: forward while the way ahead is clear, else turn."""
    from rosx.packages.crawl import PREFIX

    world = (
        PREFIX / "share" / "turtlebot3_stage" / "worlds" / "turtlebot3_world.world"
    ).read_text()
    world = world.replace('bitmap "../maps/', f'bitmap "{PREFIX}/share/turtlebot3_stage/maps/')
    stage, _ = make_stage(world, speed=10.0)
    stalls: list[bool] = []
    stage.add_step_listener(lambda report: stalls.append(bool(report.stalled[0])))
    client = make_node("/wander")
    publisher = client.advertise("/cmd_vel", Twist, queue_size=1)
    turning = {"left": 0}

    def on_scan(scan: Any) -> None:
        # The 90 beams around the front (the laser starts behind the robot, at -180°).
        ahead = min(scan.ranges[135:225])
        twist = Twist()
        if ahead < 0.45:
            twist.angular.z = 1.2
            turning["left"] += 1
        else:
            twist.linear.x = 0.22
        publisher.publish(twist)

    client.subscribe("/base_scan", LaserScan, on_scan, queue_size=1)
    odom = Inbox(client, "/base_pose_ground_truth", Odometry)
    first = odom.wait()
    # 60 s of simulated time.
    last = odom.wait(
        predicate=lambda m: m.header.stamp.to_sec() >= first.header.stamp.to_sec() + 60
    )
    start = (first.pose.pose.position.x, first.pose.pose.position.y)
    end = (last.pose.pose.position.x, last.pose.pose.position.y)
    assert math.dist(start, end) > 0.3 or turning["left"] > 0  # it moved
    assert turning["left"] > 0  # it met a wall or a pillar and turned away
    assert not any(stalls)  # and never bumped into one
