"""Console lines as roscpp's rosconsole prints them, and a node's log that goes there.

rosconsole's default format is ``[${severity}] [${time}]: ${message}``, with the severities
``DEBUG``, `` INFO``, `` WARN``, ``ERROR`` and ``FATAL`` (padded to five characters) and the time
as ``secs.nsecs`` (nine digits; a node on simulated time that has had its first ``/clock`` shows
``wall, simulated``). ``ROSCONSOLE_FORMAT`` may change it (the tokens ``severity``,
``message``, ``time``, ``walltime``, ``thread``, ``logger``, ``file``, ``line``, ``function``,
``node``). DEBUG and INFO go to stdout, WARN and above to stderr.

rosconsole colours every line (INFO plain, WARN yellow, ERROR and FATAL red, DEBUG green); here
colour is used only when the stream is a terminal, so piped or captured output is plain text.
"""

from __future__ import annotations

import logging
import re
import threading
import time
from typing import TYPE_CHECKING, TextIO

from rosx.node import DEBUG, ERROR, FATAL, INFO, WARN
from rosx.node.rosout import ROSOUT_LOGGER
from rosx.terminal import is_terminal

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.node import Node

DEFAULT_FORMAT = "[${severity}] [${time}]: ${message}"
SEVERITIES = {DEBUG: "DEBUG", INFO: " INFO", WARN: " WARN", ERROR: "ERROR", FATAL: "FATAL"}
_COLOURS = {DEBUG: "\033[32m", INFO: "\033[0m", WARN: "\033[33m", ERROR: "\033[31m"}
_NORMAL = "\033[0m"
_TOKEN = re.compile(r"\$\{(\w+)\}")


def ros_time_text(nanos: int) -> str:
    """A wall-clock time as roscpp prints it: ``secs.nsecs`` with nine digits of nsecs."""
    return f"{nanos // 1_000_000_000}.{nanos % 1_000_000_000:09d}"


def console_line(
    level: int,
    message: str,
    *,
    node: str = "",
    logger: str = "ros",
    fmt: str = DEFAULT_FORMAT,
    nanos: int | None = None,
    sim_nanos: int | None = None,
) -> str:
    """One rosconsole line (no newline, no colour) for a record; with ``sim_nanos`` (a node on
    simulated time, once it has a ``/clock``) ``${time}`` is the wall clock, then that time,
    as rosconsole's time token writes them."""
    stamp = ros_time_text(time.time_ns() if nanos is None else nanos)
    values = {
        "severity": SEVERITIES.get(level, " INFO"),
        "message": message,
        "time": stamp if sim_nanos is None else f"{stamp}, {ros_time_text(sim_nanos)}",
        "walltime": stamp,
        "thread": f"0x{threading.get_ident():x}",
        "logger": logger,
        "file": "",
        "line": "0",
        "function": "",
        "node": node,
    }
    # One pass over the format, so text inside the message is never taken for a token.
    return _TOKEN.sub(lambda m: values.get(m.group(1), m.group(0)), fmt)


class Console:
    """Where a node's lines are printed: stdout below WARN, stderr from WARN on."""

    def __init__(self, stdout: TextIO, stderr: TextIO, environ: Mapping[str, str]) -> None:
        self.stdout = stdout
        self.stderr = stderr
        self.fmt = environ.get("ROSCONSOLE_FORMAT", DEFAULT_FORMAT)
        self._lock = threading.Lock()

    def print(
        self, level: int, message: str, *, node: str = "", sim_nanos: int | None = None
    ) -> None:
        """Print one record (coloured only on a terminal); ``sim_nanos``: `console_line`'s."""
        line = console_line(level, message, node=node, fmt=self.fmt, sim_nanos=sim_nanos)
        stream = self.stdout if level < WARN else self.stderr
        if is_terminal(stream):
            line = f"{_COLOURS.get(level, _COLOURS[ERROR])}{line}{_NORMAL}"
        with self._lock:
            stream.write(line + "\n")
            stream.flush()


class NodeLog:
    """A roscpp node's log: each record to the console (roscpp's lines) and to ``/rosout``.

    Records go through the logger ``logger`` (``ros.<package>``, as roscpp names a package's
    default logger), listed by the node's ``~get_loggers`` at INFO; records below its level
    are dropped, so ``~set_logger_level ros.turtlesim DEBUG`` shows the DEBUG lines.
    """

    def __init__(self, node: Node, console: Console | None, logger: str = "ros.turtlesim") -> None:
        self.node = node
        self.console = console
        self.logger = logger
        node.log_sink.levels.setdefault(logger, INFO)

    def enabled(self, level: int) -> bool:
        """Whether a record at ``level`` would be emitted."""
        return level >= self.node.log_sink.levels.get(self.logger, INFO)

    def __call__(self, level: int, message: str) -> None:
        """Log ``message`` at ``level``: to the console as roscpp prints it and to ``/rosout``
        while the node runs; dropped below the logger's level."""
        if not self.enabled(level):
            return
        if self.console is not None:
            clock = self.node.clock
            sim = None if clock.is_wallclock else clock.now().to_nsec()
            self.console.print(level, message, node=self.node.name, sim_nanos=sim or None)
        publish = self.node.log_sink.publish
        if publish is not None and not self.node.is_shutdown():
            publish(level, message, "", "", 0)


class RosconsoleHandler(logging.Handler):
    """Prints the ``rosout`` records of a program written on rosx's rospy API as roscpp's lines
    (`Console`): the C++ programs of ROS 1's tutorials that rosx provides in Python."""

    def __init__(self, console: Console) -> None:
        super().__init__()
        self.console = console

    def emit(self, record: logging.LogRecord) -> None:
        """Print ``record`` as roscpp's console line, under the name of the program's rospy node."""
        from rosx.client import lifecycle  # noqa: PLC0415 - the program's rospy node
        from rosx.client.roslogging import ros_level  # noqa: PLC0415 - as lifecycle

        level = ros_level(record.levelno)
        self.console.print(level, record.getMessage(), node=lifecycle.get_name())


def use_rosconsole(console: Console) -> None:
    """Give this process's rospy logging roscpp's console lines: `RosconsoleHandler` takes the
    place of rospy's console handler on ``rosout`` (records still reach ``/rosout``)."""
    from rosx.client.logs import ConsoleHandler  # noqa: PLC0415 - rospy's logging, on demand

    logger = logging.getLogger(ROSOUT_LOGGER)
    for handler in [h for h in logger.handlers if isinstance(h, ConsoleHandler)]:
        logger.removeHandler(handler)
    if not any(isinstance(h, RosconsoleHandler) for h in logger.handlers):
        logger.addHandler(RosconsoleHandler(console))
