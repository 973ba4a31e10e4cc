"""The text form of messages that ``rostopic echo`` prints (genpy's ``strify_message``).

Rules, as ROS 1 prints them:

* one ``name: value`` line per field; a nested message opens with ``name: `` (trailing space) and
  its fields follow indented by two more spaces;
* numbers print as Python's ``str`` (so float32 values show their float64 expansion, e.g.
  ``0.10000000149011612``), bools as ``True``/``False``;
* strings are double-quoted YAML scalars (``"turtle2"``, escapes, folding past 80 columns) except
  the empty string, ``''``;
* primitive arrays print on one line as a Python list (``[1.0, 2.0]``; ``uint8[]`` as numbers),
  ``[]`` when empty; string arrays as a YAML block list; arrays of messages (and of times) as
  ``- `` items, each item's fields on the following lines;
* ``time``/``duration`` print as nested ``secs:`` and ``nsecs:`` (nanoseconds right-aligned in
  nine columns);
* ``--noarr``/``--nostr`` replace array and string fields by ``<array type: T, length: N>`` and
  ``<string length: N>`` (printed as strings), through nested messages but not inside arrays of
  messages, as rostopic does.

Each echoed message is followed by a ``---`` line: see `echo_record`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, NamedTuple

from rosx.msg.codec.introspect import field_types, is_message, plain
from rosx.msg.codec.rostime import Time, TVal
from rosx.msg.text.yamlstr import quoted, string_list

#: The line rostopic prints after each message (YAML's document separator).
SEPARATOR = "---"
#: What ``rostopic echo -c`` writes before each message: clear the screen, cursor home.
CLEAR_SCREEN = "\x1b[2J\x1b[;H"


class _Options(NamedTuple):
    """rostopic echo's ``--noarr``, ``--nostr``, ``-w NUM_WIDTH`` and ``--offset`` (start time)."""

    noarr: bool
    nostr: bool
    fixed_numeric_width: int | None
    time_offset: Time | None


def format_message(
    msg: object,
    *,
    indent: str = "",
    noarr: bool = False,
    nostr: bool = False,
    fixed_numeric_width: int | None = None,
    time_offset: Time | None = None,
) -> str:
    """``msg`` as ``rostopic echo`` prints it, without the ``---`` line.

    ``fixed_numeric_width`` is ``-w``; ``time_offset`` (``--offset``) prints every `Time` as its
    difference from it. With a non-empty ``indent`` the text starts with a newline and every
    line is indented, as genpy does for nested values.
    """
    options = _Options(noarr, nostr, fixed_numeric_width, time_offset)
    return _format(_transform(msg, None, options), indent, options)


def format_value(
    value: object,
    field_type: str | None = None,
    *,
    noarr: bool = False,
    nostr: bool = False,
    fixed_numeric_width: int | None = None,
    time_offset: Time | None = None,
) -> str:
    """A message or a field's value as ``rostopic echo /topic/field`` prints it.

    ``field_type`` is the declared type of the selected field (``uint8[]``, ``string``,
    ``geometry_msgs/Point[]``…): it makes ``uint8[]`` print as numbers and lets ``--noarr``/
    ``--nostr`` replace the value itself.
    """
    options = _Options(noarr, nostr, fixed_numeric_width, time_offset)
    value = plain(value)
    if field_type is not None and field_type.startswith("uint8[") and isinstance(value, bytes):
        value = list(value)
    return _format(_transform(value, field_type, options), "", options)


def echo_record(text: str, *, clear: bool = False) -> str:
    """What rostopic writes for one echoed message: ``text``, then the ``---`` line."""
    return (CLEAR_SCREEN if clear else "") + text + "\n" + SEPARATOR + "\n"


# -- --noarr / --nostr ---------------------------------------------------------------------


class _Replaced:
    """A value shown as a summary string in place of the field's own value."""

    def __init__(self, text: str) -> None:
        self.text = text


class _Summary:
    """A message whose fields print through the --noarr/--nostr replacements."""

    def __init__(self, msg: object, values: list[object]) -> None:
        self.fields = list(field_types(msg))
        self.values = values


def _summary(value: object, field_type: str, options: _Options) -> _Replaced | None:
    if options.noarr and "[" in field_type and hasattr(value, "__len__"):
        # rostopic strips brackets from the right only, so ``float64[9]`` keeps ``[9``.
        return _Replaced(f"<array type: {field_type.rstrip('[]')}, length: {len(value)}>")
    if options.nostr and field_type == "string" and isinstance(value, str | bytes):
        return _Replaced(f"<string length: {len(value)}>")
    if options.nostr and field_type == "string[]" and hasattr(value, "__len__"):
        return _Replaced(f"<array type: string, length: {len(value)}>")
    return None


def _transform(value: object, field_type: str | None, options: _Options) -> object:
    if not (options.noarr or options.nostr):
        return value
    if not is_message(value):
        if field_type is None:
            return value
        return _summary(value, field_type, options) or value
    values: list[object] = []
    for name, ftype in field_types(value):
        field_value = getattr(value, name)
        replaced = _summary(field_value, ftype, options)
        if replaced is not None:
            values.append(replaced)
        elif is_message(field_value) and "[" not in ftype and _equals_itself(field_value):
            values.append(_transform(field_value, None, options))
        else:
            values.append(field_value)
    return _Summary(value, values)


def _equals_itself(msg: object) -> bool:
    """genpy's ``msg == msg``: false when a float field (outside arrays) is NaN.

    rostopic replaces arrays and strings inside a nested message only when the message compares
    equal to itself, so a NaN in it keeps the whole nested message as it is.
    """
    for name, ftype in field_types(msg):
        value = plain(getattr(msg, name))
        if "[" in ftype:
            continue  # arrays compare as tuples, whose elements are compared by identity first
        if isinstance(value, float) and math.isnan(value):
            return False
        if is_message(value) and not _equals_itself(value):
            return False
    return True


# -- the text ------------------------------------------------------------------------------


def _format(value: Any, indent: str, options: _Options) -> str:
    value = plain(value)
    kind = type(value)
    width = options.fixed_numeric_width
    if width is not None and kind in (int, float):
        if kind is float:
            text = f"{value:.{width}f}"
            return text[: max(text.find("."), width)]
        return f"{value:{width}d}"
    if kind in (int, float, bool):
        return str(value)
    if isinstance(value, str):
        return quoted(value) if value else "''"
    if isinstance(value, _Replaced):
        return quoted(value.text)
    if isinstance(value, TVal):
        return _format_time(value, indent, options)
    if kind in (list, tuple):
        return _format_sequence(value, indent, options)
    if isinstance(value, _Summary):
        return _format_fields(value.fields, value.values, indent, options)
    if is_message(value):
        fields = list(field_types(value))
        return _format_fields(fields, [getattr(value, n) for n, _ in fields], indent, options)
    return str(value)


def _format_time(value: TVal, indent: str, options: _Options) -> str:
    if options.time_offset is not None and isinstance(value, Time):
        value = value - options.time_offset
    width = options.fixed_numeric_width
    if width is not None:
        return f"\n{indent}secs: {value.secs:{width}d}\n{indent}nsecs: {value.nsecs:{width}d}"
    return f"\n{indent}secs: {value.secs}\n{indent}nsecs: {value.nsecs:9d}"


def _format_sequence(items: Sequence[Any], indent: str, options: _Options) -> str:
    if not items:
        return "[]"
    first = plain(items[0])
    # As genpy, the first element decides how the whole array prints.
    if options.fixed_numeric_width is not None and type(first) in (int, float):
        return "[" + ", ".join(_format(item, indent, options) for item in items) + "]"
    if isinstance(first, str):
        lines = string_list([str(item) for item in items]).split("\n")
        return "".join("\n" + indent + line for line in lines)
    if type(first) in (int, float, bool):
        return str([plain(item) for item in items])
    inner = indent + "  "
    return "".join(f"\n{indent}- " + _format(item, inner, options) for item in items)


def _format_fields(
    fields: list[tuple[str, str]], values: list[Any], indent: str, options: _Options
) -> str:
    inner = indent + "  "
    text = "\n".join(
        f"{indent}{name}: {_format(_as_numbers(value, ftype), inner, options)}"
        for (name, ftype), value in zip(fields, values, strict=True)
    )
    return "\n" + text if indent else text


def _as_numbers(value: object, field_type: str) -> object:
    """uint8 arrays are held as bytes (or str) but shown as numbers."""
    if "uint8[" in field_type:
        if isinstance(value, bytes):
            return list(value)
        if isinstance(value, str):
            return [ord(ch) for ch in value]
    return value


__all__ = [
    "CLEAR_SCREEN",
    "SEPARATOR",
    "echo_record",
    "format_message",
    "format_value",
]
