"""rospy's logging functions: ``loginfo`` and friends, throttled, once-only and de-duplicated.

As in rospy, every call is a record of Python's `logging`, logged with the ``rosout`` logger
(``rosout.<name>`` given ``logger_name=name``) at DEBUG, INFO, WARNING, ERROR or CRITICAL, its
message ``msg % args``, its place the caller's file, line and function (``Class.method``
inside a method, as rospy names it). Two handlers on ``rosout`` carry the records:

* `ConsoleHandler` prints them as rospy does (``[INFO] [1700000000.123456]: text``, stdout
  below WARN and stderr from WARN on; ``ROSCONSOLE_FORMAT`` is honoured). Before `init_node`
  there is no node to log through: as with rospy, only WARN and above are printed, as the bare
  text on stderr, and only when no handler of the script's on ``rosout`` takes the record.
* `RosoutHandler` writes them to the node's log file (``__log:=``) and publishes them on
  ``/rosout``.

A handler a script adds to ``logging.getLogger('rosout')`` sees the same records; removing one
of the two stops that output. The ``rosout`` logger's level is the node's (``init_node``'s
``log_level``, ``~set_logger_level``): `LoggerLevels` keeps the node's ``rosout`` levels in
Python's loggers. A log call made while a handler runs on the same thread (a handler that
logs) goes to the console and ``/rosout`` directly, not through the handlers again.

The throttled variants log at most once per ``period`` seconds from each call site; the
``_once`` variants once per call site; ``_throttle_identical`` whenever the text changes, or
when ``period`` has passed since the last record.
"""

from __future__ import annotations

import hashlib
import logging
import sys
import threading
import time
import traceback
from collections.abc import Iterator, Mapping, MutableMapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.client.roslogging import RosStreamHandler, ros_level
from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, ROSOUT_LOGGER, WARN

if TYPE_CHECKING:
    from types import FrameType

_throttled: dict[tuple[str, int, int], float] = {}
_identical: dict[tuple[str, int, int], str] = {}
_once: set[tuple[str, int, int]] = set()
_NO_SELF = object()
_handling = threading.local()

#: The `logging` level of each ROS level, as rospy maps them.
PYTHON_LEVELS = {
    DEBUG: logging.DEBUG,
    INFO: logging.INFO,
    WARN: logging.WARNING,
    ERROR: logging.ERROR,
    FATAL: logging.CRITICAL,
}


_FORMATTER = logging.Formatter()


def record_text(record: logging.LogRecord) -> str:
    """A record's text as rospy prints and publishes it: the message, then any traceback."""
    text = record.getMessage()
    if record.exc_info:
        text = text + "\n" + _FORMATTER.formatException(record.exc_info)
    return text


class ConsoleHandler(RosStreamHandler):
    """Prints ``rosout`` records on the node's console (bare WARN and worse before the node),
    a `RosStreamHandler` as rospy's is."""

    def emit(self, record: logging.LogRecord) -> None:
        """Show ``record`` on the node's console through its log sink; before `init_node`, only
        WARN and worse reach stderr, as rospy prints them."""
        level = ros_level(record.levelno)
        node = state.CLIENT.node
        if node is None:
            if level >= WARN and not _handled_elsewhere(record):
                sys.stderr.write(record_text(record) + "\n")
                sys.stderr.flush()
            return
        node.log_sink.show(
            level,
            record_text(record),
            logger=record.name,
            file=record.filename,
            function=record.funcName,
            line=record.lineno,
        )


class RosoutHandler(logging.Handler):
    """Writes ``rosout`` records to the node's log file and publishes them on ``/rosout``."""

    def emit(self, record: logging.LogRecord) -> None:
        """Publish ``record`` on ``/rosout`` through the node's log sink; dropped before
        `init_node`."""
        node = state.CLIENT.node
        if node is None:
            return
        node.log_sink.send(
            ros_level(record.levelno),
            record_text(record),
            logger=record.name,
            file=record.filename,
            function=record.funcName,
            line=record.lineno,
        )


def _handled_elsewhere(record: logging.LogRecord) -> bool:
    """Whether a script's own handler on ``rosout`` (or the record's child of it) takes the
    record: before the node, rospy prints the bare text only when no handler does."""
    logger: logging.Logger | None = logging.getLogger(record.name)
    while logger is not None and logger is not logging.root:
        if any(not isinstance(h, (ConsoleHandler, RosoutHandler)) for h in logger.handlers):
            return True
        logger = logger.parent if logger.propagate else None
    return False


def _install_handlers() -> None:
    """Give the ``rosout`` logger its console and ``/rosout`` handlers (once per process)."""
    logger = logging.getLogger(ROSOUT_LOGGER)
    if not any(isinstance(handler, ConsoleHandler) for handler in logger.handlers):
        logger.addHandler(ConsoleHandler())
    if not any(isinstance(handler, RosoutHandler) for handler in logger.handlers):
        logger.addHandler(RosoutHandler())


_install_handlers()


class LoggerLevels(MutableMapping[str, int]):
    """A node's logger levels (`rosx.node.rosout.NodeLog.levels`) where ``rosout`` and its
    children are Python's loggers of those names: setting one sets the `logging` level,
    reading one reads the logger's effective level. Other names are kept here."""

    def __init__(self, levels: Mapping[str, int]) -> None:
        self._levels: dict[str, int] = {}
        for name, level in levels.items():
            self[name] = level

    @staticmethod
    def _in_logging(name: str) -> bool:
        return name == ROSOUT_LOGGER or name.startswith(ROSOUT_LOGGER + ".")

    def __getitem__(self, name: str) -> int:
        level = self._levels[name]
        if self._in_logging(name):
            return ros_level(logging.getLogger(name).getEffectiveLevel())
        return level

    def __setitem__(self, name: str, level: int) -> None:
        self._levels[name] = level
        if self._in_logging(name):
            logging.getLogger(name).setLevel(PYTHON_LEVELS.get(level, logging.INFO))

    def __delitem__(self, name: str) -> None:
        del self._levels[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._levels)

    def __len__(self) -> int:
        return len(self._levels)


def _call_site(depth: int) -> tuple[tuple[str, int, int], str, str, int]:
    frame = sys._getframe(depth + 1)
    code = frame.f_code
    key = (code.co_filename, frame.f_lineno, frame.f_lasti)
    return key, code.co_filename, _function_name(frame), frame.f_lineno


def _function_name(frame: FrameType) -> str:
    """``Class.method`` when the caller has a ``self``, else the function's name, as rospy."""
    owner = frame.f_locals.get("self", _NO_SELF)
    name = frame.f_code.co_name
    return name if owner is _NO_SELF else f"{type(owner).__name__}.{name}"


def _text(msg: object, args: tuple[Any, ...], kwargs: dict[str, Any]) -> str:
    text = str(msg)
    if args:
        text = text % args
    if kwargs.get("exc_info"):
        text = text + "\n" + traceback.format_exc().rstrip("\n")
    return text


def _exc_info(value: object) -> Any:
    """``exc_info=`` as `logging` takes it: an exception, a triple, or true for the current."""
    if not value:
        return None
    if isinstance(value, BaseException):
        return (type(value), value, value.__traceback__)
    if isinstance(value, tuple):
        return value
    return sys.exc_info()


def _emit(
    level: int,
    msg: object,
    args: tuple[Any, ...],
    kwargs: dict[str, Any],
    name: str,
    place: tuple[str, str, int],
) -> None:
    path, function, line = place
    logger = logging.getLogger(name)
    levelno = PYTHON_LEVELS[level]
    if not logger.isEnabledFor(levelno):
        return
    if getattr(_handling, "active", False):
        _emit_directly(level, _text(msg, args, kwargs), Path(path).name, function, line)
        return
    record = logger.makeRecord(
        logger.name,
        levelno,
        path,
        line,
        msg,
        args,
        _exc_info(kwargs.get("exc_info")),
        func=function,
        extra=kwargs.get("extra"),
    )
    _handling.active = True
    try:
        logger.handle(record)
    finally:
        _handling.active = False


def _emit_directly(level: int, text: str, file: str, function: str, line: int) -> None:
    """A record logged from inside a handler: to the console and /rosout, not the handlers."""
    node = state.CLIENT.node
    if node is not None:
        node.log(level, text, file=file, function=function, line=line)
    elif level >= WARN:
        sys.stderr.write(text + "\n")
        sys.stderr.flush()


def _log(
    level: int,
    msg: object,
    args: tuple[Any, ...],
    kwargs: dict[str, Any],
    *,
    period: float | None = None,
    identical: bool = False,
    once: bool = False,
) -> None:
    child = kwargs.pop("logger_name", None)
    name = f"{ROSOUT_LOGGER}.{child}" if child else ROSOUT_LOGGER
    key, path, function, line = _call_site(2)
    if once:
        if key in _once:
            return
        _once.add(key)
    elif identical:
        text = _text(msg, args, kwargs)
        digest = hashlib.md5(text.encode(), usedforsecurity=False).hexdigest()
        elapsed = period is not None and _period_passed(key, period)
        changed = _identical.get(key) != digest
        _identical[key] = digest
        if not changed and not elapsed:
            return
    elif period and not _period_passed(key, period):
        return
    _emit(level, msg, args, kwargs, name, (path, function, line))


def _period_passed(key: tuple[str, int, int], period: float) -> bool:
    now = time.time()
    last = _throttled.get(key)
    if last is None or now - last > period or last > now:
        _throttled[key] = now
        return True
    return False


def logdebug(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at DEBUG (shown only when the node's level is DEBUG)."""
    _log(DEBUG, msg, args, kwargs)


def loginfo(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at INFO."""
    _log(INFO, msg, args, kwargs)


def logwarn(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at WARN."""
    _log(WARN, msg, args, kwargs)


def logerr(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at ERROR."""
    _log(ERROR, msg, args, kwargs)


def logfatal(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at FATAL."""
    _log(FATAL, msg, args, kwargs)


logout = loginfo
logerror = logerr


def logdebug_throttle(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at DEBUG, at most once every ``period`` seconds from this call site."""
    _log(DEBUG, msg, args, kwargs, period=period)


def loginfo_throttle(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at INFO, at most once every ``period`` seconds from this call site."""
    _log(INFO, msg, args, kwargs, period=period)


def logwarn_throttle(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at WARN, at most once every ``period`` seconds from this call site."""
    _log(WARN, msg, args, kwargs, period=period)


def logerr_throttle(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at ERROR, at most once every ``period`` seconds from this call site."""
    _log(ERROR, msg, args, kwargs, period=period)


def logfatal_throttle(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at FATAL, at most once every ``period`` seconds from this call site."""
    _log(FATAL, msg, args, kwargs, period=period)


def logdebug_throttle_identical(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at DEBUG when the text changes, or ``period`` seconds after the last record."""
    _log(DEBUG, msg, args, kwargs, period=period, identical=True)


def loginfo_throttle_identical(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at INFO when the text changes, or ``period`` seconds after the last record."""
    _log(INFO, msg, args, kwargs, period=period, identical=True)


def logwarn_throttle_identical(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at WARN when the text changes, or ``period`` seconds after the last record."""
    _log(WARN, msg, args, kwargs, period=period, identical=True)


def logerr_throttle_identical(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at ERROR when the text changes, or ``period`` seconds after the last record."""
    _log(ERROR, msg, args, kwargs, period=period, identical=True)


def logfatal_throttle_identical(period: float, msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at FATAL when the text changes, or ``period`` seconds after the last record."""
    _log(FATAL, msg, args, kwargs, period=period, identical=True)


def logdebug_once(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at DEBUG the first time this call site runs."""
    _log(DEBUG, msg, args, kwargs, once=True)


def loginfo_once(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at INFO the first time this call site runs."""
    _log(INFO, msg, args, kwargs, once=True)


def logwarn_once(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at WARN the first time this call site runs."""
    _log(WARN, msg, args, kwargs, once=True)


def logerr_once(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at ERROR the first time this call site runs."""
    _log(ERROR, msg, args, kwargs, once=True)


def logfatal_once(msg: object, *args: Any, **kwargs: Any) -> None:
    """Log at FATAL the first time this call site runs."""
    _log(FATAL, msg, args, kwargs, once=True)


__all__ = [
    "PYTHON_LEVELS",
    "ConsoleHandler",
    "LoggerLevels",
    "RosoutHandler",
    "logdebug",
    "logdebug_once",
    "logdebug_throttle",
    "logdebug_throttle_identical",
    "logerr",
    "logerr_once",
    "logerr_throttle",
    "logerr_throttle_identical",
    "logerror",
    "logfatal",
    "logfatal_once",
    "logfatal_throttle",
    "logfatal_throttle_identical",
    "loginfo",
    "loginfo_once",
    "loginfo_throttle",
    "loginfo_throttle_identical",
    "logout",
    "logwarn",
    "logwarn_once",
    "logwarn_throttle",
    "logwarn_throttle_identical",
    "record_text",
]
