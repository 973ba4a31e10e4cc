"""The rosbridge core without sockets: each op's frames and events, and every bad request's
status (the session keeps serving after each)."""

from __future__ import annotations

import base64
import hashlib
import json
from typing import Any

import cbor2
import pytest

from rosx.bridge import ops
from rosx.bridge.outgoing import Outgoing, serialize
from rosx.bridge.png import png_text
from rosx.bridge.protocol import Session
from rosx.bridge.safety import origin_allowed
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.codec.rostime import Time

NOW = Time(1700000000, 5)
Twist = get_message_class("geometry_msgs/Twist")


def send(session: Session, request: Any) -> ops.Reaction:
    return session.receive(request if isinstance(request, str) else json.dumps(request), NOW)


def statuses(reaction: ops.Reaction | list[ops.Frame]) -> list[tuple[str, str]]:
    frames = reaction.frames if isinstance(reaction, ops.Reaction) else reaction
    found = []
    for frame in frames:
        data = json.loads(frame)
        if data["op"] == "status":
            found.append((data["level"], data["msg"]))
    return found


def still_serves(session: Session) -> None:
    """The session answers a good request after a bad one."""
    reaction = send(session, {"op": "subscribe", "topic": "/still_here", "id": "alive"})
    assert ops.Subscribe("/still_here", None, "alive") in reaction.events


BAD_REQUESTS = [
    (
        '{"op": "publish", "topic": "/a"',
        "Invalid JSON (Expecting ',' delimiter: line 1 column 32 (char 31)): "
        '{"op": "publish", "topic": "/a"',
    ),
    ("[1, 2]", "Expected a JSON object with an 'op' field but received an array"),
    ('"hello"', "Expected a JSON object with an 'op' field but received a string"),
    (
        '{"topic": "/a"}',
        "Received a message without an op.  All messages require 'op' field with value one of: "
        "['advertise', 'advertise_service', 'auth', 'call_service', 'fragment', 'publish', 'service_response', "
        "'set_level', 'subscribe', 'unadvertise', 'unadvertise_service', 'unsubscribe']",
    ),
    (
        '{"op": "frobnicate"}',
        "Unknown operation: frobnicate.  Allowed operations: ['advertise', "
        "'advertise_service', 'auth', 'call_service', 'fragment', 'publish', 'service_response', 'set_level', "
        "'subscribe', 'unadvertise', 'unadvertise_service', 'unsubscribe']",
    ),
    ('{"op": "subscribe"}', "subscribe: Expected a topic field but none was found."),
    (
        '{"op": "subscribe", "topic": 5}',
        "subscribe: Expected field topic to be a string. Invalid value: 5",
    ),
    (
        '{"op": "subscribe", "topic": "/a", "throttle_rate": true}',
        "subscribe: Expected field throttle_rate to be an integer or a number. Invalid value: true",
    ),
    (
        '{"op": "subscribe", "topic": "/a", "compression": "zip"}',
        "subscribe: Unknown compression 'zip': one of none, png, cbor, cbor-raw",
    ),
    (
        '{"op": "advertise", "topic": "/a", "type": "no_such_pkg/Thing"}',
        "advertise: Unknown message type no_such_pkg/Thing",
    ),
    (
        '{"op": "subscribe", "topic": "/a", "type": "nonsense"}',
        "subscribe: Unknown message type nonsense",
    ),
    (
        '{"op": "advertise_service", "service": "/s", "type": "std_srvs/Nope"}',
        "advertise_service: Unknown service type std_srvs/Nope",
    ),
    (
        '{"op": "set_level", "level": "loud"}',
        "set_level: Unknown level 'loud': one of none, error, warning, info",
    ),
    (
        '{"op": "service_response", "service": "/s", "id": "x", "result": true}',
        "service_response: Service /s has not been advertised via rosbridge.",
    ),
    (
        '{"op": "unadvertise_service", "service": "/s"}',
        "unadvertise_service: Service /s has not been advertised via rosbridge.",
    ),
    (
        '{"op": "fragment", "id": "f", "data": "x", "num": 3, "total": 2}',
        "fragment: fragment 3 of 2 of message f is out of range",
    ),
]


@pytest.mark.parametrize(("frame", "text"), BAD_REQUESTS)
def test_bad_requests_get_an_error_status_and_the_session_goes_on(frame: str, text: str) -> None:
    session = Session()
    reaction = session.receive(frame, NOW)
    assert statuses(reaction) == [("error", text)]
    assert reaction.events == []
    still_serves(session)


def test_a_frame_over_the_limit_is_refused_without_parsing() -> None:
    session = Session(max_message=100)
    reaction = send(session, {"op": "publish", "topic": "/a", "msg": {"data": "x" * 200}})
    assert statuses(reaction) == [("error", "Message of 253 bytes refused: the limit is 100 bytes")]
    still_serves(session)


def test_the_id_of_a_bad_request_comes_back_with_its_status() -> None:
    reaction = send(Session(), {"op": "subscribe", "id": "sub-7"})
    assert json.loads(reaction.frames[0])["id"] == "sub-7"


def test_advertise_then_publish_fills_the_message() -> None:
    session = Session()
    reaction = send(
        session, {"op": "advertise", "topic": "/cmd_vel", "type": "geometry_msgs/Twist"}
    )
    assert reaction.events == [ops.Advertise("/cmd_vel", Twist, False, 100)]
    reaction = send(session, {"op": "publish", "topic": "/cmd_vel", "msg": {"linear": {"x": 2}}})
    (event,) = reaction.events
    assert isinstance(event, ops.Publish)
    assert event.message == Twist(linear=get_message_class("geometry_msgs/Vector3")(2.0, 0.0, 0.0))
    assert reaction.frames == []


@pytest.mark.parametrize(
    ("msg", "text"),
    [
        (
            {"linear": {"x": "fast"}},
            "publish: geometry_msgs/Twist message requires a float64 for field linear.x, but got a string",
        ),
        (
            {"linear": 3},
            "publish: geometry_msgs/Twist message requires a geometry_msgs/Vector3 for field "
            "linear, but got a number",
        ),
        ({"spin": 1}, "publish: Message type geometry_msgs/Twist does not have a field spin"),
        (
            {"linear": {"w": 1}},
            "publish: Message type geometry_msgs/Twist does not have a field linear.w",
        ),
    ],
)
def test_a_message_that_does_not_fit_its_type_is_refused(msg: object, text: str) -> None:
    session = Session()
    send(session, {"op": "advertise", "topic": "/cmd_vel", "type": "geometry_msgs/Twist"})
    reaction = send(session, {"op": "publish", "topic": "/cmd_vel", "msg": msg})
    assert statuses(reaction) == [("error", text)]
    assert reaction.events == []


def test_integer_ranges_and_kinds_are_checked() -> None:
    session = Session()
    send(session, {"op": "advertise", "topic": "/b", "type": "std_msgs/UInt8"})
    reaction = send(session, {"op": "publish", "topic": "/b", "msg": {"data": 300}})
    assert statuses(reaction) == [
        (
            "error",
            "publish: std_msgs/UInt8 message requires a uint8 for field data, but 300 is out of "
            "its range [0, 255]",
        )
    ]
    reaction = send(session, {"op": "publish", "topic": "/b", "msg": {"data": 2.5}})
    assert statuses(reaction) == [
        (
            "error",
            "publish: std_msgs/UInt8 message requires a uint8 for field data, but got a number",
        )
    ]


def test_publishing_an_unadvertised_topic_asks_the_graph_for_its_type() -> None:
    session = Session()
    reaction = send(session, {"op": "publish", "topic": "/chatter", "msg": {"data": "hi"}, "id": 3})
    assert reaction.events == [ops.PublishUntyped("/chatter", {"data": "hi"}, 3)]
    refused = session.publish_typed("/chatter", None, {"data": "hi"}, 3, NOW)
    assert statuses(refused) == [
        (
            "error",
            "publish: Cannot infer topic type for topic /chatter as it is not yet advertised: "
            "advertise it first",
        )
    ]
    typed = session.publish_typed("/chatter", "std_msgs/String", {"data": "hi"}, 3, NOW)
    string_class = get_message_class("std_msgs/String")
    assert typed.events == [
        ops.Advertise("/chatter", string_class, False, 100),
        ops.Publish("/chatter", string_class("hi")),
    ]


def test_times_headers_and_byte_arrays_from_json() -> None:
    session = Session()
    send(session, {"op": "advertise", "topic": "/img", "type": "sensor_msgs/Image"})
    data = base64.b64encode(b"\x00\x01\xff").decode()
    reaction = send(session, {"op": "publish", "topic": "/img", "msg": {"data": data, "width": 1}})
    message = reaction.events[0].message  # type: ignore[union-attr]
    assert (message.data, message.width) == (b"\x00\x01\xff", 1)
    assert (message.header.stamp.secs, message.header.stamp.nsecs) == (NOW.secs, NOW.nsecs)
    reaction = send(
        session,
        {
            "op": "publish",
            "topic": "/img",
            "msg": {
                "header": {"stamp": {"secs": 3, "nsecs": 4}, "frame_id": "cam"},
                "data": [7, 8],
            },
        },
    )
    message = reaction.events[0].message  # type: ignore[union-attr]
    assert (message.header.stamp.secs, message.header.stamp.nsecs, message.header.frame_id) == (
        3,
        4,
        "cam",
    )
    assert message.data == b"\x07\x08"


def test_subscriptions_by_id_and_unsubscribe() -> None:
    session = Session()
    first = send(session, {"op": "subscribe", "topic": "/p", "id": "a", "throttle_rate": 100})
    assert first.events == [ops.Subscribe("/p", None, "a")]
    second = send(session, {"op": "subscribe", "topic": "/p", "id": "b", "queue_length": 5})
    assert second.events == []
    options = session.options("/p")
    assert options is not None
    assert (options.throttle_ms, options.queue_length) == (0.0, 5)
    assert send(session, {"op": "unsubscribe", "topic": "/p", "id": "a"}).events == []
    assert send(session, {"op": "unsubscribe", "topic": "/p", "id": "b"}).events == [
        ops.Unsubscribe("/p")
    ]
    assert session.options("/p") is None


def _twist_out(x: float) -> Outgoing:
    msg = Twist()
    msg.linear.x = x
    return Outgoing("/cmd_vel", serialize(msg), Twist, 5_000_000_006)


def test_deliver_json_with_nan_as_null_and_throttling() -> None:
    session = Session()
    send(session, {"op": "subscribe", "topic": "/cmd_vel", "throttle_rate": 1000})
    frames = session.deliver(_twist_out(float("nan")), now=10.0)
    assert frames == [
        '{"op":"publish","topic":"/cmd_vel","msg":{"linear":{"x":null,"y":0.0,"z":0.0},'
        '"angular":{"x":0.0,"y":0.0,"z":0.0}}}'
    ]
    assert session.deliver(_twist_out(1.0), now=10.5) == []
    assert len(session.deliver(_twist_out(1.0), now=11.0)) == 1


def test_deliver_cbor_and_cbor_raw() -> None:
    session = Session()
    send(session, {"op": "subscribe", "topic": "/cmd_vel", "compression": "cbor"})
    (frame,) = session.deliver(_twist_out(float("inf")), now=1.0)
    assert isinstance(frame, bytes)
    decoded = cbor2.loads(frame)
    assert decoded["msg"]["linear"]["x"] == float("inf")
    send(session, {"op": "subscribe", "topic": "/cmd_vel", "compression": "cbor-raw"})
    out = _twist_out(2.0)
    (frame,) = session.deliver(out, now=2.0)
    assert isinstance(frame, tuple)
    assert frame[1] is out.raw  # the message's bytes as they came, not copied
    assert cbor2.loads(b"".join(frame)) == {
        "op": "publish",
        "topic": "/cmd_vel",
        "msg": {"secs": 5, "nsecs": 6, "bytes": out.raw},
    }


def test_cbor_packs_numeric_arrays_as_typed_arrays() -> None:
    floats_class = get_message_class("std_msgs/Float32MultiArray")
    msg = floats_class(data=[1.5, -2.0])
    session = Session()
    send(session, {"op": "subscribe", "topic": "/f", "compression": "cbor"})
    (frame,) = session.deliver(Outgoing.of("/f", msg, 0), now=0.0)
    assert isinstance(frame, bytes)
    data = cbor2.loads(frame)["msg"]["data"]
    assert (data.tag, data.value) == (85, b"\x00\x00\xc0?\x00\x00\x00\xc0")


def test_deliver_in_fragments_that_join_to_the_message() -> None:
    session = Session()
    send(session, {"op": "subscribe", "topic": "/cmd_vel", "fragment_size": 40})
    frames = session.deliver(_twist_out(1.0), now=0.0)
    assert all(isinstance(f, str) for f in frames)
    parts = [json.loads(str(f)) for f in frames]
    assert [(p["op"], p["num"], p["total"]) for p in parts] == [
        ("fragment", i, 3) for i in range(3)
    ]
    assert json.loads("".join(p["data"] for p in parts))["msg"]["linear"]["x"] == 1.0


def test_png_compression_carries_the_json_text() -> None:
    session = Session()
    send(session, {"op": "subscribe", "topic": "/cmd_vel", "compression": "png"})
    (frame,) = session.deliver(_twist_out(3.0), now=0.0)
    assert isinstance(frame, str)
    text = png_text(json.loads(frame)["data"])
    assert json.loads(text)["msg"]["linear"]["x"] == 3.0


def test_fragments_from_the_client_are_joined() -> None:
    session = Session()
    whole = json.dumps({"op": "subscribe", "topic": "/joined"})
    for num, piece in enumerate((whole[:10], whole[10:20], whole[20:])):
        reaction = send(
            session, {"op": "fragment", "id": "m", "data": piece, "num": num, "total": 3}
        )
    assert reaction.events == [ops.Subscribe("/joined", None, None)]


def test_set_level_filters_statuses() -> None:
    session = Session()
    assert statuses(send(session, {"op": "set_level", "level": "info"})) == [
        ("info", "Status level set to info")
    ]
    assert statuses(send(session, {"op": "subscribe", "topic": "/x"})) == [
        ("info", "Subscribed to /x")
    ]
    send(session, {"op": "set_level", "level": "none"})
    assert send(session, {"op": "nope"}).frames == []


def test_call_service_args_as_list_or_object() -> None:
    session = Session()
    (call,) = send(
        session, {"op": "call_service", "service": "/spawn", "args": [1, 2], "id": "c1"}
    ).events
    assert call == ops.CallService("/spawn", [1, 2], "c1")
    spawn_class = get_service_class("turtlesim/Spawn")
    assert isinstance(call, ops.CallService)
    request = session.service_request_message(call, spawn_class, NOW)
    assert (request.x, request.y, request.name) == (1.0, 2.0, "")
    response = spawn_class._response_class(name="turtle2")
    assert json.loads(session.service_done(call, response)[0]) == {
        "op": "service_response",
        "service": "/spawn",
        "values": {"name": "turtle2"},
        "result": True,
        "id": "c1",
    }
    failed = session.service_failed(call, "service [/spawn] unavailable")
    text = "call_service /spawn: service [/spawn] unavailable"
    assert statuses(failed.frames) == [("error", text)]
    assert json.loads(failed.frames[1])["result"] is False
    assert failed.errors == [f"[id: c1] {text}"]


def test_a_service_the_client_serves() -> None:
    session = Session()
    add_class = get_service_class("rospy_tutorials/AddTwoInts")
    reaction = send(
        session,
        {"op": "advertise_service", "service": "/add", "type": "rospy_tutorials/AddTwoInts"},
    )
    assert reaction.events == [ops.AdvertiseService("/add", add_class)]
    request_id, frames = session.service_request("/add", add_class._request_class(a=1, b=2))
    assert json.loads(frames[0]) == {
        "op": "call_service",
        "id": request_id,
        "service": "/add",
        "args": {"a": 1, "b": 2},
    }
    reply = send(
        session,
        {
            "op": "service_response",
            "service": "/add",
            "id": request_id,
            "values": {"sum": 3},
            "result": True,
        },
    )
    assert reply.events == [ops.ServiceReply(request_id, add_class._response_class(sum=3), None)]
    again = send(
        session,
        {
            "op": "service_response",
            "service": "/add",
            "id": request_id,
            "values": {"sum": 3},
            "result": True,
        },
    )
    assert statuses(again) == [
        ("error", f"service_response: no call of /add waits for an answer with id {request_id}")
    ]


def test_a_token_is_needed_before_anything_else() -> None:
    session = Session(token="s3cret")
    assert statuses(send(session, {"op": "subscribe", "topic": "/x"})) == [
        ("error", "subscribe: not authenticated: send an 'auth' op first")
    ]
    wrong = send(session, {"op": "auth", "mac": "guess"})
    assert wrong.events == [ops.Close(1008, "authentication failed")]
    t, end = NOW.secs, NOW.secs + 60
    mac = hashlib.sha512(f"s3cretme youabc{t}user{end}".encode()).hexdigest()
    auth = {
        "op": "auth",
        "mac": mac,
        "client": "me",
        "dest": " you",
        "rand": "abc",
        "t": t,
        "level": "user",
        "end": end,
    }
    assert send(session, auth).events == []
    assert session.authenticated
    still_serves(session)


@pytest.mark.parametrize(
    ("origin", "allow", "allowed"),
    [
        (None, (), True),
        ("http://localhost:8000", (), True),
        ("https://127.0.0.1", (), True),
        ("http://[::1]:3000", (), True),
        ("https://evil.example", (), False),
        ("file://", (), True),
        ("null", (), False),
        ("null", ("null",), True),
        ("https://app.lichtblick.dev", ("https://*.lichtblick.dev",), True),
        ("http://localhost.evil.example", (), False),
    ],
)
def test_origins(origin: str | None, allow: tuple[str, ...], allowed: bool) -> None:
    assert origin_allowed(origin, allow) is allowed
