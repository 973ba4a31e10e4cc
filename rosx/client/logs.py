"""rospy's logging functions: ``loginfo`` and friends, throttled, once-only and de-duplicated.

Once the node runs, a record at or above its level goes to the console as rospy writes it
(``[INFO] [1700000000.123456]: text``, stdout below WARN and stderr from WARN on;
``ROSCONSOLE_FORMAT`` is honoured) and to ``/rosout`` with the caller's file, function (as
``Class.method`` inside a method, as rospy names it) and line.
Before `init_node` there is no node to log through: as with rospy, only WARN and above are
printed, as the bare text on stderr.

``msg`` is formatted as the standard `logging` module does (``msg % args``). The throttled
variants log at most once per ``period`` seconds from each call site; the ``_once`` variants
once per call site; ``_throttle_identical`` whenever the text changes, or when ``period`` has
passed since the last record.
"""

from __future__ import annotations

import hashlib
import sys
import time
import traceback
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.node.rosout import DEBUG, ERROR, FATAL, INFO, WARN

if TYPE_CHECKING:
    from types import FrameType

_throttled: dict[tuple[str, int, int], float] = {}
_identical: dict[tuple[str, int, int], str] = {}
_once: set[tuple[str, int, int]] = set()
_NO_SELF = object()


def _call_site(depth: int) -> tuple[tuple[str, int, int], str, str, int]:
    frame = sys._getframe(depth + 1)
    code = frame.f_code
    key = (code.co_filename, frame.f_lineno, frame.f_lasti)
    return key, Path(code.co_filename).name, _function_name(frame), frame.f_lineno


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


def _emit(level: int, text: str, file: str, function: str, line: int) -> None:
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
    kwargs.pop("logger_name", None)
    key, file, function, line = _call_site(2)
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
    _emit(level, _text(msg, args, kwargs), file, function, line)


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
]
