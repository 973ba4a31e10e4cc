"""Soak of the course: every part at once for hours; does anything grow, does anything get lost?

Each part runs as the course runs it, a process of its own, on one rosx master:

- ``rosx roscore``;
- turtlesim (headless), with this process driving ``/turtle1`` in circles at 10 Hz;
- the tf demo: turtle_tf2's broadcasters of ``turtle1`` and ``turtle2`` (about 62 transforms
  a second each) and its listener, which spawns ``turtle2`` and chases ``turtle1`` through tf;
- the robot simulator (``stageros -g`` on turtlebot3's world) with a wander node: forward
  while the way ahead is clear, else turn;
- ``rosbag record`` of the poses, ``/tf``, the laser and the sequence below, split every
  ``--split-mb`` MB, two files kept;
- ``rosx rosbridge``, with a browser-like client connecting every 2 s, subscribing to
  ``/turtle1/pose``, taking 10 messages and leaving;
- ``rosx rviz`` in a pseudo-terminal, showing ``/tf`` and the laser;
- a talker publishing a sequence number on ``/soak/seq`` at 100 Hz (queue 1000), which this
  process counts, so that a missing number is a message lost;
- every ``--restart`` seconds (default 30) one of the tf listener, the wander node and the
  ``turtle2`` broadcaster is killed (SIGKILL) and started again.

Every ``--every`` seconds (default 10) the resident memory, threads and open descriptors of
the long-lived processes are read from ``/proc``; after the run the samples after the warm-up
(the first third) are split in two halves, and a figure "grows" when the second half's mean
exceeds the first's by more than 5 % (and 2 MiB, 2 threads or 4 descriptors), as
`bench_soak.py` judges its master.

    python bench/bench_course_soak.py --minutes 120     # the two-hour soak
    python bench/bench_course_soak.py --minutes 10      # a quick look
"""

from __future__ import annotations

import argparse
import contextlib
import fcntl
import os
import pty
import signal
import struct
import subprocess
import sys
import tempfile
import termios
import threading
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench.bench_soak import grows, sample, wait_for_master  # noqa: E402 -- after the path is set
from rosx.msg.codec.classes import get_message_class  # noqa: E402
from rosx.node import Node  # noqa: E402
from rosx.packages.crawl import PREFIX  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

TALKER = """
import sys, time
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
UInt32 = get_message_class("std_msgs/UInt32")
node = Node("/soak_talker", master_uri=sys.argv[1]).start()
pub = node.advertise("/soak/seq", UInt32, queue_size=1000)
n, next_at = 0, time.monotonic()
while not node.is_shutdown():
    n += 1
    pub.publish(UInt32(data=n))
    next_at += 0.01
    time.sleep(max(0.0, next_at - time.monotonic()))
"""

WANDER = """
import sys
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
Twist = get_message_class("geometry_msgs/Twist")
LaserScan = get_message_class("sensor_msgs/LaserScan")
node = Node("/wander", master_uri=sys.argv[1]).start()
pub = node.advertise("/cmd_vel", Twist, queue_size=1)
def on_scan(scan):
    middle = len(scan.ranges) // 2
    ahead = min(scan.ranges[middle - len(scan.ranges) // 8 : middle + len(scan.ranges) // 8])
    twist = Twist()
    if ahead < 0.45:
        twist.angular.z = 1.2
    else:
        twist.linear.x = 0.22
    pub.publish(twist)
node.subscribe("/base_scan", LaserScan, on_scan, queue_size=1)
node.wait_for_shutdown()
"""

RVIZ_CONFIG = """\
Visualization Manager:
  Global Options:
    Fixed Frame: world
  Displays:
    - Class: rviz/TF
      Name: TF
      Enabled: true
    - Class: rviz/LaserScan
      Name: LaserScan
      Enabled: true
      Topic: /base_scan
"""


class Parts:
    """The processes of the soak, started and stopped together."""

    def __init__(self, master_uri: str, folder: Path) -> None:
        self.env = {
            **os.environ,
            "ROS_MASTER_URI": master_uri,
            "ROS_HOME": str(folder / "ros"),
            "ROS_LOG_DIR": str(folder / "log"),
            "PYTHONPATH": str(ROOT),
        }
        self.master_uri = master_uri
        self.folder = folder
        self.long_lived: dict[str, subprocess.Popen[bytes]] = {}
        self.restartable: dict[str, tuple[list[str], subprocess.Popen[bytes]]] = {}
        self.restarts = 0
        self._ptys: list[int] = []

    def rosx(self, *args: str) -> list[str]:
        return [sys.executable, "-m", "rosx_commands", *args]

    def start(self, name: str, argv: list[str]) -> subprocess.Popen[bytes]:
        """Start a part; what it prints goes to ``NAME.log`` in the soak's folder."""
        with (self.folder / f"{name}.log").open("ab") as log:
            return subprocess.Popen(
                argv,
                env=self.env,
                cwd=self.folder,
                stdin=subprocess.DEVNULL,
                stdout=log,
                stderr=subprocess.STDOUT,
                start_new_session=True,
            )

    def last_words(self, name: str, lines: int = 5) -> str:
        """The end of what a part printed."""
        log = self.folder / f"{name}.log"
        if not log.exists():
            return "    (it ran in a terminal)"
        text = log.read_text(errors="replace").splitlines()
        return "\n".join(f"    {line}" for line in text[-lines:])

    def keep(self, name: str, argv: list[str]) -> None:
        self.long_lived[name] = self.start(name, argv)

    def restartable_part(self, name: str, argv: list[str]) -> None:
        self.restartable[name] = (argv, self.start(name, argv))

    def restart(self, name: str) -> None:
        argv, process = self.restartable[name]
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGKILL)
        process.wait(10)
        self.restartable[name] = (argv, self.start(name, argv))
        self.restarts += 1

    def in_terminal(self, name: str, argv: list[str]) -> None:
        """Run a terminal app on a pseudo-terminal of 120x40, its output read and dropped."""
        leader, follower = pty.openpty()
        fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))
        env = {**self.env, "TERM": "xterm-256color", "COLUMNS": "120", "LINES": "40"}
        self.long_lived[name] = subprocess.Popen(
            argv,
            env=env,
            cwd=self.folder,
            stdin=follower,
            stdout=follower,
            stderr=follower,
            start_new_session=True,
        )
        os.close(follower)
        self._ptys.append(leader)
        threading.Thread(target=self._drain, args=(leader,), daemon=True).start()

    @staticmethod
    def _drain(fd: int) -> None:
        with contextlib.suppress(OSError):
            while os.read(fd, 65536):
                pass

    def stop(self) -> None:
        processes = [p for _, p in self.restartable.values()] + list(self.long_lived.values())
        for process in processes:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGINT)
        for process in processes:
            try:
                process.wait(10)
            except subprocess.TimeoutExpired:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(process.pid, signal.SIGKILL)
                process.wait(5)
        for fd in self._ptys:
            with contextlib.suppress(OSError):
                os.close(fd)


class Sequence:
    """Counts ``/soak/seq``: received, and numbers skipped (lost messages)."""

    def __init__(self) -> None:
        self.received = 0
        self.lost = 0
        self.last = 0
        self.lock = threading.Lock()

    def __call__(self, msg: Any) -> None:
        with self.lock:
            self.received += 1
            if self.last and msg.data > self.last + 1:
                self.lost += msg.data - self.last - 1
            self.last = max(self.last, msg.data)


class BridgeClients:
    """A client connecting every 2 s: subscribe to /turtle1/pose, take 10 messages, leave."""

    def __init__(self, port: int) -> None:
        self.port = port
        self.sessions = 0
        self.messages = 0
        self.failures = 0
        self.stopping = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        import json

        from websockets.sync.client import connect

        while not self.stopping.wait(2.0):
            try:
                with connect(f"ws://127.0.0.1:{self.port}", open_timeout=5) as socket:
                    socket.send(json.dumps({"op": "subscribe", "topic": "/turtle1/pose"}))
                    got = 0
                    while got < 10:
                        frame = json.loads(socket.recv(timeout=5))
                        if frame.get("op") == "publish":
                            got += 1
                    self.messages += got
                    self.sessions += 1
            except Exception:  # the bridge is busy or restarting: counted, not fatal
                self.failures += 1


def _drive(node: Node) -> threading.Event:
    twist_class = get_message_class("geometry_msgs/Twist")
    publisher = node.advertise("/turtle1/cmd_vel", twist_class, queue_size=1)
    stop = threading.Event()

    def loop() -> None:
        while not stop.wait(0.1):
            twist = twist_class()
            twist.linear.x = 1.5
            twist.angular.z = 1.0
            publisher.publish(twist)

    threading.Thread(target=loop, daemon=True).start()
    return stop


def _world(folder: Path) -> Path:
    share = PREFIX / "share" / "turtlebot3_stage"
    text = (share / "worlds" / "turtlebot3_world.world").read_text()
    text = text.replace('bitmap "../maps/', f'bitmap "{share}/maps/')
    path = folder / "soak.world"
    path.write_text(text)
    return path


def _bag_sizes(folder: Path) -> str:
    bags = sorted(folder.glob("soak*.bag*"))
    return " ".join(f"{p.stat().st_size >> 20}M" for p in bags) or "-"


def report(samples: list[dict[str, tuple[float, int, int]]], names: list[str]) -> None:
    settled = samples[len(samples) // 3 :]
    print("\nafter the warm-up (first third), first half -> second half of the samples:")
    for name in names:
        for label, field, floor in (("RSS MiB", 0, 2.0), ("threads", 1, 2), ("fds", 2, 4)):
            values = [float(s[name][field]) for s in settled if name in s]
            if len(values) < 2:
                continue
            first, second, grew = grows(values, floor)
            print(
                f"  {name:10} {label:8} {first:8.1f} -> {second:8.1f}  "
                f"{'GROWS' if grew else 'flat'}"
            )


def main() -> None:  # noqa: PLR0915 - one scenario, read top to bottom
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--every", type=float, default=10.0, help="seconds between samples")
    parser.add_argument("--restart", type=float, default=30.0, help="seconds between restarts")
    parser.add_argument("--split-mb", type=int, default=50, help="the recorder's split size")
    args = parser.parse_args()

    port, bridge_port = free_port(), free_port()
    master_uri = f"http://127.0.0.1:{port}/"
    with tempfile.TemporaryDirectory(prefix="rosx-soak-") as name:
        folder = Path(name)
        (folder / "soak.rviz").write_text(RVIZ_CONFIG)
        parts = Parts(master_uri, folder)
        node: Node | None = None
        clients: BridgeClients | None = None
        driving: threading.Event | None = None
        try:
            parts.keep("roscore", parts.rosx("roscore", "-p", str(port)))
            wait_for_master(master_uri)
            parts.keep("turtlesim", parts.rosx("rosrun", "turtlesim", "turtlesim_node"))
            parts.keep("talker", [sys.executable, "-c", TALKER, master_uri])
            for turtle in ("turtle1", "turtle2"):
                argv = parts.rosx(
                    "rosrun",
                    "turtle_tf2",
                    "turtle_tf2_broadcaster.py",
                    f"__name:={turtle}_tf2_broadcaster",
                    f"_turtle:={turtle}",
                )
                if turtle == "turtle1":
                    parts.keep("tf_bcast1", argv)
                else:
                    parts.restartable_part("tf_bcast2", argv)
            parts.restartable_part(
                "tf_listener", parts.rosx("rosrun", "turtle_tf2", "turtle_tf2_listener.py")
            )
            world = str(_world(folder))
            parts.keep("stageros", parts.rosx("rosrun", "stage_ros", "stageros", "-g", world))
            parts.restartable_part("wander", [sys.executable, "-c", WANDER, master_uri])
            parts.keep(
                "recorder",
                parts.rosx(
                    "rosbag",
                    "record",
                    "-O",
                    "soak",
                    "--split",
                    f"--size={args.split_mb}",
                    "--max-splits=2",
                    "/turtle1/pose",
                    "/turtle2/pose",
                    "/tf",
                    "/base_scan",
                    "/soak/seq",
                ),
            )
            parts.keep("rosbridge", parts.rosx("rosbridge", "--port", str(bridge_port)))
            parts.in_terminal(
                "rviz", parts.rosx("rviz", "-d", str(folder / "soak.rviz"), "-f", "world")
            )

            node = Node("/soak_watch", master_uri=master_uri).start()
            sequence = Sequence()
            node.subscribe(
                "/soak/seq", get_message_class("std_msgs/UInt32"), sequence, queue_size=10000
            )
            driving = _drive(node)
            clients = BridgeClients(bridge_port)

            names = list(parts.long_lived)
            samples: list[dict[str, tuple[float, int, int]]] = []
            started = time.monotonic()
            end = started + args.minutes * 60
            next_sample = started + args.every
            next_restart = started + args.restart
            victims = list(parts.restartable)
            victim = 0
            print(
                "  time  "
                + "  ".join(f"{n[:9]:>9} MiB/thr/fd" for n in names)
                + "  | restarts seq-recv lost | bridge sessions msgs fails | bags",
                flush=True,
            )
            while time.monotonic() < end:
                now = time.monotonic()
                if now >= next_restart:
                    parts.restart(victims[victim % len(victims)])
                    victim += 1
                    next_restart += args.restart
                if now >= next_sample:
                    taken = {}
                    for part in names:
                        process = parts.long_lived[part]
                        if process.poll() is None:
                            with contextlib.suppress(OSError, KeyError):
                                taken[part] = sample(process.pid)
                    samples.append(taken)
                    cells = "  ".join(
                        f"{taken[n][0]:7.1f}/{taken[n][1]:3}/{taken[n][2]:3}"
                        if n in taken
                        else f"{'dead':>17}"
                        for n in names
                    )
                    print(
                        f"{now - started:6.0f}  {cells}  | {parts.restarts:8} "
                        f"{sequence.received:8} {sequence.lost:4} | {clients.sessions:15} "
                        f"{clients.messages:4} {clients.failures:5} | {_bag_sizes(folder)}",
                        flush=True,
                    )
                    next_sample += args.every
                time.sleep(0.2)
            dead = [n for n in names if parts.long_lived[n].poll() is not None]
            print(f"\nprocesses that died: {', '.join(dead) or 'none'}")
            for part in dead:
                print(f"  {part}, last lines:\n{parts.last_words(part)}")
            print(
                f"{parts.restarts} restarts; /soak/seq {sequence.received} received, "
                f"{sequence.lost} lost; bridge {clients.sessions} sessions, {clients.messages} "
                f"messages, {clients.failures} failed; bags {_bag_sizes(folder)}"
            )
            report(samples, names)
        finally:
            if clients is not None:
                clients.stopping.set()
            if driving is not None:
                driving.set()
            if node is not None:
                node.shutdown("soak over")
            parts.stop()


if __name__ == "__main__":
    main()
