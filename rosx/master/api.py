"""The Master API and Parameter API methods (ROS wiki Master_API, Parameter Server API), as
rosmaster answers them: same checks, same reply codes, same status texts.

`MasterApi` turns each call's parameters into a ``[code, statusMessage, value]`` reply, updating
the `Registry` and the `ParamTree`; the calls it owes to nodes go to the injected `notify`.
It does no I/O, so it can be driven directly in tests; `rosx.master.server` puts it behind
XML-RPC.

Every method takes the caller id first. Before a method runs, as in rosmaster: no parameters at
all gives ``-1 "missing required caller_id parameter"``; the wrong number gives
``-1 "Error: bad call arity"``; a caller id that is not a string gives
``-1 "caller_id must be a string"``; an argument failing its check gives ``-1`` with the check's
message. While it runs, a `TypeError` gives ``-1 "Error: invalid arguments: ..."`` and any other
exception ``0 "Internal failure: ..."``. Each method has its own value for those replies.

``getSystemState`` and ``getTopicTypes`` replies are encoded once per registry change and served
as bytes until the next one.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

from rosx.master.params import ParamTree, namespace_key, param_updates
from rosx.master.registry import Registry
from rosx.master.validation import (
    InvalidArgument,
    empty_or_valid_name,
    is_api,
    is_topic,
    non_empty_str,
    not_none,
    resolve_for_caller,
    valid_name,
    valid_type_name,
)
from rosx.transport.server import EncodedResponse

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from rosx.master.actions import Action
    from rosx.master.validation import Check

Reply = tuple[int, str, Any]


class _Spec(NamedTuple):
    error_value: Any
    checks: tuple[Check | None, ...]
    run: Callable[..., Reply | EncodedResponse]


def _ignore(actions: Sequence[Action]) -> None:
    return None


class MasterApi:
    """The master's XML-RPC methods over a registry and a parameter tree.

    Args:
        uri: The master's own URI (``getUri``).
        pid: The process id ``getPid`` reports.
        notify: Receives the calls owed to nodes after each change.
        on_shutdown: Called with (caller_id, message) when a ``shutdown`` call arrives.
    """

    def __init__(
        self,
        uri: str,
        pid: int,
        *,
        notify: Callable[[Sequence[Action]], None] = _ignore,
        on_shutdown: Callable[[str, str], None] | None = None,
    ) -> None:
        self.uri = uri
        self.pid = pid
        self.registry = Registry()
        self.params = ParamTree()
        self.notify = notify
        self._on_shutdown = on_shutdown
        self._cache: dict[str, tuple[int, EncodedResponse]] = {}
        key, value, api = non_empty_str("key"), not_none("value"), is_api("caller_api")
        topic, service, kind = is_topic("topic"), is_topic("service"), valid_type_name("topic_type")
        self._specs: dict[str, _Spec] = {
            "shutdown": _Spec(0, (None,), self.shutdown),
            "getUri": _Spec("", (), self.get_uri),
            "getPid": _Spec(-1, (), self.get_pid),
            "deleteParam": _Spec(0, (key,), self.delete_param),
            "setParam": _Spec(0, (key, value), self.set_param),
            "getParam": _Spec(0, (key,), self.get_param),
            "searchParam": _Spec(0, (key,), self.search_param),
            "subscribeParam": _Spec(0, (api, key), self.subscribe_param),
            "unsubscribeParam": _Spec(0, (api, key), self.unsubscribe_param),
            "hasParam": _Spec(False, (key,), self.has_param),
            "getParamNames": _Spec([], (), self.get_param_names),
            "registerService": _Spec(
                0, (service, is_api("service_api"), api), self.register_service
            ),
            "lookupService": _Spec("", (service,), self.lookup_service),
            "unregisterService": _Spec(
                0, (service, is_api("service_api")), self.unregister_service
            ),
            "registerSubscriber": _Spec([], (topic, kind, api), self.register_subscriber),
            "unregisterSubscriber": _Spec(0, (topic, api), self.unregister_subscriber),
            "registerPublisher": _Spec([], (topic, kind, api), self.register_publisher),
            "unregisterPublisher": _Spec(0, (topic, api), self.unregister_publisher),
            "lookupNode": _Spec("", (valid_name("node"),), self.lookup_node),
            "getPublishedTopics": _Spec(
                0, (empty_or_valid_name("subgraph"),), self.get_published_topics
            ),
            "getTopicTypes": _Spec([], (), self.get_topic_types),
            "getSystemState": _Spec([[], [], []], (), self.get_system_state),
        }

    # -- dispatch -----------------------------------------------------------------------------

    def handlers(self) -> dict[str, Callable[..., Any]]:
        """Method name to XML-RPC handler, for `rosx.transport.server.XmlRpcServer`."""
        return {name: self._handler(name) for name in self._specs}

    def _handler(self, name: str) -> Callable[..., Any]:
        def handler(*params: Any) -> Any:
            return self.call(name, *params)

        handler.__name__ = name
        return handler

    def call(self, method: str, *params: Any) -> Any:
        """Run `method` on `params` (the caller id first) and return its reply."""
        spec = self._specs[method]
        error = spec.error_value
        if not params:
            return [-1, "missing required caller_id parameter", error]
        if len(params) != len(spec.checks) + 1:
            return [-1, "Error: bad call arity", error]
        caller_id = params[0]
        if not isinstance(caller_id, str):
            return [-1, "caller_id must be a string", error]
        try:
            args = [
                value if check is None else check(value, caller_id)
                for check, value in zip(spec.checks, params[1:], strict=True)
            ]
            reply = spec.run(caller_id, *args)
        except InvalidArgument as exc:
            return [-1, str(exc) or "error", error]
        except TypeError as exc:
            return [-1, f"Error: invalid arguments: {exc}", error]
        except Exception as exc:  # rosmaster's catch-all: a bad call never stops the master
            return [0, f"Internal failure: {exc}", error]
        return reply if isinstance(reply, EncodedResponse) else list(reply)

    def _cached(self, method: str, build: Callable[[], Reply]) -> EncodedResponse:
        version = self.registry.version
        entry = self._cache.get(method)
        if entry is None or entry[0] != version:
            entry = self._cache[method] = (version, EncodedResponse.of(list(build())))
        return entry[1]

    # -- master -------------------------------------------------------------------------------
    # Each method below implements the XML-RPC method of the same name in camelCase.

    def shutdown(self, caller_id: str, msg: Any) -> Reply:
        """``shutdown``: pass the request on to the master's owner, which stops the master."""
        if self._on_shutdown is not None:
            self._on_shutdown(caller_id, msg if isinstance(msg, str) else str(msg))
        return 1, "shutdown", 0

    def get_uri(self, caller_id: str) -> Reply:
        """``getUri``: the master's own XML-RPC URI."""
        return 1, "", self.uri

    def get_pid(self, caller_id: str) -> Reply:
        """``getPid``: the master process's id; rosgraph asks for it to learn whether the master
        is up."""
        return 1, "", self.pid

    # -- parameters ---------------------------------------------------------------------------

    def delete_param(self, caller_id: str, key: str) -> Reply:
        """``deleteParam``: remove ``key`` (resolved in the caller's namespace) and tell its
        subscribers. An unset key is rosmaster's error ``-1``, not an exception."""
        key = resolve_for_caller(key, caller_id)
        try:
            self.params.delete(key)
        except KeyError:
            return -1, f"parameter [{key}] is not set", 0
        self.notify(param_updates(self.registry.param_subscribers, key, {}))
        return 1, f"parameter {key} deleted", 0

    def set_param(self, caller_id: str, key: str, value: Any) -> Reply:
        """``setParam``: store ``value`` at ``key`` (a dict sets a whole subtree) and notify
        subscribers."""
        key = resolve_for_caller(key, caller_id)
        self.params.set(key, value)
        self.notify(param_updates(self.registry.param_subscribers, key, value, caller_id))
        return 1, f"parameter {key} set", 0

    def get_param(self, caller_id: str, key: str) -> Reply:
        """``getParam``: the value at ``key``; a namespace answers as a dict of its subtree."""
        key = resolve_for_caller(key, caller_id)
        try:
            return 1, f"Parameter [{key}]", self.params.get(key)
        except KeyError:
            return -1, f"Parameter [{key}] is not set", 0

    def search_param(self, caller_id: str, key: str) -> Reply:
        """``searchParam``: the nearest ``key`` upwards from the caller's namespace, as rospy's
        ``search_param`` finds it; the full name found, or ``-1``."""
        found = self.params.search(caller_id, key)
        if found:
            return 1, f"Found [{found}]", found
        return -1, f"Cannot find parameter [{key}] in an upwards search", ""

    def subscribe_param(self, caller_id: str, caller_api: str, key: str) -> Reply:
        """``subscribeParam``: register ``caller_api`` for ``paramUpdate`` calls on ``key``.
        Returns the current value, or ``{}`` while the key is unset."""
        key = resolve_for_caller(key, caller_id)
        subscribed = namespace_key(key)
        try:
            value = self.params.get(subscribed)
        except KeyError:
            value = {}
        outcome = self.registry.register_param_subscriber(subscribed, caller_id, caller_api)
        self.notify(outcome.actions)
        return 1, f"Subscribed to parameter [{key}]", value

    def unsubscribe_param(self, caller_id: str, caller_api: str, key: str) -> Reply:
        """``unsubscribeParam``: stop ``paramUpdate`` calls on ``key`` to ``caller_api``."""
        key = resolve_for_caller(key, caller_id)
        self.registry.unregister_param_subscriber(namespace_key(key), caller_id, caller_api)
        # rosmaster reports 1 whether or not the caller was subscribed.
        return 1, f"Unsubscribe to parameter [{key}]", 1

    def has_param(self, caller_id: str, key: str) -> Reply:
        """``hasParam``: whether ``key`` is set, as a value or as a namespace."""
        key = resolve_for_caller(key, caller_id)
        return 1, key, self.params.has(key)

    def get_param_names(self, caller_id: str) -> Reply:
        """``getParamNames``: every leaf parameter's full name."""
        return 1, "Parameter names", self.params.names()

    # -- services -----------------------------------------------------------------------------

    def register_service(
        self, caller_id: str, service: str, service_api: str, caller_api: str
    ) -> Reply:
        """``registerService``: record ``service_api`` (rosrpc) as the provider of ``service``. A
        second provider replaces the first, as rosmaster does."""
        outcome = self.registry.register_service(service, service_api, caller_id, caller_api)
        self.notify(outcome.actions)
        return 1, outcome.status, outcome.value

    def lookup_service(self, caller_id: str, service: str) -> Reply:
        """``lookupService``: the ``rosrpc://`` URI of the node providing ``service``."""
        api = self.registry.service_api(service)
        if api:
            return 1, f"rosrpc URI: [{api}]", api
        return -1, "no provider", ""

    def unregister_service(self, caller_id: str, service: str, service_api: str) -> Reply:
        """``unregisterService``: forget ``service`` if ``service_api`` is still its provider.
        The value is the number of registrations removed (0 or 1)."""
        outcome = self.registry.unregister_service(service, caller_id, service_api)
        return 1, outcome.status, outcome.value

    # -- topics -------------------------------------------------------------------------------

    def register_subscriber(
        self, caller_id: str, topic: str, topic_type: str, caller_api: str
    ) -> Reply:
        """``registerSubscriber``: add a subscriber to ``topic``; returns the current publishers'
        XML-RPC URIs, and later publishers reach it by ``publisherUpdate``."""
        outcome = self.registry.register_subscriber(topic, topic_type, caller_id, caller_api)
        self.notify(outcome.actions)
        return 1, outcome.status, outcome.value

    def unregister_subscriber(self, caller_id: str, topic: str, caller_api: str) -> Reply:
        """``unregisterSubscriber``: remove the caller's subscription to ``topic``. The value is
        the number of registrations removed (0 or 1)."""
        outcome = self.registry.unregister_subscriber(topic, caller_id, caller_api)
        return 1, outcome.status, outcome.value

    def register_publisher(
        self, caller_id: str, topic: str, topic_type: str, caller_api: str
    ) -> Reply:
        """``registerPublisher``: add a publisher of ``topic`` and send ``publisherUpdate`` to
        its subscribers; returns their XML-RPC URIs."""
        outcome = self.registry.register_publisher(topic, topic_type, caller_id, caller_api)
        self.notify(outcome.actions)
        return 1, outcome.status, outcome.value

    def unregister_publisher(self, caller_id: str, topic: str, caller_api: str) -> Reply:
        """``unregisterPublisher``: remove the caller as publisher of ``topic`` and tell
        subscribers. The value is the number of registrations removed (0 or 1)."""
        outcome = self.registry.unregister_publisher(topic, caller_id, caller_api)
        self.notify(outcome.actions)
        return 1, outcome.status, outcome.value

    # -- graph state --------------------------------------------------------------------------

    def lookup_node(self, caller_id: str, node_name: str) -> Reply:
        """``lookupNode``: the XML-RPC URI of node ``node_name``."""
        api = self.registry.node_api(node_name)
        if api is not None:
            return 1, "node api", api
        return -1, f"unknown node [{node_name}]", ""

    def get_published_topics(self, caller_id: str, subgraph: str) -> Reply:
        """``getPublishedTopics``: ``[topic, type]`` pairs with at least one publisher, under
        ``subgraph`` (a namespace; empty for all)."""
        return 1, "current topics", self.registry.published_topics(subgraph)

    def get_topic_types(self, caller_id: str) -> EncodedResponse:
        """``getTopicTypes``: ``[topic, type]`` for every known topic, published or only
        subscribed. The encoded reply is cached until the registry changes."""
        return self._cached(
            "getTopicTypes", lambda: (1, "current system state", self.registry.topic_type_list())
        )

    def get_system_state(self, caller_id: str) -> EncodedResponse:
        """``getSystemState``: publishers, subscribers and services, each as ``[name, [nodes]]``.
        The encoded reply is cached until the registry changes."""
        return self._cached(
            "getSystemState", lambda: (1, "current system state", self.registry.system_state())
        )
