"""A rosx node and a rospy node on a real ``roscore``: topics and services in both directions,
latching, 1 MiB images, and ROS 1's ``rosnode info`` describing the rosx node.

roscore runs on a free port; it and its children (rosmaster, rosout) are stopped by PID when
the module ends. The rospy node is a script run by Debian's /usr/bin/python3; it reports what
it receives as JSON lines on its stdout. Skipped where ROS 1 or rospy is absent.
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import signal
import socket
import subprocess
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node, ServiceError

ROS1_PYTHON = Path("/usr/bin/python3")
ROSCORE = Path("/usr/bin/roscore")


def _ros1_present() -> bool:
    if not (ROS1_PYTHON.exists() and ROSCORE.exists()):
        return False
    probe = [
        str(ROS1_PYTHON),
        "-c",
        "import rospy, geometry_msgs.msg, sensor_msgs.msg, std_srvs.srv",
    ]
    return subprocess.run(probe, capture_output=True, check=False).returncode == 0


pytestmark = pytest.mark.skipif(not _ros1_present(), reason="ROS 1 (roscore, rospy) is absent")

ROSPY_NODE = r"""
import json, sys, time, threading
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Image
from std_msgs.msg import String
from std_srvs.srv import SetBool, SetBoolResponse

def report(**event):
    sys.stdout.write(json.dumps(event) + "\n")
    sys.stdout.flush()

FLOOD = 20000
rospy.init_node("rospy_node", disable_signals=True)
seen = set()
def once(kind, **event):
    if kind not in seen:
        seen.add(kind)
        report(kind=kind, **event)

rospy.Subscriber("/rosx_twist", Twist, lambda m: once("twist", x=m.linear.x))
rospy.Subscriber("/rosx_image", Image,
                 lambda m: once("image", size=len(m.data), width=m.width, first=m.data[:4].hex()))
rospy.Subscriber("/rosx_latched", String, lambda m: once("latched", data=m.data))
flood = []
def on_flood(m):
    flood.append(int(m.linear.y))
    if len(flood) == FLOOD:
        report(kind="flood", count=len(flood), in_order=flood == list(range(FLOOD)))
rospy.Subscriber("/rosx_flood", Twist, on_flood)
rospy.Service("/rospy_srv", SetBool,
              lambda req: SetBoolResponse(success=req.data, message="rospy says hi"))
latched = rospy.Publisher("/rospy_latched", String, queue_size=1, latch=True)
latched.publish(String(data="from rospy, latched"))
twist_pub = rospy.Publisher("/rospy_twist", Twist, queue_size=10)
image_pub = rospy.Publisher("/rospy_image", Image, queue_size=2)
image = Image(height=512, width=512, encoding="rgba8", step=2048, data=bytes(range(256)) * 4096)

def call_rosx():
    rospy.wait_for_service("/rosx_srv", timeout=30)
    proxy = rospy.ServiceProxy("/rosx_srv", SetBool)
    answer = proxy(True)
    report(kind="rosx_srv", success=answer.success, message=answer.message)
    try:
        proxy(False)
    except rospy.ServiceException as exc:
        report(kind="rosx_srv_error", text=str(exc))
threading.Thread(target=call_rosx, daemon=True).start()
report(kind="ready")
while not rospy.is_shutdown():
    twist = Twist()
    twist.linear.x = 4.5
    twist_pub.publish(twist)
    image_pub.publish(image)
    time.sleep(0.1)
"""


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def _children(pid: int) -> list[int]:
    found: list[int] = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            with contextlib.suppress(OSError):
                stat = (entry / "stat").read_text()
                if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                    found.append(int(entry.name))
    return found


def _stop(pid: int) -> None:
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
        try:
            os.kill(pid, sig)
        except ProcessLookupError:
            return
        for _ in range(30):
            time.sleep(0.1)
            if not Path(f"/proc/{pid}").exists() or "Z" in _state(pid):
                return


def _state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return "Z"


def _env(master: str, home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    env.pop("PYTHONPATH", None)
    env.update(
        ROS_MASTER_URI=master,
        ROS_HOSTNAME="localhost",
        ROS_HOME=str(home),
        ROS_LOG_DIR=str(home / "log"),
        ROS_PACKAGE_PATH="/usr/share",
        PYTHONUNBUFFERED="1",
    )
    return env


@pytest.fixture(scope="module")
def roscore(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[str, dict[str, str]]]:
    """A real roscore on a free port; yields its URI and the environment for ROS 1 tools."""
    home = tmp_path_factory.mktemp("ros_home")
    port = _free_port()
    uri = f"http://127.0.0.1:{port}/"
    env = _env(uri, home)
    proc = subprocess.Popen(
        [str(ROSCORE), "-p", str(port)],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        from rosx.transport.client import call

        deadline = time.monotonic() + 30
        while True:
            try:
                call(uri, "getPid", "/test", timeout=1.0)
                break
            except Exception:
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.2)
        yield uri, env
    finally:
        children = _children(proc.pid)
        _stop(proc.pid)
        for child in children:
            _stop(child)
        proc.wait(10)


class RospyNode:
    """The rospy script as a process, with its reports in a queue."""

    def __init__(self, env: dict[str, str]) -> None:
        self.proc = subprocess.Popen(
            [str(ROS1_PYTHON), "-c", ROSPY_NODE],
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
        )
        self.events: queue.Queue[dict[str, Any]] = queue.Queue()
        self.seen: dict[str, dict[str, Any]] = {}
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with contextlib.suppress(ValueError):
                self.events.put(json.loads(line))

    def wait(self, kind: str, timeout: float = 30.0) -> dict[str, Any]:
        deadline = time.monotonic() + timeout
        while kind not in self.seen:
            left = deadline - time.monotonic()
            if left <= 0:
                raise AssertionError(f"the rospy node never reported {kind!r}: {self.seen}")
            with contextlib.suppress(queue.Empty):
                event = self.events.get(timeout=left)
                self.seen.setdefault(event["kind"], event)
        return self.seen[kind]

    def stop(self) -> None:
        _stop(self.proc.pid)
        self.proc.wait(10)


Twist = get_message_class("geometry_msgs/Twist")
Image = get_message_class("sensor_msgs/Image")
String = get_message_class("std_msgs/String")
SetBool = get_service_class("std_srvs/SetBool")
PIXELS = bytes(range(256)) * 4096


class Session:
    """The rosx node, what it received, and the rospy node, running together."""

    def __init__(self, node: Node, rospy_node: RospyNode, env: dict[str, str]) -> None:
        self.node = node
        self.rospy = rospy_node
        self.env = env
        self.twists: list[float] = []
        self.images: list[Any] = []


def _refuse_false(req: Any) -> Any:
    if not req.data:
        raise ValueError("rosx refuses false")
    return (True, "rosx says hi")


@pytest.fixture(scope="module")
def session(roscore: tuple[str, dict[str, str]]) -> Iterator[Session]:
    """The rosx node publishing, subscribing and serving; then the rospy node started."""
    master, env = roscore
    node = Node("rosx_node", master_uri=master, environ={}).start()
    rospy_node: RospyNode | None = None
    try:
        latched = node.advertise("/rosx_latched", String, latch=True)
        latched.publish(String(data="from rosx, latched"))
        node.advertise_service("/rosx_srv", SetBool, _refuse_false)
        rospy_node = RospyNode(env)
        state = Session(node, rospy_node, env)
        node.subscribe("/rospy_twist", Twist, lambda m: state.twists.append(m.linear.x))
        node.subscribe("/rospy_image", Image, state.images.append, queue_size=2)
        rospy_node.wait("ready")
        yield state
    finally:
        if rospy_node is not None:
            rospy_node.stop()
        node.shutdown("test over")


def _wait(predicate: Callable[[], object], timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.05)


def test_rosx_publishes_to_rospy(session: Session) -> None:
    twist_pub = session.node.advertise("/rosx_twist", Twist, queue_size=10)
    image_pub = session.node.advertise("/rosx_image", Image, queue_size=2)
    image = Image(height=512, width=512, encoding="rgba8", step=2048, data=PIXELS)
    twist = Twist()
    twist.linear.x = 1.25
    seen = session.rospy.seen
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and not ({"twist", "image"} <= seen.keys()):
        twist_pub.publish(twist)
        image_pub.publish(image)
        time.sleep(0.1)
        while not session.rospy.events.empty():
            event = session.rospy.events.get()
            seen.setdefault(event["kind"], event)
    assert session.rospy.wait("twist")["x"] == 1.25
    got_image = session.rospy.wait("image")
    assert (got_image["size"], got_image["width"]) == (1 << 20, 512)
    assert got_image["first"] == "00010203"


def test_a_flood_reaches_rospy_whole_and_in_order(session: Session) -> None:
    # rospy's subscriber calls back on its reading thread: it falls behind, the kernel holds
    # bytes back, and the publisher writes the flood in batches.
    pub = session.node.advertise("/rosx_flood", Twist, queue_size=None)
    _wait(lambda: pub.get_num_connections() == 1)
    (link,) = session.node.publications["/rosx_flood"].links
    held = False
    twist = Twist()
    for number in range(20_000):
        twist.linear.y = float(number)
        pub.publish(twist)
        held = held or link.stream.holding
    assert held
    flood = session.rospy.wait("flood", timeout=60)
    assert (flood["count"], flood["in_order"]) == (20_000, True)


def test_rospy_publishes_to_rosx(session: Session) -> None:
    _wait(lambda: session.twists and session.images)
    assert session.twists[0] == 4.5
    image = session.images[0]
    assert len(image.data) == 1 << 20
    assert image.data[:4] == b"\x00\x01\x02\x03"
    assert image._connection_header["callerid"] == "/rospy_node"


def test_latched_messages_reach_late_subscribers(session: Session) -> None:
    assert session.rospy.wait("latched")["data"] == "from rosx, latched"
    late: list[str] = []
    session.node.subscribe("/rospy_latched", String, lambda m: late.append(m.data))
    _wait(lambda: late)
    assert late == ["from rospy, latched"]


def test_services_both_ways(session: Session) -> None:
    assert session.rospy.wait("rosx_srv") == {
        "kind": "rosx_srv",
        "success": True,
        "message": "rosx says hi",
    }
    # rospy (Python 3) shows the error text as a bytes repr: b'...'.
    text = session.rospy.wait("rosx_srv_error")["text"]
    assert "error processing request: rosx refuses false" in text
    client = session.node.service_client("/rospy_srv", SetBool)
    answer = client.call(SetBool._request_class(data=True))
    assert (answer.success, answer.message) == (True, "rospy says hi")
    assert session.node.probe_service("/rospy_srv")["type"] == "std_srvs/SetBool"
    with pytest.raises(ServiceError):
        session.node.service_client("/nobody", SetBool).call(SetBool._request_class())


def test_rosnode_info_describes_the_rosx_node(session: Session) -> None:
    session.node.advertise("/rosx_twist", Twist, queue_size=10)
    _wait(lambda: session.twists)
    _wait(session.node.publications["/rosx_twist"].connection_count)
    info = subprocess.run(
        [str(ROS1_PYTHON), "/usr/bin/rosnode", "info", "/rosx_node"],
        env=session.env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    out = info.stdout
    assert info.returncode == 0, info.stderr
    assert "Node [/rosx_node]" in out
    assert " * /rosx_twist [geometry_msgs/Twist]" in out
    assert " * /rosout [rosgraph_msgs/Log]" in out
    assert " * /rospy_twist [geometry_msgs/Twist]" in out
    assert " * /rosx_srv\n" in out
    assert " * /rosx_node/get_loggers\n" in out
    assert f"Pid: {os.getpid()}" in out
    assert " * topic: /rosx_twist\n    * to: /rospy_node\n    * direction: outbound (" in out
    # Inbound connections name the publisher's URI, which rosnode maps back to its name.
    assert " * topic: /rospy_twist\n    * to: /rospy_node (http://" in out
    assert "    * direction: inbound (" in out
    assert "    * transport: TCPROS" in out


def test_ros1_publishers_answer_the_unixros_offer_with_tcpros(
    session: Session, roscore: tuple[str, dict[str, str]]
) -> None:
    # rosx subscribers offer ["UNIXROS", machine] before ["TCPROS"]; rospy and roscpp (the
    # rosout node publishes /rosout_agg) skip the protocol they do not know.
    from rosx.node import unixros
    from rosx.transport.client import call

    master, _ = roscore
    offer = [[unixros.PROTOCOL, unixros.machine()], ["TCPROS"]]
    for node_name, topic in (("/rospy_node", "/rospy_twist"), ("/rosout", "/rosout_agg")):
        code, _, uri = call(master, "lookupNode", "/test", node_name)
        assert code == 1
        code, _, params = call(uri, "requestTopic", "/test", topic, offer)
        assert code == 1, (node_name, params)
        assert params[0] == "TCPROS"
    _wait(lambda: session.twists)
    rows = session.node.subscriptions["/rospy_twist"].bus_info()
    assert [row[3] for row in rows] == ["TCPROS"]
