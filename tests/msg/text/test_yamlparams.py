"""Parameter values as YAML: rosparam's reading rules and PyYAML's ``yaml.dump`` layout.

Golden texts pin the layout; where Debian's ROS 1 is installed, thousands of random parameter
trees are also dumped by PyYAML itself (with rosparam's resolvers and binary representer) and
compared byte for byte.
"""

from __future__ import annotations

import base64
import json
import math
import random
import string
import subprocess
from typing import Any

import pytest

from rosx.msg.text.yamldump import dump, format_float
from rosx.msg.text.yamlload import YAMLLoadError
from rosx.msg.text.yamlparams import (
    AngleError,
    ParamValueError,
    check_value,
    dump_value,
    load_documents,
    load_value,
)
from tests.support.ros1 import ROS1_PYTHON, ros1_python_imports

# -- reading ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("5", 5),
        ("-3", -3),
        ("-3.5", -3.5),
        ("1e5", "1e5"),
        ("1.0e+5", 100000.0),
        ("010", 8),
        ("0x1F", 31),
        ("1:30", 90),
        ("true", True),
        ("yes", True),
        ("y", "y"),
        ("'5'", "5"),
        ("hello world", "hello world"),
        ("!!str", ""),
        ("[1, 2.5, x, true]", [1, 2.5, "x", True]),
        ("{a: 1, b: {c: [1, 2]}}", {"a": 1, "b": {"c": [1, 2]}}),
        ("!!binary aGVsbG8=", b"hello"),
        ("'deg(90)'", "deg(90)"),
    ],
)
def test_values_read_as_rosparam_set_reads_them(text: str, value: object) -> None:
    loaded = load_value(text)
    assert loaded == value
    assert type(loaded) is type(value)


@pytest.mark.parametrize(
    ("text", "radians"),
    [
        ("deg(90)", math.pi / 2),
        ("!degrees 180", math.pi),
        ("!degrees -45.5", -45.5 * math.pi / 180),
        ("rad(2*pi)", 2 * math.pi),
        ("!radians pi/2", math.pi / 2),
        ("!radians 1.5", 1.5),
        ("!radians -(pi + 1) ** 2 // 3 % 5", (-((math.pi + 1) ** 2) // 3) % 5),
        ("rad(-pi)", -math.pi),
    ],
)
def test_angles_are_floats_in_radians(text: str, radians: float) -> None:
    assert load_value(text) == pytest.approx(radians)
    assert load_value(f"a:\n- {text}")["a"][0] == pytest.approx(radians)


@pytest.mark.parametrize(
    ("text", "error"),
    [
        ("deg(abc)", "invalid degree value: deg(abc)"),
        ("!degrees x", "invalid degree value: x"),
        ("rad(foo+)", "invalid radian expression: rad(foo+)"),
        (
            "!radians __import__('os').getpid()",
            "invalid radian expression: __import__('os').getpid()",
        ),
        ("!radians 1/0", "invalid radian expression: 1/0"),
        ("rad(pi, 1)", "invalid radian expression: rad(pi, 1)"),
        ("!radians 2**99999", "invalid radian expression: 2**99999"),
    ],
)
def test_bad_angles_are_refused_with_rosparams_text(text: str, error: str) -> None:
    with pytest.raises(AngleError) as refused:
        load_value(text)
    assert str(refused.value) == error


def test_documents_and_errors() -> None:
    assert load_documents("a: 1\n---\nb: deg(180)\n") == [{"a": 1}, {"b": math.pi}]
    assert load_documents("") == []
    with pytest.raises(YAMLLoadError, match="expected the node content"):
        load_documents("bad: [\n")


@pytest.mark.parametrize(
    ("value", "error"),
    [
        (
            None,
            "cannot set parameter [/p]: the Parameter Server cannot store null (an empty value)",
        ),
        (2**31, "cannot set parameter [/p]: 2147483648 is beyond the Parameter Server's 32-bit"),
        (
            {"x:5": None},
            "cannot set parameter [/p/x:5]: YAML needs a space after the colon, write {x: 5}",
        ),
        (
            {"a": [1, {"b": None}]},
            "cannot set parameter [/p/a/b]: the Parameter Server cannot store null",
        ),
        ({1: "a"}, "YAML dictionaries must have string keys. Invalid dictionary is:\n{1: 'a'}"),
        ({1, 2}, "cannot set parameter [/p]: the Parameter Server cannot store a set ({1, 2})"),
    ],
)
def test_values_the_server_cannot_hold_are_named(value: object, error: str) -> None:
    with pytest.raises(ParamValueError) as refused:
        check_value(value, "/p")
    assert str(refused.value).startswith(error)


def test_values_the_server_holds_pass() -> None:
    check_value({"a": [1, -(2**31), 2**31 - 1, 1.5, "s", b"\0", True, {"b": []}], "c": {}}, "/")


# -- writing ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (5, "5\n...\n"),
        (-3.5, "-3.5\n...\n"),
        (True, "true\n...\n"),
        ("hello", "hello\n...\n"),
        ("", "''\n"),
        ("5", "'5'\n"),
        ("yes", "'yes'\n"),
        ("deg(90)", "'deg(90)'\n"),
        ("Debian\n", "'Debian\n\n  '\n"),
        ("h\xe9llo", '"h\\xE9llo"\n'),
        ([], "[]\n"),
        ({}, "{}\n"),
        ([1, "x", [2, 3], {"k": 1}], "- 1\n- x\n- - 2\n  - 3\n- k: 1\n"),
        (
            {"b": {"c": [1, 2], "d": "str"}, "a": 1, "e": {}, "f": []},
            "a: 1\nb:\n  c:\n  - 1\n  - 2\n  d: str\ne: {}\nf: []\n",
        ),
        (b"hello\x00\x01\xffworld", "!!binary |-\n  aGVsbG8AAf93b3JsZA==\n"),
        ({"bin": b"hi"}, "bin: !!binary |-\n  aGk=\n"),
        ({"": 1, "a\nb": 2}, "? ''\n: 1\n? 'a\n\n  b'\n: 2\n"),
    ],
)
def test_dump_matches_pyyaml(value: object, text: str) -> None:
    assert dump_value(value) == text


def test_long_scalars_fold_at_80_columns_but_keys_do_not() -> None:
    words = " ".join(f"word{i}" for i in range(30))
    assert dump({"long": words}) == (
        "long: word0 word1 word2 word3 word4 word5 word6 word7 word8 word9 word10 word11 word12\n"
        "  word13 word14 word15 word16 word17 word18 word19 word20 word21 word22 word23 word24\n"
        "  word25 word26 word27 word28 word29\n"
    )
    key = " ".join(f"k{i}" for i in range(30))
    assert dump({key: 1}) == f"{key}: 1\n"


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (0.1, "0.1"),
        (1e-05, "1.0e-05"),
        (1e16, "1.0e+16"),
        (1e300, "1.0e+300"),
        (float("inf"), ".inf"),
        (float("-inf"), "-.inf"),
        (float("nan"), ".nan"),
        (1.0, "1.0"),
    ],
)
def test_floats_as_pyyaml_represents_them(value: float, text: str) -> None:
    assert format_float(value) == text


# -- against PyYAML itself -------------------------------------------------------------------


def ros1_yaml() -> bool:
    return ros1_python_imports("yaml", "rosparam")


ORACLE = """
import base64, json, sys, yaml, rosparam
from xmlrpc.client import Binary

def binary(dumper, data):
    # rosparam's own representer, with the base64 text it means (it hands PyYAML bytes).
    text = base64.b64encode(data.data).decode("ascii")
    return dumper.represent_scalar("tag:yaml.org,2002:binary", text, style="|")

yaml.add_representer(Binary, binary)

def revive(v):
    if isinstance(v, dict):
        if set(v) == {"__bytes__"}:
            return Binary(base64.b64decode(v["__bytes__"]))
        return {k: revive(x) for k, x in v.items()}
    if isinstance(v, list):
        return [revive(x) for x in v]
    return v

json.dump([yaml.dump(revive(c)) for c in json.load(sys.stdin)], sys.stdout)
"""

_ODD = [
    "yes", "No", "null", "~", "1.5", "010", "0x1f", "1:30", "2002-12-14", "deg(90)", "rad(pi)",
    "---", "...", "- a", "a: b", "#x", " lead", "trail ", "a\nb", "a \nb", "\nx", "x\n", "x\n\n",
    "<<", "=", "!", "it's", 'say "hi"', "tab\there", "a #b", "a: ", "?", ":",
]  # fmt: skip
_POOLS = [
    string.ascii_lowercase + " ",
    string.ascii_letters
    + string.digits
    + " :-#'\"!&*?,[]{}|>%@`.~\n\t\\\xe9\u2028\xfc\u20ac\U0001f600\x85",
    "0123456789.e+-_:",
    "yesnoNULLtrue~ ",
]


def _random_tree(rng: random.Random, depth: int = 0) -> Any:
    roll = rng.random()
    if depth < 3 and roll < 0.2:
        return {_random_text(rng): _random_tree(rng, depth + 1) for _ in range(rng.randint(0, 4))}
    if depth < 3 and roll < 0.35:
        return [_random_tree(rng, depth + 1) for _ in range(rng.randint(0, 4))]
    roll = rng.random()
    if roll < 0.4:
        return _random_text(rng)
    if roll < 0.55:
        return rng.randint(-(2**31), 2**31 - 1)
    if roll < 0.75:
        return rng.choice(
            [0.1, 1e-05, 1e16, -3.5, 1.0, 123456789.123, 1e300, rng.uniform(-1e6, 1e6)]
        )
    if roll < 0.85:
        return rng.choice([True, False])
    return bytes(rng.randrange(256) for _ in range(rng.randint(1, 70)))


def _random_text(rng: random.Random) -> str:
    if rng.random() < 0.1:
        return rng.choice(_ODD)
    pool = rng.choice(_POOLS)
    return "".join(rng.choice(pool) for _ in range(rng.choice([0, 1, 2, 3, 5, 10, 40, 90, 130])))


def _portable(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _portable(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_portable(v) for v in value]
    if isinstance(value, bytes):
        return {"__bytes__": base64.b64encode(value).decode()}
    return value


@pytest.mark.skipif(not ros1_yaml(), reason="ROS 1's rosparam and PyYAML are not installed")
def test_random_trees_dump_as_pyyaml_dumps_them() -> None:
    rng = random.Random(20240611)
    trees = [_random_tree(rng) for _ in range(2000)]
    done = subprocess.run(
        [ROS1_PYTHON, "-c", ORACLE],
        input=json.dumps([_portable(t) for t in trees]),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    wanted = json.loads(done.stdout)
    mismatches = [(t, w) for t, w in zip(trees, wanted, strict=True) if dump_value(t) != w]
    assert not mismatches[:3]
