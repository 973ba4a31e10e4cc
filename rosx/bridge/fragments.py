"""rosbridge's ``fragment`` op: a long message cut into pieces of its JSON text, both ways.

A fragment is ``{"op": "fragment", "id", "data", "num", "total"}``; the ``data`` of fragments
``0 … total-1`` of one ``id``, joined, is the message's text (ROSBRIDGE_PROTOCOL.md, 3.1.1).
Reassembly is bounded: at most `MAX_PENDING` messages in pieces at once, and no more text
than the session's message limit in each.
"""

from __future__ import annotations

import json
from collections.abc import Iterator

#: Messages a client may have in pieces at once; a new one beyond pushes out the oldest.
MAX_PENDING = 16


class FragmentError(ValueError):
    """A fragment that does not fit its message (the text is the status)."""


def fragment_frames(text: str, size: int, mid: object) -> Iterator[str]:
    """The ``fragment`` frames of ``text`` in pieces of at most ``size`` characters."""
    total = (len(text) + size - 1) // size
    for num in range(total):
        piece = text[num * size : (num + 1) * size]
        yield json.dumps({"op": "fragment", "id": mid, "data": piece, "num": num, "total": total})


class _Pieces:
    __slots__ = ("parts", "size", "total")

    def __init__(self, total: int) -> None:
        self.total = total
        self.parts: dict[int, str] = {}
        self.size = 0


class Reassembly:
    """Collects one client's fragments; `add` gives the whole text when the last comes."""

    def __init__(self, max_message: int) -> None:
        self.max_message = max_message
        self._pending: dict[object, _Pieces] = {}

    def add(self, mid: object, num: int, total: int, data: str) -> str | None:
        """Add fragment ``num`` of ``total`` of message ``mid``.

        Raises:
            FragmentError: ``num``/``total`` out of range or disagreeing, or too much text.
        """
        if total < 1 or not 0 <= num < total:
            raise FragmentError(f"fragment {num} of {total} of message {mid} is out of range")
        if total > self.max_message:  # a fragment holds a character at least
            raise FragmentError(
                f"message {mid} in {total} fragments exceeds the limit of {self.max_message} "
                "bytes: it is dropped"
            )
        pieces = self._pending.get(mid)
        if pieces is None:
            if len(self._pending) >= MAX_PENDING:
                del self._pending[next(iter(self._pending))]
            pieces = self._pending[mid] = _Pieces(total)
        elif pieces.total != total:
            del self._pending[mid]
            raise FragmentError(
                f"fragment {num} of message {mid} says {total} fragments, earlier ones "
                f"{pieces.total}: the message is dropped"
            )
        if num not in pieces.parts:
            pieces.size += len(data)
        pieces.parts[num] = data
        if pieces.size > self.max_message:
            del self._pending[mid]
            raise FragmentError(
                f"message {mid} in fragments exceeds the limit of {self.max_message} bytes: "
                "it is dropped"
            )
        if len(pieces.parts) < total:
            return None
        del self._pending[mid]
        return "".join(pieces.parts[i] for i in range(total))


__all__ = ["MAX_PENDING", "FragmentError", "Reassembly", "fragment_frames"]
