"""``<package>.msg`` and ``<package>.srv`` as Python modules, served from the type store.

genpy lays out a package's generated Python as ``<package>/msg/__init__.py`` exporting every
message class (and ``<package>/msg/_<Type>.py`` per type), the same for ``srv`` with
``<Service>``, ``<Service>Request`` and ``<Service>Response``. `install` puts two import
finders in place that give the same layout without any generated file, so that
``from geometry_msgs.msg import Twist``, ``import std_msgs.msg`` and
``from std_srvs.srv import Empty, EmptyResponse`` give rosx's classes
(`rosx.msg.codec.classes`), for the standard packages, turtlesim and the packages on
``ROS_PACKAGE_PATH``:

* ``<package>.msg``, ``<package>.srv`` and ``<package>.msg._<Type>``: served first, before any
  other finder, whenever the type store knows the package's types of that kind, so a ROS 1
  installation's generated modules never mix with rosx's classes;
* the top-level ``<package>``: served last, only when no other finder has it, so that a real
  Python package of that name keeps working.

Classes are built on first access (module ``__getattr__``), not when the module is imported.
"""

from __future__ import annotations

import functools
import importlib
import importlib.abc
import importlib.machinery
import sys
import threading
import types
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx.msg.store import TypeStore

_KINDS = ("msg", "srv")
#: Set while a finder consults the type store, whose own imports must not come back here.
_busy = threading.local()


def _store() -> TypeStore:
    from rosx.msg.store import default_store  # noqa: PLC0415 - the store loads on first import

    return default_store()


@functools.cache
def _type_names(package: str, kind: str) -> tuple[str, ...]:
    """The bare names of ``package``'s types of ``kind`` (``Twist`` …), sorted."""
    store = _store()
    if not store.has_package(package):
        return ()
    return tuple(n.partition("/")[2] for n in store.types(kind) if n.partition("/")[0] == package)


def _exports(package: str, kind: str, names: Sequence[str]) -> list[str]:
    if kind == "msg":
        return list(names)
    return [f"{n}{suffix}" for n in names for suffix in ("", "Request", "Response")]


def _lookup(package: str, kind: str, name: str) -> type:
    from rosx.msg.codec.classes import get_message_class, get_service_class  # noqa: PLC0415 - message classes load on first use

    if kind == "srv":
        for suffix in ("Request", "Response"):
            if name.endswith(suffix) and name[: -len(suffix)] in _type_names(package, kind):
                return get_message_class(f"{package}/{name}")
        return get_service_class(f"{package}/{name}")
    return get_message_class(f"{package}/{name}")


class TypeModule(types.ModuleType):
    """``<package>.msg`` or ``<package>.srv`` (or one type's ``_<Type>`` module)."""

    def __init__(self, fullname: str, package: str, kind: str, only: str | None = None) -> None:
        super().__init__(fullname, f"The ROS 1 {kind} types of package {package}.")
        self._ros_package = package
        self._ros_kind = kind
        self._ros_only = only

    def _ros_exports(self) -> list[str]:
        if self._ros_only is not None:
            return _exports(self._ros_package, self._ros_kind, [self._ros_only])
        names = _type_names(self._ros_package, self._ros_kind)
        return _exports(self._ros_package, self._ros_kind, names)

    def __getattr__(self, name: str) -> Any:
        if name == "__all__":
            return self._ros_exports()
        if name.startswith("__") or name not in self._ros_exports():
            raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")
        value = _lookup(self._ros_package, self._ros_kind, name)
        setattr(self, name, value)
        return value

    def __dir__(self) -> list[str]:
        return sorted({*super().__dir__(), *self._ros_exports()})


class _Loader(importlib.abc.Loader):
    """Creates the modules the finders promise; there is no code to run."""

    def __init__(self, package: str, kind: str | None, only: str | None = None) -> None:
        self.package = package
        self.kind = kind
        self.only = only

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType:
        if self.kind is None:
            module = types.ModuleType(spec.name, f"The ROS 1 package {self.package}.")
        else:
            module = TypeModule(spec.name, self.package, self.kind, self.only)
        return module

    def exec_module(self, module: types.ModuleType) -> None:
        return None


def _spec(fullname: str, loader: _Loader, package: bool) -> importlib.machinery.ModuleSpec:
    spec = importlib.machinery.ModuleSpec(fullname, loader, is_package=package)
    if package:
        spec.submodule_search_locations = []
    return spec


class TypeModuleFinder(importlib.abc.MetaPathFinder):
    """Serves ``<package>.msg``, ``<package>.srv`` and their ``_<Type>`` modules (first)."""

    def find_spec(
        self,
        fullname: str,
        path: Sequence[str] | None,
        target: types.ModuleType | None = None,
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for ``<pkg>.msg``/``<pkg>.srv`` or one of their ``_<Type>`` modules when the
        type store knows such types, else None so the next finder is asked."""
        parts = fullname.split(".")
        if len(parts) not in (2, 3) or parts[1] not in _KINDS or parts[0] == "rosx":
            return None
        if len(parts) == 3 and not parts[2].startswith("_"):
            return None
        if getattr(_busy, "active", False):
            return None  # the store being imported while a lookup runs: not a message module
        _busy.active = True
        try:
            names = _type_names(parts[0], parts[1])
        finally:
            _busy.active = False
        package, kind = parts[0], parts[1]
        if not names:
            return None
        if len(parts) == 2:
            return _spec(fullname, _Loader(package, kind), package=True)
        only = parts[2][1:]
        if only not in names:
            return None
        return _spec(fullname, _Loader(package, kind, only), package=False)


class PackageFinder(importlib.abc.MetaPathFinder):
    """Serves a message package's top-level module when nothing else provides it (last)."""

    def find_spec(
        self,
        fullname: str,
        path: Sequence[str] | None,
        target: types.ModuleType | None = None,
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for a message package's top-level module (``std_msgs``) when the store has its
        types and no other finder served it; else None."""
        if "." in fullname or getattr(_busy, "active", False):
            return None
        _busy.active = True
        try:
            known = any(_type_names(fullname, kind) for kind in _KINDS)
        finally:
            _busy.active = False
        return _spec(fullname, _Loader(fullname, None), package=True) if known else None


#: The Python helpers ROS 1 ships beside a package's generated modules, by module name: the
#: rosx module that serves each.
HELPERS = {"sensor_msgs.point_cloud2": "rosx.client.point_cloud2"}


class _HelperLoader(importlib.abc.Loader):
    """A helper module: a new module of that name with the names of rosx's."""

    def __init__(self, source: str) -> None:
        self.source = source

    def exec_module(self, module: types.ModuleType) -> None:
        served = importlib.import_module(self.source)
        module.__doc__ = served.__doc__
        for name in dir(served):
            if not name.startswith("__"):
                setattr(module, name, getattr(served, name))


class HelperFinder(importlib.abc.MetaPathFinder):
    """Serves `HELPERS` when nothing else provides them (last), so a ROS 1 installation's
    own helper modules keep working."""

    def find_spec(
        self,
        fullname: str,
        path: Sequence[str] | None,
        target: types.ModuleType | None = None,
    ) -> importlib.machinery.ModuleSpec | None:
        """A spec for one of `HELPERS` (ROS 1's helper modules rosx serves itself), else None."""
        source = HELPERS.get(fullname)
        if source is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, _HelperLoader(source))


def install() -> None:
    """Put the finders in place (once a process)."""
    finders = sys.meta_path
    if not any(isinstance(f, TypeModuleFinder) for f in finders):
        finders.insert(0, TypeModuleFinder())
    if not any(isinstance(f, PackageFinder) for f in finders):
        finders.append(PackageFinder())
    if not any(isinstance(f, HelperFinder) for f in finders):
        finders.append(HelperFinder())


__all__ = ["HELPERS", "HelperFinder", "PackageFinder", "TypeModule", "TypeModuleFinder", "install"]
