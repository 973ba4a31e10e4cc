"""The XML-RPC transport on real sockets at 127.0.0.1:0, against Python's own XML-RPC stack
(the one rospy and rosmaster use) on the other side, plus refusals and failure modes."""

from __future__ import annotations

import asyncio
import http.client
import socket
import socketserver
import subprocess
import sys
import threading
import time
import xmlrpc.client
import xmlrpc.server
from collections.abc import Iterator
from typing import Any

import pytest

from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.address import (
    address_override,
    address_warnings,
    advertised_host,
    bind_host,
    http_uri,
)
from rosx.transport.client import ServerProxy, XmlRpcClient
from rosx.transport.errors import (
    BadReplyError,
    CallTimeoutError,
    ConnectError,
    FaultError,
    InvalidUriError,
)
from rosx.transport.loop_thread import LoopThread, ServerThread
from rosx.transport.server import EncodedResponse
from tests.support.procs import wait_for

VALUES: list[Any] = [
    0,
    -(2**31),
    1.25,
    True,
    "text <&> \u00e9",
    b"\x00\x01binary",
    [1, [2, "x"], {}],
    {"nested": {"list": [False, 2.5]}, "": ""},
    [],
]


async def _slow(seconds: float) -> str:
    await asyncio.sleep(seconds)
    return "slow done"


#: Set by "hold" when it is called; "hold" answers once `_RELEASE` is set.
_HOLDING = threading.Event()
_RELEASE = threading.Event()


async def _hold() -> str:
    _HOLDING.set()
    while not _RELEASE.is_set():
        await asyncio.sleep(0.01)
    return "released"


def _boom() -> None:
    raise ValueError("handler bug")


def _fault() -> None:
    raise FaultError(7, "chosen fault")


HANDLERS = {
    "echo": lambda *args: list(args),
    "slow": _slow,
    "hold": _hold,
    "boom": _boom,
    "fault": _fault,
    "cached": lambda: EncodedResponse.of([1, "cached", 2]),
}


@pytest.fixture
def server() -> Iterator[ServerThread]:
    with ServerThread(HANDLERS, multicall=True) as running:
        yield running


# -- server, driven by Python's xmlrpc.client and http.client ----------------------------------


def test_values_round_trip_with_python_xmlrpc(server: ServerThread) -> None:
    proxy = xmlrpc.client.ServerProxy(server.uri, use_builtin_types=True)
    for value in VALUES:
        assert proxy.echo(value) == [value]
    assert proxy.cached() == [1, "cached", 2]


def test_uri_and_port(server: ServerThread) -> None:
    assert server.port > 0
    assert server.uri == f"http://127.0.0.1:{server.port}/"


def test_faults_keep_python_wording(server: ServerThread) -> None:
    proxy = xmlrpc.client.ServerProxy(server.uri)
    with pytest.raises(xmlrpc.client.Fault) as unknown:
        proxy.nope()
    assert unknown.value.faultCode == 1
    assert unknown.value.faultString == "<class 'Exception'>:method \"nope\" is not supported"
    with pytest.raises(xmlrpc.client.Fault) as bug:
        proxy.boom()
    assert bug.value.faultString == "<class 'ValueError'>:handler bug"
    with pytest.raises(xmlrpc.client.Fault) as chosen:
        proxy.fault()
    assert (chosen.value.faultCode, chosen.value.faultString) == (7, "chosen fault")
    with pytest.raises(xmlrpc.client.Fault) as arity:
        proxy.boom(1, 2)
    assert arity.value.faultString.startswith("<class 'TypeError'>:")


def test_multicall(server: ServerThread) -> None:
    multi = xmlrpc.client.MultiCall(xmlrpc.client.ServerProxy(server.uri))
    multi.echo(1)
    multi.cached()
    multi.nope()
    results = multi()
    assert results[0] == [1]
    assert results[1] == [1, "cached", 2]
    with pytest.raises(xmlrpc.client.Fault):
        results[2]


def test_keep_alive_serves_many_calls_on_one_connection(server: ServerThread) -> None:
    conn = http.client.HTTPConnection("127.0.0.1", server.port, timeout=5)
    body = xmlrpc.client.dumps((1,), "echo").encode()
    for _ in range(3):
        conn.request("POST", "/", body, {"Content-Type": "text/xml"})
        response = conn.getresponse()
        assert response.status == 200
        assert xmlrpc.client.loads(response.read())[0] == ([1],)
    conn.close()


def _raw(port: int, data: bytes) -> bytes:
    with socket.create_connection(("127.0.0.1", port), timeout=5) as sock:
        sock.sendall(data)
        chunks = []
        while chunk := sock.recv(65536):
            chunks.append(chunk)
    return b"".join(chunks)


def test_bad_requests_are_refused_and_the_server_carries_on(server: ServerThread) -> None:
    assert _raw(server.port, b"GET / HTTP/1.1\r\nHost: x\r\n\r\n").startswith(b"HTTP/1.1 501 ")
    assert _raw(server.port, b"garbage\r\n\r\n").startswith(b"HTTP/1.1 400 ")
    assert _raw(server.port, b"POST / HTTP/1.1\r\nHost: x\r\n\r\n").startswith(b"HTTP/1.1 411 ")
    # Malformed XML: a fault, on a connection that stays usable.
    conn = http.client.HTTPConnection("127.0.0.1", server.port, timeout=5)
    conn.request("POST", "/", b"<methodCall><bad", {"Content-Type": "text/xml"})
    response = conn.getresponse()
    assert response.status == 200
    with pytest.raises(xmlrpc.client.Fault):
        xmlrpc.client.loads(response.read())
    conn.request("POST", "/", xmlrpc.client.dumps((2,), "echo").encode())
    assert xmlrpc.client.loads(conn.getresponse().read())[0] == ([2],)
    conn.close()
    assert xmlrpc.client.ServerProxy(server.uri).echo(3) == [3]


def test_a_slow_handler_does_not_hold_up_other_connections(server: ServerThread) -> None:
    result: list[str] = []
    _HOLDING.clear()
    _RELEASE.clear()
    held = threading.Thread(
        target=lambda: result.append(XmlRpcClient(timeout=30).call(server.uri, "hold"))
    )
    held.start()
    try:
        wait_for(_HOLDING.is_set, what="the held call")
        assert XmlRpcClient(timeout=30).call(server.uri, "echo", 1) == [1]
        assert result == []  # answered while the other call is still waiting
    finally:
        _RELEASE.set()
        held.join(30)
    assert result == ["released"]


def test_port_in_use_is_an_oserror(server: ServerThread) -> None:
    other = ServerThread(HANDLERS, port=server.port)
    with pytest.raises(OSError):
        other.start()


# -- blocking client -----------------------------------------------------------------------------


class _CountingServer(socketserver.ThreadingMixIn, xmlrpc.server.SimpleXMLRPCServer):
    """Threaded, as rospy's and rosmaster's servers are."""

    daemon_threads = True
    connections = 0

    def get_request(self) -> tuple[socket.socket, Any]:
        type(self).connections += 1
        return super().get_request()


class _Handler(xmlrpc.server.SimpleXMLRPCRequestHandler):
    protocol_version = "HTTP/1.1"  # keep-alive, as rospy's and rosmaster's servers

    def log_message(self, format: str, *args: Any) -> None:
        pass


@pytest.fixture
def python_server() -> Iterator[str]:
    srv = _CountingServer(("127.0.0.1", 0), _Handler, logRequests=False, use_builtin_types=True)
    srv.register_function(lambda *args: list(args), "echo")
    srv.register_function(lambda: 1 / 0, "divide")
    _CountingServer.connections = 0
    thread = threading.Thread(target=srv.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{srv.server_address[1]}/"
    finally:
        srv.shutdown()
        srv.server_close()
        thread.join()


def test_client_against_python_server(python_server: str) -> None:
    with XmlRpcClient() as client:
        for value in VALUES:
            assert client.call(python_server, "echo", value) == [value]
        with pytest.raises(FaultError) as fault:
            client.call(python_server, "divide")
        assert fault.value.code == 1
        assert "ZeroDivisionError" in fault.value.message
    assert _CountingServer.connections == 1  # one kept-alive connection for all of it


def test_server_proxy(python_server: str) -> None:
    with XmlRpcClient() as client:
        assert ServerProxy(python_server, client=client).echo("x", 1) == ["x", 1]


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def test_connection_refused_is_a_connect_error() -> None:
    uri = f"http://127.0.0.1:{_free_port()}/"
    with pytest.raises(ConnectError) as error:
        XmlRpcClient().call(uri, "getPid", "/x")
    assert error.value.uri == uri
    assert "connection refused" in str(error.value)
    with pytest.raises(ConnectError):
        XmlRpcClient().call("ftp://nowhere/", "getPid")


@pytest.fixture
def mute_server() -> Iterator[tuple[socket.socket, str]]:
    """Accepts connections and never answers (a hung node)."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen()
    try:
        yield listener, f"http://127.0.0.1:{listener.getsockname()[1]}/"
    finally:
        listener.close()


def test_timeout_is_a_call_timeout_error(mute_server: tuple[socket.socket, str]) -> None:
    started = time.monotonic()
    with pytest.raises(CallTimeoutError):
        XmlRpcClient().call(mute_server[1], "getPid", "/x", timeout=0.3)
    assert time.monotonic() - started < 2


def _answer_once(listener: socket.socket, reply: bytes) -> threading.Thread:
    def serve() -> None:
        conn, _ = listener.accept()
        conn.recv(65536)
        conn.sendall(reply)
        conn.close()

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    return thread


@pytest.mark.parametrize(
    "reply",
    [
        b"HTTP/1.1 404 Not Found\r\nContent-Length: 4\r\n\r\nnope",
        b"HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\n<bad>",
        b"HTTP/1.1 200 OK\r\nContent-Length: 500\r\n\r\n<methodResponse>",
        b"not http at all\r\n\r\n",
        b"",
        "HTTP/1.1 2²0 OK\r\nContent-Length: 0\r\n\r\n".encode("latin-1"),
        "HTTP/1.1 200 OK\r\nContent-Length: ²\r\n\r\n".encode("latin-1"),
    ],
)
def test_bad_replies_are_bad_reply_errors(
    mute_server: tuple[socket.socket, str], reply: bytes
) -> None:
    thread = _answer_once(mute_server[0], reply)
    with pytest.raises(BadReplyError):
        XmlRpcClient().call(mute_server[1], "getPid", "/x", timeout=5)
    thread.join()


@pytest.mark.parametrize("uri", ["http://127.0.0.1:1²/", "http://[::1/", "rosrpc://h:1"])
def test_a_uri_that_does_not_parse_is_an_invalid_uri_error(uri: str) -> None:
    with pytest.raises(InvalidUriError, match=r"invalid host or port|not an http"):
        XmlRpcClient().call(uri, "getPid", "/x", timeout=5)


def test_a_connection_closed_by_the_server_is_replaced(server: ServerThread) -> None:
    client = XmlRpcClient()
    uri = server.uri
    assert client.call(uri, "echo", 1) == [1]
    server.loop_thread.run(server.server.close())  # drops the kept-alive connection
    server.loop_thread.run(server.server.start())
    assert server.uri == uri
    assert client.call(uri, "echo", 2) == [2]


def test_client_is_shared_by_threads(server: ServerThread) -> None:
    client = XmlRpcClient()
    errors: list[BaseException] = []

    def work(n: int) -> None:
        try:
            for i in range(50):
                assert client.call(server.uri, "echo", n, i) == [n, i]
        except BaseException as exc:
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(n,)) for n in range(8)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []


def test_blocking_client_imports_no_asyncio_nor_xmlrpc_client() -> None:
    code = (
        "import sys; import rosx.transport.client, rosx.transport.errors; "
        "print(sorted(m for m in ('asyncio', 'xmlrpc.client', 'threading', 'logging') "
        "if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# -- async client --------------------------------------------------------------------------------


def test_async_client(server: ServerThread, mute_server: tuple[socket.socket, str]) -> None:
    refused = f"http://127.0.0.1:{_free_port()}/"

    async def scenario() -> None:
        client = AsyncXmlRpcClient(timeout=2.0)
        try:
            assert await client.call(server.uri, "echo", "a", 1) == ["a", 1]
            results = await asyncio.gather(*(client.call(server.uri, "echo", i) for i in range(20)))
            assert results == [[i] for i in range(20)]
            with pytest.raises(FaultError):
                await client.call(server.uri, "nope")
            with pytest.raises(ConnectError):
                await client.call(refused, "echo")
            with pytest.raises(CallTimeoutError):
                await client.call(mute_server[1], "echo", timeout=0.2)
        finally:
            await client.close()

    asyncio.run(scenario())


# -- loop thread and addresses ---------------------------------------------------------------------


def test_loop_thread_runs_coroutines() -> None:
    async def add(a: int, b: int) -> int:
        await asyncio.sleep(0)
        return a + b

    with LoopThread() as loop_thread:
        assert loop_thread.run(add(1, 2)) == 3
        assert loop_thread.submit(add(2, 3)).result(5) == 5
    assert not loop_thread.running


@pytest.mark.parametrize(
    ("environ", "remap", "advertised", "bind"),
    [
        ({}, None, "localhost", "127.0.0.1"),
        ({"ROS_IP": "10.0.0.5"}, None, "10.0.0.5", "0.0.0.0"),
        ({"ROS_HOSTNAME": "robot", "ROS_IP": "10.0.0.5"}, None, "robot", "0.0.0.0"),
        ({"ROS_HOSTNAME": "localhost"}, None, "localhost", "127.0.0.1"),
        ({"ROS_IP": "127.0.0.2"}, None, "127.0.0.2", "127.0.0.2"),
        ({"ROS_IP": "::1"}, None, "::1", "::1"),
        ({"ROS_HOSTNAME": ""}, None, "localhost", "127.0.0.1"),
        ({"ROS_IP": "10.0.0.5"}, "other", "other", "0.0.0.0"),
    ],
)
def test_address_choice(
    environ: dict[str, str], remap: str | None, advertised: str, bind: str
) -> None:
    assert advertised_host(environ, remap) == advertised
    assert bind_host(environ, remap) == bind


def test_address_override_and_warnings() -> None:
    assert address_override({}) is None
    assert address_override({"ROS_HOSTNAME": "", "ROS_IP": "1.2.3.4"}) is None
    assert address_warnings({"ROS_HOSTNAME": ""}) == ["invalid ROS_HOSTNAME (an empty string)"]
    assert address_warnings({"ROS_HOSTNAME": "http://h:1"}) == [
        "invalid ROS_HOSTNAME (protocol and port should not be included)"
    ]
    assert address_warnings({"ROS_HOSTNAME": "h:1"}) == [
        "invalid ROS_HOSTNAME (protocol should not be included)"
    ]
    assert address_warnings({"ROS_HOSTNAME": "10.0.0.1:5"}) == [
        "invalid ROS_HOSTNAME (port should not be included)"
    ]
    assert address_warnings({"ROS_HOSTNAME": "http://h"}) == [
        "invalid ROS_HOSTNAME (protocol should not be included)"
    ]
    assert address_warnings({"ROS_IP": "1.2.3.4:5"}) == [
        "invalid ROS_IP (port should not be included)"
    ]
    assert address_warnings({"ROS_IP": "robot"}) == [
        "invalid ROS_IP (must be a valid IPv4 or IPv6 address)"
    ]
    assert address_warnings({"ROS_IP": "10.0.0.1"}) == []
    assert http_uri("::1", 5) == "http://[::1]:5/"
    assert http_uri("localhost", 11311) == "http://localhost:11311/"
