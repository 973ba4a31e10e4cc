"""Clients nobody here wrote, in JavaScript: roslib (npm) in node, Lichtblick's own packages
doing Lichtblick's connect sequence, and a page using roslib in headless Debian chromium that
shows the turtle's pose live, while a page of a foreign origin is refused.

The npm packages are installed once into the user's cache (`npm_dir`); everything skips when
node, npm or the registry cannot be had, and the browser tests when chromium is missing.
"""

from __future__ import annotations

import functools
import http.server
import re
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.bridge import NodeScript, Running, start_bridge
from tests.support.cli import clean_environ, rosx

CHROMIUM = Path("/usr/bin/chromium")


def test_roslib_in_node(running: Running, node_script: Callable[..., NodeScript]) -> None:
    client = node_script("roslib_client.mjs", running.url)
    assert "/turtle1/pose" in client.step("topics")
    assert set(client.step("pose")) == {"x", "y", "theta", "linear_velocity", "angular_velocity"}
    assert client.step("turning") == 2.0
    assert client.step("spawned") == "from_node"
    assert client.step("service_type") == "turtlesim/Spawn"
    assert client.step("advertised") == "/roslib_add"
    environ = clean_environ(ROS_MASTER_URI=running.master, ROS_IP="127.0.0.1")
    deadline = time.monotonic() + 10
    while "/roslib_add" not in rosx("rosservice", "list", environ=environ).out:
        assert time.monotonic() < deadline, "the service never registered"
        time.sleep(0.05)
    result = rosx("rosservice", "call", "/roslib_add", "3", "4", environ=environ)
    assert (result.status, result.out) == (0, "sum: 7\n")
    assert client.step("served") == {"a": 3, "b": 4}
    assert client.finish() == 0


def test_lichtblick_connect_sequence(
    running: Running, node_script: Callable[..., NodeScript]
) -> None:
    client = node_script("lichtblick_connect.cjs", running.url)
    assert client.step("ros_version") == 1  # told from rosgraph_msgs/Log, as Lichtblick does
    pose = client.step("pose")  # cbor-raw bytes read by @lichtblick/rosmsg-serialization
    assert set(pose) == {"x", "y", "theta", "linear_velocity", "angular_velocity"}
    details = client.step("node_details")
    assert "/turtle1/pose" in details["publications"]
    assert "/spawn" in details["services"]
    assert client.step("spawned") == "lichtblick"
    assert client.step("advertised") == "/lichtblick/cmd_vel"
    again = client.step("topics_again")
    assert again == {"lichtblick": True}  # asked again 3 s later, as Lichtblick does
    assert client.finish() == 0


@pytest.fixture(scope="module")
def page_server(npm_dir: Path) -> Iterator[int]:
    """The npm folder served over HTTP on a free port of the loopback."""
    handler = functools.partial(QuietHandler, directory=str(npm_dir))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield server.server_address[1]
    server.shutdown()
    server.server_close()
    thread.join()


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:
        pass


needs_chromium = pytest.mark.skipif(not CHROMIUM.exists(), reason="chromium is not installed")


@needs_chromium
def test_a_page_shows_the_live_pose(
    running: Running, page_server: int, node_script: Callable[..., NodeScript]
) -> None:
    twist_class = get_message_class("geometry_msgs/Twist")
    driver = Node("page_driver", master_uri=running.master, environ=running.environ).start()
    stop = threading.Event()

    def drive() -> None:
        twist = twist_class()
        twist.angular.z = 1.0
        while not stop.is_set():
            publisher.publish(twist)
            stop.wait(0.05)

    publisher = driver.advertise("/turtle1/cmd_vel", twist_class, queue_size=1)
    thread = threading.Thread(target=drive, daemon=True)
    thread.start()
    try:
        url = f"http://127.0.0.1:{page_server}/page.html?port={running.port}"
        browser = node_script("browser.cjs", url, "3")
        shown = browser.values("pose")
    finally:
        stop.set()
        thread.join()
        driver.shutdown("test over")
    assert browser.finish() == 0
    assert len(shown) == 3, shown  # three different poses: the page follows the turning turtle
    assert all(
        re.fullmatch(r"x=\d+\.\d{3} y=\d+\.\d{3} theta=-?\d+\.\d{3}", text) for text in shown
    ), shown


@needs_chromium
def test_a_foreign_page_cannot_connect(
    running: Running, page_server: int, node_script: Callable[..., NodeScript]
) -> None:
    url = f"http://evil.example:{page_server}/page.html?port={running.port}"
    browser = node_script("browser.cjs", url, "1", "MAP evil.example 127.0.0.1")
    assert browser.step("pose") == "error: connection closed"
    assert browser.finish() == 0
    assert any(
        f"Refused a connection from a page of http://evil.example:{page_server}" in line
        for line in running.lines
    )


@needs_chromium
def test_a_page_opened_from_a_file_connects_once_its_origin_is_allowed(
    running: Running, npm_dir: Path, node_script: Callable[..., NodeScript]
) -> None:
    # The roslibjs tutorial's page is a file opened in the browser: its origin is "null", as
    # sandboxed frames of any web site are, so it is refused until allowed; the log says how.
    url = f"file://{npm_dir}/file-page.html?port={{}}"
    refused = node_script("browser.cjs", url.format(running.port), "1")
    assert refused.step("pose") == "error: connection closed"
    assert refused.finish() == 0
    assert any("(--allow-origin null, or allow_origin:=null" in line for line in running.lines)
    bridge, _ = start_bridge(running.master, rosapi=False, allow_origins=("null",))
    try:
        browser = node_script("browser.cjs", url.format(bridge.port), "1")
        (shown,) = browser.values("pose")
        assert browser.finish() == 0
    finally:
        bridge.shutdown("test over")
    assert re.fullmatch(r"x=\d+\.\d{3} y=\d+\.\d{3} theta=-?\d+\.\d{3}", shown), shown
