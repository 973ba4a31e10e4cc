"""YAML under fuzz, as ``rosparam`` and ``rostopic pub`` read it.

Text made of YAML's own pieces (indentation, flow collections, anchors and aliases, tags,
scalars of every implicit type, ``deg()``/``rad()``) and random text is read as rosparam reads a
file (`load_documents`, then `check_value` of each value) and as rostopic pub reads its
arguments (`load_args`, then `fill_message_args` and serialization of a few message types):
each step gives values or its own error (`YAMLLoadError`, `AngleError`, `ParamValueError`,
genpy's `MessageException`, or `ValueError` where rostopic pub says a scalar is no message);
never another exception, never a hang. Any value the Parameter Server can hold dumps as
rosparam dumps it and loads back equal. Alias bombs are refused within `MEMORY_BOUND`.
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import MessageException
from rosx.msg.codec.rostime import Time
from rosx.msg.text.yamlargs import fill_message_args, load_args
from rosx.msg.text.yamlload import YAMLLoadError
from rosx.msg.text.yamlparams import (
    AngleError,
    ParamValueError,
    check_value,
    dump_value,
    load_documents,
    load_value,
)
from tests.support.fuzz import MEMORY_BOUND, fuzz_settings, no_hang, peak_allocation

pytestmark = pytest.mark.fuzz

_SCALARS = st.one_of(
    st.sampled_from(
        [
            *["1", "-0", "0x1F", "010", "1:30", "1.5", ".inf", "-.nan", "1e5", "1.0e+5", "yes"],
            *["on", "~", "null", "2001-12-14", "2001-12-14t21:59:43.10-05:00", "'q'", '"d\\x41"'],
            *["''", "deg(90)", "rad(pi/2)", "deg(x)", "rad(2**9999)", "rad(", "!!binary aGk="],
            *["now", "auto", "!degrees 45", "!radians pi", "!!str 1", "!!int x", "!!bool 2"],
            *[
                "!!python/name:os.system",
                "2001-13-45",
                "!!float y",
                "!!binary ab!",
                "!!timestamp 1",
            ],
        ]
    ),
    st.text(alphabet="abcxyz019 .-+_:'\"#!&*%@`|>?,", max_size=8),
)
_NAMES = st.sampled_from(["a", "b", "x", "linear", "data", "header", "stamp", "&a a", "*a", "? k"])


@st.composite
def _node(draw: st.DrawFn, depth: int = 0) -> str:
    kind = draw(st.sampled_from(["scalar", "scalar", "flow_list", "flow_map", "alias", "anchor"]))
    if depth >= 3 or kind == "scalar":
        return draw(_SCALARS)
    if kind == "alias":
        return "*" + draw(st.sampled_from(["a", "b", "missing"]))
    if kind == "anchor":
        return f"&{draw(st.sampled_from(['a', 'b']))} {draw(_node(depth + 1))}"
    items = draw(st.lists(_node(depth + 1), max_size=4))
    if kind == "flow_list":
        return "[" + ", ".join(items) + draw(st.sampled_from(["]", "", "]]"]))
    keys = draw(st.lists(_NAMES, min_size=len(items), max_size=len(items)))
    pairs = [f"{key}: {item}" for key, item in zip(keys, items, strict=True)]
    return "{" + ", ".join(pairs) + draw(st.sampled_from(["}", "", "}}"]))


@st.composite
def _document(draw: st.DrawFn) -> str:
    lines = []
    for _ in range(draw(st.integers(0, 6))):
        indent = " " * draw(st.sampled_from([0, 0, 2, 4, 1]))
        kind = draw(st.sampled_from(["pair", "pair", "item", "separator", "comment", "block"]))
        if kind == "pair":
            lines.append(f"{indent}{draw(_NAMES)}: {draw(_node())}")
        elif kind == "item":
            lines.append(f"{indent}- {draw(_node())}")
        elif kind == "separator":
            lines.append(draw(st.sampled_from(["---", "...", "%YAML 1.1", "%TAG ! !x"])))
        elif kind == "comment":
            lines.append(f"{indent}# {draw(st.text(max_size=10))}")
        else:
            lines.append(f"{indent}{draw(_NAMES)}: {draw(st.sampled_from(['|', '>', '|-']))}")
    return "\n".join(lines)


yaml_texts = st.one_of(_document(), _node(), st.text(max_size=60))


@fuzz_settings(200)
@given(text=yaml_texts)
def test_rosparam_reads_values_or_refuses(text: str) -> None:
    try:
        with no_hang():
            documents = load_documents(text)
    except (YAMLLoadError, AngleError) as error:
        assert str(error)
        return
    for value in documents:
        try:
            check_value(value, "/fuzz")
        except ParamValueError as error:
            assert str(error)
            continue
        back = load_value(dump_value(value))
        assert _same(back, value)


_TYPES = [
    "geometry_msgs/Twist",
    "std_msgs/String",
    "geometry_msgs/PoseStamped",
    "std_msgs/Float64MultiArray",
    "sensor_msgs/LaserScan",
    "std_msgs/Time",
]
_CLOCK = Time(1, 2)


@fuzz_settings(200)
@given(type_name=st.sampled_from(_TYPES), words=st.lists(yaml_texts, max_size=3))
def test_rostopic_pub_fills_messages_or_refuses(type_name: str, words: list[str]) -> None:
    msg = get_message_class(type_name)()
    try:
        with no_hang():
            fill_message_args(msg, load_args(words), clock=lambda: _CLOCK)
            msg.serialize(io.BytesIO())
    except (MessageException, ValueError) as error:  # YAMLLoadError is a ValueError
        assert str(error)


# -- what the Parameter Server holds dumps and loads back -------------------------------------

_PARAM_SCALARS = st.one_of(
    st.integers(-(2**31), 2**31 - 1),
    st.floats(allow_nan=True),
    st.booleans(),
    st.text(max_size=12),
    st.binary(max_size=12),
    st.sampled_from(["deg(90)", "rad(pi)", "yes", "~", "1:30", "010", "", " x ", "a: b"]),
)


def _containers(inner: st.SearchStrategy[Any]) -> st.SearchStrategy[Any]:
    return st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=6), inner, max_size=4)
    )


param_values = st.recursive(_PARAM_SCALARS, _containers, max_leaves=12)


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a):
        return math.isnan(b)
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    return type(a) is type(b) and a == b


@fuzz_settings(200)
@given(value=param_values)
def test_parameters_dump_and_load_back(value: Any) -> None:
    check_value(value, "/p")
    assert _same(load_value(dump_value(value)), value)


# -- bombs ------------------------------------------------------------------------------------

_LAUGHS = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]\n" for i in range(8)
)
BOMBS = {
    "billion laughs": _LAUGHS,
    "laughs in one flow": "[" + _LAUGHS.replace("\n", ", ").replace(": &", ": &") + "]",
    "an alias inside its anchor": "&a [*a, *a]",
    "nested too deeply": "[" * 5000 + "]" * 5000,
    "nested too deeply in blocks": "- " * 5000 + "x",
}


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_yaml_bombs_are_refused_without_allocating(name: str) -> None:
    text = BOMBS[name]
    for read in (load_documents, lambda t: load_args([t]), load_value):
        refused: list[Exception] = []

        def attempt(read: Any = read, refused: list[Exception] = refused) -> None:
            try:
                with no_hang():
                    read(text)
            except (YAMLLoadError, AngleError) as error:
                refused.append(error)

        assert peak_allocation(attempt) < MEMORY_BOUND
        assert len(refused) == 1, name


@pytest.mark.parametrize("text", ["a: !!int x", "a: 2001-13-45", "[!!float y]", "!!bool 2"])
def test_scalars_their_tag_cannot_make_are_refused(text: str) -> None:
    # PyYAML lets the constructor's ValueError escape; rosparam prints its traceback.
    for read in (load_documents, lambda t: load_args([t]), load_value):
        with pytest.raises(YAMLLoadError, match=r"^invalid value: "):
            read(text)
