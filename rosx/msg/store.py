"""One type store: every message, service and action type rosx knows, found lazily by name.

Sources, first match wins per type:

1. packages on the package path (``ROS_PACKAGE_PATH``): their ``msg/*.msg`` and ``srv/*.srv``,
   and the seven messages genaction makes of each ``action/*.action`` (``XAction``,
   ``XActionGoal`` …, `rosx.msg.parser.parse_action`), the first package of a name on the path
   winning, as with rospack;
2. the packages shipped with rosx (`rosx.packages.crawl`): the standard packages' original
   ``.msg`` and ``.srv`` files (comments included, for ``rosmsg show -r``), the tutorials' and
   turtlesim's types, actionlib's and its tutorials' actions;
3. rosbags' ROS 1 Noetic types, for the types no file defines (their texts rebuilt from field
   lists, `rosx.msg.standard`).

A package on the path shadows a standard one only for the types it really has: Debian's
``libroscpp-dev`` leaves ``/usr/share/roscpp`` with a manifest and no ``msg`` files, and
``roscpp/Logger`` must still resolve, since every node serves ``~get_loggers`` with it.

Packages are found through the package index (`rosx.packages.index`), the one crawl of the
package path that ``rospack``, ``rosrun`` and ``roscd`` use too. Nothing is parsed until asked
for; listing every type reads directory names, not files. Within a package a ``.msg`` file
wins over an action's message of the same name: an installed ROS 1 package holds both the
``.action`` and genaction's ``.msg`` files, which say the same.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from rosx.msg.md5 import full_text, message_md5, service_md5
from rosx.msg.parser import (
    InvalidMsgSpecError,
    is_valid_type_name,
    parse_action,
    parse_msg,
    parse_srv,
)
from rosx.msg.spec import ACTION_SUFFIXES, ActionSpec, MsgSpec, SrvSpec
from rosx.msg.standard import standard_text, standard_types
from rosx.packages.crawl import bundled_packages, split_package_path
from rosx.packages.index import PackageIndex


class UnknownTypeError(LookupError):
    """No definition of the type was found; ``package_known`` tells which part was missing."""

    def __init__(self, full_name: str, kind: str, package_known: bool) -> None:
        super().__init__(f"Cannot locate {kind} [{full_name}]")
        self.full_name = full_name
        self.kind = kind
        self.package_known = package_known


class TypeStore:
    """Message and service specs by ``pkg/Type`` name, with their md5 sums and full texts."""

    def __init__(
        self, package_path: list[Path] | None = None, *, index: PackageIndex | None = None
    ) -> None:
        """A store over ``package_path``, or over ``index`` (whose crawl it then shares)."""
        self._index = PackageIndex(package_path or []) if index is None else index
        self._msgs: dict[str, MsgSpec] = {}
        self._srvs: dict[str, SrvSpec] = {}
        self._actions: dict[str, ActionSpec] = {}
        self._md5: dict[str, str] = {}
        self._md5_pending: set[str] = set()

    @classmethod
    def from_environ(cls, environ: Mapping[str, str] | None = None) -> TypeStore:
        """The store over ``environ``'s ``ROS_PACKAGE_PATH`` (its crawl kept in ``ROS_HOME``)."""
        return cls(index=PackageIndex.from_environ(os.environ if environ is None else environ))

    # -- where definitions live -------------------------------------------------------------

    @property
    def path_packages(self) -> dict[str, Path]:
        """Packages found on the package path, by name."""
        return self._index.path_packages

    @property
    def _bundled_packages(self) -> dict[str, Path]:
        return bundled_packages()

    def package_dir(self, package: str) -> Path | None:
        """The directory of ``package`` when its definitions live in files."""
        root = self._index.on_path(package)
        return self._bundled_packages.get(package) if root is None else root

    def _directories(self, package: str, kind: str) -> list[Path]:
        """Where files of ``package`` may live, the package path's first."""
        roots = (self._index.on_path(package), self._bundled_packages.get(package))
        return [root / kind for root in roots if root is not None]

    def search_path(self, kind: str) -> dict[str, list[Path]]:
        """Every package with a directory and where its ``kind`` files may live, as rosmsg's
        search path (named in its errors)."""
        return {name: self._directories(name, kind) for name in self._index.packages}

    @property
    def package_path(self) -> list[Path]:
        """The package path the store searches for ``.msg``/``.srv``/``.action`` files (a copy)."""
        return list(self._index.package_path)

    def has_package(self, package: str) -> bool:
        """True when ``package`` is known, with or without types."""
        return self._has_package(package)

    def _has_package(self, package: str) -> bool:
        return (
            package in self._bundled_packages
            or self._index.on_path(package) is not None
            or any(name.partition("/")[0] == package for name in standard_types())
        )

    # -- lookups ---------------------------------------------------------------------------

    def msg(self, full_name: str) -> MsgSpec:
        """The spec of message ``full_name``; service halves (``pkg/SrvRequest``) included."""
        spec = self._msgs.get(full_name)
        if spec is not None:
            return spec
        text = self._msg_text(full_name)
        spec = parse_msg(full_name, text) if text is not None else self._msg_without_file(full_name)
        self._msgs[full_name] = spec
        return spec

    def srv(self, full_name: str) -> SrvSpec:
        """The parsed ``.srv`` definition of ``full_name``, read on first use and then cached.

        Raises:
            UnknownTypeError: no such service type; it says whether the package exists.
        """
        spec = self._srvs.get(full_name)
        if spec is None:
            text = self._file_text(full_name, "srv") if is_valid_type_name(full_name) else None
            if text is None:
                package = full_name.partition("/")[0]
                raise UnknownTypeError(full_name, "service", self._has_package(package))
            spec = self._srvs[full_name] = parse_srv(full_name, text)
        return spec

    def action(self, full_name: str) -> ActionSpec:
        """The spec of action ``full_name`` (``pkg/Name``, from ``action/Name.action``)."""
        spec = self._actions.get(full_name)
        if spec is None:
            text = self._file_text(full_name, "action") if is_valid_type_name(full_name) else None
            if text is None:
                package = full_name.partition("/")[0]
                raise UnknownTypeError(full_name, "action", self._has_package(package))
            spec = self._actions[full_name] = parse_action(full_name, text)
        return spec

    def has_action(self, full_name: str) -> bool:
        """Whether ``full_name`` names an action type this store can find."""
        try:
            self.action(full_name)
        except UnknownTypeError:
            return False
        return True

    def has_msg(self, full_name: str) -> bool:
        """Whether ``full_name`` names a message type this store can find."""
        try:
            self.msg(full_name)
        except UnknownTypeError:
            return False
        return True

    def has_srv(self, full_name: str) -> bool:
        """Whether ``full_name`` names a service type this store can find."""
        try:
            self.srv(full_name)
        except UnknownTypeError:
            return False
        return True

    def _msg_text(self, full_name: str) -> str | None:
        """The text of ``full_name``'s ``.msg`` file, if one defines it."""
        if not is_valid_type_name(full_name):
            return None
        return self._file_text(full_name, "msg")

    def _file_text(self, full_name: str, kind: str) -> str | None:
        package, _, short = full_name.partition("/")
        for directory in self._directories(package, kind):
            try:
                return (directory / f"{short}.{kind}").read_text(encoding="utf-8")
            except FileNotFoundError:
                continue
            except (OSError, UnicodeDecodeError):
                return None
        return None

    def _msg_without_file(self, full_name: str) -> MsgSpec:
        """A half of a service, else a message of an action, else a standard type (no standard
        name ends with ``Request`` or ``Response``, so the order changes no answer; it spares
        every node's logger services the standard types' loading)."""
        for suffix in ("Request", "Response"):
            if full_name.endswith(suffix) and len(full_name) > len(suffix):
                try:
                    service = self.srv(full_name[: -len(suffix)])
                except UnknownTypeError:
                    break
                return service.request if suffix == "Request" else service.response
        generated = self._action_message(full_name)
        if generated is not None:
            return generated
        text = standard_text(full_name) if is_valid_type_name(full_name) else None
        if text is not None:
            return parse_msg(full_name, text)
        package = full_name.partition("/")[0]
        raise UnknownTypeError(full_name, "message", self._has_package(package))

    def _action_message(self, full_name: str) -> MsgSpec | None:
        """The message ``full_name`` as an action of its package generates it, if one does.

        ``XActionGoal`` is the ``ActionGoal`` of action ``X`` or the ``Goal`` of action
        ``XAction``: the longest suffix whose action exists wins.
        """
        if not is_valid_type_name(full_name):
            return None
        for suffix in sorted(ACTION_SUFFIXES, key=len, reverse=True):
            stem = full_name[: -len(suffix)]
            if full_name.endswith(suffix) and not stem.endswith("/"):
                try:
                    return self.action(stem).message(suffix)
                except UnknownTypeError:
                    continue
        return None

    # -- sums and texts --------------------------------------------------------------------

    def md5(self, full_name: str) -> str:
        """The md5sum of message ``full_name``."""
        cached = self._md5.get(full_name)
        if cached is None:
            if full_name in self._md5_pending:
                raise InvalidMsgSpecError(f"[{full_name}] embeds itself")
            self._md5_pending.add(full_name)
            try:
                cached = message_md5(self.msg(full_name), self.msg, self.md5)
            finally:
                self._md5_pending.discard(full_name)
            self._md5[full_name] = cached
        return cached

    def srv_md5(self, full_name: str) -> str:
        """The service's md5sum as ROS 1 computes it (request and response text together),
        cached."""
        key = "srv:" + full_name
        cached = self._md5.get(key)
        if cached is None:
            cached = self._md5[key] = service_md5(self.srv(full_name), self.msg, self.md5)
        return cached

    def full_text(self, full_name: str) -> str:
        """The ``message_definition`` of message ``full_name``."""
        return full_text(self.msg(full_name), self.msg)

    # -- listings --------------------------------------------------------------------------

    def types(self, kind: str) -> list[str]:
        """Every ``pkg/Type`` of ``kind`` (``msg``, ``srv`` or ``action``), sorted; messages
        include those of actions."""
        names: set[str] = set()
        for packages in (self._bundled_packages, self.path_packages):
            for package, root in packages.items():
                directory = root / kind
                if directory.is_dir():
                    names.update(f"{package}/{e.stem}" for e in directory.glob("*." + kind))
        if kind == "msg":
            names.update(standard_types())
            for action in self.types("action"):
                names.update(action + suffix for suffix in ACTION_SUFFIXES)
        return sorted(names)

    def packages(self, kind: str) -> list[str]:
        """Packages holding types of ``kind``, sorted."""
        return sorted({name.partition("/")[0] for name in self.types(kind)})

    def find(self, short_name: str, kind: str) -> list[str]:
        """Full names of every type of ``kind`` whose bare name is ``short_name``."""
        return [n for n in self.types(kind) if n.partition("/")[2] == short_name]


_default: TypeStore | None = None


def default_store() -> TypeStore:
    """The process-wide store over ``ROS_PACKAGE_PATH`` as it was at first use."""
    global _default  # noqa: PLW0603 - one lazily built store a process
    if _default is None:
        _default = TypeStore.from_environ()
    return _default


def share_package_index(index: PackageIndex) -> None:
    """Let the process-wide store find packages through ``index`` (one crawl of the package path
    a process, not one for the program and one for its types): done when the store is not built
    yet and ``index`` covers the package path it would cover; nothing otherwise."""
    global _default  # noqa: PLW0603 - see default_store
    if _default is None and index.package_path == split_package_path(
        os.environ.get("ROS_PACKAGE_PATH")
    ):
        _default = TypeStore(index=index)


__all__ = [
    "InvalidMsgSpecError",
    "TypeStore",
    "UnknownTypeError",
    "default_store",
    "share_package_index",
]
