"""A program in a tmux window of a given size, as a user sees it: what the screen shows, keys
typed, and whether the program has ended. Tests skip where tmux is not installed."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path
from types import TracebackType

import pytest

from tests.support.cli import clean_environ

ROOT = Path(__file__).parents[2]


def needs_tmux() -> str:
    """tmux's path; skips the test where there is none."""
    path = shutil.which("tmux")
    if path is None:
        pytest.skip("tmux is not installed")
    return path


class Tmux:
    """``rosx ARGV…`` alone in a detached tmux session of ``size`` (columns, rows), on a tmux
    server of its own (a socket in ``folder``), stopped on exit."""

    def __init__(self, folder: Path, size: tuple[int, int], argv: list[str], **extra: str):
        self.tmux = needs_tmux()
        self.socket = str(folder / "tmux.sock")
        environ = clean_environ(TERM="xterm-256color", COLORTERM="truecolor", **extra)
        # textual takes COLUMNS and LINES over the terminal's size; pytest's process may have
        # them, and the tmux server hands its own environment to the program.
        for sized in ("COLUMNS", "LINES"):
            environ.pop(sized, None)
        self._server_environ = {
            k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")
        }
        environ["PYTHONPATH"] = os.pathsep.join(str(ROOT / p) for p in (".", "commands", "turtle"))
        command = [sys.executable, "-c", "from rosx_commands.main import run; run()", *argv]
        columns, rows = size
        self._run(
            "-f", "/dev/null", "new-session", "-d", "-x", str(columns), "-y", str(rows),
            *(arg for key, value in environ.items() for arg in ("-e", f"{key}={value}")),
            " ".join(_quote(part) for part in command),
        )  # fmt: skip
        self._run("set-option", "-g", "remain-on-exit", "on")

    def _run(self, *args: str) -> str:
        done = subprocess.run(
            [self.tmux, "-S", self.socket, *args],
            capture_output=True,
            text=True,
            check=False,
            timeout=10,
            env=self._server_environ,
        )
        return done.stdout

    def screen(self) -> list[str]:
        """The window's rows as text."""
        return self._run("capture-pane", "-p").splitlines()

    def wait_for(self, text: str, timeout: float = 30.0) -> list[str]:
        """The screen once it shows ``text``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            rows = self.screen()
            if any(text in row for row in rows):
                return rows
            time.sleep(0.1)
        raise AssertionError(f"{text!r} never showed; the screen:\n" + "\n".join(self.screen()))

    def keys(self, *keys: str) -> None:
        self._run("send-keys", *keys)

    def ended(self, timeout: float = 15.0) -> bool:
        """Whether the program ends within ``timeout`` seconds."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self._run("display-message", "-p", "#{pane_dead}").strip() == "1":
                return True
            time.sleep(0.1)
        return False

    def __enter__(self) -> Tmux:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        pid = self._run("display-message", "-p", "#{pane_pid}").strip()
        if pid.isdigit() and self._run("display-message", "-p", "#{pane_dead}").strip() != "1":
            self.keys("C-c")
            self.ended(10.0)
        self._run("kill-server")


def _quote(text: str) -> str:
    return "'" + text.replace("'", "'\\''") + "'"
