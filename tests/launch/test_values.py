"""``<param>`` values: roslaunch's typing rules."""

from __future__ import annotations

from typing import Any

import pytest

from rosx.launch.values import ValueConversionError, command_value, convert_value, flatten


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("42", 42),
        (" 7 ", 7),
        ("-3", -3),
        ("3.5", 3.5),
        (".5", 0.5),
        ("2.", 2.0),
        ("1_000", "1_000"),
        ("1_000.5", 1000.5),
        ("1e5", "1e5"),
        ("1.5e3", 1500.0),
        ("0x10", "0x10"),
        ("true", True),
        ("FALSE", False),
        ("yes", "yes"),
        ("inf", "inf"),
        ("1.2.3", "1.2.3"),
        ("", ""),
    ],
)
def test_auto(text: str, value: Any) -> None:
    result = convert_value(text, "auto")
    assert (type(result), result) == (type(value), value)


@pytest.mark.parametrize(
    ("text", "type_", "value"),
    [
        ("10", "str", "10"),
        ("true", "string", "true"),
        (" 12 ", "int", 12),
        ("4", "double", 4.0),
        ("1", "bool", True),
        (" FALSE ", "boolean", False),
        ("0", "BOOL", False),
        ("[1, a]", "yaml", [1, "a"]),
        ("deg(180)", "yaml", "deg(180)"),
    ],
)
def test_types(text: str, type_: str, value: Any) -> None:
    assert convert_value(text, type_) == value


@pytest.mark.parametrize(
    ("text", "type_", "message"),
    [
        ("1.5", "int", "invalid literal for int() with base 10: '1.5'"),
        ("x", "double", "could not convert string to float: 'x'"),
        ("yes", "bool", "yes is not a 'bool' type"),
        ("1", "float", "Unknown type 'float'"),
    ],
)
def test_refusals(text: str, type_: str, message: str) -> None:
    with pytest.raises(ValueConversionError) as error:
        convert_value(text, type_)
    assert str(error.value) == message


def test_command_output_is_converted() -> None:
    def run(argv: list[str]) -> tuple[int, str]:
        assert argv == ["tool", "a b", "c"]
        return 0, "2.5\n"

    assert command_value("p", "tool 'a b' c", "auto", run) == 2.5


def test_command_failures() -> None:
    with pytest.raises(ValueConversionError, match=r"returned with code \[3\]"):
        command_value("p", "x", "auto", lambda argv: (3, ""))

    def missing(argv: list[str]) -> tuple[int, str]:
        raise FileNotFoundError(argv[0])

    with pytest.raises(ValueConversionError, match=r"no such command \[\['x'\]\]"):
        command_value("p", "x", "auto", missing)


def test_flatten_unrolls_dictionaries() -> None:
    data = {"a": {"b": 1, "c": {}}, "/abs": 2, "~priv": 3, "list": [1, {"x": 1}]}
    assert list(flatten("/ns", data)) == [
        ("/ns/a/b", 1),
        ("/abs", 2),
        ("~priv", 3),
        ("/ns/list", [1, {"x": 1}]),
    ]


def test_flatten_refuses_keys_that_are_not_text() -> None:
    with pytest.raises(ValueConversionError, match="must have string keys"):
        list(flatten("/", {1: "a"}))
