"""Message classes for a bag's connections, from the type store or from the bag itself.

A connection records its type's full definition (the ``.msg`` text, then each embedded type's
after a line of ``=`` and ``MSG: pkg/Type``). `message_class` gives the class of a connection:
the store's when it knows the type with the recorded md5sum, otherwise one built from the
recorded definition, so bags of types this machine does not have (or has in another version)
still decode, as genpy's dynamic classes let ROS 1's rosbag do.
"""

from __future__ import annotations

import re
import threading
from typing import TYPE_CHECKING

from rosx.msg.store import TypeStore, default_store

if TYPE_CHECKING:
    from rosx.bag.reader import Connection
    from rosx.msg.codec.message import Message

_SEPARATOR = re.compile(r"^=+\s*\nMSG: *(\S+)\s*\n", re.MULTILINE)


def split_definition(msg_type: str, definition: str) -> dict[str, str]:
    """Type name → ``.msg`` text, for a full definition as a connection header carries it."""
    parts = _SEPARATOR.split(definition)
    texts = {msg_type: parts[0]}
    for name, text in zip(parts[1::2], parts[2::2], strict=False):
        texts[name] = text
    return texts


class DefinitionStore(TypeStore):
    """A type store that knows the types of one recorded definition first."""

    def __init__(self, texts: dict[str, str]) -> None:
        super().__init__([])
        self._texts = texts

    def _msg_text(self, full_name: str) -> str | None:
        text = self._texts.get(full_name)
        if text is None and "/" not in full_name:
            return None
        return text if text is not None else super()._msg_text(full_name)


_lock = threading.Lock()
_classes: dict[tuple[str, str], type[Message]] = {}


def message_class(conn: Connection, store: TypeStore | None = None) -> type[Message]:
    """The class to decode ``conn``'s messages with (see the module's docstring).

    Raises:
        Exception: neither the store nor the recorded definition gives the type.
    """
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    key = (conn.type, conn.md5sum)
    with _lock:
        cls = _classes.get(key)
    if cls is not None:
        return cls
    try:
        cls = get_message_class(conn.type, store or default_store())
        if conn.md5sum not in (cls._md5sum, "*", ""):
            cls = None
    except Exception:
        cls = None
    if cls is None:
        recorded = DefinitionStore(split_definition(conn.type, conn.message_definition))
        cls = get_message_class(conn.type, recorded)
    with _lock:
        _classes[key] = cls
    return cls


__all__ = ["DefinitionStore", "message_class", "split_definition"]
