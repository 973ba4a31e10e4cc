"""Services, parameters, logging and refused connections, between rosx nodes in one process."""

from __future__ import annotations

import io
import socket
import struct
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node, ServiceError, rosout
from rosx.node.outgoing import OutgoingStream
from rosx.transport.client import call
from rosx.wire.framing import FrameReader, frame
from rosx.wire.header import decode_header, encode_header
from rosx.wire.tcpros import subscriber_header
from tests.support.cli import clean_environ
from tests.support.procs import wait_for

SetBool = get_service_class("std_srvs/SetBool")
Trigger = get_service_class("std_srvs/Trigger")
Twist = get_message_class("geometry_msgs/Twist")
Log = get_message_class("rosgraph_msgs/Log")


def set_bool(req: Any) -> Any:
    if req.data:
        raise ValueError("boom")
    return (True, "fine")


def test_service_call_ok_error_and_probe(make_node: Callable[..., Node]) -> None:
    server, client_node = make_node("server"), make_node("client")
    handle = server.advertise_service("/set", SetBool, set_bool)
    assert handle.uri.startswith("rosrpc://")
    client = client_node.service_client("/set", SetBool)
    answer = client.call(SetBool._request_class(data=False))
    assert (answer.success, answer.message) == (True, "fine")
    with pytest.raises(ServiceError) as failed:
        client.call(SetBool._request_class(data=True))
    assert str(failed.value) == (
        "service [/set] responded with an error: error processing request: boom"
    )
    header = client_node.probe_service("/set")
    assert header["type"] == "std_srvs/SetBool"
    assert header["md5sum"] == SetBool._md5sum
    assert header["callerid"] == "/server"


def test_service_error_texts_follow_rospy(make_node: Callable[..., Node]) -> None:
    server, client_node = make_node("texts"), make_node("asker")

    def refuse(req: Any) -> Any:
        raise ServiceError("not now")

    server.advertise_service("/refuse", Trigger, refuse)
    server.advertise_service("/none", Trigger, lambda req: None)
    with pytest.raises(ServiceError, match=r"service cannot process request: not now$"):
        client_node.service_client("/refuse", Trigger).call(Trigger._request_class())
    with pytest.raises(ServiceError, match="service handler returned None"):
        client_node.service_client("/none", Trigger).call(Trigger._request_class())
    with pytest.raises(ServiceError, match=r"^service \[/absent\] unavailable$"):
        client_node.service_client("/absent", Trigger).call(Trigger._request_class())
    with pytest.raises(ServiceError, match="already registered"):
        server.advertise_service("/refuse", Trigger, refuse)


def test_persistent_client_reuses_its_connection(make_node: Callable[..., Node]) -> None:
    server, client_node = make_node("persist_srv"), make_node("persist_cli")
    handle = server.advertise_service("/count", Trigger, lambda req: (True, "x"))
    client = client_node.service_client("/count", Trigger, persistent=True)
    for _ in range(5):
        assert client.call(Trigger._request_class()).success
    assert handle.server.calls == 5
    client.close()


def test_bad_connection_headers_are_refused(make_node: Callable[..., Node]) -> None:
    node = make_node("gatekeeper")
    node.advertise("/guarded", Twist)
    port = node.tcpros_address()[1]

    def exchange(payload: bytes) -> dict[str, str]:
        with socket.create_connection(("127.0.0.1", port), timeout=5) as sock:
            sock.sendall(payload)
            reader = FrameReader()
            while (block := reader.next_frame()) is None:
                data = sock.recv(65536)
                assert data, "closed without an error header"
                reader.feed(data)
            return decode_header(block)

    garbage = struct.pack("<I", 8) + b"\x03\x00\x00\x00abc\x00"
    assert "error" in exchange(garbage)
    assert exchange(encode_header({"callerid": "/x"})) == {
        "error": "no topic or service name detected"
    }
    assert exchange(encode_header({"topic": "/guarded", "callerid": "/x"})) == {
        "error": "Missing required 'md5sum' field"
    }
    wrong = subscriber_header(callerid="/x", topic="/guarded", md5sum="0" * 32, msg_type="*")
    assert exchange(encode_header(wrong))["error"] == (
        f"Client [/x] wants topic [/guarded] to have datatype/md5sum [*/{'0' * 32}], "
        f"but our version has [geometry_msgs/Twist/{Twist._md5sum}] Dropping connection."
    )
    unknown = subscriber_header(callerid="/x", topic="/other", md5sum="*", msg_type="*")
    assert exchange(encode_header(unknown))["error"].startswith(
        "[/gatekeeper] is not a publisher of [/other]"
    )
    # The node still serves everyone else.
    listener = make_node("after")
    got: list[Any] = []
    sub = listener.subscribe("/guarded", Twist, got.append)
    wait_for(lambda: sub.get_num_connections() == 1)
    wait_for(lambda: node.publications["/guarded"].connection_count() == 1)


def test_publisher_queue_drops_the_oldest_frames() -> None:
    from rosx.transport.loop_thread import process_loop

    left, right = socket.socketpair()
    left.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 4096)
    right.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stream = OutgoingStream(left, process_loop(), queue_size=3)
    frames = [frame(bytes([i]) * 20000) for i in range(40)]
    for item in frames:
        stream.send(item)
    assert stream.dropped > 0
    assert stream.queued <= 4  # the queue, and maybe a frame half on the wire
    right.setblocking(True)
    reader = FrameReader()
    received: list[bytes] = []
    right.settimeout(5)
    while not received or received[-1] != frames[-1][4:]:
        reader.feed(right.recv(1 << 20))
        received.extend(reader.frames())
    assert all(len(set(payload)) == 1 and len(payload) == 20000 for payload in received)
    indices = [payload[0] for payload in received]
    assert indices == sorted(indices)
    assert indices[-3:] == [37, 38, 39]
    assert len(indices) < 40
    stream.close()
    right.close()


def test_parameters(make_node: Callable[..., Node], master: str) -> None:
    node = make_node("paramy", namespace="/ns")
    params = node.params
    params.set("~private", 3)
    params.set("relative", {"a": 1, "b": [1, 2]})
    assert params.get("/ns/paramy/private") == 3
    assert params.get("relative/b") == [1, 2]
    assert params.has("relative") and not params.has("nothing")
    assert params.get("nothing", "dflt") == "dflt"
    with pytest.raises(KeyError):
        params.get("nothing")
    assert params.search("relative") == "/ns/relative"
    assert "/ns/relative/a" in params.names()
    assert params.get_cached("relative/a") == 1
    other = make_node("setter")
    other.params.set("/ns/relative/a", 42)
    wait_for(lambda: params.get_cached("relative/a") == 42)
    params.delete("relative")
    with pytest.raises(KeyError):
        params.delete("relative")


def test_rosout_and_logger_services(make_node: Callable[..., Node]) -> None:
    lines: list[tuple[int, str]] = []
    node = make_node("logger", console=lambda level, line: lines.append((level, line)))
    watcher = make_node("watcher")
    got: list[Any] = []
    sub = watcher.subscribe("/rosout", Log, got.append)
    wait_for(lambda: sub.get_num_connections() >= 1)
    node.log(rosout.INFO, "hello", file="f.py", function="fn", line=7)
    node.log(rosout.DEBUG, "hidden")
    wait_for(lambda: any(m.name == "/logger" and m.msg == "hello" for m in got))
    record = next(m for m in got if m.msg == "hello")
    assert (record.level, record.file, record.function, record.line) == (2, "f.py", "fn", 7)
    assert "/rosout" in record.topics
    assert record.header.stamp.secs > 0
    assert not any(m.msg == "hidden" for m in got)
    assert lines and lines[0][0] == rosout.INFO
    assert lines[0][1].startswith("[INFO] [") and lines[0][1].endswith("]: hello")

    client = watcher.service_client("/logger/get_loggers", get_service_class("roscpp/GetLoggers"))
    loggers = {lg.name: lg.level for lg in client.call(client.request_class()).loggers}
    assert loggers["rosout"] == "INFO"
    setter = watcher.service_client(
        "/logger/set_logger_level", get_service_class("roscpp/SetLoggerLevel")
    )
    setter.call(setter.request_class(logger="rosout", level="debug"))
    node.log(rosout.DEBUG, "now visible")
    wait_for(lambda: any(m.msg == "now visible" for m in got))


def test_a_node_starts_with_a_typeless_roscpp_on_the_package_path(
    master: str, tmp_path: Path
) -> None:
    # Debian's libroscpp-dev leaves /usr/share/roscpp with a manifest and no msg/srv files.
    (tmp_path / "roscpp").mkdir()
    (tmp_path / "roscpp" / "package.xml").write_text("<package><name>roscpp</name></package>\n")
    script = (
        "from rosx.node import Node\n"
        f"node = Node('/typeless', master_uri={master!r}).start()\n"
        "print(sorted(node.services))\n"
        "node.shutdown('done')\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script],
        capture_output=True,
        text=True,
        env=clean_environ(ROS_PACKAGE_PATH=str(tmp_path)),
        timeout=60,
        check=False,
    )
    assert (done.returncode, done.stderr) == (0, "")
    assert "/typeless/get_loggers" in done.stdout


def test_console_line_follows_rosconsole_format() -> None:
    line = rosout.console_line(rosout.WARN, "careful", stamp=12.5, environ={})
    assert line == "[WARN] [12.500000]: careful"
    custom = rosout.console_line(
        rosout.ERROR,
        "bad",
        node="/n",
        stamp=1.0,
        environ={"ROSCONSOLE_FORMAT": "${node} ${severity} ${message} ${time}"},
    )
    assert custom == "/n ERROR bad 1.000000"
    out, err = io.StringIO(), io.StringIO()
    rosout.print_console(rosout.INFO, "to stdout", stdout=out, stderr=err)
    rosout.print_console(rosout.ERROR, "to stderr", stdout=out, stderr=err)
    assert (out.getvalue(), err.getvalue()) == ("to stdout\n", "to stderr\n")


def test_node_answers_get_pid_over_xmlrpc(make_node: Callable[..., Node]) -> None:
    node = make_node("pid")
    assert call(node.uri, "getPid", "/x")[2] > 0
