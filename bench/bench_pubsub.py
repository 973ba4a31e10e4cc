"""Publish/subscribe speed of rosx against rospy, side by side, in one run.

Each case runs a publisher process and a subscriber process on the same master (ROS 1's
``rosmaster --core`` when installed, else rosx's), first with rospy under ROS 1's Python, then
with rosx under this Python, and prints:

* small messages (``geometry_msgs/Twist``, 48 bytes) sent as fast as the publisher can: msgs/s
  delivered and messages lost, with rospy's asynchronous publisher (``queue_size=100``) and with
  its synchronous one (``queue_size=None``) against rosx's equivalents;
* latency from ``publish`` to the callback at 1 kHz and in bursts of 10 every 10 ms: p50 and
  p99, the first messages ignored as a warm-up, medians over several rounds with rospy and rosx
  alternating, and the p99 ratio round by round; and the floor under them, a bare Python sender
  and receiving thread over a Unix socket and over loopback TCP, same pacing; and over the Unix
  socket again with the receiving thread given the short time slice rosx's readers ask for
  (`rosx.node.slices`), the floor under rosx's own design;
* 1 MiB messages (``sensor_msgs/Image``) and 10 MiB ``sensor_msgs/PointCloud2``: bytes/s
  delivered, several rounds; and the floor under them, a bare Python sender and receiver
  moving frames of that size over a Unix socket (the kernel's copies, nothing else);
* fan-out and fan-in: one publisher to 10 subscriber processes and 10 publishers to one, Twist
  and 1 MiB images: delivered msgs/s or bytes/s summed over subscribers, and the slowest
  subscriber's rate;
* publisher and subscriber in one process (``inproc``: Twist floods, latency at 1 kHz and in
  bursts): rospy has one node per process, its publisher and subscriber talking over loopback
  TCPROS; rosx has two `Node` objects linked in-process (``ROSX_INTRAPROCESS=0``: over TCPROS,
  shown too); and the floor under any in-process link in this Python: the publishing loop
  with a ``publish`` that does nothing, and the private copy of a Twist a subscriber gets;

and the ratios rosx/rospy. Run:
``python bench/bench_pubsub.py [--quick] [--only CASE] [--rounds N] [--fast-rounds N]``.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter, roscpp_program  # noqa: E402 -- after the path is set
from bench.interpreter import ROS1_PYTHON  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

# The worker scripts are the same for both libraries: `api` makes a node, a publisher, a
# subscriber and the message classes, with rospy or with rosx.node.
API_ROSPY = """
import rospy
def make_node(name):
    rospy.init_node(name, disable_signals=True)
def second_node(name):
    pass  # one node per process
def publisher(topic, cls, queue_size):
    return rospy.Publisher(topic, cls, queue_size=queue_size)
def subscriber(topic, cls, cb, queue_size):
    return rospy.Subscriber(topic, cls, cb, queue_size=queue_size)
def msg_class(name):
    pkg, _, short = name.partition('/')
    module = __import__(pkg + '.msg', fromlist=[short])
    return getattr(module, short)
"""

API_ROSX = """
import os
from rosx.node import Node
from rosx.msg.codec.classes import get_message_class as msg_class
_node = []
def make_node(name):
    _node.append(Node(name, master_uri=os.environ['ROS_MASTER_URI']).start())
second_node = make_node
def publisher(topic, cls, queue_size):
    return _node[0].advertise(topic, cls, queue_size=queue_size)
def subscriber(topic, cls, cb, queue_size):
    return _node[-1].subscribe(topic, cls, cb, queue_size=queue_size)
"""

# Publisher and subscriber in one process: rospy's one node, or two rosx nodes.
INPROC = """
import sys, time, json, threading
count, pub_queue, sub_queue = int(sys.argv[1]), json.loads(sys.argv[2]), json.loads(sys.argv[3])
period, warmup = float(sys.argv[4]), int(sys.argv[5])
make_node('bench_inproc_pub')
second_node('bench_inproc_sub')
cls = msg_class('geometry_msgs/Twist')
state = {'n': 0, 'first': 0.0, 'last': 0.0}
lat = []
done = threading.Event()
clock = time.time
def cb(msg):
    now = clock()
    if state['n'] == 0:
        state['first'] = now
    state['n'] += 1
    state['last'] = now
    if msg.linear.y >= warmup:
        lat.append(now - msg.linear.x)
    if msg.linear.y == count - 1:
        done.set()
sub = subscriber('/bench_inproc', cls, cb, sub_queue)
pub = publisher('/bench_inproc', cls, pub_queue)
while pub.get_num_connections() == 0:
    time.sleep(0.01)
time.sleep(0.5)
msg = cls()
start = clock()
for i in range(count):
    msg.linear.x = clock()
    msg.linear.y = i
    pub.publish(msg)
    if period > 0:
        time.sleep(period)
    elif period < 0 and i % 10 == 9:  # bursts of 10
        time.sleep(-period)
pub_rate = count / (clock() - start)
deadline = time.monotonic() + 120
while not done.is_set() and time.monotonic() < deadline:
    before = state['n']
    done.wait(3.0)
    if state['n'] == before:
        break
span = max(state['last'] - state['first'], 1e-9)
lat.sort()
result = {'received': state['n'], 'rate': state['n'] / span, 'pub_rate': pub_rate}
if lat:
    result['p50'] = lat[len(lat) // 2] * 1e6
    result['p99'] = lat[min(len(lat) - 1, int(len(lat) * 0.99))] * 1e6
print(json.dumps(result), flush=True)
import os
os._exit(0)
"""

KINDS = """
CLASSES = {'twist': 'geometry_msgs/Twist', 'image': 'sensor_msgs/Image',
           'cloud': 'sensor_msgs/PointCloud2'}
"""

PUBLISHER = (
    KINDS
    + """
import sys, time, json
count, queue_size = int(sys.argv[1]), json.loads(sys.argv[2])
period, kind = float(sys.argv[3]), sys.argv[4]
subscribers, name = int(sys.argv[5]), sys.argv[6]
make_node(name)
cls = msg_class(CLASSES[kind])
pub = publisher('/bench', cls, queue_size)
while pub.get_num_connections() < subscribers:
    time.sleep(0.01)
time.sleep(0.5)
msg = cls()
if kind == 'image':
    msg.height, msg.width, msg.encoding, msg.step = 512, 512, 'rgba8', 2048
    msg.data = bytes(1 << 20)
elif kind == 'cloud':
    msg.height, msg.width, msg.point_step, msg.row_step = 1, 655360, 16, 10485760
    msg.data = bytes(10 << 20)
clock = time.time
start = clock()
for i in range(count):
    if kind != 'twist':
        msg.header.frame_id = str(i)
    else:
        msg.linear.x = clock()
        msg.linear.y = i
        if i % 10 == 0:
            msg.angular.x = msg.linear.x  # when the burst (of 10) began
    pub.publish(msg)
    if period > 0:
        time.sleep(period)
    elif period < 0 and i % 10 == 9:  # bursts of 10
        time.sleep(-period)
print(json.dumps({'pub_rate': count / (clock() - start)}), flush=True)
time.sleep(1.0)
"""
)

SUBSCRIBER = (
    KINDS
    + """
import sys, time, json, threading
count, queue_size, kind = int(sys.argv[1]), json.loads(sys.argv[2]), sys.argv[3]
warmup, publishers, name = int(sys.argv[4]), int(sys.argv[5]), sys.argv[6]
make_node(name)
cls = msg_class(CLASSES[kind])
state = {'n': 0, 'first': 0.0, 'last': 0.0, 'bytes': 0}
lat = []
first = []  # every 10th message: the first of a burst
whole = []  # from a burst's first publish to its last callback
done = threading.Event()
clock = time.time
def cb(msg):
    now = clock()
    if state['n'] == 0:
        state['first'] = now
    state['n'] += 1
    state['last'] = now
    if kind != 'twist':
        state['bytes'] += len(msg.data)
        last = int(msg.header.frame_id) == count - 1 and publishers == 1
    else:
        if msg.linear.y >= warmup:
            lat.append(now - msg.linear.x)
            if msg.linear.y % 10 == 0:
                first.append(now - msg.linear.x)
            elif msg.linear.y % 10 == 9:
                whole.append(now - msg.angular.x)
        last = msg.linear.y == count - 1 and publishers == 1
    if last or state['n'] == count * publishers:
        done.set()
sub = subscriber('/bench', cls, cb, queue_size)
print('ready', flush=True)
deadline = time.monotonic() + 120
while not done.is_set() and time.monotonic() < deadline:
    before = state['n']
    done.wait(3.0)
    if state['n'] == before and before:
        break
span = max(state['last'] - state['first'], 1e-9)
lat.sort()
result = {'received': state['n'], 'rate': state['n'] / span, 'bytes_rate': state['bytes'] / span}
if lat:
    result['p50'] = lat[len(lat) // 2] * 1e6
    result['p99'] = lat[min(len(lat) - 1, int(len(lat) * 0.99))] * 1e6
    result['samples'] = len(lat)
    first.sort()
    result['first_p50'] = first[len(first) // 2] * 1e6
    whole.sort()
    result['burst_p50'] = whole[len(whole) // 2] * 1e6
print(json.dumps(result), flush=True)
"""
)

# Ping-pong: a pinger publishes a Twist on /ping stamped with ``time.time()``; the ponger's
# callback publishes it back on /pong; the pinger's callback records half the round trip and
# publishes the next ping (callback to callback, no other thread), COUNT times, the first
# WARMUP left out. Probes (place -1) first, until one comes back: both connections are up.
PING = """
import sys, time, json, threading
count, warmup, name = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
make_node(name)
cls = msg_class('geometry_msgs/Twist')
pub = publisher('/ping', cls, 100)
one_way = []
state = {'sent': 0}
answered = threading.Event()
done = threading.Event()
msg = cls()
clock = time.time
def send(place):
    msg.linear.y = place
    msg.linear.x = clock()
    pub.publish(msg)
def cb(echo):
    now = clock()
    place = int(echo.linear.y)
    if place < 0:
        answered.set()
        return
    if place != state['sent']:
        return
    if place >= warmup:
        one_way.append((now - echo.linear.x) / 2)
    if place + 1 == count:
        done.set()
        return
    state['sent'] = place + 1
    send(place + 1)
sub = subscriber('/pong', cls, cb, 100)
deadline = time.monotonic() + 30
while not answered.is_set() and time.monotonic() < deadline:
    msg.linear.y = -1
    pub.publish(msg)
    answered.wait(0.1)
time.sleep(0.5)
send(0)
done.wait(120)
one_way.sort()
result = {'received': state['sent'] + 1}
if one_way:
    result['p50'] = one_way[len(one_way) // 2] * 1e6
    result['p99'] = one_way[min(len(one_way) - 1, int(len(one_way) * 0.99))] * 1e6
    result['samples'] = len(one_way)
print(json.dumps(result), flush=True)
import os
os._exit(0)
"""

PONG = """
import sys, time
make_node(sys.argv[1])
cls = msg_class('geometry_msgs/Twist')
pub = publisher('/pong', cls, 100)
sub = subscriber('/ping', cls, pub.publish, 100)
print('ready', flush=True)
time.sleep(600)  # until the bench stops it
"""

#: The Python workers by role (`spawn_worker`); the C++ worker has the same roles.
WORKERS = {"pub": PUBLISHER, "sub": SUBSCRIBER, "ping": PING, "pong": PONG}


# The floor: a bare Python sender and a Python thread blocked in ``recv_into``, no library, the
# same pacing and stamps as the latency cases (a 52-byte frame per message). ``unix-slice``: the
# receiving thread first asks for rosx's short time slice.
FLOOR = """
import os, socket, struct, sys, threading, time, json
family, count, period, warmup = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
family, short_slice = family.split('-')[0], family.endswith('-slice')
if short_slice:
    from rosx.node.slices import request_short_slice
if family == 'unix':
    server = socket.socket(socket.AF_UNIX)
    server.bind('\\0rosx-bench-floor-%d' % os.getpid())
else:
    server = socket.socket()
    server.bind(('127.0.0.1', 0))
server.listen(1)
address = server.getsockname()
lat = []
def receive(conn):
    if short_slice:
        request_short_slice()
    buff = bytearray(65536)
    while True:
        size = conn.recv_into(buff)
        now = time.time()
        if not size:
            return
        for offset in range(0, size, 52):
            stamp, index = struct.unpack_from('<dd', buff, offset)
            if index >= warmup:
                lat.append(now - stamp)
sender = socket.socket(server.family)
sender.connect(address)
conn, _ = server.accept()
thread = threading.Thread(target=receive, args=(conn,))
thread.start()
pid = os.fork()
if pid == 0:
    conn.close()
    time.sleep(0.3)
    pad = bytes(36)
    for i in range(count):
        sender.send(struct.pack('<dd', time.time(), i) + pad)
        if period > 0:
            time.sleep(period)
        elif period < 0 and i % 10 == 9:
            time.sleep(-period)
    os._exit(0)
sender.close()
os.waitpid(pid, 0)
thread.join()
lat.sort()
print(json.dumps({'p50': lat[len(lat) // 2] * 1e6, 'p99': lat[int(len(lat) * 0.99)] * 1e6}))
"""


# The floor under the large-message cases: a bare Python sender process and receiver, no
# library, over a Unix socket with rosx's send buffer; each frame read whole into one buffer
# (the kernel's two copies, no serializing or decoding). Rate from the first frame read to
# the last, as the subscribers measure theirs.
FLOOR_BULK = """
import json, os, socket, sys, time
from rosx.node.unixros import SEND_BUFFER
size, count = int(sys.argv[1]), int(sys.argv[2])
sender, receiver = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
sender.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, SEND_BUFFER)
if os.fork() == 0:
    receiver.close()
    frame = bytes(size)
    for _ in range(count):
        sender.sendall(frame)
    os._exit(0)
sender.close()
view = memoryview(bytearray(size))
first = 0.0
for i in range(count):
    got = 0
    while got < size:
        got += receiver.recv_into(view[got:])
    if i == 0:
        first = time.perf_counter()
span = time.perf_counter() - first
os.wait()
print(json.dumps({'bytes_rate': size * (count - 1) / span}))
"""


def start_master() -> tuple[subprocess.Popen[bytes], str]:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    if shutil.which("rosmaster", path="/usr/bin"):
        cmd = ["/usr/bin/rosmaster", "--core", "-p", str(port)]
    else:
        cmd = [sys.executable, "-m", "rosx_commands.main", "roscore", "-p", str(port)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.2):
                return proc, uri
        except OSError:
            time.sleep(0.1)
    proc.kill()
    raise SystemExit("the master did not start")


def spawn_worker(lib: str, role: str, master: str, *argv: object) -> subprocess.Popen[str]:
    """Start one worker process: ``role`` ``pub``, ``sub``, ``ping`` or ``pong`` (`WORKERS`)
    of ``lib``: ``rospy`` (ROS 1's Python), ``rosx`` (this Python), ``rosx-tcp`` (rosx over
    TCPROS, ``ROSX_UNIXROS=0``, instead of Unix sockets) or ``roscpp`` (the C++ worker of
    `bench.roscpp_program`, which takes the same arguments and prints the same lines).
    ``rosx@PATH`` and ``rosx-tcp@PATH`` run rosx from the checkout at PATH (another version,
    to measure a change side by side)."""
    lib, _, checkout = lib.partition("@")
    root = Path(checkout) if checkout else ROOT
    env = dict(os.environ, ROS_MASTER_URI=master, PYTHONPATH=str(root))
    if lib == "roscpp":
        binary = roscpp_program.program()
        if binary is None:
            raise SystemExit("roscpp: the C++ worker could not be built")
        command = [str(binary), role]
    else:
        python = ROS1_PYTHON if lib == "rospy" else sys.executable
        api = API_ROSPY if lib == "rospy" else API_ROSX
        command = [python, "-c", api + WORKERS[role]]
    if lib == "rospy":
        env["ROS_PACKAGE_PATH"] = "/usr/share"
    if lib == "rosx-tcp":
        env["ROSX_UNIXROS"] = "0"
    return subprocess.Popen(
        [*command, *map(str, argv)],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env=env,
        cwd=root,
        text=True,
    )


def run_case(
    lib: str,
    master: str,
    kind: str,
    count: int,
    pub_queue: int | None,
    sub_queue: int | None,
    period: float,
    warmup: int = 0,
    *,
    publishers: int = 1,
    subscribers: int = 1,
    sub_lib: str | None = None,
) -> dict[str, float]:
    """Run publisher and subscriber processes of ``lib`` (`spawn_worker`; the subscribers of
    ``sub_lib`` if given); with several subscribers, ``rate`` and ``bytes_rate`` are their sum
    and ``slowest`` the lowest subscriber's ``rate``."""

    def spawn(role: str, *argv: object) -> subprocess.Popen[str]:
        return spawn_worker(sub_lib or lib if role == "sub" else lib, role, master, *argv)

    subs = [
        spawn("sub", count, json.dumps(sub_queue), kind, warmup, publishers, f"bench_sub{i}")
        for i in range(subscribers)
    ]
    for sub in subs:
        assert sub.stdout is not None
        sub.stdout.readline()  # "ready"
    pubs = [
        spawn("pub", count, json.dumps(pub_queue), period, kind, subscribers, f"bench_pub{i}")
        for i in range(publishers)
    ]
    try:
        outs = [sub.communicate(timeout=240)[0] for sub in subs]
        pub_outs = [pub.communicate(timeout=60)[0] for pub in pubs]
    finally:
        for proc in subs + pubs:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    each = [json.loads(out.strip().splitlines()[-1]) for out in outs]
    result: dict[str, float] = dict(each[0])
    for field in ("received", "rate", "bytes_rate"):
        result[field] = sum(r[field] for r in each)
    result["slowest"] = min(r["rate"] for r in each)
    if pub_outs[0].strip():
        result.update(json.loads(pub_outs[0].strip().splitlines()[-1]))
    result["lost"] = count * publishers * subscribers - result["received"]
    return result


def run_floor(family: str, count: int, period: float, warmup: int) -> dict[str, float]:
    """The floor under the latency cases: bare sockets (``unix``, ``unix-slice`` or ``tcp``),
    no library."""
    return run_script(FLOOR, family, count, period, warmup)


def run_bulk_floor(kind: str, count: int) -> dict[str, float]:
    """The floor under the large-message cases (``kind`` ``image`` or ``cloud``): bare Unix
    sockets moving frames of that size, no library."""
    return run_script(FLOOR_BULK, {"image": 1 << 20, "cloud": 10 << 20}[kind], count)


def run_script(script: str, *argv: object) -> dict[str, float]:
    """What ``script`` (run by this Python, this checkout importable) prints last, as JSON."""
    done = subprocess.run(
        [sys.executable, "-c", script, *map(str, argv)],
        env=dict(os.environ, PYTHONPATH=str(ROOT)),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    result: dict[str, float] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


def run_inproc(
    lib: str,
    master: str,
    count: int,
    pub_queue: int | None,
    sub_queue: int | None,
    period: float,
    warmup: int = 0,
) -> dict[str, float]:
    """One process publishing to itself; ``lib`` ``rosx-tcp`` is rosx without in-process links
    (its nodes then talk over TCPROS: ``ROSX_UNIXROS=0`` too)."""
    python = ROS1_PYTHON if lib == "rospy" else sys.executable
    api = API_ROSPY if lib == "rospy" else API_ROSX
    env = dict(os.environ, ROS_MASTER_URI=master, PYTHONPATH=str(ROOT))
    if lib == "rospy":
        env["ROS_PACKAGE_PATH"] = "/usr/share"
    if lib == "rosx-tcp":
        env["ROSX_INTRAPROCESS"] = "0"
        env["ROSX_UNIXROS"] = "0"
    argv = [str(count), json.dumps(pub_queue), json.dumps(sub_queue), str(period), str(warmup)]
    done = subprocess.run(
        [python, "-c", api + INPROC, *argv],
        capture_output=True,
        env=env,
        cwd=ROOT,
        text=True,
        timeout=240,
        check=False,
    )
    result: dict[str, float] = json.loads(done.stdout.strip().splitlines()[-1])
    result["lost"] = count - result["received"]
    return result


InprocRow = tuple[str, dict[str, dict[str, float]], str]


def inproc_cases(
    master: str, small: int, latency: int, rounds: int, warmup: int
) -> list[InprocRow]:
    """The one-process cases, rospy, rosx over TCPROS and rosx in-process alternating."""
    rows: list[InprocRow] = []
    cases = [
        (
            "Twist flood, one process, async publisher (queue_size=100)",
            small,
            100,
            None,
            0.0,
            "rate",
        ),
        (
            "Twist flood, one process, sync publisher (queue_size=None)",
            small,
            None,
            None,
            0.0,
            "rate",
        ),
        ("Twist at 1 kHz, one process, latency", latency, 100, None, 0.001, "p50"),
        (
            "Twist in bursts of 10 every 10 ms, one process, latency",
            latency,
            100,
            None,
            -0.01,
            "p50",
        ),
    ]
    for title, count, pq, sq, period, key in cases:
        libs: dict[str, list[dict[str, float]]] = {"rospy": [], "rosx-tcp": [], "rosx": []}
        for _ in range(rounds):
            for lib, results in libs.items():
                results.append(run_inproc(lib, master, count, pq, sq, period, warmup))
        merged: dict[str, dict[str, float]] = {}
        for lib, results in libs.items():
            res = dict(results[-1])
            for field in ("p50", "p99", "rate", "received", "lost"):
                if field in res:
                    res[field] = median([r[field] for r in results])
            res["rounds"] = [round(r[key]) for r in results]  # type: ignore[assignment]
            if key == "p50":
                res["p99_rounds"] = [r["p99"] for r in results]  # type: ignore[assignment]
            merged[lib] = res
        rows.append((title, merged, key))
    return rows


def paired_p99(base: dict[str, float], mine: dict[str, float]) -> str:
    """rosx's p99 over rospy's, round by round (each pair ran one after the other, so the
    host's moods, which move both, mostly cancel out), and how many met the target."""
    mine_p99: list[float] = mine["p99_rounds"]  # type: ignore[assignment]
    base_p99: list[float] = base["p99_rounds"]  # type: ignore[assignment]
    ratios = [m / b for m, b in zip(mine_p99, base_p99, strict=True)]
    met = sum(ratio <= 0.5 for ratio in ratios)
    shown = ", ".join(f"{ratio:.2f}" for ratio in ratios)
    return f"  p99 ratio round by round: {shown} ({met} of {len(ratios)} <= 0.5)"


def inproc_floor(count: int) -> dict[str, float]:
    """What any in-process link costs at least, in this Python: the workers' publishing loop
    with ``publish`` doing nothing (msgs/s), and the private copy of a Twist each in-process
    subscriber gets (ns)."""
    from rosx.msg.codec.classes import get_message_class
    from rosx.msg.codec.clone import clone

    msg = get_message_class("geometry_msgs/Twist")()
    clock = time.time

    def publish(_: object) -> None:
        pass

    loops = []
    for _ in range(3):
        start = clock()
        for i in range(count):
            msg.linear.x = clock()
            msg.linear.y = i
            publish(msg)
        loops.append(count / (clock() - start))
    copies = []
    for _ in range(3):
        start = time.perf_counter()
        for _ in range(count):
            clone(msg)
        copies.append((time.perf_counter() - start) / count * 1e9)
    return {"loop_rate": max(loops), "copy_ns": min(copies)}


def print_inproc(rows: list[InprocRow], rounds: int, floor: dict[str, float] | None) -> None:
    """Print the one-process cases, and the floor under the floods (`inproc_floor`)."""
    if rows and floor is not None:
        print(
            f"One process, floor: the publishing loop alone {floor['loop_rate']:,.0f} msgs/s; "
            f"a Twist's copy {floor['copy_ns']:.0f} ns (at most "
            f"{1e9 / floor['copy_ns']:,.0f} msgs/s)"
        )
    for title, by_lib, key in rows:
        print(title)
        for lib, res in by_lib.items():
            parts = [f"received {int(res['received'])}", f"lost {int(res['lost'])}"]
            parts.append(f"{res['rate']:,.0f} msgs/s")
            if key == "p50":
                parts.append(f"latency p50 {res['p50']:.0f} us p99 {res['p99']:.0f} us")
            parts.append(f"(median of {rounds} rounds: {res['rounds']})")
            print(f"  {lib:8}: " + ", ".join(parts))
        base, mine = by_lib["rospy"], by_lib["rosx"]
        if key == "p50":
            print(
                f"  ratio rosx/rospy latency p50: {mine['p50'] / base['p50']:.2f}, "
                f"p99: {mine['p99'] / base['p99']:.2f}"
            )
            print(paired_p99(base, mine))
        else:
            print(f"  ratio rosx/rospy: {mine['rate'] / base['rate']:.1f}x (target >= 20)")
            if floor is not None and "queue_size=None" in title:
                wanted = 20 * base["rate"]
                print(
                    f"  20 x rospy's is {wanted:,.0f} msgs/s, {1e9 / wanted:.0f} ns a message: "
                    f"the copy alone takes {floor['copy_ns']:.0f}"
                )


def median(values: list[float]) -> float:
    ordered = sorted(values)
    mid = len(ordered) // 2
    return ordered[mid] if len(ordered) % 2 else (ordered[mid - 1] + ordered[mid]) / 2


Row = tuple[str, dict[str, dict[str, float]], str]

#: A two-process case's figures that are medians over its rounds.
MEDIAN_FIELDS = (
    "p50",
    "p99",
    "first_p50",
    "burst_p50",
    "rate",
    "bytes_rate",
    "received",
    "lost",
    "slowest",
)


def merged_rounds(runs: dict[str, list[dict[str, float]]], key: str) -> dict[str, dict[str, float]]:
    """Each library's figures over its rounds: the medians of `MEDIAN_FIELDS`, and the rounds'
    values of ``key`` (and of the p99, for latency)."""
    merged: dict[str, dict[str, float]] = {}
    for lib, results in runs.items():
        res = dict(results[-1])
        for field in MEDIAN_FIELDS:
            if field in res:
                res[field] = median([r[field] for r in results])
        if key == "p50" and not lib.startswith("floor-"):
            res["p99_rounds"] = [r["p99"] for r in results]  # type: ignore[assignment]
        scale_key = 2**30 if key == "bytes_rate" else 1
        res["rounds"] = [  # type: ignore[assignment]
            round(r[key] / scale_key, 2) if key == "bytes_rate" else round(r[key]) for r in results
        ]
        merged[lib] = res
    return merged


def print_rows(rows: list[Row]) -> None:
    """Print the two-process cases (``rosx-tcp``: rosx over TCPROS, for reference)."""
    for title, by_lib, key in rows:
        print(title)
        ros, rx = by_lib["rospy"], by_lib["rosx"]
        for lib, res in by_lib.items():
            if lib.startswith("floor-") and key == "bytes_rate":
                rate = res["bytes_rate"] / 2**30
                print(
                    f"  {lib}: {rate:.2f} GiB/s"
                    f" (median of {len(res['rounds'])}: {res['rounds']}),"  # type: ignore[arg-type]
                    f" rosx {rx['bytes_rate'] / res['bytes_rate']:.2f} x of it"
                )
                continue
            if lib.startswith("floor-"):  # bare sockets: latency
                print(
                    f"  {lib}: latency p50 {res['p50']:.0f} us p99 {res['p99']:.0f} us "
                    f"(median of {len(res['rounds'])}: {res['rounds']}), "  # type: ignore[arg-type]
                    f"p99 {res['p99'] / ros['p99']:.2f} x rospy's"
                )
                continue
            parts = [f"received {int(res['received'])}", f"lost {int(res['lost'])}"]
            if key == "bytes_rate":
                parts.append(f"{res['bytes_rate'] / 2**30:.2f} GiB/s")
            else:
                parts.append(f"{res['rate']:,.0f} msgs/s")
            if key == "p50":
                parts.append(f"latency p50 {res['p50']:.0f} us p99 {res['p99']:.0f} us")
            if key == "p50" and "burst" in title:
                parts.append(f"a burst's first message p50 {res['first_p50']:.0f} us")
                parts.append(
                    f"whole burst (first publish to last callback) {res['burst_p50']:.0f} us"
                )
            if res["slowest"] != res["rate"]:
                parts.append(f"slowest subscriber {res['slowest']:,.0f} msgs/s")
            rounds_done = len(res["rounds"])  # type: ignore[arg-type]
            parts.append(f"(median of {rounds_done}: {res['rounds']})")
            print(f"  {lib:8}: " + ", ".join(parts))
        base, mine = ros[key], rx[key]
        if key == "p50":
            print(
                f"  ratio rosx/rospy latency p50: {mine / base:.2f} (target <= 0.4), "
                f"p99: {rx['p99'] / ros['p99']:.2f} (target <= 0.5)"
            )
            print(paired_p99(ros, rx))
            if "burst" in title:
                print(
                    f"  ratio rosx/rospy whole burst p50: {rx['burst_p50'] / ros['burst_p50']:.2f}"
                )
        else:
            print(f"  ratio rosx/rospy: {mine / base:.1f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer messages")
    parser.add_argument(
        "--only",
        choices=("async", "sync", "latency", "image", "inproc", "fanout"),
        help="run only this case",
    )
    parser.add_argument(
        "--rounds",
        type=int,
        default=5,
        help="rounds of the latency, one-process and large-message cases, libraries alternating",
    )
    parser.add_argument(
        "--fast-rounds", type=int, default=1, help="rounds of the floods and fan-out cases"
    )
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    scale = 0.2 if args.quick else 1.0
    small, latency, images = int(200_000 * scale), int(3000 * scale), int(1000 * scale)
    warmup = latency // 6
    rounds = max(1, args.rounds if not args.quick else min(args.rounds, 2))
    fast_rounds = max(1, args.fast_rounds if not args.quick else 1)
    proc, master = start_master()
    rows: list[Row] = []
    inproc_rows: list[InprocRow] = []
    floor: dict[str, float] | None = None
    try:
        # name, title, kind, messages per publisher, publisher queue, period, key,
        # publishers, subscribers
        cases: list[tuple[str, str, str, int, int | None, float, str, int, int]] = [
            (
                "async",
                "Twist flood, async publisher (queue_size=100)",
                "twist",
                small,
                100,
                0.0,
                "rate",
                1,
                1,
            ),
            (
                "sync",
                "Twist flood, sync publisher (queue_size=None)",
                "twist",
                small,
                None,
                0.0,
                "rate",
                1,
                1,
            ),
            (
                "latency",
                "Twist at 1 kHz, latency (queue_size=100)",
                "twist",
                latency,
                100,
                0.001,
                "p50",
                1,
                1,
            ),
            (
                "latency",
                "Twist in bursts of 10 every 10 ms, latency (queue_size=100)",
                "twist",
                latency,
                100,
                -0.01,
                "p50",
                1,
                1,
            ),
            (
                "image",
                "1 MiB Image flood (queue_size=None)",
                "image",
                images // 5,
                None,
                0.0,
                "bytes_rate",
                1,
                1,
            ),
            (
                "image",
                "10 MiB PointCloud2 flood (queue_size=None)",
                "cloud",
                images // 50,
                None,
                0.0,
                "bytes_rate",
                1,
                1,
            ),
            (
                "fanout",
                "Twist, 1 publisher -> 10 subscribers (queue_size=100)",
                "twist",
                small // 10,
                100,
                0.0,
                "rate",
                1,
                10,
            ),
            (
                "fanout",
                "Twist, 10 publishers -> 1 subscriber (queue_size=100)",
                "twist",
                small // 10,
                100,
                0.0,
                "rate",
                10,
                1,
            ),
            (
                "fanout",
                "1 MiB Image, 1 publisher -> 10 subscribers (queue_size=None)",
                "image",
                images // 20,
                None,
                0.0,
                "bytes_rate",
                1,
                10,
            ),
            (
                "fanout",
                "1 MiB Image, 10 publishers -> 1 subscriber (queue_size=None)",
                "image",
                images // 20,
                None,
                0.0,
                "bytes_rate",
                10,
                1,
            ),
        ]
        if not args.only or args.only == "inproc":
            inproc_rows = inproc_cases(master, small, latency, rounds, warmup)
            floor = inproc_floor(small)
        for name, title, kind, count, pq, period, key, npubs, nsubs in cases:
            if args.only and name != args.only:
                continue
            # Rounds alternating rospy and rosx; for latency the first `warmup` messages of
            # each are ignored. Each library's figures are the medians over its rounds.
            libs: tuple[str, ...] = ("rospy", "rosx")
            if name in ("latency", "image"):
                libs = (*libs, "rosx-tcp")
            if name == "image":
                libs = (*libs, "floor-unix")
            if name == "latency":
                libs = (*libs, "floor-unix", "floor-unix-slice", "floor-tcp")
            runs: dict[str, list[dict[str, float]]] = {lib: [] for lib in libs}
            for _ in range(rounds if name in ("latency", "image") else fast_rounds):
                for lib, results in runs.items():
                    if lib.startswith("floor-") and name == "image":
                        results.append(run_bulk_floor(kind, count))
                        continue
                    if lib.startswith("floor-"):
                        results.append(run_floor(lib[6:], count, period, warmup))
                        continue
                    results.append(
                        run_case(
                            lib,
                            master,
                            kind,
                            count,
                            pq,
                            None,
                            period,
                            warmup if key == "p50" else 0,
                            publishers=npubs,
                            subscribers=nsubs,
                        )
                    )
            rows.append((title, merged_rounds(runs, key), key))
    finally:
        proc.terminate()
        proc.wait()
    print_inproc(inproc_rows, rounds, floor)
    print_rows(rows)


if __name__ == "__main__":
    main()
