"""`rosx.core.Core` in this process: what it hosts, how it stops, how it refuses a taken port."""

from __future__ import annotations

import socket
import threading
from collections.abc import Iterator
from typing import Any

import pytest

from rosx.core import Core, PortInUseError
from rosx.msg.codec.classes import get_message_class
from rosx.node import INFO, Node
from rosx.transport.client import XmlRpcClient
from tests.support.procs import wait_for

Log = get_message_class("rosgraph_msgs/Log")


@pytest.fixture
def core() -> Iterator[Core]:
    with Core(0, {}) as running:
        yield running


@pytest.fixture
def client() -> Iterator[XmlRpcClient]:
    with XmlRpcClient(timeout=5.0) as xmlrpc:
        yield xmlrpc


def test_master_parameters_and_rosout(core: Core, client: XmlRpcClient) -> None:
    uri = f"http://localhost:{core.port}/"
    assert core.port != 0 and core.uri == uri
    assert client.call(uri, "getUri", "/t") == [1, "", uri]

    def param(name: str) -> Any:
        code, _, value = client.call(uri, "getParam", "/t", name)
        return value if code == 1 else None

    assert param("/run_id") == core.run_id
    assert (param("/rosversion"), param("/rosdistro")) == ("1.16.0\n", "noetic\n")
    assert param("/roslaunch/uris") == {f"host_localhost__{core.port}": uri}
    _, _, (publishers, subscribers, _) = client.call(uri, "getSystemState", "/t")
    assert ["/rosout_agg", ["/rosout"]] in publishers
    assert ["/rosout", ["/rosout"]] in subscribers


def test_rosout_gathers_logs_on_rosout_agg(core: Core) -> None:
    got: list[Any] = []
    listener = Node("/listener", master_uri=core.uri, environ={}).start()
    talker = Node("/talker", master_uri=core.uri, environ={}).start()
    try:
        listener.subscribe("/rosout_agg", Log, got.append)

        def heard() -> bool:
            talker.log(INFO, "hello core")
            return any(record.msg == "hello core" for record in got)

        wait_for(heard, what="the record on /rosout_agg")
        record = next(record for record in got if record.msg == "hello core")
        assert record.name == "/talker"
    finally:
        talker.shutdown("test over")
        listener.shutdown("test over")


def test_a_shutdown_call_ends_wait_and_stop_ends_the_core(core: Core, client: XmlRpcClient) -> None:
    assert core.wait(timeout=0.01) is None
    assert client.call(core.uri, "shutdown", "/t", "bye") == [1, "shutdown", 0]
    assert core.wait(timeout=10) == "bye"
    assert client.call(core.uri, "getPid", "/t")[0] == 1  # its owner decides when it stops
    core.stop()
    assert core.wait() == "bye"


def test_stop_from_several_threads_frees_the_port() -> None:
    first = Core(0, {})
    started: list[str] = []
    starter = threading.Thread(target=lambda: started.append(first.start()))
    starter.start()
    starter.join()
    assert started == [first.uri]
    stoppers = [threading.Thread(target=first.stop) for _ in range(3)]
    for stopper in stoppers:
        stopper.start()
    for stopper in stoppers:
        stopper.join()
    assert first.wait() is None
    first.stop()
    with pytest.raises(RuntimeError):
        first.start()
    with Core(first.port, {}) as second:  # the port is free again
        assert second.uri == first.uri


def test_a_second_master_on_the_port_is_refused_in_roscores_words(core: Core) -> None:
    with pytest.raises(PortInUseError) as refused:
        Core(core.port, {}).start()
    error = refused.value
    assert (error.another_master, error.uri, error.port) == (True, core.uri, core.port)
    assert error.message == (
        "RLException: roscore cannot run as another roscore/master is already running. \n"
        "Please kill other roscore/master processes before relaunching.\n"
        f"The ROS_MASTER_URI is {core.uri}"
    )


def test_a_port_held_by_something_else_is_refused_in_roscores_words() -> None:
    with socket.create_server(("127.0.0.1", 0)) as squatter:
        port = squatter.getsockname()[1]
        with pytest.raises(PortInUseError) as refused:
            Core(port, {}).start()
    error = refused.value
    assert (error.another_master, error.uri, error.port) == (
        False,
        f"http://localhost:{port}/",
        port,
    )
    assert error.message == f"ERROR: Unable to start XML-RPC server, port {port} is already in use"
    assert str(error) == error.message
