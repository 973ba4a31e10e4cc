"""Calls to the master's Master and Parameter APIs, and to other nodes' Slave APIs.

Every ROS XML-RPC method answers ``[code, statusMessage, value]`` (ROS wiki ROS/Master_API);
these helpers return ``value`` when ``code`` is 1 and raise `MasterError` otherwise, as
``rosgraph.Master`` does. `MasterProxy` is blocking (for the node's synchronous facade, on the
caller's thread); `call_async` serves code on the I/O loop.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.node.errors import MasterError
from rosx.wire.errors import ProtocolError
from rosx.wire.reply import parse_ros_reply

if TYPE_CHECKING:
    from rosx.transport.aclient import AsyncXmlRpcClient
    from rosx.transport.client import XmlRpcClient


def ros_value(reply: object) -> Any:
    """The value of a ``[code, statusMessage, value]`` reply; `MasterError` unless code is 1."""
    try:
        parsed = parse_ros_reply(reply)
    except ProtocolError as exc:
        raise MasterError(0, str(exc)) from None
    if not parsed.ok:
        raise MasterError(parsed.code, parsed.status)
    return parsed.value


class MasterProxy:
    """Blocking calls to one master as one caller: ``proxy.registerPublisher(topic, ...)``."""

    def __init__(self, uri: str, caller_id: str, client: XmlRpcClient) -> None:
        self.uri = uri
        self.caller_id = caller_id
        self.client = client

    def call(self, method: str, *params: object, timeout: float | None = None) -> Any:
        """Call ``method(caller_id, *params)``; its value, or `MasterError`/`TransportError`."""
        reply = self.client.call(self.uri, method, self.caller_id, *params, timeout=timeout)
        return ros_value(reply)

    def __getattr__(self, method: str) -> Any:
        if method.startswith("_"):
            raise AttributeError(method)

        def remote(*params: object) -> Any:
            return self.call(method, *params)

        return remote


async def call_async(
    client: AsyncXmlRpcClient, uri: str, method: str, *params: object, timeout: float | None = None
) -> Any:
    """``method(*params)`` on the server at ``uri`` from the loop; the value, or `MasterError`."""
    return ros_value(await client.call(uri, method, *params, timeout=timeout))
