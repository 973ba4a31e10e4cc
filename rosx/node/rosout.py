"""Node logging as rospy does it: ``/rosout`` messages, console lines, logger levels.

* Every record a node logs at or above its ``rosout`` logger's level is published on
  ``/rosout`` as a ``rosgraph_msgs/Log`` with rospy's fields: ``level`` (DEBUG 1, INFO 2,
  WARN 4, ERROR 8, FATAL 16), ``name`` (the node's name), ``msg``, ``file``, ``function``,
  ``line``, ``topics`` (the node's published and subscribed topics) and ``header.stamp``.
* `console_line` formats a record as rospy's console handler does: ``ROSCONSOLE_FORMAT``,
  default ``[${severity}] [${time}]: ${message}``, time as ``%f`` seconds, followed by the
  node's ROS time (``, %f``) when that is a simulator's, not the wall clock. Whether a node prints
  is its creator's choice (`NodeLog.console`); `print_console` writes as rospy does (stdout
  below WARN, stderr from WARN on, coloured on a terminal).
* The levels behind the ``~get_loggers`` and ``~set_logger_level`` services
  (``roscpp/GetLoggers``, ``roscpp/SetLoggerLevel``) live in `NodeLog.levels`.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping, MutableMapping

DEBUG = 1
INFO = 2
WARN = 4
ERROR = 8
FATAL = 16

#: Level names as ``~get_loggers`` reports them and ``~set_logger_level`` accepts them.
LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}
LEVELS_BY_NAME = {name: level for level, name in LEVEL_NAMES.items()}

_COLOURS = {DEBUG: "\033[32m", WARN: "\033[33m", ERROR: "\033[31m", FATAL: "\033[31m"}
_RESET = "\033[0m"
_DEFAULT_FORMAT = "[${severity}] [${time}]: ${message}"

#: The logger a node's own records go through (rospy's user-facing logger has this name).
ROSOUT_LOGGER = "rosout"


def console_line(
    level: int,
    message: str,
    *,
    node: str = "",
    logger: str = ROSOUT_LOGGER,
    file: str = "",
    function: str = "",
    line: int = 0,
    stamp: float | None = None,
    ros_time: float | None = None,
    environ: Mapping[str, str] | None = None,
) -> str:
    """One console line (without the newline) for a record, as rospy's handler writes it.

    ``ros_time`` is the node's simulated time, if it has one: rospy's ``${time}`` is then the
    wall clock's and the simulator's, ``1764339000.123456, 42.100000``.
    """
    env = os.environ if environ is None else environ
    text = env.get("ROSCONSOLE_FORMAT", _DEFAULT_FORMAT)
    wall = f"{time.time() if stamp is None else stamp:f}"
    simulated = "" if ros_time is None else f", {ros_time:f}"
    replacements = {
        "${severity}": LEVEL_NAMES.get(level, "INFO"),
        "${message}": message,
        "${walltime}": wall,
        "${thread}": str(threading.get_ident()),
        "${logger}": logger,
        "${file}": file,
        "${line}": str(line),
        "${function}": function,
        "${node}": node,
        "${time}": wall + simulated,
    }
    for tag, value in replacements.items():
        if tag in text:
            text = text.replace(tag, value)
    for tag in ("${walltime:", "${time:"):
        while tag in text:
            start = text.index(tag) + len(tag)
            end = text.index("}", start)
            pattern = text[start:end]
            shown = time.strftime(pattern) + (simulated if tag == "${time:" else "")
            text = text.replace(tag + pattern + "}", shown)
    return text


def print_console(
    level: int, line: str, *, stdout: TextIO | None = None, stderr: TextIO | None = None
) -> None:
    """Write ``line`` where rospy would: stdout below WARN, else stderr, coloured on a TTY."""
    stream = (stdout or sys.stdout) if level < WARN else (stderr or sys.stderr)
    colour = _COLOURS.get(level)
    if colour and getattr(stream, "isatty", lambda: False)():
        line = f"{colour}{line}{_RESET}"
    stream.write(line + "\n")
    stream.flush()


class NodeLog:
    """A node's logger levels and the sinks of its records (``/rosout`` and the console).

    ``publish`` sends one ``rosgraph_msgs/Log`` (built by the node); ``console`` receives the
    level and the formatted line, or is ``None`` for a quiet node. `log` filters a record by the
    ``rosout`` level and hands it to both; `show` and `send` are the two halves, for a caller
    that has filtered it already (say, a `logging` handler).
    """

    def __init__(
        self,
        name: str,
        *,
        level: int = INFO,
        publish: Callable[[int, str, str, str, int], None] | None = None,
        console: Callable[[int, str], None] | None = None,
        environ: Mapping[str, str] | None = None,
    ) -> None:
        self.name = name
        #: Level of each logger by name; may be replaced by another mapping (one kept in
        #: Python's `logging`, say) as long as it holds ``rosout``.
        self.levels: MutableMapping[str, int] = {ROSOUT_LOGGER: level, "rospy": INFO, "rosx": INFO}
        self.publish = publish
        self.console = console
        #: Receives each emitted record's logger name, level and text (a log file), if set.
        self.record: Callable[[str, int, str], None] | None = None
        #: The node's ROS time in seconds when it follows a simulator (console lines show it
        #: after the wall clock's, as rospy's do); None on the wall clock.
        self.ros_time: Callable[[], float] | None = None
        self._environ = environ
        self._busy = threading.local()

    @property
    def level(self) -> int:
        """The level below which the node's own records are dropped."""
        return self.levels[ROSOUT_LOGGER]

    def enabled(self, level: int) -> bool:
        """Whether a record at ``level`` would be emitted."""
        return level >= self.levels[ROSOUT_LOGGER]

    def log(
        self, level: int, message: str, *, file: str = "", function: str = "", line: int = 0
    ) -> None:
        """Emit one record to the console and ``/rosout`` if its level is enabled."""
        if level < self.levels[ROSOUT_LOGGER]:
            return
        self.show(level, message, file=file, function=function, line=line)
        self.send(level, message, file=file, function=function, line=line)

    def show(
        self,
        level: int,
        message: str,
        *,
        logger: str = ROSOUT_LOGGER,
        file: str = "",
        function: str = "",
        line: int = 0,
    ) -> None:
        """Print one record on the console (if the node has one), whatever its level."""
        if self.console is not None:
            self.console(
                level,
                console_line(
                    level,
                    message,
                    node=self.name,
                    logger=logger,
                    file=file,
                    function=function,
                    line=line,
                    ros_time=None if self.ros_time is None else self.ros_time(),
                    environ=self._environ,
                ),
            )

    def send(
        self,
        level: int,
        message: str,
        *,
        logger: str = ROSOUT_LOGGER,
        file: str = "",
        function: str = "",
        line: int = 0,
    ) -> None:
        """Write one record to the log file and publish it on ``/rosout``, whatever its level."""
        if self.record is not None:
            self.record(logger, level, message)
        # A record logged while publishing one (say, about a failed connection) is not sent
        # again to /rosout: that could recurse without end.
        if self.publish is not None and not getattr(self._busy, "active", False):
            self._busy.active = True
            try:
                self.publish(level, message, file, function, line)
            finally:
                self._busy.active = False

    def get_loggers(self) -> list[tuple[str, str]]:
        """``(name, LEVEL)`` of every logger, for ``~get_loggers``."""
        return [(name, LEVEL_NAMES[level]) for name, level in sorted(self.levels.items())]

    def set_logger_level(self, logger: str, level_name: str) -> bool:
        """Set one logger's level (``~set_logger_level``); False for an unknown level name."""
        level = LEVELS_BY_NAME.get(level_name.upper())
        if level is None:
            return False
        self.levels[logger] = level
        return True
