"""``rosx rosbridge`` and ``roslaunch rosbridge_server rosbridge_websocket.launch`` as a user
runs them: processes of their own, a client served, Ctrl-C ending them cleanly."""

from __future__ import annotations

import json
import re
import signal
import socket
import subprocess
import time
from collections.abc import Iterator

import pytest
from websockets.sync.client import connect

from tests.support.cli import ROSX_COMMAND, clean_environ, rosx, rosx_process


@pytest.fixture
def environ(master: str) -> dict[str, str]:
    return clean_environ(ROS_MASTER_URI=master, ROS_IP="127.0.0.1")


def start(argv: list[str], environ: dict[str, str]) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [*ROSX_COMMAND, *argv],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=environ,
    )  # fmt: skip


def url_of(proc: subprocess.Popen[str]) -> Iterator[str]:
    """The URLs the process says it serves, as it prints them."""
    assert proc.stdout is not None
    for line in proc.stdout:
        found = re.search(r"server started at (ws://\S+)", line)
        if found:
            yield found.group(1)


def stop(proc: subprocess.Popen[str]) -> int:
    proc.send_signal(signal.SIGINT)
    try:
        return proc.wait(timeout=20)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        if proc.stdout is not None:
            proc.stdout.close()


def call_rosapi_nodes(url: str) -> list[str]:
    """``/rosapi/nodes``, asked until rosapi (a process of its own under roslaunch) answers."""
    deadline = time.monotonic() + 20
    with connect(url) as ws:
        while True:
            ws.send(json.dumps({"op": "call_service", "service": "/rosapi/nodes", "id": "n"}))
            answer = json.loads(ws.recv(timeout=20))
            while answer["op"] != "service_response":
                answer = json.loads(ws.recv(timeout=20))
            if answer["result"] or time.monotonic() > deadline:
                break
            time.sleep(0.1)
    assert answer["result"] is True, answer
    nodes: list[str] = answer["values"]["nodes"]
    return nodes


def test_rosx_rosbridge_serves_both_protocols_until_ctrl_c(environ: dict[str, str]) -> None:
    proc = start(["rosbridge", "--port", "0", "--foxglove-port", "0"], environ)
    try:
        urls = url_of(proc)
        rosbridge, foxglove = next(urls), next(urls)
        assert rosbridge.startswith("ws://127.0.0.1:")
        assert {"/rosbridge_websocket", "/rosapi"} <= set(call_rosapi_nodes(rosbridge))
        with connect(foxglove, subprotocols=["foxglove.websocket.v1"]) as ws:  # type: ignore[list-item]
            assert json.loads(ws.recv(timeout=20))["op"] == "serverInfo"
    finally:
        status = stop(proc)
    assert status == 0


def test_the_launch_file_starts_rosbridge_and_rosapi(environ: dict[str, str]) -> None:
    proc = start(
        ["roslaunch", "rosbridge_server", "rosbridge_websocket.launch", "port:=0"], environ
    )
    try:
        url = next(url_of(proc))
        assert {"/rosbridge_websocket", "/rosapi"} <= set(call_rosapi_nodes(url))
    finally:
        status = stop(proc)
    assert status == 0


@pytest.mark.parametrize(
    ("argv", "error"),
    [
        (["--port", "http"], "rosx rosbridge: error: 'http' is not a port number (0 to 65535)"),
        (
            ["--max-message-size", "-1"],
            "rosx rosbridge: error: --max-message-size: '-1' is not a number of bytes",
        ),
        (["extra"], "rosx rosbridge: error: rosx rosbridge takes no arguments"),
    ],
)
def test_bad_options(argv: list[str], error: str) -> None:
    result = rosx("rosbridge", *argv)
    assert result.status == 2
    assert result.err.splitlines()[-1] == error


def test_a_port_in_use_is_one_line(environ: dict[str, str]) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = rosx("rosbridge", "--port", str(port), "--no-rosapi", environ=environ)
    assert (result.status, result.err) == (
        1,
        f"Unable to start the bridge on 127.0.0.1:{port}: address already in use\n",
    )


def test_an_address_that_does_not_resolve_is_one_line(environ: dict[str, str]) -> None:
    result = rosx("rosbridge", "--address", "no-such-host.invalid", "--no-rosapi", environ=environ)
    assert (result.status, result.err) == (
        1,
        "Unable to start the bridge on no-such-host.invalid:9090: name or service not known\n",
    )


@pytest.mark.parametrize(
    ("name", "param", "error"),
    [
        ("a", "_port:=http", "~port: 'http' is not a port number (0 to 65535)"),
        ("b", "_port:=70000", "~port: '70000' is not a port number (0 to 65535)"),
        ("c", "_max_message_size:=-3", "~max_message_size: '-3' is not a number of bytes"),
    ],
)
def test_a_bad_private_parameter_is_one_line(
    master: str, name: str, param: str, error: str
) -> None:
    # as `roslaunch rosbridge_server rosbridge_websocket.launch port:=http` sets it; a node
    # name each, as the parameters stay on the master
    program = ("rosrun", "rosbridge_server", "rosbridge_websocket", f"__name:=bridge_{name}")
    result = rosx_process(*program, param, ROS_MASTER_URI=master, ROS_IP="127.0.0.1")
    assert (result.status, result.err) == (1, error + "\n")
