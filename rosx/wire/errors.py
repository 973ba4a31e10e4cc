"""Errors raised by the wire layer.

Every refusal of bytes from a peer (or of a value the protocols cannot carry) is a
`ProtocolError` whose message names what is wrong. Callers that serve many peers catch it, refuse
that one peer in the protocol's own way (an ``error=`` header, an HTTP status, an XML-RPC fault)
and keep serving everyone else.
"""

from __future__ import annotations


class ProtocolError(ValueError):
    """Input that a ROS 1 wire protocol does not allow: malformed, truncated or unencodable."""


class OversizedError(ProtocolError):
    """A length prefix or declared size exceeds the configured limit; nothing was allocated."""

    def __init__(self, what: str, size: int, limit: int) -> None:
        super().__init__(
            f"{what} of {size} bytes exceeds the limit of {limit} bytes; "
            "the peer is out of sync or sends more than this side accepts"
        )
        self.size = size
        self.limit = limit


class HttpError(ProtocolError):
    """An HTTP message this side refuses; `status` is the status code to answer it with."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


class UnencodableError(ProtocolError):
    """A value XML-RPC cannot carry; `python_fault` is how Python's marshaller refuses it.

    ROS 1's servers (rosmaster, rospy nodes) answer such a reply with a fault of that text, which
    their peers show to users; a server that wants to answer as they do uses it.
    """

    def __init__(self, message: str, python_fault: str) -> None:
        super().__init__(message)
        self.python_fault = python_fault
