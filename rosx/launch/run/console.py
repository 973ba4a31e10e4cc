"""roslaunch's console: plain, bold and red lines, the terminal title, and the launcher's log.

ROS 1's roslaunch prints progress lines (``printlog``), bold ones (``printlog_bold``: process
starts, ``ROS_MASTER_URI=…``, ``done``) and errors in red on stderr (``printerrlog``), and copies
each into its log file ``roslaunch-<host>-<pid>.log``. rosx prints the same words; bold, red and
the terminal title only reach a terminal, so the text piped or captured is ROS 1's text without
escape codes. The log file gets ``[roslaunch][LEVEL] date time,ms: text`` lines, as rosgraph's
logging configuration writes them.
"""

from __future__ import annotations

import threading
import time
import traceback
from typing import TYPE_CHECKING

from rosx.terminal import is_terminal

if TYPE_CHECKING:
    from pathlib import Path
    from typing import TextIO


class LaunchConsole:
    """Where roslaunch's lines go; safe to use from several threads."""

    def __init__(
        self,
        stdout: TextIO,
        stderr: TextIO,
        *,
        color: bool | None = None,
        titles: bool = True,
    ) -> None:
        self.stdout = stdout
        self.stderr = stderr
        self.bold_out = is_terminal(stdout) if color is None else color
        self.red_err = is_terminal(stderr) if color is None else color
        self.titles = titles and self.bold_out
        self._log: TextIO | None = None
        self._lock = threading.Lock()

    def open_log(self, path: Path) -> bool:
        """Copy every line to the launcher's log file ``path`` from now on; False if it cannot
        be opened (the lines still reach the console)."""
        try:
            self._log = path.open("a", encoding="utf-8")
        except OSError:
            return False
        return True

    @property
    def logging(self) -> bool:
        """Whether lines are copied to the launcher's log file."""
        return self._log is not None

    def log_traceback(self) -> None:
        """The traceback of the exception being handled, to the log file alone (roslaunch's
        ``The traceback for the exception was written to the log file``)."""
        with self._lock:
            self._record("ERROR", traceback.format_exc().rstrip("\n"))

    def close(self) -> None:
        """Close the log file."""
        with self._lock:
            if self._log is not None:
                self._log.close()
                self._log = None

    def _record(self, level: str, text: str) -> None:
        if self._log is None:
            return
        now = time.time()
        stamp = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(now))
        millis = int(now * 1000) % 1000
        try:
            self._log.write(f"[roslaunch][{level}] {stamp},{millis:03d}: {text}\n")
            self._log.flush()
        except (OSError, ValueError):
            self._log = None

    def _write(self, stream: TextIO, text: str) -> None:
        try:
            stream.write(text + "\n")
            stream.flush()
        except (OSError, ValueError):
            pass  # a closed terminal must not stop the launch from shutting its nodes down

    def line(self, text: str = "") -> None:
        """A progress line on stdout (``printlog``)."""
        with self._lock:
            self._record("INFO", text)
            self._write(self.stdout, text)

    def plain(self, text: str = "") -> None:
        """A line on stdout that is not copied to the log."""
        with self._lock:
            self._write(self.stdout, text)

    def block(self, text: str) -> None:
        """Text on stdout as it is, its own newlines included (the SUMMARY)."""
        with self._lock:
            self._write(self.stdout, text.removesuffix("\n"))

    def bold(self, text: str) -> None:
        """A bold line on stdout (``printlog_bold``)."""
        with self._lock:
            self._record("INFO", text)
            self._write(self.stdout, f"\033[1m{text}\033[0m" if self.bold_out else text)

    def error(self, text: str) -> None:
        """A red line on stderr (``printerrlog``)."""
        with self._lock:
            self._record("ERROR", text)
            self._write(self.stderr, f"\033[31m{text}\033[0m" if self.red_err else text)

    def title(self, text: str) -> None:
        """Set the terminal's title, when stdout is a terminal and titles are wanted."""
        if self.titles:
            with self._lock:
                self._write(self.stdout, f"\033]2;{text}\007")


__all__ = ["LaunchConsole"]
