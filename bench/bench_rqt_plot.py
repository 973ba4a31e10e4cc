"""rosx rqt_plot's CPU: idle (nothing arrives) and with 3 series at 1 kHz. Target: idle at most
2 % of one core (DESIGN.md; rqt_common_plugins#219: rqt_plot's MatPlot backend burns a core
with nothing published).

The real program runs on a terminal (a tmux pane, 120x40) against a rosx master, plotting
``/bench_a/data /bench_b/data /bench_c/data`` (std_msgs/Float64). Its process CPU time (user +
system, from /proc) is read over a window in each phase:

* **idle**: the three topics are advertised and the series attached, nothing is published;
* **3 x 1 kHz**: this process publishes each topic at 1 kHz (a sine), the plot at its default
  10 frames a second at most.

rqt_plot itself is not in the ROS 1 reference installed here (Debian packages no rqt), so
there is no ROS 1 figure beside these.

    python bench/bench_rqt_plot.py [--window 10]
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "commands"), str(ROOT / "turtle")]

from bench.procstat import cpu_seconds  # noqa: E402 -- after the path is set
from tests.support.procs import free_port  # noqa: E402

TOPICS = ("/bench_a", "/bench_b", "/bench_c")
RATE = 1000.0


def measure(pid: int, window: float) -> float:
    """Percent of one core ``pid`` used over ``window`` seconds."""
    start, t0 = cpu_seconds(pid), time.monotonic()
    time.sleep(window)
    return 100 * (cpu_seconds(pid) - start) / (time.monotonic() - t0)


def publish(publishers: Sequence[Any], message: type, stop: threading.Event) -> list[int]:
    """Each topic at `RATE` on average (batches catch up after a late wake-up)."""
    sent = [0]
    t0 = time.monotonic()
    while not stop.is_set():
        due = int((time.monotonic() - t0) * RATE)
        while sent[0] < due:
            value = math.sin(sent[0] / RATE)
            for publisher in publishers:
                publisher.publish(message(data=value))
            sent[0] += 1
        time.sleep(0.0005)
    return sent


def program_environ(uri: str) -> dict[str, str]:
    """This process's environment, less ROS_*, plus the master and the source roots."""
    environ = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    environ |= {"ROS_MASTER_URI": uri, "TERM": "xterm-256color"}
    environ["PYTHONPATH"] = os.pathsep.join(str(ROOT / p) for p in (".", "commands", "turtle"))
    return environ


def wait_for_port(port: int) -> None:
    deadline = time.monotonic() + 20
    while True:
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            return
        except OSError:
            if time.monotonic() > deadline:
                raise SystemExit("the master did not start") from None
            time.sleep(0.1)


def start_in_tmux(session: str, command: str, environ: dict[str, str]) -> int:
    """Run ``command`` as the only program of a 120x40 tmux pane; its PID."""
    subprocess.run(
        ["tmux", "new-session", "-d", "-s", session, "-x", "120", "-y", "40", command],
        env=environ,
        check=True,
    )
    pane = subprocess.run(
        ["tmux", "display", "-p", "-t", session, "#{pane_pid}"],
        capture_output=True,
        text=True,
        check=True,
    )
    return int(pane.stdout.strip())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--window", type=float, default=10.0, help="seconds measured per phase")
    args = parser.parse_args()
    if shutil.which("tmux") is None:
        raise SystemExit("tmux is needed (apt-get install tmux)")
    from rosx.msg.codec.classes import get_message_class
    from rosx.node import Node

    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    environ = program_environ(uri)
    rosx = [sys.executable, "-m", "rosx_commands"]
    core = subprocess.Popen(
        [*rosx, "roscore", "-p", str(port)],
        env=environ,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    session = f"bench_rqt_plot_{os.getpid()}"
    node = None
    try:
        wait_for_port(port)
        float64 = get_message_class("std_msgs/Float64")
        node = Node("bench_publisher", master_uri=uri, environ={}).start()
        publishers = [node.advertise(f"{t}/data", float64, queue_size=1000) for t in TOPICS]
        topics = [f"{t}/data/data" for t in TOPICS]
        pid = start_in_tmux(session, " ".join([*rosx, "rqt_plot", *topics]), environ)
        deadline = time.monotonic() + 30
        while sum(publisher.get_num_connections() for publisher in publishers) < 3:
            if time.monotonic() > deadline:
                raise SystemExit("rqt_plot did not subscribe")
            time.sleep(0.2)
        time.sleep(2.0)  # start-up done
        idle = measure(pid, args.window)
        stop = threading.Event()
        sent: list[int] = []
        thread = threading.Thread(
            target=lambda: sent.extend(publish(publishers, float64, stop)), daemon=True
        )
        thread.start()
        time.sleep(2.0)
        t0 = time.monotonic()
        busy = measure(pid, args.window)
        stop.set()
        thread.join()
        elapsed = time.monotonic() - t0 + 2.0
        screen = subprocess.run(
            ["tmux", "capture-pane", "-p", "-t", session],
            capture_output=True,
            text=True,
            check=False,
        ).stdout
        print(f"rqt_plot CPU, idle (3 series, nothing arrives): {idle:.2f} % of one core")
        print(f"rqt_plot CPU, 3 series at 1 kHz: {busy:.1f} % of one core")
        print(f"published: {sent[0] if sent else 0} per topic in {elapsed:.1f} s")
        print("legend at the end:", *[ln for ln in screen.splitlines() if "━━" in ln], sep="\n")
    finally:
        subprocess.run(["tmux", "kill-session", "-t", session], capture_output=True, check=False)
        if node is not None:
            node.shutdown("bench over")
        core.terminate()
        core.wait(10)


if __name__ == "__main__":
    main()
