"""The Foxglove WebSocket protocol: its core without sockets, then clients on the wire that see
the turtle's pose, drive it, call ``/spawn`` and read a parameter: one written here on
`websockets`, and Foxglove's own (@foxglove/ws-protocol, in node, with Lichtblick's ROS 1
message readers and writers)."""

from __future__ import annotations

import json
import struct
import time
from collections.abc import Callable, Iterator
from typing import Any

import pytest
from websockets.exceptions import InvalidStatus
from websockets.sync.client import ClientConnection, connect
from websockets.typing import Origin, Subprotocol

from rosx.bridge import foxglove as fx
from rosx.bridge.app import Bridge
from rosx.bridge.outgoing import serialize
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from rosx_turtle.node.turtlesim import TurtlesimNode
from rosx_turtle.roscpp import NodeArgs
from tests.support.bridge import NodeScript, start_bridge

Pose = get_message_class("turtlesim/Pose")
Twist = get_message_class("geometry_msgs/Twist")
Spawn = get_service_class("turtlesim/Spawn")


def status_of(frames: list[fx.Frame]) -> list[tuple[int, str]]:
    return [(d["level"], d["message"]) for d in map(json.loads, frames) if d["op"] == "status"]


def test_the_core_advertises_the_graph_and_maps_subscriptions() -> None:
    session = fx.FoxgloveSession(name="rosx")
    info = json.loads(session.hello()[0])
    assert info["capabilities"] == ["clientPublish", "parameters", "services"]
    assert info["supportedEncodings"] == ["ros1"]
    frames = session.update_graph(
        {"/pose": "turtlesim/Pose", "/odd": "unknown_pkg/T"}, {"/spawn": "turtlesim/Spawn"}
    )
    channels = json.loads(frames[0])["channels"]
    assert [(c["topic"], c["schemaName"], c["schema"]) for c in channels] == [
        ("/pose", "turtlesim/Pose", Pose._full_text)
    ]
    services = json.loads(frames[1])["services"]
    assert [(s["name"], s["request"]["schemaName"]) for s in services] == [
        ("/spawn", "turtlesim/SpawnRequest")
    ]
    cid = channels[0]["id"]
    reaction = session.receive(
        json.dumps({"op": "subscribe", "subscriptions": [{"id": 7, "channelId": cid}]})
    )
    assert reaction.events == [fx.Subscribe("/pose")]
    assert session.deliver("/pose", b"abc", 5) == [(struct.pack("<BIQ", 1, 7, 5), b"abc")]
    assert json.loads(session.update_graph({}, {})[0]) == {"op": "unadvertise", "channelIds": [cid]}


@pytest.mark.parametrize(
    ("frame", "text"),
    [
        ("{", "Expecting property name enclosed in double quotes: line 1 column 2 (char 1)"),
        ('{"op": "dance"}', 'Unrecognized client opcode "dance"'),
        ('{"op": "subscribe"}', "Invalid request: missing or wrong 'subscriptions'"),
        (b"\x01\x05\x00\x00\x00data", "Channel 5 is not advertised by this client"),
        (b"\x02\x01\x00\x00\x00", "Truncated service call request"),
        (b"\x09", "Unrecognized client opcode 9"),
    ],
)
def test_bad_requests_get_an_error_status(frame: str | bytes, text: str) -> None:
    session = fx.FoxgloveSession()
    reaction = session.receive(frame)
    assert status_of(reaction.frames) == [(fx.ERROR, text)]
    assert reaction.events == []


@pytest.fixture(scope="module")
def foxglove(master: str) -> Iterator[tuple[Bridge, str]]:
    environ = {"ROS_MASTER_URI": master, "ROS_IP": "127.0.0.1"}
    sim = TurtlesimNode(NodeArgs.parse([], "turtlesim"), environ=environ).start()
    bridge, _ = start_bridge(master, rosapi=False, foxglove_port=0)
    try:
        assert bridge.foxglove is not None
        yield bridge, f"ws://127.0.0.1:{bridge.foxglove.port}"
    finally:
        bridge.shutdown("test over")
        sim.shutdown("test over")


def test_a_refused_page_is_told_how_to_let_it_in(master: str) -> None:
    bridge, lines = start_bridge(master, rosapi=False, foxglove_port=0)
    try:
        assert bridge.foxglove is not None
        url = f"ws://127.0.0.1:{bridge.foxglove.port}"
        with pytest.raises(InvalidStatus) as refused:
            connect(url, origin=Origin("null"), subprotocols=[Subprotocol(fx.SUBPROTOCOL)])
        assert refused.value.response.status_code == 403
        assert refused.value.response.body == (
            b"Origin null is not allowed: start the bridge with --allow-origin null to let its "
            b"pages connect\n"
        )
        line = (
            "Refused a Foxglove connection from a page of null: not an allowed origin "
            "(--allow-origin null, or allow_origin:=null with roslaunch, lets its pages connect)"
        )
        deadline = time.monotonic() + 10
        while line not in lines:
            assert time.monotonic() < deadline, lines
            time.sleep(0.01)
    finally:
        bridge.shutdown("test over")


class Reader:
    """A client's frames, kept: `receive` looks at those already read before reading more."""

    def __init__(self, ws: ClientConnection) -> None:
        self.ws = ws
        self.seen: list[Any] = []

    def receive(self, want: Any, timeout: float = 10.0) -> Any:
        """The first frame, old or new, for which ``want`` gives something."""
        for message in self.seen:
            found = want(message)
            if found is not None:
                return found
        deadline = time.monotonic() + timeout
        while True:
            frame = self.ws.recv(timeout=max(0.01, deadline - time.monotonic()))
            message = json.loads(frame) if isinstance(frame, str) else frame
            if isinstance(message, dict):
                self.seen.append(message)
            found = want(message)
            if found is not None:
                return found


def test_a_client_sees_drives_and_calls(foxglove: tuple[Bridge, str]) -> None:
    _, url = foxglove
    with connect(url, subprotocols=[Subprotocol(fx.SUBPROTOCOL)], max_size=None) as ws:
        assert ws.subprotocol == fx.SUBPROTOCOL
        receive = Reader(ws).receive
        info = receive(lambda m: m if isinstance(m, dict) and m["op"] == "serverInfo" else None)
        assert "services" in info["capabilities"]

        def channel(message: Any) -> Any:
            if isinstance(message, dict) and message["op"] == "advertise":
                return next((c for c in message["channels"] if c["topic"] == "/turtle1/pose"), None)
            return None

        pose_channel = receive(channel)
        assert (pose_channel["encoding"], pose_channel["schemaEncoding"]) == ("ros1", "ros1msg")
        ws.send(
            json.dumps(
                {"op": "subscribe", "subscriptions": [{"id": 1, "channelId": pose_channel["id"]}]}
            )
        )
        ws.send(
            json.dumps(
                {
                    "op": "advertise",
                    "channels": [
                        {
                            "id": 9,
                            "topic": "/turtle1/cmd_vel",
                            "encoding": "ros1",
                            "schemaName": "geometry_msgs/Twist",
                        }
                    ],
                }
            )
        )
        twist = Twist()
        twist.angular.z = 1.5
        drive = struct.pack("<BI", 1, 9) + serialize(twist)

        def turning(message: Any) -> Any:
            if isinstance(message, bytes) and message[0] == 1:
                (sub,) = struct.unpack_from("<I", message, 1)
                assert sub == 1
                pose = Pose().deserialize(message[13:])
                ws.send(drive)
                return pose if pose.angular_velocity == 1.5 else None
            return None

        ws.send(drive)
        receive(turning)

        def spawn_service(message: Any) -> Any:
            if isinstance(message, dict) and message["op"] == "advertiseServices":
                return next((s for s in message["services"] if s["name"] == "/spawn"), None)
            return None

        service = receive(spawn_service)
        request = serialize(Spawn._request_class(x=1.0, y=1.0, theta=0.0, name="foxy"))
        ws.send(struct.pack("<BIII", 2, service["id"], 42, 4) + b"ros1" + request)

        def answer(message: Any) -> Any:
            if isinstance(message, bytes) and message[0] == 3:
                _, sid, call, length = struct.unpack_from("<BIII", message)
                assert (sid, call, message[13 : 13 + length]) == (service["id"], 42, b"ros1")
                return Spawn._response_class().deserialize(message[13 + length :])
            return None

        assert receive(answer).name == "foxy"
        ws.send(
            json.dumps(
                {"op": "getParameters", "parameterNames": ["/turtlesim/background_b"], "id": "p"}
            )
        )
        values = receive(
            lambda m: m if isinstance(m, dict) and m["op"] == "parameterValues" else None
        )
        assert values == {
            "op": "parameterValues",
            "parameters": [{"name": "/turtlesim/background_b", "value": 255}],
            "id": "p",
        }


def test_foxglove_s_own_client(
    foxglove: tuple[Bridge, str], node_script: Callable[..., NodeScript]
) -> None:
    _, url = foxglove
    client = node_script("foxglove_client.cjs", url)
    assert client.step("capabilities") == ["clientPublish", "parameters", "services"]
    assert client.step("schema") == {"encoding": "ros1", "schemaName": "turtlesim/Pose"}
    assert client.step("spawned") == {"callId": 7, "name": "foxglove"}
    assert client.step("parameters") == {
        "id": "p",
        "parameters": [{"name": "/turtlesim/background_b", "value": 255}],
    }
    assert client.step("turning") == 1.5
    assert client.finish() == 0
    assert "status" not in client.steps


def test_a_topic_whose_publishers_left_is_unadvertised(
    foxglove: tuple[Bridge, str], make_node: Callable[..., Node]
) -> None:
    _, url = foxglove
    talker = make_node("/fleeting_talker")
    publisher = talker.advertise("/fleeting", get_message_class("std_msgs/String"))
    with connect(url, subprotocols=[Subprotocol(fx.SUBPROTOCOL)], max_size=None) as ws:
        receive = Reader(ws).receive

        def fleeting(message: Any) -> Any:
            if isinstance(message, dict) and message["op"] == "advertise":
                return next((c for c in message["channels"] if c["topic"] == "/fleeting"), None)
            return None

        channel = receive(fleeting)
        publisher.unregister()

        def unadvertised(message: Any) -> Any:
            if isinstance(message, dict) and message["op"] == "unadvertise":
                return channel["id"] in message["channelIds"] or None
            return None

        # the master still knows the topic's type; foxglove_bridge offers published topics only
        assert receive(unadvertised, timeout=15.0)
