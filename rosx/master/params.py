"""The parameter tree of the Parameter Server (ROS wiki Parameter_Server, Parameter Server API).

Rules, as rosmaster keeps them:

* Keys are global names; a dict value is a namespace. Setting a dict replaces the whole
  namespace (no merge); setting below a non-dict value turns that value into a namespace.
  Getting a namespace returns its subtree as a dict. The root ``/`` can only be set to a dict
  and cannot be deleted.
* Values keep their XML-RPC types: int, float, bool, str, bytes (base64), lists, dicts.
* `search` looks for a relative key from a node upwards, matching on the key's first element
  (``robot_description/arm`` is found under the nearest namespace holding
  ``robot_description``, whether or not ``arm`` exists there).
* `param_updates` says which parameter subscribers hear of a change, with what key and value.

Pure data: nothing here knows of XML-RPC or of who calls.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.master.actions import ParamUpdate
from rosx.names import canonicalize, is_global, is_private, ns_join

if TYPE_CHECKING:
    from collections.abc import Iterable, Mapping

SEP = "/"


def _parts(key: str) -> list[str]:
    return [part for part in key.split(SEP) if part]


class ParamTree:
    """The parameters, as nested dicts below the root namespace."""

    def __init__(self) -> None:
        self.root: dict[str, Any] = {}

    def get(self, key: str) -> Any:
        """The value at global `key`, or the subtree (a dict) if it is a namespace.

        Raises:
            KeyError: nothing is set at `key`.
        """
        value: Any = self.root
        for part in _parts(key):
            if type(value) is not dict:
                raise KeyError(key)
            value = value[part]
        return value

    def has(self, key: str) -> bool:
        """Whether something (a value or a namespace) is set at `key`."""
        try:
            self.get(key)
        except KeyError:
            return False
        return True

    def set(self, key: str, value: Any) -> None:
        """Set `key` to `value` (a dict replaces the namespace).

        Raises:
            TypeError: `key` is the root and `value` is not a dict.
        """
        if key == SEP:
            if type(value) is not dict:
                raise TypeError("cannot set root of parameter tree to non-dictionary")
            self.root = value
            return
        *namespaces, leaf = _parts(key)
        tree = self.root
        for part in namespaces:
            child = tree.get(part)
            if type(child) is not dict:
                child = tree[part] = {}
            tree = child
        tree[leaf] = value

    def delete(self, key: str) -> None:
        """Delete the value or namespace at `key`.

        Raises:
            KeyError: nothing is set at `key`, or `key` is the root.
        """
        if key == SEP:
            raise KeyError("cannot delete root of parameter tree")
        *namespaces, leaf = _parts(key)
        tree: Any = self.root
        for part in namespaces:
            if type(tree) is not dict or part not in tree:
                raise KeyError(key)
            tree = tree[part]
        if type(tree) is not dict or leaf not in tree:
            raise KeyError(key)
        del tree[leaf]

    def names(self) -> list[str]:
        """Every parameter's full name (namespaces are not names; empty ones add nothing)."""
        found: list[str] = []
        _collect_names(found, SEP, self.root)
        return found

    def search(self, ns: str, key: str) -> str | None:
        """The key `key` resolves to when searched from `ns` upwards, or ``None``.

        `ns` is where the search starts: rosmaster passes the caller's own name, so a node's
        private namespace is searched first. A global `key` is returned if it is set.

        Raises:
            ValueError: `key` is empty or private, or `ns` is not global.
        """
        if not key or is_private(key):
            raise ValueError("invalid key")
        if not is_global(ns):
            raise ValueError("namespace must be global")
        if is_global(key):
            return key if self.has(key) else None
        first = _parts(key)[0]
        if self.has(ns_join(ns, first)):
            return ns_join(ns, key)
        namespaces = _parts(ns)
        for depth in range(len(namespaces) - 1, -1, -1):
            prefix = namespaces[:depth]
            if self.has(SEP + SEP.join([*prefix, first])):
                return SEP + SEP.join([*prefix, key])
        return None


def _collect_names(found: list[str], ns: str, tree: dict[str, Any]) -> None:
    for name, value in tree.items():
        if type(value) is dict:
            _collect_names(found, ns_join(ns, name), value)
        else:
            found.append(ns_join(ns, name))


def namespace_key(key: str) -> str:
    """`key` as parameter subscriptions store it: canonical, with a trailing ``/``."""
    return key if key == SEP else canonicalize(key) + SEP


def _all_keys(ns: str, value: dict[str, Any], found: list[str]) -> list[str]:
    for name, item in value.items():
        key = ns_join(ns, name) + SEP
        found.append(key)
        if type(item) is dict:
            _all_keys(key, item, found)
    return found


def param_updates(
    subscribers: Mapping[str, Iterable[tuple[str, str]]],
    key: str,
    value: Any,
    ignore_caller: str | None = None,
) -> list[ParamUpdate]:
    """The ``paramUpdate`` calls owed after `key` was set to `value` (or deleted: ``{}``).

    Args:
        subscribers: Subscribed key (with a trailing ``/``) to its ``(caller_id, api)`` pairs.
        key: The global key that changed.
        value: Its new value; ``{}`` for a deletion.
        ignore_caller: The node that made the change: it is not told of its own change to a
            key it subscribed to (it still hears of keys deleted or set below it), as rosmaster.

    Returns:
        One update per subscriber and key, as rosmaster computes them: subscribers of `key` or
        of a namespace above it get `key` (with a trailing ``/``) and `value`; when `value` is
        a namespace, subscribers of keys inside it get their own part of it, and subscribers of
        keys it no longer holds get ``{}``.
    """
    if not subscribers:
        return []
    changed = namespace_key(key)
    inner = _all_keys(changed, value, []) if type(value) is dict else None
    updates: list[ParamUpdate] = []
    for sub_key, nodes in subscribers.items():
        ns_key = sub_key if sub_key.endswith(SEP) else sub_key + SEP
        if changed.startswith(ns_key):
            updates.extend(
                ParamUpdate(api, cid, changed, value) for cid, api in nodes if cid != ignore_caller
            )
        elif inner is not None and ns_key.startswith(changed) and sub_key not in inner:
            updates.extend(ParamUpdate(api, cid, sub_key, {}) for cid, api in nodes)
    for inner_key in inner or ():
        inner_nodes = subscribers.get(inner_key)
        if inner_nodes is not None:
            part: Any = value
            for name in _parts(inner_key[len(changed) :]):
                part = part[name]
            updates.extend(ParamUpdate(api, cid, inner_key, part) for cid, api in inner_nodes)
    return updates
