"""roscpp (C++), rosx and rospy side by side, in one run, on one master.

The C++ workers (`bench/cpp/bench_node.cpp`, compiled at bench time against Debian's
``libroscpp-dev`` by `bench.roscpp_program`; without it their cases say ``skipped: roscpp: …``
once and run without them) take the same arguments and print the same figures as the Python
workers of `bench_pubsub.py`, so every library runs the same cases in the same rounds,
libraries taking turns in each round:

* ``flood``: Twists as fast as the publisher goes, none lost: roscpp's publisher with an
  unbounded queue (``advertise(topic, 0)``), rospy's and rosx's synchronous one
  (``queue_size=None``); msgs/s delivered (the subscriber's count over the time from its
  first message to its last);
* ``flood100``: the same with ``queue_size=100`` for every publisher, as tutorials write it:
  msgs/s delivered and messages lost (roscpp's publisher queues each message for its I/O
  thread and drops the oldest when its queue is full; rosx writes on the publishing thread);
* ``latency``: Twists at 1 kHz, ``time.time()`` (the wall clock) before ``publish`` to the
  callback, p50 and p99, the first sixth left out; and the floor under them, a bare Python
  sender and receiver over a Unix socket, the receiver with rosx's short time slice
  (`bench_pubsub.run_floor`, ``unix-slice``): what this machine's wake-ups cost any library;
* ``pingpong``: a Twist bounced between two nodes, each publishing from its callback: half of
  each round trip, p50 and p99;
* ``image``: 1 MiB ``sensor_msgs/Image`` and ``cloud``: 10 MiB ``sensor_msgs/PointCloud2``,
  unbounded queues: bytes/s delivered, and the floor under them (bare Unix sockets moving
  frames of that size, `bench_pubsub.run_bulk_floor`).

Contenders: ``roscpp`` (C++ to C++, over TCPROS), ``rosx`` (over its Unix links, UNIXROS),
``rosx-tcp`` (over TCPROS, as to a ROS 1 node), ``rospy``, and in the floods the mixed pairs
``roscpp>rosx`` and ``rosx>roscpp`` (publisher > subscriber, over TCPROS). Each figure is the
median of the rounds, with its range; ratios are to roscpp's, the median and round by round
(each round's contenders ran within seconds of each other), against the targets in
bench/README.md (printed with each ratio). ``--against PATH`` adds rosx from the checkout at
PATH (``rosx@PATH`` and ``rosx-tcp@PATH``, and its mixed pairs), to measure a change side by
side with the code before it. ``--busy`` keeps one core busy with another process (a Python
loop) for the whole run; the load average (1 minute) is printed with each case.

Run: ``python bench/bench_roscpp.py [--only CASE ...] [--rounds 5] [--quick] [--busy]
[--against PATH] [--json PATH]``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter, roscpp_program  # noqa: E402 -- after the path is set
from bench.bench_pubsub import (  # noqa: E402
    median,
    run_bulk_floor,
    run_case,
    run_floor,
    spawn_worker,
    start_master,
)


class Case(NamedTuple):
    """One case: what runs, who runs it, the figure compared, and the targets."""

    name: str
    title: str
    kind: str  # twist, image, cloud, or pingpong
    messages: int
    queue: int | None  # the publishers' queue_size (None: roscpp's 0)
    period: float
    key: str  # rate, bytes_rate or p50
    contenders: tuple[str, ...]


#: Contenders: a library, a mixed pair ``PUB>SUB``, or ``floor`` (bare sockets).
SINGLE = ("roscpp", "rosx", "rosx-tcp", "rospy")
MIXED = ("roscpp>rosx", "rosx>roscpp")


def cases(scale: float) -> list[Case]:
    small, latency, large = int(200_000 * scale), int(3000 * scale), int(1000 * scale)
    clouds = max(10, large // 10)
    return [
        Case("flood", "Twist flood, none lost (queue unbounded / None)", "twist", small, None,
             0.0, "rate", SINGLE + MIXED),
        Case("flood100", "Twist flood, queue_size=100", "twist", small, 100, 0.0, "rate",
             ("roscpp", "rosx", "rosx-tcp", *MIXED)),
        Case("latency", "Twist at 1 kHz, publish -> callback", "twist", latency, 100, 0.001,
             "p50", (*SINGLE, "floor")),
        Case("pingpong", "Twist ping-pong, one way (half a round trip)", "pingpong", latency,
             100, 0.0, "p50", SINGLE),
        Case("image", "1 MiB Image flood (queue unbounded / None)", "image", large // 5, None,
             0.0, "bytes_rate", (*SINGLE, "floor")),
        Case("cloud", "10 MiB PointCloud2 flood (queue unbounded / None)", "cloud", clouds, None,
             0.0, "bytes_rate", (*SINGLE, "floor")),
    ]  # fmt: skip


def run_pingpong(lib: str, master: str, count: int, warmup: int) -> dict[str, float]:
    """One ping-pong between two processes of ``lib``."""
    pong = spawn_worker(lib, "pong", master, "bench_pong")
    ping = None
    try:
        assert pong.stdout is not None
        if pong.stdout.readline().strip() != "ready":
            raise SystemExit(f"{lib}: the ponger did not start")
        ping = spawn_worker(lib, "ping", master, count, warmup, "bench_ping")
        out = ping.communicate(timeout=240)[0]
    finally:
        for proc in (ping, pong):
            if proc is not None and proc.poll() is None:
                proc.kill()
                proc.wait()
    result: dict[str, float] = json.loads(out.strip().splitlines()[-1])
    result["lost"] = count - result["received"]
    return result


def with_checkout(contender: str, checkout: Path) -> str:
    """``contender`` with its rosx side run from the checkout at ``checkout``."""
    return ">".join(
        f"{lib}@{checkout}" if lib.startswith("rosx") else lib for lib in contender.split(">")
    )


def run_one(case: Case, contender: str, master: str) -> dict[str, float]:
    """One round of one contender in ``case``."""
    warmup = case.messages // 6 if case.key == "p50" else 0
    if contender == "floor" and case.key == "p50":
        return run_floor("unix-slice", case.messages, case.period, warmup)
    if contender == "floor":
        return run_bulk_floor(case.kind, case.messages)
    if case.kind == "pingpong":
        return run_pingpong(contender, master, case.messages, warmup)
    pub, _, sub = contender.partition(">")
    return run_case(
        pub, master, case.kind, case.messages, case.queue, None, case.period, warmup,
        sub_lib=sub or None,
    )  # fmt: skip


#: The targets (bench/README.md): (case, contender, figure) -> (comparison, bound, against whom).
TARGETS: dict[tuple[str, str, str], tuple[str, float, str]] = {
    ("flood", "rosx", "rate"): (">=", 2.0, "roscpp"),
    ("flood", "roscpp>rosx", "rate"): (">=", 1.25, "roscpp"),
    ("flood", "rosx>roscpp", "rate"): (">=", 1.25, "roscpp"),
    ("latency", "rosx", "p50"): ("<=", 0.3, "roscpp"),
    ("latency", "rosx", "p99"): ("<=", 0.3, "roscpp"),
    ("latency", "rosx-tcp", "p50"): ("<=", 0.5, "roscpp"),
    ("pingpong", "rosx", "p50"): ("<=", 0.3, "roscpp"),
    ("image", "rosx", "bytes_rate"): (">=", 1.5, "roscpp"),
    ("cloud", "rosx", "bytes_rate"): (">=", 0.7, "floor"),
}


def show(value: float, figure: str) -> str:
    if figure == "bytes_rate":
        return f"{value / 2**30:.2f}"
    if figure == "rate":
        return f"{value:,.0f}"
    return f"{value:.0f}"


UNITS = {"rate": "msgs/s", "bytes_rate": "GiB/s", "p50": "us", "p99": "us"}


def report(case: Case, runs: dict[str, list[dict[str, float]]], loads: list[float]) -> None:
    """Print a case: each contender's medians, ranges and rounds, then the ratios."""
    figures = ("p50", "p99") if case.key == "p50" else (case.key,)
    print(f"{case.title} (load {min(loads):.2f}-{max(loads):.2f}):")
    for contender, results in runs.items():
        if not results:
            continue
        parts = []
        for figure in figures:
            values = [r[figure] for r in results]
            parts.append(
                f"{figure} {show(median(values), figure)} {UNITS[figure]}"
                f" ({show(min(values), figure)}-{show(max(values), figure)})"
            )
        if contender != "floor":
            lost = [r["lost"] for r in results]
            parts.append(
                f"lost {median(lost):.0f} ({min(lost):.0f}-{max(lost):.0f} of {case.messages})"
            )
        rounds = ", ".join(show(r[case.key], case.key) for r in results)
        print(f"  {contender:12}: {'; '.join(parts)}; rounds: {rounds}")
    for contender, results in runs.items():
        for figure in figures:
            target = TARGETS.get((case.name, contender, figure))
            base_name = target[2] if target else "roscpp"
            base = runs.get(base_name)
            if contender == base_name or not results or not base:
                continue
            ratios = [r[figure] / b[figure] for r, b in zip(results, base, strict=True)]
            whole = median([r[figure] for r in results]) / median([b[figure] for b in base])
            line = (
                f"  {contender} / {base_name} {figure}: {whole:.2f}"
                f" (rounds {', '.join(f'{ratio:.2f}' for ratio in ratios)})"
            )
            if target is not None:
                sign, bound, _ = target
                ok = [ratio >= bound if sign == ">=" else ratio <= bound for ratio in ratios]
                met = whole >= bound if sign == ">=" else whole <= bound
                line += (
                    f"; target {sign} {bound}: {'met' if met else 'NOT met'},"
                    f" {sum(ok)} of {len(ok)} rounds"
                )
            print(line)


def keep_busy() -> subprocess.Popen[bytes]:
    """Another process keeping one core busy (a Python loop), until it is killed."""
    return subprocess.Popen([sys.executable, "-c", "while True: pass"])


def stop_run(master: subprocess.Popen[bytes], busy: subprocess.Popen[bytes] | None) -> None:
    """Stop a run's master and its busy loop, if it had one."""
    master.terminate()
    master.wait()
    if busy is not None:
        busy.kill()
        busy.wait()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    names = [case.name for case in cases(1.0)]
    parser.add_argument("--only", nargs="+", choices=names, help="run only these cases")
    parser.add_argument("--rounds", type=int, default=5, help="rounds of every case")
    parser.add_argument("--quick", action="store_true", help="a fifth of the messages")
    parser.add_argument(
        "--busy", action="store_true", help="keep one core busy with another process meanwhile"
    )
    parser.add_argument("--against", type=Path, help="also rosx from the checkout at PATH")
    parser.add_argument("--json", type=Path, help="write every round's figures to this file")
    interpreter.add_option(parser)
    args = parser.parse_args()
    if args.rounds < 1:
        parser.error("--rounds: at least 1")
    if args.against is not None and not (args.against / "rosx" / "node").is_dir():
        parser.error(f"--against: no rosx checkout at {args.against}")
    interpreter.run_on(args.python)
    has_roscpp = roscpp_program.program() is not None
    chosen = [
        case for case in cases(0.2 if args.quick else 1.0) if case.name in (args.only or names)
    ]
    busy = keep_busy() if args.busy else None
    when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    print(
        f"{when}, {args.rounds} rounds, load {os.getloadavg()[0]:.2f}"
        + (f", one core kept busy (pid {busy.pid})" if busy else ""),
        flush=True,
    )
    proc, master = start_master()
    everything: dict[str, dict[str, object]] = {}
    try:
        for case in chosen:
            contenders = [c for c in case.contenders if has_roscpp or "roscpp" not in c.split(">")]
            if args.against is not None:
                checkout = args.against.resolve()
                contenders += [with_checkout(c, checkout) for c in contenders if "rosx" in c]
            runs: dict[str, list[dict[str, float]]] = {c: [] for c in contenders}
            loads = []
            for number in range(args.rounds):
                loads.append(os.getloadavg()[0])
                turn = number % len(contenders)  # who goes first moves round by round
                for contender in contenders[turn:] + contenders[:turn]:
                    runs[contender].append(run_one(case, contender, master))
            loads.append(os.getloadavg()[0])
            report(case, runs, loads)
            sys.stdout.flush()
            everything[case.name] = {"loads": loads, "runs": runs}
    finally:
        stop_run(proc, busy)
    if args.json is not None:
        args.json.write_text(json.dumps({"when": when, "busy": args.busy, **everything}))


if __name__ == "__main__":
    main()
