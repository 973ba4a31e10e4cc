"""A burst's first message, side by side: rospy, rosx, and rosx from another checkout.

The p99 latency of bursts (`bench_pubsub.py`) is the first message of each burst: it runs
after the publisher and the subscriber have slept, with the CPU's caches cold, and how cold
depends on what the host did meanwhile, so single runs minutes apart differ twofold. Here every
contender is started at once, each its own publisher (and, between two processes, its own
subscriber process), and they take turns: each publishes a burst of ten Twists every 10 ms, as
in `bench_pubsub.py`, the contenders' bursts spread evenly over those 10 ms in an order shuffled
every round. Whatever the host does then falls on all of them alike (and each contender's
bursts run after the others' work, not after 10 ms of nothing). Printed per contender, with
its ratio to rospy's: the first message's latency (``time.time()`` before ``publish`` to
``time.time()`` in the callback), p50 and p90 over the bursts (the p90 of first messages is about
the p99 of all messages); then every message's p50 and p99 (what `bench_pubsub.py` reports for
bursts), and the p99 ratio in ``--rounds`` rounds, the run cut into that many runs of
consecutive bursts. A round's p99 is its few slowest bursts, so one late burst of either
library moves it.

One more contender, ``floor``, is no library at all: a bare Python sender and a Python thread
blocked in ``recv_into`` on a Unix socket, that thread with the short time slice rosx's readers
ask for (`rosx.node.slices`). It is the floor under rosx's design in the same moment of the host,
and so shows how much of the ratio is left to any library (for a burst's first message: it does
not give way within a burst, so its later messages wait for the first, and it is left out of
the every-message figures).

``--against PATH`` adds rosx from the checkout at PATH (to measure a change: PATH holds the code
before it). ``--one-process`` puts each contender's subscriber in its publisher's process
(rosx links them in-process; rospy's one node talks to itself over TCPROS; the floor's thread
reads a socket pair in its sender's process).

Run: ``python bench/bench_burst.py [--bursts 390] [--rounds 5] [--against PATH] [--one-process]``.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_pubsub import API_ROSPY, API_ROSX, start_master  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402

# What publisher and subscriber share: the topic's class and the callback that records each
# message's place in its burst and latency (linear.x holds the stamp, linear.y the place; -1
# ends the run). The first argument names the contender's nodes and topic apart.
RECORDER = """
import sys, time, json, threading
tag = sys.argv[1]
cls = msg_class('geometry_msgs/Twist')
lat = []
done = threading.Event()
clock = time.time
def cb(msg):
    now = clock()
    if msg.linear.y >= 0:
        lat.append((msg.linear.y, now - msg.linear.x))
    else:
        done.set()
"""

# A publisher waiting for its turn: on "b" it publishes a burst and says "ok"; on "q" it
# publishes the last message and, with its own subscriber, prints what it measured.
PUBLISHER = (
    RECORDER
    + """
one_process = sys.argv[2] == '1'
make_node('burst_pub_' + tag)
if one_process:
    second_node('burst_sub_' + tag)
    subscriber('/burst_' + tag, cls, cb, 100)
pub = publisher('/burst_' + tag, cls, 100)
while pub.get_num_connections() == 0:
    time.sleep(0.01)
time.sleep(0.5)
print('ready', flush=True)
msg = cls()
for line in sys.stdin:
    if line.strip() != 'b':
        break
    for i in range(10):
        msg.linear.x = clock()
        msg.linear.y = i
        pub.publish(msg)
    print('ok', flush=True)
msg.linear.y = -1
pub.publish(msg)
if one_process:
    done.wait(10)
    print(json.dumps(lat), flush=True)
else:
    time.sleep(0.5)
import os
os._exit(0)
"""
)

SUBSCRIBER = (
    RECORDER
    + """
make_node('burst_sub_' + tag)
subscriber('/burst_' + tag, cls, cb, 100)
print('ready', flush=True)
done.wait(600)
print(json.dumps(lat), flush=True)
import os
os._exit(0)
"""
)

# The floor: the same turns and the same record (a 52-byte frame: stamp, place in its burst),
# over a Unix socket pair; its reader runs in a child process (two processes) or a thread.
FLOOR = """
import os, socket, struct, sys, threading, time, json
from rosx.node.slices import request_short_slice
one_process = sys.argv[2] == '1'
record = struct.Struct('<dd36x')
sender, receiver = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
clock = time.time
lat = []
def read():
    request_short_slice()
    buff = bytearray(65536)
    view = memoryview(buff)
    kept = 0
    while True:
        size = receiver.recv_into(view[kept:])
        now = clock()
        if not size:
            return
        kept += size
        whole = kept - kept % record.size
        for offset in range(0, whole, record.size):
            stamp, place = record.unpack_from(buff, offset)
            if place < 0:
                return
            lat.append((place, now - stamp))
        buff[:kept - whole] = buff[whole:kept]
        kept -= whole
if one_process:
    reader = threading.Thread(target=read)
    reader.start()
else:
    child = os.fork()
    if child == 0:
        sender.close()
        read()
        print(json.dumps(lat), flush=True)
        os._exit(0)
    receiver.close()
print('ready', flush=True)
for line in sys.stdin:
    if line.strip() != 'b':
        break
    for i in range(10):
        sender.send(record.pack(clock(), i))
    print('ok', flush=True)
sender.send(record.pack(0.0, -1))
if one_process:
    reader.join(10)
    print(json.dumps(lat), flush=True)
else:
    os.waitpid(child, 0)
os._exit(0)
"""

#: Bursts at the start of a run that are not counted (connections settling, first imports).
WARMUP = 20
#: Seconds from one burst of a contender to its next (`bench_pubsub.py`'s bursts: 10 ms).
PERIOD = 0.01
#: DESIGN.md's target for the p99 latency, as a share of rospy's.
P99_TARGET = 0.5


class Contender:
    """One library (or one checkout of rosx, or the floor): its publisher and, between two
    processes, its subscriber, on a topic of its own."""

    def __init__(
        self, name: str, master: str, root: Path | None, tag_number: int, *, one_process: bool
    ) -> None:
        self.name = name
        self.root = root
        self.floor = name == "floor"  # bare sockets: one worker, which forks its reader
        self.one_process = one_process
        self.tag = str(tag_number)  # names its nodes and topic apart from the others'
        self.env = dict(os.environ, ROS_MASTER_URI=master)
        if root is None:
            self.env["ROS_PACKAGE_PATH"] = "/usr/share"
        else:
            self.env["PYTHONPATH"] = str(root)
        self.sub: subprocess.Popen[str] | None = None
        self.pub: subprocess.Popen[str] | None = None

    def start(self) -> None:
        """Start the workers; return once the publisher sees its subscriber."""
        if not self.one_process and not self.floor:
            self.sub = self._spawn(SUBSCRIBER, self.tag)
            self._expect(self.sub, "ready")
        script = FLOOR if self.floor else PUBLISHER
        self.pub = self._spawn(script, self.tag, "1" if self.one_process else "0")
        self._expect(self.pub, "ready")

    def _spawn(self, script: str, *argv: str) -> subprocess.Popen[str]:
        python = ROS1_PYTHON if self.root is None else sys.executable
        api = "" if self.floor else API_ROSPY if self.root is None else API_ROSX
        return subprocess.Popen(
            [python, "-c", api + script, *argv],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            env=self.env,
            cwd=self.root or ROOT,
            text=True,
        )

    @staticmethod
    def _expect(proc: subprocess.Popen[str], word: str) -> None:
        assert proc.stdout is not None
        line = proc.stdout.readline().strip()
        if line != word:
            raise SystemExit(f"a worker said {line!r}, not {word!r}")

    def go(self) -> None:
        """Have the publisher publish a burst now (`done` waits for it)."""
        assert self.pub is not None and self.pub.stdin is not None
        self.pub.stdin.write("b\n")
        self.pub.stdin.flush()

    def done(self) -> None:
        assert self.pub is not None
        self._expect(self.pub, "ok")

    def finish(self) -> list[list[float]]:
        """Stop the workers; each burst's latencies in µs, in order, warm-up left out."""
        assert self.pub is not None
        out, _ = self.pub.communicate("q\n", timeout=60)
        if self.sub is not None:
            out, _ = self.sub.communicate(timeout=60)
        bursts: list[list[float]] = []
        for place, latency in json.loads(out.strip().splitlines()[-1]):
            if place == 0 or not bursts:
                bursts.append([])
            bursts[-1].append(latency * 1e6)
        return bursts[WARMUP:]

    def kill(self) -> None:
        for proc in (self.pub, self.sub):
            if proc is not None and proc.poll() is None:
                proc.kill()
                proc.wait()


def percentile(values: list[float], share: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(len(ordered) * share))]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bursts", type=int, default=390, help="bursts per contender")
    parser.add_argument("--against", type=Path, help="also rosx from the checkout at PATH")
    parser.add_argument(
        "--one-process", action="store_true", help="each subscriber in its publisher's process"
    )
    parser.add_argument("--rounds", type=int, default=5, help="rounds the run is cut into")
    interpreter.add_option(parser)
    args = parser.parse_args()
    if args.rounds < 1 or args.bursts < args.rounds:
        parser.error("--rounds: from 1 to the number of bursts")
    if args.against is not None and not (args.against / "rosx" / "node").is_dir():
        parser.error(f"--against: no rosx checkout at {args.against}")
    interpreter.run_on(args.python)
    roots: list[tuple[str, Path | None]] = []
    if Path(ROS1_PYTHON).exists():
        roots.append(("rospy", None))
    roots.append(("rosx", ROOT))
    if args.against is not None:
        roots.append((f"rosx@{args.against}", args.against.resolve()))
    roots.append(("floor", ROOT))
    proc, master = start_master()
    contenders: list[Contender] = []
    try:
        for number, (name, root) in enumerate(roots):
            contender = Contender(name, master, root, number, one_process=args.one_process)
            contenders.append(contender)  # before it starts: stopped whatever happens
            contender.start()
        order = list(contenders)
        rng = random.Random(0)
        slot = PERIOD / len(order)
        start = time.monotonic()
        for burst in range(args.bursts + WARMUP):
            rng.shuffle(order)
            for number, contender in enumerate(order):
                time.sleep(max(0.0, start + burst * PERIOD + number * slot - time.monotonic()))
                contender.go()
            for contender in order:
                contender.done()
        results = {contender.name: contender.finish() for contender in contenders}
    finally:
        for contender in contenders:
            contender.kill()
        proc.terminate()
        proc.wait()
    report(results, args.rounds, "one process" if args.one_process else "two processes")


def summary(values: list[float], base: list[float] | None, high: float, what: str) -> str:
    """``values``' p50 and their ``high`` percentile, and their ratios to ``base``'s (rospy's)."""
    label = f"p{round(high * 100)}"
    p50, top = percentile(values, 0.5), percentile(values, high)
    line = f"p50 {p50:6.1f} us, {label} {top:6.1f} us ({len(values)} {what})"
    if base is not None:
        line += (
            f", ratio to rospy p50 {p50 / percentile(base, 0.5):.2f}"
            f" {label} {top / percentile(base, high):.2f}"
        )
    return line


def report(results: dict[str, list[list[float]]], rounds: int, where: str) -> None:
    """Print the first messages' p50 and p90, then every message's p50 and p99, the whole run
    and round by round (the run cut into ``rounds`` runs of consecutive bursts), with the
    ratios to rospy's."""
    count = len(next(iter(results.values())))
    size = max(1, count // rounds)

    def flat(bursts: list[list[float]], part: int | None = None) -> list[float]:
        chosen = bursts if part is None else bursts[part * size : (part + 1) * size]
        return [value for burst in chosen for value in burst]

    base = results.get("rospy")
    base_firsts = None if base is None else [burst[0] for burst in base]
    base_every = None if base is None else flat(base)
    print(f"A burst's first message, publish -> callback, {where}, {count} bursts each:")
    for name, bursts in results.items():
        firsts = [burst[0] for burst in bursts]
        compared = None if name == "rospy" else base_firsts
        print(f"  {name:12}: {summary(firsts, compared, 0.9, 'bursts')}")
    print(
        f"Every message of the bursts, publish -> callback, p50 / p99,"
        f" and the p99 in {rounds} rounds of {size} bursts:"
    )
    for name, bursts in results.items():
        if name == "floor":
            continue  # it gives no way within a burst: its later messages wait for the first
        compared = None if name == "rospy" else base_every
        line = f"  {name:12}: {summary(flat(bursts), compared, 0.99, 'messages')}"
        if base is not None and name != "rospy":
            ratios = [
                percentile(flat(bursts, part), 0.99) / percentile(flat(base, part), 0.99)
                for part in range(rounds)
            ]
            within = sum(ratio <= P99_TARGET for ratio in ratios)
            line += (
                f"; p99 ratio by round {', '.join(f'{r:.2f}' for r in ratios)}"
                f" ({within} of {rounds} <= {P99_TARGET})"
            )
        print(line)


if __name__ == "__main__":
    main()
