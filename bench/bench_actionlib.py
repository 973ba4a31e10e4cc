"""actionlib's speed in rosx against ROS 1's python3-actionlib, side by side, in one run.

The same two programs run with each library: a server (a ``SimpleActionServer`` of
``actionlib/Test`` whose execute callback answers at once, or sends feedback at 1 kHz first) and
a client (a ``SimpleActionClient``), each a process of its own on ROS 1's ``rosmaster --core``.
ROS 1's run on Debian's Python with rospy and python3-actionlib; rosx's run under ``rosx
run-script`` (rosx's ``rospy`` and ``actionlib``), on ROS 1's interpreter by default
(`bench.interpreter`). Cases:

* round trip: goals sent one after the other, each waited for (``send_goal`` then
  ``wait_for_result``): the time from sending to the result, p50 and p99, and goals whose
  result never came or was wrong (rounds alternate the libraries; 1 000 goals a round);
* feedback at 1 kHz: one goal whose server sends N feedback messages 1 ms apart, then the
  result: feedback delivered, in order or not, and any that came after the result.

Prints the figures, the ratios rosx/ROS 1 and the target (goal -> result p50 <= 0.4 x ROS 1's).
Run: ``python bench/bench_actionlib.py [--quick] [--rounds N] [--goals N] [--feedback N]``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_pubsub import start_master  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402

SERVER = """
import time
import rospy
import actionlib
from actionlib.msg import TestAction, TestFeedback, TestResult

rospy.init_node("bench_action_server", disable_signals=True)

def execute(goal):
    if goal.goal < 0:  # the feedback case: -goal feedback messages, 1 ms apart
        start = time.perf_counter()
        for n in range(-goal.goal):
            server.publish_feedback(TestFeedback(n))
            pause = start + (n + 1) * 0.001 - time.perf_counter()
            if pause > 0:
                time.sleep(pause)
    server.set_succeeded(TestResult(goal.goal))

server = actionlib.SimpleActionServer("bench", TestAction, execute, auto_start=False)
server.start()
print("ready", flush=True)
rospy.spin()
"""

CLIENT = """
import json, sys, time
import rospy
import actionlib
from actionlib.msg import TestAction, TestGoal

goals, feedback_count = int(sys.argv[1]), int(sys.argv[2])
rospy.init_node("bench_action_client", disable_signals=True)
client = actionlib.SimpleActionClient("bench", TestAction)
assert client.wait_for_server(rospy.Duration(60))
report = {}
if goals:
    times, lost = [], 0
    for n in range(goals):
        start = time.perf_counter()
        client.send_goal(TestGoal(n))
        done = client.wait_for_result(rospy.Duration(10))
        times.append(time.perf_counter() - start)
        result = client.get_result()
        if not done or client.get_state() != 3 or result is None or result.result != n:
            lost += 1
    times.sort()
    report["p50"] = times[len(times) // 2]
    report["p99"] = times[int(len(times) * 0.99)]
    report["lost"] = lost
if feedback_count:
    seen, after = [], []
    finished = []
    def on_feedback(fb):
        (after if finished else seen).append(fb.feedback)
    client.send_goal(TestGoal(-feedback_count), lambda state, result: finished.append(state),
                     None, on_feedback)
    client.wait_for_result(rospy.Duration(60))
    time.sleep(0.5)  # feedback still in flight would arrive now
    report["feedback"] = len(seen)
    report["in_order"] = seen == sorted(seen) and len(set(seen)) == len(seen)
    report["after_result"] = len(after)
print(json.dumps(report), flush=True)
"""


def command(lib: str, script: Path) -> list[str]:
    if lib == "ros1":
        return [ROS1_PYTHON, str(script)]
    return [sys.executable, "-m", "rosx_commands", "run-script", str(script)]


def environ(lib: str, master: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
    env["ROS_MASTER_URI"] = master
    if lib == "ros1":
        env["ROS_PACKAGE_PATH"] = "/usr/share"
        env.pop("PYTHONPATH", None)
    else:
        env["PYTHONPATH"] = str(ROOT)
    return env


def run(lib: str, master: str, folder: Path, goals: int, feedback: int) -> dict[str, float]:
    """One server and one client of ``lib``; what the client reports."""
    server = subprocess.Popen(
        command(lib, folder / "server.py"),
        env=environ(lib, master),
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )
    try:
        assert server.stdout is not None
        if server.stdout.readline().strip() != "ready":
            raise SystemExit(f"{lib}: the server did not start")
        done = subprocess.run(
            [*command(lib, folder / "client.py"), str(goals), str(feedback)],
            env=environ(lib, master),
            capture_output=True,
            text=True,
            timeout=600,
            check=False,
        )
        if done.returncode != 0:
            raise SystemExit(f"{lib}: the client failed\n{done.stderr}")
        report: dict[str, float] = json.loads(done.stdout.splitlines()[-1])
        return report
    finally:
        server.terminate()
        try:
            server.wait(5)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer goals and rounds")
    parser.add_argument("--rounds", type=int, default=3, help="round-trip rounds per library")
    parser.add_argument("--goals", type=int, default=1000, help="goals in a row per round")
    parser.add_argument("--feedback", type=int, default=2000, help="feedback messages at 1 kHz")
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    rounds = 1 if args.quick else max(1, args.rounds)
    goals = 200 if args.quick else args.goals
    feedback = 500 if args.quick else args.feedback
    proc, master = start_master()
    libs = ("ros1", "rosx")
    trips: dict[str, list[dict[str, float]]] = {lib: [] for lib in libs}
    flows: dict[str, dict[str, float]] = {}
    try:
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            (folder / "server.py").write_text(SERVER)
            (folder / "client.py").write_text(CLIENT)
            for _ in range(rounds):
                for lib in libs:
                    trips[lib].append(run(lib, master, folder, goals, 0))
            for lib in libs:
                flows[lib] = run(lib, master, folder, 0, feedback)
    finally:
        proc.terminate()
        proc.wait()
    print(f"\ngoal -> result round trip, {goals} goals in a row, {rounds} round(s), medians:")
    p50 = {lib: statistics.median(r["p50"] for r in trips[lib]) for lib in libs}
    p99 = {lib: statistics.median(r["p99"] for r in trips[lib]) for lib in libs}
    lost = {lib: sum(int(r["lost"]) for r in trips[lib]) for lib in libs}
    print(f"{'':10}{'ROS 1':>12}{'rosx':>12}{'rosx/ROS 1':>12}")
    for name, values in (("p50 ms", p50), ("p99 ms", p99)):
        ratio = values["rosx"] / values["ros1"]
        print(f"{name:10}{values['ros1'] * 1e3:12.3f}{values['rosx'] * 1e3:12.3f}{ratio:12.2f}")
    print(f"{'lost':10}{lost['ros1']:12d}{lost['rosx']:12d}")
    verdict = "met" if p50["rosx"] <= 0.4 * p50["ros1"] else "NOT met"
    print(f"target: p50 <= 0.4 x ROS 1's: {verdict} ({p50['rosx'] / p50['ros1']:.2f} x)")
    print(f"\nfeedback at 1 kHz, {feedback} messages, then the result:")
    print(f"{'':14}{'ROS 1':>10}{'rosx':>10}")
    for key in ("feedback", "in_order", "after_result"):
        print(f"{key:14}{flows['ros1'][key]!s:>10}{flows['rosx'][key]!s:>10}")


if __name__ == "__main__":
    main()
