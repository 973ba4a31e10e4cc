"""The ``rosmsg show`` text of a type: constants and fields, nested types expanded below them.

Each line is ``type name`` (constants ``type NAME=value`` as written), nested message types
expanded beneath their field with two more spaces of indentation, as ROS 1's rosmsg prints.
"""

from __future__ import annotations

from collections.abc import Callable

from rosx.msg.spec import MsgSpec, SrvSpec


def describe_msg(spec: MsgSpec, lookup: Callable[[str], MsgSpec], indent: str = "") -> str:
    """The expanded text of ``spec``; ``lookup`` finds nested types."""
    lines: list[str] = []
    _describe(spec, lookup, indent, lines)
    return "".join(lines)


def describe_srv(spec: SrvSpec, lookup: Callable[[str], MsgSpec]) -> str:
    """Request, a ``---`` line, response."""
    return describe_msg(spec.request, lookup) + "---\n" + describe_msg(spec.response, lookup)


def _describe(spec: MsgSpec, lookup: Callable[[str], MsgSpec], indent: str, out: list[str]) -> None:
    out.extend(f"{indent}{c.type} {c.name}={c.text}\n" for c in spec.constants)
    for field in spec.fields:
        out.append(f"{indent}{field.type} {field.name}\n")
        if not field.is_builtin:
            _describe(lookup(field.base_type), lookup, indent + "  ", out)
