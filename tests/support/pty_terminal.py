"""A program run on a pseudo-terminal, as a user runs it (stdout a terminal), for tests."""

from __future__ import annotations

import contextlib
import fcntl
import os
import pty
import select
import struct
import subprocess
import termios
import time
from collections.abc import Iterator

from tests.support.cli import clean_environ
from tests.support.procs import stop

#: The pond's background colour as a true-colour background escape.
BLUE_BACKGROUND = b"48;2;69;86;255m"


class Terminal:
    """A program on a pseudo-terminal of 100x30 cells; what it drew is in ``output``."""

    def __init__(self, args: list[str], environ: dict[str, str]) -> None:
        self.main, child = pty.openpty()
        fcntl.ioctl(child, termios.TIOCSWINSZ, struct.pack("HHHH", 30, 100, 0, 0))
        self.process = subprocess.Popen(
            args, stdin=child, stdout=child, stderr=child, env=environ, start_new_session=True
        )
        os.close(child)
        self.output = b""

    def read(self, seconds: float, until: bytes | None = None) -> None:
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline and not (until and until in self.output):
            ready, _, _ = select.select([self.main], [], [], 0.05)
            if ready:
                try:
                    self.output += os.read(self.main, 1 << 16)
                except OSError:  # the program closed the terminal
                    return

    def type(self, keys: bytes) -> None:
        os.write(self.main, keys)

    def wait(self, seconds: float) -> int | None:
        """The exit status, reading what the program draws meanwhile (it must not block)."""
        deadline = time.monotonic() + seconds
        while self.process.poll() is None and time.monotonic() < deadline:
            self.read(0.1)
        self.read(0.2)
        return self.process.poll()

    def close(self) -> None:
        stop(self.process)
        with contextlib.suppress(OSError):
            os.close(self.main)


@contextlib.contextmanager
def on_a_terminal(args: list[str], **extra: str) -> Iterator[Terminal]:
    """Run ``args`` on a 100x30 pseudo-terminal with a clean ROS environment plus ``extra``."""
    environ = clean_environ(TERM="xterm-256color", COLORTERM="truecolor", **extra)
    environ["PYTHONPATH"] = os.pathsep.join([".", "commands", "turtle"])
    terminal = Terminal(args, environ)
    try:
        yield terminal
    finally:
        terminal.close()
