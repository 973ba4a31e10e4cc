"""Ways to cut a byte string into the pieces a socket might deliver.

Every wire fixture is fed whole, one byte at a time and in uneven pieces; `CHUNKINGS` names
them for ``pytest.mark.parametrize``.
"""

from __future__ import annotations

CHUNKINGS = ("whole", "bytewise", "uneven")


def pieces(data: bytes, how: str) -> list[bytes]:
    """`data` cut as `how` says: in one piece, byte by byte, or in growing uneven pieces."""
    if how == "whole":
        return [data]
    if how == "bytewise":
        return [data[i : i + 1] for i in range(len(data))]
    if how == "uneven":
        out: list[bytes] = []
        pos, size = 0, 1
        while pos < len(data):
            out.append(data[pos : pos + size])
            pos += size
            size = size * 2 + 1 if size < 4096 else 3
        return out
    raise ValueError(how)
