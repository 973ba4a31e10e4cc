"""HTTP framing for XML-RPC: exact bytes, incremental parsing, Python's http stack both ways."""

from __future__ import annotations

import http.client
import io
import xmlrpc.client

import pytest

from rosx.wire.errors import HttpError, ProtocolError
from rosx.wire.xmlrpc import MethodCall, decode_call, encode_call
from rosx.wire.xmlrpc_http import (
    HttpRequest,
    HttpResponse,
    RequestReader,
    ResponseReader,
    build_error_response,
    build_request,
    build_response,
    parse_http_uri,
)
from tests.support.wirefeed import CHUNKINGS, pieces

BODY = b"<methodCall><methodName>getPid</methodName></methodCall>"


def test_request_bytes_are_exact() -> None:
    assert build_request("localhost:11311", "/", BODY) == (
        b"POST / HTTP/1.1\r\nHost: localhost:11311\r\nUser-Agent: rosx\r\n"
        b"Content-Type: text/xml\r\nContent-Length: 56\r\n\r\n" + BODY
    )
    assert build_request("h", "", b"", keep_alive=False) == (
        b"POST / HTTP/1.1\r\nHost: h\r\nUser-Agent: rosx\r\n"
        b"Content-Type: text/xml\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"
    )


def test_response_bytes_are_exact() -> None:
    assert build_response(b"<x/>") == (
        b"HTTP/1.1 200 OK\r\nServer: rosx\r\nContent-Type: text/xml\r\n"
        b"Content-Length: 4\r\n\r\n<x/>"
    )
    assert build_error_response(411) == (
        b"HTTP/1.1 411 Length Required\r\nServer: rosx\r\n"
        b"Content-Type: text/plain; charset=utf-8\r\nContent-Length: 15\r\n"
        b"Connection: close\r\n\r\nLength Required"
    )


def _requests(data: bytes, how: str, reader: RequestReader | None = None) -> list[HttpRequest]:
    reader = reader or RequestReader()
    out: list[HttpRequest] = []
    for piece in pieces(data, how):
        reader.feed(piece)
        while (request := reader.next_request()) is not None:
            out.append(request)
    return out


@pytest.mark.parametrize("how", CHUNKINGS)
def test_requests_in_any_chunking_and_pipelined(how: str) -> None:
    first = build_request("m:1", "/RPC2", BODY)
    second = build_request("m:1", "/", b"", keep_alive=False)
    reader = RequestReader()
    requests = _requests(first + second + first[:30], how, reader)
    assert requests == [
        HttpRequest(
            method="POST",
            target="/RPC2",
            version="HTTP/1.1",
            headers={
                "host": "m:1",
                "user-agent": "rosx",
                "content-type": "text/xml",
                "content-length": "56",
            },
            body=BODY,
            keep_alive=True,
        ),
        HttpRequest(
            method="POST",
            target="/",
            version="HTTP/1.1",
            headers={
                "host": "m:1",
                "user-agent": "rosx",
                "content-type": "text/xml",
                "content-length": "0",
                "connection": "close",
            },
            body=b"",
            keep_alive=False,
        ),
    ]
    reader.feed(first[30:])
    third = reader.next_request()
    assert third is not None
    assert third.body == BODY


@pytest.mark.parametrize("how", CHUNKINGS)
def test_responses_in_any_chunking(how: str) -> None:
    stream = build_response(b"one") + build_response(b"", keep_alive=False) + b"HTTP/1.1 2"
    reader = ResponseReader()
    out: list[HttpResponse] = []
    for piece in pieces(stream, how):
        reader.feed(piece)
        while (response := reader.next_response()) is not None:
            out.append(response)
    assert [(r.status, r.reason, r.body, r.keep_alive) for r in out] == [
        (200, "OK", b"one", True),
        (200, "OK", b"", False),
    ]
    assert out[0].headers["content-type"] == "text/xml"


def test_response_without_length_ends_with_the_connection() -> None:
    reader = ResponseReader()
    reader.feed(b"HTTP/1.0 200 OK\r\nServer: old\r\n\r\n<methodResponse>")
    assert reader.next_response() is None
    reader.feed(b"</methodResponse>")
    assert reader.next_response() is None
    reader.feed_eof()
    response = reader.next_response()
    assert response is not None
    assert (response.body, response.keep_alive, response.version) == (
        b"<methodResponse></methodResponse>",
        False,
        "HTTP/1.0",
    )
    assert reader.next_response() is None


def test_interim_responses_are_skipped() -> None:
    reader = ResponseReader()
    reader.feed(b"HTTP/1.1 100 Continue\r\n\r\n" + build_response(b"x"))
    response = reader.next_response()
    assert response is not None
    assert (response.status, response.body) == (200, b"x")


@pytest.mark.parametrize(
    ("version", "connection", "keep_alive"),
    [
        ("HTTP/1.1", None, True),
        ("HTTP/1.1", "close", False),
        ("HTTP/1.1", "Keep-Alive, Close", False),
        ("HTTP/1.0", None, False),
        ("HTTP/1.0", "keep-alive", True),
    ],
)
def test_keep_alive_rules(version: str, connection: str | None, keep_alive: bool) -> None:
    extra = f"Connection: {connection}\r\n" if connection else ""
    reader = RequestReader()
    reader.feed(f"POST / {version}\r\nContent-Length: 0\r\n{extra}\r\n".encode())
    request = reader.next_request()
    assert request is not None
    assert request.keep_alive is keep_alive
    responses = ResponseReader()
    responses.feed(f"{version} 200 OK\r\nContent-Length: 0\r\n{extra}\r\n".encode())
    response = responses.next_response()
    assert response is not None
    assert response.keep_alive is keep_alive


@pytest.mark.parametrize(
    ("data", "status", "message"),
    [
        (b"POST / HTTP/1.1\r\n\r\n", 411, "needs a Content-Length"),
        (b"POST / HTTP/1.1\r\nContent-Length: 11\r\n\r\n", 413, "body of 11 bytes exceeds"),
        (b"POST / HTTP/1.1\r\nContent-Length: -1\r\n\r\n", 400, "invalid Content-Length"),
        # Latin-1 has digits that str.isdigit accepts and int refuses.
        (
            "POST / HTTP/1.1\r\nContent-Length: ²\r\n\r\n".encode("latin-1"),
            400,
            "invalid Content-Length",
        ),
        (
            "POST / HTTP/1.1\r\nContent-Length: 1¹\r\n\r\n".encode("latin-1"),
            400,
            "invalid Content-Length",
        ),
        (
            b"POST / HTTP/1.1\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\n",
            400,
            "conflicting Content-Length",
        ),
        (b"POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 501, "chunked"),
        (b"POST /\r\n\r\n", 400, "malformed HTTP request line"),
        (b"POST / HTTP/2.0\r\nContent-Length: 0\r\n\r\n", 505, "unsupported HTTP version"),
        (b"POST / HTTP/1.1\r\nNo colon here\r\n\r\n", 400, "malformed HTTP header line"),
        (b"POST / HTTP/1.1\r\nName : v\r\n\r\n", 400, "malformed HTTP header line"),
        (b"POST / HTTP/1.1\r\nA: b\r\n folded\r\n\r\n", 400, "line folding"),
        (b"POST / HTTP/1.1\r\nX: " + b"x" * 200, 431, "HTTP head exceeds 100 bytes"),
        (b"POST / HTTP/1.1\r\nX: " + b"x" * 200 + b"\r\n\r\n", 431, "exceeds 100 bytes"),
    ],
)
def test_bad_requests_are_refused_with_a_status(data: bytes, status: int, message: str) -> None:
    reader = RequestReader(max_head_size=100, max_body_size=10)
    reader.feed(data)
    with pytest.raises(HttpError, match=message) as info:
        reader.next_request()
    assert info.value.status == status


def test_request_without_body_for_other_methods() -> None:
    reader = RequestReader()
    reader.feed(b"GET /x HTTP/1.1\r\nHost: h\r\n\r\n")
    request = reader.next_request()
    assert request is not None
    assert (request.method, request.target, request.body) == ("GET", "/x", b"")


@pytest.mark.parametrize(
    ("data", "eof", "message"),
    [
        (b"HTTP/1.1 abc OK\r\n\r\n", False, "malformed HTTP status line"),
        ("HTTP/1.1 2²0 OK\r\n\r\n".encode("latin-1"), False, "malformed HTTP status line"),
        ("HTTP/1.1 200 OK\r\nContent-Length: ³\r\n\r\n".encode("latin-1"), False, "Content-Length"),
        (b"ICY 200 OK\r\n\r\n", False, "malformed HTTP status line"),
        (b"HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nab", True, "after 2 of 5 HTTP body"),
        (b"HTTP/1.1 200 OK\r\nContent-", True, "in the middle of an HTTP response head"),
        (b"HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n", False, "chunked"),
    ],
)
def test_bad_responses_are_refused(data: bytes, eof: bool, message: str) -> None:
    reader = ResponseReader()
    reader.feed(data)
    if eof:
        reader.feed_eof()
    with pytest.raises(ProtocolError, match=message):
        reader.next_response()


def test_response_body_limit_applies_without_a_length() -> None:
    reader = ResponseReader(max_body_size=4)
    reader.feed(b"HTTP/1.0 200 OK\r\n\r\n12345")
    with pytest.raises(HttpError, match="exceeds 4 bytes"):
        reader.next_response()


class _RecordingSocket:
    """Enough of a socket for http.client to send a request into."""

    def __init__(self) -> None:
        self.sent = bytearray()

    def sendall(self, data: bytes) -> None:
        self.sent += data

    def makefile(self, mode: str) -> io.BytesIO:
        raise AssertionError("the request is only recorded")

    def close(self) -> None:
        pass


def test_parses_what_python_xmlrpc_client_sends() -> None:
    sock = _RecordingSocket()

    class RecordingTransport(xmlrpc.client.Transport):
        def make_connection(self, host: object) -> http.client.HTTPConnection:
            connection = http.client.HTTPConnection("localhost", 11311)
            connection.sock = sock
            return connection

    body = xmlrpc.client.dumps(("/rostopic",), methodname="getSystemState").encode()
    RecordingTransport().send_request("localhost:11311", "/RPC2", body, False)
    requests = _requests(bytes(sock.sent), "bytewise")
    assert len(requests) == 1
    assert (requests[0].method, requests[0].target, requests[0].keep_alive) == (
        "POST",
        "/RPC2",
        True,
    )
    assert decode_call(requests[0].body) == MethodCall("getSystemState", ("/rostopic",))


class _ReplaySocket:
    def __init__(self, data: bytes) -> None:
        self.data = data

    def makefile(self, mode: str) -> io.BytesIO:
        return io.BytesIO(self.data)


@pytest.mark.parametrize("keep_alive", [True, False])
def test_python_http_client_reads_what_we_send(keep_alive: bool) -> None:
    payload = encode_call("x", [1])
    response = http.client.HTTPResponse(
        _ReplaySocket(build_response(payload, keep_alive=keep_alive))  # type: ignore[arg-type]
    )
    response.begin()
    assert (response.status, response.reason, response.will_close) == (200, "OK", not keep_alive)
    assert response.read() == payload


@pytest.mark.parametrize(
    ("uri", "parts"),
    [
        ("http://localhost:11311/", ("localhost", 11311, "/")),
        ("http://localhost:11311", ("localhost", 11311, "/")),
        ("http://10.0.0.2:4567/RPC2", ("10.0.0.2", 4567, "/RPC2")),
        ("HTTP://host/", ("host", 80, "/")),
        ("http://[::1]:11311/", ("::1", 11311, "/")),
        ("http://user@host:1/", ("host", 1, "/")),
    ],
)
def test_parse_http_uri(uri: str, parts: tuple[str, int, str]) -> None:
    assert parse_http_uri(uri) == parts


@pytest.mark.parametrize(
    "uri",
    [
        "rosrpc://h:1",
        "localhost:11311",
        "http://:80/",
        "http://h:x/",
        "http://h:70000/",
        "http://127.0.0.1:1²/",
        "http://127.0.0.1:١٢/",
        "http://[::1]:²/",
        "http://[::1/",
    ],
)
def test_parse_http_uri_refuses(uri: str) -> None:
    with pytest.raises(ProtocolError):
        parse_http_uri(uri)
