"""The package index's cache: a crawl of ``ROS_PACKAGE_PATH`` kept under ``ROS_HOME``, never stale.

rospack keeps its crawl in ``ROS_HOME/rospack_cache_<hash>`` and trusts it for 60 seconds
(``ROS_CACHE_TIMEOUT``): a package made a moment ago is not found, one removed still is. This
cache is trusted only while the tree it describes is unchanged, which is asked each time at the
cost of one ``stat`` per folder the crawl listed (no listing, no manifest read):

- each folder whose listing the crawl used (not a package's own: files saved there do not
  matter) must have the change time (``st_ctime``) it had before the crawl listed it: a
  package added, removed or renamed in it, a ``CATKIN_IGNORE`` put there, moves that time, and
  unlike a modification time nothing sets it back;
- each ``package.xml`` must have its change time and size (a package renamed in its manifest).

Times a file system may not yet have moved on from are not trusted: a crawl that saw a time less
than `RACY_SECONDS` old (or in the future) is not written, and the next command crawls again,
as git treats its index's "racy" entries. A cache that cannot be read or written is no cache:
the path is crawled, as without one.

The file is ``ROS_HOME/rosx_packages_<hash of the path>``, written whole under another name and
renamed, so a reader sees the old file or the new one.
"""

from __future__ import annotations

import contextlib
import marshal
import os
import time
import zlib
from pathlib import Path

from rosx.packages.crawl import Seen, find_packages

#: Changes younger than this may not have moved a file system's times yet (FAT: 2 s).
RACY_SECONDS = 2.0
_VERSION = 1


def cache_file(folder: Path, roots: list[Path]) -> Path:
    """Where the crawl of ``roots`` is kept in ``folder`` (``ROS_HOME``)."""
    key = zlib.crc32(os.pathsep.join(str(r) for r in roots).encode())
    return folder / f"rosx_packages_{key:08x}"


def cached_packages(roots: list[Path], folder: Path | None) -> dict[str, Path]:
    """The packages on ``roots`` by name, as `find_packages` finds them: from the cache in
    ``folder`` while the tree is unchanged, else crawled (and the cache written again)."""
    if folder is None or not roots:
        return find_packages(roots)
    path = cache_file(folder, roots)
    kept = _read(path, roots)
    if kept is not None:
        return kept
    seen = Seen()
    started = time.time_ns()
    found = find_packages(roots, seen)
    _write(path, roots, found, seen, started)
    return found


def _read(path: Path, roots: list[Path]) -> dict[str, Path] | None:
    try:
        data = marshal.loads(path.read_bytes())
        version, kept_roots, packages, directories, manifests = data
    except (OSError, EOFError, ValueError, TypeError):
        return None
    if version != _VERSION or kept_roots != [str(r) for r in roots]:
        return None
    stat = os.stat
    for directory, changed in directories:
        try:
            now = stat(directory).st_ctime_ns
        except OSError:  # a root that was not there (-1) may still not be
            now = -1
        if now != changed:
            return None
    for manifest, changed, size in manifests:
        try:
            now_stat = stat(manifest)
        except OSError:
            return None
        if now_stat.st_ctime_ns != changed or now_stat.st_size != size:
            return None
    return {name: Path(directory) for name, directory in packages}


def _write(path: Path, roots: list[Path], found: dict[str, Path], seen: Seen, started: int) -> None:
    newest = started - int(RACY_SECONDS * 1e9)
    times = [t for _, t in seen.directories] + [t for _, t, _ in seen.manifests]
    if any(t > newest for t in times):
        return  # racy: a change within the file system's resolution could go unseen
    data = (
        _VERSION,
        [str(r) for r in roots],
        [(name, str(directory)) for name, directory in found.items()],
        seen.directories,
        seen.manifests,
    )
    partial = path.with_name(f".{path.name}.{os.getpid()}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        partial.write_bytes(marshal.dumps(data))
        partial.replace(path)
    except OSError:
        with contextlib.suppress(OSError):
            partial.unlink()


__all__ = ["RACY_SECONDS", "cache_file", "cached_packages"]
