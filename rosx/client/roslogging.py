"""The part of ``rosgraph.roslogging`` that scripts use: `RosStreamHandler`.

A `logging.Handler` that writes records to the console as rospy's console lines
(``[INFO] [1700000000.123456]: text``, ``ROSCONSOLE_FORMAT`` honoured): below WARNING to
stdout, from WARNING on to stderr, coloured on a terminal unless ``colorize`` is false.
"""

from __future__ import annotations

import logging
import sys
from typing import TextIO

from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, WARN, console_line, print_console


def ros_level(levelno: int) -> int:
    """The ROS level of a `logging` level number (CRITICAL is FATAL)."""
    if levelno >= logging.CRITICAL:
        return FATAL
    if levelno >= logging.ERROR:
        return ERROR
    if levelno >= logging.WARNING:
        return WARN
    return INFO if levelno >= logging.INFO else DEBUG


class RosStreamHandler(logging.Handler):
    """Writes records as rospy's console lines to ``stdout`` and ``stderr``."""

    def __init__(
        self, colorize: bool = True, stdout: TextIO | None = None, stderr: TextIO | None = None
    ) -> None:
        super().__init__()
        self._colorize = colorize
        self._stdout = stdout
        self._stderr = stderr

    def emit(self, record: logging.LogRecord) -> None:
        """Write ``record`` as a rospy console line: below WARN to stdout, else stderr; coloured
        as rospy colours it unless ``colorize`` is false."""
        level = ros_level(record.levelno)
        line = console_line(
            level,
            record.getMessage(),
            logger=record.name,
            file=record.pathname,
            function=record.funcName,
            line=record.lineno,
            stamp=record.created,
        )
        if self._colorize:
            print_console(level, line, stdout=self._stdout, stderr=self._stderr)
            return

        stream = (self._stdout or sys.stdout) if level < WARN else (self._stderr or sys.stderr)
        stream.write(line + "\n")
        stream.flush()


__all__ = ["RosStreamHandler", "ros_level"]
