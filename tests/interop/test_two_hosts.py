"""A graph across two machines, and over IPv6 loopback.

The two machines are network namespaces the test makes (``ip netns add``), joined by a veth pair
with link-local addresses that exist only inside them, and removed after. A rosx master runs on
host A; rosx nodes run on both hosts and a rospy node (ROS 1's, where installed) on host B, each
with ``ROS_IP`` set to its host's address; topics and services flow both ways. Where namespaces
cannot be made (not root, no ``ip``, a container that forbids them) those tests skip.
"""

from __future__ import annotations

import contextlib
import os
import random
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.support.cli import ROSX_COMMAND, clean_environ
from tests.support.procs import free_port, stop, wait_for
from tests.support.ros1 import ROS1, ROS1_PYTHON, ros1_environ

#: A node as a lab sheet writes it (rospy's API, so rosx and ROS 1 both run it): ``NAME OTHER…``.
#: It publishes ``/from_NAME`` and serves ``/svc_NAME``; for each OTHER it prints the first
#: message of ``/from_OTHER`` and the answer of ``/svc_OTHER``, then keeps serving.
NODE = """
import sys
import rospy
from std_msgs.msg import String
from std_srvs.srv import Trigger, TriggerResponse

me, others = sys.argv[1], sys.argv[2:]
rospy.init_node("node_" + me)
seen = set()

def heard(msg):
    if msg.data not in seen:
        seen.add(msg.data)
        print("topic: " + msg.data, flush=True)

subscribers = [rospy.Subscriber("/from_" + o, String, heard) for o in others]
pub = rospy.Publisher("/from_" + me, String, queue_size=10)
rospy.Service("/svc_" + me, Trigger, lambda req: TriggerResponse(True, "answer from " + me))
for other in others:
    rospy.wait_for_service("/svc_" + other, timeout=120)
    print("service: " + rospy.ServiceProxy("/svc_" + other, Trigger)().message, flush=True)
rate = rospy.Rate(5)
while not rospy.is_shutdown():
    pub.publish(String("hello from " + me))
    rate.sleep()
"""


class Process:
    """A child process whose output lines are collected as they come; stopped by `close`."""

    def __init__(self, args: list[str], env: dict[str, str]) -> None:
        self.lines: list[str] = []
        self.process = subprocess.Popen(
            args,
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,
        )
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            self.lines.append(line.rstrip("\n"))

    def has(self, *expected: str) -> bool:
        return set(expected) <= set(self.lines)

    def close(self) -> None:
        stop(self.process)
        self._reader.join(10)


@dataclass(frozen=True)
class Hosts:
    """Two namespaces, ``a`` and ``b``, with ``ip_a`` and ``ip_b`` on the veth pair."""

    a: str
    b: str
    ip_a: str
    ip_b: str


def _ip(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["ip", *args], capture_output=True, text=True, timeout=30, check=False)


@pytest.fixture
def hosts() -> Iterator[Hosts]:
    if sys.platform != "linux" or shutil.which("ip") is None:
        pytest.skip("network namespaces need Linux's ip command")
    tag = f"{os.getpid() % 100000}{random.randrange(100)}"
    a, b = f"rosxa{tag}", f"rosxb{tag}"
    subnet = f"169.254.{random.randrange(1, 255)}"
    made: list[str] = []
    try:
        for ns in (a, b):
            done = _ip("netns", "add", ns)
            if done.returncode != 0:
                pytest.skip(f"network namespaces are not allowed here: {done.stderr.strip()}")
            made.append(ns)
        veth = ("link", "add", f"va{tag}", "netns", a, "type", "veth")
        steps = [
            (*veth, "peer", "name", f"vb{tag}", "netns", b),
            ("-n", a, "address", "add", f"{subnet}.1/24", "dev", f"va{tag}"),
            ("-n", b, "address", "add", f"{subnet}.2/24", "dev", f"vb{tag}"),
            ("-n", a, "link", "set", f"va{tag}", "up"),
            ("-n", b, "link", "set", f"vb{tag}", "up"),
            ("-n", a, "link", "set", "lo", "up"),
            ("-n", b, "link", "set", "lo", "up"),
        ]
        for step in steps:
            done = _ip(*step)
            if done.returncode != 0:
                pytest.skip(f"cannot join the namespaces (ip {' '.join(step)}): {done.stderr}")
        yield Hosts(a, b, f"{subnet}.1", f"{subnet}.2")
    finally:
        for ns in made:  # the veth pair goes with its namespaces
            _ip("netns", "del", ns)


@contextlib.contextmanager
def processes() -> Iterator[list[Process]]:
    started: list[Process] = []
    try:
        yield started
    finally:
        for process in reversed(started):
            process.close()


def _on(ns: str | None, args: list[str]) -> list[str]:
    return ["ip", "netns", "exec", ns, *args] if ns else args


def _rosx(*argv: str) -> list[str]:
    return [*ROSX_COMMAND, *argv]


def _wait_for_lines(process: Process, *expected: str) -> None:
    try:
        wait_for(lambda: process.has(*expected), timeout=90, what=", ".join(expected))
    except TimeoutError:
        output = "\n".join(process.lines)
        raise AssertionError(f"{expected} not seen; the output:\n{output}") from None


def test_a_graph_across_two_hosts(hosts: Hosts, tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text(NODE)
    port = free_port()
    master = f"http://{hosts.ip_a}:{port}"
    rospy = ROS1 and sys.executable != ROS1_PYTHON
    with processes() as started:
        core = Process(
            _on(hosts.a, _rosx("roscore", "-p", str(port))),
            clean_environ(ROS_IP=hosts.ip_a, ROS_MASTER_URI=master),
        )
        started.append(core)
        _wait_for_lines(core, "started core service [/rosout]")

        def rosx_node(ns: str, ip: str, *names: str) -> Process:
            env = clean_environ(ROS_IP=ip, ROS_MASTER_URI=master)
            started.append(Process(_on(ns, _rosx("run-script", str(node), *names)), env))
            return started[-1]

        on_a = rosx_node(hosts.a, hosts.ip_a, "a", "b", *(["r"] if rospy else []))
        on_b = rosx_node(hosts.b, hosts.ip_b, "b", "a")
        if rospy:
            env = ros1_environ(ROS_IP=hosts.ip_b, ROS_MASTER_URI=master)
            started.append(Process(_on(hosts.b, [ROS1_PYTHON, str(node), "r", "a"]), env))
            _wait_for_lines(started[-1], "service: answer from a", "topic: hello from a")
            _wait_for_lines(on_a, "service: answer from r", "topic: hello from r")
        _wait_for_lines(on_a, "service: answer from b", "topic: hello from b")
        _wait_for_lines(on_b, "service: answer from a", "topic: hello from a")
        # The master on A lists what B advertises, with B's address in its URIs.
        listing = subprocess.run(
            _on(hosts.b, _rosx("rosnode", "info", "/node_b")),
            env=clean_environ(ROS_IP=hosts.ip_b, ROS_MASTER_URI=master),
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        ).stdout
        assert f"contacting node http://{hosts.ip_b}:" in listing


def test_a_ros_ip_of_another_host_is_diagnosed(hosts: Hosts, tmp_path: Path) -> None:
    script = tmp_path / "init.py"
    script.write_text("import rospy\nrospy.init_node('lost')\nprint('up', flush=True)\n")
    port = free_port()
    master = f"http://{hosts.ip_a}:{port}"
    with processes() as started:
        core = Process(
            _on(hosts.a, _rosx("roscore", "-p", str(port))),
            clean_environ(ROS_IP=hosts.ip_a, ROS_MASTER_URI=master),
        )
        started.append(core)
        _wait_for_lines(core, "started core service [/rosout]")
        # On B, but advertising A's address: nobody could reach this node.
        done = subprocess.run(
            _on(hosts.b, _rosx("run-script", str(script))),
            env=clean_environ(ROS_IP=hosts.ip_a, ROS_MASTER_URI=master),
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
    assert done.stdout == "up\n"
    (warning,) = done.stderr.splitlines()
    assert warning.startswith("[WARN] [")
    assert warning.endswith(
        f"]: ROS_IP is {hosts.ip_a}, which is not an address of this machine: other nodes "
        "cannot connect to this one (set ROS_IP to one of this machine's addresses)"
    )


def _ipv6_loopback() -> bool:
    import socket

    try:
        with socket.socket(socket.AF_INET6) as probe:
            probe.bind(("::1", 0))
    except OSError:
        return False
    return True


@pytest.mark.skipif(not _ipv6_loopback(), reason="no IPv6 loopback here")
def test_a_graph_over_ipv6_loopback(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text(NODE)
    port = free_port()
    master = f"http://[::1]:{port}"
    env = clean_environ(ROS_IP="::1", ROS_MASTER_URI=master)
    with processes() as started:
        core = Process(_rosx("roscore", "-p", str(port)), env)
        started.append(core)
        _wait_for_lines(core, "started core service [/rosout]")
        on_a = Process(_rosx("run-script", str(node), "a", "b"), env)
        started.append(on_a)
        on_b = Process(_rosx("run-script", str(node), "b", "a"), env)
        started.append(on_b)
        _wait_for_lines(on_a, "service: answer from b", "topic: hello from b")
        _wait_for_lines(on_b, "service: answer from a", "topic: hello from a")
        topics = subprocess.run(
            _rosx("rostopic", "list"),
            env=env,
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        ).stdout
        assert {"/from_a", "/from_b", "/rosout"} <= set(topics.split())
