"""Name resolution as ROS 1's command-line tools do it (rosgraph's ``script_resolve_name``).

Tools such as ``rostopic`` and ``rosparam`` resolve the names a user types against the
namespace the tool runs in (``ROS_NAMESPACE``, or ``__ns:=``), without remapping and without
canonicalising what the user typed: ``/turtle1/pose/`` stays as written. Private names join the
tool's own would-be node name.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rosx.names.resolution import GLOBAL_NS, make_global_ns, ns_join
from rosx.names.validation import is_global, is_private

__all__ = ["ROS_NAMESPACE", "ros_namespace", "script_resolve_name"]

#: The environment variable naming the namespace a program runs in.
ROS_NAMESPACE = "ROS_NAMESPACE"

_NS_ARG = "__ns:="


def ros_namespace(environ: Mapping[str, str], argv: Sequence[str] = ()) -> str:
    """The namespace a program runs in, global with a trailing ``/`` (``/a/b/``).

    A ``__ns:=`` argument wins over ``ROS_NAMESPACE``; neither means the global namespace.

    Args:
        environ: The process environment (``os.environ`` at the entry point).
        argv: The command line, searched for ``__ns:=``.

    Raises:
        ValueError: If the namespace given is a private name.
    """
    for arg in argv:
        if arg.startswith(_NS_ARG):
            return make_global_ns(arg[len(_NS_ARG) :])
    return make_global_ns(environ.get(ROS_NAMESPACE, GLOBAL_NS))


def script_resolve_name(script_name: str, name: str, namespace: str = GLOBAL_NS) -> str:
    """Resolves a name typed on a tool's command line.

    Args:
        script_name: The tool's base name (``rostopic``); private names resolve under it.
        name: The name as typed.
        namespace: The namespace the tool runs in, e.g. from `ros_namespace`.

    Returns:
        ``name`` unchanged if global; the namespace (``/a/``) if empty;
        ``<namespace>/<script_name>/<rest>`` for ``~rest``; ``<namespace>/<name>`` otherwise.
    """
    prefix = make_global_ns(namespace)
    if not name:
        return prefix
    if is_global(name):
        return name
    if is_private(name):
        return ns_join(make_global_ns(ns_join(prefix, script_name)), name[1:])
    return prefix + name
