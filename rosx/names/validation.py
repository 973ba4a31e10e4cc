"""Validation of ROS 1 graph resource names.

Two rule sets exist in ROS 1 and both are provided here:

* `validate` follows roscpp (``ros::names::validate``): the first character is a letter, ``/`` or
  ``~``; every later one is a letter, a digit, ``/`` or ``_``. The empty name is valid (it stands
  for the namespace itself). Doubled and trailing slashes pass, because resolution removes them.
  Its error texts are roscpp's, word for word.
* The predicates (`is_legal_name`, `is_legal_base_name`, `is_global`, `is_private`) follow
  rosgraph/rospy, which additionally refuse ``//`` in a legal name.

Letters and digits mean ASCII ones only, as in the C locale roscpp checks them in.
"""

from __future__ import annotations

import re
import string

__all__ = [
    "InvalidNameError",
    "check_name",
    "is_global",
    "is_legal_base_name",
    "is_legal_name",
    "is_private",
    "validate",
]

_FIRST_CHARS = frozenset(string.ascii_letters + "/~")
_LATER_CHARS = frozenset(string.ascii_letters + string.digits + "/_")

_LEGAL_NAME = re.compile(r"[~/A-Za-z][A-Za-z0-9_/]*")
_LEGAL_BASE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


class InvalidNameError(ValueError):
    """A graph resource name broke ROS 1's rules; ``str(error)`` is roscpp's message."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


def validate(name: str) -> str | None:
    """Checks ``name`` against roscpp's rules.

    Args:
        name: A graph resource name as written (relative, ``/global`` or ``~private``).

    Returns:
        None when the name is valid, otherwise the error text roscpp gives for it.
    """
    if not name:
        return None
    first = name[0]
    if first not in _FIRST_CHARS:
        return (
            f"Character [{first}] is not valid as the first character in Graph Resource Name "
            f"[{name}].  Valid characters are a-z, A-Z, / and in some cases ~."
        )
    for index, char in enumerate(name[1:], start=1):
        if char not in _LATER_CHARS:
            return (
                f"Character [{char}] at element [{index}] is not valid in Graph Resource Name "
                f"[{name}].  Valid characters are a-z, A-Z, 0-9, / and _."
            )
    return None


def check_name(name: str) -> str:
    """Returns ``name`` unchanged if `validate` accepts it.

    Raises:
        InvalidNameError: With roscpp's message when the name is invalid.
    """
    error = validate(name)
    if error is not None:
        raise InvalidNameError(error)
    return name


def is_global(name: str) -> bool:
    """Whether ``name`` is global (starts with ``/``)."""
    return name.startswith("/")


def is_private(name: str) -> bool:
    """Whether ``name`` is private (starts with ``~``)."""
    return name.startswith("~")


def is_legal_name(name: str) -> bool:
    """rosgraph's test for a legal graph resource name.

    The empty name is legal; otherwise the name is a letter, ``/`` or ``~`` followed by letters,
    digits, ``_`` and ``/``, with no ``//`` anywhere.
    """
    if not name:
        return True
    return _LEGAL_NAME.fullmatch(name) is not None and "//" not in name


def is_legal_base_name(name: str) -> bool:
    """rosgraph's test for a base name: one letter then letters, digits and ``_``; no namespace."""
    return _LEGAL_BASE_NAME.fullmatch(name) is not None
