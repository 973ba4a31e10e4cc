"""The exceptions of the rospy-compatible API, with rospy's names and hierarchy.

`ROSInterruptException` is both a `ROSException` and a `KeyboardInterrupt`, as in rospy, so code
written for either catches it. `ServiceException` is the node runtime's `ServiceError`: what a
`ServiceProxy` raises and what a service handler raises to refuse a request.
"""

from __future__ import annotations

from rosx.node.errors import ServiceError

ServiceException = ServiceError


class ROSException(Exception):  # noqa: N818 - rospy's name, which scripts catch
    """Base of the errors of the client API."""


class ROSSerializationException(ROSException):
    """A message could not be serialized: usually a field holds a value of the wrong type."""


class ROSInitException(ROSException):
    """The node could not be initialized, or something needed `init_node` first."""


class ROSInterruptException(ROSException, KeyboardInterrupt):
    """An operation was interrupted by the node's shutdown (Ctrl-C, ``rosnode kill``…)."""


class ROSTimeMovedBackwardsException(ROSInterruptException):
    """ROS time jumped backwards during a sleep; ``time`` is by how many seconds."""

    def __init__(self, time: float) -> None:
        self.time = time
        super().__init__("ROS time moved backwards")


class ROSInternalException(Exception):  # noqa: N818 - rospy's name
    """Base of the errors internal to the ROS system."""


class TransportException(ROSInternalException):
    """A connection to another node failed."""


class TransportTerminated(TransportException):
    """A connection to another node was closed."""


class TransportInitError(TransportException):
    """A connection to another node could not be set up."""


__all__ = [
    "ROSException",
    "ROSInitException",
    "ROSInternalException",
    "ROSInterruptException",
    "ROSSerializationException",
    "ROSTimeMovedBackwardsException",
    "ServiceException",
    "TransportException",
    "TransportInitError",
    "TransportTerminated",
]
