"""What ``catkin_python_setup()`` needs of a package's ``setup.py``, read without running it.

catkin runs ``setup.py`` with ``setup()`` replaced by a recorder, and keeps ``packages``,
``package_dir``, ``py_modules`` and ``scripts``. rosx runs no code of a package at build time:
it parses the file (`ast`) and works out those four arguments from the few forms ``setup.py``
files take: literals, names assigned before (also ``d["packages"] = …`` and ``+=``),
catkin_pkg's ``generate_distutils_setup(…)`` (its keywords, with the name and version of
``package.xml``), ``dict(…)``, ``find_packages(where, exclude)`` and ``+`` of lists. What it
needs and cannot work out is `NotUnderstood`, with the line: ``catkin_make`` says so rather
than guess.

`read_setup_py` does no I/O; ``find_packages`` is given to it.
"""

from __future__ import annotations

import ast
import fnmatch
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from collections.abc import Callable

#: The arguments of ``setup()`` that catkin's devel space does not support: catkin names them
#: on stderr, and so does rosx.
UNSUPPORTED = (
    "entry_points",
    "exclude_package_data",
    "ext_package",
    "include_package_data",
    "namespace_packages",
    "setup_requires",
    "use_2to3",
    "zip_safe",
)

#: The arguments that say what becomes importable or runnable.
_NEEDED = ("packages", "package_dir", "py_modules", "scripts")


class PythonSetup(NamedTuple):
    """The arguments of a ``setup()`` call that ``catkin_python_setup()`` carries out."""

    line: int
    version: str | None
    packages: list[str]
    package_dir: dict[str, str]
    modules: list[str]
    scripts: list[str]
    unsupported: list[str]


class NotUnderstood(NamedTuple):
    """The part of ``setup.py`` (its line and text) that rosx cannot work out without running it."""

    line: int
    text: str


class _Unknown(NamedTuple):
    """A value that depends on running code: where it comes from."""

    node: ast.AST


_SETUP = {"setuptools.setup", "distutils.core.setup", "setup"}
_GENERATE = {"catkin_pkg.python_setup.generate_distutils_setup", "generate_distutils_setup"}
_FIND = {"setuptools.find_packages", "find_packages"}


class _Reader:
    """The evaluation of one ``setup.py``'s module body, statement by statement."""

    def __init__(self, name: str, version: str, find: Callable[[str], list[str]]) -> None:
        self.name = name
        self.version = version
        self.find = find
        self.values: dict[str, object] = {}
        self.imported: dict[str, str] = {}

    def qualified(self, node: ast.expr) -> str | None:
        """The dotted name ``node`` stands for, through the imports seen."""
        if isinstance(node, ast.Name):
            return self.imported.get(node.id, node.id if node.id not in self.values else None)
        if isinstance(node, ast.Attribute):
            base = self.qualified(node.value)
            return None if base is None else f"{base}.{node.attr}"
        return None

    def statement(self, node: ast.stmt) -> ast.Call | None:
        """Take in one statement; the ``setup()`` call when it is one."""
        if isinstance(node, ast.Import):
            for alias in node.names:
                local = alias.asname or alias.name.partition(".")[0]
                self.imported[local] = alias.name if alias.asname else local
        elif isinstance(node, ast.ImportFrom) and node.module:
            for alias in node.names:
                self.imported[alias.asname or alias.name] = f"{node.module}.{alias.name}"
        elif isinstance(node, ast.Expr) and isinstance(node.value, ast.Call):
            if self.qualified(node.value.func) in _SETUP:
                return node.value
        elif isinstance(node, ast.Assign) and len(node.targets) == 1:
            self.assign(node.targets[0], self.value(node.value), node)
        elif isinstance(node, ast.AugAssign) and isinstance(node.op, ast.Add):
            before = self.value(node.target)
            self.assign(node.target, _add(before, self.value(node.value), node), node)
        else:
            self.forget(node)
        return None

    def assign(self, target: ast.expr, value: object, node: ast.stmt) -> None:
        if isinstance(target, ast.Name):
            self.values[target.id] = value
            return
        if isinstance(target, ast.Subscript) and isinstance(target.value, ast.Name):
            mapping = self.values.get(target.value.id)
            key = self.value(target.slice)
            if isinstance(mapping, dict) and isinstance(key, str):
                mapping[key] = value
                return
        self.forget(node)

    def forget(self, node: ast.stmt) -> None:
        """Names that a statement rosx does not follow binds depend on running it."""
        for child in ast.walk(node):
            if isinstance(child, ast.Name) and isinstance(child.ctx, ast.Store):
                self.values[child.id] = _Unknown(node)
            elif isinstance(child, (ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef)):
                self.values[child.name] = _Unknown(node)
            elif (
                isinstance(child, ast.Subscript)
                and isinstance(child.ctx, ast.Store)
                and isinstance(child.value, ast.Name)
            ):
                self.values[child.value.id] = _Unknown(node)

    def value(self, node: ast.expr) -> object:
        """What ``node`` evaluates to, or `_Unknown` where that needs running code."""
        if isinstance(node, ast.Constant) and isinstance(node.value, (str, int, float, bool)):
            return node.value
        if isinstance(node, (ast.List, ast.Tuple)):
            items = [self.value(item) for item in node.elts]
            return next((i for i in items if isinstance(i, _Unknown)), items)
        if isinstance(node, ast.Dict):
            return self.mapping(node)
        if isinstance(node, ast.Name):
            known = self.values.get(node.id, _Unknown(node))
            return dict(known) if isinstance(known, dict) else known
        if isinstance(node, ast.Subscript):
            mapping, key = self.value(node.value), self.value(node.slice)
            if isinstance(mapping, dict) and isinstance(key, str) and key in mapping:
                return mapping[key]
            return _Unknown(node)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            return _add(self.value(node.left), self.value(node.right), node)
        if isinstance(node, ast.Call):
            return self.call(node)
        return _Unknown(node)

    def mapping(self, node: ast.Dict) -> object:
        result: dict[str, object] = {}
        for key, item in zip(node.keys, node.values, strict=True):
            if key is None:
                merged = self.value(item)
                if not isinstance(merged, dict):
                    return _Unknown(item)
                result.update(merged)
                continue
            name = self.value(key)
            if not isinstance(name, str):
                return _Unknown(key)
            result[name] = self.value(item)
        return result

    def keywords(self, node: ast.Call) -> dict[str, object] | _Unknown:
        """The keyword arguments of a call (``**`` expanded); positional ones are not read."""
        if node.args:
            return _Unknown(node.args[0])
        found: dict[str, object] = {}
        for keyword in node.keywords:
            given = self.value(keyword.value)
            if keyword.arg is not None:
                found[keyword.arg] = given
            elif isinstance(given, dict):
                found.update(given)
            else:
                return given if isinstance(given, _Unknown) else _Unknown(keyword.value)
        return found

    def call(self, node: ast.Call) -> object:
        called = self.qualified(node.func)
        if called in _GENERATE or called == "dict":
            given = self.keywords(node)
            if called == "dict" or isinstance(given, _Unknown):
                return given
            return {"name": self.name, "version": self.version, **given}
        if called in _FIND:
            return self.find_packages(node)
        return _Unknown(node)

    def find_packages(self, node: ast.Call) -> object:
        """``find_packages(where='.', exclude=())`` as setuptools answers it."""
        arguments = dict(zip(("where", "exclude"), node.args, strict=False))
        arguments.update({k.arg: k.value for k in node.keywords if k.arg is not None})
        if any(k.arg is None for k in node.keywords) or set(arguments) - {"where", "exclude"}:
            return _Unknown(node)
        where = self.value(arguments["where"]) if "where" in arguments else "."
        exclude = _strings(self.value(arguments["exclude"]) if "exclude" in arguments else [])
        if not isinstance(where, str) or exclude is None:
            return _Unknown(node)
        return [
            name
            for name in self.find(where)
            if not any(fnmatch.fnmatchcase(name, pattern) for pattern in exclude)
        ]


def _add(left: object, right: object, node: ast.AST) -> object:
    for side in (left, right):
        if isinstance(side, _Unknown):
            return side
    if isinstance(left, list) and isinstance(right, list):
        return left + right
    if isinstance(left, str) and isinstance(right, str):
        return left + right
    return _Unknown(node)


def _strings(value: object) -> list[str] | None:
    """``value`` when it is a list of strings."""
    if isinstance(value, list) and all(isinstance(item, str) for item in value):
        return value
    return None


def _not_understood(text: str, node: ast.AST) -> NotUnderstood:
    line = getattr(node, "lineno", 1)
    part = ast.get_source_segment(text, node) or ast.dump(node)
    return NotUnderstood(line, " ".join(part.split()))


def read_setup_py(
    text: str, name: str, version: str, find_packages: Callable[[str], list[str]]
) -> PythonSetup | NotUnderstood:
    """The arguments of the ``setup()`` call of the ``setup.py`` source ``text``.

    Args:
        text: the file's source.
        name: the package's name (``package.xml``), which ``generate_distutils_setup`` gives.
        version: the package's version (``package.xml``), likewise.
        find_packages: setuptools' ``find_packages(where)``: the packages below ``where``
            (relative to the package's folder), dotted.
    """
    try:
        tree = ast.parse(text)
    except SyntaxError as error:
        return NotUnderstood(error.lineno or 1, f"invalid syntax: {error.msg}")
    reader = _Reader(name, version, find_packages)
    for statement in tree.body:
        call = reader.statement(statement)
        if call is not None:
            break
    else:
        return NotUnderstood(1, "no setup() call at the top level")
    arguments = reader.keywords(call)
    if isinstance(arguments, _Unknown):
        return _not_understood(text, arguments.node)
    for key in _NEEDED:
        given = arguments.get(key)
        if isinstance(given, _Unknown):
            return _not_understood(text, given.node)
    packages = _strings(arguments.get("packages", []))
    modules = _strings(arguments.get("py_modules", []))
    scripts = _strings(arguments.get("scripts", []))
    package_dir = arguments.get("package_dir", {})
    folders = _strings(list(package_dir.values())) if isinstance(package_dir, dict) else None
    if packages is None or modules is None or scripts is None or folders is None:
        return _not_understood(text, call)
    assert isinstance(package_dir, dict)
    version_given = arguments.get("version")
    return PythonSetup(
        line=call.lineno,
        version=version_given if isinstance(version_given, str) else None,
        packages=packages,
        package_dir={str(k): str(v) for k, v in package_dir.items()},
        modules=modules,
        scripts=scripts,
        unsupported=[key for key in UNSUPPORTED if key in arguments],
    )


__all__ = ["UNSUPPORTED", "NotUnderstood", "PythonSetup", "read_setup_py"]
