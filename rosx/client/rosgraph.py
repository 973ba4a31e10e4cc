"""The part of ``rosgraph`` that ROS 1 scripts import: ``Master``, its errors, ``names``.

``rosgraph.Master(caller_id)`` calls the Master and Parameter APIs as ``caller_id`` (resolved in
``ROS_NAMESPACE``, as rosgraph's ``make_caller_id``): each method returns the reply's value, or
raises `MasterError` (code -1: the arguments were refused) or `MasterFailure` (code 0). Network
failures are OSErrors (``ConnectionRefusedError`` …), as with rosgraph's ``ServerProxy``.
``is_master_online``, ``get_master_uri`` and ``myargv`` are rosgraph's. ``rosgraph.names`` is
`rosx.client.rosgraph_names`.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING, Any

from rosx.names import REMAP

if TYPE_CHECKING:
    from collections.abc import Mapping, Sequence

    from rosx.master.client import MasterClient

ROS_MASTER_URI = "ROS_MASTER_URI"
ROS_NAMESPACE = "ROS_NAMESPACE"
ROS_HOSTNAME = "ROS_HOSTNAME"
ROS_IP = "ROS_IP"
ROS_IPV6 = "ROS_IPV6"


class MasterException(Exception):  # noqa: N818 - rosgraph's name
    """A call to the master did not succeed."""


class MasterFailure(MasterException):
    """The master answered code 0: it failed (it may be in an inconsistent state)."""


class MasterError(MasterException):
    """The master answered code -1: it refused the arguments."""


ROSMasterException = MasterException
Error = MasterError
Failure = MasterFailure


def get_master_uri(env: Mapping[str, str] | None = None, argv: Sequence[str] | None = None) -> str:
    """``__master:=`` from ``argv``, else ``ROS_MASTER_URI``, else the default master's URI.

    Raises:
        ValueError: a ``__master:=`` argument without a URI.
    """
    for arg in sys.argv if argv is None else argv:
        if arg.startswith("__master:="):
            parts = arg.split(REMAP)
            if len(parts) != 2 or not parts[1]:
                raise ValueError(f"__master remapping argument '{arg}' improperly specified")
            return parts[1]
    from rosx.master.defaults import DEFAULT_MASTER_URI  # noqa: PLC0415 - the master's code loads only to talk to one

    return (os.environ if env is None else env).get(ROS_MASTER_URI, DEFAULT_MASTER_URI)


def myargv(argv: Sequence[str] | None = None) -> list[str]:
    """``argv`` (default ``sys.argv``) without the arguments holding ``:=``."""
    return [arg for arg in (sys.argv if argv is None else argv) if REMAP not in arg]


def is_master_online(master_uri: str | None = None) -> bool:
    """Whether the master answers ``getPid``."""
    return Master("rosgraph", master_uri=master_uri).is_online()


class Master:
    """The ROS master's API with its return codes checked (see the module docstring)."""

    def __init__(self, caller_id: str, master_uri: str | None = None) -> None:
        from rosx.client.rosgraph_names import make_caller_id  # noqa: PLC0415 - the rospy API loads only when used
        from rosx.wire.errors import ProtocolError  # noqa: PLC0415 - protocol code loads only when used
        from rosx.wire.xmlrpc_http import parse_http_uri  # noqa: PLC0415 - protocol code loads only when used

        uri = get_master_uri() if master_uri is None else master_uri
        try:
            parse_http_uri(uri)
        except ProtocolError:
            raise ValueError(f"invalid master URI: {uri}") from None
        self.master_uri = uri
        self.caller_id = make_caller_id(caller_id).rstrip("/") or "/"
        self._client: MasterClient | None = None

    def _call(self, method: str, *params: Any) -> Any:
        from rosx.master.client import MasterClient, MasterUnreachable  # noqa: PLC0415 - the master's code loads only to talk to one
        from rosx.master.client import MasterError as Refused  # noqa: PLC0415 - the master's code loads only to talk to one
        from rosx.transport.errors import ConnectError  # noqa: PLC0415 - the network code loads only to talk

        if self._client is None:
            self._client = MasterClient(self.master_uri, self.caller_id)
        try:
            return self._client.call(method, *params)
        except Refused as refused:
            raise (MasterError if refused.code == -1 else MasterFailure)(refused.status) from None
        except MasterUnreachable as exc:
            # What rosgraph's ServerProxy lets through: the socket's own error.
            cause = exc.__cause__
            if isinstance(cause, ConnectError) and cause.errno:
                raise OSError(cause.errno, os.strerror(cause.errno)) from None
            raise OSError(exc.message) from None

    def is_online(self) -> bool:
        """Whether the master answers ``getPid``."""
        try:
            self.getPid()
        except Exception:  # any failure means offline, as rosgraph says
            return False
        return True

    # -- Parameter API -------------------------------------------------------------------------

    def deleteParam(self, key: str) -> Any:  # noqa: N802 - the API's names
        """``deleteParam``: remove ``key``; returns 0. Raises `MasterError` if it is unset."""
        return self._call("deleteParam", key)

    def setParam(self, key: str, value: Any) -> Any:  # noqa: N802
        """``setParam``: set ``key`` (a dict sets a subtree); returns 0."""
        return self._call("setParam", key, value)

    def getParam(self, key: str) -> Any:  # noqa: N802
        """``getParam``: the value at ``key``. Raises `MasterError` if it is unset."""
        return self._call("getParam", key)

    def searchParam(self, key: str) -> Any:  # noqa: N802
        """``searchParam``: the nearest ``key`` upwards from this caller's namespace. Raises
        `MasterError` if none is found."""
        return self._call("searchParam", key)

    def subscribeParam(self, caller_api: str, key: str) -> Any:  # noqa: N802
        """``subscribeParam``: have the master call ``caller_api``'s ``paramUpdate`` on changes
        to ``key``; returns the current value (``{}`` while unset)."""
        return self._call("subscribeParam", caller_api, key)

    def unsubscribeParam(self, caller_api: str, key: str) -> Any:  # noqa: N802
        """``unsubscribeParam``: stop ``paramUpdate`` calls for ``key``; returns 1."""
        return self._call("unsubscribeParam", caller_api, key)

    def hasParam(self, key: str) -> Any:  # noqa: N802
        """``hasParam``: whether ``key`` is set, as a value or a namespace."""
        return self._call("hasParam", key)

    def getParamNames(self) -> Any:  # noqa: N802
        """``getParamNames``: every parameter's full name."""
        return self._call("getParamNames")

    # -- Master API ----------------------------------------------------------------------------

    def getPid(self) -> Any:  # noqa: N802
        """``getPid``: the master's process id; `is_online` calls it as a ping."""
        return self._call("getPid")

    def getUri(self) -> Any:  # noqa: N802
        """``getUri``: the master's own XML-RPC URI."""
        return self._call("getUri")

    def registerService(self, service: str, service_api: str, caller_api: str) -> Any:  # noqa: N802
        """``registerService``: register this caller as ``service``'s provider at
        ``service_api``."""
        return self._call("registerService", service, service_api, caller_api)

    def lookupService(self, service: str) -> Any:  # noqa: N802
        """``lookupService``: the ``rosrpc://`` URI of ``service``'s provider. Raises
        `MasterError` when none is registered."""
        return self._call("lookupService", service)

    def unregisterService(self, service: str, service_api: str) -> Any:  # noqa: N802
        """``unregisterService``: returns how many registrations were removed (0 or 1)."""
        return self._call("unregisterService", service, service_api)

    def registerSubscriber(self, topic: str, topic_type: str, caller_api: str) -> Any:  # noqa: N802
        """``registerSubscriber``: register a subscription; returns the publishers' XML-RPC URIs."""
        return self._call("registerSubscriber", topic, topic_type, caller_api)

    def unregisterSubscriber(self, topic: str, caller_api: str) -> Any:  # noqa: N802
        """``unregisterSubscriber``: returns how many registrations were removed (0 or 1)."""
        return self._call("unregisterSubscriber", topic, caller_api)

    def registerPublisher(self, topic: str, topic_type: str, caller_api: str) -> Any:  # noqa: N802
        """``registerPublisher``: register a publication; returns the subscribers' XML-RPC URIs."""
        return self._call("registerPublisher", topic, topic_type, caller_api)

    def unregisterPublisher(self, topic: str, caller_api: str) -> Any:  # noqa: N802
        """``unregisterPublisher``: returns how many registrations were removed (0 or 1)."""
        return self._call("unregisterPublisher", topic, caller_api)

    def lookupNode(self, node_name: str) -> Any:  # noqa: N802
        """``lookupNode``: the XML-RPC URI of ``node_name``. Raises `MasterError` if it is
        unknown."""
        return self._call("lookupNode", node_name)

    def getPublishedTopics(self, subgraph: str) -> Any:  # noqa: N802
        """``getPublishedTopics``: ``[topic, type]`` pairs with a publisher, under ``subgraph``."""
        return self._call("getPublishedTopics", subgraph)

    def getTopicTypes(self) -> Any:  # noqa: N802
        """``getTopicTypes``: ``[topic, type]`` for every topic the master knows."""
        return self._call("getTopicTypes")

    def getSystemState(self) -> Any:  # noqa: N802
        """``getSystemState``: ``[publishers, subscribers, services]``, each ``[[name, [nodes]],
        ...]``."""
        return self._call("getSystemState")


__all__ = [
    "ROS_HOSTNAME",
    "ROS_IP",
    "ROS_IPV6",
    "ROS_MASTER_URI",
    "ROS_NAMESPACE",
    "Master",
    "MasterError",
    "MasterException",
    "MasterFailure",
    "get_master_uri",
    "is_master_online",
    "myargv",
]
