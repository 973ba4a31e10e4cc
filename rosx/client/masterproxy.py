"""``rospy.MasterProxy``: the master's API as rospy hands it to scripts (``rospy.get_master()``).

Every Master and Parameter API method is an attribute: the node's name goes first, the names
the method takes are resolved as the node resolves them (``~k``, relative names, remappings),
and the reply comes back whole, ``[code, statusMessage, value]``, as rospy returns it. The
Parameter Server is also a mapping: ``proxy[key]``, ``proxy[key] = value``, ``del proxy[key]``,
``key in proxy``, ``iter(proxy)``; ``search_param`` and ``get_param_cached`` as rospy's.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.client import state
from rosx.client.exceptions import ROSException

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

#: Methods whose first argument (after the caller) is a name to resolve, as rospy's table.
_NAMED_FIRST = frozenset(
    {
        "deleteParam", "setParam", "getParam", "searchParam", "subscribeParam",
        "unsubscribeParam", "hasParam", "registerService", "lookupService", "unregisterService",
        "registerSubscriber", "unregisterSubscriber", "registerPublisher",
        "unregisterPublisher", "lookupNode", "getPublishedTopics",
    }
)  # fmt: skip


class MasterProxy:
    """The master at ``uri``, called as the process's node (see the module docstring)."""

    def __init__(self, uri: str) -> None:
        from rosx.transport.client import ServerProxy  # noqa: PLC0415 - the network code loads only to talk

        self.uri = uri
        #: The master's plain XML-RPC proxy (no caller, no resolution), as rospy's ``target``.
        self.target = ServerProxy(uri)

    def __getattr__(self, method: str) -> Callable[..., Any]:
        if method.startswith("_"):
            raise AttributeError(method)
        remote = getattr(self.target, method)

        def call(*args: Any) -> Any:
            params = list(args)
            if params and method in _NAMED_FIRST:
                params[0] = state.CLIENT.resolve_name(params[0])
            return remote(state.CLIENT.caller_id(), *params)

        call.__name__ = method
        return call

    def __getitem__(self, key: str) -> Any:
        code, _, value = self.target.getParam(state.CLIENT.caller_id(), _resolve(key))
        if code != 1:
            raise KeyError(key)
        return value

    def __setitem__(self, key: str, value: Any) -> None:
        self.target.setParam(state.CLIENT.caller_id(), _resolve(key), value)

    def __delitem__(self, key: str) -> None:
        code, status, _ = self.target.deleteParam(state.CLIENT.caller_id(), _resolve(key))
        if code == -1:
            raise KeyError(key)
        if code != 1:
            raise ROSException(f"cannot delete parameter: {status}")

    def __contains__(self, key: object) -> bool:
        code, status, value = self.target.hasParam(state.CLIENT.caller_id(), _resolve(str(key)))
        if code != 1:
            raise ROSException(f"cannot check parameter on server: {status}")
        return bool(value)

    def __iter__(self) -> Iterator[str]:
        code, status, value = self.target.getParamNames(state.CLIENT.caller_id())
        if code != 1:
            raise ROSException(f"cannot retrieve parameter names: {status}")
        return iter(value)

    def search_param(self, key: str) -> str | None:
        """The closest ``key`` up the node's namespaces, or None (a remapped key first)."""
        from rosx.client.names import get_mappings  # noqa: PLC0415 - the rospy API loads only when used

        key = get_mappings().get(key, key)
        code, status, value = self.target.searchParam(state.CLIENT.caller_id(), key)
        if code == 1:
            return str(value)
        if code == -1:
            return None
        raise ROSException(f"cannot search for parameter: {status}")

    def get_param_cached(self, key: str) -> Any:
        """``key``'s value, from the cache the master keeps current once the node runs."""
        from rosx.client.params import get_param_cached  # noqa: PLC0415 - the rospy API loads only when used

        return get_param_cached(key)


def _resolve(key: str) -> str:
    return state.CLIENT.resolve_name(key)


def get_master(env: object = None) -> MasterProxy:
    """The process's `MasterProxy` for its master (``__master:=``, ``ROS_MASTER_URI``)."""
    client = state.CLIENT
    with client.lock:
        if client.script_master is None:
            client.script_master = MasterProxy(client.master_uri())
        proxy: MasterProxy = client.script_master
        return proxy


__all__ = ["MasterProxy", "get_master"]
