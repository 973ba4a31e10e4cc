"""Errors raised by the node runtime.

`ServiceError` is what rospy calls ``ServiceException``: a service call that failed (its
subclasses say how, `rosx.node.service_client`), or a handler's way to refuse a request;
`NodeShutdownError` is raised by calls made on a node that has been shut down,
`TimeMovedBackwardsError` by a sleep in simulated time that saw the time go back. A master's
refusal is `rosx.master.client.MasterError`; connection failures surface as
`rosx.transport.errors.TransportError` (`rosx.master.client.MasterUnreachable` for the master).
"""

from __future__ import annotations


class NodeError(Exception):
    """Base of the node runtime's errors."""


class ServiceError(NodeError):
    """A service call failed; raised by a handler, it sends its text to the client (ok=0)."""


class NodeShutdownError(NodeError):
    """The node has been shut down, so it can no longer do what was asked."""


class TimeMovedBackwardsError(NodeError):
    """Simulated time (``/clock``) jumped backwards during a sleep, by ``jump`` seconds."""

    def __init__(self, jump: float) -> None:
        super().__init__(f"ROS time moved backwards by {jump} s")
        self.jump = jump
