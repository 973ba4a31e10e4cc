"""A node's Slave API (ROS wiki ROS/Slave_API), as rospy's ``ROSHandler`` answers it.

Every method takes the caller's id first and answers ``[code, statusMessage, value]``. Argument
checks and their texts are rospy's: a call without ``caller_id`` gets ``missing required
caller_id parameter``, a wrong number of arguments ``Error: bad call arity``, a non-string
caller ``caller_id must be a string``; topic names must be non-empty strings without ``:`` or
spaces and are resolved in the caller's namespace; ``paramUpdate`` keys must be global. The
methods run on the I/O loop and never block: ``shutdown`` and ``publisherUpdate`` only start
the work they ask for.

Besides the specification's methods, ``getName`` and ``getUri`` (rospy's extras) are served.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any, Protocol
from urllib.parse import urlparse

from rosx.names import is_global, namespace_of, resolve
from rosx.node import unixros

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from rosx.node.params import ParamCache
    from rosx.node.publication import Publication
    from rosx.node.subscription import Subscription


class SlaveNode(Protocol):
    """What the Slave API needs to know about, and ask of, its node."""

    name: str
    uri: str
    master_uri: str
    param_cache: ParamCache

    @property
    def publications(self) -> Mapping[str, Publication]:
        """The node's publications by topic."""

    @property
    def subscriptions(self) -> Mapping[str, Subscription]:
        """The node's subscriptions by topic."""

    def publisher_update(self, topic: str, uris: list[str]) -> None:
        """Apply a publisher list (on the loop)."""

    def request_shutdown(self, reason: str) -> None:
        """Start shutting the node down (on the loop; returns at once)."""

    def tcpros_address(self) -> tuple[str, int]:
        """The host and port subscribers connect to (the node's TCPROS server)."""

    def unixros_address(self) -> str | None:
        """The Unix socket subscribers of this machine may connect to (`rosx.node.unixros`)."""


class _Invalid(Exception):  # noqa: N818 - rospy's ParameterInvalid, used only here
    pass


def _topic(caller_id: str, name: str, value: object) -> str:
    if not value or not isinstance(value, str):
        raise _Invalid(f"ERROR: parameter [{name}] must be a non-empty string")
    if ":" in value or " " in value:
        raise _Invalid(f"ERROR: parameter [{name}] contains illegal chars")
    if value == "/":
        raise _Invalid(f"ERROR: parameter [{name}] cannot be the global namespace")
    return resolve(
        value, namespace_of(caller_id) if caller_id.startswith("/") else "/", strict=False
    )


def _publishers(name: str, value: object) -> list[str]:
    if not isinstance(value, list):
        raise _Invalid(f"ERROR: param [{name}] must be a list")
    for uri in value:
        if not isinstance(uri, str):
            raise _Invalid(f"ERROR: param [{name}] must be a list of strings")
        parsed = urlparse(uri)
        if not parsed.scheme or not parsed.netloc:
            raise _Invalid(f"ERROR: param [{name}] does not contain valid URLs [{uri}]")
    return value


class SlaveApi:
    """The handlers of one node's Slave API, by method name (see `methods`)."""

    def __init__(self, node: SlaveNode) -> None:
        self.node = node

    def methods(self) -> dict[str, Callable[..., Any]]:
        """Handlers to serve, each checking its arguments as rospy's ``apivalidate`` does."""
        table: dict[str, tuple[int, object, Callable[..., list[Any]]]] = {
            "getUri": (0, "", self.get_uri),
            "getName": (0, "", self.get_name),
            "getBusStats": (0, [], self.get_bus_stats),
            "getBusInfo": (0, [], self.get_bus_info),
            "getMasterUri": (0, "", self.get_master_uri),
            "shutdown": (-1, 0, self.shutdown),
            "getPid": (0, -1, self.get_pid),
            "getSubscriptions": (0, [], self.get_subscriptions),
            "getPublications": (0, [], self.get_publications),
            "paramUpdate": (2, -1, self.param_update),
            "publisherUpdate": (2, -1, self.publisher_update),
            "requestTopic": (2, [], self.request_topic),
        }
        return {name: _checked(*entry) for name, entry in table.items()}

    # -- the methods (caller_id checked) ---------------------------------------------------------

    def get_uri(self, caller_id: str) -> list[Any]:
        """``getUri``: the node's XML-RPC URI."""
        return [1, "", self.node.uri]

    def get_name(self, caller_id: str) -> list[Any]:
        """``getName``: the node's resolved name."""
        return [1, "", self.node.name]

    def get_bus_stats(self, caller_id: str) -> list[Any]:
        """``getBusStats``: per-connection byte and message counts for publications and
        subscriptions (the service list is empty, as in rospy)."""
        pubs = [p.bus_stats() for p in list(self.node.publications.values())]
        subs = [s.bus_stats() for s in list(self.node.subscriptions.values())]
        return [1, "", [pubs, subs, []]]

    def get_bus_info(self, caller_id: str) -> list[Any]:
        """``getBusInfo``: one row per connection (id, peer, direction, transport, topic,
        connected), which ``rosnode info`` prints."""
        rows: list[list[object]] = []
        for pub in list(self.node.publications.values()):
            rows.extend(pub.bus_info())
        for sub in list(self.node.subscriptions.values()):
            rows.extend(sub.bus_info())
        return [1, "bus info", rows]

    def get_master_uri(self, caller_id: str) -> list[Any]:
        """``getMasterUri``: the master this node registered with, or code 0 if it has none."""
        uri = self.node.master_uri
        return [1, uri, uri] if uri else [0, "master URI not set", ""]

    def shutdown(self, caller_id: str, msg: str = "") -> list[Any]:
        """``shutdown``: ask the node to shut down; returns at once, the node stops on its own
        thread."""
        self.node.request_shutdown(f"external shutdown request from [{caller_id}]: [{msg}]")
        return [1, "shutdown", 0]

    def get_pid(self, caller_id: str) -> list[Any]:
        """``getPid``: this process's id."""
        return [1, "", os.getpid()]

    def get_subscriptions(self, caller_id: str) -> list[Any]:
        """``getSubscriptions``: ``[topic, type]`` for each topic the node subscribes to."""
        subs = [[s.topic, s.type] for s in list(self.node.subscriptions.values())]
        return [1, "subscriptions", subs]

    def get_publications(self, caller_id: str) -> list[Any]:
        """``getPublications``: ``[topic, type]`` for each topic the node publishes."""
        pubs = [[p.topic, p.info.type] for p in list(self.node.publications.values())]
        return [1, "publications", pubs]

    def param_update(self, caller_id: str, key: object, value: object) -> list[Any]:
        """``paramUpdate``: the master's news that subscribed parameter ``key`` changed; ``-1``
        if the node no longer subscribes."""
        if not key or not isinstance(key, str):
            raise _Invalid("ERROR: parameter [parameter_key] must be a non-empty string")
        if not is_global(key):
            raise _Invalid("ERROR: parameter [parameter_key] must be a globally referenced name")
        try:
            self.node.param_cache.update(key, value)
        except KeyError:
            return [-1, "not subscribed", 0]
        return [1, "", 0]

    def publisher_update(self, caller_id: str, topic: object, publishers: object) -> list[Any]:
        """``publisherUpdate``: the master's current publishers of ``topic``; the node connects
        to new ones and drops the gone."""
        name = _topic(caller_id, "topic", topic)
        uris = _publishers("publishers", publishers)
        self.node.publisher_update(name, uris)
        return [1, "", 0]

    def request_topic(self, caller_id: str, topic: object, protocols: Any) -> list[Any]:
        """``requestTopic``: the address to connect to for ``topic`` in the first protocol both
        sides speak (TCPROS, or UNIXROS on the same host); ``-1`` if the node does not publish
        it."""
        name = _topic(caller_id, "topic", topic)
        if not protocols:
            raise _Invalid("ERROR: parameter [protocols] must be specified and non-empty")
        publication = self.node.publications.get(name)
        if publication is None:
            return [-1, f"Not a publisher of [{name}]", []]
        # Python's own failures on odd protocol lists are rospy's answers (see `_checked`).
        for protocol in protocols:
            if protocol[0] == "TCPROS":
                host, port = self.node.tcpros_address()
                return [1, f"ready on {host}:{port}", ["TCPROS", host, port]]
            if protocol[0] == unixros.PROTOCOL and unixros.accepts(protocol):
                address = self.node.unixros_address()
                if address is not None:
                    return [1, f"ready on {address}", [unixros.PROTOCOL, address]]
        return [0, "no supported protocol implementations", []]


def _checked(
    arity: int, error_value: object, handler: Callable[..., list[Any]]
) -> Callable[..., Any]:
    """Wrap ``handler`` with rospy's argument checks. ``arity`` -1: one optional argument."""

    def method(*args: Any) -> list[Any]:
        if not args:
            return [-1, "missing required caller_id parameter", error_value]
        given = len(args) - 1
        if (arity >= 0 and given != arity) or (arity < 0 and given > 1):
            return [-1, "Error: bad call arity", error_value]
        if not isinstance(args[0], str):
            return [-1, "caller_id must be a string", error_value]
        try:
            return handler(*args)
        except _Invalid as exc:
            return [-1, str(exc) or "error", error_value]
        except TypeError as exc:  # rospy's reading: arguments of the wrong shape
            return [-1, f"Error: invalid arguments: {exc}", error_value]
        except Exception as exc:  # rospy answers code 0 for its own failures
            return [0, f"Internal failure: {exc}", error_value]

    return method
