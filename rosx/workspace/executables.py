"""How ``rosrun`` finds a package's executable, and how it is to be started.

ROS 1's rosrun searches the whole package directory (following symbolic links, skipping
``build/``) for regular files of the given name with any execute bit set; a name containing
``/`` is taken as a path inside the package instead. `find_executables` does the same, and
also lists the same-named files that are not executable, which rosrun reports. Like rosrun (with
``catkin_find --libexec``) it looks first in an installed package's ``lib/PKG`` folder. For a
name not found, `suggestion` picks the executable the user most likely meant.

Which programs rosx itself provides is `rosx.workspace.programs`'s to say.

`is_python_script` tells the scripts rosx runs with its own Python and ``rospy``, whatever their
``#!`` line says: a ``#!`` line naming python, or no ``#!`` line and a ``.py`` name.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple

from rosx.packages.crawl import libexec_dir

_EXECUTE_BITS = 0o111


class Search(NamedTuple):
    """What a search found: executables, and same-named files rosrun cannot run."""

    executables: list[Path]
    not_executable: list[Path]


def _walk(root: Path) -> list[Path]:
    found: list[Path] = []
    seen: set[tuple[int, int]] = set()
    for directory, subdirs, files in os.walk(root, followlinks=True):
        stat = Path(directory).stat()
        key = (stat.st_dev, stat.st_ino)
        if key in seen:  # a link loop
            subdirs[:] = []
            continue
        seen.add(key)
        here = Path(directory)
        if here == root:
            subdirs[:] = [d for d in subdirs if d != "build"]
        subdirs.sort()
        found += [here / name for name in sorted(files)]
        found += [here / name for name in subdirs if (here / name).is_symlink()]
    return found


def _runnable(path: Path) -> bool:
    try:
        return path.is_file() and bool(path.stat().st_mode & _EXECUTE_BITS)
    except OSError:
        return False


def find_executables(package_dir: Path, name: str) -> Search:
    """The files called ``name`` in the package's ``lib/PKG`` folder (`libexec_dir`) and below
    ``package_dir`` (``name`` may be a relative path)."""
    if "/" in name:
        path = package_dir / name
        runnable = [path] if _runnable(path) else []
        return Search(runnable, [] if runnable or not path.exists() else [path])
    executables: list[Path] = []
    others: list[Path] = []
    libexec = libexec_dir(package_dir)
    searched = [*(_walk(libexec) if libexec else []), *_walk(package_dir)]
    for path in searched:
        if path.name != name:
            continue
        (executables if _runnable(path) else others).append(path)
    return Search(executables, others)


def executable_names(package_dir: Path) -> list[str]:
    """The names of every executable below ``package_dir`` (what rosrun could run), sorted."""
    return sorted({path.name for path in _walk(package_dir) if _runnable(path)})


def suggestion(name: str, following: list[str], known: list[str]) -> tuple[str, int] | None:
    """The executable a user most likely meant by ``name`` among ``known``, with how many of
    the words ``name, *following`` it stands for: ``name`` joined to the next arguments by
    ``_`` or nothing (spaces typed for underscores, as in ``turtle teleop key``, or in a name,
    `rosx.names.typos.joined`), else the closest name, if one is close (one word)."""
    from rosx.names.typos import joined  # noqa: PLC0415 - only for a name not found

    found = joined([name, *following], set(known))
    if found is not None:
        return found
    import difflib  # noqa: PLC0415 - only for a name not found

    close = difflib.get_close_matches(name, known, n=1, cutoff=0.6)
    return (close[0], 1) if close else None


def is_python_script(path: Path) -> bool:
    """Whether rosx runs ``path`` with its own Python (see the module docstring)."""
    try:
        with path.open("rb") as file:
            first = file.readline(256)
    except OSError:
        return False
    if first.startswith(b"#!"):
        return b"python" in first
    return path.suffix == ".py"


__all__ = [
    "Search",
    "executable_names",
    "find_executables",
    "is_python_script",
    "suggestion",
]
