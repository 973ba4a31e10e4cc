"""A node's client of the Parameter Server (ROS wiki Parameter_Server, ROS/Parameter Server API).

Names are resolved in the node's namespace (``~name`` in its private one) and remapped before
they reach the master. `ParamClient.get_cached` subscribes to a key once (``subscribeParam``)
and then answers from a cache that the master keeps current through the node's ``paramUpdate``
(`ParamCache.update`), as rospy's ``get_param_cached`` does.
"""

from __future__ import annotations

import contextlib
import threading
from typing import TYPE_CHECKING, Any

from rosx.master.client import MasterError

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.master.client import MasterClient

_UNSET: Any = object()


class ParamCache:
    """Values of subscribed parameters, updated by ``paramUpdate`` (rospy's param cache)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._values: dict[str, Any] = {}

    def set(self, key: str, value: Any) -> None:
        """Record ``key``'s value as the master gave it on subscribing."""
        with self._lock:
            self._values[key.rstrip("/") or "/"] = value

    def get(self, key: str) -> Any:
        """The cached value; `KeyError` when ``key`` is not subscribed."""
        with self._lock:
            return self._values[key.rstrip("/") or "/"]

    def has(self, key: str) -> bool:
        """Whether ``key`` is subscribed."""
        with self._lock:
            return (key.rstrip("/") or "/") in self._values

    def update(self, key: str, value: Any) -> None:
        """Apply a ``paramUpdate``; `KeyError` if neither ``key`` nor a parent is subscribed.

        A dict value replaces the namespace, as on the server: cached keys below it take the
        new values (or are unset, ``{}``, when the dict no longer has them).
        """
        key = key.rstrip("/") or "/"
        with self._lock:
            matched = False
            for cached in list(self._values):
                if cached == key:
                    self._values[cached] = value
                    matched = True
                elif cached.startswith(key + "/") or key == "/":
                    self._values[cached] = _descend(value, cached[len(key) :].strip("/"))
                    matched = True
                elif key.startswith(cached + "/") or cached == "/":
                    parent = self._values[cached]
                    if isinstance(parent, dict):
                        _assign(parent, key[len(cached) :].strip("/"), value)
                    matched = True
            if not matched:
                raise KeyError(key)

    def subscribed(self) -> list[str]:
        """The subscribed keys."""
        with self._lock:
            return list(self._values)


def _descend(value: Any, path: str) -> Any:
    for part in filter(None, path.split("/")):
        if not isinstance(value, dict) or part not in value:
            return {}
        value = value[part]
    return value


def _assign(tree: dict[str, Any], path: str, value: Any) -> None:
    parts = [p for p in path.split("/") if p]
    for part in parts[:-1]:
        child = tree.get(part)
        if not isinstance(child, dict):
            child = tree[part] = {}
        tree = child
    if parts:
        tree[parts[-1]] = value


class ParamClient:
    """get/set/has/delete/search/names on the master, with names resolved by ``resolve``."""

    def __init__(
        self,
        master: MasterClient,
        resolve: Callable[[str], str],
        node_uri: Callable[[], str],
        cache: ParamCache,
    ) -> None:
        self._master = master
        self._resolve = resolve
        self._node_uri = node_uri
        self.cache = cache

    def get(self, name: str, default: Any = _UNSET) -> Any:
        """The value of ``name``; ``default`` if given and unset, else `KeyError`."""
        key = self._resolve(name)
        try:
            return self._master.call("getParam", key)
        except MasterError:
            if default is _UNSET:
                raise KeyError(name) from None
            return default

    def get_cached(self, name: str, default: Any = _UNSET) -> Any:
        """As `get`, but subscribed once and then answered from the cache."""
        key = self._resolve(name)
        if not self.cache.has(key):
            value = self._master.call("subscribeParam", self._node_uri(), key)
            self.cache.set(key, value)
        value = self.cache.get(key)
        if value == {} and not self.has(name):
            # subscribeParam answers {} for an unset key, as for an empty namespace.
            if default is _UNSET:
                raise KeyError(name)
            return default
        return value

    def set(self, name: str, value: Any) -> None:
        """Set ``name`` to ``value`` (a dict sets a whole namespace)."""
        self._master.call("setParam", self._resolve(name), value)

    def has(self, name: str) -> bool:
        """Whether ``name`` is set."""
        return bool(self._master.call("hasParam", self._resolve(name)))

    def delete(self, name: str) -> None:
        """Delete ``name``; `KeyError` if it is not set."""
        try:
            self._master.call("deleteParam", self._resolve(name))
        except MasterError:
            raise KeyError(name) from None

    def search(self, name: str) -> str | None:
        """The closest key named ``name`` up the node's namespaces, or ``None``."""
        try:
            found = self._master.call("searchParam", name)
        except MasterError:
            return None
        return str(found) if found else None

    def names(self) -> list[str]:
        """Every parameter name on the server."""
        return [str(name) for name in self._master.call("getParamNames")]

    def unsubscribe_all(self) -> None:
        """Unsubscribe every cached key (on shutdown); errors are ignored."""
        for key in self.cache.subscribed():
            with contextlib.suppress(Exception):  # best effort while shutting down
                self._master.call("unsubscribeParam", self._node_uri(), key, timeout=2.0)
