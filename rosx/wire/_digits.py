"""`is_ascii_number`: the test for a port, a length or a status code read from a peer.

``str.isdigit`` also accepts ``²`` (refused by ``int``) and Arabic-Indic digits (read by it);
the protocols' numbers are ASCII digits only, as ``urllib.parse`` requires of a port.
"""

from __future__ import annotations


def is_ascii_number(text: str) -> bool:
    """Whether ``text`` is one or more ASCII digits (``0``-``9``), nothing else."""
    return text.isascii() and text.isdigit()
