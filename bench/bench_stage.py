"""The robot simulator's speed: CPU of stageros with 10 robots x 1 081 beams, and headless speed.

Stage itself (a C++ program with an OpenGL window) is not on this machine, so the figures are
held against DESIGN.md's targets rather than against ROS 1: 10 robots, each with a laser of
1 081 beams over 270.25° to 30 m at 10 Hz and odometry at 50 Hz (``interval_sim 20``), in a
20 m room with pillars, must cost at most 20 % of one core; one robot run headless with
``--speed`` must reach at least 20 x real time on ``/clock``.

Both run stageros as ``rosrun`` starts it (``-g``: no drawing) against ``rosx roscore``, with a
subscriber in this process to every scan and odometry topic (so every message is serialised
and sent). CPU is stageros's user + system time from /proc over the window. On a busy machine
stageros may fall behind real time (it gets less than it asks for), so its share is also given
per simulated second, and the headless speed per core it used.

``--against PATH`` also runs stageros from the rosx checkout at PATH (the code before a change),
the two taking turns in each of ``--rounds`` rounds, so that both see the same load.

    python bench/bench_stage.py [--seconds 10] [--rounds 1] [--against PATH]
                                [--python ros1|current|PATH]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "turtle"), str(ROOT / "commands")]

from bench import interpreter  # noqa: E402 - after the path is set
from bench.procstat import cpu_seconds  # noqa: E402
from tests.support.procs import free_port  # noqa: E402

ROBOT = """\
define lms ranger ( sensor ( range [ 0.0 30.0 ] fov 270.25 samples 1081 ) update_interval 100 )
define bot position ( size [ 0.35 0.35 0.25 ] drive "diff" lms ( pose [ 0.05 0 0 0 ] ) )
"""


def world_text(robots: int, interval_ms: int) -> str:
    """A 20 m room with 16 pillars and ``robots`` robots in a row."""
    lines = [f"resolution 0.02\ninterval_sim {interval_ms}\n", ROBOT]
    lines.append('define wall model ( color "gray30" )\n')
    for x, y, sx, sy in (
        (10, 0, 0.2, 20.2),
        (-10, 0, 0.2, 20.2),
        (0, 10, 20.2, 0.2),
        (0, -10, 20.2, 0.2),
    ):
        lines.append(f"wall ( pose [ {x} {y} 0 0 ] size [ {sx} {sy} 0.5 ] )\n")
    for i in range(4):
        for j in range(4):
            lines.append(f"wall ( pose [ {-6 + 4 * i} {-6 + 4 * j} 0 0 ] size [ 0.4 0.4 0.5 ] )\n")
    for k in range(robots):
        lines.append(f'bot ( pose [ {-8 + 1.6 * k:.2f} -8 0 90 ] name "r{k}" )\n')
    return "".join(lines)


def start(argv: list[str], env: dict[str, str], cwd: Path = ROOT) -> subprocess.Popen[bytes]:
    return subprocess.Popen(
        [sys.executable, "-m", "rosx_commands", *argv], cwd=cwd,
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True,
    )  # fmt: skip


def code_path(root: Path) -> str:
    """PYTHONPATH for rosx's code from the checkout at ``root``."""
    return os.pathsep.join(str(root / folder) for folder in ("", "turtle", "commands"))


def stop(proc: subprocess.Popen[bytes]) -> None:
    proc.terminate()
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def measure(
    robots: int, interval_ms: int, speed: float, seconds: float, root: Path = ROOT
) -> tuple[float, float, dict[str, int]]:
    """(stageros's CPU share of one core, simulated seconds per wall second, messages seen),
    stageros run from the checkout at ``root``."""
    from rosx.msg.codec.classes import get_message_class
    from rosx.node import Node

    port = free_port()
    uri = f"http://127.0.0.1:{port}/"
    env = {**os.environ, "ROS_MASTER_URI": uri, "PYTHONPATH": os.pathsep.join(sys.path)}
    with tempfile.TemporaryDirectory() as folder:
        world = Path(folder) / "bench.world"
        world.write_text(world_text(robots, interval_ms))
        core = start(["roscore", "-p", str(port)], env)
        stage = None
        node = None
        try:
            time.sleep(1.5)
            stage = start(
                ["rosrun", "stage_ros", "stageros", "-g", "--speed", str(speed), str(world)],
                {**env, "PYTHONPATH": code_path(root) + os.pathsep + env["PYTHONPATH"]},
                root,
            )
            node = Node("/bench_stage", master_uri=uri, environ=env).start()
            counts = {"scan": 0, "odom": 0}
            clock: list[float] = []
            lock = threading.Lock()

            def count(kind: str) -> Callable[[object], None]:
                def callback(message: object) -> None:
                    with lock:
                        counts[kind] += 1

                return callback

            def prefix(k: int) -> str:
                return f"/robot_{k}/" if robots > 1 else "/"

            scan_class = get_message_class("sensor_msgs/LaserScan")
            odom_class = get_message_class("nav_msgs/Odometry")
            for k in range(robots):
                node.subscribe(prefix(k) + "base_scan", scan_class, count("scan"), queue_size=10)
                node.subscribe(prefix(k) + "odom", odom_class, count("odom"), queue_size=50)
            node.subscribe(
                "/clock",
                get_message_class("rosgraph_msgs/Clock"),
                lambda m: clock.append(m.clock.to_sec()),
                queue_size=100,
            )
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline and counts["scan"] < robots * 3:
                time.sleep(0.1)
            with lock:
                for key in counts:
                    counts[key] = 0
            sim0 = clock[-1] if clock else 0.0
            cpu0, wall0 = cpu_seconds(stage.pid), time.monotonic()
            time.sleep(seconds)
            cpu1, wall1 = cpu_seconds(stage.pid), time.monotonic()
            sim1 = clock[-1] if clock else 0.0
            return (cpu1 - cpu0) / (wall1 - wall0), (sim1 - sim0) / (wall1 - wall0), dict(counts)
        finally:
            if node is not None:
                node.shutdown("bench over")
            if stage is not None:
                stop(stage)
            stop(core)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--rounds", type=int, default=1, help="rounds of every contender")
    parser.add_argument("--against", type=Path, help="also stageros from the checkout at PATH")
    interpreter.add_option(parser)
    args = parser.parse_args()
    if args.against is not None and not (args.against / "turtle" / "rosx_turtle").is_dir():
        parser.error(f"--against: no rosx checkout at {args.against}")
    interpreter.run_on(args.python)
    contenders = [("rosx", ROOT)]
    if args.against is not None:
        contenders.append((f"rosx@{args.against}", args.against.resolve()))
    for number in range(args.rounds):
        if args.rounds > 1:
            print(f"round {number + 1}:")
        for name, root in contenders:
            share, pace, counts = measure(10, 20, 1.0, args.seconds, root)
            scans, odometry = counts["scan"] / args.seconds, counts["odom"] / args.seconds
            print(
                f"  {name}: 10 robots x 1081 beams at 10 Hz, odometry at 50 Hz: stageros uses"
                f" {share * 100:.1f} % of one core at {pace:.2f} x real time, so"
                f" {share / pace * 100:.1f} % at real time (target <= 20 %); received"
                f" {scans:.0f} scans/s, {odometry:.0f} odometry/s",
                flush=True,
            )
        for name, root in contenders:
            share, factor, _ = measure(1, 100, 1000.0, args.seconds / 2, root)
            print(
                f"  {name}: 1 robot headless, --speed 1000: {factor:.1f} x real time on /clock"
                f" (target >= 20 x), stageros using {share * 100:.0f} % of one core:"
                f" {factor / share:.1f} x per core",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
