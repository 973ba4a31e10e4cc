"""The master's registrations (ROS wiki Master_API): nodes, publishers, subscribers, services,
topic types and parameter subscriptions, as a plain data structure.

Rules, as rosmaster keeps them:

* A node is known by its caller id and bound to one XML-RPC URI. It exists while it has any
  registration (publication, subscription, service or parameter subscription) and is forgotten
  when its last one goes.
* A registration from a known caller id with a *different* URI replaces the node: every
  registration of the old one is dropped and the old URI is told to shut down.
* Publishers and subscribers of a topic are kept in registration order; registering twice is one
  registration. A service has one provider: the last to register.
* A topic's type is set by its publishers (``*`` does not overwrite a known type), or by a
  subscriber if the topic has none yet; types are never forgotten.
* Unregistering succeeds whether or not something was registered (code 1); the value is 1 if a
  registration was removed, else 0, and the status says which, in rosmaster's words.

This module knows nothing of XML-RPC, sockets or threads: each change returns an `Outcome`
whose `actions` say whom to notify (`rosx.master.actions`); the caller makes those calls.
`version` grows with every change, so readers can cache what they derive from the registry.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from rosx.master.actions import Action, PublisherUpdate, ShutdownNode

ANY_TYPE = "*"
REPLACED = "new node registered with same name"

Provider = tuple[str, str]  # (caller_id, caller_api)
_Providers = dict[Provider, None]  # an ordered set


class Outcome(NamedTuple):
    """The result of a change: the reply's `status` text and `value`, and the calls to make."""

    status: str
    value: Any
    actions: list[Action]


class Node:
    """A registered node: its XML-RPC URI and the names it holds, per kind of registration."""

    __slots__ = ("api", "param_subscriptions", "publications", "services", "subscriptions")

    def __init__(self, api: str) -> None:
        self.api = api
        self.publications: set[str] = set()
        self.subscriptions: set[str] = set()
        self.services: set[str] = set()
        self.param_subscriptions: set[str] = set()

    def is_empty(self) -> bool:
        """Whether the node holds no registration at all."""
        return not (
            self.publications or self.subscriptions or self.services or self.param_subscriptions
        )


class Registry:
    """All registrations the master holds."""

    def __init__(self) -> None:
        self.version = 0
        self.nodes: dict[str, Node] = {}
        self.publishers: dict[str, _Providers] = {}
        self.subscribers: dict[str, _Providers] = {}
        self.param_subscribers: dict[str, _Providers] = {}
        #: service name -> (caller_id, caller_api, service_api)
        self.services: dict[str, tuple[str, str, str]] = {}
        self.topic_types: dict[str, str] = {}
        # rosmaster words an unregisterService before any service ever registered differently.
        self._had_services = False

    # -- queries ------------------------------------------------------------------------------

    def node_api(self, caller_id: str) -> str | None:
        """The XML-RPC URI of node `caller_id`, or ``None`` if it is not registered."""
        node = self.nodes.get(caller_id)
        return node.api if node is not None else None

    def service_api(self, service: str) -> str | None:
        """The ``rosrpc://`` URI of `service`'s provider, or ``None``."""
        entry = self.services.get(service)
        return entry[2] if entry is not None else None

    def publisher_apis(self, topic: str) -> list[str]:
        """The XML-RPC URIs of `topic`'s publishers, in registration order."""
        return [api for _, api in self.publishers.get(topic, ())]

    def subscriber_apis(self, topic: str) -> list[str]:
        """The XML-RPC URIs of `topic`'s subscribers, in registration order."""
        return [api for _, api in self.subscribers.get(topic, ())]

    def system_state(self) -> list[list[list[Any]]]:
        """``[publishers, subscribers, services]``, each ``[[name, [caller_id, ...]], ...]``."""
        return [
            [[topic, [cid for cid, _ in providers]] for topic, providers in table.items()]
            for table in (self.publishers, self.subscribers)
        ] + [[[name, [entry[0]]] for name, entry in self.services.items()]]

    def published_topics(self, subgraph: str) -> list[list[str]]:
        """``[[topic, type], ...]`` for topics with a publisher, under namespace `subgraph`
        (``''`` for all)."""
        if subgraph and not subgraph.endswith("/"):
            subgraph += "/"
        return [[t, self.topic_types[t]] for t in self.publishers if t.startswith(subgraph)]

    def topic_type_list(self) -> list[list[str]]:
        """``[[topic, type], ...]`` for every topic ever given a type."""
        return [[topic, kind] for topic, kind in self.topic_types.items()]

    # -- registration -------------------------------------------------------------------------

    def register_publisher(
        self, topic: str, topic_type: str, caller_id: str, caller_api: str
    ) -> Outcome:
        """Add a publisher; the value is the subscribers' URIs, and each subscriber is sent
        the new list of publishers."""
        node, actions = self._bind(caller_id, caller_api)
        node.publications.add(topic)
        self.publishers.setdefault(topic, {})[caller_id, caller_api] = None
        if topic_type != ANY_TYPE or topic not in self.topic_types:
            self.topic_types[topic] = topic_type
        publishers = self.publisher_apis(topic)
        subscribers = self.subscriber_apis(topic)
        actions += [PublisherUpdate(api, topic, publishers) for api in subscribers]
        status = f"Registered [{caller_id}] as publisher of [{topic}]"
        return Outcome(status, subscribers, actions)

    def register_subscriber(
        self, topic: str, topic_type: str, caller_id: str, caller_api: str
    ) -> Outcome:
        """Add a subscriber; the value is the publishers' URIs."""
        node, actions = self._bind(caller_id, caller_api)
        node.subscriptions.add(topic)
        self.subscribers.setdefault(topic, {})[caller_id, caller_api] = None
        if topic not in self.topic_types and topic_type != ANY_TYPE:
            self.topic_types[topic] = topic_type
        return Outcome(f"Subscribed to [{topic}]", self.publisher_apis(topic), actions)

    def register_service(
        self, service: str, service_api: str, caller_id: str, caller_api: str
    ) -> Outcome:
        """Make the caller `service`'s provider (replacing any other); the value is 1."""
        node, actions = self._bind(caller_id, caller_api)
        node.services.add(service)
        self.services[service] = (caller_id, caller_api, service_api)
        self._had_services = True
        return Outcome(f"Registered [{caller_id}] as provider of [{service}]", 1, actions)

    def register_param_subscriber(self, key: str, caller_id: str, caller_api: str) -> Outcome:
        """Subscribe the caller to parameter `key` (a namespace with a trailing ``/``)."""
        node, actions = self._bind(caller_id, caller_api)
        node.param_subscriptions.add(key)
        self.param_subscribers.setdefault(key, {})[caller_id, caller_api] = None
        return Outcome(f"Subscribed to parameter [{key}]", 1, actions)

    # -- unregistration -----------------------------------------------------------------------

    def unregister_publisher(self, topic: str, caller_id: str, caller_api: str) -> Outcome:
        """Remove a publisher; if one was removed, subscribers get the remaining list."""
        outcome = self._unregister(self.publishers, "publications", topic, caller_id, caller_api)
        if outcome.value:
            publishers = self.publisher_apis(topic)
            outcome.actions.extend(
                PublisherUpdate(api, topic, publishers) for api in self.subscriber_apis(topic)
            )
        return outcome

    def unregister_subscriber(self, topic: str, caller_id: str, caller_api: str) -> Outcome:
        """Remove a subscriber."""
        return self._unregister(self.subscribers, "subscriptions", topic, caller_id, caller_api)

    def unregister_param_subscriber(self, key: str, caller_id: str, caller_api: str) -> Outcome:
        """Remove a parameter subscription (`key` with a trailing ``/``)."""
        return self._unregister(
            self.param_subscribers, "param_subscriptions", key, caller_id, caller_api
        )

    def unregister_service(self, service: str, caller_id: str, service_api: str) -> Outcome:
        """Remove the caller as `service`'s provider, if it still is, with that service URI."""
        node = self.nodes.get(caller_id)
        if node is None:
            return Outcome(f"[{caller_id}] is not a registered node", 0, [])
        entry = self.services.get(service)
        if not self._had_services:
            outcome = Outcome(f"[{caller_id}] is not a provider of [{service}]", 0, [])
        elif entry is None or (entry[0], entry[2]) != (caller_id, service_api):
            status = f"[{service_api}] is no longer the current service api handle for [{service}]"
            outcome = Outcome(status, 0, [])
        else:
            del self.services[service]
            node.services.discard(service)
            self.version += 1
            outcome = Outcome(f"Unregistered [{caller_id}] as provider of [{service}]", 1, [])
        self._forget_if_empty(caller_id, node)
        return outcome

    # -- internals ----------------------------------------------------------------------------

    def _bind(self, caller_id: str, caller_api: str) -> tuple[Node, list[Action]]:
        """The node `caller_id` at `caller_api`, replacing one registered at another URI."""
        self.version += 1
        node = self.nodes.get(caller_id)
        if node is not None and node.api == caller_api:
            return node, []
        actions: list[Action] = []
        if node is not None:
            actions.append(ShutdownNode(node.api, caller_id, REPLACED))
            self._drop_all(caller_id)
        node = self.nodes[caller_id] = Node(caller_api)
        return node, actions

    def _drop_all(self, caller_id: str) -> None:
        for table in (self.publishers, self.subscribers, self.param_subscribers):
            for key in list(table):
                providers = table[key]
                for provider in [p for p in providers if p[0] == caller_id]:
                    del providers[provider]
                if not providers:
                    del table[key]
        for name in [n for n, entry in self.services.items() if entry[0] == caller_id]:
            del self.services[name]

    def _unregister(
        self, table: dict[str, _Providers], kind: str, key: str, caller_id: str, caller_api: str
    ) -> Outcome:
        node = self.nodes.get(caller_id)
        if node is None:
            return Outcome(f"[{caller_id}] is not a registered node", 0, [])
        providers = table.get(key)
        if providers is not None and (caller_id, caller_api) in providers:
            del providers[caller_id, caller_api]
            if not providers:
                del table[key]
            getattr(node, kind).discard(key)
            self.version += 1
            outcome = Outcome(f"Unregistered [{caller_id}] as provider of [{key}]", 1, [])
        else:
            outcome = Outcome(f"[{caller_id}] is not a known provider of [{key}]", 0, [])
        self._forget_if_empty(caller_id, node)
        return outcome

    def _forget_if_empty(self, caller_id: str, node: Node) -> None:
        if node.is_empty():
            del self.nodes[caller_id]
            self.version += 1
