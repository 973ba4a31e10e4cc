"""Talking to the master from a command-line tool: the URI, the calls, ROS 1's error texts."""

from __future__ import annotations

from typing import Any

from rosx.transport.client import XmlRpcClient
from rosx.transport.errors import FaultError, TransportError
from rosx_commands.context import CommandError, Environment

DEFAULT_MASTER_URI = "http://localhost:11311"
#: Seconds to reach the master before saying it is not there (ROS 1 may take minutes).
CONNECT_TIMEOUT = 2.0


def master_uri(env: Environment) -> str:
    return env.environ.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI


def unreachable(uri: str) -> CommandError:
    """ROS 1's line, then (on a terminal) how to get a master."""
    return CommandError(
        "ERROR: Unable to communicate with master!",
        hint=f"No master answers at ROS_MASTER_URI={uri}: start one with `rosx roscore` "
        "(or `rosx sim`) in another terminal, or point ROS_MASTER_URI at a running one.",
    )


class MasterError(Exception):
    """The master answered with a failure code; ``status`` is its message."""

    def __init__(self, code: int, status: str) -> None:
        super().__init__(status)
        self.code = code
        self.status = status


class Master:
    """The master a tool talks to, as caller ``caller_id``."""

    def __init__(self, env: Environment, caller_id: str) -> None:
        self.uri = master_uri(env)
        self.caller_id = caller_id
        self.client = XmlRpcClient(timeout=CONNECT_TIMEOUT)

    def call(self, method: str, *params: object) -> Any:
        """Call a Master/Parameter API method; the value, or `MasterError` for codes ≠ 1."""
        try:
            reply = self.client.call(self.uri, method, self.caller_id, *params)
        except (TransportError, FaultError, OSError):
            raise unreachable(self.uri) from None
        if not isinstance(reply, list) or len(reply) != 3:
            raise CommandError(f"ERROR: the master at {self.uri} sent a malformed reply")
        code, status, value = reply
        if code != 1:
            raise MasterError(code, status)
        return value

    def system_state(self) -> tuple[list[Any], list[Any], list[Any]]:
        publishers, subscribers, services = self.call("getSystemState")
        return publishers, subscribers, services

    def topic_types(self) -> dict[str, str]:
        return dict(self.call("getTopicTypes"))

    def published_topics(self, subgraph: str = "/") -> dict[str, str]:
        return dict(self.call("getPublishedTopics", subgraph))

    def lookup_node(self, name: str) -> str | None:
        try:
            uri: str = self.call("lookupNode", name)
        except MasterError:
            return None
        return uri

    def node_call(self, uri: str, method: str, *params: object, timeout: float = 3.0) -> Any:
        """Call a Slave API method on a node; raises TransportError when it does not answer."""
        return self.client.call(uri, method, self.caller_id, *params, timeout=timeout)
