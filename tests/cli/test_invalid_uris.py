"""URIs that any client may register and that do not parse: one-line errors, never tracebacks.

``str.isdigit`` accepts ``²``, ``int`` does not: ``http://127.0.0.1:1²/`` and
``rosrpc://127.0.0.1:1²`` are the URIs of a node and a service that cannot be called. ROS 1's
rosservice says the service ``has an invalid RPC URI``; rosnode says the same of the node.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from rosx.transport.client import XmlRpcClient
from tests.support.cli import Result, clean_environ, rosx

BAD_API = "http://127.0.0.1:1²/"
BAD_SERVICE = "rosrpc://127.0.0.1:1²"


@pytest.fixture
def env(master: str) -> Iterator[dict[str, str]]:
    """The master, with node ``/bad`` (URI ``BAD_API``) serving ``/bad_srv`` at ``BAD_SERVICE``."""
    client = XmlRpcClient(timeout=5)
    client.call(master, "registerPublisher", "/bad", "/bad_topic", "std_msgs/String", BAD_API)
    client.call(master, "registerService", "/bad", "/bad_srv", BAD_SERVICE, BAD_API)
    try:
        yield clean_environ(ROS_MASTER_URI=master)
    finally:
        client.call(master, "unregisterPublisher", "/bad", "/bad_topic", BAD_API)
        client.call(master, "unregisterService", "/bad", "/bad_srv", BAD_SERVICE)
        client.close()


def _run(env: dict[str, str], *argv: str) -> Result:
    return rosx(*argv, environ=env)


@pytest.mark.parametrize("command", ["call", "type", "args"])
def test_rosservice_names_the_invalid_uri(env: dict[str, str], command: str) -> None:
    done = _run(env, "rosservice", command, "/bad_srv")
    invalid = f"ERROR: service [/bad_srv] has an invalid RPC URI [{BAD_SERVICE}]\n"
    assert (done.out, done.err, done.status) == ("", invalid, 2)


def test_rosservice_info_prints_what_it_knows_first(env: dict[str, str]) -> None:
    done = _run(env, "rosservice", "info", "/bad_srv")
    assert done.out == f"Node: /bad\nURI: {BAD_SERVICE}\n"
    invalid = f"ERROR: service [/bad_srv] has an invalid RPC URI [{BAD_SERVICE}]\n"
    assert (done.err, done.status) == (invalid, 2)


def test_rosnode_ping_names_the_invalid_uri(env: dict[str, str]) -> None:
    done = _run(env, "rosnode", "ping", "/bad")
    assert done.out == "rosnode: node is [/bad]\npinging /bad with a timeout of 3.0s\n"
    assert done.err == f"ERROR: node [/bad] has an invalid RPC URI [{BAD_API}]\n"


def test_rosnode_info_prints_what_the_master_knows_then_the_error(env: dict[str, str]) -> None:
    done = _run(env, "rosnode", "info", "/bad")
    assert "Node [/bad]\nPublications: \n * /bad_topic [std_msgs/String]\n" in done.out
    assert done.out.endswith(f"\ncontacting node {BAD_API} ...\n")
    invalid = f"ERROR: node [/bad] has an invalid RPC URI [{BAD_API}]\n"
    assert (done.err, done.status) == (invalid, 1)


def test_rosnode_kill_says_killed_as_ros1_does(env: dict[str, str]) -> None:
    done = _run(env, "rosnode", "kill", "/bad")
    assert (done.out, done.err, done.status) == ("killing /bad\nkilled\n", "", 0)


def test_rosnode_machine_and_rostopic_list_host_survive_a_malformed_uri(master: str) -> None:
    client = XmlRpcClient(timeout=5)
    broken = "http://[::1/"  # urllib.parse refuses it: "Invalid IPv6 URL"
    client.call(master, "registerPublisher", "/broken", "/broken_topic", "std_msgs/String", broken)
    try:
        env = clean_environ(ROS_MASTER_URI=master)
        machines = _run(env, "rosnode", "machine")
        hosts = _run(env, "rostopic", "list", "--host")
    finally:
        client.call(master, "unregisterPublisher", "/broken", "/broken_topic", broken)
        client.close()
    assert (machines.err, machines.status) == ("", 0)
    assert (hosts.err, hosts.status) == ("", 0)
