"""rosapi's services through the bridge, each answering as rosbridge_suite's rosapi_node does."""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import Any

import pytest
from websockets.sync.client import ClientConnection, connect

from tests.support.bridge import Running


@pytest.fixture(scope="module")
def ws(running: Running) -> Iterator[ClientConnection]:
    with connect(running.url, max_size=None) as conn:
        yield conn


def call(ws: ClientConnection, service: str, /, **args: Any) -> Any:
    request = {"op": "call_service", "service": f"/rosapi/{service}", "args": args, "id": service}
    ws.send(json.dumps(request))
    while True:
        answer = json.loads(ws.recv(timeout=20))
        if answer["op"] == "service_response" and answer.get("id") == service:
            assert answer["result"] is True, answer
            return answer["values"]


def test_topics_and_their_types(ws: ClientConnection) -> None:
    topics = call(ws, "topics")
    pairs = dict(zip(topics["topics"], topics["types"], strict=True))
    assert pairs["/turtle1/pose"] == "turtlesim/Pose"
    assert pairs["/rosout"] == "rosgraph_msgs/Log"
    raw = call(ws, "topics_and_raw_types")
    texts = dict(zip(raw["topics"], raw["typedefs_full_text"], strict=True))
    assert (
        texts["/turtle1/pose"]
        == "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n"
    )
    assert call(ws, "topics_for_type", type="turtlesim/Pose")["topics"] == ["/turtle1/pose"]
    assert call(ws, "topic_type", topic="/turtle1/cmd_vel") == {"type": "geometry_msgs/Twist"}
    assert call(ws, "topic_type", topic="/nothing") == {"type": ""}
    assert call(ws, "publishers", topic="/turtle1/pose") == {"publishers": ["/turtlesim"]}
    assert call(ws, "subscribers", topic="/turtle1/cmd_vel") == {"subscribers": ["/turtlesim"]}


def test_services_and_nodes(ws: ClientConnection) -> None:
    services = call(ws, "services")["services"]
    assert {"/spawn", "/kill", "/rosapi/topics"} <= set(services)
    assert call(ws, "service_type", service="/spawn") == {"type": "turtlesim/Spawn"}
    assert call(ws, "services_for_type", type="turtlesim/Spawn") == {"services": ["/spawn"]}
    assert call(ws, "service_node", service="/spawn") == {"node": "/turtlesim"}
    assert call(ws, "service_host", service="/spawn") == {"host": "127.0.0.1"}
    assert call(ws, "service_providers", service="turtlesim/Kill") == {"providers": ["/turtlesim"]}
    nodes = call(ws, "nodes")["nodes"]
    assert {"/turtlesim", "/rosapi", "/rosout"} <= set(nodes)
    details = call(ws, "node_details", node="/turtlesim")
    assert details["subscribing"] == ["/turtle1/cmd_vel"]
    assert "/turtle1/pose" in details["publishing"]
    assert "/spawn" in details["services"]
    assert call(ws, "action_servers") == {"action_servers": []}


def test_parameters_as_json_text(ws: ClientConnection) -> None:
    call(ws, "set_param", name="/rosapi_test/gains", value='{"p": 1.5, "i": [1, 2]}')
    assert json.loads(call(ws, "get_param", name="/rosapi_test/gains")["value"]) == {
        "p": 1.5,
        "i": [1, 2],
    }
    assert call(ws, "get_param", name="/rosapi_test/none", default="7") == {"value": "7"}
    assert call(ws, "has_param", name="/rosapi_test/gains/p") == {"exists": True}
    assert "/rosapi_test/gains/p" in call(ws, "get_param_names")["names"]
    assert call(ws, "search_param", name="rosapi_test") == {"global_name": "/rosapi_test"}
    call(ws, "delete_param", name="/rosapi_test")
    assert call(ws, "has_param", name="/rosapi_test/gains") == {"exists": False}
    ws.send(
        json.dumps(
            {
                "op": "call_service",
                "service": "/rosapi/set_param",
                "args": {"name": "/x", "value": "{bad"},
                "id": "bad",
            }
        )
    )
    answer = json.loads(ws.recv(timeout=20))
    while answer["op"] != "service_response":
        answer = json.loads(ws.recv(timeout=20))
    assert answer["result"] is False
    assert "must be a JSON-formatted string" in answer["values"]


def test_time_and_type_details(ws: ClientConnection) -> None:
    stamp = call(ws, "get_time")["time"]
    assert set(stamp) == {"secs", "nsecs"} and stamp["secs"] > 1_600_000_000
    typedefs = call(ws, "message_details", type="geometry_msgs/PoseStamped")["typedefs"]
    assert [t["type"] for t in typedefs] == [
        "geometry_msgs/PoseStamped",
        "std_msgs/Header",
        "time",
        "geometry_msgs/Pose",
        "geometry_msgs/Point",
        "geometry_msgs/Quaternion",
    ]
    header = typedefs[1]
    assert header == {
        "type": "std_msgs/Header",
        "fieldnames": ["seq", "stamp", "frame_id"],
        "fieldtypes": ["uint32", "time", "string"],
        "fieldarraylen": [-1, -1, -1],
        "examples": ["0", "0", ""],
        "constnames": [],
        "constvalues": [],
    }
    log = call(ws, "message_details", type="rosgraph_msgs/Log")["typedefs"][0]
    assert (log["constnames"], log["constvalues"]) == (
        ["DEBUG", "ERROR", "FATAL", "INFO", "WARN"],
        ["1", "8", "16", "2", "4"],
    )
    request = call(ws, "service_request_details", type="turtlesim/Spawn")["typedefs"]
    assert request[0]["fieldnames"] == ["x", "y", "theta", "name"]
    response = call(ws, "service_response_details", type="turtlesim/Spawn")["typedefs"]
    assert response[0] == {
        "type": "turtlesim/SpawnResponse",
        "fieldnames": ["name"],
        "fieldtypes": ["string"],
        "fieldarraylen": [-1],
        "examples": [""],
        "constnames": [],
        "constvalues": [],
    }
