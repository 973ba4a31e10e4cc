"""rospy's log calls are records of Python's ``rosout`` logger, as in rospy: a handler a script
adds to ``logging.getLogger('rosout')`` sees each one, and the console and ``/rosout`` are two
handlers on that logger."""

from __future__ import annotations

import logging
import re
from collections.abc import Iterator
from types import ModuleType

import pytest

from rosx.client.logs import RosoutHandler
from rosx.client.roslogging import RosStreamHandler
from rosx.msg.codec.classes import get_service_class
from tests.support.procs import wait_for

GetLoggers = get_service_class("roscpp/GetLoggers")
SetLoggerLevel = get_service_class("roscpp/SetLoggerLevel")

LINE = re.compile(r"^\[(INFO|WARN|ERROR|DEBUG|FATAL)\] \[\d+\.\d{6}\]: (.*)$")


class Records(logging.Handler):
    """Keeps every record it is given."""

    def __init__(self) -> None:
        super().__init__()
        self.records: list[logging.LogRecord] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.records.append(record)

    def seen(self) -> list[tuple[str, int, str]]:
        return [(r.name, r.levelno, r.getMessage()) for r in self.records]


@pytest.fixture(autouse=True)
def rosout_level() -> Iterator[None]:
    """The ``rosout`` logger's level as it was before the test (a test may set it)."""
    logger = logging.getLogger("rosout")
    saved = logger.level
    yield
    logger.setLevel(saved)


@pytest.fixture
def handler() -> Iterator[Records]:
    """A handler on the ``rosout`` logger, as a script adds one; removed after the test."""
    logger = logging.getLogger("rosout")
    records = Records()
    logger.addHandler(records)
    yield records
    logger.removeHandler(records)


def lines(text: str) -> list[tuple[str, str]]:
    """The (severity, message) of each console line."""
    found: list[tuple[str, str]] = []
    for line in text.splitlines():
        match = LINE.match(line)
        found.append((match.group(1), match.group(2)) if match else ("?", line))
    return found


def test_a_handler_sees_every_call_at_or_above_the_level(
    rospy: ModuleType, handler: Records, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("recorded", disable_signals=True)
    rospy.loginfo("hello %s", "world")
    rospy.logdebug("not at INFO")
    rospy.logwarn("careful")
    rospy.logerr("broken: %d", 3)
    rospy.logfatal("gone")
    assert handler.seen() == [
        ("rosout", logging.INFO, "hello world"),
        ("rosout", logging.WARNING, "careful"),
        ("rosout", logging.ERROR, "broken: 3"),
        ("rosout", logging.CRITICAL, "gone"),
    ]
    first = handler.records[0]
    assert (first.filename, first.funcName) == (
        "test_rospy_logging_handlers.py",
        "test_a_handler_sees_every_call_at_or_above_the_level",
    )
    out, err = capsys.readouterr()
    assert lines(out) == [("INFO", "hello world")]
    assert lines(err) == [("WARN", "careful"), ("ERROR", "broken: 3"), ("FATAL", "gone")]


def test_logger_name_logs_with_a_child_of_rosout(
    rospy: ModuleType, handler: Records, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("named", disable_signals=True)
    rospy.loginfo("from a part %d", 1, logger_name="part")
    rospy.logwarn("plain")
    assert handler.seen() == [
        ("rosout.part", logging.INFO, "from a part 1"),
        ("rosout", logging.WARNING, "plain"),
    ]
    out, err = capsys.readouterr()
    assert (lines(out), lines(err)) == ([("INFO", "from a part 1")], [("WARN", "plain")])


def test_a_throttled_call_reaches_the_handler_once_per_period(
    rospy: ModuleType, handler: Records
) -> None:
    rospy.init_node("throttled", disable_signals=True)
    period = 0.3
    calls = 0

    def two_records() -> bool:
        nonlocal calls
        calls += 1
        rospy.loginfo_throttle(period, "tick")
        rospy.logwarn_once("once")
        return sum(r.getMessage() == "tick" for r in handler.records) == 2

    wait_for(two_records, what="a second period")
    ticks = [r for r in handler.records if r.getMessage() == "tick"]
    assert calls > 2
    assert ticks[1].created - ticks[0].created > period * 0.9
    assert [r.getMessage() for r in handler.records if r.getMessage() == "once"] == ["once"]


def test_the_nodes_level_governs_the_logger(
    rospy: ModuleType, handler: Records, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("levelled", disable_signals=True)
    set_level = rospy.ServiceProxy("/levelled/set_logger_level", SetLoggerLevel)
    get_loggers = rospy.ServiceProxy("/levelled/get_loggers", GetLoggers)
    rospy.logdebug("hidden")
    set_level(logger="rosout", level="debug")
    rospy.logdebug("shown")
    levels = {logger.name: logger.level for logger in get_loggers().loggers}
    assert levels["rosout"] == "DEBUG"
    logging.getLogger("rosout").setLevel(logging.ERROR)  # as a script may set it
    rospy.logwarn("dropped")
    levels = {logger.name: logger.level for logger in get_loggers().loggers}
    assert levels["rosout"] == "ERROR"
    assert handler.seen() == [("rosout", logging.DEBUG, "shown")]
    out, err = capsys.readouterr()
    assert (lines(out), err) == ([("DEBUG", "shown")], "")


def test_the_console_and_rosout_are_the_loggers_handlers(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("handled", disable_signals=True)
    logger = logging.getLogger("rosout")
    console, rosout = logger.handlers[:2]
    assert isinstance(console, RosStreamHandler)
    assert isinstance(rosout, RosoutHandler)
    logger.removeHandler(console)
    try:
        rospy.loginfo("nowhere to print")
    finally:
        logger.handlers.insert(0, console)
    rospy.loginfo("printed")
    assert lines(capsys.readouterr().out) == [("INFO", "printed")]


def test_a_handler_that_logs_does_not_recurse(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    class Echo(Records):
        def emit(self, record: logging.LogRecord) -> None:
            super().emit(record)
            rospy.loginfo("echo: %s", record.getMessage())

    rospy.init_node("echoing", disable_signals=True)
    logger = logging.getLogger("rosout")
    echo = Echo()
    logger.addHandler(echo)
    try:
        rospy.loginfo("said")
    finally:
        logger.removeHandler(echo)
    assert echo.seen() == [("rosout", logging.INFO, "said")]
    assert lines(capsys.readouterr().out) == [("INFO", "said"), ("INFO", "echo: said")]


def test_before_init_node_a_handler_takes_the_warnings_from_stderr(
    rospy: ModuleType, handler: Records, capsys: pytest.CaptureFixture[str]
) -> None:
    logging.getLogger("rosout").setLevel(logging.WARNING)  # Python's default, before the node
    rospy.loginfo("quiet")
    rospy.logwarn("taken")
    assert handler.seen() == [("rosout", logging.WARNING, "taken")]
    assert capsys.readouterr() == ("", "")
