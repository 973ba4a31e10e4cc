"""Building a package's ``msg/`` and ``srv/`` types, as ``catkin_make`` checks them.

Each ``msg/<Type>.msg`` and ``srv/<Type>.srv`` is loaded as a node will load it: parsed, its
embedded types found (in the workspace, on ``ROS_PACKAGE_PATH`` or among the standard types),
its md5 sum computed and its class built. The first mistake stops the build with a report that
names the file and, where there is one, the line::

    Error(s) in message file '/home/u/catkin_ws/src/lab2/msg/Num.msg', line 2:
    Invalid declaration: int32 x y
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.parser import InvalidMsgSpecError, is_valid_type_name
from rosx.msg.spec import HEADER_TYPE, PRIMITIVE_TYPES
from rosx.msg.store import TypeStore, UnknownTypeError
from rosx.workspace.errors import BuildError

if TYPE_CHECKING:
    from rosx.packages.manifest import Manifest

_KIND_NAMES = {"msg": "message", "srv": "service"}


class PackageTypes(NamedTuple):
    """The types a package defines, by full name."""

    package: str
    messages: list[str]
    services: list[str]

    def steps(self) -> list[tuple[str, str]]:
        """``(kind, full name)`` of every type, messages first."""
        return [("msg", n) for n in self.messages] + [("srv", n) for n in self.services]

    def all_names(self) -> list[str]:
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
        else:
            store.srv(full_name)
            get_service_class(full_name, store)
    except InvalidMsgSpecError as error:
        raise _report(path, kind, str(error), error.line) from None
    except UnknownTypeError as error:
        line = _line_using(text, package, error.full_name)
        raise _report(path, kind, str(error), line) from None
    return full_name


def build_types(manifest: Manifest, package_path: list[Path]) -> PackageTypes:
    """Load every type of the package of ``manifest``, looking types up on ``package_path``.

    Raises:
        BuildError: a file is not a valid definition (see the module docstring).
    """
    store = TypeStore(package_path)
    found: dict[str, list[str]] = {"msg": [], "srv": []}
    for kind, names in found.items():
        directory = manifest.directory / kind
        if not directory.is_dir():
            continue
        for path in sorted(directory.glob(f"*.{kind}")):
            names.append(_build_one(store, manifest.name, kind, path))
    return PackageTypes(manifest.name, found["msg"], found["srv"])


__all__ = ["PackageTypes", "build_types"]
