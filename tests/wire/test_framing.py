"""Length-prefixed frames: byte-exact framing, any chunking, limits, large and tiny frames."""

from __future__ import annotations

import pytest

from rosx.wire.errors import OversizedError, ProtocolError
from rosx.wire.framing import FrameReader, frame, length_prefix
from tests.support.wirefeed import CHUNKINGS, pieces

PAYLOADS = [b"", b"a", b"\x00" * 48, bytes(range(256)) * 4]
STREAM = b"".join(frame(p) for p in PAYLOADS)


def test_frame_is_byte_exact() -> None:
    assert frame(b"abc") == b"\x03\x00\x00\x00abc"
    assert frame(b"") == b"\x00\x00\x00\x00"
    assert frame(bytearray(b"\x01" * 258)) == b"\x02\x01\x00\x00" + b"\x01" * 258
    assert length_prefix(0x01020304) == b"\x04\x03\x02\x01"


def test_length_prefix_refuses_what_uint32_cannot_hold() -> None:
    with pytest.raises(ProtocolError, match="does not fit"):
        length_prefix(2**32)


def _drain_one_by_one(reader: FrameReader) -> list[bytes]:
    out: list[bytes] = []
    while (payload := reader.next_frame()) is not None:
        out.append(payload)
    return out


@pytest.mark.parametrize("how", CHUNKINGS)
@pytest.mark.parametrize("take", ["next_frame", "frames"])
def test_frames_in_any_chunking(how: str, take: str) -> None:
    reader = FrameReader()
    got: list[bytes] = []
    for piece in pieces(STREAM, how):
        reader.feed(piece)
        got.extend(_drain_one_by_one(reader) if take == "next_frame" else reader.frames())
    assert got == PAYLOADS
    assert all(type(p) is bytes for p in got)
    assert reader.buffered == 0
    assert reader.next_frame() is None


@pytest.mark.parametrize("how", CHUNKINGS)
def test_trailing_bytes_wait_for_the_rest(how: str) -> None:
    trailing = frame(b"next message")[:7]
    reader = FrameReader()
    got: list[bytes] = []
    for piece in pieces(STREAM + trailing, how):
        reader.feed(piece)
        got.extend(reader.frames())
    assert got == PAYLOADS
    assert reader.buffered == 7
    reader.feed(frame(b"next message")[7:] + frame(b"z")[:2])
    assert reader.frames() == [b"next message"]
    assert reader.buffered == 2


def test_oversized_frame_is_refused_from_its_prefix_alone() -> None:
    reader = FrameReader(max_frame_size=10)
    reader.feed(frame(b"0123456789"))
    assert reader.next_frame() == b"0123456789"
    reader.feed(b"\x0b\x00\x00\x00")
    with pytest.raises(OversizedError, match="frame of 11 bytes exceeds the limit of 10") as info:
        reader.next_frame()
    assert (info.value.size, info.value.limit) == (11, 10)
    huge = FrameReader()
    huge.feed(b"\xff\xff\xff\xff")
    with pytest.raises(OversizedError):
        huge.frames()


def test_frames_returns_good_frames_before_raising_on_an_oversized_one() -> None:
    data = frame(b"ok") + b"\x64\x00\x00\x00"
    joined = FrameReader(max_frame_size=50)
    joined.feed(data)
    grown = FrameReader(max_frame_size=50)  # a feed smaller than what is buffered grows in place
    grown.feed(data[:-1])
    grown.feed(data[-1:])
    for reader in (joined, grown):
        assert reader.frames() == [b"ok"]
        with pytest.raises(OversizedError):
            reader.frames()


def test_limit_can_change_between_frames() -> None:
    reader = FrameReader(max_frame_size=4)
    reader.feed(frame(b"head") + frame(b"a longer body"))
    assert reader.next_frame() == b"head"
    with pytest.raises(OversizedError):
        reader.next_frame()
    reader.max_frame_size = 100
    assert reader.next_frame() == b"a longer body"


def test_reader_keeps_its_own_copy_of_fed_buffers() -> None:
    source = bytearray(frame(b"abc"))
    reader = FrameReader()
    reader.feed(source)
    source[4:7] = b"xyz"
    assert reader.next_frame() == b"abc"
    view_source = bytearray(frame(b"defg"))
    reader.feed(memoryview(view_source)[:6])
    view_source[4] = ord("X")
    reader.feed(memoryview(view_source)[6:])
    assert reader.next_frame() == b"defg"


@pytest.mark.parametrize("chunk", [1, 1000, 4096, 65536, 1 << 20])
def test_one_mebibyte_frames(chunk: int) -> None:
    payload = bytes(range(256)) * 4096  # 1 MiB
    stream = frame(payload) * 2 + frame(b"tail")
    if chunk == 1:
        stream = frame(payload[:65536]) + frame(b"tail")  # byte by byte, kept short
    reader = FrameReader()
    got: list[bytes] = []
    for pos in range(0, len(stream), chunk):
        reader.feed(stream[pos : pos + chunk])
        got.extend(reader.frames())
    expected = [payload[:65536], b"tail"] if chunk == 1 else [payload, payload, b"tail"]
    assert got == expected


def test_many_tiny_frames_from_large_reads() -> None:
    twists = [bytes([i % 256]) * 48 for i in range(5000)]
    stream = b"".join(frame(t) for t in twists)
    reader = FrameReader()
    got: list[bytes] = []
    for pos in range(0, len(stream), 65536):
        reader.feed(stream[pos : pos + 65536])
        got.extend(reader.frames())
    assert got == twists


def test_a_pending_large_frame_is_handed_over_for_direct_reading() -> None:
    reader = FrameReader()
    payload = bytes(range(256)) * 40
    data = frame(b"small") + frame(payload)
    reader.feed(data[:100])
    assert reader.frames() == [b"small"]
    assert reader.pending() == len(payload)
    into = bytearray(len(payload))
    head = reader.take_pending(into)
    assert head == 100 - 9 - 4
    assert into[:head] == payload[:head]
    assert reader.buffered == 0
    assert reader.pending() == 0
    reader.feed(frame(b"next"))
    assert reader.frames() == [b"next"]
