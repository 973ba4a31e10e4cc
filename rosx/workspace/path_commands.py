"""ROS 1's command names as small programs on ``PATH``, written for ``rosx shell-init``.

In ROS 1, ``rostopic``, ``roslaunch``… are programs in ``/opt/ros/noetic/bin``, so whatever runs
a program finds them: ``timeout -s INT 3 rostopic hz …``, ``watch rosnode list``, ``xargs``,
``env``, ``nohup``, a script, ``exec``. Shell functions cannot be found that way, so
`write_commands` writes one program per name, a ``#!/bin/sh`` line and
``exec <rosx> NAME "$@"``, and ``rosx shell-init`` puts their folder in front of ``PATH``; so
does a workspace's ``setup.sh``, for the copies ``catkin_make`` writes in its ``bin/``.

The folder (`command_folder`) is in rosx's cache folder (`rosx.cache`:
``$XDG_CACHE_HOME/rosx``, else ``~/.cache/rosx``), named after a checksum of how rosx is run
(``~/.cache/rosx/bin-1a2b3c4d/``): each install (virtual environment) has its own, and every
shell of one install shares it. A file is written only when it is missing or different, under a
temporary name then renamed, so a program starting meanwhile runs the old file or the new one,
never half of one; files of names no longer given are removed.

`runs_rosx` tells whether a name on ``PATH`` is such a program, and `hint_once` gives ``rosx
sim``'s one-time hint at ``rosx shell-init --install`` where it is not.

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


def write_commands(folder: Path, rosx: str, names: Iterable[str], *, prune: bool = True) -> None:
    """Make ``folder`` hold one program per name of ``names`` (`command_script`), and, with
    ``prune``, no other (a workspace's ``bin/``, which packages' programs share, is not pruned).

    Raises:
        OSError: the folder or a program in it cannot be written.
    """
    folder.mkdir(parents=True, exist_ok=True)
    wanted = set(names)
    for name in sorted(wanted):
        _write_if_different(folder / name, command_script(rosx, name).encode())
    if not prune:
        return
    for entry in folder.iterdir():
        # A name starting with "." is another shell-init's file being written.
        if entry.name not in wanted and not entry.name.startswith(".") and entry.is_file():
            with contextlib.suppress(FileNotFoundError):
                entry.unlink()


def runs_rosx(environ: Mapping[str, str], name: str) -> bool:
    """Whether the program ``PATH`` finds first for ``name`` is one of these (rosx's tool of
    that name), not a system's ROS 1 program or nothing."""
    import shutil  # noqa: PLC0415 - only sim's hint asks

    found = shutil.which(name, path=environ.get("PATH", ""))
    if found is None:
        return False
    try:
        with Path(found).open("rb") as program:
            head = program.read(4096)
    except OSError:
        return False
    return head.startswith(b"#!/bin/sh\nexec ") and head.endswith(f' {name} "$@"\n'.encode())


#: Says that the hint of `hint_once` was given (a file in rosx's cache folder).
HINTED = "hinted-shell-init"

#: What ``rosx sim`` says once where ROS 1's command names do not run rosx.
SHELL_INIT_HINT = (
    "Tip: to type roscore, rostopic, rosrun… without `rosx` in front, in every new terminal, "
    "run once: rosx shell-init --install"
)


def hint_once(environ: Mapping[str, str]) -> str | None:
    """`SHELL_INIT_HINT` the first time it is asked where ``rostopic`` does not run rosx's
    tool (remembered in rosx's cache folder); None otherwise."""
    if runs_rosx(environ, "rostopic"):
        return None
    folder = cache_folder(environ)
    if folder is None:
        return SHELL_INIT_HINT
    marker = folder / HINTED
    if marker.exists():
        return None
    with contextlib.suppress(OSError):
        folder.mkdir(parents=True, exist_ok=True)
        marker.write_text("rosx sim gave its shell-init hint\n", encoding="utf-8")
    return SHELL_INIT_HINT


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


__all__ = [
    "HINTED",
    "MODE",
    "SHELL_INIT_HINT",
    "command_folder",
    "command_script",
    "hint_once",
    "runs_rosx",
    "write_commands",
]
