"""Message and service classes by type name, built from a type store and cached per store.

``get_message_class("geometry_msgs/Twist")`` gives the class rospy scripts know as
``geometry_msgs.msg.Twist``; service halves (``turtlesim/SpawnRequest``) are messages too.
``get_service_class("turtlesim/Spawn")`` gives the service class with ``_request_class`` and
``_response_class``. A class is built once per store, with the classes of the types it embeds;
building needs only the store (no numpy, no textual).
"""

from __future__ import annotations

import threading
import weakref
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.codegen import Resolver, build_message_class
from rosx.msg.codec.message import Message, ServiceDefinition
from rosx.msg.parser import MAX_FIXED_ITEMS, InvalidMsgSpecError
from rosx.msg.store import TypeStore, default_store

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.spec import MsgSpec

#: genpy accepts ``Header`` alone for ``std_msgs/Header``.
_ALIASES = {"Header": "std_msgs/Header"}


class _Classes:
    """The classes built from one store."""

    def __init__(self, store: TypeStore) -> None:
        self.store = store
        self.messages: dict[str, type[Message]] = {}
        self.services: dict[str, type[ServiceDefinition]] = {}
        self.building: list[str] = []
        # Values a message of each type holds in fixed-size fields, embedded ones included.
        self.fixed_items: dict[str, int] = {}
        self.resolver = Resolver(store.msg, self.message)

    def message(self, name: str) -> type[Message]:
        cls = self.messages.get(name)
        if cls is not None:
            return cls
        if name in self.building:
            cycle = " -> ".join([*self.building[self.building.index(name) :], name])
            raise InvalidMsgSpecError(f"message types embed each other: {cycle}")
        spec = self.store.msg(name)
        self.building.append(name)
        try:
            # Embedded types first: that finds cycles before the md5 sums recurse into them.
            items = 0
            for field in spec.fields:
                each = 1
                if not field.is_builtin:
                    self.message(field.base_type)
                    each = self.fixed_items[field.base_type]
                if not field.is_array:
                    items += each
                elif field.array_len is not None:
                    items += each * field.array_len
            if items > MAX_FIXED_ITEMS:
                raise InvalidMsgSpecError(
                    f"[{name}] holds {items} values in fixed-size arrays, more than the "
                    f"{MAX_FIXED_ITEMS} supported"
                )
            self.fixed_items[name] = items
            built: type[Message] = build_message_class(
                spec,
                self.store.md5(name),
                self.store.full_text(name),
                self.resolver,
                {"__reduce__": _reduce},
            )
            service = self._service_of(name, spec)
            if service is not None:  # genpy keeps a service's halves in the service's module
                package, _, short = service.partition("/")
                built.__module__ = f"{package}.srv._{short}"
        finally:
            self.building.pop()
        self.messages[name] = built
        return built

    def _service_of(self, name: str, spec: MsgSpec) -> str | None:
        """The service whose request or response ``spec`` is, if it is one."""
        for suffix in ("Request", "Response"):
            base = name.removesuffix(suffix)
            if base != name and base.partition("/")[2] and self.store.has_srv(base):
                halves = self.store.srv(base)
                if spec is halves.request or spec is halves.response:
                    return base
        return None

    def service(self, name: str) -> type[ServiceDefinition]:
        cls = self.services.get(name)
        if cls is None:
            spec = self.store.srv(name)
            namespace = {
                "__module__": f"{spec.package}.srv._{spec.short_name}",
                "__qualname__": spec.short_name,
                "__doc__": f"The ROS 1 service type {spec.full_name}.",
                "_type": spec.full_name,
                "_md5sum": self.store.srv_md5(name),
                "_request_class": self.message(spec.request.full_name),
                "_response_class": self.message(spec.response.full_name),
            }
            cls = self.services[name] = type(spec.short_name, (ServiceDefinition,), namespace)
        return cls


def _reduce(msg: Message) -> tuple[Callable[[str], Message], tuple[str], list[Any]]:
    # Classes are built at run time, so a pickle names the type, not a module attribute.
    return _restore, (msg._type,), msg.__getstate__()


def _restore(type_name: str) -> Message:
    """An empty message of type ``type_name`` (unpickling: its state is set after)."""
    cls = get_message_class(type_name)
    return object.__new__(cls)


_lock = threading.RLock()
_by_store: weakref.WeakKeyDictionary[TypeStore, _Classes] = weakref.WeakKeyDictionary()


def _classes(store: TypeStore | None) -> _Classes:
    store = default_store() if store is None else store
    classes = _by_store.get(store)
    if classes is None:
        classes = _by_store[store] = _Classes(store)
    return classes


def get_message_class(name: str, store: TypeStore | None = None) -> type[Message]:
    """The class of message type ``name`` (``pkg/Type``); raises the store's UnknownTypeError."""
    name = _ALIASES.get(name, name)
    built = _by_store.get(default_store() if store is None else store)
    cls = None if built is None else built.messages.get(name)
    if cls is not None:
        return cls
    with _lock:
        return _classes(store).message(name)


def get_service_class(name: str, store: TypeStore | None = None) -> type[ServiceDefinition]:
    """The class of service type ``name`` (``pkg/Type``); raises the store's UnknownTypeError."""
    with _lock:
        return _classes(store).service(name)


__all__ = ["get_message_class", "get_service_class"]
