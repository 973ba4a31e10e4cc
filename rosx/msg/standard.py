"""The standard ROS 1 Noetic message types, taken from rosbags' ROS1_NOETIC type store.

rosbags keeps field lists, not the original files, so each type's definition text is rebuilt
from them (``type name`` lines, constants first as ``type NAME=value``) and then parsed like any
other ``.msg`` text. Comments of the original files are therefore absent; md5 sums are not
affected, since ROS 1 hashes neither comments nor layout.
"""

from __future__ import annotations

from functools import cache
from typing import Any

#: rosbags gives empty ROS 1 messages this one field (an IDL rule); ROS 1 has no such field.
_PLACEHOLDER = "structure_needs_at_least_one_member"
_TIME_TYPES = {"builtin_interfaces/msg/Time": "time", "builtin_interfaces/msg/Duration": "duration"}


@cache
def _fielddefs() -> dict[str, Any]:
    from rosbags.typesys import Stores, get_typestore  # 80 ms: only when needed

    defs: dict[str, Any] = get_typestore(Stores.ROS1_NOETIC).fielddefs
    return defs


def _ros1_name(name: str) -> str:
    package, _, short = name.partition("/msg/")
    return f"{package}/{short}"


@cache
def standard_types() -> dict[str, str]:
    """Map each standard ``pkg/Type`` to its rosbags name (``pkg/msg/Type``)."""
    return {
        _ros1_name(name): name
        for name in _fielddefs()
        if "/msg/" in name and not name.startswith("builtin_interfaces/")
    }


def standard_text(full_name: str) -> str | None:
    """The definition text of standard type ``full_name``, or None when rosbags lacks it."""
    source = standard_types().get(full_name)
    if source is None:
        return None
    constants, fields = _fielddefs()[source]
    lines = [f"{type_} {name}={_constant_text(value)}" for name, type_, value in constants]
    lines += [f"{_type_text(node)} {name}" for name, node in fields if name != _PLACEHOLDER]
    return "".join(line + "\n" for line in lines)


def _constant_text(value: object) -> str:
    return str(value)


def _type_text(node: tuple[Any, Any]) -> str:
    kind, detail = node
    kind_name = getattr(kind, "name", str(kind))
    if kind_name == "BASE":
        return str(detail[0])
    if kind_name == "NAME":
        name = str(detail)
        if name in _TIME_TYPES:
            return _TIME_TYPES[name]
        ros1 = _ros1_name(name)
        return "Header" if ros1 == "std_msgs/Header" else ros1
    element, size = detail
    suffix = f"[{size}]" if kind_name == "ARRAY" else "[]"
    return _type_text(element) + suffix
