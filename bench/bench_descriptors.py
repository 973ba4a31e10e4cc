"""A master out of file descriptors: rosx's master and ROS 1's rosmaster, in the same run.

Each master runs in its own process limited to 1 024 descriptors (Linux's usual default,
``ulimit -n 1024``): rosx's as ``rosx.core.Core``, rosmaster as roscore starts it
(``rosmaster --core``) on ROS 1's Python. Once it answers, C connections (default 1 100) are
opened to it and left silent, as a port scanner, a hung client or a leaking one leaves them.
Then a legitimate client calls ``getPid`` on a new connection, with a 1 s timeout, again and
again for up to ``--wait`` seconds (default 40, past rosx's 30 s idle timeout).

Printed for each master: the seconds until the first answer (``never`` within the wait), the
calls that failed before it, how many idle connections the master closed by then, its
threads, and whether its output holds a traceback.

    python bench/bench_descriptors.py [--connections 1100] [--wait 40]
"""

from __future__ import annotations

import argparse
import os
import resource
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import IO

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_master import ROSMASTER, ROSX_MASTER  # noqa: E402
from bench.bench_soak import sample  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402
from rosx.transport.client import XmlRpcClient  # noqa: E402
from tests.support.procs import free_port  # noqa: E402
from tests.support.reserve import closed_by_peer  # noqa: E402

LIMIT = 1024


def _limited() -> None:
    resource.setrlimit(resource.RLIMIT_NOFILE, (LIMIT, LIMIT))


def start(which: str, port: int, log: IO[bytes]) -> subprocess.Popen[bytes]:
    if which == "rosx":
        args = [sys.executable, "-c", ROSX_MASTER, str(port)]
        env = {**os.environ, "PYTHONPATH": str(ROOT)}
    else:
        args = [ROS1_PYTHON, ROSMASTER, "--core", "-p", str(port)]
        env = dict(os.environ)
    return subprocess.Popen(
        args,
        env=env,
        stdout=log,
        stderr=subprocess.STDOUT,
        preexec_fn=_limited,  # noqa: PLW1509 - only setrlimit, before exec
        start_new_session=True,
    )


def stop(proc: subprocess.Popen[bytes]) -> None:
    for sig in (signal.SIGINT, signal.SIGKILL):
        if proc.poll() is not None:
            return
        os.killpg(proc.pid, sig)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            continue


def answers(uri: str, timeout: float) -> bool:
    client = XmlRpcClient(timeout=timeout)
    try:
        client.call(uri, "getPid", "/bench")
    except Exception:
        return False
    finally:
        client.close()
    return True


def descriptors(pid: int) -> int:
    try:
        return sample(pid)[2]
    except OSError:
        return 0


def open_idle(pid: int, port: int, count: int) -> list[socket.socket]:
    """``count`` silent connections, each opened once the master has accepted the one before
    (its descriptor count grew), as connections leaked over time pile up; once the master
    stops accepting, the rest are opened without waiting."""
    sockets: list[socket.socket] = []
    waiting = True
    for _ in range(count):
        before = descriptors(pid)
        sock = socket.socket()
        sock.settimeout(10)
        try:
            sock.connect(("127.0.0.1", port))
        except OSError:
            sock.close()
            continue
        sockets.append(sock)
        deadline = time.monotonic() + 0.5
        while waiting and descriptors(pid) <= before:
            if time.monotonic() > deadline:
                waiting = False
            time.sleep(0.001)
    return sockets


def measure(which: str, args: argparse.Namespace) -> None:
    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    with tempfile.TemporaryFile() as log:
        proc = start(which, port, log)
        try:
            deadline = time.monotonic() + 30
            while not answers(uri, 1.0):
                if time.monotonic() > deadline:
                    raise RuntimeError(f"{which} master did not start")
                time.sleep(0.1)
            idle = open_idle(proc.pid, port, args.connections)
            held = descriptors(proc.pid)
            started = time.monotonic()
            failed = 0
            first: float | None = None
            while time.monotonic() - started < args.wait:
                if answers(uri, 1.0):
                    first = time.monotonic() - started
                    break
                failed += 1
            closed = closed_by_peer(idle)
            count = sample(proc.pid)[1]
            for sock in idle:
                sock.close()
        finally:
            stop(proc)
        log.seek(0)
        traceback = b"Traceback" in log.read()
    answer = "never" if first is None else f"{first:.2f} s"
    print(
        f"{which:10} {len(idle):5} idle connected, {held:4} fds held   first answer {answer:>8}"
        f"   failed calls {failed:3}   idle closed {closed:5}   threads {count:5}"
        f"   traceback {'yes' if traceback else 'no'}",
        flush=True,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--connections", type=int, default=1100)
    parser.add_argument("--wait", type=float, default=40.0, help="seconds to keep calling")
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    wanted = args.connections + 256
    if soft < wanted:
        resource.setrlimit(resource.RLIMIT_NOFILE, (min(wanted, hard), hard))
    print(f"masters limited to {LIMIT} descriptors, {args.connections} idle connections")
    measure("rosx", args)
    if Path(ROSMASTER).exists():
        measure("rosmaster", args)
    else:
        print(f"rosmaster: {ROSMASTER} not found (install ROS 1's reference)")


if __name__ == "__main__":
    main()
