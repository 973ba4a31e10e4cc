"""Soak: a churning graph for minutes; do the master and a long-lived node grow?

A rosx master runs in a process of its own (``rosx.core.Core``), and so does a long-lived
observer node that subscribes to all T topics (default 100). This process hosts N nodes (default
100), node ``i`` publishing ``std_msgs/String`` on 10 of the topics; every node publishes one
message on each of its topics per second, and every second C of them (default 5) are shut down
and started again under the same name, re-registering their topics: the master sends
``publisherUpdate`` to the observer, which drops the old connections and opens new ones.

Every ``--every`` seconds (default 5) the master's and the observer's resident memory, threads
and open file descriptors are read from ``/proc`` (Linux). After the run, the samples after the
warm-up (the first third) are split in two halves; a figure "grows" when the second half's mean
exceeds the first's by more than 5 % (and 2 MiB, 2 threads or 4 fds).

    python bench/bench_soak.py [--minutes 10] [--nodes 100] [--topics 100] [--churn 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from rosx.msg.codec.classes import get_message_class  # noqa: E402 -- after the path is set
from rosx.node import Node  # noqa: E402
from rosx.transport.client import XmlRpcClient  # noqa: E402
from rosx.transport.errors import ConnectError  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

TOPICS_PER_NODE = 10

_MASTER = """
import sys
from rosx.core import Core
with Core(int(sys.argv[1]), {}) as core:
    try:
        core.wait()
    except KeyboardInterrupt:
        pass
"""

_OBSERVER = """
import sys, threading, time
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
String = get_message_class("std_msgs/String")
count = [0]
lock = threading.Lock()
def heard(msg):
    with lock:
        count[0] += 1
node = Node("/soak_observer", master_uri=sys.argv[1], environ={}).start()
for t in range(int(sys.argv[2])):
    node.subscribe(f"/soak/t{t}", String, heard)
print("ready", flush=True)
try:
    while True:
        time.sleep(1)
        print(count[0], flush=True)
except KeyboardInterrupt:
    node.shutdown("soak over")
"""


def sample(pid: int) -> tuple[float, int, int]:
    """Resident memory (MiB), threads and open file descriptors of process ``pid``."""
    fields = dict(
        line.split(":", 1) for line in Path(f"/proc/{pid}/status").read_text().splitlines()
    )
    rss = int(fields["VmRSS"].split()[0]) / 1024
    return rss, int(fields["Threads"]), len(list(Path(f"/proc/{pid}/fd").iterdir()))


class Churn:
    """The N publishing nodes of this process, restarted C at a time."""

    def __init__(self, master: str, nodes: int, topics: int) -> None:
        self.master = master
        self.topics = topics
        self.string = get_message_class("std_msgs/String")
        self.nodes: list[tuple[Node, list[object]] | None] = [None] * nodes
        self.restarts = 0
        self.sent = 0

    def start(self, i: int) -> None:
        node = Node(f"/soak_{i}", master_uri=self.master, environ={}, rosout_enabled=False)
        node.start()
        publishers: list[object] = [
            node.advertise(f"/soak/t{(i * TOPICS_PER_NODE + k) % self.topics}", self.string)
            for k in range(TOPICS_PER_NODE)
        ]
        self.nodes[i] = (node, publishers)

    def restart(self, i: int) -> None:
        entry = self.nodes[i]
        if entry is not None:
            entry[0].shutdown("churn")
        self.start(i)
        self.restarts += 1

    def publish(self) -> None:
        for entry in self.nodes:
            if entry is None:
                continue
            for publisher in entry[1]:
                publisher.publish(self.string(data="x" * 64))  # type: ignore[attr-defined]
                self.sent += 1

    def close(self) -> None:
        for entry in self.nodes:
            if entry is not None:
                entry[0].shutdown("soak over")


def grows(values: list[float], floor: float) -> tuple[float, float, bool]:
    """Means of the two halves of ``values`` and whether the second is clearly higher."""
    half = len(values) // 2
    first, second = statistics.fmean(values[:half]), statistics.fmean(values[half:])
    return first, second, second > first * 1.05 and second - first > floor


Sample = tuple[float, tuple[float, int, int], tuple[float, int, int]]


def wait_for_master(uri: str) -> None:
    deadline = time.monotonic() + 30
    while True:
        try:
            XmlRpcClient(timeout=1).call(uri, "getPid", "/soak")
            return
        except (OSError, ConnectError):
            if time.monotonic() > deadline:
                raise
            time.sleep(0.1)


def follow(observer: subprocess.Popen[str]) -> list[str]:
    """Wait for the observer to subscribe; a list whose item is its latest message count."""
    assert observer.stdout is not None
    assert observer.stdout.readline() == "ready\n"
    received = ["0"]
    stdout = observer.stdout
    threading.Thread(
        target=lambda: [received.__setitem__(0, line.strip()) for line in stdout], daemon=True
    ).start()
    return received


def report(samples: list[Sample]) -> None:
    settled = samples[len(samples) // 3 :]
    print("\nafter the warm-up (first third), first half -> second half of the samples:")
    for who, index in (("master", 1), ("observer", 2)):
        for label, field, floor in (("RSS MiB", 0, 2.0), ("threads", 1, 2), ("fds", 2, 4)):
            values = [float(s[index][field]) for s in settled]  # type: ignore[index]
            first, second, grew = grows(values, floor)
            verdict = "GROWS" if grew else "flat"
            print(f"  {who:8} {label:8} {first:8.1f} -> {second:8.1f}  {verdict}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--nodes", type=int, default=100)
    parser.add_argument("--topics", type=int, default=100)
    parser.add_argument("--churn", type=int, default=5, help="nodes restarted per second")
    parser.add_argument("--every", type=float, default=5.0, help="seconds between samples")
    args = parser.parse_args()

    port = free_port()
    master_uri = f"http://127.0.0.1:{port}/"
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    master = subprocess.Popen([sys.executable, "-c", _MASTER, str(port)], env=env)
    observer: subprocess.Popen[str] | None = None
    churn: Churn | None = None
    try:
        wait_for_master(master_uri)
        observer = subprocess.Popen(
            [sys.executable, "-c", _OBSERVER, master_uri, str(args.topics)],
            env=env,
            stdout=subprocess.PIPE,
            text=True,
        )
        received = follow(observer)

        churn = Churn(master_uri, args.nodes, args.topics)
        started = time.monotonic()
        for i in range(args.nodes):
            churn.start(i)
        print(f"{args.nodes} nodes up in {time.monotonic() - started:.1f} s", flush=True)

        samples: list[Sample] = []
        end = time.monotonic() + args.minutes * 60
        next_sample = time.monotonic()
        victim = 0
        header = "  time  master MiB thr  fd | observer MiB thr  fd | restarts    sent  received"
        print(header, flush=True)
        while time.monotonic() < end:
            tick = time.monotonic()
            for _ in range(args.churn):
                churn.restart(victim)
                victim = (victim + 1) % args.nodes
            churn.publish()
            if tick >= next_sample:
                m, o = sample(master.pid), sample(observer.pid)
                elapsed = tick - started
                samples.append((elapsed, m, o))
                print(
                    f"{elapsed:6.0f}  {m[0]:10.1f} {m[1]:3} {m[2]:3} | {o[0]:12.1f} {o[1]:3}"
                    f" {o[2]:3} | {churn.restarts:8} {churn.sent:7} {received[0]:>9}",
                    flush=True,
                )
                next_sample += args.every
            time.sleep(max(0.0, 1.0 - (time.monotonic() - tick)))
        report(samples)
    finally:
        if churn is not None:
            churn.close()
        for process in (observer, master):
            if process is not None and process.poll() is None:
                process.terminate()
                process.wait(10)


if __name__ == "__main__":
    main()
