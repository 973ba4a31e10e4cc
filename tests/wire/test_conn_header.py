"""TCPROS connection headers: byte-exact encoding, decoding in any chunking, refusals."""

from __future__ import annotations

import pytest

from rosx.wire.errors import ProtocolError
from rosx.wire.framing import FrameReader
from rosx.wire.header import Refused, decode_header, encode_header
from tests.support.wirefeed import CHUNKINGS, pieces

# Built by hand from ROS/Connection Header: uint32 LE total length, then per field a uint32 LE
# length and "name=value".
TWO_FIELDS = (
    b"\x26\x00\x00\x00"  # 38 = (4 + 16) + (4 + 14)
    b"\x10\x00\x00\x00callerid=/talker"
    b"\x0e\x00\x00\x00topic=/chatter"
)


def test_encode_is_byte_exact() -> None:
    assert encode_header({"callerid": "/talker", "topic": "/chatter"}) == TWO_FIELDS


def test_encode_keeps_the_given_order() -> None:
    encoded = encode_header({"topic": "/chatter", "callerid": "/talker"})
    assert encoded == (
        b"\x26\x00\x00\x00\x0e\x00\x00\x00topic=/chatter\x10\x00\x00\x00callerid=/talker"
    )


def test_empty_header() -> None:
    assert encode_header({}) == b"\x00\x00\x00\x00"
    assert decode_header(b"") == {}


def test_decode_is_the_inverse_without_the_prefix() -> None:
    assert decode_header(TWO_FIELDS[4:]) == {"callerid": "/talker", "topic": "/chatter"}
    assert list(decode_header(TWO_FIELDS[4:])) == ["callerid", "topic"]


def test_value_splits_at_the_first_equals_sign() -> None:
    block = b"\x0b\x00\x00\x00a=b=c=d\n==e"
    assert decode_header(block) == {"a": "b=c=d\n==e"}
    fields = {"message_definition": "int32 X=1\nint32 x\n", "md5sum": "*"}
    assert decode_header(encode_header(fields)[4:]) == fields


def test_utf8_lengths_count_bytes() -> None:
    encoded = encode_header({"callerid": "/n\u00e9"})
    assert encoded == b"\x11\x00\x00\x00\x0d\x00\x00\x00callerid=/n\xc3\xa9"
    assert decode_header(encoded[4:]) == {"callerid": "/n\u00e9"}


def test_empty_value_and_repeated_name() -> None:
    assert decode_header(b"\x02\x00\x00\x00a=\x03\x00\x00\x00a=1") == {"a": "1"}
    assert decode_header(b"\x02\x00\x00\x00a=") == {"a": ""}


@pytest.mark.parametrize(
    ("block", "message"),
    [
        (b"\x10\x00\x00\x00abc", "field 0 claims 16 bytes but only 3 remain"),
        (b"\x03\x00\x00\x00a=b\x05\x00", "ends inside the length of field 1 (2 of 4 bytes"),
        (b"\x00\x00\x00\x00", "field 0 is empty"),
        (b"\x03\x00\x00\x00a=b\x03\x00\x00\x00abc", "field 1 has no '='"),
        (b"\x03\x00\x00\x00a=\xff", "field 0 is not UTF-8"),
    ],
)
def test_malformed_blocks_are_refused(block: bytes, message: str) -> None:
    with pytest.raises(ProtocolError, match=message.replace("(", r"\(")):
        decode_header(block)


@pytest.mark.parametrize("name", ["", "a=b"])
def test_encode_refuses_names_a_peer_could_not_split(name: str) -> None:
    with pytest.raises(ProtocolError, match="field name"):
        encode_header({name: "x"})


@pytest.mark.parametrize("how", CHUNKINGS)
def test_header_then_data_through_a_frame_reader(how: str) -> None:
    stream = TWO_FIELDS + b"\x02\x00\x00\x00hi" + b"\x05\x00\x00"  # a header, a frame, a partial
    reader = FrameReader()
    frames: list[bytes] = []
    for piece in pieces(stream, how):
        reader.feed(piece)
        frames.extend(reader.frames())
    assert decode_header(frames[0]) == {"callerid": "/talker", "topic": "/chatter"}
    assert frames[1:] == [b"hi"]
    assert reader.buffered == 3


def test_refused_carries_only_an_error_field() -> None:
    refused = Refused("no such topic")
    assert refused.header == {"error": "no such topic"}
    assert encode_header(refused.header) == b"\x17\x00\x00\x00\x13\x00\x00\x00error=no such topic"
    assert not refused.by_peer
    assert refused == Refused("no such topic", by_peer=False)
    assert refused != Refused("no such topic", by_peer=True)
    assert repr(refused) == "Refused(reason='no such topic', by_peer=False)"
    with pytest.raises(AttributeError, match="immutable"):
        refused.reason = "changed"
