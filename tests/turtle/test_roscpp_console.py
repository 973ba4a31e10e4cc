"""roscpp's console lines and the roscpp habits turtlesim's programs share."""

from __future__ import annotations

import io
import math
import re
from typing import Any

import pytest

from rosx.msg.codec.rostime import Time
from rosx.node import DEBUG, ERROR, INFO, WARN, Node
from rosx_turtle.console import Console, NodeLog, console_line, ros_time_text
from rosx_turtle.roscpp import NodeArgs, param_int, typed_param


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_default_line() -> None:
    line = console_line(INFO, "Clearing turtlesim.", nanos=1_700_000_000_000_000_005)
    assert line == "[ INFO] [1700000000.000000005]: Clearing turtlesim."
    assert console_line(WARN, "x", nanos=0) == "[ WARN] [0.000000000]: x"
    assert console_line(ERROR, "x", nanos=0).startswith("[ERROR] ")
    assert console_line(DEBUG, "x", nanos=0).startswith("[DEBUG] ")
    assert ros_time_text(12_000_000_001) == "12.000000001"


def test_a_node_on_simulated_time_shows_the_wall_clock_then_its_clock() -> None:
    """rosconsole's time token: ``wall, simulated`` once ROS time is simulated and valid."""
    line = console_line(INFO, "x", nanos=5, sim_nanos=84_100_000_000)
    assert line == "[ INFO] [0.000000005, 84.100000000]: x"
    out = io.StringIO()
    node = Node("/sim_logger", master_uri="http://localhost:1/")
    log = NodeLog(node, Console(out, out, {}), logger="ros.map_server")
    log(INFO, "wall")
    node.clock.use_sim_time()
    log(INFO, "no clock yet")
    node.clock.set(Time(84, 100_000_000))
    log(INFO, "simulated")
    lines = out.getvalue().splitlines()
    assert re.fullmatch(r"\[ INFO\] \[\d+\.\d{9}\]: wall", lines[0])
    assert re.fullmatch(r"\[ INFO\] \[\d+\.\d{9}\]: no clock yet", lines[1])
    assert re.fullmatch(r"\[ INFO\] \[\d+\.\d{9}, 84\.100000000\]: simulated", lines[2])


def test_format_tokens_are_read_from_the_format_only() -> None:
    line = console_line(
        INFO, "a ${node} b", node="/n", fmt="${severity}|${node}|${message}", nanos=0
    )
    assert line == " INFO|/n|a ${node} b"


def test_plain_when_piped_coloured_on_a_terminal() -> None:
    out, err = io.StringIO(), io.StringIO()
    Console(out, err, {}).print(INFO, "hello")
    Console(out, err, {}).print(WARN, "careful")
    assert re.fullmatch(r"\[ INFO\] \[\d+\.\d{9}\]: hello\n", out.getvalue())
    assert re.fullmatch(r"\[ WARN\] \[\d+\.\d{9}\]: careful\n", err.getvalue())
    tty_out, tty_err = Terminal(), Terminal()
    console = Console(tty_out, tty_err, {"ROSCONSOLE_FORMAT": "[${severity}]: ${message}"})
    console.print(INFO, "hello")
    console.print(ERROR, "bad")
    assert tty_out.getvalue() == "\033[0m[ INFO]: hello\033[0m\n"
    assert tty_err.getvalue() == "\033[31m[ERROR]: bad\033[0m\n"


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("3", 3),
        ("-7", -7),
        ("2.5", 2.5),
        ("1e3", 1000.0),
        ("true", True),
        ("False", False),
        ("abc", "abc"),
        ("99999999999", 99999999999.0),
        ("1_0", "1_0"),
    ],
)
def test_private_params_are_typed_as_roscpp_types_them(text: str, value: Any) -> None:
    typed = typed_param(text)
    assert typed == value and type(typed) is type(value)


@pytest.mark.parametrize(
    ("value", "expected"),
    [(7, 7), (7.4, 7), (7.5, 8), (-1, -1), ("12", 69), (True, 69), (math.nan, 69), (None, 69)],
)
def test_param_int_reads_as_roscpp(value: Any, expected: int) -> None:
    assert param_int(value, 69) == expected


def test_node_args() -> None:
    args = NodeArgs.parse(
        [
            "__name:=sim",
            "__ns:=/pond",
            "a:=b",
            "_background_r:=1",
            "extra",
            "__master:=http://m:1/",
        ],
        "turtlesim",
    )
    assert (args.name, args.namespace, args.master_uri) == ("sim", "/pond", "http://m:1/")
    assert dict(args.remappings) == {"a": "b"}
    assert dict(args.params) == {"background_r": 1}
    assert list(args.argv) == ["extra"]
    assert NodeArgs.parse([], "turtlesim").name == "turtlesim"
