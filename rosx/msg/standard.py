"""The standard ROS 1 Noetic message types, taken from rosbags' ROS1_NOETIC type store.

rosbags keeps field lists, not the original files, so each type's definition text is rebuilt
from them (``type name`` lines, constants first as ``type NAME=value``) and then parsed like any
other ``.msg`` text. Comments of the original files are therefore absent; md5 sums are not
affected, since ROS 1 hashes neither comments nor layout.

Importing rosbags' store costs a command about 60 ms (hundreds of dataclasses), more than the
rest of ``rosmsg show`` or of a rospy script's start-up. So the texts, once built, are kept in
rosx's cache folder (`rosx.cache`: ``$XDG_CACHE_HOME/rosx``, else ``~/.cache/rosx``) as one
`marshal` file per rosbags install and Python version, named after and tagged with the path,
size and time of rosbags' store module and Python's version: virtual environments sharing the
folder each keep their own, and another rosbags or Python builds its file anew. Writing one
removes those nobody has written for `STALE_DAYS` days (a later run there builds its file
again). Nothing else is written; where the folder cannot be written, each run reads rosbags
as before.
"""

from __future__ import annotations

import contextlib
import marshal
import os
import sys
import time
from functools import cache
from pathlib import Path

from rosx.cache import cache_folder

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

#: rosbags gives empty ROS 1 messages this one field (an IDL rule); ROS 1 has no such field.
_PLACEHOLDER = "structure_needs_at_least_one_member"
_TIME_TYPES = {"builtin_interfaces/msg/Time": "time", "builtin_interfaces/msg/Duration": "duration"}
_CACHE_STEM = "ros1_noetic_types"
#: A cache file nobody has written for this many days goes when another is written.
STALE_DAYS = 90

#: rosbags' store module (path, size, modification time) and Python's major and minor version.
Tag = tuple[str, int, int, int, int]


def standard_types() -> dict[str, str]:
    """The definition text of each standard ``pkg/Type``, by name."""
    return _texts()


def standard_text(full_name: str) -> str | None:
    """The definition text of standard type ``full_name``, or None when rosbags lacks it."""
    return _texts().get(full_name)


@cache
def _texts() -> dict[str, str]:
    tag = _store_tag()
    cache_path = None if tag is None else _cache_path(tag)
    if tag is not None and cache_path is not None:
        texts = _read_cache(cache_path, tag)
        if texts is not None:
            return texts
    texts = _texts_from_rosbags()
    if tag is not None and cache_path is not None:
        _write_cache(cache_path, tag, texts)
    return texts


def _store_tag() -> Tag | None:
    """What identifies rosbags' Noetic store and this Python, found without importing rosbags."""
    import importlib.util  # noqa: PLC0415 - importlib is not needed at start-up

    spec = importlib.util.find_spec("rosbags")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(spec.submodule_search_locations[0], "typesys", "stores", "ros1_noetic.py")
    try:
        stat = path.stat()
    except OSError:
        return None
    return (str(path), stat.st_size, stat.st_mtime_ns, *sys.version_info[:2])


def _cache_path(tag: Tag) -> Path | None:
    """Where the texts of ``tag``'s rosbags and Python are kept (None: no usable folder)."""
    import zlib  # noqa: PLC0415 - zlib is not needed at start-up

    folder = cache_folder(os.environ)
    if folder is None:
        return None
    key = zlib.crc32(repr(tag).encode())
    return folder / f"{_CACHE_STEM}-py{tag[3]}.{tag[4]}-{key:08x}.marshal"


def _read_cache(path: Path, tag: Tag) -> dict[str, str] | None:
    try:
        content = marshal.loads(path.read_bytes())
    except (OSError, EOFError, ValueError, TypeError):
        return None
    if type(content) is tuple and len(content) == 2 and content[0] == tag:
        texts = content[1]
        if type(texts) is dict:
            return texts
    return None


def _write_cache(path: Path, tag: Tag, texts: dict[str, str]) -> None:
    partial = path.with_name(f"{path.name}.{os.getpid()}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        partial.write_bytes(marshal.dumps((tag, texts)))
        partial.replace(path)
    except OSError:
        with contextlib.suppress(OSError):
            partial.unlink()
        return
    _remove_stale(path)


def _remove_stale(kept: Path) -> None:
    """Remove the other cache files not written for `STALE_DAYS` days."""
    oldest = time.time() - STALE_DAYS * 86400
    for other in kept.parent.glob(f"{_CACHE_STEM}*.marshal"):
        with contextlib.suppress(OSError):
            if other != kept and other.stat().st_mtime < oldest:
                other.unlink()


def _texts_from_rosbags() -> dict[str, str]:
    from rosbags.typesys import Stores, get_typestore  # 60 ms, see above

    fielddefs: dict[str, Any] = get_typestore(Stores.ROS1_NOETIC).fielddefs
    return {
        _ros1_name(name): _text(*fielddefs[name])
        for name in fielddefs
        if "/msg/" in name and not name.startswith("builtin_interfaces/")
    }


def _text(constants: list[Any], fields: list[Any]) -> str:
    lines = [f"{type_} {name}={_constant_text(value)}" for name, type_, value in constants]
    lines += [f"{_type_text(node)} {name}" for name, node in fields if name != _PLACEHOLDER]
    return "".join(line + "\n" for line in lines)


def _ros1_name(name: str) -> str:
    package, _, short = name.partition("/msg/")
    return f"{package}/{short}"


def _constant_text(value: object) -> str:
    return str(value)


def _type_text(node: tuple[Any, Any]) -> str:
    kind, detail = node
    kind_name = getattr(kind, "name", str(kind))
    if kind_name == "BASE":
        return str(detail[0])
    if kind_name == "NAME":
        name = str(detail)
        if name in _TIME_TYPES:
            return _TIME_TYPES[name]
        ros1 = _ros1_name(name)
        return "Header" if ros1 == "std_msgs/Header" else ros1
    element, size = detail
    suffix = f"[{size}]" if kind_name == "ARRAY" else "[]"
    return _type_text(element) + suffix
