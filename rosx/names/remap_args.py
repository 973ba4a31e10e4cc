"""Remapping arguments on a ROS 1 command line (ROS wiki *Remapping Arguments*).

An argument is a remapping argument when it looks like ``key:=value`` with a key that starts
with a letter, ``/``, ``~`` or ``_`` and continues with letters, digits, ``_`` and ``/``. Three
kinds exist, told apart by the key:

* ``from:=to`` renames a graph resource;
* ``__name:=``, ``__ns:=``, ``__master:=``, ``__ip:=``, ``__hostname:=``, ``__log:=`` (any key
  starting with ``__``) are special settings;
* ``_param:=value`` sets the node's private parameter ``~param``; the value is YAML text, kept
  raw here.

Every remapping argument is removed from the program's own argv (rospy's ``myargv``), including
ones ROS 1 then ignores (an empty side, or ``:=`` twice). Anything not shaped like a remapping
argument, such as ``:=x``, stays in argv untouched.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

from rosx.record import Record

__all__ = [
    "REMAP",
    "RemapArgs",
    "is_legal_remap",
    "parse_remap_args",
    "strip_remap_args",
]

REMAP = ":="

# Without DOTALL, "." stops at a newline, so (as in rosgraph) an argument whose value spans
# lines is not a remapping argument at all.
_REMAP_ARG = re.compile(r"[~/A-Za-z_][A-Za-z0-9_/]*:=.*")


def is_legal_remap(arg: str) -> bool:
    """Whether ``arg`` has the shape of a remapping argument (``key:=value``)."""
    return _REMAP_ARG.fullmatch(arg) is not None


def strip_remap_args(argv: Sequence[str]) -> list[str]:
    """``argv`` without its remapping arguments (rospy's ``myargv``)."""
    return [arg for arg in argv if not is_legal_remap(arg)]


class RemapArgs(Record):
    """What a command line's remapping arguments say.

    Attributes:
        remappings: ``from`` → ``to`` name remappings, unresolved, in command-line order.
        special: ``__key`` → value settings, keyed with their leading ``__`` (``"__name"``).
        params: Private parameters: name without the leading ``_`` → raw YAML text.
        argv: The arguments that are not remapping arguments, in order.
        ignored: Remapping arguments that carry nothing usable and that ROS 1 skips: an empty
            side (``foo:=``) or more than one ``:=``.
    """

    # A Record rather than a dataclass or a NamedTuple: importing dataclasses (~15 ms) or typing
    # (~2 ms) would cost every tool's start-up.
    __match_args__ = ("remappings", "special", "params", "argv", "ignored")
    __slots__ = __match_args__
    remappings: Mapping[str, str]
    special: Mapping[str, str]
    params: Mapping[str, str]
    argv: Sequence[str]
    ignored: Sequence[str]

    def __init__(
        self,
        remappings: Mapping[str, str] | None = None,
        special: Mapping[str, str] | None = None,
        params: Mapping[str, str] | None = None,
        argv: Sequence[str] = (),
        ignored: Sequence[str] = (),
    ) -> None:
        super().__init__(
            remappings={} if remappings is None else remappings,
            special={} if special is None else special,
            params={} if params is None else params,
            argv=argv,
            ignored=ignored,
        )

    @property
    def name(self) -> str | None:
        """The ``__name:=`` node name override."""
        return self.special.get("__name")

    @property
    def ns(self) -> str | None:
        """The ``__ns:=`` namespace override, as written."""
        return self.special.get("__ns")

    @property
    def master(self) -> str | None:
        """The ``__master:=`` master URI override."""
        return self.special.get("__master")

    @property
    def ip(self) -> str | None:
        """The ``__ip:=`` address override."""
        return self.special.get("__ip")

    @property
    def hostname(self) -> str | None:
        """The ``__hostname:=`` host name override."""
        return self.special.get("__hostname")

    @property
    def log(self) -> str | None:
        """The ``__log:=`` log file override."""
        return self.special.get("__log")


def parse_remap_args(argv: Sequence[str]) -> RemapArgs:
    """Sorts a command line into remappings, special settings, private parameters and the rest.

    Keys and values are stripped of surrounding whitespace; a later argument with the same key
    wins. ``argv`` is taken as given: drop the program name first if it should not be in
    `RemapArgs.argv` (rospy keeps it).
    """
    remappings: dict[str, str] = {}
    special: dict[str, str] = {}
    params: dict[str, str] = {}
    rest: list[str] = []
    ignored: list[str] = []
    for arg in argv:
        if not is_legal_remap(arg):
            rest.append(arg)
            continue
        parts = arg.split(REMAP)
        if len(parts) != 2:
            ignored.append(arg)
            continue
        key, value = (part.strip() for part in parts)
        if not key or not value:
            ignored.append(arg)
        elif key.startswith("__"):
            special[key] = value
        elif key.startswith("_") and len(key) > 1:
            params[key[1:]] = value
        else:
            remappings[key] = value
    return RemapArgs(
        remappings=remappings,
        special=special,
        params=params,
        argv=tuple(rest),
        ignored=tuple(ignored),
    )
