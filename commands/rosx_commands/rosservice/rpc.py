"""One-shot ROSRPC exchanges for ``rosservice``: a probe and a call, on plain blocking sockets.

A command-line tool makes one exchange and exits, so it needs no node: it connects, sends the
client header (`rosx.wire.rosrpc.client_header`), reads the server's header with
`rosx.wire.rosrpc.ServiceReplyReader` and, for a call, sends the request frame and reads the ok
byte and the answer. Failures carry the texts ROS 1's rosservice prints (rosservice's own for the
probe, rospy's ``ServiceProxy`` for the call), with the server's error bytes shown as Python
shows ``bytes`` (``b'...'``), as rospy under Python 3 does.
"""

from __future__ import annotations

import socket
import time

from rosx.wire.errors import ProtocolError
from rosx.wire.framing import frame
from rosx.wire.header import Refused, encode_header
from rosx.wire.rosrpc import (
    ServerHeader,
    ServiceReplyReader,
    ServiceResponse,
    check_server_reply,
    client_header,
    parse_rosrpc_uri,
)

#: rosservice's socket timeout for a probe, in seconds.
PROBE_TIMEOUT = 5.0
#: Seconds to open a call's connection when no --timeout is given.
CONNECT_TIMEOUT = 10.0
_TERMINATED = "unable to receive data from sender, check sender's logs for details"


class ServiceIOError(Exception):
    """The service could not be reached; the text is what rosservice prints after ``ERROR: ``."""


class CallError(Exception):
    """A call failed; the text is what rosservice prints after ``ERROR: ``."""


class CallTimeout(CallError):  # noqa: N818 - a CallError, named for its cause
    """No answer within the time allowed (``--timeout``)."""


def _address(name: str, uri: str) -> tuple[str, int]:
    try:
        return parse_rosrpc_uri(uri)
    except ProtocolError:
        raise ServiceIOError(f"service [{name}] has an invalid RPC URI [{uri}]") from None


def _read_event(
    sock: socket.socket, reader: ServiceReplyReader, deadline: float | None = None
) -> ServerHeader | ServiceResponse | None:
    """The next header or response; ``None`` when the server closed the connection first."""
    while True:
        event = reader.next_event()
        if event is not None:
            return event
        if deadline is not None:
            _until(sock, deadline)
        data = sock.recv(65536)
        if not data:
            return None
        reader.feed(data)


def probe(name: str, uri: str, *, caller_id: str = "/rosservice") -> dict[str, str]:
    """The header the server of ``name`` at ``uri`` answers a probe with (``probe=1``).

    Raises:
        ServiceIOError: the server cannot be reached or closed without a header.
    """
    host, port = _address(name, uri)
    fields = client_header(callerid=caller_id, service=name, md5sum="*", probe=True)
    try:
        with socket.create_connection((host, port), timeout=PROBE_TIMEOUT) as sock:
            sock.sendall(encode_header(fields))
            event = _read_event(sock, ServiceReplyReader())
    except (OSError, ProtocolError):
        event = None
    if not isinstance(event, ServerHeader):
        raise ServiceIOError(f"Unable to communicate with service [{name}], address [{uri}]")
    return event.fields


def call(
    name: str,
    uri: str,
    *,
    md5sum: str,
    request: bytes,
    caller_id: str,
    timeout: float | None = None,
) -> bytes:
    """Send the serialized ``request`` to service ``name`` at ``uri``; the serialized response.

    ``timeout`` bounds the whole exchange (rosservice's ``--timeout``); without it the call
    waits for the server as long as it takes, as ROS 1's does.

    Raises:
        CallError: with rospy's text (``unable to connect to service: …``, ``transport error
            completing service call: …``, ``service [/x] responded with an error: b'…'``).
        CallTimeout: ``timeout`` passed first.
    """
    host, port = _address(name, uri)
    deadline = None if timeout is None else time.monotonic() + timeout
    fields = client_header(callerid=caller_id, service=name, md5sum=md5sum)
    try:
        sock = socket.create_connection(
            (host, port), timeout=CONNECT_TIMEOUT if timeout is None else timeout
        )
    except TimeoutError:
        raise _timeout(name, timeout) from None
    except OSError as error:
        raise CallError(f"unable to connect to service: {error}") from None
    reader = ServiceReplyReader()
    with sock:
        try:
            _until(sock, deadline)
            sock.sendall(encode_header(fields))
            event = _read_event(sock, reader, deadline)
            if event is None:
                raise CallError(f"unable to connect to service: {_TERMINATED}")
            assert isinstance(event, ServerHeader)
            verdict = check_server_reply(event.fields, service=name, md5sum=md5sum)
            if isinstance(verdict, Refused):
                reason = verdict.reason
                if verdict.by_peer:
                    reason = f"remote error reported: {reason}"
                raise CallError(f"unable to connect to service: {reason}")
            _until(sock, deadline)
            sock.sendall(frame(request))
            answer = _read_event(sock, reader, deadline)
        except TimeoutError:
            raise _timeout(name, timeout) from None
        except (OSError, ProtocolError) as error:
            raise CallError(f"transport error completing service call: {error}") from None
    if answer is None:
        raise CallError(f"transport error completing service call: {_TERMINATED}")
    assert isinstance(answer, ServiceResponse)
    if not answer.ok:
        raise CallError(f"service [{name}] responded with an error: {answer.payload!r}")
    return answer.payload


def _until(sock: socket.socket, deadline: float | None) -> None:
    if deadline is None:
        sock.settimeout(None)
        return
    left = deadline - time.monotonic()
    if left <= 0:
        raise TimeoutError
    sock.settimeout(left)


def _timeout(name: str, timeout: float | None) -> CallTimeout:
    return CallTimeout(f"service [{name}] did not respond within {timeout} seconds")
