"""The master under load, rosx against ROS 1's rosmaster in the same run.

Each master runs in its own process on a free port: rosx's as ``rosx.core.Core`` under this
Python, rosmaster as roscore starts it (``rosmaster --core``) under ``/usr/bin/python3``
(override with ``ROS1_PYTHON``). Both get the same graph: N nodes (default 1 000), each
registering as subscriber of T/2 topics and publisher of T/2 others (T = 10 by default, so
1 000 topics with 5 publishers and 5 subscribers each). Node URIs name closed ports on loopback
addresses, so the master's notifications fail at once, as they would for vanished nodes.

Measured, for each master:

* ``registerPublisher`` throughput: the publisher half of the graph registered over one
  kept-alive connection, after the subscribers (so every registration owes notifications);
* ``getSystemState`` latency, p50 and p99: request bytes sent and the complete reply read on a
  kept-alive connection, so the figure is the master's time, not a client's XML parsing.

Prints both, and rosx's ratio (rosx time / rosmaster time; the target is p50 <= 0.1).

    python bench/bench_master.py [--nodes 1000] [--topics 10] [--calls 200]
"""

from __future__ import annotations

import argparse
import os
import signal
import socket
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from rosx.transport.client import XmlRpcClient  # noqa: E402 -- after the path is set
from rosx.wire.xmlrpc import encode_call  # noqa: E402
from rosx.wire.xmlrpc_http import build_request  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

ROS1_PYTHON = os.environ.get("ROS1_PYTHON", "/usr/bin/python3")
ROSMASTER = "/usr/bin/rosmaster"

ROSX_MASTER = """
import sys
from rosx.core import Core
with Core(int(sys.argv[1]), {}) as core:
    try:
        core.wait()
    except KeyboardInterrupt:
        pass
"""


def wait_ready(uri: str) -> None:
    client = XmlRpcClient(timeout=1.0)
    deadline = time.monotonic() + 20
    while True:
        try:
            client.call(uri, "getPid", "/bench")
            return
        except Exception:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.05)


def start_rosx() -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    proc = subprocess.Popen(
        [sys.executable, "-c", ROSX_MASTER, str(port)],
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        stdout=subprocess.DEVNULL,
    )
    return proc, f"http://127.0.0.1:{port}/"


def start_rosmaster() -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    proc = subprocess.Popen(
        [ROS1_PYTHON, ROSMASTER, "--core", "-p", str(port)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    return proc, f"http://127.0.0.1:{port}/"


def stop(proc: subprocess.Popen[bytes]) -> None:
    for sig in (signal.SIGINT, signal.SIGKILL):
        if proc.poll() is not None:
            return
        os.kill(proc.pid, sig)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            continue


def node_api(i: int) -> str:
    # Distinct loopback hosts, port 9 closed: every notification is refused at once.
    return f"http://127.0.{i // 250}.{i % 250 + 2}:9/"


def populate(uri: str, nodes: int, topics: int) -> float:
    """Register the graph; returns registerPublisher calls per second."""
    client = XmlRpcClient(timeout=60.0)
    half = topics // 2
    for i in range(nodes):
        for k in range(half):
            topic = f"/topic_{(i + nodes // 2 + k) % nodes}"
            client.call(
                uri, "registerSubscriber", f"/node_{i}", topic, "std_msgs/String", node_api(i)
            )
    started = time.perf_counter()
    for i in range(nodes):
        for k in range(half):
            topic = f"/topic_{(i + k) % nodes}"
            client.call(
                uri, "registerPublisher", f"/node_{i}", topic, "std_msgs/String", node_api(i)
            )
    elapsed = time.perf_counter() - started
    client.close()
    return nodes * half / elapsed


def system_state_times(uri: str, calls: int) -> tuple[list[float], int]:
    """Seconds per getSystemState round trip, and the reply's size."""
    host = uri.split("/")[2]
    port = int(host.rsplit(":", 1)[1])
    request = build_request(host, "/", encode_call("getSystemState", ["/bench"]))
    times: list[float] = []
    size = 0
    with socket.create_connection(("127.0.0.1", port)) as sock:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        for _ in range(calls + 3):
            started = time.perf_counter()
            sock.sendall(request)
            size = _read_response(sock)
            times.append(time.perf_counter() - started)
    return times[3:], size  # the first calls warm caches up


def _read_response(sock: socket.socket) -> int:
    buf = b""
    while b"\r\n\r\n" not in buf:
        buf += sock.recv(65536)
    head, _, body = buf.partition(b"\r\n\r\n")
    length = next(
        int(line.split(b":", 1)[1])
        for line in head.split(b"\r\n")
        if line.lower().startswith(b"content-length:")
    )
    received = len(body)
    while received < length:
        chunk = sock.recv(1 << 20)
        if not chunk:
            raise ConnectionError("master closed the connection mid-reply")
        received += len(chunk)
    return length


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def measure(name: str, start: object, args: argparse.Namespace) -> dict[str, float]:
    proc, uri = start()  # type: ignore[operator]
    try:
        wait_ready(uri)
        rate = populate(uri, args.nodes, args.topics)
        times, size = system_state_times(uri, args.calls)
    finally:
        stop(proc)
    result = {
        "register_per_s": rate,
        "p50_ms": statistics.median(times) * 1e3,
        "p99_ms": percentile(times, 0.99) * 1e3,
        "bytes": float(size),
    }
    print(
        f"{name:10} registerPublisher {rate:8.0f}/s   getSystemState p50 {result['p50_ms']:8.2f} ms"
        f"   p99 {result['p99_ms']:8.2f} ms   reply {size / 1024:.0f} KiB",
        flush=True,
    )
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--nodes", type=int, default=1000)
    parser.add_argument("--topics", type=int, default=10, help="registrations per node")
    parser.add_argument("--calls", type=int, default=200, help="getSystemState calls timed")
    args = parser.parse_args()
    print(f"{args.nodes} nodes x {args.topics} topics, {args.calls} getSystemState calls each")
    ours = measure("rosx", start_rosx, args)
    if not Path(ROSMASTER).exists():
        print("rosmaster not installed: no comparison")
        return
    theirs = measure("rosmaster", start_rosmaster, args)
    print(
        f"ratio (rosx / rosmaster): getSystemState p50 {ours['p50_ms'] / theirs['p50_ms']:.3f}"
        f", p99 {ours['p99_ms'] / theirs['p99_ms']:.3f}"
        f"; registerPublisher throughput x{ours['register_per_s'] / theirs['register_per_s']:.2f}"
    )


if __name__ == "__main__":
    main()
