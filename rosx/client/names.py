"""``rospy.names``: the node's names and the command line's remappings, as rospy exposes them.

What scripts call: `get_caller_id` (also `get_name`), `get_namespace`, `resolve_name`,
`remap_name`, `get_mappings` and `get_resolved_mappings`, and rosgraph's helpers rospy
re-exports (`ns_join`, `namespace`, `canonicalize_name`, `is_global`…). The rules are rospy's:

* before `init_node` the caller is ``<namespace>unnamed`` and nothing is resolved against the
  remappings (`get_resolved_mappings` is empty);
* `resolve_name` resolves ``~x`` under the caller, relative names in its namespace, the empty
  name to the namespace itself, then applies the resolved remappings;
* `remap_name` changes only a name written exactly as a remapping's left side, resolving the
  right side against the caller.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING

from rosx.client import state
from rosx.names import (
    REMAP,
    SEP,
    canonicalize,
    is_global,
    is_private,
    make_global_ns,
    namespace_of,
    ns_join,
    resolve,
    ros_namespace,
)

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

GLOBALNS = "/"
#: The type of a topic or service subscribed or called without one (``AnyMsg``, probes).
ANYTYPE = TOPIC_ANYTYPE = SERVICE_ANYTYPE = "*"


def get_caller_id() -> str:
    """The node's global name; ``<namespace>unnamed`` before `init_node`."""
    return state.CLIENT.caller_id()


get_name = get_caller_id


def _set_caller_id(caller_id: str) -> None:
    """Resolve names and ask the Parameter Server as ``caller_id`` from now on (rospy's
    private hook; the node's own name and registrations do not change). The node's own name
    again puts things back."""
    client = state.CLIENT
    own = client.node.name if client.node is not None else None
    client.caller_override = None if caller_id == own else caller_id


def get_namespace() -> str:
    """The node's namespace, with a trailing ``/``."""
    return state.CLIENT.namespace()


def get_ros_namespace(
    env: Mapping[str, str] | None = None, argv: Sequence[str] | None = None
) -> str:
    """The namespace of ``__ns:=`` in ``argv``, else of ``ROS_NAMESPACE``, global with ``/``."""
    return ros_namespace(os.environ if env is None else env, sys.argv if argv is None else argv)


def get_mappings() -> dict[str, str]:
    """The command line's remappings as written (``__name`` settings included, ``_param`` not)."""
    args = state.CLIENT.args
    return {**args.remappings, **args.special}


def get_resolved_mappings() -> dict[str, str]:
    """The remappings resolved against the node; empty before `init_node`."""
    node = state.CLIENT.node
    if node is None:
        return {}
    return {**node.remappings, **state.CLIENT.args.special}


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """``name`` in global, canonical form, remapped as the node remaps it."""
    return state.CLIENT.resolve_name(name, caller_id)


def resolve_name_without_node_name(name: str) -> str:
    """A topic or service name resolved before `init_node` (``~names`` are refused)."""
    return state.CLIENT.resolve_graph_name(name)


def remap_name(name: str, caller_id: str | None = None, resolved: bool = True) -> str:
    """``name``'s remapping, resolved against the caller; ``name`` itself when none maps it."""
    target = get_mappings().get(name)
    if target is None:
        return name
    caller = caller_id or get_caller_id()
    return resolve(target, namespace_of(caller), caller, strict=False)


def namespace(name: str) -> str:
    """The namespace holding ``name``, with a trailing ``/``."""
    return namespace_of(name)


def canonicalize_name(name: str) -> str:
    """``name`` without repeated or trailing ``/``."""
    return canonicalize(name)


def scoped_name(caller_id: str, name: str) -> str:
    """``name`` relative to the caller's namespace (``/a/node``, ``/a/b/c`` give ``b/c``).

    Raises:
        ROSException: ``caller_id`` is not global.
    """
    if not is_global(caller_id):
        from rosx.client.exceptions import ROSException  # noqa: PLC0415 - the rospy API loads only when used

        raise ROSException("caller_id must be global")
    return canonicalize(name)[len(namespace_of(caller_id)) :]


__all__ = [
    "ANYTYPE",
    "GLOBALNS",
    "REMAP",
    "SEP",
    "SERVICE_ANYTYPE",
    "TOPIC_ANYTYPE",
    "canonicalize_name",
    "get_caller_id",
    "get_mappings",
    "get_name",
    "get_namespace",
    "get_resolved_mappings",
    "get_ros_namespace",
    "is_global",
    "is_private",
    "make_global_ns",
    "namespace",
    "ns_join",
    "remap_name",
    "resolve_name",
    "resolve_name_without_node_name",
    "scoped_name",
]
