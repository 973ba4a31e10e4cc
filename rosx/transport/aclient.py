"""An asyncio XML-RPC client, for servers calling out to peers (the master's ``publisherUpdate``,
``paramUpdate`` and ``shutdown`` to nodes; a node's ``requestTopic`` to publishers).

Same contract as the blocking `rosx.transport.client`: kept-alive connections per server, used by
one call at a time; typed errors (`ConnectError`, `CallTimeoutError`, `BadReplyError`,
`FaultError`). Timeouts default to a few seconds, so a dead or hung peer costs its caller little.
"""

from __future__ import annotations

import asyncio

from rosx.transport.errors import BadReplyError, CallTimeoutError
from rosx.transport.exchange import (
    StaleConnectionError,
    bad_reply,
    connect_error,
    interpret,
    prepare,
)
from rosx.wire.errors import ProtocolError
from rosx.wire.xmlrpc_http import ResponseReader

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from rosx.transport.exchange import Key
    from rosx.wire.xmlrpc_http import HttpResponse

    _Connection = tuple[asyncio.StreamReader, asyncio.StreamWriter]

#: Seconds a call may take, connecting included, unless the caller says otherwise.
DEFAULT_TIMEOUT = 3.0
_MAX_IDLE_PER_SERVER = 2
# A master calls out to every node; kept connections must not eat its file descriptors.
_MAX_IDLE_TOTAL = 64
_READ_SIZE = 1 << 16


class AsyncXmlRpcClient:
    """Calls XML-RPC methods from an event loop over kept-alive connections."""

    def __init__(self, timeout: float = DEFAULT_TIMEOUT) -> None:
        self.timeout = timeout
        self._idle: dict[Key, list[_Connection]] = {}
        self._idle_count = 0

    async def call(
        self, uri: str, method: str, *params: object, timeout: float | None = None
    ) -> Any:
        """Call `method` with `params` on the server at `uri` and return the reply's value.

        Raises:
            ConnectError: no connection could be opened.
            CallTimeoutError: no complete reply within `timeout` (the client's default if
                ``None``).
            BadReplyError: the reply is not an XML-RPC response.
            FaultError: the server answered with a fault.
            ProtocolError: a parameter cannot be carried by XML-RPC.
        """
        key, payload = prepare(uri, method, params)
        limit = self.timeout if timeout is None else timeout
        try:
            return await asyncio.wait_for(self._call(uri, key, payload), limit)
        except asyncio.TimeoutError:  # not the builtin TimeoutError before Python 3.11
            raise CallTimeoutError(uri, f"{uri} did not reply within {limit:g} s") from None

    async def close(self) -> None:
        """Close every kept-alive connection."""
        idle, self._idle = self._idle, {}
        self._idle_count = 0
        for connections in idle.values():
            for _, writer in connections:
                writer.close()

    def _sweep(self) -> None:
        """Close kept connections their servers have closed: a node that died, or a server's
        idle timeout. Each would otherwise hold a descriptor (in CLOSE_WAIT) until the next call
        to its server, and a master or ``/rosout`` never calls a dead node again."""
        for key, connections in list(self._idle.items()):
            alive = [c for c in connections if not (c[0].at_eof() or c[1].is_closing())]
            for connection in connections:
                if connection not in alive:
                    connection[1].close()
            self._idle_count -= len(connections) - len(alive)
            if alive:
                self._idle[key] = alive
            else:
                del self._idle[key]

    async def _call(self, uri: str, key: Key, payload: bytes) -> Any:
        self._sweep()
        connections = self._idle.get(key)
        if connections:
            connection = connections.pop()
            self._idle_count -= 1
            try:
                response = await _exchange(uri, connection, payload)
            except StaleConnectionError:
                connection[1].close()
            else:
                return self._finish(uri, key, connection, response)
        try:
            connection = await asyncio.open_connection(*key)
        except OSError as exc:
            raise connect_error(uri, exc) from None
        try:
            response = await _exchange(uri, connection, payload)
        except StaleConnectionError:
            connection[1].close()
            raise BadReplyError(uri, f"{uri} closed the connection without replying") from None
        return self._finish(uri, key, connection, response)

    def _finish(self, uri: str, key: Key, connection: _Connection, response: HttpResponse) -> Any:
        connections = self._idle.setdefault(key, [])
        if (
            response.keep_alive
            and len(connections) < _MAX_IDLE_PER_SERVER
            and self._idle_count < _MAX_IDLE_TOTAL
        ):
            connections.append(connection)
            self._idle_count += 1
        else:
            connection[1].close()
        return interpret(uri, response)


async def _exchange(uri: str, connection: _Connection, payload: bytes) -> HttpResponse:
    """Send `payload`, read the response; `StaleConnectionError` if the peer closed at once."""
    reader, writer = connection
    responses = ResponseReader()
    received = False
    try:
        writer.write(payload)
        await writer.drain()
        while True:
            response = responses.next_response()
            if response is not None:
                return response
            data = await reader.read(_READ_SIZE)
            if not data:
                if not received:
                    raise StaleConnectionError
                responses.feed_eof()
                continue
            received = True
            responses.feed(data)
    except StaleConnectionError:
        raise
    except (ConnectionResetError, BrokenPipeError) as exc:
        if not received:
            raise StaleConnectionError from None
        writer.close()
        raise bad_reply(uri, exc) from None
    except (OSError, ProtocolError) as exc:
        writer.close()
        raise bad_reply(uri, exc) from None
    except BaseException:
        # Timed out or cancelled mid-exchange: the connection's state is unknown; drop it.
        writer.close()
        raise
