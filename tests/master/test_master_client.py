"""The one master client: several calls in one round trip, and whether a master answers."""

from __future__ import annotations

import socket

import pytest

from rosx.master.client import MasterClient, MasterError


def test_multicall_returns_each_value_in_order(master: str) -> None:
    client = MasterClient(master, "/tester")
    calls = [("setParam", ("/mc/a", 1)), ("setParam", ("/mc/b", "two")), ("getParam", ("/mc",))]
    try:
        assert client.multicall(calls) == [0, 0, {"a": 1, "b": "two"}]
        assert client.multicall([]) == []
    finally:
        client.close()


def test_multicall_raises_the_first_refusal_with_its_status(master: str) -> None:
    client = MasterClient(master, "/tester")
    try:
        with pytest.raises(MasterError) as refused:
            client.multicall([("setParam", ("/mc/c", 3)), ("getParam", ("/mc/nope",))])
        assert refused.value.status == "Parameter [/mc/nope] is not set"
        assert client.call("getParam", "/mc/c") == 3
    finally:
        client.close()


def test_is_online_tells_a_master_from_a_closed_port(master: str) -> None:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        closed = f"http://127.0.0.1:{probe.getsockname()[1]}"
    assert MasterClient(master, "/tester").is_online()
    assert not MasterClient(closed, "/tester", timeout=1.0).is_online()
