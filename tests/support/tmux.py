"""A program in a tmux window of a given size, as a user sees it: what the screen shows (text,
and the colours of each cell), keys typed, and whether the program has ended. Tests skip
where tmux is not installed."""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import signal
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from types import TracebackType
from typing import NamedTuple

import pytest

from rosx.workspace.path_commands import HINTED
from tests.support.cli import ROSX_COMMAND, clean_environ

ROOT = Path(__file__).parents[2]


#: How a program's first screen may take to come on a loaded machine (seconds).
STARTUP = 60.0


def needs_tmux() -> str:
    """tmux's path; skips the test where there is none."""
    path = shutil.which("tmux")
    if path is None:
        pytest.skip("tmux is not installed")
    return path


#: A colour as the terminal is told it (``"69;86;255"``: 24-bit RGB), None for the default.
Colour = str | None


class Cell(NamedTuple):
    """One cell of the screen: its character and its colours."""

    char: str
    fg: Colour
    bg: Colour


class Tmux:
    """``rosx ARGV…`` alone in a detached tmux session of ``size`` (columns, rows), on a tmux
    server of its own (a socket in ``folder``), stopped on exit."""

    def __init__(
        self,
        folder: Path,
        size: tuple[int, int],
        argv: list[str],
        *,
        first_run: bool = False,
        **extra: str,
    ):
        self.tmux = needs_tmux()
        self.socket = str(folder / "tmux.sock")
        # rosx's cache folder of its own: rosx sim's one-time hints are given there (already
        # given, unless ``first_run``), not in the user's.
        cache = folder / "cache"
        (cache / "rosx").mkdir(parents=True, exist_ok=True)
        if not first_run:
            (cache / "rosx" / HINTED).write_text("given\n")
        extra.setdefault("XDG_CACHE_HOME", str(cache))
        environ = clean_environ(TERM="xterm-256color", COLORTERM="truecolor", **extra)
        # textual takes COLUMNS and LINES over the terminal's size; pytest's process may have
        # them, and the tmux server hands its own environment to the program.
        for sized in ("COLUMNS", "LINES"):
            environ.pop(sized, None)
        self._server_environ = {
            k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")
        }
        environ["PYTHONPATH"] = os.pathsep.join(str(ROOT / p) for p in (".", "commands", "turtle"))
        command = [*ROSX_COMMAND, *argv]
        columns, rows = size
        # The pane stays, dead, after the program ends (so its end is seen however soon it comes).
        config = folder / "tmux.conf"
        config.write_text("set-option -g remain-on-exit on\n")
        try:
            self._run(
                "-f", str(config), "new-session", "-d", "-x", str(columns), "-y", str(rows),
                *(arg for key, value in environ.items() for arg in ("-e", f"{key}={value}")),
                " ".join(_quote(part) for part in command),
            )  # fmt: skip
        except BaseException:
            self._stop()
            raise

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

    def lines(self) -> list[str]:
        """The lines the program wrote, each whole: a line wider than the window, which the
        terminal wraps, comes back as one."""
        return self._run("capture-pane", "-p", "-J").splitlines()

    def cells(self) -> list[list[Cell]]:
        """The window's rows as cells with their colours."""
        return [list(_cells(row)) for row in self._run("capture-pane", "-p", "-e").splitlines()]

    def wait_for(self, text: str, timeout: float = 30.0) -> list[str]:
        """The screen once it shows ``text``."""
        return self.wait_until(lambda rows: any(text in row for row in rows), repr(text), timeout)

    def wait_until(
        self, shows: Callable[[list[str]], object], what: str, timeout: float = 30.0
    ) -> list[str]:
        """The screen once ``shows(rows)`` is true of it."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            rows = self.screen()
            if shows(rows):
                return rows
            time.sleep(0.1)
        raise AssertionError(f"{what} never showed; the screen:\n" + "\n".join(self.screen()))

    def keys(self, *keys: str) -> None:
        self._run("send-keys", *keys)

    def ended(self, timeout: float = 15.0) -> bool:
        """Whether the program ends within ``timeout`` seconds: its terminal closed and its
        process gone (or a zombie: tmux at times collects its status late, or never)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            shown = self._run("display-message", "-p", "#{pane_dead} #{pane_pid}").split()
            if shown[:1] == ["1"] and (len(shown) < 2 or not _running(shown[1])):
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
        self._stop()

    def _stop(self) -> None:
        """Ctrl-C to a program still running, then its process group killed if it stays; the
        tmux server ended."""
        try:
            pid = self._run("display-message", "-p", "#{pane_pid}").strip()
            if pid.isdigit() and self._run("display-message", "-p", "#{pane_dead}").strip() != "1":
                self.keys("C-c")
                if not self.ended(10.0):
                    # The pane's program leads a process group of its own (tmux makes it a
                    # session leader): its children go with it.
                    with contextlib.suppress(ProcessLookupError):
                        os.killpg(int(pid), signal.SIGKILL)
        finally:
            self._run("kill-server")


def footer(rows: list[str]) -> list[str]:
    """The words of the last row that shows anything."""
    return next(row for row in reversed(rows) if row.strip()).split()


def fits_and_shows_how_to_quit(term: Tmux, columns: int) -> None:
    """No line is wider than the terminal, and the footer begins with the quit key."""
    rows = term.wait_for("Quit")
    assert footer(rows)[:2] == ["q", "Quit"], rows
    lines = term.lines()
    assert all(len(line) <= columns for line in lines), lines


def quits_on_ctrl_c(term: Tmux) -> None:
    """Ctrl-C ends the program, and without a traceback."""
    term.keys("C-c")
    assert term.ended()
    lines = term.lines()
    assert not any("Traceback" in line for line in lines), lines


def _running(pid: str) -> bool:
    """Whether process ``pid`` runs (exists and is no zombie)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:  # gone, or no /proc: the closed terminal says enough
        return False
    return stat.rpartition(")")[2].split()[:1] != ["Z"]


_SGR = re.compile(r"\x1b\[([0-9;]*)m")


def _cells(row: str) -> Iterator[Cell]:
    """The cells of a row captured with its escapes (24-bit colours and resets)."""
    fg: Colour = None
    bg: Colour = None
    at = 0
    for match in _SGR.finditer(row):
        yield from (Cell(char, fg, bg) for char in row[at : match.start()])
        at = match.end()
        codes = match.group(1).split(";") if match.group(1) else ["0"]
        while codes:
            code = codes.pop(0)
            if code in ("38", "48") and codes[:1] == ["2"]:
                colour = ";".join(codes[1:4])
                del codes[:4]
                fg, bg = (colour, bg) if code == "38" else (fg, colour)
            elif code in ("38", "48") and codes[:1] == ["5"]:
                colour = "5;" + ";".join(codes[1:2])
                del codes[:2]
                fg, bg = (colour, bg) if code == "38" else (fg, colour)
            elif code == "0":
                fg = bg = None
            elif code == "39":
                fg = None
            elif code == "49":
                bg = None
    yield from (Cell(char, fg, bg) for char in row[at:])


def _quote(text: str) -> str:
    return "'" + text.replace("'", "'\\''") + "'"
