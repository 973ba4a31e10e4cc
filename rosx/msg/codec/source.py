"""Python source under construction for one generated message class, and how it is compiled.

Generated code refers to everything it needs (structs, classes, helpers) as globals of its own
namespace, bound here under short private names; locals get unique names. The compiled source
is registered with `linecache`, so tracebacks through generated methods show their lines.
"""

from __future__ import annotations

import linecache
import struct
from typing import Any

from rosx.msg.codec.wiretypes import PACK_CHARS
from rosx.msg.spec import MsgSpec

_PYTHON_KEYWORDS = frozenset(
    {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
        "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global",
        "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return",
        "try", "while", "with", "yield", "self",
    }
)  # fmt: skip


def python_name(name: str) -> str:
    """The attribute name of field or constant ``name``: Python keywords get a trailing ``_``."""
    return name + "_" if name in _PYTHON_KEYWORDS else name


def python_names(spec: MsgSpec) -> list[str]:
    """The attribute names of ``spec``'s fields (Python keywords suffixed with ``_``, as genpy
    names them)."""
    return [python_name(field.name) for field in spec.fields]


def default_expression(base_type: str) -> str | None:
    """The literal default of a primitive scalar, or None when it is not a literal."""
    if base_type == "bool":
        return "False"
    if base_type in ("float32", "float64"):
        return "0.0"
    if base_type in PACK_CHARS:
        return "0"
    if base_type == "string":
        return "''"
    return None


class Source:
    """Lines of Python plus the global names they use."""

    def __init__(self, title: str, names: dict[str, Any]) -> None:
        self.title = title
        self.lines: list[str] = []
        self.names: dict[str, Any] = dict(names)
        self._bound: dict[int, str] = {}
        self._structs: dict[str, str] = {}
        self._count = 0

    def local(self, stem: str) -> str:
        """A fresh module-global name starting with ``stem`` (``_S3``), unique within this
        source."""
        self._count += 1
        return f"_{stem}{self._count}"

    def bind(self, value: object, stem: str) -> str:
        """A global name for ``value`` (one name per object)."""
        name = self._bound.get(id(value))
        if name is None:
            name = self._bound[id(value)] = self.local(stem)
            self.names[name] = value
        return name

    def struct(self, fmt: str) -> str:
        """A global holding ``struct.Struct`` of little-endian ``fmt``."""
        name = self._structs.get(fmt)
        if name is None:
            name = self._structs[fmt] = self.local("S")
            self.names[name] = struct.Struct("<" + fmt)
        return name

    def add(self, depth: int, line: str) -> None:
        """Append ``line`` to the function, indented ``depth`` levels."""
        self.lines.append("    " * depth + line)

    def compile(self) -> dict[str, Any]:
        """Execute the source; return its namespace (the defined functions among the names)."""
        text = "\n".join(self.lines) + "\n"
        filename = f"<rosx generated {self.title}>"
        linecache.cache[filename] = (len(text), None, text.splitlines(True), filename)
        namespace = dict(self.names)
        exec(compile(text, filename, "exec"), namespace)
        return namespace
