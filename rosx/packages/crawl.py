"""Find ROS packages on a package path, the way rospack crawls ``ROS_PACKAGE_PATH``.

A package is a directory holding a ``package.xml``; its name is the manifest's ``<name>``. The
crawl does not descend into a package, into hidden directories, or below a directory holding
``CATKIN_IGNORE`` or ``rospack_nosubdirs``. When a name occurs twice, the first one on the path
wins, as with rospack.

The packages rosx ships are data files of the wheel, under one prefix laid out as Noetic's
``/opt/ros/noetic`` (`PREFIX`): ``share/<package>/`` holds a package's ``package.xml`` (with
Noetic's dependency facts), its ``msg/`` and ``srv/`` files (the original texts, comments
included) and its scripts; ``lib/<package>/`` holds the programs rosrun finds there, as catkin's
``libexec`` folders. `rosx.packages.bundled` finds them; here they are paths.
"""

from __future__ import annotations

import os
import re
from functools import cache
from pathlib import Path

from rosx.packages import bundled

_NAME = re.compile(r"<name>\s*([^<\s]+)\s*</name>")

#: The install prefix of the ROS packages shipped with rosx (``share/``, ``lib/``).
PREFIX = Path(bundled.PREFIX)


def package_name(manifest: Path) -> str | None:
    """The ``<name>`` of a ``package.xml``, or None when it has none or cannot be read."""
    try:
        match = _NAME.search(manifest.read_text(encoding="utf-8", errors="replace"))
    except OSError:
        return None
    return match.group(1) if match else None


def split_package_path(value: str | None) -> list[Path]:
    """The entries of a ``ROS_PACKAGE_PATH`` value, empty ones dropped."""
    return [Path(p) for p in (value or "").split(os.pathsep) if p]


class Seen:
    """What a crawl looked at, to tell later whether it would find the same (`rosx.packages.
    cache`): each directory it listed, with its change time read before the listing, and each
    manifest it read, with its own (change time, size). A directory's change time moves when an
    entry is added to it, removed or renamed; a file's when it is written or replaced. Unlike
    the modification time, nobody can set it back (``touch -d``, ``tar``, ``rsync -t``)."""

    def __init__(self) -> None:
        #: ``(path, st_ctime_ns)``; ``-1`` for a path that was not there.
        self.directories: list[tuple[str, int]] = []
        #: ``(path of package.xml, st_ctime_ns, st_size)``.
        self.manifests: list[tuple[str, int, int]] = []
        #: Each package found, by name: how many directories had been listed before it, and
        #: where its manifest is in `manifests` (what came before it in the crawl's order).
        self.positions: dict[str, tuple[int, int]] = {}


def find_packages(roots: list[Path], seen: Seen | None = None) -> dict[str, Path]:
    """Map each package name found under ``roots`` to its directory (what was looked at goes
    in ``seen``)."""
    found: dict[str, Path] = {}
    for root in roots:
        _crawl(str(root), found, seen)
    return found


def _crawl(directory: str, found: dict[str, Path], seen: Seen | None) -> None:
    # Strings and one scandir a directory, no Path objects: a package path such as Debian's
    # /usr/share holds thousands of directories, and every launch and node start crawls it.
    if seen is not None:
        # Its time before its listing: a change made while it is read shows as a new time.
        try:
            seen.directories.append((directory, os.stat(directory).st_ctime_ns))  # noqa: PTH116 - strings, as the crawl
        except OSError:
            seen.directories.append((directory, -1))
            return
    try:
        with os.scandir(directory) as listing:
            entries = {entry.name: entry for entry in listing}
    except OSError:
        return
    manifest = entries.get("package.xml")
    if manifest is not None and manifest.is_file():
        if seen is not None:
            # A package's own folder changes with every file saved in it; its manifest decides.
            seen.directories.pop()
            try:
                stat = manifest.stat()
            except OSError:
                return
            seen.manifests.append((manifest.path, stat.st_ctime_ns, stat.st_size))
        name = package_name(Path(manifest.path))
        if name and name not in found:
            found[name] = Path(directory)
            if seen is not None:
                seen.positions[name] = (len(seen.directories), len(seen.manifests) - 1)
        return
    if "CATKIN_IGNORE" in entries or "rospack_nosubdirs" in entries:
        return
    for name in sorted(entries):
        entry = entries[name]
        if not name.startswith(".") and entry.is_dir():
            _crawl(entry.path, found, seen)


@cache
def bundled_packages() -> dict[str, Path]:
    """The ROS package directories shipped with rosx (`PREFIX`'s ``share/``), by name."""
    return {name: Path(folder) for name, folder in bundled.bundled_folders().items()}


def bundled_libexec(package: str) -> Path | None:
    """The folder of programs rosx ships for ``package`` (``lib/<package>``), if it has one."""
    folder = PREFIX / "lib" / package
    return folder if folder.is_dir() else None


def libexec_dir(package_dir: Path) -> Path | None:
    """Where an installed package's programs are: ``PREFIX/lib/PKG`` for a package in
    ``PREFIX/share/PKG`` (catkin's ``CATKIN_PACKAGE_BIN_DESTINATION``), if it exists."""
    if package_dir.parent.name != "share":
        return None
    folder = package_dir.parent.parent / "lib" / package_dir.name
    return folder if folder.is_dir() else None
