"""The TCPROS topic handshake: headers both ways, rospy's refusal texts, wildcards."""

from __future__ import annotations

import pytest

from rosx.wire.framing import FrameReader, frame
from rosx.wire.header import Refused, decode_header, encode_header
from rosx.wire.tcpros import (
    NO_TOPIC_OR_SERVICE,
    Publication,
    PublisherAccepted,
    SubscriberAccepted,
    accept_subscriber,
    check_publisher_reply,
    connection_kind,
    publisher_header,
    subscriber_header,
)
from tests.support.wirefeed import CHUNKINGS, pieces

STRING_MD5 = "992ce8a1687cec8c8bd883ec73ca41d1"
CHATTER = Publication("/chatter", "std_msgs/String", STRING_MD5, "string data\n", latching=True)
PUBLICATIONS = {"/chatter": CHATTER, "/rosout": Publication("/rosout", "rosgraph_msgs/Log", "x")}


def _request(**fields: str) -> dict[str, str]:
    base = {"callerid": "/listener", "topic": "/chatter", "md5sum": STRING_MD5}
    base.update(fields)
    return base


def test_subscriber_header_is_sorted_like_ros1() -> None:
    fields = subscriber_header(
        callerid="/listener",
        topic="/chatter",
        md5sum=STRING_MD5,
        msg_type="std_msgs/String",
        message_definition="string data\n",
        tcp_nodelay=True,
    )
    assert list(fields.items()) == [
        ("callerid", "/listener"),
        ("md5sum", STRING_MD5),
        ("message_definition", "string data\n"),
        ("tcp_nodelay", "1"),
        ("topic", "/chatter"),
        ("type", "std_msgs/String"),
    ]


def test_unlatched_publisher_says_so() -> None:
    plain = Publication("/t", "std_msgs/Empty", "d41d8cd98f00b204e9800998ecf8427e")
    assert publisher_header(plain, callerid="/p")["latching"] == "0"
    assert publisher_header(plain, callerid="/p")["message_definition"] == ""


def test_subscriber_header_bytes() -> None:
    fields = subscriber_header(callerid="/l", topic="/t", md5sum="*", msg_type="*")
    assert encode_header(fields) == (
        b"\x42\x00\x00\x00"  # 66 = 15 + 12 + 17 + 12 + 10
        b"\x0b\x00\x00\x00callerid=/l"
        b"\x08\x00\x00\x00md5sum=*"
        b"\x0d\x00\x00\x00tcp_nodelay=0"
        b"\x08\x00\x00\x00topic=/t"
        b"\x06\x00\x00\x00type=*"
    )


def test_publisher_header_is_sorted_like_ros1() -> None:
    assert list(publisher_header(CHATTER, callerid="/talker").items()) == [
        ("callerid", "/talker"),
        ("latching", "1"),
        ("md5sum", STRING_MD5),
        ("message_definition", "string data\n"),
        ("topic", "/chatter"),
        ("type", "std_msgs/String"),
    ]


@pytest.mark.parametrize(
    ("request_fields", "nodelay"),
    [
        (_request(), None),
        (_request(tcp_nodelay="1"), True),
        (_request(tcp_nodelay=" 1 "), True),
        (_request(tcp_nodelay="0"), False),
        (_request(md5sum="*", type="*"), None),
        (_request(md5sum="*", type="other/Type"), None),
        (_request(type="std_msgs/String"), None),
    ],
)
def test_publisher_accepts(request_fields: dict[str, str], nodelay: bool | None) -> None:
    accepted = accept_subscriber(request_fields, callerid="/talker", publications=PUBLICATIONS)
    assert accepted == SubscriberAccepted(
        callerid="/listener",
        publication=CHATTER,
        tcp_nodelay=nodelay,
        reply=publisher_header(CHATTER, callerid="/talker"),
    )


def test_publisher_with_wildcard_md5_accepts_any() -> None:
    anything = Publication("/any", "*", "*")
    accepted = accept_subscriber(
        _request(topic="/any", md5sum="abc"), callerid="/p", publications={"/any": anything}
    )
    assert isinstance(accepted, SubscriberAccepted)


@pytest.mark.parametrize(
    ("request_fields", "reason"),
    [
        ({"md5sum": "*", "callerid": "/l"}, "Missing required 'topic' field"),
        ({"topic": "/chatter", "callerid": "/l"}, "Missing required 'md5sum' field"),
        ({"topic": "/chatter", "md5sum": "*"}, "Missing required 'callerid' field"),
        (
            _request(topic="/nope"),
            "[/talker] is not a publisher of [/nope]. Topics are "
            "[['/chatter', 'std_msgs/String'], ['/rosout', 'rosgraph_msgs/Log']]",
        ),
        (
            _request(md5sum="0123"),
            "Client [/listener] wants topic [/chatter] to have datatype/md5sum "
            f"[std_msgs/String/0123], but our version has [std_msgs/String/{STRING_MD5}] "
            "Dropping connection.",
        ),
        (
            _request(md5sum="0123", type="*"),
            "Client [/listener] wants topic [/chatter] to have datatype/md5sum "
            f"[*/0123], but our version has [std_msgs/String/{STRING_MD5}] "
            "Dropping connection.",
        ),
        (
            _request(md5sum="0123", type="std_msgs/Int32"),
            "topic types do not match: [std_msgs/Int32] vs. [std_msgs/String]",
        ),
    ],
)
def test_publisher_refuses_with_rospys_texts(request_fields: dict[str, str], reason: str) -> None:
    refused = accept_subscriber(request_fields, callerid="/talker", publications=PUBLICATIONS)
    assert refused == Refused(reason)
    assert isinstance(refused, Refused)
    assert refused.header == {"error": reason}


def test_subscriber_checks_the_reply() -> None:
    reply = publisher_header(CHATTER, callerid="/talker")
    accepted = check_publisher_reply(reply, topic="/chatter", md5sum=STRING_MD5)
    assert accepted == PublisherAccepted(
        callerid="/talker",
        type="std_msgs/String",
        md5sum=STRING_MD5,
        latching=True,
        message_definition="string data\n",
        header=reply,
    )
    minimal = check_publisher_reply(
        {"md5sum": STRING_MD5, "type": "std_msgs/String"}, topic="/chatter", md5sum="*"
    )
    assert isinstance(minimal, PublisherAccepted)
    assert (minimal.callerid, minimal.latching, minimal.message_definition) == (None, False, None)


@pytest.mark.parametrize(
    ("reply", "expected"),
    [
        ({"error": "go away"}, Refused("go away", by_peer=True)),
        ({"type": "std_msgs/String"}, Refused("header missing required field [md5sum]")),
        ({"md5sum": STRING_MD5}, Refused("header missing required field [type]")),
        (
            {"md5sum": "f00", "type": "std_msgs/String", "callerid": "/talker"},
            Refused(
                "[/talker] sent md5sum [f00] for topic [/chatter], "
                f"but this side expects [{STRING_MD5}]"
            ),
        ),
    ],
)
def test_subscriber_refuses_a_bad_reply(reply: dict[str, str], expected: Refused) -> None:
    assert check_publisher_reply(reply, topic="/chatter", md5sum=STRING_MD5) == expected


def test_connection_kind() -> None:
    assert connection_kind({"topic": "/t", "service": "/s"}) == "topic"
    assert connection_kind({"service": "/s"}) == "service"
    assert connection_kind({"callerid": "/x"}) is None
    assert NO_TOPIC_OR_SERVICE == "no topic or service name detected"


@pytest.mark.parametrize("how", CHUNKINGS)
def test_whole_exchange_over_bytes(how: str) -> None:
    sub_fields = subscriber_header(
        callerid="/listener", topic="/chatter", md5sum=STRING_MD5, msg_type="std_msgs/String"
    )
    publisher_in = FrameReader()
    for piece in pieces(encode_header(sub_fields), how):
        publisher_in.feed(piece)
    request = publisher_in.next_frame()
    assert request is not None
    decision = accept_subscriber(
        decode_header(request), callerid="/talker", publications=PUBLICATIONS
    )
    assert isinstance(decision, SubscriberAccepted)
    to_subscriber = encode_header(decision.reply) + frame(b"\x05\x00\x00\x00hello")
    subscriber_in = FrameReader()
    received: list[bytes] = []
    for piece in pieces(to_subscriber, how):
        subscriber_in.feed(piece)
        received.extend(subscriber_in.frames())
    reply = check_publisher_reply(decode_header(received[0]), topic="/chatter", md5sum=STRING_MD5)
    assert isinstance(reply, PublisherAccepted)
    assert reply.latching
    assert received[1:] == [b"\x05\x00\x00\x00hello"]


def test_publisher_header_adds_the_publishers_own_fields_over_the_standard_ones() -> None:
    cookies = Publication(
        "/chatter",
        "std_msgs/String",
        CHATTER.md5sum,
        CHATTER.message_definition,
        headers=(("cookies", "oreo"), ("latching", "1")),
    )
    header = publisher_header(cookies, callerid="/talker")
    assert (header["cookies"], header["latching"], header["callerid"]) == ("oreo", "1", "/talker")
    assert list(header) == sorted(header)
