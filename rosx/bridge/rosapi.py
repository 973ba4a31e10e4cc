"""rosapi: services that describe the graph, the types and the parameters to bridge clients.

The services of rosbridge_suite's ``rosapi_node`` (0.11), with its ``rosapi/*`` types (bundled
in ``rosx/packages/noetic/share/rosapi``), served under the node's private names
(``/rosapi/topics``…). Parameter values travel as JSON text, as rosapi's do. Type
descriptions (`typedefs`) follow rosapi's ``TypeDef``: one per type met, depth first, each
with its fields' base types, array lengths (-1 scalar, 0 variable, N fixed), example values,
and constants by name.

Everything goes through the node's public API (its master client and parameter client);
the graph's shape comes from `rosx.graph.state.GraphState`. ``topics_and_raw_types`` asks
the master twice, whatever the number of topics, and the type texts are cached per type.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from rosx.graph.state import GraphState, registrations
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.msg.codec.source import python_name
from rosx.node.clock import now

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message
    from rosx.msg.spec import MsgSpec
    from rosx.node import Node, ServiceHandle

_ATOMICS = frozenset(
    [
        "bool",
        "byte",
        "char",
        "int8",
        "uint8",
        "int16",
        "uint16",
        "int32",
        "uint32",
        "int64",
        "uint64",
        "float32",
        "float64",
        "string",
    ]
)
_TIMES = ("time", "duration")
_ACTION_TOPICS = ("cancel", "feedback", "goal", "result", "status")


class RosApi:
    """rosapi's services on ``node`` (named ``rosapi`` to be found where clients look)."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.handles: list[ServiceHandle] = []
        self._full_texts: dict[str, str] = {}

    def advertise(self) -> RosApi:
        """Serve every service; returns self."""
        table: dict[str, tuple[str, Callable[[Any], dict[str, Any]]]] = {
            "topics": ("Topics", self.topics),
            "topics_for_type": ("TopicsForType", self.topics_for_type),
            "topics_and_raw_types": ("TopicsAndRawTypes", self.topics_and_raw_types),
            "topic_type": ("TopicType", self.topic_type),
            "publishers": ("Publishers", self.publishers),
            "subscribers": ("Subscribers", self.subscribers),
            "services": ("Services", self.services),
            "services_for_type": ("ServicesForType", self.services_for_type),
            "service_type": ("ServiceType", self.service_type),
            "service_node": ("ServiceNode", self.service_node),
            "service_host": ("ServiceHost", self.service_host),
            "service_providers": ("ServiceProviders", self.service_providers),
            "nodes": ("Nodes", self.nodes),
            "node_details": ("NodeDetails", self.node_details),
            "action_servers": ("GetActionServers", self.action_servers),
            "get_param": ("GetParam", self.get_param),
            "set_param": ("SetParam", self.set_param),
            "has_param": ("HasParam", self.has_param),
            "search_param": ("SearchParam", self.search_param),
            "delete_param": ("DeleteParam", self.delete_param),
            "get_param_names": ("GetParamNames", self.get_param_names),
            "get_time": ("GetTime", self.get_time),
            "message_details": ("MessageDetails", self.message_details),
            "service_request_details": ("ServiceRequestDetails", self.service_request_details),
            "service_response_details": ("ServiceResponseDetails", self.service_response_details),
        }
        for name, (srv_type, handler) in table.items():
            service_class = get_service_class(f"rosapi/{srv_type}")
            response_class = service_class._response_class
            self.handles.append(
                self.node.advertise_service(
                    f"~{name}", service_class, _answer(handler, response_class)
                )
            )
        return self

    def _state(self) -> GraphState:
        return registrations(self.node.master, types=True)

    # -- topics ---------------------------------------------------------------------------------

    def topics(self, request: Any) -> dict[str, Any]:
        """``~topics``: every topic the master knows, with its type ("" if unknown)."""
        state = self._state()
        names = state.topics
        return {"topics": names, "types": [state.topic_types.get(t, "") for t in names]}

    def topics_for_type(self, request: Any) -> dict[str, Any]:
        """``~topics_for_type``: the topics of type ``request.type``, sorted."""
        types = self.node.master.topic_types()
        return {"topics": sorted(t for t, kind in types.items() if kind == request.type)}

    def topics_and_raw_types(self, request: Any) -> dict[str, Any]:
        """``~topics_and_raw_types``: as ``~topics``, with each type's full definition text (a
        connection header's ``message_definition``; "" for a type the bridge cannot load)."""
        state = self._state()
        names = state.topics
        types = [state.topic_types.get(t, "") for t in names]
        return {
            "topics": names,
            "types": types,
            "typedefs_full_text": [self._full(t) for t in types],
        }

    def _full(self, type_name: str) -> str:
        text = self._full_texts.get(type_name)
        if text is None:
            try:
                text = get_message_class(type_name)._full_text
            except Exception:  # a type only its publisher knows
                text = ""
            self._full_texts[type_name] = text
        return text

    def topic_type(self, request: Any) -> dict[str, Any]:
        """``~topic_type``: ``request.topic``'s type, or "" if the master does not know it."""
        return {"type": self.node.master.topic_types().get(request.topic, "")}

    def publishers(self, request: Any) -> dict[str, Any]:
        """``~publishers``: the nodes publishing ``request.topic``."""
        return {"publishers": list(self._state().publishers.get(request.topic, ()))}

    def subscribers(self, request: Any) -> dict[str, Any]:
        """``~subscribers``: the nodes subscribing to ``request.topic``."""
        return {"subscribers": list(self._state().subscribers.get(request.topic, ()))}

    def action_servers(self, request: Any) -> dict[str, Any]:
        """``~action_servers``: the namespaces that have all five action topics (goal, cancel,
        status, feedback, result), sorted."""
        by_namespace: dict[str, set[str]] = {}
        for topic in self._state().topics:
            namespace, _, last = topic.rpartition("/")
            if namespace and last in _ACTION_TOPICS:
                by_namespace.setdefault(namespace, set()).add(last)
        found = [
            ns for ns, seen in sorted(by_namespace.items()) if len(seen) == len(_ACTION_TOPICS)
        ]
        return {"action_servers": found}

    # -- services -------------------------------------------------------------------------------

    def services(self, request: Any) -> dict[str, Any]:
        """``~services``: every service the master knows, sorted."""
        return {"services": sorted(self._state().services)}

    def _type_of(self, service: str) -> str:
        try:
            return self.node.probe_service(service, timeout=2.0).get("type", "")
        except Exception:  # a service that is gone or does not answer has no type to tell
            return ""

    def service_type(self, request: Any) -> dict[str, Any]:
        """``~service_type``: ``request.service``'s type, asked of its provider; "" if it does
        not answer."""
        return {"type": self._type_of(request.service)}

    def services_for_type(self, request: Any) -> dict[str, Any]:
        """``~services_for_type``: the services of type ``request.type`` (each provider asked)."""
        names = sorted(self._state().services)
        return {"services": [s for s in names if self._type_of(s) == request.type]}

    def service_node(self, request: Any) -> dict[str, Any]:
        """``~service_node``: the node providing ``request.service``, or ""."""
        providers = self._state().services.get(request.service, ())
        return {"node": providers[0] if providers else ""}

    def service_host(self, request: Any) -> dict[str, Any]:
        """``~service_host``: the host name in the provider's ``rosrpc://`` URI, or ""."""
        from urllib.parse import urlsplit  # noqa: PLC0415 - only this service needs it

        uri = self.node.master.lookup_service(request.service) or ""
        return {"host": urlsplit(uri).hostname or ""}

    def service_providers(self, request: Any) -> dict[str, Any]:
        """``~service_providers``: the nodes providing a service of type ``request.service``
        (rosapi's field name, though it holds a type)."""
        found: list[str] = []
        for service, nodes in sorted(self._state().services.items()):
            if self._type_of(service) == request.service:
                found += nodes
        return {"providers": found}

    # -- nodes ----------------------------------------------------------------------------------

    def nodes(self, request: Any) -> dict[str, Any]:
        """``~nodes``: every node with a registration."""
        return {"nodes": self._state().nodes}

    def node_details(self, request: Any) -> dict[str, Any]:
        """``~node_details``: the topics ``request.node`` subscribes to and publishes, and its
        services."""
        state = self._state()
        node = request.node

        def of(section: Any) -> list[str]:
            return sorted(name for name, nodes in section.items() if node in nodes)

        return {
            "subscribing": of(state.subscribers),
            "publishing": of(state.publishers),
            "services": of(state.services),
        }

    # -- parameters -----------------------------------------------------------------------------

    def get_param(self, request: Any) -> dict[str, Any]:
        """``~get_param``: the value at ``request.name`` as JSON; ``request.default`` (JSON, or
        the text itself) when it is unset."""
        default: Any = None
        if request.default != "":
            try:
                default = json.loads(request.default)
            except ValueError:
                default = request.default
        return {"value": json.dumps(self.node.params.get(request.name, default))}

    def set_param(self, request: Any) -> dict[str, Any]:
        """``~set_param``: set ``request.name`` to the JSON in ``request.value``; text that is
        not JSON raises rosapi's error."""
        try:
            value = json.loads(request.value)
        except ValueError:
            raise ValueError(
                "Due to the type flexibility of the ROS parameter server, the value argument "
                "to set_param must be a JSON-formatted string."
            ) from None
        self.node.params.set(request.name, value)
        return {}

    def has_param(self, request: Any) -> dict[str, Any]:
        """``~has_param``: whether ``request.name`` is set."""
        return {"exists": self.node.params.has(request.name)}

    def search_param(self, request: Any) -> dict[str, Any]:
        """``~search_param``: the nearest ``request.name`` upwards from the bridge's namespace,
        or ""."""
        return {"global_name": self.node.params.search(request.name) or ""}

    def delete_param(self, request: Any) -> dict[str, Any]:
        """``~delete_param``: delete ``request.name``; an unset name is not an error."""
        if self.node.params.has(request.name):
            self.node.params.delete(request.name)
        return {}

    def get_param_names(self, request: Any) -> dict[str, Any]:
        """``~get_param_names``: every parameter's full name."""
        return {"names": self.node.params.names()}

    def get_time(self, request: Any) -> dict[str, Any]:
        """``~get_time``: the node's ROS time (sim time under ``/use_sim_time``)."""
        return {"time": now()}

    # -- types ----------------------------------------------------------------------------------

    def message_details(self, request: Any) -> dict[str, Any]:
        """``~message_details``: the typedefs of ``request.type`` and the types it holds, as
        roslibjs reads them."""
        return {"typedefs": typedefs(request.type)}

    def service_request_details(self, request: Any) -> dict[str, Any]:
        """``~service_request_details``: the typedefs of service ``request.type``'s request."""
        return {"typedefs": _typedefs_of(get_service_class(request.type)._request_class)}

    def service_response_details(self, request: Any) -> dict[str, Any]:
        """``~service_response_details``: the typedefs of service ``request.type``'s response."""
        return {"typedefs": _typedefs_of(get_service_class(request.type)._response_class)}


def _answer(
    handler: Callable[[Any], dict[str, Any]], response_class: type[Message]
) -> Callable[[Any], Message]:
    def serve(request: Any) -> Message:
        return response_class(**handler(request))

    return serve


def typedefs(type_name: str) -> list[Message]:
    """rosapi's ``TypeDef`` of ``type_name`` and of every type in it (each once, depth first)."""
    if type_name in _ATOMICS:
        return []
    if type_name in _TIMES:
        return [_time_typedef(type_name)]
    return _typedefs_of(get_message_class(type_name))


def _typedefs_of(cls: type[Message], seen: set[str] | None = None) -> list[Message]:
    seen = set() if seen is None else seen
    spec = cls._spec
    assert spec is not None, f"{cls._type} has no definition"
    seen.add(spec.full_name)
    found = [_typedef(spec, cls())]
    for field in spec.fields:
        base = field.base_type
        if base in seen or base in _ATOMICS:
            continue
        if base in _TIMES:
            seen.add(base)
            found.append(_time_typedef(base))
        else:
            found += _typedefs_of(get_message_class(base), seen)
    return found


def _typedef(spec: MsgSpec, example: Message) -> Message:
    typedef_class = get_message_class("rosapi/TypeDef")
    examples = []
    for field in spec.fields:
        if field.is_array:
            examples.append("[]")
        elif field.base_type in _ATOMICS or field.base_type in _TIMES:
            examples.append(str(getattr(example, python_name(field.name))))
        else:
            examples.append("{}")
    constants = sorted(spec.constants, key=lambda c: c.name)
    return typedef_class(
        type=spec.full_name,
        fieldnames=[f.name for f in spec.fields],
        fieldtypes=[f.base_type for f in spec.fields],
        fieldarraylen=[-1 if not f.is_array else (f.array_len or 0) for f in spec.fields],
        examples=examples,
        constnames=[c.name for c in constants],
        constvalues=[str(c.value) for c in constants],
    )


def _time_typedef(kind: str) -> Message:
    return get_message_class("rosapi/TypeDef")(
        type=kind,
        fieldnames=["secs", "nsecs"],
        fieldtypes=["int32", "int32"],
        fieldarraylen=[-1, -1],
        examples=["0", "0"],
        constnames=[],
        constvalues=[],
    )


__all__ = ["RosApi", "typedefs"]
