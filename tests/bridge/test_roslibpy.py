"""roslibpy (PyPI), a rosbridge client nobody here wrote, against the bridge: the turtle's pose,
driving it, ``/spawn``, rosapi, and a service the client serves that ``rosservice call`` reaches.

roslibpy runs on Twisted's reactor, which cannot restart in a process: clients are closed,
never terminated.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from typing import Any

import pytest

from tests.support.bridge import Running
from tests.support.cli import clean_environ, rosx

roslibpy = pytest.importorskip("roslibpy")


def wait_for(check: Callable[[], object], what: str, timeout: float = 10.0) -> Any:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = check()
        if value:
            return value
        time.sleep(0.02)
    raise AssertionError(f"timed out waiting for {what}")


@pytest.fixture
def client(running: Running) -> Iterator[Any]:
    ros = roslibpy.Ros(host="127.0.0.1", port=running.port)
    ros.run(timeout=10)
    yield ros
    ros.close()


def test_pose_arrives_and_the_turtle_drives(client: Any) -> None:
    poses: list[dict[str, float]] = []
    pose = roslibpy.Topic(client, "/turtle1/pose", "turtlesim/Pose")
    pose.subscribe(poses.append)
    first = wait_for(lambda: poses and poses[-1], "a pose")
    assert set(first) == {"x", "y", "theta", "linear_velocity", "angular_velocity"}
    cmd = roslibpy.Topic(client, "/turtle1/cmd_vel", "geometry_msgs/Twist")
    twist = roslibpy.Message(
        {"linear": {"x": 1.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}
    )

    def moved() -> bool:
        cmd.publish(twist)
        return poses[-1]["linear_velocity"] == 1.0 and poses[-1]["x"] > first["x"] + 0.05

    wait_for(moved, "the turtle to move forward")
    pose.unsubscribe()
    cmd.unadvertise()


def test_spawn_and_rosapi(client: Any) -> None:
    spawn = roslibpy.Service(client, "/spawn", "turtlesim/Spawn")
    answer = spawn.call(
        roslibpy.ServiceRequest({"x": 2.0, "y": 3.0, "theta": 0.5, "name": "bridged"}), timeout=10
    )
    assert answer["name"] == "bridged"
    topics = client.get_topics()
    assert {"/turtle1/pose", "/bridged/pose"} <= set(topics)
    assert client.get_topic_type("/turtle1/pose") == "turtlesim/Pose"
    assert "/turtlesim" in client.get_nodes()
    assert client.get_service_type("/spawn") == "turtlesim/Spawn"
    details = client.get_message_details("turtlesim/Pose")
    assert details["typedefs"][0]["fieldnames"] == [
        "x",
        "y",
        "theta",
        "linear_velocity",
        "angular_velocity",
    ]
    client.set_param("/bridge_test/answer", 42)
    assert client.get_param("/bridge_test/answer") == 42
    assert "/bridge_test/answer" in client.get_params()
    kill = roslibpy.Service(client, "/kill", "turtlesim/Kill")
    kill.call(roslibpy.ServiceRequest({"name": "bridged"}), timeout=10)


def test_a_service_the_client_serves_is_reached_by_rosservice(
    client: Any, running: Running
) -> None:
    def add(request: dict[str, int], response: dict[str, int]) -> bool:
        response["sum"] = request["a"] + request["b"]
        return True

    service = roslibpy.Service(client, "/bridged_add", "rospy_tutorials/AddTwoInts")
    service.advertise(add)
    environ = clean_environ(ROS_MASTER_URI=running.master, ROS_IP="127.0.0.1")
    wait_for(
        lambda: "/bridged_add" in rosx("rosservice", "list", environ=environ).out, "the service"
    )
    result = rosx("rosservice", "call", "/bridged_add", "1", "2", environ=environ)
    assert (result.status, result.out) == (0, "sum: 3\n")
    service.unadvertise()
    wait_for(
        lambda: "/bridged_add" not in rosx("rosservice", "list", environ=environ).out,
        "the service to go",
    )
