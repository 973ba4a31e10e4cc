"""Errors raised by the node runtime.

`MasterError` carries a master's refusal (its ``[code, statusMessage, value]`` reply with code
-1 or 0, as ``rosgraph.MasterError`` and ``MasterFailure`` do); `ServiceError` is what rospy calls
``ServiceException``: a service call that failed, or a handler's way to refuse a request;
`NodeShutdownError` is raised by calls made on a node that has been shut down.
Connection failures surface as `rosx.transport.errors.TransportError`.
"""

from __future__ import annotations


class NodeError(Exception):
    """Base of the node runtime's errors."""


class MasterError(NodeError):
    """The master (or a node's Slave API) answered a call with code `code` and `status`."""

    def __init__(self, code: int, status: str) -> None:
        super().__init__(status)
        self.code = code
        self.status = status


class ServiceError(NodeError):
    """A service call failed; raised by a handler, it sends its text to the client (ok=0)."""


class NodeShutdownError(NodeError):
    """The node has been shut down, so it can no longer do what was asked."""
