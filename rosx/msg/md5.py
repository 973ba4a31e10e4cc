r"""MD5 sums and full definitions of message and service types, computed as ROS 1 does.

The md5 text of a message (genmsg's rules): constants first as ``type NAME=value`` (value as
written), then fields, a built-in as ``type name`` with its array suffix, a message field as
``<md5 of its type> name`` with no suffix; lines joined by ``\n``. A service's sum hashes the
request text followed by the response text. The full definition (``message_definition`` in
connection headers) is the type's own text, then each dependency once, depth first in field
order, after a line of 80 ``=`` and ``MSG: pkg/Type``.
"""

from __future__ import annotations

from collections.abc import Callable

from rosx.msg.spec import MsgSpec, SrvSpec

Lookup = Callable[[str], MsgSpec]

_SEPARATOR = "=" * 80


def md5_text(spec: MsgSpec, lookup: Lookup, md5_of: Callable[[str], str] | None = None) -> str:
    """The text genmsg hashes for ``spec``; nested sums come from ``md5_of`` (or are computed)."""
    nested = md5_of or (lambda name: message_md5(lookup(name), lookup))
    lines = [f"{c.type} {c.name}={c.text}" for c in spec.constants]
    for field in spec.fields:
        if field.is_builtin:
            lines.append(f"{field.type} {field.name}")
        else:
            lines.append(f"{nested(field.base_type)} {field.name}")
    return "\n".join(lines)


def message_md5(spec: MsgSpec, lookup: Lookup, md5_of: Callable[[str], str] | None = None) -> str:
    """The md5 sum of message type ``spec``, as ROS 1 computes it."""
    import hashlib  # noqa: PLC0415 - loads OpenSSL (2 ms), which rosmsg show does not need

    return hashlib.md5(md5_text(spec, lookup, md5_of).encode()).hexdigest()


def service_md5(spec: SrvSpec, lookup: Lookup, md5_of: Callable[[str], str] | None = None) -> str:
    """The md5 sum of service type ``spec`` (its request's text, then its response's)."""
    import hashlib  # noqa: PLC0415 - hashlib is not needed at start-up

    digest = hashlib.md5(md5_text(spec.request, lookup, md5_of).encode())
    digest.update(md5_text(spec.response, lookup, md5_of).encode())
    return digest.hexdigest()


def dependencies(spec: MsgSpec, lookup: Lookup) -> list[str]:
    """Every message type ``spec`` embeds, once each, depth first in field order."""
    seen: list[str] = []

    def visit(current: MsgSpec) -> None:
        for field in current.fields:
            if field.is_builtin:
                continue
            name = field.base_type
            if name in seen:
                continue  # its own dependencies were listed when it was first seen
            seen.append(name)
            visit(lookup(name))

    visit(spec)
    return seen


def full_text(spec: MsgSpec, lookup: Lookup) -> str:
    """The ``message_definition`` text of ``spec``."""
    parts = [spec.text, "\n"]
    for name in dependencies(spec, lookup):
        parts += [_SEPARATOR, "\n", f"MSG: {name}\n", lookup(name).text, "\n"]
    return "".join(parts)[:-1]
