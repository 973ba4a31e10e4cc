"""rosx's rosbridge server against rosbridge_suite 0.11's, side by side, in one run.

Each bridge runs as its own process on one master (ROS 1's ``rosmaster --core`` when
installed): rosbridge_suite's ``rosbridge_websocket.py`` and ``rosapi_node`` from their source
on Debian's rospy (ROS 1's Python), then rosx's bundled ``rosbridge_websocket`` and
``rosapi_node`` programs on the bench's Python (ROS 1's, `bench.interpreter`). The same
publisher (a rosx node in a process of its own) feeds both, and the same WebSocket clients
(in this process) read them:

* ``twist``: ``geometry_msgs/Twist`` published as fast as the publisher can; the messages per
  second one subscribed JSON client receives;
* ``latency``: Twist at 200 Hz, each carrying its publishing time; publish → client p50 and
  p99 (the first half second ignored);
* ``image``: 1 MiB ``sensor_msgs/Image`` as fast as the publisher can, to a ``cbor-raw``
  client: MiB/s received;
* ``clients``: Twist at 200 Hz to 100 clients at once: messages per second delivered in all,
  and the share of what was published that the slowest client got;
* ``topics``: ``/rosapi/topics_and_raw_types`` with 1 200 topics in the graph: the median
  time of one call.

and the ratios rosx / rosbridge_suite, medians of ``--rounds`` rounds in which the two bridges
take turns (each round the other first, each case once both are idle). Each bridge has topics
of its own, so that a subscription one of them keeps for a while cannot slow
down the publisher feeding the other. rosbridge_suite's source is a directory holding its
``ros1`` branch, prepared as bench/README.md says (``--rosbridge-suite DIR``, else
``$ROSBRIDGE_SUITE``); without it, its side is skipped with one line. Run:
``python bench/bench_bridge.py [--seconds S] [--rounds N] [--only CASE] [--rosbridge-suite DIR]``.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import os
import signal
import socket
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_pubsub import free_port, start_master  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402

CASES = ("twist", "latency", "image", "clients", "topics")
ROSX_PROGRAMS = ROOT / "rosx/packages/noetic/lib"
RAW_TYPES = "/rosapi/topics_and_raw_types"

#: The publisher process: ``MODE TOPIC SECONDS`` (a rosx node, the same for both bridges).
PUBLISHER = r"""
import os, sys, time
from rosx.node import Node
from rosx.msg.codec.classes import get_message_class
mode, topic, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
node = Node("bench_publisher", master_uri=os.environ["ROS_MASTER_URI"]).start()
if mode == "topics":
    String = get_message_class("std_msgs/String")
    pubs = [node.advertise(f"/many/topic_{i}", String, queue_size=1) for i in range(1200)]
    print("ready", flush=True)
    time.sleep(seconds)
    node.shutdown("done")
    sys.exit(0)
if mode == "image":
    Image = get_message_class("sensor_msgs/Image")
    msg = Image(height=512, width=512, encoding="mono32", step=2048, data=bytes(1 << 20))
    pub = node.advertise(topic, Image, queue_size=None)
else:
    Twist = get_message_class("geometry_msgs/Twist")
    msg = Twist()
    pub = node.advertise(topic, Twist, queue_size=None)
deadline = time.monotonic() + 15
while pub.get_num_connections() == 0 and time.monotonic() < deadline:
    time.sleep(0.01)
print("ready", flush=True)
sys.stdin.readline()
period = {"latency": 1 / 200, "clients": 1 / 200}.get(mode, 0.0)
end = time.monotonic() + seconds
sent = 0
next_at = time.monotonic()
while time.monotonic() < end:
    if mode in ("latency", "clients"):
        msg.linear.x = time.time()
    pub.publish(msg)
    sent += 1
    if period:
        next_at += period
        time.sleep(max(0.0, next_at - time.monotonic()))
print(sent, flush=True)
node.shutdown("done")
"""


# -- the bridges -----------------------------------------------------------------------------


class Bridge:
    """One bridge implementation's processes."""

    def __init__(
        self,
        name: str,
        master: str,
        port: int,
        procs: list[subprocess.Popen[bytes]],
        rosapi: str = "",
    ) -> None:
        self.name = name
        self.rosapi = rosapi
        self.master = master
        self.port = port
        self.procs = procs

    @property
    def url(self) -> str:
        return f"ws://127.0.0.1:{self.port}"

    def stop(self) -> None:
        for proc in self.procs:
            with contextlib.suppress(ProcessLookupError):
                proc.send_signal(signal.SIGINT)
        for proc in self.procs:
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()


def wait_port(port: int, procs: list[subprocess.Popen[bytes]], timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if any(p.poll() is not None for p in procs):
            raise SystemExit("a bridge process ended at start-up")
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.2):
                return
        except OSError:
            time.sleep(0.1)
    raise SystemExit(f"nothing listens on port {port}")


def start_suite(source: Path, master: str) -> Bridge:
    """rosbridge_suite's websocket server and rosapi, from ``source``, on ROS 1's Python."""
    port = free_port()
    paths = [
        source / "gen",
        *(source / p / "src" for p in ("rosbridge_library", "rosbridge_server", "rosapi")),
    ]
    env = dict(
        os.environ,
        ROS_MASTER_URI=master,
        ROS_PACKAGE_PATH=f"{source}:/usr/share",
        # Its nodes run beside rosx's, under names of their own (a second node of one name
        # makes the master shut the first down).
        ROS_NAMESPACE="/suite",
        PYTHONPATH=":".join(map(str, paths)),
    )
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "env": env}
    procs = [
        subprocess.Popen(
            [
                ROS1_PYTHON,
                str(source / "rosbridge_server/scripts/rosbridge_websocket.py"),
                f"_port:={port}",
            ],
            **quiet,  # type: ignore[call-overload]
        ),
        # rosapi_node's services have absolute names: the one measured is remapped beside rosx's
        subprocess.Popen(
            [
                ROS1_PYTHON,
                str(source / "rosapi/scripts/rosapi_node"),
                f"{RAW_TYPES}:=/suite{RAW_TYPES}",
            ],
            **quiet,  # type: ignore[call-overload]
        ),
    ]
    wait_port(port, procs)
    return Bridge("rosbridge_suite", master, port, procs, rosapi="/suite")


def start_rosx(master: str) -> Bridge:
    """rosx's bundled rosbridge_websocket and rosapi_node programs on this Python."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI=master, ROS_IP="127.0.0.1")
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "env": env}
    procs = [
        subprocess.Popen(
            [
                sys.executable,
                str(ROSX_PROGRAMS / "rosbridge_server/rosbridge_websocket"),
                f"_port:={port}",
            ],
            **quiet,  # type: ignore[call-overload]
        ),
        subprocess.Popen([sys.executable, str(ROSX_PROGRAMS / "rosapi/rosapi_node")], **quiet),  # type: ignore[call-overload]
    ]
    wait_port(port, procs)
    return Bridge("rosx", master, port, procs)


def publisher(master: str, mode: str, topic: str, seconds: float) -> subprocess.Popen[str]:
    env = dict(os.environ, ROS_MASTER_URI=master, ROS_IP="127.0.0.1", PYTHONPATH=str(ROOT))
    return subprocess.Popen(
        [sys.executable, "-c", PUBLISHER, mode, topic, str(seconds)],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, env=env,
    )  # fmt: skip


# -- the clients -----------------------------------------------------------------------------


async def _subscribe(url: str, topic: str, msg_type: str, compression: str = "none") -> Any:
    from websockets.asyncio.client import connect

    ws = await connect(url, max_size=None, compression=None, ping_interval=None, close_timeout=1)
    request = {"op": "subscribe", "topic": topic, "type": msg_type, "compression": compression}
    await ws.send(json.dumps(request))
    return ws


async def _read(ws: Any, until: float, on_message: Callable[[Any], None]) -> None:
    """Hand each message to ``on_message`` until monotonic time ``until`` (one timer for the
    whole window: a timer per message would make the client the slowest part)."""

    async def consume() -> None:
        async for message in ws:
            on_message(message)

    with contextlib.suppress(TimeoutError):
        await asyncio.wait_for(consume(), max(0.0, until - time.monotonic()))


def case_twist(bridge: Bridge, seconds: float) -> float:
    async def run() -> float:
        ws = await _subscribe(bridge.url, f"/bench_{bridge.name}_twist", "geometry_msgs/Twist")
        proc = publisher(bridge.master, "twist", f"/bench_{bridge.name}_twist", seconds + 1.0)
        await _start(proc)
        count = [0]
        await _read(ws, time.monotonic() + 0.5, lambda m: None)  # warm-up
        start = time.monotonic()
        await _read(ws, start + seconds, lambda m: count.__setitem__(0, count[0] + 1))
        rate = count[0] / (time.monotonic() - start)
        await ws.close()
        _finish(proc)
        return rate

    return asyncio.run(run())


def case_latency(bridge: Bridge, seconds: float) -> tuple[float, float]:
    async def run() -> tuple[float, float]:
        ws = await _subscribe(bridge.url, f"/bench_{bridge.name}_latency", "geometry_msgs/Twist")
        proc = publisher(bridge.master, "latency", f"/bench_{bridge.name}_latency", seconds + 0.5)
        await _start(proc)
        await _read(ws, time.monotonic() + 0.5, lambda m: None)
        lags: list[float] = []

        def lag(message: Any) -> None:
            lags.append(time.time() - json.loads(message)["msg"]["linear"]["x"])

        await _read(ws, time.monotonic() + seconds, lag)
        await ws.close()
        _finish(proc)
        lags.sort()
        return lags[len(lags) // 2] * 1000, lags[int(len(lags) * 0.99)] * 1000

    return asyncio.run(run())


def case_image(bridge: Bridge, seconds: float) -> float:
    async def run() -> float:
        ws = await _subscribe(
            bridge.url, f"/bench_{bridge.name}_image", "sensor_msgs/Image", "cbor-raw"
        )
        proc = publisher(bridge.master, "image", f"/bench_{bridge.name}_image", seconds + 1.0)
        await _start(proc)
        await _read(ws, time.monotonic() + 0.5, lambda m: None)
        size = [0]
        start = time.monotonic()
        await _read(ws, start + seconds, lambda m: size.__setitem__(0, size[0] + len(m)))
        rate = size[0] / (time.monotonic() - start) / (1 << 20)
        await ws.close()
        _finish(proc)
        return rate

    return asyncio.run(run())


def case_clients(bridge: Bridge, seconds: float) -> tuple[float, float]:
    async def run() -> tuple[float, float]:
        clients = [
            await _subscribe(bridge.url, f"/bench_{bridge.name}_fan", "geometry_msgs/Twist")
            for _ in range(100)
        ]
        proc = publisher(bridge.master, "clients", f"/bench_{bridge.name}_fan", seconds)
        await _start(proc)
        counts = [0] * len(clients)
        until = time.monotonic() + seconds + 2.0

        def counter(i: int) -> Callable[[Any], None]:
            return lambda m: counts.__setitem__(i, counts[i] + 1)

        await asyncio.gather(*(_read(ws, until, counter(i)) for i, ws in enumerate(clients)))
        sent = _finish(proc)
        await asyncio.gather(*(ws.close() for ws in clients))
        return sum(counts) / seconds, min(counts) / max(1, sent)

    return asyncio.run(run())


def case_topics(bridge: Bridge, seconds: float) -> float:
    proc = publisher(bridge.master, "topics", "", 120)
    assert proc.stdout is not None
    proc.stdout.readline()

    async def run() -> float:
        from websockets.asyncio.client import connect

        async with connect(bridge.url, max_size=None, compression=None) as ws:
            times = []
            for n in range(6):
                start = time.monotonic()
                await ws.send(
                    json.dumps(
                        {
                            "op": "call_service",
                            "service": f"{bridge.rosapi}{RAW_TYPES}",
                            "id": n,
                        }
                    )
                )
                answer = json.loads(await ws.recv())
                times.append(time.monotonic() - start)
                if not answer.get("result"):
                    raise RuntimeError(str(answer.get("values"))[:300])
                assert len(answer["values"]["topics"]) >= 1200, answer
            return statistics.median(times[1:]) * 1000

    try:
        return asyncio.run(run())
    finally:
        proc.kill()
        proc.wait()


async def _start(proc: subprocess.Popen[str]) -> None:
    assert proc.stdin is not None and proc.stdout is not None
    await asyncio.get_running_loop().run_in_executor(None, proc.stdout.readline)
    await asyncio.sleep(0.3)
    proc.stdin.write("go\n")
    proc.stdin.flush()


def _finish(proc: subprocess.Popen[str]) -> int:
    assert proc.stdout is not None
    try:
        line = proc.stdout.readline()
        proc.wait(timeout=30)
        return int(line or 0)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


# -- main -------------------------------------------------------------------------------------


RUNS: dict[str, Callable[[Bridge, float], Any]] = {
    "twist": case_twist,
    "latency": case_latency,
    "image": case_image,
    "clients": case_clients,
    "topics": case_topics,
}


def measure_once(bridge: Bridge, case: str, seconds: float) -> Any:
    try:
        value = RUNS[case](bridge, seconds)
    except Exception as exc:  # one case failing still leaves the others' figures
        print(f"  {bridge.name} {case}: failed ({type(exc).__name__}: {exc})", flush=True)
        return None
    print(f"  {bridge.name} {case}: {value}", flush=True)
    return value


def _cpu_seconds(pids: list[int]) -> float:
    total = 0
    for pid in pids:
        with contextlib.suppress(OSError, IndexError, ValueError):
            fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
            total += int(fields[11]) + int(fields[12])  # utime + stime, in clock ticks
    return total / os.sysconf("SC_CLK_TCK")


def settle(bridges: list[Bridge], timeout: float = 30.0) -> None:
    """Wait until every bridge is idle (under 5 % of a core over half a second): a bridge
    still sending the backlog of the last case would steal the CPU from the next one."""
    pids = [p.pid for b in bridges for p in b.procs]
    deadline = time.monotonic() + timeout
    before = _cpu_seconds(pids)
    while time.monotonic() < deadline:
        time.sleep(0.5)
        after = _cpu_seconds(pids)
        if after - before < 0.025:
            return
        before = after


def median_of(values: list[Any]) -> Any:
    """The median of a case's rounds (element by element for pairs); None if none ran."""
    found = [v for v in values if v is not None]
    if not found:
        return None
    if isinstance(found[0], tuple):
        return tuple(statistics.median(column) for column in zip(*found, strict=True))
    return statistics.median(found)


def ratio(mine: float | None, theirs: float | None) -> str:
    if not mine or not theirs:
        return "-"
    return f"{mine / theirs:.2f}x"


def report(rosx: dict[str, Any], suite: dict[str, Any] | None) -> None:
    theirs = suite or {}

    def get(results: dict[str, Any], case: str, index: int | None = None) -> float | None:
        value = results.get(case)
        if value is None:
            return None
        return float(value if index is None else value[index])

    rows = [
        ("Twist to one JSON client, msgs/s", "twist", None, "≥ 5x"),
        ("publish → client latency p50, ms", "latency", 0, "≤ 0.3x"),
        ("publish → client latency p99, ms", "latency", 1, ""),
        ("1 MiB Image, cbor-raw, MiB/s", "image", None, "≥ 100 MiB/s"),
        ("Twist at 200 Hz to 100 clients, msgs/s delivered", "clients", 0, ""),
        ("  share the slowest of 100 clients got", "clients", 1, ""),
        ("topics_and_raw_types, 1 200 topics, ms", "topics", None, ""),
    ]
    print()
    print(f"{'case':50} {'rosbridge_suite':>16} {'rosx':>12} {'rosx/suite':>11}  target")
    for label, case, index, target in rows:
        mine, other = get(rosx, case, index), get(theirs, case, index)
        cells = [
            f"{v:.3f}" if v is not None and v < 10 else (f"{v:,.0f}" if v is not None else "-")
            for v in (other, mine)
        ]
        print(f"{label:50} {cells[0]:>16} {cells[1]:>12} {ratio(mine, other):>11}  {target}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=3.0, help="each case's measuring window")
    parser.add_argument("--only", choices=CASES, action="append", help="run only this case")
    parser.add_argument("--rounds", type=int, default=3, help="rounds; the medians are shown")
    parser.add_argument(
        "--rosbridge-suite",
        default=os.environ.get("ROSBRIDGE_SUITE", "/tmp/rosbridge_suite"),
        help="rosbridge_suite's ros1 branch, prepared as bench/README.md says",
    )
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    cases = args.only or list(CASES)
    source = Path(args.rosbridge_suite)
    has_suite = (source / "rosbridge_server/scripts/rosbridge_websocket.py").exists()
    if not has_suite or not Path(ROS1_PYTHON).exists():
        print(f"rosbridge_suite: no source at {source} (see bench/README.md): its side is skipped")
    master_proc, master = start_master()
    bridges: list[Bridge] = []
    try:
        if has_suite and Path(ROS1_PYTHON).exists():
            bridges.append(start_suite(source, master))
        bridges.append(start_rosx(master))
        # Both run all along and take turns, case by case and round by round, so a change in
        # the machine's load meets both.
        found: dict[str, dict[str, list[Any]]] = {b.name: {c: [] for c in cases} for b in bridges}
        for round_ in range(args.rounds):
            for case in cases:
                for bridge in bridges if round_ % 2 == 0 else bridges[::-1]:
                    settle(bridges)
                    found[bridge.name][case].append(measure_once(bridge, case, args.seconds))
    finally:
        for bridge in bridges:
            bridge.stop()
        master_proc.send_signal(signal.SIGINT)
        try:
            master_proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            master_proc.kill()
            master_proc.wait()
    medians = {
        name: {c: median_of(v) for c, v in by_case.items()} for name, by_case in found.items()
    }
    mine, suite = medians["rosx"], medians.get("rosbridge_suite")
    report(mine, suite)
    return 0


if __name__ == "__main__":
    sys.exit(main())
