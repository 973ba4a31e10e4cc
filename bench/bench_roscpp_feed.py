"""What a roscpp subscriber takes from a Twist flood, by who feeds it, and what each costs.

The mixed pair rosx → roscpp of `bench_roscpp.py` ends in roscpp's subscriber, which reads
each message with two ``recv`` calls and hands it to its spinner thread: two busy threads. On
a machine of two cores its publisher's CPU is taken from them. This bench feeds the same
roscpp subscriber (`bench/cpp/bench_node.cpp`) from

* ``roscpp``: roscpp's publisher (the pair rosx → roscpp is compared with);
* ``rosx``: rosx's publisher (and ``rosx@PATH`` with ``--against PATH``);
* ``bare-1`` and ``bare-64``: a bare TCPROS publisher (this file, ``--feed``, on ROS 1's
  Python, nothing but the standard library), every frame serialized before the flood starts,
  written one ``send`` a frame or 64 frames a ``send``: a publisher that costs next to
  nothing, the most the subscriber can take on this machine.

Each run is a flood of ``--messages`` Twists (a million: the subscriber's socket stays full
for seconds, not only while the kernel's buffers fill); printed are the subscriber's msgs/s
(first message to last), and the CPU the publisher and the subscriber used while the flood
ran (their ``/proc`` times over the middle half of the time the subscriber was busy, in
cores), medians of the rounds.

``--busy`` keeps one core busy with another process (a Python loop) for the whole run.

Run: ``python bench/bench_roscpp_feed.py [--rounds 3] [--messages 1000000] [--against PATH]
[--busy]``.
"""

from __future__ import annotations

import argparse
import json
import os
import struct
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

TWIST_MD5 = "9f195f881246fdfa2798d1d3eebca84a"


def feed(master: str, count: int, chunk: int, name: str) -> None:
    """The bare publisher: register, take one subscriber, write ``count`` Twists."""
    import socket
    import threading
    import xmlrpc.client
    from xmlrpc.server import SimpleXMLRPCServer

    listener = socket.create_server(("127.0.0.1", 0))
    port = listener.getsockname()[1]
    slave = SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False, allow_none=True)
    slave.register_function(lambda *_: [1, "", ["TCPROS", "127.0.0.1", port]], "requestTopic")
    slave.register_function(lambda *_: [1, "", 0], "publisherUpdate")
    slave.register_function(lambda *_: [1, "", os.getpid()], "getPid")
    threading.Thread(target=slave.serve_forever, daemon=True).start()
    uri = f"http://127.0.0.1:{slave.server_address[1]}/"
    xmlrpc.client.ServerProxy(master).registerPublisher(name, "/bench", "geometry_msgs/Twist", uri)
    conn, _ = listener.accept()
    size = struct.unpack("<I", conn.recv(4, socket.MSG_WAITALL))[0]
    conn.recv(size, socket.MSG_WAITALL)  # the subscriber's header
    fields = [f"callerid={name}", f"md5sum={TWIST_MD5}", "type=geometry_msgs/Twist"]
    body = b"".join(struct.pack("<I", len(f)) + f.encode() for f in fields)
    conn.sendall(struct.pack("<I", len(body)) + body)
    now = time.time()
    frames = [struct.pack("<I6d", 48, now, float(i), 0, 0, 0, 0) for i in range(count)]
    for start in range(0, count, chunk):
        conn.sendall(b"".join(frames[start : start + chunk]))
    conn.recv(1)  # until the subscriber leaves


def cpu_or_none(pid: int) -> float | None:
    """The CPU seconds process ``pid`` has used, None once it is gone."""
    from bench.procstat import cpu_seconds

    try:
        return cpu_seconds(pid)
    except OSError:
        return None


def run(contender: str, master: str, count: int, number: int) -> dict[str, float]:
    """One flood from ``contender`` to a roscpp subscriber: its rate and the CPU used."""
    from bench.bench_pubsub import spawn_worker
    from bench.interpreter import ROS1_PYTHON

    name = f"feed{number}"
    sub = spawn_worker("roscpp", "sub", master, count, "null", "twist", 0, 1, f"{name}_sub")
    assert sub.stdout is not None
    sub.stdout.readline()  # "ready"
    env = dict(os.environ, ROS_MASTER_URI=master)
    if contender.startswith("bare-"):
        chunk = contender.removeprefix("bare-")
        argv = [ROS1_PYTHON, __file__, "--feed", master, str(count), chunk, f"/{name}_pub"]
        pub: subprocess.Popen[str] = subprocess.Popen(argv, env=env, text=True)
    else:  # roscpp's publisher or rosx's
        pub = spawn_worker(contender, "pub", master, count, "null", 0, "twist", 1, f"{name}_pub")
    samples = []
    while sub.poll() is None:
        samples.append((time.monotonic(), cpu_or_none(pub.pid), cpu_or_none(sub.pid)))
        time.sleep(0.05)
    out = sub.communicate()[0]
    pub.kill()
    pub.communicate()
    result: dict[str, float] = json.loads(out.strip().splitlines()[-1])
    live = [(t, p, s) for t, p, s in samples if p is not None and s is not None]
    # The flood: from the first to the last interval in which the subscriber used half a CPU.
    busy = [
        i
        for i in range(1, len(live))
        if live[i][2] - live[i - 1][2] > 0.5 * (live[i][0] - live[i - 1][0])
    ]
    if busy and busy[-1] - busy[0] >= 4:
        first, last = busy[0], busy[-1]
        quarter = (last - first) // 4
        (t0, p0, s0), (t1, p1, s1) = live[first + quarter], live[last - quarter]
        result["pub_cpu"] = (p1 - p0) / (t1 - t0)
        result["sub_cpu"] = (s1 - s0) / (t1 - t0)
    return result


def main() -> None:
    from bench import interpreter, roscpp_program
    from bench.bench_pubsub import median, start_master
    from bench.bench_roscpp import keep_busy, stop_run

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3, help="rounds of every contender")
    parser.add_argument("--messages", type=int, default=1_000_000, help="Twists a flood")
    parser.add_argument("--against", type=Path, help="also rosx from the checkout at PATH")
    parser.add_argument(
        "--busy", action="store_true", help="keep one core busy with another process meanwhile"
    )
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    if roscpp_program.program() is None:
        print("skipped: roscpp: the C++ worker could not be built")
        return
    contenders = ["roscpp", "rosx", "bare-1", "bare-64"]
    if args.against is not None:
        contenders.insert(2, f"rosx@{args.against.resolve()}")
    busy = keep_busy() if args.busy else None
    when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    print(
        f"{when}, {args.rounds} rounds of {args.messages} Twists, load {os.getloadavg()[0]:.2f}"
        + (f", one core kept busy (pid {busy.pid})" if busy else "")
    )
    proc, master = start_master()
    runs: dict[str, list[dict[str, float]]] = {c: [] for c in contenders}
    try:
        for number in range(args.rounds):
            turn = number % len(contenders)
            for index, contender in enumerate(contenders[turn:] + contenders[:turn]):
                runs[contender].append(run(contender, master, args.messages, number * 10 + index))
    finally:
        stop_run(proc, busy)
    base = median([r["rate"] for r in runs["roscpp"]])
    for contender, results in runs.items():
        rate = median([r["rate"] for r in results])
        cpu = [median([r.get(k, float("nan")) for r in results]) for k in ("pub_cpu", "sub_cpu")]
        rounds = ", ".join(f"{r['rate']:,.0f}" for r in results)
        print(
            f"  {contender:>12} > roscpp: {rate:,.0f} msgs/s ({rate / base:.2f} x roscpp's),"
            f" publisher {cpu[0]:.2f} CPU, subscriber {cpu[1]:.2f}; rounds: {rounds}"
        )
    print(f"  load {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--feed"]:
        feed(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5])
    else:
        main()
