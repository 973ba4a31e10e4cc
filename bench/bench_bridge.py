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
  p99 (the first half second ignored), measured twice: with a lean client (`LeanClient`: a
  thread of its own blocked in ``recv`` on a plain socket, taking the time as a message's last
  bytes arrive and decoding it after the run), the figure checked against the target, every
  bridge and the floor in the same window (`latency_together`: their publishers run at once,
  their messages interleaved), then with the websockets client, one bridge after the other,
  as the earlier runs in bench/README.md were. The websockets client's own reading (its event
  loop's wake-up, frame parser and queue: 35-80 µs a message on this machine, idle) is in
  every contender's figure and is no bridge's latency: it pushes every ratio toward 1;
* ``image``: 1 MiB ``sensor_msgs/Image`` as fast as the publisher can, to a ``cbor-raw``
  client: MiB/s received;
* ``clients``: Twist at 200 Hz to 100 clients at once: messages per second delivered in all,
  and the share of what was published that the slowest client got;
* ``topics``: ``/rosapi/topics_and_raw_types`` with 1 200 topics in the graph: the median
  time of one call.

and the ratios rosx / rosbridge_suite, medians of ``--rounds`` rounds in which the two bridges
take turns (each round the other first, each case once both are idle). The latency case also
measures its floor, with the same publishing loop and the same clients: a bare relay process
(the standard library, a thread blocked in ``recv`` with rosx's short time slice) that frames
each JSON text it is fed over a Unix socket (as two rosx processes talk) as a WebSocket frame
to its clients, so two process hops with no ROS work in them; and what each bridge adds to it
(its p50 less the floor's, round by round), the part of the latency that is the bridge's own
work.
``--compare DIR`` runs the rosx bridge of another checkout beside this one (before and after
a change, in one run). Each bridge has topics of its own, so that a subscription one of them
keeps for a while cannot slow down the publisher feeding the other. rosbridge_suite's source
is a directory holding its ``ros1`` branch, prepared as bench/README.md says
(``--rosbridge-suite DIR``, else ``$ROSBRIDGE_SUITE``); without it, its side is skipped with
one line. Run:
``python bench/bench_bridge.py [--seconds S] [--rounds N] [--only CASE] [--rosbridge-suite DIR]
[--compare DIR]``.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import os
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from websockets.client import ClientProtocol
from websockets.frames import Frame, Opcode
from websockets.http11 import Response
from websockets.uri import parse_uri

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_pubsub import start_master  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402
from bench.procstat import cpu_seconds  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

CASES = ("twist", "latency", "image", "clients", "topics")
RAW_TYPES = "/rosapi/topics_and_raw_types"
TWIST = "geometry_msgs/Twist"

#: The publisher process: ``MODE TOPIC SECONDS`` (a rosx node, the same for both bridges).
PUBLISHER = r"""
import os, sys, time
from rosx.node import Node
from rosx.msg.codec.classes import get_message_class
mode, topic, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
node = Node(f"bench_publisher_{os.getpid()}", master_uri=os.environ["ROS_MASTER_URI"]).start()
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
line = sys.stdin.readline().strip()
# "go", or the instant (time.monotonic(), the machine's clock) of the first message
next_at = float(line) if line.replace(".", "", 1).isdigit() else time.monotonic()
time.sleep(max(0.0, next_at - time.monotonic()))
period = {"latency": 1 / 200, "clients": 1 / 200}.get(mode, 0.0)
end = next_at + seconds
sent = 0
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


#: The floor's feed: JSON texts of the latency case's messages at 200 Hz over a Unix socket,
#: each ended by a newline (``PATH SECONDS``).
FLOOR_PUBLISHER = r"""
import socket, sys, time
path, seconds = sys.argv[1], float(sys.argv[2])
sock = socket.socket(socket.AF_UNIX)
sock.connect(path)
print("ready", flush=True)
line = sys.stdin.readline().strip()
next_at = float(line) if line.replace(".", "", 1).isdigit() else time.monotonic()
time.sleep(max(0.0, next_at - time.monotonic()))
text = ('{"op":"publish","topic":"/bench_floor_latency","msg":{"linear":{"x":%r,"y":0.0,'
        '"z":0.0},"angular":{"x":0.0,"y":0.0,"z":0.0}}}\n')
end = next_at + seconds
sent = 0
while time.monotonic() < end:
    sock.sendall((text % time.time()).encode())
    sent += 1
    next_at += 1 / 200
    time.sleep(max(0.0, next_at - time.monotonic()))
print(sent, flush=True)
"""

#: The floor's relay: WebSocket clients on a TCP port (``PORT PATH``), each line fed on the Unix
#: socket ``PATH`` written to each of them as one text frame by the thread that read it, which
#: asks for the short time slice rosx's reading threads ask for.
RELAY = r"""
import base64, hashlib, os, socket, struct, sys, threading
port, path = int(sys.argv[1]), sys.argv[2]
clients, lock = [], threading.Lock()

def drain(sock):
    try:
        while sock.recv(65536):
            pass
    except OSError:
        pass
    with lock:
        clients.remove(sock)
    sock.close()

def accept(server):
    while True:
        sock, _ = server.accept()
        request = chunk = b"-"
        while chunk and b"\r\n\r\n" not in request:
            chunk = sock.recv(4096)
            request += chunk
        if not chunk:  # a probe of the port, not a client
            sock.close()
            continue
        key = next(line.split(b":", 1)[1].strip() for line in request.split(b"\r\n")
                   if line.lower().startswith(b"sec-websocket-key:"))
        digest = hashlib.sha1(key + b"258EAFA5-E914-47DA-95CA-C5AB0DC85B11").digest()
        sock.sendall(b"HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\n"
                     b"Connection: Upgrade\r\nSec-WebSocket-Accept: "
                     + base64.b64encode(digest) + b"\r\n\r\n")
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        with lock:
            clients.append(sock)
        threading.Thread(target=drain, args=(sock,), daemon=True).start()

def relay(feed):
    # The scheduling rosx's reading threads ask for (rosx.node.slices): woken by a message,
    # this thread runs at once rather than after its CPU's running thread; without it the
    # floor would not be the least a bridge can do.
    try:
        from rosx.node.slices import request_short_slice
        request_short_slice()
    except ImportError:
        pass
    rest = b""
    while True:
        chunk = feed.recv(65536)
        if not chunk:
            return
        *lines, rest = (rest + chunk).split(b"\n")
        for line in lines:
            n = len(line)
            head = bytes((0x81, n)) if n < 126 else struct.pack("!BBH", 0x81, 126, n)
            with lock:
                targets = list(clients)
            for sock in targets:
                sock.sendall(head + line)

server = socket.create_server(("127.0.0.1", port))
threading.Thread(target=accept, args=(server,), daemon=True).start()
feeds = socket.socket(socket.AF_UNIX)
feeds.bind(path)
feeds.listen()
while True:
    feed, _ = feeds.accept()
    threading.Thread(target=relay, args=(feed,), daemon=True).start()
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
        feed: str = "",
    ) -> None:
        self.name = name
        self.rosapi = rosapi
        self.master = master
        self.port = port
        self.procs = procs
        #: The floor's: the Unix socket its publisher feeds.
        self.feed = feed

    def publisher(self, mode: str, topic: str, seconds: float) -> subprocess.Popen[str]:
        """The publishing process of a case (the floor's own for its latency case)."""
        if self.feed:
            return subprocess.Popen(
                [sys.executable, "-c", FLOOR_PUBLISHER, self.feed, str(seconds)],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
            )  # fmt: skip
        return publisher(self.master, mode, topic, seconds)

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
        if self.feed:  # the floor's socket, in a folder of its own
            shutil.rmtree(Path(self.feed).parent, ignore_errors=True)


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


def start_rosx(master: str, checkout: Path = ROOT) -> Bridge:
    """rosx's bundled rosbridge_websocket and rosapi_node programs on this Python, from
    ``checkout`` (this one, or another named ``rosx@<its folder>``)."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI=master, ROS_IP="127.0.0.1")
    name = "rosx"
    if checkout != ROOT:
        name = f"rosx@{checkout.name}"
        roots = (checkout, checkout / "commands", checkout / "turtle")
        env["PYTHONPATH"] = ":".join(map(str, roots))
    programs = checkout / "rosx/packages/noetic/lib"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "env": env}
    procs = [
        subprocess.Popen(
            [
                sys.executable,
                str(programs / "rosbridge_server/rosbridge_websocket"),
                f"_port:={port}",
                f"__name:={name.replace('@', '_').replace('-', '_')}_bridge",
            ],
            **quiet,  # type: ignore[call-overload]
        ),
    ]
    namespace = ""
    if checkout != ROOT:  # its rosapi beside this one's, in a namespace of its own
        namespace = "/" + name.replace("@", "_").replace("-", "_").replace(".", "_")
    procs.append(
        subprocess.Popen(
            [sys.executable, str(programs / "rosapi/rosapi_node")],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            env=dict(env, ROS_NAMESPACE=namespace or "/"),
        )
    )
    wait_port(port, procs)
    return Bridge(name, master, port, procs, rosapi=namespace)


def start_floor() -> Bridge:
    """The bare relay the latency case's floor is measured with."""
    port = free_port()
    feed = str(Path(tempfile.mkdtemp(prefix="rosx-bench-floor-")) / "feed")
    env = dict(os.environ, PYTHONPATH=str(ROOT))  # rosx.node.slices, for its scheduling
    procs = [
        subprocess.Popen(
            [sys.executable, "-c", RELAY, str(port), feed], stderr=subprocess.DEVNULL, env=env
        )
    ]
    wait_port(port, procs)
    return Bridge("floor", "", port, procs, feed=feed)


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


class LeanClient:
    """A WebSocket client that takes the time the moment a message's bytes arrive: a thread of
    its own, blocked in ``recv`` on a plain socket, that notes `time.time` right after each
    ``recv`` and only then hands the bytes to websockets' sans-I/O client protocol; the
    messages are decoded after the run. The websockets asyncio client's own reading (the event
    loop's wake-up, its queue) is time every bridge's figure would include and none of them
    spends. No ``Origin`` is sent, as programs that are not browsers send none.
    """

    def __init__(self, port: int) -> None:
        self.protocol = ClientProtocol(parse_uri(f"ws://127.0.0.1:{port}/"))
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.protocol.send_request(self.protocol.connect())
        self._flush()
        #: Frames that came with the handshake's answer.
        self._pending: list[Frame] = []
        answered = False
        while not answered:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("the server closed the connection in the handshake")
            self.protocol.receive_data(chunk)
            for event in self.protocol.events_received():
                if isinstance(event, Response):
                    answered = True
                elif isinstance(event, Frame):
                    self._pending.append(event)
        if self.protocol.handshake_exc is not None:
            raise ConnectionError(f"the handshake failed: {self.protocol.handshake_exc}")
        self.sock.settimeout(None)
        #: (time.time() when the message was complete, its payload), in order.
        self.arrivals: list[tuple[float, bytes]] = []
        self._thread = threading.Thread(target=self._run, name="lean-client", daemon=True)

    def _flush(self) -> None:
        for data in self.protocol.data_to_send():
            if data:
                self.sock.sendall(data)

    def send_text(self, text: str) -> None:
        self.protocol.send_text(text.encode())
        self._flush()

    def start(self) -> None:
        self._thread.start()

    def _run(self) -> None:
        sock, protocol, arrivals = self.sock, self.protocol, self.arrivals
        parts: list[bytes] = []  # a fragmented message so far
        frames, now = list(self._pending), time.time()
        while True:
            for frame in frames:
                if frame.opcode in (Opcode.TEXT, Opcode.BINARY, Opcode.CONT):
                    parts.append(bytes(frame.data))
                    if frame.fin:
                        arrivals.append((now, b"".join(parts)))
                        parts = []
            with contextlib.suppress(OSError):
                self._flush()  # pongs, the answer to a close
            if protocol.close_expected():  # the server closes
                return
            try:
                chunk = sock.recv(1 << 16)
            except OSError:
                return
            now = time.time()  # the moment the bytes arrived, before any work on them
            if not chunk:
                return
            protocol.receive_data(chunk)
            frames = [e for e in protocol.events_received() if isinstance(e, Frame)]

    def stop(self) -> list[tuple[float, bytes]]:
        """End the connection (the socket shut down: the protocol object is the reading
        thread's alone); what came."""
        self.close()
        return self.arrivals

    def close(self) -> None:
        if self._thread.is_alive():
            with contextlib.suppress(OSError):
                self.sock.shutdown(socket.SHUT_RDWR)
            self._thread.join(5)
        self.sock.close()


def _tag(bridge: Bridge) -> str:
    """The bridge's name as a part of a topic name."""
    return bridge.name.replace("@", "_").replace("-", "_").replace(".", "_")


def case_twist(bridge: Bridge, seconds: float) -> float:
    async def run() -> float:
        ws = await _subscribe(bridge.url, f"/bench_{_tag(bridge)}_twist", TWIST)
        proc = bridge.publisher("twist", f"/bench_{_tag(bridge)}_twist", seconds + 1.0)
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


def latency_together(bridges: list[Bridge], seconds: float) -> dict[str, tuple[float, float]]:
    """p50 and p99 in ms with the lean client, every bridge in the same window: their
    publishers run at once, each at 200 Hz, their messages interleaved (the n-th bridge's
    ``n / len(bridges)`` of a period after the first's), so that what else the machine does
    meets each alike and no two messages are on their way at once."""
    clients: dict[str, LeanClient] = {}
    procs: dict[str, subprocess.Popen[str]] = {}
    try:
        for bridge in bridges:
            topic = f"/bench_{_tag(bridge)}_latency"
            client = clients[bridge.name] = LeanClient(bridge.port)
            client.send_text(json.dumps({"op": "subscribe", "topic": topic, "type": TWIST}))
            client.start()
            procs[bridge.name] = bridge.publisher("latency", topic, seconds + 0.5)
        for proc in procs.values():
            assert proc.stdout is not None
            proc.stdout.readline()  # ready: its subscriber found
        time.sleep(0.3)
        first = time.monotonic() + 0.2
        begin = time.time() + 0.2 + 0.5  # the first half second ignored
        for index, proc in enumerate(procs.values()):
            assert proc.stdin is not None
            proc.stdin.write(f"{first + index / 200 / len(procs):.6f}\n")
            proc.stdin.flush()
        time.sleep(0.2 + seconds + 0.5)
        arrivals = {name: client.stop() for name, client in clients.items()}
        for proc in procs.values():
            _finish(proc)
    finally:
        for client in clients.values():
            client.close()
        for proc in procs.values():
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    # Decoded only now: the time was taken as the bytes came.
    found: dict[str, tuple[float, float]] = {}
    for name, came in arrivals.items():
        lags = [
            arrived - json.loads(payload)["msg"]["linear"]["x"]
            for arrived, payload in came
            if begin <= arrived < begin + seconds
        ]
        if not lags:
            raise RuntimeError(f"{name}: no message came ({len(came)} in all)")
        found[name] = _percentiles(lags)
    return found


def _percentiles(lags: list[float]) -> tuple[float, float]:
    """p50 and p99 of ``lags`` (seconds), in ms."""
    lags.sort()
    return lags[len(lags) // 2] * 1000, lags[int(len(lags) * 0.99)] * 1000


def _latency_websockets(bridge: Bridge, seconds: float) -> tuple[float, float]:
    async def run() -> tuple[float, float]:
        topic = f"/bench_{_tag(bridge)}_latency_ws"
        ws = await _subscribe(bridge.url, topic, TWIST)
        proc = bridge.publisher("latency", topic, seconds + 0.5)
        await _start(proc)
        await _read(ws, time.monotonic() + 0.5, lambda m: None)
        lags: list[float] = []

        def lag(message: Any) -> None:
            lags.append(time.time() - json.loads(message)["msg"]["linear"]["x"])

        await _read(ws, time.monotonic() + seconds, lag)
        await ws.close()
        _finish(proc)
        return _percentiles(lags)

    return asyncio.run(run())


def case_image(bridge: Bridge, seconds: float) -> float:
    async def run() -> float:
        ws = await _subscribe(
            bridge.url, f"/bench_{_tag(bridge)}_image", "sensor_msgs/Image", "cbor-raw"
        )
        proc = bridge.publisher("image", f"/bench_{_tag(bridge)}_image", seconds + 1.0)
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
            await _subscribe(bridge.url, f"/bench_{_tag(bridge)}_fan", TWIST) for _ in range(100)
        ]
        proc = bridge.publisher("clients", f"/bench_{_tag(bridge)}_fan", seconds)
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


def _go(proc: subprocess.Popen[str]) -> None:
    """Wait until the publisher is ready (its subscriber found), then let it publish."""
    assert proc.stdin is not None and proc.stdout is not None
    proc.stdout.readline()
    time.sleep(0.3)
    proc.stdin.write("go\n")
    proc.stdin.flush()


async def _start(proc: subprocess.Popen[str]) -> None:
    await asyncio.get_running_loop().run_in_executor(None, _go, proc)


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
    "latency_ws": _latency_websockets,  # the latency case's second figure (see `main`)
    "image": case_image,
    "clients": case_clients,
    "topics": case_topics,
}


def measure_together(bridges: list[Bridge], seconds: float) -> dict[str, tuple[float, float]]:
    """`latency_together`, or nothing when it fails (the other cases' figures still count)."""
    try:
        found = latency_together(bridges, seconds)
    except Exception as exc:  # one case failing still leaves the others' figures
        print(f"  latency with the lean client: failed ({type(exc).__name__}: {exc})", flush=True)
        return {}
    for name, value in found.items():
        print(f"  {name} latency, lean client: {value}", flush=True)
    return found


def measure_once(bridge: Bridge, case: str, seconds: float) -> Any:
    try:
        value = RUNS[case](bridge, seconds)
    except Exception as exc:  # one case failing still leaves the others' figures
        print(f"  {bridge.name} {case}: failed ({type(exc).__name__}: {exc})", flush=True)
        return None
    print(f"  {bridge.name} {case}: {value}", flush=True)
    return value


def _cpu_seconds(pids: list[int]) -> float:
    total = 0.0
    for pid in pids:
        with contextlib.suppress(OSError, IndexError, ValueError):
            total += cpu_seconds(pid)
    return total


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


ROWS = [
    ("Twist to one JSON client, msgs/s", "twist", None, "≥ 5x"),
    ("publish → client latency p50, ms", "latency", 0, "≤ 0.3x"),
    ("publish → client latency p99, ms", "latency", 1, ""),
    ("  with the websockets client: p50, ms", "latency", 2, ""),
    ("  with the websockets client: p99, ms", "latency", 3, ""),
    ("1 MiB Image, cbor-raw, MiB/s", "image", None, "≥ 100 MiB/s"),
    ("Twist at 200 Hz to 100 clients, msgs/s delivered", "clients", 0, ""),
    ("  share the slowest of 100 clients got", "clients", 1, ""),
    ("topics_and_raw_types, 1 200 topics, ms", "topics", None, ""),
]


def _value(value: Any, index: int | None) -> float | None:
    if value is None:
        return None
    return float(value if index is None else value[index])


def _cell(value: float | None) -> str:
    if value is None:
        return "-"
    return f"{value:.3f}" if value < 10 else f"{value:,.0f}"


def report(found: dict[str, dict[str, list[Any]]]) -> None:
    """The medians of every bridge, their ratios to rosbridge_suite's and to the floor, and
    the ratios round by round."""
    medians = {
        name: {c: median_of(v) for c, v in by_case.items()} for name, by_case in found.items()
    }
    names = list(found)
    mine = [n for n in names if n.startswith("rosx")]
    ratios = [(n, "rosbridge_suite") for n in mine] + [(n, "floor") for n in mine]
    ratios += [("floor", "rosbridge_suite")]  # how near the target any bridge could come
    ratios = [(a, b) for a, b in ratios if a in found and b in found]
    heads = names + [f"{a}/{b.replace('rosbridge_', '')}" for a, b in ratios]
    width = max(12, *map(len, heads))
    print()
    print(f"{'case':50} " + " ".join(f"{h:>{width}}" for h in heads) + "  target")
    for label, case, index, target in ROWS:
        values = {n: _value(medians[n].get(case), index) for n in names}
        cells = [_cell(values[n]) for n in names]
        cells += [ratio(values[a], values[b]) for a, b in ratios]
        if all(c == "-" for c in cells):
            continue
        print(f"{label:50} " + " ".join(f"{c:>{width}}" for c in cells) + f"  {target}")
    print()
    for label, case, index, _ in ROWS:
        for a, b in ratios:
            rounds = [
                ratio(_value(x, index), _value(y, index))
                for x, y in zip(found[a].get(case, []), found[b].get(case, []), strict=False)
            ]
            if rounds and any(r != "-" for r in rounds):
                print(f"{label:50} {a}/{b} by round: {', '.join(rounds)}")


def report_added(found: dict[str, dict[str, list[Any]]]) -> None:
    """What each bridge adds to the floor's latency (p50 with the lean client), round by
    round: its own work, the two process hops the floor has too taken away."""
    floors = found.get("floor", {}).get("latency", [])
    if not floors:
        return
    added: dict[str, list[float | None]] = {}
    for name, by_case in found.items():
        if name == "floor":
            continue
        added[name] = [
            None if mine is None or floor is None else (mine[0] - floor[0]) * 1000
            for mine, floor in zip(by_case.get("latency", []), floors, strict=False)
        ]
    suite = added.get("rosbridge_suite", [])
    print()
    print("what each bridge adds to the floor's p50 (its own work, the hops taken away), µs:")
    for name, values in added.items():
        known = [v for v in values if v is not None]
        if not known:
            continue
        rounds = ", ".join("-" if v is None else f"{v:.0f}" for v in values)
        line = f"  {name:24} {statistics.median(known):6.1f}  (rounds {rounds})"
        if name != "rosbridge_suite" and suite:
            ratios = [
                "-" if a is None or not b else f"{a / b:.2f}x"
                for a, b in zip(values, suite, strict=False)
            ]
            theirs = [v for v in suite if v is not None]
            if theirs:
                share = statistics.median(known) / statistics.median(theirs)
                line += f"  / rosbridge_suite's: {share:.2f}x"
                line += f" (by round: {', '.join(ratios)})"
        print(line)


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
    parser.add_argument(
        "--compare",
        type=Path,
        metavar="DIR",
        help="also run the rosx bridge of the checkout in DIR (another version of rosx)",
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
        if args.compare is not None:
            bridges.append(start_rosx(master, args.compare.resolve()))
        if "latency" in cases:
            bridges.append(start_floor())
        # All run all along and take turns, case by case and round by round, so a change in
        # the machine's load meets each.
        found: dict[str, dict[str, list[Any]]] = {b.name: {c: [] for c in cases} for b in bridges}
        for round_ in range(args.rounds):
            for case in cases:
                order = bridges if round_ % 2 == 0 else bridges[::-1]
                if case == "latency":
                    settle(bridges)
                    together = measure_together(order, args.seconds)
                    for bridge in order:
                        settle(bridges)
                        lean = together.get(bridge.name)
                        alone = measure_once(bridge, "latency_ws", args.seconds)
                        found[bridge.name][case].append(
                            None if lean is None or alone is None else (*lean, *alone)
                        )
                    continue
                for bridge in order:
                    if bridge.name == "floor":
                        continue
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
    report(found)
    report_added(found)
    return 0


if __name__ == "__main__":
    sys.exit(main())
