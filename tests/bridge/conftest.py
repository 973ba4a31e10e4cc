"""A core, a turtlesim and a bridge on free ports, shared by a test module."""

from __future__ import annotations

import secrets
from collections.abc import Iterator
from dataclasses import dataclass

import pytest

from rosx.bridge.app import Bridge, BridgeOptions
from rosx_turtle.node.turtlesim import TurtlesimNode
from rosx_turtle.roscpp import NodeArgs


@dataclass
class Running:
    """What a module's tests reach: the master, the bridge's port and its environment."""

    master: str
    port: int
    environ: dict[str, str]
    bridge: Bridge
    lines: list[str]

    @property
    def url(self) -> str:
        return f"ws://127.0.0.1:{self.port}"


def start_bridge(master: str, **options: object) -> tuple[Bridge, list[str]]:
    """A bridge on a free port of the loopback; its log lines collected."""
    environ = {"ROS_MASTER_URI": master, "ROS_IP": "127.0.0.1"}
    lines: list[str] = []
    # A name of its own (this module may be imported twice, as conftest and by path): a second
    # node of one name makes the master shut the first down.
    name = f"rosbridge_websocket_{secrets.token_hex(4)}"
    settings = BridgeOptions(port=0, master_uri=master, environ=environ, node_name=name)
    for key, value in options.items():
        setattr(settings, key, value)
    return Bridge(settings, log=lines.append).start(), lines


@pytest.fixture(scope="module")
def running(master: str) -> Iterator[Running]:
    """turtlesim and a bridge (with rosapi) on the module's master."""
    environ = {"ROS_MASTER_URI": master, "ROS_IP": "127.0.0.1"}
    sim = TurtlesimNode(NodeArgs.parse([], "turtlesim"), environ=environ).start()
    bridge, lines = start_bridge(master)
    try:
        yield Running(master, bridge.port, environ, bridge, lines)
    finally:
        bridge.shutdown("test over")
        sim.shutdown("test over")
