"""The terminal as turtle_teleop_key uses it: one key byte at a time, no echo, Ctrl-C alive.

`RawKeys` puts a terminal in non-canonical mode with echo off (``ICANON`` and ``ECHO`` cleared,
``VEOL`` = 1 and ``VEOF`` = 2, ``ISIG`` left on so that Ctrl-C still raises SIGINT), exactly as
the teleop does, and puts the saved settings back when the block ends, however it ends. On a
file descriptor that is not a terminal it changes nothing and just reads. Windows has no termios:
there the terminal is left as it is (keys arrive when Enter is pressed), as for a non-terminal.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING, Any

if sys.platform != "win32":
    import termios

if TYPE_CHECKING:
    from types import TracebackType


class RawKeys:
    """``with RawKeys(fd) as keys: keys.read()`` reads one byte per call (b"" at end of input)."""

    def __init__(self, fd: int) -> None:
        self.fd = fd
        self.saved: list[Any] | None = None

    def __enter__(self) -> RawKeys:
        if sys.platform == "win32":
            return self
        try:
            self.saved = termios.tcgetattr(self.fd)
        except termios.error:  # not a terminal: nothing to set or restore
            return self
        raw = [*self.saved[:6], list(self.saved[6])]
        raw[3] &= ~(termios.ICANON | termios.ECHO)
        raw[6][termios.VEOL] = 1
        raw[6][termios.VEOF] = 2
        termios.tcsetattr(self.fd, termios.TCSANOW, raw)
        return self

    def read(self) -> bytes:
        """The next byte, waiting for it.

        Raises:
            OSError: the read failed (as ``read(2)`` reports it).
        """
        return os.read(self.fd, 1)

    def restore(self) -> None:
        """Put the terminal back as it was (idempotent)."""
        if self.saved is not None and sys.platform != "win32":
            termios.tcsetattr(self.fd, termios.TCSANOW, self.saved)
            self.saved = None

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.restore()
