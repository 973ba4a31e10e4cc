"""ROS 1's command names as small programs on ``PATH``, written for ``rosx shell-init``.

In ROS 1, ``rostopic``, ``roslaunch``… are programs in ``/opt/ros/noetic/bin``, so whatever runs
a program finds them: ``timeout -s INT 3 rostopic hz …``, ``watch rosnode list``, ``xargs``,
``env``, ``nohup``, a script, ``exec``. Shell functions cannot be found that way, so
`write_commands` writes one program per name, a ``#!/bin/sh`` line and
``exec <rosx> NAME "$@"``, and ``rosx shell-init`` puts their folder in front of ``PATH``.

The folder (`command_folder`) is in rosx's cache folder (`rosx.cache`:
``$XDG_CACHE_HOME/rosx``, else ``~/.cache/rosx``), named after a checksum of how rosx is run
(``~/.cache/rosx/bin-1a2b3c4d/``): each install (virtual environment) has its own, and every
shell of one install shares it. A file is written only when it is missing or different, under a
temporary name then renamed, so a program starting meanwhile runs the old file or the new one,
never half of one; files of names no longer given are removed.

Everything takes the environment as a mapping; nothing here reads `os.environ`.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import TYPE_CHECKING

from rosx.cache import cache_folder

if TYPE_CHECKING:
    from collections.abc import Iterable, Mapping

#: The mode of every program written: anyone may run it, only its owner change it.
MODE = 0o755


def command_folder(environ: Mapping[str, str], rosx: str) -> Path | None:
    """The folder of the programs running rosx as ``rosx`` (shell words), or None when the
    environment names no usable cache folder."""
    import zlib  # noqa: PLC0415 - only shell-init needs it

    folder = cache_folder(environ)
    if folder is None:
        return None
    return folder / f"bin-{zlib.crc32(rosx.encode()):08x}"


def command_script(rosx: str, name: str) -> str:
    """The program named ``name``: rosx's tool of that name with the arguments given."""
    return f'#!/bin/sh\nexec {rosx} {name} "$@"\n'


def write_commands(folder: Path, rosx: str, names: Iterable[str]) -> None:
    """Make ``folder`` hold one program per name of ``names`` (`command_script`) and no other.

    Raises:
        OSError: the folder or a program in it cannot be written.
    """
    folder.mkdir(parents=True, exist_ok=True)
    wanted = set(names)
    for name in sorted(wanted):
        _write_if_different(folder / name, command_script(rosx, name).encode())
    for entry in folder.iterdir():
        # A name starting with "." is another shell-init's file being written.
        if entry.name not in wanted and not entry.name.startswith(".") and entry.is_file():
            with contextlib.suppress(FileNotFoundError):
                entry.unlink()


def _write_if_different(path: Path, content: bytes) -> None:
    try:
        if path.read_bytes() == content and path.stat().st_mode & 0o7777 == MODE:
            return
    except OSError:
        pass
    partial = path.with_name(f".{path.name}.{os.getpid()}")
    try:
        partial.write_bytes(content)
        partial.chmod(MODE)
        partial.replace(path)
    except OSError:
        with contextlib.suppress(OSError):
            partial.unlink()
        raise


__all__ = ["MODE", "command_folder", "command_script", "write_commands"]
