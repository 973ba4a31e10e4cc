"""The bridges' protocol cores under fuzz: any frame a browser can send gets frames back.

Sessions of rosbridge v2 (`rosx.bridge.protocol.Session`) and of the Foxglove protocol
(`rosx.bridge.foxglove.FoxgloveSession`) are fed requests made of their own ops and fields with
values of every JSON kind, random JSON text, and random CBOR and binary frames, several to a
session. Every frame is answered with a reaction (frames and events; a ``status`` for what
cannot be done): never an exception, never a hang. Frames that ask for gigabytes (deep
nesting, fragments of many messages at once, CBOR lengths of billions) stay within
`MEMORY_BOUND` and get a status.
"""

from __future__ import annotations

import json
from typing import Any

import cbor2
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.bridge.foxglove import FoxgloveSession
from rosx.bridge.protocol import Session
from rosx.msg.codec.rostime import Time
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation

pytestmark = pytest.mark.fuzz

NOW = Time(1700000000, 5)

_JSON_SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(2**70), 2**70),
    st.floats(allow_nan=False),
    st.text(max_size=12),
    st.sampled_from(["/chatter", "std_msgs/String", "geometry_msgs/Twist", "cbor", "png"]),
)


def _containers(inner: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    return st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=8), inner, max_size=4)
    )


json_values = st.recursive(_JSON_SCALARS, _containers, max_leaves=10)
_OPS = st.sampled_from(
    [
        *["advertise", "unadvertise", "publish", "subscribe", "unsubscribe", "call_service"],
        *["advertise_service", "unadvertise_service", "service_response", "set_level"],
        *["fragment", "auth", "status", "nonsense"],
    ]
)
_FIELDS = st.sampled_from(
    [
        *["id", "topic", "type", "msg", "throttle_rate", "queue_length", "fragment_size"],
        *["compression", "service", "args", "values", "result", "level", "data", "num"],
        *["total", "mac", "client", "dest", "rand", "t", "end", "latch", "queue_size"],
    ]
)


@st.composite
def requests(draw: st.DrawFn) -> dict[str, Any]:
    request: dict[str, Any] = {"op": draw(_OPS)}
    for name in draw(st.lists(_FIELDS, max_size=6)):
        request[name] = draw(json_values)
    if draw(st.booleans()):
        request["topic"] = draw(st.sampled_from(["/chatter", "/cmd_vel", "bad name", ""]))
        request["type"] = draw(
            st.sampled_from(["std_msgs/String", "geometry_msgs/Twist", "no/Such", "x"])
        )
    if request["op"] == "publish" and draw(st.booleans()):
        request["msg"] = draw(
            st.sampled_from([{"data": "hi"}, {"linear": {"x": 1}}, {"data": 3}, [], None])
        )
    return request


frames = st.one_of(
    requests().map(json.dumps),
    requests().map(cbor2.dumps),
    st.text(max_size=80),
    st.binary(max_size=80),
    json_values.map(json.dumps),
)


@fuzz_settings(200)
@given(sequence=st.lists(frames, min_size=1, max_size=6))
def test_rosbridge_sessions_answer_every_frame(sequence: list[str | bytes]) -> None:
    session = Session()
    with no_hang():
        for frame in sequence:
            reaction = session.receive(frame, NOW)
            for out in reaction.frames:
                assert isinstance(out, str | bytes)


@st.composite
def foxglove_requests(draw: st.DrawFn) -> dict[str, Any]:
    request: dict[str, Any] = {
        "op": draw(
            st.sampled_from(
                [
                    *["subscribe", "unsubscribe", "advertise", "unadvertise"],
                    *["getParameters", "setParameters", "subscribeParameterUpdates", "x"],
                ]
            )
        )
    }
    for name in draw(
        st.lists(
            st.sampled_from(
                [
                    *["subscriptions", "subscriptionIds", "channels", "channelIds"],
                    *["parameterNames", "parameters", "id", "topic", "encoding", "schemaName"],
                    "channelId",
                ]
            ),
            max_size=4,
        )
    ):
        request[name] = draw(json_values)
    return request


@fuzz_settings(150)
@given(
    sequence=st.lists(
        st.one_of(
            foxglove_requests().map(json.dumps), st.text(max_size=60), st.binary(max_size=60)
        ),
        min_size=1,
        max_size=6,
    )
)
def test_foxglove_sessions_answer_every_frame(sequence: list[str | bytes]) -> None:
    session = FoxgloveSession()
    with no_hang():
        session.hello()
        for frame in sequence:
            session.receive(frame)


# -- bombs ------------------------------------------------------------------------------------

_DEEP = "[" * 200_000 + "]" * 200_000


def _fragments(count: int, size: int) -> list[str]:
    # The first of two fragments of ``count`` messages, none ever completed.
    return [
        json.dumps({"op": "fragment", "id": f"m{i}", "data": "x" * size, "num": 0, "total": 2})
        for i in range(count)
    ]


BOMBS: dict[str, list[str | bytes]] = {
    "nested JSON": [_DEEP],
    "nested JSON in a request": ['{"op": "publish", "topic": "/t", "msg": ' + _DEEP + "}"],
    "nested CBOR": [b"\x81" * 200_000 + b"\x00"],
    "CBOR array of four billion": [b"\x9b\x00\x00\x00\x01\x00\x00\x00\x00"],
    "CBOR string of four gigabytes": [b"\x7b\x00\x00\x00\x01\x00\x00\x00\x00"],
    "CBOR map of four billion": [b"\xbb\x00\x00\x00\x01\x00\x00\x00\x00"],
    "fragments of many messages": list(_fragments(400, 256 << 10)),
    "a fragment count of billions": [
        json.dumps({"op": "fragment", "id": 1, "data": "x", "num": 0, "total": 10**12})
    ],
}


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_rosbridge_frames_that_ask_for_gigabytes_get_a_status(name: str) -> None:
    session = Session()
    answered: list[int] = []

    def feed() -> None:
        with no_hang():
            for frame in BOMBS[name]:
                answered.append(len(session.receive(frame, NOW).frames))

    assert peak_allocation(feed) < MEMORY_BOUND
    assert len(answered) == len(BOMBS[name])
    if name != "fragments of many messages":  # each first fragment waits for its second
        assert answered[-1] >= 1  # a status says what was refused


@pytest.mark.parametrize(
    "frame", [_DEEP, b"\x9b\x00\x00\x00\x01\x00\x00\x00\x00"], ids=["nested JSON", "CBOR"]
)
def test_foxglove_frames_that_ask_for_gigabytes_get_a_status(frame: str | bytes) -> None:
    session = FoxgloveSession()
    answered: list[int] = []

    def feed() -> None:
        with no_hang():
            answered.append(len(session.receive(frame).frames))

    assert peak_allocation(feed) < MEMORY_BOUND
    assert answered == [1]
