"""The bridge's encodings without sockets: messages straight to JSON text (the same text as
through dictionaries and ``json.dumps``, for every message type rosx knows), WebSocket frame
headers (as `websockets` writes them), and cbor-raw's two pieces (as ``cbor2`` writes the
whole)."""

from __future__ import annotations

import json
import math
import random
from typing import Any

import cbor2
import pytest
from websockets.frames import Frame, Opcode

from rosx.bridge import wsframes
from rosx.bridge.convert import json_values
from rosx.bridge.jsontext import json_text
from rosx.bridge.outgoing import Outgoing, serialize
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, INTEGER_RANGES
from rosx.msg.store import default_store

FLOATS = [0.0, -0.0, 1.5, -2.25e-308, 1e300, 0.1, math.nan, math.inf, -math.inf, 123456789.125]
TEXTS = [
    "",
    "plain",
    'quote " and \\ backslash',
    "tab\tnew\nline",
    "é ü ∑",
    "\U0001f422",
    "\x00\x1f",
]


def dumped(msg: Any) -> str:
    return json.dumps(json_values(msg), separators=(",", ":"), allow_nan=False)


def fill(cls: type[Any], rng: random.Random, depth: int = 0) -> Any:
    """A message of ``cls`` with every field set to a value picked from awkward ones."""
    msg = cls()
    spec = cls._spec
    for field in spec.fields:
        name = field.name + "_" if not hasattr(msg, field.name) else field.name
        count = field.array_len if field.array_len is not None else rng.randint(0, 3)
        if field.is_array and field.base_type in BYTE_ARRAY_TYPES:
            value: Any = bytes(rng.randrange(256) for _ in range(count))
        elif field.is_array:
            value = [_scalar(field.base_type, rng, depth) for _ in range(count)]
        else:
            value = _scalar(field.base_type, rng, depth)
        setattr(msg, name, value)
    return msg


def _scalar(base: str, rng: random.Random, depth: int) -> Any:
    if base in ("float32", "float64"):
        return rng.choice(FLOATS)
    if base in INTEGER_RANGES:
        low, high = INTEGER_RANGES[base]
        return rng.choice([low, high, 0, 1, (low + high) // 2])
    if base == "bool":
        return rng.random() < 0.5
    if base == "string":
        return rng.choice(TEXTS)
    if base == "time":
        return Time(rng.randrange(2**31), rng.randrange(10**9))
    if base == "duration":
        return Duration(rng.randrange(-(2**31), 2**31), rng.randrange(10**9))
    nested = get_message_class(base)
    return fill(nested, rng, depth + 1) if depth < 4 else nested()


def test_every_known_message_type_gives_the_same_text_as_json_dumps() -> None:
    rng = random.Random(34)
    types = default_store().types("msg")
    assert len(types) > 100
    for name in types:
        cls = get_message_class(name)
        for msg in (cls(), fill(cls, rng), fill(cls, rng)):
            assert json_text(msg) == dumped(msg), name


def test_values_the_generated_code_does_not_expect_fall_back_to_the_long_way() -> None:
    twist_class = get_message_class("geometry_msgs/Twist")
    msg = twist_class()
    msg.linear.x = 3  # an integer in a float field: json_values writes it as 3
    out = Outgoing.of("/cmd_vel", msg, 0)
    assert json.loads(out.publish_json())["msg"]["linear"] == {"x": 3, "y": 0.0, "z": 0.0}
    with pytest.raises(TypeError):
        json_text(msg)


@pytest.mark.parametrize("length", [0, 1, 125, 126, 4095, 4096, 65535, 65536, 70000])
@pytest.mark.parametrize("opcode", [Opcode.TEXT, Opcode.BINARY])
def test_frames_are_the_bytes_websockets_writes(length: int, opcode: Opcode) -> None:
    data = bytes(range(256)) * (length // 256) + bytes(length % 256)
    frame: Any = data.decode("latin-1") if opcode is Opcode.TEXT else data
    if opcode is Opcode.TEXT:
        data = frame.encode()
    expected = Frame(opcode, data).serialize(mask=False, extensions=[])
    assert b"".join(wsframes.wire(frame)) == expected
    if opcode is Opcode.BINARY:  # in pieces: the same bytes, a big piece not copied
        rest = data[10:]
        pieces = wsframes.wire((data[:10], rest))
        assert b"".join(pieces) == expected
        assert (pieces[-1] is rest) == (length >= wsframes.JOIN_BELOW)


@pytest.mark.parametrize("length", [0, 23, 24, 255, 256, 65535, 65536])
def test_cbor_raw_pieces_are_the_cbor_of_the_whole_message(length: int) -> None:
    string_class = get_message_class("std_msgs/String")
    raw = serialize(string_class("x" * max(0, length - 4)))[: max(length, 4)]
    out = Outgoing("/chatter", raw, string_class, 1_700_000_000_000_000_005)
    head, body = out.publish_cbor_raw()
    assert body is raw
    whole = {
        "op": "publish",
        "topic": "/chatter",
        "msg": {"secs": 1_700_000_000, "nsecs": 5, "bytes": raw},
    }
    assert head + body == cbor2.dumps(whole)
