"""ROS's [code, statusMessage, value] reply convention."""

from __future__ import annotations

import pytest

from rosx.wire.errors import ProtocolError
from rosx.wire.reply import ERROR, FAILURE, SUCCESS, RosReply, parse_ros_reply, ros_reply
from rosx.wire.xmlrpc import MethodResponse, decode_response, encode_response


def test_codes() -> None:
    assert (SUCCESS, FAILURE, ERROR) == (1, 0, -1)


def test_reply_round_trip() -> None:
    body = encode_response(ros_reply(SUCCESS, "current system state", [[], [], []]))
    decoded = decode_response(body)
    assert isinstance(decoded, MethodResponse)
    reply = parse_ros_reply(decoded.value)
    assert reply == RosReply(1, "current system state", [[], [], []])
    assert reply.ok
    assert not parse_ros_reply([ERROR, "unknown node [/x]", ""]).ok
    assert ros_reply(FAILURE, "x") == [0, "x", 0]


def test_reply_codes_are_checked() -> None:
    with pytest.raises(ProtocolError, match="must be 1, 0 or -1, not 2"):
        ros_reply(2, "x")


@pytest.mark.parametrize(
    "value", [None, [], [1, "x"], [1, "x", 0, 0], ["1", "x", 0], [1, 2, 0], [True, "x", 0]]
)
def test_malformed_replies_are_refused(value: object) -> None:
    with pytest.raises(ProtocolError, match="a ROS reply must"):
        parse_ros_reply(value)
