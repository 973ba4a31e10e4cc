"""Property-based round trips of the wire codec over every bundled message type and both
halves of every bundled service type.

For any message hypothesis builds (every field kind, nested messages, arrays of any length,
non-ASCII strings, extreme integers, float32-exact floats), decoding its bytes gives back the
same values, and encoding the decoded message gives the same bytes. Random bytes read as any of
these types give a message or a `DeserializationError` with one line of text, with and without
numpy, and damaging a valid message's bytes changes nothing about that.
"""

from __future__ import annotations

import io
from typing import Any

import numpy
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import DeserializationError
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.wiretypes import INTEGER_RANGES
from rosx.msg.spec import Field
from rosx.msg.store import TypeStore
from tests.support.fuzz import fuzz_settings, no_hang

STORE = TypeStore([])
TYPES = (
    STORE.types("msg")
    + [STORE.srv(name).request.full_name for name in STORE.types("srv")]
    + [STORE.srv(name).response.full_name for name in STORE.types("srv")]
)
_MAX_ITEMS = 4


def _scalar(base: str) -> st.SearchStrategy[Any]:
    if base in INTEGER_RANGES:
        low, high = INTEGER_RANGES[base]
        return st.integers(low, high)
    if base == "bool":
        return st.booleans()
    if base == "float32":
        return st.floats(width=32, allow_nan=False)
    if base == "float64":
        return st.floats(allow_nan=False)
    if base == "string":
        return st.text(max_size=12)
    if base == "time":
        return st.builds(Time, st.integers(0, 2**32 - 1), st.integers(0, 999_999_999))
    if base == "duration":
        return st.builds(Duration, st.integers(-(2**31), 2**31 - 1), st.integers(0, 999_999_999))
    return st.deferred(lambda: message(base))


def _field(field: Field) -> st.SearchStrategy[Any]:
    if not field.is_array:
        return _scalar(field.base_type)
    size = field.array_len
    if field.base_type in ("uint8", "char"):
        return st.binary(min_size=size or 0, max_size=size if size is not None else 16)
    items = _scalar(field.base_type)
    if size is not None:
        return st.lists(items, min_size=size, max_size=size)
    return st.lists(items, max_size=_MAX_ITEMS)


def message(type_name: str) -> st.SearchStrategy[Any]:
    cls = get_message_class(type_name, STORE)
    spec = STORE.msg(type_name)
    return st.builds(cls, **{f.name: _field(f) for f in spec.fields})


def plain(value: Any) -> Any:
    """A value with lists and tuples alike, for comparing what went in with what came out."""
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if hasattr(value, "__slots__") and hasattr(value, "_type"):
        return {
            name: plain(getattr(value, name))
            for name in value.__slots__
            if name != "_connection_header"
        }
    if isinstance(value, (Time, Duration)):
        return (type(value).__name__, value.secs, value.nsecs)
    return value


def encode(msg: Any) -> bytes:
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue()


@pytest.mark.parametrize("type_name", TYPES)
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_round_trip(type_name: str, data: st.DataObject) -> None:
    msg = data.draw(message(type_name))
    wire = encode(msg)
    back = get_message_class(type_name, STORE)().deserialize(wire)
    assert plain(back) == plain(msg)
    assert encode(back) == wire
    assert msg._frame() == len(wire).to_bytes(4, "little") + wire


def _read_or_refuse(type_name: str, data: bytes) -> None:
    cls = get_message_class(type_name, STORE)
    for read in (cls().deserialize, lambda d: cls().deserialize_numpy(d, numpy)):
        try:
            with no_hang():
                read(data)
        except DeserializationError as error:
            assert str(error)
            assert "\n" not in str(error)


@pytest.mark.fuzz
@fuzz_settings(25)
@given(data=st.binary(max_size=200))
def test_random_bytes_read_as_every_type_or_are_refused(data: bytes) -> None:
    for type_name in TYPES:
        _read_or_refuse(type_name, data)


@pytest.mark.fuzz
@fuzz_settings(300)
@given(type_name=st.sampled_from(TYPES), data=st.data())
def test_damaged_messages_read_or_are_refused(type_name: str, data: st.DataObject) -> None:
    wire = bytearray(encode(data.draw(message(type_name))))
    if wire:
        at = data.draw(st.integers(0, len(wire) - 1))
        wire[at : at + 4] = data.draw(st.sampled_from([b"\xff\xff\xff\xff", b"\x00", b"\x80"]))
    cut = data.draw(st.integers(0, len(wire)))
    _read_or_refuse(type_name, bytes(wire[:cut]))
