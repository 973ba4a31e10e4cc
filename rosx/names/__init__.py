"""ROS 1 graph resource names: validation, resolution, remapping arguments, anonymous names.

* `rosx.names.validation`: roscpp's rules and error texts (`validate`, `InvalidNameError`) and
  rosgraph's predicates.
* `rosx.names.resolution`: `resolve` (global, relative, ``~private``, remapped) and the helpers
  it is built from (`canonicalize`, `ns_join`, `namespace_of`, `basename`).
* `rosx.names.script`: how command-line tools resolve what users type (`script_resolve_name`).
* `rosx.names.remap_args`: ``from:=to``, ``__name:=``, ``_param:=`` and friends on a command line.
* `rosx.names.anonymous`: unique names for anonymous nodes.

This layer uses the standard library only and nothing else of rosx.
"""

from __future__ import annotations

from rosx._lazy import lazy_names

TYPE_CHECKING = False
if TYPE_CHECKING:
    from rosx.names.anonymous import anonymous_name, anonymous_node_name, roscpp_anonymous_name
    from rosx.names.remap_args import (
        REMAP,
        RemapArgs,
        is_legal_remap,
        parse_remap_args,
        strip_remap_args,
    )
    from rosx.names.resolution import (
        GLOBAL_NS,
        PRIVATE_PREFIX,
        SEP,
        basename,
        canonicalize,
        make_global_ns,
        namespace_of,
        ns_join,
        resolve,
        resolve_remappings,
    )
    from rosx.names.script import ROS_NAMESPACE, ros_namespace, script_resolve_name
    from rosx.names.validation import (
        InvalidNameError,
        check_name,
        is_global,
        is_legal_base_name,
        is_legal_name,
        is_private,
        validate,
    )

_HOMES = {
    "GLOBAL_NS": "rosx.names.resolution",
    "InvalidNameError": "rosx.names.validation",
    "PRIVATE_PREFIX": "rosx.names.resolution",
    "REMAP": "rosx.names.remap_args",
    "ROS_NAMESPACE": "rosx.names.script",
    "RemapArgs": "rosx.names.remap_args",
    "SEP": "rosx.names.resolution",
    "anonymous_name": "rosx.names.anonymous",
    "anonymous_node_name": "rosx.names.anonymous",
    "roscpp_anonymous_name": "rosx.names.anonymous",
    "basename": "rosx.names.resolution",
    "canonicalize": "rosx.names.resolution",
    "check_name": "rosx.names.validation",
    "is_global": "rosx.names.validation",
    "is_legal_base_name": "rosx.names.validation",
    "is_legal_name": "rosx.names.validation",
    "is_legal_remap": "rosx.names.remap_args",
    "is_private": "rosx.names.validation",
    "make_global_ns": "rosx.names.resolution",
    "namespace_of": "rosx.names.resolution",
    "ns_join": "rosx.names.resolution",
    "parse_remap_args": "rosx.names.remap_args",
    "resolve": "rosx.names.resolution",
    "resolve_remappings": "rosx.names.resolution",
    "ros_namespace": "rosx.names.script",
    "script_resolve_name": "rosx.names.script",
    "strip_remap_args": "rosx.names.remap_args",
    "validate": "rosx.names.validation",
}


# Loaded on first use, so a tool needing one helper does not import the whole layer.
__getattr__ = lazy_names(__name__, _HOMES)


__all__ = [
    "GLOBAL_NS",
    "PRIVATE_PREFIX",
    "REMAP",
    "ROS_NAMESPACE",
    "SEP",
    "InvalidNameError",
    "RemapArgs",
    "anonymous_name",
    "anonymous_node_name",
    "basename",
    "canonicalize",
    "check_name",
    "is_global",
    "is_legal_base_name",
    "is_legal_name",
    "is_legal_remap",
    "is_private",
    "make_global_ns",
    "namespace_of",
    "ns_join",
    "parse_remap_args",
    "resolve",
    "resolve_remappings",
    "ros_namespace",
    "roscpp_anonymous_name",
    "script_resolve_name",
    "strip_remap_args",
    "validate",
]
