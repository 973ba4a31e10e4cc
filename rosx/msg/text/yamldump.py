"""Plain data written as YAML exactly as PyYAML's ``yaml.dump(data)`` writes it.

``rosparam get`` and ``rosparam dump`` print parameter trees through ``yaml.dump`` with its
defaults: block style (``default_flow_style=False``), keys sorted, indent 2, width 80, no
unicode (non-ASCII characters are escaped in double quotes). This module reproduces that output
for the values the Parameter Server holds: dicts with string keys, lists and tuples, strings,
ints, floats, bools, ``None``, bytes (binary values) and ``xmlrpc.client.DateTime`` (XML-RPC
dates, as rospy hands them to rosparam), and for the dates and times YAML files may hold
(``--dump-params`` of roslaunch writes them back as PyYAML does).

The layout rules, as PyYAML's emitter applies them:

* a mapping's entries start each on a new line at its indentation, ``key: value``; a nested
  mapping is indented two more spaces; a sequence inside a mapping is not indented (``- `` at
  the key's column), a sequence or mapping inside a sequence starts on the ``- `` line;
* empty collections are written in flow style, ``{}`` and ``[]``;
* a scalar is plain unless a YAML reader would take it for something else or its characters
  forbid it, then single-quoted, then double-quoted (`rosx.msg.text.yamlstr` decides and writes);
  long plain and quoted scalars fold at 80 columns, keys never do; a key over 128 characters,
  empty or multi-line becomes a complex key (``? key`` / ``: value``);
* floats print as ``repr`` in lower case with ``.0`` added before an exponent that lacks a
  point (``1.0e-05``), ``.inf``, ``-.inf``, ``.nan``; bools ``true``/``false``; ``None``
  ``null``;
* bytes print as ``!!binary |-`` followed by their base64 text on one indented line: what
  ROS 1's rosparam registers for binary values (``base64.b64encode``, literal style);
* a ``DateTime`` prints as PyYAML prints any Python object: the tag
  ``!!python/object:xmlrpc.client.DateTime`` and the mapping of its state, ``value: TEXT``;
* a plain scalar at the root ends the document with a ``...`` line.
"""

from __future__ import annotations

import binascii
import datetime as dt
import math
from collections.abc import Callable

from rosx.msg.text.yamlstr import Writer, analyze, resolves_as_non_str

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any, TypeGuard
    from xmlrpc.client import DateTime as _DateTime

_INDENT = 2
_DATE_TIME = "xmlrpc.client.DateTime"
_SIMPLE_KEY_LIMIT = 128

#: Decides whether a plain string would be read back as something else than a string.
Implicit = Callable[[str], bool]


def dump(data: object, *, implicit: Implicit | None = None) -> str:
    """``data`` as ``yaml.dump(data)`` writes it, final line break (and ``...``) included.

    ``implicit`` adds to YAML 1.1's implicit types the plain scalars that the dumping program's
    resolver knows too (ROS 1's rosparam adds ``deg(…)`` and ``rad(…)``), so that strings
    looking like them are quoted.

    Raises:
        TypeError: ``data`` holds a value of another type.
    """
    emitter = _Emitter(implicit)
    emitter.node(data, root=True)
    return emitter.finish()


def format_float(value: float) -> str:
    """A float as PyYAML represents it."""
    if math.isnan(value):
        return ".nan"
    if math.isinf(value):
        return ".inf" if value > 0 else "-.inf"
    text = repr(value).lower()
    if "." not in text and "e" in text:
        text = text.replace("e", ".0e", 1)
    return text


class _Emitter:
    """PyYAML's emitter states for one document, followed by recursion over the data."""

    def __init__(self, implicit: Implicit | None) -> None:
        self.writer = Writer()
        self.implicit = implicit
        self.indent: int | None = None
        self.indents: list[int | None] = []

    def finish(self) -> str:
        writer = self.writer
        self._set_indent(None)
        writer.write_indent()
        if writer.open_ended:
            writer.indicator("...", need_space=True)
            writer.write_indent()
        return "".join(writer.out)

    # -- indentation ---------------------------------------------------------------------------

    def _set_indent(self, indent: int | None) -> None:
        self.indent = indent
        self.writer.indent = indent or 0

    def _increase(self, *, flow: bool, indentless: bool = False) -> None:
        self.indents.append(self.indent)
        if self.indent is None:
            self._set_indent(_INDENT if flow else 0)
        elif not indentless:
            self._set_indent(self.indent + _INDENT)

    def _restore(self) -> None:
        self._set_indent(self.indents.pop())

    # -- nodes ---------------------------------------------------------------------------------

    def node(
        self, value: object, *, root: bool = False, mapping: bool = False, key: bool = False
    ) -> None:
        if isinstance(value, dict):
            if value:
                self._block_mapping(value)
            else:
                self._empty_flow("{", "}")
        elif isinstance(value, list | tuple):
            if value:
                self._block_sequence(value, mapping=mapping)
            else:
                self._empty_flow("[", "]")
        elif _is_date_time(value):
            self.writer.indicator(f"!!python/object:{_DATE_TIME}", need_space=True)
            self._block_mapping({"value": value.value})
        else:
            self._increase(flow=True)
            self._scalar(value, root=root, key=key)
            self._restore()

    def _empty_flow(self, start: str, end: str) -> None:
        self.writer.indicator(start, need_space=True, whitespace=True)
        self.writer.indicator(end, need_space=False)

    def _block_sequence(self, items: list[Any] | tuple[Any, ...], *, mapping: bool) -> None:
        writer = self.writer
        self._increase(flow=False, indentless=mapping and not writer.indention)
        for item in items:
            writer.write_indent()
            writer.indicator("-", need_space=True, indention=True)
            self.node(item)
        self._restore()

    def _block_mapping(self, mapping: dict[Any, Any]) -> None:
        writer = self.writer
        self._increase(flow=False)
        try:
            entries = sorted(mapping.items())
        except TypeError:
            entries = list(mapping.items())
        for key, value in entries:
            writer.write_indent()
            if self._simple_key(key):
                self.node(key, mapping=True, key=True)
                writer.indicator(":", need_space=False)
            else:
                writer.indicator("?", need_space=True, indention=True)
                self.node(key, mapping=True)
                writer.write_indent()
                writer.indicator(":", need_space=True, indention=True)
            self.node(value, mapping=True)
        self._restore()

    def _simple_key(self, key: object) -> bool:
        if isinstance(key, dict | list | tuple):
            return not key
        if isinstance(key, bytes):
            return False
        text = _scalar_text(key)
        analysis = analyze(text)
        return len(text) < _SIMPLE_KEY_LIMIT and not analysis.empty and not analysis.multiline

    # -- scalars -------------------------------------------------------------------------------

    def _scalar(self, value: object, *, root: bool, key: bool) -> None:
        writer = self.writer
        split = not key
        if isinstance(value, bytes | bytearray):
            writer.indicator("!!binary", need_space=True)
            encoded = binascii.b2a_base64(value, newline=False).decode("ascii")
            if encoded:
                writer.literal(encoded)
            else:  # PyYAML writes no empty block scalar
                writer.double_quoted(encoded, split)
            return
        text = _scalar_text(value)
        if not isinstance(value, str):
            writer.plain(text, split, root=root)
            return
        analysis = analyze(text)
        plain_is_str = not (resolves_as_non_str(text) or (self.implicit and self.implicit(text)))
        if plain_is_str and analysis.plain and not (key and (analysis.empty or analysis.multiline)):
            writer.plain(text, split, root=root)
        elif analysis.single_quoted and not (key and analysis.multiline):
            writer.single_quoted(text, split)
        else:
            writer.double_quoted(text, split)


def _is_date_time(value: object) -> TypeGuard[_DateTime]:
    # Looked at by name: the class is only loaded where XML-RPC delivered a date.
    kind = type(value)
    return f"{kind.__module__}.{kind.__qualname__}" == _DATE_TIME


def _scalar_text(value: object) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return format_float(value)
    if isinstance(value, str):
        return value
    if isinstance(value, dt.datetime):
        return value.isoformat(" ")
    if isinstance(value, dt.date):
        return value.isoformat()
    raise TypeError(f"cannot write a {type(value).__name__} as YAML: {value!r}")


__all__ = ["dump", "format_float"]
