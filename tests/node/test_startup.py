"""Private parameters from the command line (``_name:=value``), set as ROS 1 sets them."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from rosx.master.client import MasterClient
from rosx.names import parse_remap_args
from rosx.node import Node
from rosx.node.startup import (
    ParamArgsError,
    load_private_params,
    private_param_keys,
    set_private_params,
)
from rosx.transport.client import XmlRpcClient


def _get(master: str, name: str) -> Any:
    client = XmlRpcClient(timeout=5.0)
    try:
        code, status, value = client.call(master, "getParam", "/test", name)
    finally:
        client.close()
    assert code == 1, status
    return value


def test_values_are_typed_as_yaml() -> None:
    args = parse_remap_args(
        [
            "_i:=1",
            "_f:=1.0",
            "_b:=true",
            "_s:='1'",
            "_w:=hello",
            "_l:=[1, a]",
            "_d:={a: 1}",
            "_i:=2",
        ]
    )
    values = load_private_params(args.params)
    assert values == {
        "i": 2, "f": 1.0, "b": True, "s": "1", "w": "hello", "l": [1, "a"], "d": {"a": 1}
    }  # fmt: skip
    assert [type(values[k]) for k in ("i", "f", "b", "s")] == [int, float, bool, str]


def test_names_resolve_privately_after_name_namespace_and_remapping() -> None:
    keyed = private_param_keys({"rate": 5}, node_name="talker", namespace="/robot")
    assert keyed == {"/robot/talker/rate": 5}
    assert private_param_keys({"rate": 5}, node_name="/other/n") == {"/other/n/rate": 5}
    remapped = private_param_keys(
        {"rate": 5}, node_name="/n", remappings={"/n/rate": "/global_rate"}
    )
    assert remapped == {"/global_rate": 5}


@pytest.mark.parametrize(
    ("arg", "error"),
    [
        ("_x:=[1", "invalid command-line parameters: while parsing a flow sequence"),
        ("_x:=null", "invalid command-line parameters: cannot set parameter [~x]: the Parameter"),
        (
            "_x:=3000000000",
            "invalid command-line parameters: cannot set parameter [~x]: 3000000000",
        ),
        ("_x:={a:1}", "invalid command-line parameters: cannot set parameter [~x/a:1]: YAML needs"),
    ],
)
def test_bad_values_stop_before_anything_is_set(master: str, arg: str, error: str) -> None:
    proxy = MasterClient(master, "/bad", XmlRpcClient(timeout=5.0))
    with pytest.raises(ParamArgsError) as refused:
        set_private_params(proxy, parse_remap_args(["_ok:=1", arg]), node_name="/bad")
    assert str(refused.value).startswith(error)
    code, _, _ = proxy.client.call(master, "getParam", "/test", "/bad/ok")
    assert code == -1
    proxy.client.close()


def test_set_private_params_on_the_master(master: str) -> None:
    proxy = MasterClient(master, "/setter", XmlRpcClient(timeout=5.0))
    args = parse_remap_args(["prog", "_speed:=2.5", "_name:=bob", "chatter:=/c", "__ns:=/x"])
    keyed = set_private_params(proxy, args, node_name="driver", namespace="/x")
    proxy.client.close()
    assert keyed == {"/x/driver/speed": 2.5, "/x/driver/name": "bob"}
    assert _get(master, "/x/driver") == {"speed": 2.5, "name": "bob"}


def test_a_node_sets_its_private_params_when_it_starts(
    make_node: Callable[..., Node], master: str
) -> None:
    node = make_node("turtle", namespace="/sim", private_params={"scale": "3", "mode": "fast"})
    assert node.params.get("~scale") == 3
    assert _get(master, "/sim/turtle/mode") == "fast"


def test_a_node_with_a_bad_private_param_does_not_start(master: str) -> None:
    node = Node("broken", master_uri=master, environ={}, private_params={"x": "{a: [1"})
    with pytest.raises(ParamArgsError):
        node.start()
    assert node.is_shutdown()
