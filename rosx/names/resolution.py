"""Resolution of ROS 1 graph resource names to their global, canonical form.

The rules (ROS wiki *Names*, as rospy, rosgraph and roscpp apply them):

* ``/a/b`` is global and stays as it is;
* ``a/b`` is relative and joins the node's namespace;
* ``~a`` is private and joins the node's own name;
* the result is canonical: ``//`` collapses to ``/`` and a trailing ``/`` goes;
* the empty name stands for the namespace itself, returned as rosgraph does, with a trailing
  ``/`` (``/a/b/``);
* remappings (``from:=to``) are matched against the *resolved* name. Both sides of a remapping
  are first resolved like any other name of the node, so ``chatter:=talk`` in namespace ``/a``
  maps ``/a/chatter`` to ``/a/talk``, and ``~x:=y`` maps the node's private ``x``.
"""

from __future__ import annotations

from collections.abc import Mapping

from rosx.names.validation import check_name, is_global, is_private

__all__ = [
    "GLOBAL_NS",
    "PRIVATE_PREFIX",
    "SEP",
    "basename",
    "canonicalize",
    "make_global_ns",
    "namespace_of",
    "ns_join",
    "resolve",
    "resolve_remappings",
]

SEP = "/"
GLOBAL_NS = "/"
PRIVATE_PREFIX = "~"


def canonicalize(name: str) -> str:
    """Collapses repeated ``/`` and drops a trailing ``/``; ``/`` and ``""`` stay as they are.

    Examples: ``/a//b/`` gives ``/a/b``; ``a/b/`` gives ``a/b``; ``~x/`` gives ``~x``.
    """
    if not name or name == SEP:
        return name
    joined = SEP.join(part for part in name.split(SEP) if part)
    return SEP + joined if name.startswith(SEP) else joined


def ns_join(ns: str, name: str) -> str:
    """Joins a namespace and a name, rosgraph's way.

    Global and private names cannot be joined and come back unchanged. A namespace of ``~``
    makes the name private; an empty namespace leaves it alone. No canonicalisation happens.
    """
    if is_private(name) or is_global(name):
        return name
    if ns == PRIVATE_PREFIX:
        return PRIVATE_PREFIX + name
    if not ns:
        return name
    if ns.endswith(SEP):
        return ns + name
    return ns + SEP + name


def namespace_of(name: str) -> str:
    """The namespace holding ``name``, with a trailing ``/`` (rosgraph's ``namespace``).

    ``/wg/node1`` gives ``/wg/``; ``/wg/`` gives ``/``; a relative ``node1`` and the empty name
    give ``/``.
    """
    if not name:
        return GLOBAL_NS
    trimmed = name[:-1] if name.endswith(SEP) else name
    return trimmed[: trimmed.rfind(SEP) + 1] or GLOBAL_NS


def basename(name: str) -> str:
    """The last element of ``name``: ``/a/b`` and ``/a/b/`` give ``b``; ``~x`` gives ``x``."""
    trimmed = name.rstrip(SEP)
    last = trimmed[trimmed.rfind(SEP) + 1 :]
    return last.removeprefix(PRIVATE_PREFIX)


def make_global_ns(name: str) -> str:
    """Turns a namespace into global form with a trailing ``/``: ``a`` gives ``/a/``.

    Raises:
        ValueError: If ``name`` is private; a private name has no global namespace form.
    """
    if is_private(name):
        raise ValueError(f"cannot turn [{name}] into a global name")
    if not is_global(name):
        name = SEP + name
    if not name.endswith(SEP):
        name += SEP
    return name


def _namespace_prefix(namespace: str) -> str:
    return make_global_ns(canonicalize(namespace))


def _node_full_name(node_name: str, prefix: str) -> str:
    # A base name such as "talker" belongs to the namespace being resolved in; a global one
    # already says where the node lives.
    return canonicalize(node_name if is_global(node_name) else prefix + node_name)


def _resolve_unmapped(name: str, prefix: str, node_name: str | None) -> str:
    if not name:
        return prefix
    name = canonicalize(name)
    if is_global(name):
        return name
    if is_private(name):
        if node_name is None:
            raise ValueError(f"cannot resolve the private name [{name}] without a node name")
        # Joined with an explicit separator so that "~/x" stays inside the node (ROS 1 #3044).
        return canonicalize(_node_full_name(node_name, prefix) + SEP + name[1:])
    return canonicalize(prefix + name)


def resolve_remappings(
    remappings: Mapping[str, str],
    namespace: str,
    node_name: str | None = None,
    *,
    strict: bool = True,
) -> dict[str, str]:
    """Resolves both sides of each remapping against the node, as ROS 1 does at node start.

    Keys starting with ``_`` are skipped: ``__name``-style settings and ``_param`` private
    parameters are not name remappings. Entries with an empty side are skipped too.
    Already-resolved remappings come back unchanged, so resolving twice is harmless.

    Args:
        remappings: ``from`` → ``to`` as written on the command line.
        namespace: The node's namespace (``/``, ``/a/b``).
        node_name: The node's name, global or relative to ``namespace``; needed only for
            ``~private`` entries.
        strict: Validate both sides first (roscpp refuses invalid remappings).

    Returns:
        Resolved ``from`` → resolved ``to``.

    Raises:
        InvalidNameError: If ``strict`` and a side is not a valid name.
        ValueError: If an entry is private and ``node_name`` is None.
    """
    prefix = _namespace_prefix(namespace)
    resolved: dict[str, str] = {}
    for source, target in remappings.items():
        if not source or not target or source.startswith("_"):
            continue
        if strict:
            check_name(source)
            check_name(target)
        resolved[_resolve_unmapped(source, prefix, node_name)] = _resolve_unmapped(
            target, prefix, node_name
        )
    return resolved


def resolve(
    name: str,
    namespace: str,
    node_name: str | None = None,
    remappings: Mapping[str, str] | None = None,
    *,
    strict: bool = True,
) -> str:
    """Resolves ``name`` to its global, canonical form, then applies remappings.

    Args:
        name: The name as written: ``/global``, ``relative``, ``~private`` or empty.
        namespace: The node's namespace (``/``, ``/a/b``; a trailing ``/`` is fine).
        node_name: The node's name, global (``/a/b/talker``) or relative to ``namespace``
            (``talker``); needed only for ``~private`` names.
        remappings: ``from`` → ``to`` remappings, raw (as on the command line) or already
            resolved by `resolve_remappings`.
        strict: Validate ``name`` first, as roscpp does; rospy and the command-line tools do not.

    Returns:
        The resolved name, e.g. ``/a/b/chatter``. The empty name gives the namespace with a
        trailing ``/``.

    Raises:
        InvalidNameError: If ``strict`` and the name (or a remapping) is not a valid name.
        ValueError: If a private name must be resolved and ``node_name`` is None.
    """
    if strict:
        check_name(name)
    prefix = _namespace_prefix(namespace)
    resolved = _resolve_unmapped(name, prefix, node_name)
    if not name or not remappings:
        return resolved
    table = resolve_remappings(remappings, namespace, node_name, strict=strict)
    return table.get(resolved, resolved)
