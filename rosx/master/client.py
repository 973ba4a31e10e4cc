"""The client of the ROS master's Master and Parameter APIs, and of nodes' Slave APIs.

Every ROS XML-RPC method answers ``[code, statusMessage, value]`` (ROS wiki ROS/Master_API,
ROS/Slave_API; parsed by `rosx.wire.reply`). `MasterClient.call` returns ``value`` when
``code`` is 1 and raises `MasterError` otherwise, as ``rosgraph.Master`` does; a master that
cannot be reached raises `MasterUnreachable`. Calls block the calling thread;
`reply_value` serves code that calls through the asyncio client.

One client for every user: the command-line tools, the node runtime, the rospy-compatible API
and the graph views. Cheap to import on purpose (the blocking transport client and the reply
parser only), so ``rosx rostopic list`` pays for nothing else.

    master = MasterClient(master_uri(os.environ), "/rostopic")  # master_uri: rosx.master.defaults
    publishers, subscribers, services = master.system_state()
"""

from __future__ import annotations

from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError
from rosx.wire.errors import ProtocolError
from rosx.wire.reply import parse_ros_reply

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Sequence
    from typing import Any


class MasterError(Exception):
    """A ROS API call answered with code ``code`` (-1 or 0) and ``status``, as
    ``rosgraph.MasterError`` and ``MasterFailure`` carry it."""

    def __init__(self, code: int, status: str) -> None:
        super().__init__(status)
        self.code = code
        self.status = status


class MasterUnreachable(TransportError):  # noqa: N818 - named for what happened, as ROS 1 says it
    """The master at ``uri`` gave no usable answer (not running, not answering, a fault)."""


def reply_value(reply: object) -> Any:
    """The value of a ``[code, statusMessage, value]`` reply; `MasterError` unless code is 1."""
    try:
        parsed = parse_ros_reply(reply)
    except ProtocolError as exc:
        raise MasterError(0, str(exc)) from None
    if not parsed.ok:
        raise MasterError(parsed.code, parsed.status)
    return parsed.value


def master_is_online(uri: str, caller_id: str, timeout: float | None = None) -> bool:
    """Whether the master at ``uri`` answers ``getPid`` (`MasterClient.is_online`), asked
    once on a connection of its own."""
    master = MasterClient(uri, caller_id, timeout=timeout)
    try:
        return master.is_online()
    finally:
        master.close()


class MasterClient:
    """Calls to one master as one caller: ``master.call("getParam", "/x")``, or as attributes,
    ``master.getParam("/x")``. Safe to share between threads (the connections are pooled)."""

    def __init__(
        self,
        uri: str,
        caller_id: str,
        client: XmlRpcClient | None = None,
        *,
        timeout: float | None = None,
    ) -> None:
        self.uri = uri
        self.caller_id = caller_id
        self.client = client if client is not None else XmlRpcClient()
        #: Seconds a master call may take unless the call says otherwise (the client's default).
        self.timeout = timeout

    def call(self, method: str, *params: object, timeout: float | None = None) -> Any:
        """Call ``method(caller_id, *params)`` on the master; its value.

        Raises:
            MasterError: the master answered with a failure code (or an unreadable reply).
            MasterUnreachable: no answer from the master.
        """
        limit = self.timeout if timeout is None else timeout
        try:
            reply = self.client.call(self.uri, method, self.caller_id, *params, timeout=limit)
        except TransportError as exc:
            raise MasterUnreachable(self.uri, exc.message) from exc
        except (FaultError, OSError) as exc:
            raise MasterUnreachable(self.uri, str(exc)) from exc
        return reply_value(reply)

    def __getattr__(self, method: str) -> Callable[..., Any]:
        if method.startswith("_"):
            raise AttributeError(method)

        def remote(*params: object) -> Any:
            return self.call(method, *params)

        remote.__name__ = method
        return remote

    def multicall(
        self, calls: Sequence[tuple[str, tuple[object, ...]]], timeout: float | None = None
    ) -> list[Any]:
        """Several calls in one ``system.multicall`` round trip (as roslaunch sets its
        parameters); each call's value, in order. A master without ``system.multicall`` gets
        them one by one.

        Raises:
            MasterError: the first call the master refused.
            MasterUnreachable: no answer from the master.
        """
        if not calls:
            return []
        payload = [{"methodName": m, "params": [self.caller_id, *p]} for m, p in calls]
        limit = self.timeout if timeout is None else timeout
        try:
            replies = self.client.call(self.uri, "system.multicall", payload, timeout=limit)
        except FaultError:
            return [self.call(method, *params, timeout=timeout) for method, params in calls]
        except TransportError as exc:
            raise MasterUnreachable(self.uri, exc.message) from exc
        except OSError as exc:
            raise MasterUnreachable(self.uri, str(exc)) from exc
        # multicall wraps each successful result in a one-element list
        return [reply_value(r[0] if isinstance(r, list) and len(r) == 1 else r) for r in replies]

    # -- is a master up? ----------------------------------------------------------------------

    def is_online(self, timeout: float | None = None) -> bool:
        """Whether a master answers ``getPid`` with its pid, as ``rosgraph.Master.is_online``
        (and roscore, before saying another master runs) asks it."""
        try:
            self.call("getPid", timeout=timeout)
        except (MasterUnreachable, MasterError):
            return False
        return True

    def check_online(self, timeout: float | None = None) -> None:
        """Ask the master for its pid, as ROS 1's tools do before anything else.

        Raises:
            MasterUnreachable: no master answers (the tools' ``Unable to communicate with
                master!``).
            MasterError: it answered with a failure.
        """
        self.call("getPid", timeout=timeout)

    def answers(self, timeout: float | None = None) -> bool:
        """Whether anything answers ROS's API at the URI, even with a refusal: a master to
        register with once it can, as rospy's and roscpp's nodes wait for one."""
        try:
            self.call("getPid", timeout=timeout)
        except MasterUnreachable:
            return False
        except MasterError:
            return True  # it answered
        return True

    def as_caller(self, caller_id: str) -> MasterClient:
        """The same master called as ``caller_id``, over the same connections."""
        return MasterClient(self.uri, caller_id, self.client, timeout=self.timeout)

    def close(self) -> None:
        """Close the kept-alive connections (later calls open new ones)."""
        self.client.close()

    # -- the Master API's questions ----------------------------------------------------------

    def system_state(self) -> tuple[list[Any], list[Any], list[Any]]:
        """``getSystemState``: publishers, subscribers and services, each ``[name, [nodes]]``."""
        publishers, subscribers, services = self.call("getSystemState")
        return publishers, subscribers, services

    def topic_types(self) -> dict[str, str]:
        """``getTopicTypes``: every known topic's type."""
        return dict(self.call("getTopicTypes"))

    def published_topics(self, subgraph: str = "/") -> dict[str, str]:
        """``getPublishedTopics``: the type of every published topic in ``subgraph``."""
        return dict(self.call("getPublishedTopics", subgraph))

    def lookup_node(self, name: str) -> str | None:
        """The Slave API URI of node ``name``, or ``None`` when the master does not know it."""
        try:
            return str(self.call("lookupNode", name))
        except MasterError:
            return None

    def lookup_service(self, name: str) -> str | None:
        """The ``rosrpc://`` URI of service ``name``, or ``None`` when no node provides it."""
        try:
            return str(self.call("lookupService", name))
        except MasterError:
            return None

    # -- nodes -------------------------------------------------------------------------------

    def node_call(self, uri: str, method: str, *params: object, timeout: float = 3.0) -> Any:
        """Call Slave API ``method(caller_id, *params)`` on the node at ``uri``; its value.

        Raises:
            MasterError: the node answered with a failure code.
            TransportError, FaultError: the node gave no usable answer.
        """
        return reply_value(self.client.call(uri, method, self.caller_id, *params, timeout=timeout))


__all__ = [
    "MasterClient",
    "MasterError",
    "MasterUnreachable",
    "master_is_online",
    "reply_value",
]
