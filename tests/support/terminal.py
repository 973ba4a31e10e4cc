"""Shells started as a new terminal starts them: an empty environment (``env -i``), a fresh
``HOME``, and on ``PATH`` only a folder holding ``rosx`` (as pipx's ``~/.local/bin``) in front of
the system's folders, where Debian's ROS 1 has its own ``roscore``, ``rostopic`` and the rest."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

#: The system's folders, after rosx's.
SYSTEM_PATH = "/usr/local/bin:/usr/bin:/bin"


def rosx_program() -> Path:
    """The installed ``rosx`` console script of this Python; skips the test without one."""
    program = Path(sys.executable).with_name("rosx")
    if not os.access(program, os.X_OK):
        pytest.skip(f"no rosx console script beside {sys.executable}")
    return program


class NewTerminal:
    """Shells of one user: ``home`` is their ``HOME``, ``home/.local/bin`` holds ``rosx``."""

    def __init__(self, home: Path) -> None:
        self.home = home
        self.bin = home / ".local" / "bin"
        self.bin.mkdir(parents=True, exist_ok=True)
        link = self.bin / "rosx"
        if not link.exists():
            link.symlink_to(rosx_program())

    @property
    def environ(self) -> dict[str, str]:
        """What ``env -i`` and a login leave: HOME, PATH, TERM, LANG, USER, SHELL."""
        return {
            "HOME": str(self.home),
            "PATH": f"{self.bin}:{SYSTEM_PATH}",
            "TERM": "xterm-256color",
            "LANG": "C.UTF-8",
            "USER": os.environ.get("USER", "student"),
        }

    def run(
        self,
        script: str,
        shell: str = "bash",
        *,
        interactive: bool = False,
        cwd: Path | None = None,
        timeout: float = 120,
        **extra: str,
    ) -> subprocess.CompletedProcess[str]:
        """``script`` in a new ``shell`` (``-i``: reading ``~/.bashrc`` or ``~/.zshrc``, as a
        terminal's shell does); skips the test where that shell is not installed."""
        path = shutil.which(shell, path=SYSTEM_PATH)
        if path is None:
            pytest.skip(f"{shell} is not installed")
        flags = ["-i", "-c"] if interactive else ["-c"]
        return subprocess.run(
            ["env", "-i", *(f"{k}={v}" for k, v in {**self.environ, **extra}.items()), path,
             *flags, script],
            cwd=cwd or self.home, capture_output=True, text=True, timeout=timeout, check=False,
            stdin=subprocess.DEVNULL,
        )  # fmt: skip


def debian_ros1_program(name: str) -> str | None:
    """Debian's ROS 1 program ``name`` in the system's folders, if installed."""
    return shutil.which(name, path=SYSTEM_PATH)
