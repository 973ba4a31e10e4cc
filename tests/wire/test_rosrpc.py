"""ROSRPC services: headers, rospy's refusal texts, ok-byte responses read in any chunking."""

from __future__ import annotations

import pytest

from rosx.wire.errors import OversizedError, ProtocolError
from rosx.wire.header import Refused, encode_header
from rosx.wire.rosrpc import (
    ServerHeader,
    ServiceClientAccepted,
    ServiceInfo,
    ServiceReplyReader,
    ServiceResponse,
    ServiceServerAccepted,
    accept_client,
    check_server_reply,
    client_header,
    encode_error,
    encode_response,
    format_rosrpc_uri,
    parse_rosrpc_uri,
    server_header,
)
from tests.support.wirefeed import CHUNKINGS, pieces

ADD_MD5 = "6a2e34150c00229791cc89ff309fff21"
ADD = ServiceInfo(
    "/add_two_ints",
    "rospy_tutorials/AddTwoInts",
    ADD_MD5,
    "rospy_tutorials/AddTwoIntsRequest",
    "rospy_tutorials/AddTwoIntsResponse",
)
SERVICES = {"/add_two_ints": ADD}


def test_client_headers() -> None:
    assert list(client_header(callerid="/c", service="/s", md5sum="abc").items()) == [
        ("callerid", "/c"),
        ("md5sum", "abc"),
        ("service", "/s"),
    ]
    assert client_header(callerid="/c", service="/s", md5sum="abc", persistent=True) == {
        "callerid": "/c",
        "md5sum": "abc",
        "persistent": "1",
        "service": "/s",
    }
    probe = client_header(callerid="/c", service="/s", md5sum="abc", probe=True)
    assert list(probe.items()) == [
        ("callerid", "/c"),
        ("md5sum", "*"),
        ("probe", "1"),
        ("service", "/s"),
    ]


def test_server_header_is_sorted_and_complete() -> None:
    assert list(server_header(ADD, callerid="/server").items()) == [
        ("callerid", "/server"),
        ("md5sum", ADD_MD5),
        ("request_type", "rospy_tutorials/AddTwoIntsRequest"),
        ("response_type", "rospy_tutorials/AddTwoIntsResponse"),
        ("service", "/add_two_ints"),
        ("type", "rospy_tutorials/AddTwoInts"),
    ]


@pytest.mark.parametrize(
    ("extra", "persistent", "probe"),
    [
        ({}, False, False),
        ({"persistent": "1"}, True, False),
        ({"persistent": "True"}, True, False),
        ({"persistent": "0"}, False, False),
        ({"probe": "1", "md5sum": "*"}, False, True),
    ],
)
def test_server_accepts(extra: dict[str, str], persistent: bool, probe: bool) -> None:
    request = {"callerid": "/c", "service": "/add_two_ints", "md5sum": ADD_MD5, **extra}
    assert accept_client(request, callerid="/server", services=SERVICES) == ServiceClientAccepted(
        callerid="/c",
        service=ADD,
        persistent=persistent,
        probe=probe,
        reply=server_header(ADD, callerid="/server"),
    )


@pytest.mark.parametrize(
    ("request_fields", "reason"),
    [
        ({"md5sum": "*", "callerid": "/c"}, "Missing required 'service' field"),
        ({"service": "/add_two_ints", "callerid": "/c"}, "Missing required 'md5sum' field"),
        ({"service": "/add_two_ints", "md5sum": "*"}, "Missing required 'callerid' field"),
        (
            {"service": "/nope", "md5sum": "*", "callerid": "/c"},
            "[/server] is not a provider of  [/nope]",
        ),
        (
            {"service": "/add_two_ints", "md5sum": "bad", "callerid": "/c"},
            f"request from [/c]: md5sums do not match: [bad] vs. [{ADD_MD5}]",
        ),
    ],
)
def test_server_refuses_with_rospys_texts(request_fields: dict[str, str], reason: str) -> None:
    assert accept_client(request_fields, callerid="/server", services=SERVICES) == Refused(reason)


def test_client_checks_the_server_header() -> None:
    reply = server_header(ADD, callerid="/server")
    assert check_server_reply(reply, service="/add_two_ints", md5sum=ADD_MD5) == (
        ServiceServerAccepted(
            callerid="/server", type="rospy_tutorials/AddTwoInts", md5sum=ADD_MD5, header=reply
        )
    )
    assert check_server_reply({"error": "no"}, service="/s", md5sum="*") == Refused(
        "no", by_peer=True
    )
    mismatch = check_server_reply(reply, service="/add_two_ints", md5sum="0" * 32)
    assert isinstance(mismatch, Refused)
    assert "service [/add_two_ints]" in mismatch.reason
    assert not mismatch.by_peer


def test_response_bytes() -> None:
    assert encode_response(b"abc") == b"\x01\x03\x00\x00\x00abc"
    assert encode_response(b"") == b"\x01\x00\x00\x00\x00"
    assert encode_error("oops!") == b"\x00\x05\x00\x00\x00oops!"
    assert encode_error("\u00e9") == b"\x00\x02\x00\x00\x00\xc3\xa9"


SERVER_STREAM = (
    encode_header(server_header(ADD, callerid="/server"))
    + encode_response(b"\x03\x00\x00\x00\x00\x00\x00\x00")
    + encode_error("service cannot process request: no")
    + encode_response(b"")
)
EVENTS = [
    ServerHeader(server_header(ADD, callerid="/server")),
    ServiceResponse(ok=True, payload=b"\x03\x00\x00\x00\x00\x00\x00\x00"),
    ServiceResponse(ok=False, payload=b"service cannot process request: no"),
    ServiceResponse(ok=True, payload=b""),
]


def _drain(reader: ServiceReplyReader) -> list[ServerHeader | ServiceResponse]:
    out: list[ServerHeader | ServiceResponse] = []
    while (event := reader.next_event()) is not None:
        out.append(event)
    return out


@pytest.mark.parametrize("how", CHUNKINGS)
def test_reply_reader_in_any_chunking(how: str) -> None:
    reader = ServiceReplyReader()
    events: list[ServerHeader | ServiceResponse] = []
    for piece in pieces(SERVER_STREAM + encode_response(b"xyz")[:6], how):
        reader.feed(piece)
        events.extend(_drain(reader))
    assert events == EVENTS
    error = events[2]
    assert isinstance(error, ServiceResponse)
    assert error.error == "service cannot process request: no"
    reader.feed(b"yz")
    assert reader.next_event() == ServiceResponse(ok=True, payload=b"xyz")


def test_reply_reader_without_header_and_any_nonzero_ok_byte() -> None:
    reader = ServiceReplyReader(expect_header=False)
    reader.feed(b"\x02\x01\x00\x00\x00z")
    assert reader.next_event() == ServiceResponse(ok=True, payload=b"z")


def test_reply_reader_limits() -> None:
    reader = ServiceReplyReader(max_header_size=8)
    reader.feed(b"\x09\x00\x00\x00")
    with pytest.raises(OversizedError, match="service connection header of 9 bytes"):
        reader.next_event()
    reader = ServiceReplyReader(expect_header=False, max_response_size=3)
    reader.feed(b"\x01\x04\x00\x00\x00")
    with pytest.raises(OversizedError, match="service response of 4 bytes"):
        reader.next_event()
    reader = ServiceReplyReader()
    reader.feed(b"\x07\x00\x00\x00\x03\x00\x00\x00abc")
    with pytest.raises(ProtocolError, match="no '='"):
        reader.next_event()


def test_rosrpc_uris() -> None:
    assert format_rosrpc_uri("host", 1234) == "rosrpc://host:1234"
    assert parse_rosrpc_uri("rosrpc://host:1234") == ("host", 1234)
    assert parse_rosrpc_uri("rosrpc://10.0.0.1:80/extra") == ("10.0.0.1", 80)
    with pytest.raises(ProtocolError, match="Invalid protocol for ROS service URL: http://h:1"):
        parse_rosrpc_uri("http://h:1")
    for bad in (
        "rosrpc://host",
        "rosrpc://host:x",
        "rosrpc://:1",
        "rosrpc://a:b:1",
        "rosrpc://h:1²",
    ):
        with pytest.raises(ProtocolError, match=f"ROS service URL is invalid: {bad}"):
            parse_rosrpc_uri(bad)


def test_ipv6_rosrpc_uris() -> None:
    assert format_rosrpc_uri("::1", 4000) == "rosrpc://[::1]:4000"
    assert parse_rosrpc_uri("rosrpc://[::1]:4000/") == ("::1", 4000)
    # As ROS 1's nodes write it, without brackets: the port follows the last colon.
    assert parse_rosrpc_uri("rosrpc://fd00::2:4000") == ("fd00::2", 4000)
    with pytest.raises(ProtocolError, match="ROS service URL is invalid"):
        parse_rosrpc_uri("rosrpc://[::1]")
