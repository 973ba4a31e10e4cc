"""``rosgraph.names``: ROS 1's name helpers with rosgraph's signatures, over `rosx.names`.

``resolve_name(name, namespace_, remappings)`` takes the caller's name as ``namespace_`` and
remappings already resolved, as rosgraph's does; ``script_resolve_name`` and
``get_ros_namespace`` read ``ROS_NAMESPACE`` (and ``__ns:=``) as the command-line tools do.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING

from rosx.names import (
    REMAP,
    SEP,
    canonicalize,
    is_global,
    is_legal_base_name,
    is_legal_name,
    is_legal_remap,
    is_private,
    make_global_ns,
    namespace_of,
    ns_join,
    parse_remap_args,
    resolve,
    ros_namespace,
)
from rosx.names import (
    anonymous_name as _anonymous_name,
)

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

GLOBALNS = "/"
PRIV_NAME = "~"
ANYTYPE = "*"
MSG_EXT = ".msg"
SRV_EXT = ".srv"
ROS_NAMESPACE = "ROS_NAMESPACE"


def get_ros_namespace(
    env: Mapping[str, str] | None = None, argv: Sequence[str] | None = None
) -> str:
    """The namespace of ``__ns:=`` in ``argv``, else of ``ROS_NAMESPACE``, global with ``/``."""
    return ros_namespace(os.environ if env is None else env, sys.argv if argv is None else argv)


def make_caller_id(name: str) -> str:
    """``name`` in the program's namespace, global, with a trailing ``/``."""
    return make_global_ns(ns_join(get_ros_namespace(), name))


def namespace(name: str) -> str:
    """The namespace holding ``name``, with a trailing ``/``."""
    return namespace_of(name)


def canonicalize_name(name: str) -> str:
    """``name`` without repeated or trailing ``/``."""
    return canonicalize(name)


def load_mappings(argv: Sequence[str]) -> dict[str, str]:
    """The remappings of a command line as written, ``_param:=`` assignments left out."""
    args = parse_remap_args(argv)
    return {**args.remappings, **args.special}


def resolve_name(name: str, namespace_: str, remappings: Mapping[str, str] | None = None) -> str:
    """``name`` resolved for the caller ``namespace_``, then looked up in ``remappings``."""
    resolved = resolve(name, namespace_of(namespace_), namespace_, strict=False)
    return remappings.get(resolved, resolved) if remappings else resolved


def script_resolve_name(script_name: str, name: str) -> str:
    """A name typed on a tool's command line, resolved in ``ROS_NAMESPACE`` (no remapping)."""
    if not name:
        return get_ros_namespace()
    if is_global(name):
        return name
    if is_private(name):
        return ns_join(make_caller_id(script_name), name[1:])
    return get_ros_namespace() + name


def anonymous_name(id: str) -> str:
    """``id_<host>_<pid>_<random>``, with ``.``, ``-`` and ``:`` made ``_``."""
    return _anonymous_name(id)


__all__ = [
    "ANYTYPE",
    "GLOBALNS",
    "MSG_EXT",
    "PRIV_NAME",
    "REMAP",
    "ROS_NAMESPACE",
    "SEP",
    "SRV_EXT",
    "anonymous_name",
    "canonicalize_name",
    "get_ros_namespace",
    "is_global",
    "is_legal_base_name",
    "is_legal_name",
    "is_legal_remap",
    "is_private",
    "load_mappings",
    "make_caller_id",
    "make_global_ns",
    "namespace",
    "ns_join",
    "resolve_name",
    "script_resolve_name",
]
