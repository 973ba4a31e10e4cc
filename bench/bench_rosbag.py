"""rosbag, rosx against Debian's ROS 1 in one run: record throughput, ``info`` of a large bag,
play timing at 1 kHz.

* record: a rosx publisher process publishes N messages as fast as its subscriber takes them
  (``queue_size=None``: it waits rather than drops) to one recorder at a time, ``rosx rosbag
  record`` then ROS 1's; messages/s over the publishing, and how many of the N the bag holds.
  Twist (N = 200 000) and 1 MiB ``sensor_msgs/Image`` (N = 300).
* info: wall time of ``rosbag info`` on one bag of 1 GiB (1 024 messages of 1 MiB, written by
  rosx.bag; 1 024 chunks) and on one of 2 million Twists (``--freq`` reads every index entry).
* play: a bag of 3 000 Twists 1 ms apart, played by each into a rosx subscriber in this
  process; the error of each arrival against the recorded spacing (p50/p99, after the first).

Run: ``python bench/bench_rosbag.py [--quick]`` with the ROS 1 reference installed.
"""

from __future__ import annotations

import io
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

from rosx.bag.reader import BagReader
from rosx.bag.writer import BagWriter
from rosx.master.server import MasterThread
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node

ROSBAG = "/usr/bin/rosbag"
QUICK = "--quick" in sys.argv

PUBLISHER = """
import sys, time
from rosx.node import Node
from rosx.msg.codec.classes import get_message_class
kind, count = sys.argv[1], int(sys.argv[2])
cls = get_message_class(kind)
msg = cls()
if kind == 'sensor_msgs/Image':
    msg.height, msg.width, msg.step, msg.encoding = 1024, 1024, 1024, 'mono8'
    msg.data = bytes(1024 * 1024)
with Node('bench_talker') as node:
    pub = node.advertise('/bench', cls, queue_size=None)
    while pub.get_num_connections() < 1:
        time.sleep(0.01)
    time.sleep(0.3)
    began = time.perf_counter()
    for i in range(count):
        pub.publish(msg)
    while not pub.delivered_to():
        time.sleep(0.001)
    print(time.perf_counter() - began, flush=True)
    time.sleep(0.5)
"""


def _env(uri: str, home: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    env.update(ROS_MASTER_URI=uri, ROS_HOME=home, ROS_PACKAGE_PATH="/usr/share")
    return env


def _stop(process: subprocess.Popen[Any]) -> None:
    import signal

    if process.poll() is None:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(60)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def _recorder(tool: str, out: str, env: dict[str, str], cwd: str) -> subprocess.Popen[bytes]:
    if tool == "rosx":
        args = [
            sys.executable,
            "-m",
            "rosx_commands",
            "rosbag",
            "record",
            "-q",
            "-O",
            out,
            "/bench",
        ]
    else:
        # the C++ recorder itself: Debian's Python wrapper fails on SIGINT before it waits
        args = ["/usr/lib/rosbag/record", "-q", "-O", out, "/bench"]
    return subprocess.Popen(
        args, env=env, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )


def bench_record(uri: str, home: str, kind: str, count: int) -> None:
    env = _env(uri, home)
    print(f"record {kind} x {count}:")
    for tool in ("ROS 1", "rosx"):
        name = f"rec_{tool.replace(' ', '')}_{kind.replace('/', '_')}"
        recorder = _recorder("rosx" if tool == "rosx" else "ros1", name, env, home)
        publisher = subprocess.run(
            [sys.executable, "-c", PUBLISHER, kind, str(count)],
            env=env,
            capture_output=True,
            text=True,
            timeout=900,
            check=True,
        )
        _stop(recorder)
        seconds = float(publisher.stdout.strip())
        with BagReader(Path(home) / f"{name}.bag") as bag:
            kept = bag.message_count()
        rate = count / seconds
        print(f"  {tool:6} {rate:10.0f} msgs/s  {kept}/{count} recorded ({count - kept} lost)")


def _image_bytes() -> bytes:
    image = get_message_class("sensor_msgs/Image")()
    image.height, image.width, image.step, image.encoding = 1024, 1024, 1024, "mono8"
    image.data = bytes(1024 * 1024)
    buff = io.BytesIO()
    image.serialize(buff)
    return buff.getvalue()


def _header(kind: str) -> dict[str, str]:
    cls = get_message_class(kind)
    return {
        "type": kind,
        "md5sum": cls._md5sum,
        "message_definition": cls._full_text,
        "topic": "/x",
    }


def bench_info(home: str) -> None:
    big = Path(home) / "big.bag"
    many = Path(home) / "many.bag"
    data = _image_bytes()
    images = 256 if QUICK else 1024
    with BagWriter(big) as writer:
        conn = writer.add_connection("/camera", _header("sensor_msgs/Image"))
        for i in range(images):
            writer.write(conn, 10**18 + i * 10**8, data)
    twist = bytes(48)
    twists = 200_000 if QUICK else 2_000_000
    with BagWriter(many) as writer:
        conn = writer.add_connection("/cmd_vel", _header("geometry_msgs/Twist"))
        for i in range(twists):
            writer.write(conn, 10**18 + i * 10**6, twist)
    for path, options in ((big, []), (many, []), (many, ["--freq"])):
        size = path.stat().st_size / 2**30
        times = {}
        for tool, args in (
            ("ROS 1", ["/usr/bin/python3", ROSBAG]),
            ("rosx", [sys.executable, "-m", "rosx_commands", "rosbag"]),
        ):
            began = time.perf_counter()
            done = subprocess.run(
                [*args, "info", *options, str(path)], capture_output=True, text=True, check=False
            )
            times[tool] = time.perf_counter() - began
            assert done.returncode == 0, done.stderr
        ratio = times["rosx"] / times["ROS 1"]
        print(
            f"info {' '.join(options)} {path.name} ({size:.2f} GiB): ROS 1 {times['ROS 1']:.2f} s, "
            f"rosx {times['rosx']:.2f} s ({ratio:.2f} x)"
        )


def bench_play(uri: str, home: str) -> None:
    path = Path(home) / "khz.bag"
    count = 3000
    twist_cls = get_message_class("geometry_msgs/Twist")
    buff = io.BytesIO()
    twist_cls().serialize(buff)
    with BagWriter(path) as writer:
        conn = writer.add_connection("/khz", _header("geometry_msgs/Twist"))
        for i in range(count):
            writer.write(conn, 10**18 + i * 10**6, buff.getvalue())
    env = _env(uri, home)
    for tool, args in (
        ("ROS 1", ["/usr/bin/python3", ROSBAG]),
        ("rosx", [sys.executable, "-m", "rosx_commands", "rosbag"]),
    ):
        arrivals: list[float] = []
        done = threading.Event()

        def heard(msg: Any, arrivals: list[float] = arrivals, done: threading.Event = done) -> None:
            arrivals.append(time.perf_counter())
            if len(arrivals) == count:
                done.set()

        with Node("khz_listener", master_uri=uri, environ={}) as node:
            node.subscribe("/khz", twist_cls, heard, tcp_nodelay=True)
            player = subprocess.Popen(
                [*args, "play", "-q", str(path)],
                env=env,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
            )
            done.wait(60)
            player.wait(60)
        errors = [abs((a - arrivals[0]) - i * 1e-3) * 1e3 for i, a in enumerate(arrivals)]
        errors.sort()
        p50 = statistics.median(errors)
        p99 = errors[int(len(errors) * 0.99) - 1]
        print(
            f"play 1 kHz {tool:6}: {len(arrivals)}/{count} delivered, "
            f"error p50 {p50:.3f} ms, p99 {p99:.3f} ms"
        )


def main() -> None:
    with (
        tempfile.TemporaryDirectory() as home,
        MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master,
    ):
        bench_record(master.uri, home, "geometry_msgs/Twist", 20_000 if QUICK else 200_000)
        bench_record(master.uri, home, "sensor_msgs/Image", 50 if QUICK else 300)
        bench_play(master.uri, home)
        bench_info(home)


if __name__ == "__main__":
    main()
