"""Message, service and action definitions under fuzz.

Definitions made of the language's own pieces (types, array suffixes, names, constants,
comments, ``---`` separators) and of random text are parsed as ``.msg``, ``.srv`` and
``.action``: each is a spec or an `InvalidMsgSpecError` with one line of text. A ``.msg`` the
parser accepts is then put in a package and its class built, as ``rosmsg`` and a node do: the
class is built or refused (`InvalidMsgSpecError`, `UnknownTypeError`), a default message
serializes and reads back, and random bytes read as it give the message or a
`DeserializationError`. Array bounds of billions are refused without allocating them.
"""

from __future__ import annotations

import io
import tempfile
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import DeserializationError
from rosx.msg.parser import InvalidMsgSpecError, parse_action, parse_msg, parse_srv
from rosx.msg.spec import PRIMITIVE_TYPES
from rosx.msg.store import TypeStore, UnknownTypeError
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation
from tests.support.msgpackages import make_package

pytestmark = pytest.mark.fuzz

_TYPES = st.sampled_from(
    [
        *sorted(PRIMITIVE_TYPES),
        "Header",
        "std_msgs/String",
        "std_msgs/Empty",
        "geometry_msgs/Point",
        "Other",
        "fuzz/Fuzz",
        "fuzz/Missing",
        "no/such",
        "bad//type",
        "9bad",
    ]
)
_SUFFIXES = st.one_of(
    st.sampled_from(["", "", "[]", "[0]", "[1]", "[3]", "[", "]", "[-1]", "[][]", "[x]"]),
    st.integers(0, 2**64).map(lambda n: f"[{n}]"),
)
_NAMES = st.one_of(
    st.sampled_from(["x", "data", "header", "X_1", "_x", "1x", "a-b", "x", "CONST"]),
    st.text(alphabet="abcxyzXYZ_019", min_size=1, max_size=6),
)
_VALUES = st.one_of(
    st.sampled_from(["0", "-1", "1.5", "True", "hello # c", "255", "256", "1e400", "nan", "x"]),
    st.integers(-(2**70), 2**70).map(str),
    st.text(max_size=10),
)
_WS = st.sampled_from([" ", "  ", "\t", ""])


@st.composite
def _line(draw: st.DrawFn) -> str:
    kind = draw(st.sampled_from(["field", "field", "constant", "comment", "separator", "junk"]))
    if kind == "field":
        return f"{draw(_TYPES)}{draw(_SUFFIXES)}{draw(_WS)} {draw(_NAMES)}"
    if kind == "constant":
        return f"{draw(_TYPES)} {draw(_NAMES)}{draw(_WS)}={draw(_WS)}{draw(_VALUES)}"
    if kind == "comment":
        return "#" + draw(st.text(max_size=20))
    if kind == "separator":
        return draw(st.sampled_from(["---", "----", " ---", "---x"]))
    return draw(st.text(max_size=30))


definitions = st.one_of(
    st.lists(_line(), max_size=12).map("\n".join),
    st.text(max_size=200),
)


def _one_line(error: Exception) -> None:
    text = str(error)
    assert text
    assert "\n" not in text


@fuzz_settings(300)
@given(text=definitions)
def test_definitions_parse_or_are_refused(text: str) -> None:
    for parse in (parse_msg, parse_srv, parse_action):
        try:
            with no_hang():
                parse("fuzz/Fuzz", text)
        except InvalidMsgSpecError as error:
            _one_line(error)


@pytest.fixture(scope="module")
def folder() -> Any:
    with tempfile.TemporaryDirectory() as name:
        yield Path(name)


def _class_of(root: Path, text: str, other: str = "int32 y\n") -> Any:
    """The class of ``fuzz/Fuzz`` defined by ``text``, from a package written under ``root``;
    None when it is refused."""
    make_package(root, "fuzz", {"Fuzz": text, "Other": other})
    try:
        with no_hang():
            return get_message_class("fuzz/Fuzz", TypeStore([root]))
    except (InvalidMsgSpecError, UnknownTypeError) as error:
        _one_line(error)
        return None


def _serialized(msg: Any) -> bytes:
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue()


@fuzz_settings(80)
@given(text=definitions, data=st.binary(max_size=64))
def test_accepted_definitions_make_classes_that_read_any_bytes(
    folder: Path, text: str, data: bytes
) -> None:
    with tempfile.TemporaryDirectory(dir=folder) as name:
        cls = _class_of(Path(name), text)
    if cls is None:
        return
    with no_hang():
        default = cls()
        wire = _serialized(default)
        assert _serialized(cls().deserialize(wire)) == wire
        try:
            cls().deserialize(data)
        except DeserializationError as error:
            _one_line(error)


# -- bombs: a few bytes of definition that ask for gigabytes ------------------------------------

BOMBS = {
    "byte array bound": "uint8[4294967295] data\n",
    "number array bound": "float64[1000000000] data\n",
    "string array bound": "string[100000000] data\n",
    "message array bound": "geometry_msgs/Point[50000000] points\n",
    # Each bound alone is small; nested, they multiply.
    "nested bounds": "Other[60000] others\n",
}
_NESTED_OTHER = "float64[60000] values\n"


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_huge_array_bounds_are_refused_without_allocating(folder: Path, name: str) -> None:
    built: list[object] = []
    with tempfile.TemporaryDirectory(dir=folder) as root:
        peak = peak_allocation(
            lambda: built.append(_class_of(Path(root), BOMBS[name], _NESTED_OTHER))
        )
    assert peak < MEMORY_BOUND
    assert built == [None]


def test_a_count_of_billions_of_empty_elements_is_refused(folder: Path) -> None:
    # Four bytes on the wire; each element an object and no bytes.
    with tempfile.TemporaryDirectory(dir=folder) as root:
        cls = _class_of(Path(root), "std_msgs/Empty[] nothing\nint8 after\n")
    assert len(cls().deserialize(b"\x03\x00\x00\x00\x07").nothing) == 3
    with no_hang(), pytest.raises(DeserializationError) as caught:
        cls().deserialize(b"\xff\xff\xff\xff\x07")
    _one_line(caught.value)
