"""How the master checks and resolves the arguments of Master and Parameter API calls.

rosmaster resolves every name argument against the *caller id* (rosgraph's ``resolve_name``): a
relative name joins the caller's namespace, ``~name`` joins the caller's own name, and the empty
name stands for the caller's namespace. Each check below either returns the argument to use
(resolved, for names) or raises `InvalidArgument` with rosmaster's message, which becomes the
``-1`` reply's status text.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.names import canonicalize, namespace_of

if TYPE_CHECKING:
    from collections.abc import Callable

    Check = Callable[[Any, str], Any]

ANY_TYPE = "*"


class InvalidArgument(ValueError):  # noqa: N818 -- rosmaster's ParameterInvalid, renamed
    """An argument rosmaster would refuse; the message is rosmaster's."""


def resolve_for_caller(name: str, caller_id: str) -> str:
    """`name` resolved against `caller_id`, exactly as rosmaster resolves call arguments."""
    if not name:
        return namespace_of(caller_id)
    name = canonicalize(name)
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        return canonicalize(caller_id + "/" + name[1:])
    return namespace_of(caller_id) + name


def non_empty_str(param: str) -> Check:
    """A non-empty string, kept as given (parameter keys are resolved by the method)."""

    def check(value: Any, caller_id: str) -> Any:
        if not value:
            raise InvalidArgument(f"ERROR: parameter [{param}] must be specified and non-empty")
        if not isinstance(value, str):
            raise InvalidArgument(f"ERROR: parameter [{param}] must be a string")
        return value

    return check


def not_none(param: str) -> Check:
    """Any value but nil."""

    def check(value: Any, caller_id: str) -> Any:
        if value is None:
            raise InvalidArgument(f"ERROR: parameter [{param}] must be specified")
        return value

    return check


def is_api(param: str) -> Check:
    """An ``http://`` or ``rosrpc://`` URI."""

    def check(value: Any, caller_id: str) -> Any:
        if not value or not isinstance(value, str):
            raise InvalidArgument(f"ERROR: parameter [{param}] is not an XMLRPC URI")
        if not value.startswith(("http://", "rosrpc://")):
            raise InvalidArgument(f"ERROR: parameter [{param}] is not an RPC URI")
        return value

    return check


def _resolved_name(param: str, value: Any, caller_id: str) -> str:
    if not value or not isinstance(value, str):
        raise InvalidArgument(f"ERROR: parameter [{param}] must be a non-empty string")
    # rosmaster's only character check: a URI given where a name belongs.
    if ":" in value or " " in value:
        raise InvalidArgument(f"ERROR: parameter [{param}] contains illegal chars")
    return resolve_for_caller(value, caller_id)


def valid_name(param: str) -> Check:
    """A name, resolved."""

    def check(value: Any, caller_id: str) -> Any:
        return _resolved_name(param, value, caller_id)

    return check


def is_topic(param: str) -> Check:
    """A topic or service name, resolved; not the root namespace."""

    def check(value: Any, caller_id: str) -> Any:
        resolved = _resolved_name(param, value, caller_id)
        if value == "/":
            raise InvalidArgument(f"ERROR: parameter [{param}] cannot be the global namespace")
        return resolved

    return check


def empty_or_valid_name(param: str) -> Check:
    """``''`` (everything), or a name, resolved."""

    def check(value: Any, caller_id: str) -> Any:
        if not isinstance(value, str):
            raise InvalidArgument(f"ERROR: parameter [{param}] must be a string")
        return resolve_for_caller(value, caller_id) if value else ""

    return check


def valid_type_name(param: str) -> Check:
    """A message type ``package/Type``, or ``*``."""

    def check(value: Any, caller_id: str) -> Any:
        if value == ANY_TYPE:
            return value
        if not value or not isinstance(value, str):
            raise InvalidArgument(f"ERROR: parameter [{param}] must be a non-empty string")
        if len(value.split("/")) != 2:
            raise InvalidArgument(
                f"ERROR: parameter [{param}] is not a valid package resource name"
            )
        return value

    return check
