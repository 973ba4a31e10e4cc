"""YAML errors told in one line, for tools whose arguments are YAML (rosservice, rosparam).

PyYAML's description of an error spans several lines (context, the problem, and for each a mark
with a snippet of the text and a caret). A command-line error is one line: the descriptions
joined, and where the problem is.
"""

from __future__ import annotations

import re

_MARK = re.compile(r'^\s+in "[^"]*", line (\d+), column (\d+)')


def one_line(description: str) -> str:
    """``while parsing …; expected …, but found … (line 1, column 7)`` from PyYAML's text."""
    parts: list[str] = []
    where = ""
    for line in description.splitlines():
        mark = _MARK.match(line)
        if mark is not None:
            where = f" (line {mark.group(1)}, column {mark.group(2)})"
        elif line and not line[0].isspace():
            parts.append(line.strip())
    return "; ".join(parts) + where
