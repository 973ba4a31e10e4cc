"""The plotting form of ``rostopic echo -p``: a CSV header line, then one row per message.

Rules, as rostopic prints them:

* the header is ``%time,`` followed by the leaf field paths of the first message, each rooted at
  ``field`` (``field.linear.x``); array elements are numbered without a separator
  (``field.position0``, ``field.markers0.pose.position.x``);
* a row starts with the message's time in nanoseconds: its ``header.stamp`` when it has a
  header, else the receipt time (the bag time when reading a bag), minus ``--offset``'s time;
* values: bools ``1``/``0``, numbers as ``str``, times in nanoseconds, strings raw (unquoted);
* empty arrays, and ``uint8[]``/``char[]`` (held as bytes), add no column;
* ``--noarr`` drops every field whose type holds ``[``, ``--nostr`` every field whose type holds
  ``string`` (including ``string[]``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

from rosx.msg.codec.introspect import field_types, has_header, is_message, plain
from rosx.msg.codec.rostime import Time, TVal

_FieldFilter = Callable[[str], bool]


def csv_header(value: object, *, noarr: bool = False, nostr: bool = False) -> str:
    """The header line (without newline) for a topic whose first message is ``value``."""
    columns = _columns(value, "field", _keep(noarr, nostr))
    return "%time," + (columns or "")


def csv_row(
    value: object,
    now: Time,
    *,
    bag_time: Time | None = None,
    time_offset: Time | None = None,
    noarr: bool = False,
    nostr: bool = False,
) -> str:
    """One row (without newline) for message or field value ``value``.

    The time column is ``bag_time`` when reading a bag, else the message's ``header.stamp`` when
    it has a header, else ``now`` (the current ROS time); ``time_offset`` is ``--offset``'s start.
    """
    cells = _cells(value, time_offset, _keep(noarr, nostr))
    when = bag_time
    if when is None and is_message(value) and has_header(value):
        when = value.header.stamp  # type: ignore[attr-defined]
    stamp = (when if isinstance(when, TVal) else now).to_nsec()
    if time_offset is not None:
        stamp -= time_offset.to_nsec()
    return f"{stamp},{cells or ''}"


def _keep(noarr: bool, nostr: bool) -> _FieldFilter:
    def keep(field_type: str) -> bool:
        return not ((noarr and "[" in field_type) or (nostr and "string" in field_type))

    return keep


def _fields(msg: object, keep: _FieldFilter) -> Iterator[tuple[str, Any]]:
    for name, field_type in field_types(msg):
        if keep(field_type):
            value = plain(getattr(msg, name))
            if isinstance(value, str) and "uint8[" in field_type:
                value = [ord(ch) for ch in value]
            yield name, value


def _is_number(value: object) -> bool:
    return type(value) in (bool, int, float) or isinstance(value, TVal)


def _columns(value: Any, label: str, keep: _FieldFilter) -> str | None:
    value = plain(value)
    if _is_number(value) or isinstance(value, str):
        return label
    if is_message(value):
        parts = [_columns(v, f"{label}.{name}", keep) for name, v in _fields(value, keep)]
        return ",".join(p for p in parts if p is not None) or None
    if type(value) in (list, tuple) and value:
        first = plain(value[0])
        labels = [f"{label}{index}" for index in range(len(value))]
        if _is_number(first) or isinstance(first, str):
            return ",".join(labels)
        if is_message(first):
            parts = [_columns(item, sub, keep) for item, sub in zip(value, labels, strict=True)]
            return ",".join(p for p in parts if p) or None
    return None


def _cells(value: Any, offset: Time | None, keep: _FieldFilter) -> str | None:
    value = plain(value)
    if type(value) is bool:
        return "1" if value else "0"
    if type(value) in (int, float):
        return str(value)
    if isinstance(value, TVal):
        if offset is not None and isinstance(value, Time):
            return str(value - offset)
        return str(value)
    if isinstance(value, str):
        return value
    if is_message(value):
        parts = [p for _, v in _fields(value, keep) if (p := _cells(v, offset, keep)) is not None]
        return ",".join(parts) if parts else None
    if type(value) in (list, tuple) and value:
        items = [plain(item) for item in value]
        first = items[0]
        if type(first) is bool:
            return ",".join("1" if item else "0" for item in items)
        if type(first) in (int, float) or isinstance(first, TVal):
            # Times inside arrays are printed without --offset, as rostopic does.
            return ",".join(str(item) for item in items)
        if isinstance(first, str):
            return ",".join(items)
        if is_message(first):
            parts = [p for item in items if (p := _cells(item, offset, keep)) is not None]
            return ",".join(parts) if parts else None
    return None


__all__ = ["csv_header", "csv_row"]
