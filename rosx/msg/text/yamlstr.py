"""Strings written as PyYAML's ``yaml.dump`` writes them, for the echo text of ROS 1 messages.

ROS 1 prints a string field through ``yaml.dump(value, default_style='"')`` and a string array
through ``yaml.dump(values)`` (a block list), so its output carries PyYAML's choices: which
characters are escaped and how, when a scalar may stay plain or needs quotes (YAML 1.1 implicit
types: ``yes``, ``1.5``, ``~``…), and where long scalars are folded at 80 columns. This module
reproduces those choices for ``str`` scalars with PyYAML's default settings (width 80, indent 2,
``allow_unicode=False``), without depending on PyYAML.

`analyze`, `resolves_as_non_str` and `Writer` are the pieces `rosx.msg.text.yamldump` builds whole
documents from (``rosparam get``/``dump``).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import cache

from rosx.record import Record

_WIDTH = 80
_INDENT = 2
_BREAKS = "\n\x85\u2028\u2029"
_BLANK_OR_END = "\0 \t\r\n\x85\u2028\u2029"

#: Escapes with a short form in double-quoted scalars.
_SHORT_ESCAPES = {
    "\0": "0",
    "\x07": "a",
    "\x08": "b",
    "\t": "t",
    "\n": "n",
    "\x0b": "v",
    "\x0c": "f",
    "\r": "r",
    "\x1b": "e",
    '"': '"',
    "\\": "\\",
    "\x85": "N",
    "\xa0": "_",
    "\u2028": "L",
    "\u2029": "P",
}

#: Plain scalars that a YAML 1.1 reader (PyYAML's resolver) would take for something other
#: than a string: bool, float, int, merge key, null, timestamp, value key, yaml tag.
_IMPLICIT_NON_STR = r"""^(?:
      yes|Yes|YES|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF
    | [-+]?[0-9][0-9_]*\.[0-9_]*(?:[eE][-+][0-9]+)?
    | \.[0-9][0-9_]*(?:[eE][-+][0-9]+)?
    | [-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*
    | [-+]?\.(?:inf|Inf|INF)
    | \.(?:nan|NaN|NAN)
    | [-+]?0b[0-1_]+
    | [-+]?0[0-7_]+
    | [-+]?(?:0|[1-9][0-9_]*)
    | [-+]?0x[0-9a-fA-F_]+
    | [-+]?[1-9][0-9_]*(?::[0-5]?[0-9])+
    | <<
    | ~|null|Null|NULL|
    | [0-9]{4}-[0-9]{2}-[0-9]{2}
    | [0-9]{4}-[0-9]{1,2}-[0-9]{1,2}(?:[Tt]|[ \t]+)[0-9]{1,2}:[0-9]{2}:[0-9]{2}(?:\.[0-9]*)?
      (?:[ \t]*(?:Z|[-+][0-9]{1,2}(?::[0-9]{2})?))?
    | =
    | [!&*]
    )$"""


@cache
def _implicit_non_str() -> re.Pattern[str]:
    # Compiled on first use: most messages have no string arrays.
    return re.compile(_IMPLICIT_NON_STR, re.VERBOSE)


def resolves_as_non_str(text: str) -> bool:
    """Whether a YAML 1.1 reader would take ``text``, written plain, for something else than a
    string (a bool, number, null…), so that it must be quoted."""
    return _implicit_non_str().match(text) is not None


class Analysis(Record):
    """Which styles PyYAML's emitter allows for a scalar (its ``ScalarAnalysis``, block context)."""

    __match_args__ = ("empty", "multiline", "plain", "single_quoted", "block")
    __slots__ = __match_args__
    empty: bool
    multiline: bool
    plain: bool
    single_quoted: bool
    block: bool

    def __init__(
        self, *, empty: bool, multiline: bool, plain: bool, single_quoted: bool, block: bool
    ) -> None:
        super().__init__(
            empty=empty, multiline=multiline, plain=plain, single_quoted=single_quoted, block=block
        )


def quoted(text: str) -> str:
    """``text`` as ``yaml.dump(text, default_style='"')`` gives it, without the final newline."""
    writer = Writer()
    writer.indent = _INDENT
    writer.double_quoted(text)
    return "".join(writer.out)


def string_list(items: Sequence[str]) -> str:
    """A non-empty list of strings as ``yaml.dump(items)`` gives it (a block list), unterminated."""
    writer = Writer()
    for number, item in enumerate(items):
        writer.indent = 0
        if number:
            writer.line_break()
        writer.indicator("-", need_space=True, indention=True)
        writer.indent = _INDENT
        style = _style(item)
        if style == "plain":
            writer.plain(item)
        elif style == "single":
            writer.single_quoted(item)
        else:
            writer.double_quoted(item)
    return "".join(writer.out)


def analyze(text: str) -> Analysis:
    """The styles a block-context scalar may take (PyYAML's analysis, ``allow_unicode=False``)."""
    if not text:
        return Analysis(empty=True, multiline=False, plain=True, single_quoted=True, block=False)
    block_indicators = text.startswith(("---", "..."))
    line_breaks = special = False
    leading_space = leading_break = trailing_space = trailing_break = False
    break_space = space_break = False
    previous_space = previous_break = False
    last = len(text) - 1
    for index, ch in enumerate(text):
        followed_by_blank = index == last or text[index + 1] in _BLANK_OR_END
        if index == 0:
            if ch in "#,[]{}&*!|>'\"%@`" or (ch in "?:-" and followed_by_blank):
                block_indicators = True
        elif (ch == ":" and followed_by_blank) or (ch == "#" and text[index - 1] in _BLANK_OR_END):
            block_indicators = True
        if ch in _BREAKS:
            line_breaks = True
        if not (ch == "\n" or "\x20" <= ch <= "\x7e"):
            # Without allow_unicode every other character is written as an escape.
            special = True
        if ch == " ":
            leading_space = leading_space or index == 0
            trailing_space = trailing_space or index == last
            break_space = break_space or previous_break
            previous_space, previous_break = True, False
        elif ch in _BREAKS:
            leading_break = leading_break or index == 0
            trailing_break = trailing_break or index == last
            space_break = space_break or previous_space
            previous_space, previous_break = False, True
        else:
            previous_space = previous_break = False
    plain = not (
        leading_space
        or leading_break
        or trailing_space
        or trailing_break
        or break_space
        or space_break
        or special
        or line_breaks
        or block_indicators
    )
    single = not (break_space or space_break or special)
    block = not (trailing_space or space_break or special)
    return Analysis(
        empty=False, multiline=line_breaks, plain=plain, single_quoted=single, block=block
    )


def _style(text: str) -> str:
    analysis = analyze(text)
    if analysis.plain and not resolves_as_non_str(text):
        return "plain"
    if analysis.single_quoted:
        return "single"
    return "double"


class Writer:
    """The parts of PyYAML's emitter state that decide spaces, breaks and folding.

    ``split=False`` (a mapping key) never folds a long scalar. ``open_ended`` is set by a
    plain scalar at the document's root: PyYAML then ends the document with ``...``.
    """

    def __init__(self) -> None:
        self.out: list[str] = []
        self.column = 0
        self.whitespace = True
        self.indention = True
        self.indent = 0
        self.open_ended = False

    def write(self, data: str) -> None:
        """Append ``data`` and advance the column (``data`` holds no line break)."""
        self.out.append(data)
        self.column += len(data)

    def line_break(self, data: str = "\n") -> None:
        """End the line; the next write starts at column 0 and counts as indentation."""
        self.out.append(data)
        self.whitespace = self.indention = True
        self.column = 0

    def indicator(
        self, text: str, *, need_space: bool, whitespace: bool = False, indention: bool = False
    ) -> None:
        """Write an indicator such as ``-``, ``:`` or a quote, with a space before it where YAML
        needs one."""
        self.write(text if self.whitespace or not need_space else " " + text)
        self.whitespace = whitespace
        self.indention = self.indention and indention
        self.open_ended = False

    def write_indent(self) -> None:
        """Break the line if needed and pad to the current indent, as PyYAML's ``write_indent``."""
        if (
            not self.indention
            or self.column > self.indent
            or (self.column == self.indent and not self.whitespace)
        ):
            self.line_break()
        if self.column < self.indent:
            self.whitespace = True
            self.out.append(" " * (self.indent - self.column))
            self.column = self.indent

    def double_quoted(self, text: str, split: bool = True) -> None:
        """Write ``text`` as a double-quoted scalar with PyYAML's escapes, folding long lines
        with a backslash unless ``split`` is false."""
        self.indicator('"', need_space=True)
        start = end = 0
        while end <= len(text):
            ch = text[end] if end < len(text) else None
            if ch is None or ch in '"\\\x85\u2028\u2029\ufeff' or not "\x20" <= ch <= "\x7e":
                if start < end:
                    self.write(text[start:end])
                    start = end
                if ch is not None:
                    self.write("\\" + _escape(ch))
                    start = end + 1
            fold = 0 < end < len(text) - 1 and (ch == " " or start >= end)
            if fold and split and self.column + (end - start) > _WIDTH:
                self.write(text[start:end] + "\\")
                start = max(start, end)
                self.write_indent()
                self.whitespace = self.indention = False
                if text[start] == " ":
                    # A line may not start with a folded space: it is escaped.
                    self.write("\\")
            end += 1
        self.indicator('"', need_space=False)

    def single_quoted(self, text: str, split: bool = True) -> None:
        """Write ``text`` as a single-quoted scalar (``'`` doubled), folding at spaces as PyYAML
        does unless ``split`` is false."""
        self.indicator("'", need_space=True)
        spaces = breaks = False
        start = end = 0
        while end <= len(text):
            ch = text[end] if end < len(text) else None
            if spaces:
                if ch != " ":
                    lone = start + 1 == end and start != 0 and end != len(text)
                    if lone and split and self.column > _WIDTH:
                        self.write_indent()
                    else:
                        self.write(text[start:end])
                    start = end
            elif breaks:
                if ch is None or ch not in _BREAKS:
                    self._breaks(text[start:end])
                    self.write_indent()
                    start = end
            elif (ch is None or ch in " '" or ch in _BREAKS) and start < end:
                self.write(text[start:end])
                start = end
            if ch == "'":
                self.write("''")
                start = end + 1
            if ch is not None:
                spaces, breaks = ch == " ", ch in _BREAKS
            end += 1
        self.indicator("'", need_space=False)

    def plain(self, text: str, split: bool = True, *, root: bool = False) -> None:
        """Write ``text`` as a plain scalar, folding at spaces past PyYAML's width unless
        ``split`` is false; ``root`` marks a document-level scalar, which PyYAML ends with
        ``...``."""
        if root:
            self.open_ended = True
        if not text:
            return
        if not self.whitespace:
            self.write(" ")
        self.whitespace = self.indention = False
        spaces = False
        start = end = 0
        # Plain scalars here never hold line breaks (the analysis forbids them).
        while end <= len(text):
            ch = text[end] if end < len(text) else None
            if spaces:
                if ch != " ":
                    if start + 1 == end and split and self.column > _WIDTH:
                        self.write_indent()
                        self.whitespace = self.indention = False
                    else:
                        self.write(text[start:end])
                    start = end
            elif ch is None or ch == " ":
                self.write(text[start:end])
                start = end
            if ch is not None:
                spaces = ch == " "
            end += 1

    def literal(self, text: str) -> None:
        """A literal block scalar (``|``), as PyYAML writes one, line break included."""
        hints = ""
        if text[:1] in (" ", *_BREAKS):
            hints += str(_INDENT)
        if text[-1:] not in _BREAKS:
            hints += "-"
        elif len(text) == 1 or text[-2] in _BREAKS:
            hints += "+"
        self.indicator("|" + hints, need_space=True)
        if hints.endswith("+"):
            self.open_ended = True
        self.line_break()
        breaks = True
        start = end = 0
        while end <= len(text):
            ch = text[end] if end < len(text) else None
            if breaks:
                if ch is None or ch not in _BREAKS:
                    for br in text[start:end]:
                        self.line_break(br)
                    if ch is not None:
                        self.write_indent()
                    start = end
            elif ch is None or ch in _BREAKS:
                self.out.append(text[start:end])
                if ch is None:
                    self.line_break()
                start = end
            if ch is not None:
                breaks = ch in _BREAKS
            end += 1

    def _breaks(self, run: str) -> None:
        # A first newline is doubled: a single break inside quotes would fold into a space.
        if run[0] == "\n":
            self.line_break()
        for br in run:
            self.line_break(br)


def _escape(ch: str) -> str:
    short = _SHORT_ESCAPES.get(ch)
    if short is not None:
        return short
    code = ord(ch)
    if code <= 0xFF:
        return f"x{code:02X}"
    if code <= 0xFFFF:
        return f"u{code:04X}"
    return f"U{code:08X}"


__all__ = ["Analysis", "Writer", "analyze", "quoted", "resolves_as_non_str", "string_list"]
