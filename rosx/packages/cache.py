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

A package that is found needs less: nothing the crawl met after it can change where it is
(the first of a name wins), so a lookup checks only what came before it in the crawl's
order, its manifest included (`KeptCrawl.find`): a package of the user's workspace, in front
of the path, is found with a few hundred ``stat`` calls, where the whole of Debian's
``/usr/share`` takes thousands; and what one question checked, the next does not check again.

Times a file system may not yet have moved on from are not trusted: a crawl that saw a time less
than `RACY_SECONDS` old (or in the future) is not written, and the next command crawls again,
as git treats its index's "racy" entries. A cache that cannot be read or written is no cache:
the path is crawled, as without one.

The file is ``ROS_HOME/rosx_packages_<hash of the path>``, written whole under another name and
renamed, so a reader sees the old file or the new one. Its format and the check are
`rosx.packages.kept`, which a <TAB> reads without the rest of the index.
"""

from __future__ import annotations

import contextlib
import marshal
import os
import time
from pathlib import Path

from rosx.packages import kept as kept_format
from rosx.packages.crawl import Seen, find_packages

#: Changes younger than this may not have moved a file system's times yet (FAT: 2 s).
RACY_SECONDS = 2.0


def cache_file(folder: Path, roots: list[Path]) -> Path:
    """Where the crawl of ``roots`` is kept in ``folder`` (``ROS_HOME``)."""
    return Path(kept_format.kept_file(str(folder), [str(r) for r in roots]))


class KeptCrawl:
    """A process's view of the crawl kept for one package path: what it has checked of it so
    far (in the crawl's order), so that each question checks only what no earlier one did."""

    def __init__(self, roots: list[Path], folder: Path | None) -> None:
        self.roots = roots
        self.folder = folder
        self._kept = (
            kept_format.read_kept(str(cache_file(folder, roots)), [str(r) for r in roots])
            if folder and roots
            else None
        )
        self._directories_checked = 0
        self._manifests_checked = 0

    def find(self, name: str) -> Path | None:
        """Where package ``name`` is, if the cache has it and nothing before it in the crawl's
        order has changed; None when that cannot tell (`packages` then answers)."""
        if self._kept is None:
            return None
        found = self._kept[0].get(name)
        if found is None:
            return None
        directory, listed, manifest = found
        return Path(directory) if self._unchanged(listed, manifest + 1) else None

    def packages(self) -> dict[str, Path]:
        """Every package on the path, by name: the kept crawl while all of it is unchanged,
        else a new crawl (kept in turn)."""
        if self._kept is not None:
            packages, directories, manifests = self._kept
            if self._unchanged(len(directories), len(manifests)):
                return {name: Path(directory) for name, (directory, _, _) in packages.items()}
        if self.folder is None or not self.roots:
            return find_packages(self.roots)
        seen = Seen()
        started = time.time_ns()
        found = find_packages(self.roots, seen)
        _write(cache_file(self.folder, self.roots), self.roots, found, seen, started)
        return found

    def _unchanged(self, directories: int, manifests: int) -> bool:
        """Whether the first ``directories`` folders and ``manifests`` manifests of the kept
        crawl are as they were (those checked before are not checked again)."""
        assert self._kept is not None
        _, kept_directories, kept_manifests = self._kept
        if not kept_format.unchanged(
            kept_directories[self._directories_checked : directories],
            kept_manifests[self._manifests_checked : manifests],
        ):
            self._kept = None  # stale: every answer comes from a new crawl
            return False
        self._directories_checked = max(self._directories_checked, directories)
        self._manifests_checked = max(self._manifests_checked, manifests)
        return True


def cached_packages(roots: list[Path], folder: Path | None) -> dict[str, Path]:
    """The packages on ``roots`` by name, as `find_packages` finds them: from the cache in
    ``folder`` while the tree is unchanged, else crawled (and the cache written again)."""
    return KeptCrawl(roots, folder).packages()


def _write(path: Path, roots: list[Path], found: dict[str, Path], seen: Seen, started: int) -> None:
    newest = started - int(RACY_SECONDS * 1e9)
    times = [t for _, t in seen.directories] + [t for _, t, _ in seen.manifests]
    if any(t > newest for t in times):
        return  # racy: a change within the file system's resolution could go unseen
    data = (
        kept_format.VERSION,
        [str(r) for r in roots],
        [(name, str(directory), *seen.positions[name]) for name, directory in found.items()],
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


__all__ = ["RACY_SECONDS", "KeptCrawl", "cache_file", "cached_packages"]
