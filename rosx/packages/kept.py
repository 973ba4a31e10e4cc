"""The kept crawl's file, read and checked with ``os`` alone, and the list it answers.

`rosx.packages.cache` keeps the crawl of ``ROS_PACKAGE_PATH`` under ``ROS_HOME`` and says when
it is trusted (every folder it listed and every manifest it read unchanged). This module is
that file's format and that check, and `listed_packages`: the list of every package, as the
index lists it, while the kept crawl holds. No ``pathlib``, no ``re``, no XML, so that a shell's
<TAB> (`rosx_commands.complete.main`, in a Python started for it alone) and ``rospack list``
pay for the ``stat`` calls of the check and little more. Paths are plain strings here.
"""

from __future__ import annotations

import marshal
import os
import zlib

from rosx.cache import ros_home_text
from rosx.packages.bundled import bundled_folders

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

#: The kept file's format; a file of another is not read.
VERSION = 2

#: What the file holds: each package's ``(folder, folders listed before it, its manifest's
#: place)`` by name; each folder listed, with its change time (``-1``: not there); each manifest
#: read, with its change time and size; all in the crawl's order.
Kept = tuple[dict[str, tuple[str, int, int]], list[tuple[str, int]], list[tuple[str, int, int]]]


def kept_file(folder: str, roots: Sequence[str]) -> str:
    """Where the crawl of ``roots`` is kept in ``folder`` (``ROS_HOME``)."""
    key = zlib.crc32(os.pathsep.join(roots).encode())
    return os.path.join(folder, f"rosx_packages_{key:08x}")  # noqa: PTH118 - strings, no pathlib


def read_kept(path: str, roots: Sequence[str]) -> Kept | None:
    """The crawl of ``roots`` kept at ``path``; None when there is none that can be read."""
    try:
        with open(path, "rb") as file:  # noqa: PTH123 - strings, no pathlib
            data = marshal.loads(file.read())
        version, kept_roots, packages, directories, manifests = data
        if version != VERSION or kept_roots != list(roots):
            return None
        by_name = {name: (directory, listed, at) for name, directory, listed, at in packages}
    except (OSError, EOFError, ValueError, TypeError):
        return None
    return by_name, directories, manifests


def unchanged(
    directories: Sequence[tuple[str, int]], manifests: Sequence[tuple[str, int, int]]
) -> bool:
    """Whether each folder has its change time and each manifest its change time and size."""
    stat = os.stat
    for directory, changed in directories:
        try:
            now = stat(directory).st_ctime_ns
        except OSError:  # a root that was not there (-1) may still not be
            now = -1
        if now != changed:
            return False
    for manifest, changed, size in manifests:
        try:
            now_stat = stat(manifest)
        except OSError:
            return False
        if now_stat.st_ctime_ns != changed or now_stat.st_size != size:
            return False
    return True


def root_text(entry: str) -> str:
    """An entry of ``ROS_PACKAGE_PATH`` as ``str(pathlib.Path(entry))`` writes it (the kept
    file names its roots so), without importing pathlib."""
    if entry.startswith("//") and not entry.startswith("///"):
        head = "//"
    else:
        head = "/" if entry.startswith("/") else ""
    return head + "/".join(part for part in entry.split("/") if part not in ("", ".")) or "."


def _kept_of(environ: Mapping[str, str]) -> Kept | None:
    """The crawl of ``environ``'s ``ROS_PACKAGE_PATH`` kept in its ``ROS_HOME``, unchecked."""
    roots = [root_text(p) for p in environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    return read_kept(kept_file(ros_home_text(environ), roots), roots) if roots else None


def kept_packages(environ: Mapping[str, str]) -> dict[str, str] | None:
    """The packages on ``environ``'s ``ROS_PACKAGE_PATH`` (not rosx's own) by name, in the
    crawl's order, from the crawl kept in ``ROS_HOME`` while all of it is unchanged; None when
    that cannot tell (none kept, or something changed: a crawl answers then,
    `rosx.packages.cache`)."""
    kept = _kept_of(environ)
    if kept is None or not unchanged(kept[1], kept[2]):
        return None
    return {name: directory for name, (directory, _, _) in kept[0].items()}


def kept_find(environ: Mapping[str, str], name: str) -> str | None:
    """The folder of package ``name`` as `rosx.packages.index.PackageIndex.find` finds it,
    from the kept crawl: one on the package path checking only what precedes it there (as
    `rosx.packages.cache.KeptCrawl.find`), one of rosx's own checking all of the path (no
    package there may shadow it). None when the kept crawl cannot tell, or there is no such
    package: the index answers then."""
    kept = _kept_of(environ)
    if kept is None:
        return None
    packages, directories, manifests = kept
    found = packages.get(name)
    if found is None:
        return bundled_folders().get(name) if unchanged(directories, manifests) else None
    directory, listed, manifest = found
    return directory if unchanged(directories[:listed], manifests[: manifest + 1]) else None


def listed_packages(environ: Mapping[str, str]) -> dict[str, str] | None:
    """Every package's folder by name, sorted, as `rosx.packages.index.PackageIndex.packages`
    lists them (the package path's first, then rosx's own), from the kept crawl
    (`kept_packages`); None when it cannot tell."""
    found = kept_packages(environ)
    if found is None:
        return None
    for name, folder in bundled_folders().items():
        found.setdefault(name, folder)
    return dict(sorted(found.items()))


__all__ = [
    "VERSION",
    "Kept",
    "kept_file",
    "kept_find",
    "kept_packages",
    "listed_packages",
    "read_kept",
    "root_text",
    "unchanged",
]
