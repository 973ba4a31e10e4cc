"""The rosbridge requests' shapes: each op's fields and their kinds, checked before an op runs.

The texts are rosbridge_suite's (``Expected a topic field but none was found.``), with JSON's
names for the kinds, and every failure is a `RequestError` whose text is the status the client
gets.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.msg.store import UnknownTypeError

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message

_STR = (str,)
_INT = (int,)
_NUM = (int, float)
_BOOL = (bool,)
_ID = (str, int, float)
#: Each op's fields: (required, name, accepted kinds). Kinds as JSON's: a bool is no number.
_FIELDS: dict[str, list[tuple[bool, str, tuple[type, ...]]]] = {
    "advertise": [
        (True, "topic", _STR),
        (True, "type", _STR),
        (False, "latch", _BOOL),
        (False, "queue_size", _INT),
    ],
    "unadvertise": [(True, "topic", _STR)],
    "publish": [(True, "topic", _STR), (True, "msg", (dict,))],
    "subscribe": [
        (True, "topic", _STR),
        (False, "type", _STR),
        (False, "throttle_rate", _NUM),
        (False, "queue_length", _INT),
        (False, "fragment_size", _INT),
        (False, "compression", _STR),
    ],
    "unsubscribe": [(True, "topic", _STR)],
    "call_service": [
        (True, "service", _STR),
        (False, "args", (list, dict)),
        (False, "fragment_size", _INT),
        (False, "compression", _STR),
    ],
    "advertise_service": [(True, "service", _STR), (True, "type", _STR)],
    "unadvertise_service": [(True, "service", _STR)],
    "service_response": [
        (True, "service", _STR),
        (True, "id", _STR),
        (False, "values", (dict, list)),
        (True, "result", _BOOL),
    ],
    "set_level": [(True, "level", _STR)],
    "fragment": [
        (True, "id", _ID),
        (True, "data", _STR),
        (True, "num", _INT),
        (True, "total", _INT),
    ],
    "auth": [(True, "mac", _STR)],
}
_KIND_NAMES = {
    str: "a string",
    int: "an integer",
    float: "a number",
    bool: "a boolean",
    dict: "an object",
    list: "an array",
}


class RequestError(Exception):
    """A request that cannot be carried out; the text is the status the client gets."""


def check_fields(op: str, request: dict[str, Any]) -> None:
    """Refuse ``request`` unless it has the fields ``op`` requires, each of its kind, in
    rosbridge's words."""
    for required, name, kinds in _FIELDS.get(op, ()):
        if name not in request:
            if required:
                raise RequestError(f"Expected a {name} field but none was found.")
            continue
        value = request[name]
        if not isinstance(value, kinds) or (bool not in kinds and isinstance(value, bool)):
            expected = " or ".join(_KIND_NAMES[k] for k in kinds)
            shown = excerpt(json.dumps(value))
            raise RequestError(f"Expected field {name} to be {expected}. Invalid value: {shown}")


def message_class(type_name: str) -> type[Message]:
    """The class of message type ``type_name``; `RequestError` with rosbridge's words if unknown."""
    try:
        return get_message_class(type_name)
    except (UnknownTypeError, ValueError):
        raise RequestError(f"Unknown message type {type_name}") from None


def kind(value: object) -> str:
    """What ``value`` is, as rosbridge's errors say it (``an array``, ``a string``…)."""
    if isinstance(value, list):
        return "an array"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int | float):
        return "a number"
    return "null" if value is None else type(value).__name__


def excerpt(text: str, limit: int = 80) -> str:
    """``text``, cut to ``limit`` characters with an ellipsis, for an error message."""
    return text if len(text) <= limit else text[:limit] + "…"


__all__ = ["RequestError", "check_fields", "excerpt", "kind", "message_class"]
