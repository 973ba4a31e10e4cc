"""Building a package's ``msg/``, ``srv/`` and ``action/`` types, as ``catkin_make`` checks them.

Each ``msg/<Type>.msg`` and ``srv/<Type>.srv``, and the seven messages genaction makes of each
``action/<Name>.action``, is loaded as a node will load it: parsed, its embedded types found (in
the workspace, on ``ROS_PACKAGE_PATH`` or among the standard types), its md5 sum computed and
its class built. The first mistake stops the build with a report that
names the file and, where there is one, the line::

    Error(s) in message file '/home/u/catkin_ws/src/lab2/msg/Num.msg', line 2:
    Invalid declaration: int32 x y
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.parser import InvalidMsgSpecError, is_valid_type_name
from rosx.msg.spec import ACTION_SUFFIXES, HEADER_TYPE, PRIMITIVE_TYPES
from rosx.msg.store import TypeStore, UnknownTypeError
from rosx.workspace.errors import BuildError

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.packages.manifest import Manifest

_KIND_NAMES = {"msg": "message", "srv": "service", "action": "action"}
#: The kinds of type file, in the order catkin_make builds them.
KINDS = ("msg", "action", "srv")


class PackageTypes(NamedTuple):
    """The types a package defines, by full name; ``messages`` include those of ``actions``."""

    package: str
    messages: list[str]
    services: list[str]
    actions: list[str] = []  # noqa: RUF012 - a NamedTuple default, never changed in place

    def steps(self) -> list[tuple[str, str]]:
        """``(kind, full name)`` of every type, messages first."""
        return [("msg", n) for n in self.messages] + [("srv", n) for n in self.services]

    def all_names(self) -> list[str]:
        """The package's message and service type names, messages first."""
        return self.messages + self.services


def _report(path: Path, kind: str, problem: str, line: int | None) -> BuildError:
    where = f", line {line}" if line else ""
    return BuildError(f"Error(s) in {_KIND_NAMES[kind]} file '{path}'{where}:\n{problem}")


def _line_using(text: str, package: str, full_name: str) -> int | None:
    """The line of ``text`` declaring a field of type ``full_name``, if any."""
    for number, line in enumerate(text.split("\n"), start=1):
        words = line.split("#", 1)[0].split()
        if len(words) != 2 or "=" in line.split("#", 1)[0]:
            continue
        base = words[0].split("[", 1)[0]
        if base == "Header":
            base = HEADER_TYPE
        elif "/" not in base and base not in PRIMITIVE_TYPES:
            base = f"{package}/{base}"
        if base == full_name:
            return number
    return None


def _build_one(store: TypeStore, package: str, kind: str, path: Path) -> str:
    full_name = f"{package}/{path.stem}"
    if not is_valid_type_name(full_name):
        raise _report(path, kind, f"[{path.stem}] is not a legal {_KIND_NAMES[kind]} name", None)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise _report(path, kind, f"cannot be read: {error}", None) from None
    try:
        if kind == "msg":
            store.msg(full_name)
            get_message_class(full_name, store)
        elif kind == "action":
            store.action(full_name)
            for suffix in ACTION_SUFFIXES:
                get_message_class(full_name + suffix, store)
        else:
            store.srv(full_name)
            get_service_class(full_name, store)
    except InvalidMsgSpecError as error:
        raise _report(path, kind, str(error), error.line) from None
    except UnknownTypeError as error:
        line = _line_using(text, package, error.full_name)
        raise _report(path, kind, str(error), line) from None
    return full_name


def type_paths(manifest: Manifest, chosen: Mapping[str, list[str] | None]) -> dict[str, list[Path]]:
    """The type files of each kind (`KINDS`) that the package builds: those ``chosen`` names
    for the kind (its CMakeLists.txt's ``FILES``), else every file of the kind's folder."""
    found: dict[str, list[Path]] = {}
    for kind in KINDS:
        directory = manifest.directory / kind
        names = chosen.get(kind)
        if names is not None:
            found[kind] = [directory / name for name in dict.fromkeys(names)]
        else:
            found[kind] = sorted(directory.glob(f"*.{kind}")) if directory.is_dir() else []
    return found


def build_types(
    manifest: Manifest,
    package_path: list[Path],
    chosen: Mapping[str, list[str] | None] | None = None,
) -> PackageTypes:
    """Load the types of the package of ``manifest`` (those of `type_paths`), looking types up
    on ``package_path``.

    Raises:
        BuildError: a file is not a valid definition (see the module docstring).
    """
    store = TypeStore(package_path)
    built: dict[str, list[str]] = {kind: [] for kind in KINDS}
    for kind, paths in type_paths(manifest, chosen or {}).items():
        for path in paths:
            built[kind].append(_build_one(store, manifest.name, kind, path))
    messages = built["msg"] + [a + suffix for a in built["action"] for suffix in ACTION_SUFFIXES]
    return PackageTypes(manifest.name, messages, built["srv"], built["action"])


__all__ = ["PackageTypes", "build_types"]
