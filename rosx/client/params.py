"""rospy's Parameter Server functions: ``get_param``, ``set_param``, ``search_param`` and more.

Names resolve as the node resolves them (``~x`` is private; relative names are in the node's
namespace). They work before `init_node` too, as rospy's do, calling the master as
``/unnamed``. ``get_param_cached`` subscribes to the parameter once the node runs and answers
from the cache the master keeps current.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.client.exceptions import ROSException

if TYPE_CHECKING:
    from rosx.node.params import ParamClient

_unspecified: Any = object()


def _params() -> ParamClient:
    client = state.CLIENT
    node = client.node
    if node is not None and client.caller_override is None:
        return node.params
    from rosx.node.params import ParamCache, ParamClient  # noqa: PLC0415 - the node runtime loads with the first node

    master = client.master()
    if client.caller_override is not None:
        from rosx.master.client import MasterClient  # noqa: PLC0415 - the master's code loads only to talk to one

        master = MasterClient(client.master_uri(), client.caller_override)
    return ParamClient(master, client.resolve_name, lambda: "", ParamCache())


def get_param(param_name: str, default: Any = _unspecified) -> Any:
    """The value of ``param_name``; ``default`` when it is unset and a default is given.

    Raises:
        KeyError: the parameter is not set and there is no default.
    """
    if default is _unspecified:
        return _params().get(param_name)
    return _params().get(param_name, default)


def get_param_cached(param_name: str, default: Any = _unspecified) -> Any:
    """As `get_param`, answered from a cache the master keeps current once the node runs."""
    if state.CLIENT.node is None:
        return get_param(param_name, default)
    if default is _unspecified:
        return _params().get_cached(param_name)
    return _params().get_cached(param_name, default)


def get_param_names() -> list[str]:
    """Every parameter name on the server."""
    try:
        return _params().names()
    except Exception as exc:
        raise ROSException(f"Unable to retrieve parameter names: {exc}") from None


def set_param(param_name: str, param_value: Any) -> None:
    """Set ``param_name`` to ``param_value`` (a dict sets a whole namespace)."""
    _params().set(param_name, param_value)


def has_param(param_name: str) -> bool:
    """Whether ``param_name`` is set."""
    return _params().has(param_name)


def delete_param(param_name: str) -> None:
    """Delete ``param_name``.

    Raises:
        KeyError: the parameter is not set.
    """
    _params().delete(param_name)


def search_param(param_name: str) -> str | None:
    """The closest parameter called ``param_name`` up the node's namespaces, or None."""
    return _params().search(param_name)


__all__ = [
    "delete_param",
    "get_param",
    "get_param_cached",
    "get_param_names",
    "has_param",
    "search_param",
    "set_param",
]
