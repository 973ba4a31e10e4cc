"""A message framed in parts (`rosx.msg.codec.parts`): the same bytes as its whole frame, its
large byte arrays sent from the message itself; received in parts, the same message as its whole
frame decodes to, its large array the bytes as read."""

from __future__ import annotations

from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.codegen import variant
from rosx.msg.codec.parts import (
    LARGE,
    FrameInParts,
    array_locator,
    decode_in_parts,
    frame_parts,
    in_parts,
)

Image = get_message_class("sensor_msgs/Image")
CompressedImage = get_message_class("sensor_msgs/CompressedImage")
PointCloud2 = get_message_class("sensor_msgs/PointCloud2")
PointField = get_message_class("sensor_msgs/PointField")
UInt8MultiArray = get_message_class("std_msgs/UInt8MultiArray")
MultiArrayDimension = get_message_class("std_msgs/MultiArrayDimension")


def joined(frame: bytes | tuple[bytes, ...]) -> bytes:
    return frame if isinstance(frame, bytes) else b"".join(frame)


def test_types_with_a_byte_array_are_framed_in_parts() -> None:
    for name in ("sensor_msgs/Image", "sensor_msgs/CompressedImage", "std_msgs/UInt8MultiArray"):
        assert in_parts(get_message_class(name)), name
    # A byte array inside an embedded message counts too (stereo_msgs' image).
    assert in_parts(get_message_class("stereo_msgs/DisparityImage"))
    for name in ("geometry_msgs/Twist", "sensor_msgs/LaserScan", "std_msgs/String"):
        assert not in_parts(get_message_class(name)), name
    assert not in_parts(dict)


def cloud(data: Any) -> Any:
    fields = [
        PointField(name=axis, offset=4 * i, datatype=7, count=1) for i, axis in enumerate("xyz")
    ]
    return PointCloud2(height=1, width=7, fields=fields, point_step=12, data=data, is_dense=True)


@pytest.mark.parametrize(
    "msg",
    [
        Image(height=2, encoding="mono8", step=3, data=bytes(range(256)) * 1024),
        Image(encoding="rgb8", data=b"\x01\x02\x03"),
        Image(data=bytes(LARGE)),
        Image(data=bytes(LARGE - 1)),
        CompressedImage(format="jpeg", data=bytearray(b"\xff\xd8" * 40_000)),
        cloud(list(range(256)) * 200),
        cloud(bytes(3 << 20)),
        UInt8MultiArray(data=bytes(100_000)),
    ],
    ids=["image", "small", "at-large", "under-large", "bytearray", "list", "cloud", "multiarray"],
)
def test_the_parts_are_the_whole_frame(msg: Any) -> None:
    frame = frame_parts(msg)
    assert joined(frame) == msg._frame()


def test_a_large_array_is_sent_from_the_message_itself() -> None:
    data = bytes(range(256)) * 4096
    msg = Image(header=get_message_class("std_msgs/Header")(seq=7, frame_id="cam"), data=data)
    frame = frame_parts(msg)
    assert isinstance(frame, tuple)
    assert frame[1] is data  # no copy
    assert len(frame) == 2  # nothing after it: Image ends with its data
    assert int.from_bytes(frame[0][:4], "little") == len(joined(frame)) - 4


def test_small_arrays_make_one_frame() -> None:
    msg = Image(encoding="mono8", data=bytes(LARGE - 1))
    assert frame_parts(msg) == msg._frame()


def test_a_frame_keeps_what_was_published_when_the_message_changes() -> None:
    msg = Image(data=bytes(LARGE) + b"first")
    frame = frame_parts(msg)
    before = joined(frame)
    msg.data = bytes(LARGE) + b"second"
    msg.height = 99
    assert joined(frame) == before


def test_what_cannot_be_serialized_is_refused_as_by_the_whole_frame() -> None:
    msg = Image(data=bytes(LARGE), height="tall")
    with pytest.raises(Exception) as whole:
        msg._frame()
    with pytest.raises(type(whole.value)) as parts:
        frame_parts(msg)
    assert str(parts.value) == str(whole.value)


def test_types_without_a_byte_array_use_their_own_frame() -> None:
    twist = get_message_class("geometry_msgs/Twist")()
    twist.linear.x = 1.5
    assert frame_parts(twist) == twist._frame()
    dims = [MultiArrayDimension(label="x", size=3, stride=3)]
    floats = get_message_class("std_msgs/Float32MultiArray")(data=[1.0] * 20_000)
    floats.layout.dim = dims
    assert frame_parts(floats) == floats._frame()


def received_in_parts(msg: Any) -> FrameInParts:
    """``msg``'s payload as a reader would take it in parts, found by the type's locator in the
    payload's first 4 KiB."""
    payload = msg._frame()[4:]
    locate = array_locator(type(msg))
    assert locate is not None
    at = locate(payload[:4096])
    assert at is not None
    count = int.from_bytes(payload[at : at + 4], "little")
    return FrameInParts(
        payload[: at + 4], payload[at + 4 : at + 4 + count], payload[at + 4 + count :]
    )


@pytest.mark.parametrize(
    "msg",
    [
        Image(height=2, encoding="mono8", step=3, data=bytes(range(256)) * 1024),
        Image(encoding="rgb8", data=b""),
        CompressedImage(format="jpeg", data=b"\xff\xd8" * 40_000),
        cloud(bytes(range(256)) * 300),
        UInt8MultiArray(data=bytes(100_000)),
    ],
    ids=["image", "empty", "compressed", "cloud", "multiarray"],
)
def test_a_frame_received_in_parts_decodes_to_the_message_of_the_whole_frame(msg: Any) -> None:
    if hasattr(msg, "header"):
        msg.header.frame_id = "cámara"  # not ASCII: decoded as UTF-8 around the array
    if isinstance(msg, UInt8MultiArray):
        msg.layout.dim = [MultiArrayDimension(label="rows", size=10, stride=100_000)]
        msg.layout.data_offset = 3
    frame = received_in_parts(msg)
    assert frame.whole() == msg._frame()[4:]
    cls = type(msg)
    decoded = decode_in_parts(variant(cls, "deserialize_fresh"), cls, frame)
    assert decoded == msg
    assert decoded._frame() == msg._frame()
    assert type(decoded.data) is bytes
    assert decoded.data is frame.array  # the bytes as read: no copy


def test_the_locator_needs_the_bytes_before_the_array_and_its_length() -> None:
    msg = cloud(bytes(LARGE))
    msg.header.frame_id = "lidar"
    payload = msg._frame()[4:]
    locate = array_locator(PointCloud2)
    assert locate is not None
    at = locate(payload)
    assert at is not None
    assert int.from_bytes(payload[at : at + 4], "little") == LARGE
    assert payload[at + 4 : at + 4 + LARGE] == msg.data
    assert locate(payload[: at + 4]) == at
    for cut in (0, 3, 20, at, at + 3):
        assert locate(payload[:cut]) is None, cut


def test_only_a_byte_array_of_the_message_itself_is_found() -> None:
    for name in ("geometry_msgs/Twist", "std_msgs/String", "nav_msgs/OccupancyGrid"):
        assert array_locator(get_message_class(name)) is None, name
    # The first byte array is inside the embedded image: not found, read whole.
    assert array_locator(get_message_class("stereo_msgs/DisparityImage")) is None
