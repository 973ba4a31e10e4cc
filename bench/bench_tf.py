"""tf2 speed of rosx against Debian's tf2_ros (python3-tf2-ros, whose core is C++), one run.

The same scripts run twice: under ROS 1's Python with Debian's ``tf2_ros`` and ``rospy``, and
under this Python with rosx's (``rosx run-script``, whose ``tf2_ros`` is `rosx.tf`):

* ``lookup``: ``Buffer.lookup_transform`` on a tree holding 10 s of transforms, between
  frame pairs drawn at random: at the latest time (``rospy.Time()``), and at random times in
  the buffer (each lookup its own time, so no answer can be kept from the one before). p50
  and p99 of single calls, in µs. Two trees: ``arms``, the target's, 30 frames all moving at
  100 Hz (map, odom, a base, two six-joint arms with grippers, sensors, a head, wheels;
  chains up to 11 frames deep), and ``robot``, a mobile base as its URDF and a driver
  publish it (map -> odom -> base_footprint at 20 Hz, wheels at 50 Hz from the joint states,
  base_link, laser, imu, caster and camera static).
* ``listener``: a ``TransformListener`` taking 50 frames at 100 Hz on ``/tf`` (one TFMessage
  of 50 transforms a hundred times a second, from a rospy publisher in both cases): the CPU
  it uses, in % of one core, over ``--seconds``.
* ``latency``: a ``TransformBroadcaster`` in one process, a ``Buffer`` and listener in
  another: from the stamp ``sendTransform`` sends to the transform being there for a lookup,
  p50 and p99 over ``--messages`` transforms at 50 Hz, in each of ``--rounds``, three ways
  (``--way``; each round the libraries take turns, the other first every other round):
  ``wait``, as the tutorials wait, a ``lookup_transform`` with a timeout (1 s) for the
  transform at a time not sent yet (1 ms after the last one's stamp), the time taken when it
  returns; ``stored``, the moment the listener's callback has stored it (its
  ``TransformListener.callback`` wrapped the same way in both libraries), when any lookup
  would find it; ``polled``, lookups at the latest time every ``--poll`` µs (20, with a timer
  slack of 1 ns) until one finds it, which adds the poll's own delay to both (a 20 µs sleep
  takes about 42 µs on this machine).

Targets (DESIGN.md): lookup p50 ≤ 1 x Debian's; listener ≤ 10 % of one core; latency p50 ≤
0.5 x ROS 1's. Run: ``python bench/bench_tf.py [--only lookup|listener|latency]
[--tree arms|robot] [--seconds N] [--messages N] [--rounds N] [--way wait|stored|polled]
[--poll µs]``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench import interpreter  # noqa: E402 -- after the path is set
from bench.bench_pubsub import start_master  # noqa: E402
from bench.interpreter import ROS1_PYTHON  # noqa: E402

# Two arms on a mobile base: (child, parent, Hz), in the order they are sent.
ARMS = [
    ("odom", "map"),
    ("base_footprint", "odom"),
    ("base_link", "base_footprint"),
    *[(f"left_{i}", "base_link" if i == 1 else f"left_{i - 1}") for i in range(1, 7)],
    ("left_gripper", "left_6"),
    ("left_finger", "left_gripper"),
    *[(f"right_{i}", "base_link" if i == 1 else f"right_{i - 1}") for i in range(1, 7)],
    ("right_gripper", "right_6"),
    ("right_finger", "right_gripper"),
    ("torso", "base_link"),
    ("head", "torso"),
    ("camera", "head"),
    ("camera_optical", "camera"),
    ("laser", "base_link"),
    ("imu", "base_link"),
    ("wheel_left", "base_link"),
    ("wheel_right", "base_link"),
    ("gps", "base_link"),
    ("bumper", "base_footprint"),
]
assert len(ARMS) == 29  # 30 frames with map

# A mobile base: (child, parent, Hz), 0 for a static joint.
ROBOT = [
    ("odom", "map", 20),
    ("base_footprint", "odom", 20),
    ("base_link", "base_footprint", 0),
    ("laser", "base_link", 0),
    ("imu_link", "base_link", 0),
    ("wheel_left_link", "base_link", 50),
    ("wheel_right_link", "base_link", 50),
    ("caster_link", "base_link", 0),
    ("camera_link", "base_link", 0),
    ("camera_optical_frame", "camera_link", 0),
]

TREES = {
    "arms": ([(child, parent, 100) for child, parent in ARMS], "30 frames, all at 100 Hz"),
    "robot": (ROBOT, "11 frames: odom 20 Hz, wheels 50 Hz, 6 static"),
}

LOOKUP = r"""
import json, math, random, sys, time
import rospy, tf2_ros
from geometry_msgs.msg import TransformStamped
tree = json.loads(sys.argv[1]); count = int(sys.argv[2])
buffer = tf2_ros.Buffer(rospy.Duration(10), debug=False)
start = 1000.0
for k in range(1000):  # 10 s in steps of 10 ms
    for i, (child, parent, hz) in enumerate(tree):
        if (k and not hz) or (hz and k % (100 // hz)):
            continue
        t = TransformStamped()
        t.header.frame_id = parent
        t.child_frame_id = child
        t.header.stamp = rospy.Time.from_sec(start + k * 0.01)
        a = 0.001 * k + 0.1 * i
        t.transform.translation.x = 0.1 * i
        t.transform.translation.y = math.sin(a)
        t.transform.rotation.z = math.sin(a / 2)
        t.transform.rotation.w = math.cos(a / 2)
        if hz:
            buffer.set_transform(t, "bench")
        else:
            buffer.set_transform_static(t, "bench")
frames = ["map"] + [c for c, _, _ in tree]
rng = random.Random(30)
pairs = [rng.sample(frames, 2) for _ in range(count)]
times = [rospy.Time.from_sec(start + 0.5 + 9.0 * rng.random()) for _ in range(count)]
latest = rospy.Time()
out = {}
for name, when in (("latest", None), ("random", times)):
    spent = []
    for i, (target, source) in enumerate(pairs):
        at = latest if when is None else when[i]
        t0 = time.perf_counter_ns()
        buffer.lookup_transform(target, source, at)
        spent.append(time.perf_counter_ns() - t0)
    spent.sort()
    out[name] = [spent[len(spent) // 2] / 1000, spent[len(spent) * 99 // 100] / 1000]
print(json.dumps(out))
"""

PUBLISHER = r"""
import math, sys, rospy
from geometry_msgs.msg import TransformStamped
from tf2_msgs.msg import TFMessage
rospy.init_node("bench_tf_publisher", disable_signals=True)
pub = rospy.Publisher("/tf", TFMessage, queue_size=100)
rate = rospy.Rate(100)
k = 0
while not rospy.is_shutdown():
    now = rospy.Time.now()
    msg = TFMessage()
    for i in range(50):
        t = TransformStamped()
        t.header.frame_id = "base" if i == 0 else "f%d" % (i - 1)
        t.child_frame_id = "f%d" % i
        t.header.stamp = now
        t.transform.translation.x = 0.01 * k
        t.transform.rotation.z = math.sin(0.001 * k)
        t.transform.rotation.w = math.cos(0.001 * k)
        msg.transforms.append(t)
    pub.publish(msg)
    k += 1
    rate.sleep()
"""

LISTENER = r"""
import json, resource, sys, time
import rospy, tf2_ros
seconds = float(sys.argv[1])
rospy.init_node("bench_tf_listener", disable_signals=True)
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
while not buffer.can_transform("base", "f49", rospy.Time()):
    time.sleep(0.05)
time.sleep(1.0)  # warm-up
before = resource.getrusage(resource.RUSAGE_SELF)
t0 = time.monotonic()
time.sleep(seconds)
after = resource.getrusage(resource.RUSAGE_SELF)
wall = time.monotonic() - t0
cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
rate = float(buffer.all_frames_as_yaml().split("f49: ")[1].split("rate: ")[1].split()[0])
print(json.dumps({"cpu": 100 * cpu / wall, "rate": rate}))
"""

BROADCASTER = r"""
import sys, time, rospy, tf2_ros
from geometry_msgs.msg import TransformStamped
count = int(sys.argv[1])
rospy.init_node("bench_tf_broadcaster", disable_signals=True)
br = tf2_ros.TransformBroadcaster()
time.sleep(2.0)  # the listener connects
for k in range(count + 20):
    t = TransformStamped()
    t.header.frame_id = "world"
    t.child_frame_id = "mover"
    t.transform.translation.x = k
    t.transform.rotation.w = 1.0
    t.header.stamp = rospy.Time.now()
    br.sendTransform(t)
    time.sleep(0.02)
"""

WAITER = r"""
import ctypes, json, sys, threading, time, rospy, tf2_ros
count, way, poll = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
try:  # sleep as asked: Linux's default 50 µs timer slack would stretch each poll
    ctypes.CDLL(None).prctl(29, 1, 0, 0, 0)  # PR_SET_TIMERSLACK, 1 ns
except (OSError, AttributeError):
    pass
rospy.init_node("bench_tf_waiter", disable_signals=True)
delays = []
if way == "stored":  # the moment the listener's callback has stored it
    done = threading.Event()
    plain = tf2_ros.TransformListener.callback
    def callback(self, data):
        plain(self, data)
        now = time.time()
        delays.append(now - data.transforms[0].header.stamp.to_sec())
        if len(delays) >= count + 10:
            done.set()
    tf2_ros.TransformListener.callback = callback
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
print("ready", flush=True)
zero = rospy.Time()
deadline = time.time() + 60
if way == "stored":
    done.wait(60)
elif way == "wait":  # as the tutorials wait: for the transform at a time not yet sent
    # 1 ms after the last stamp (tf2_py takes times as doubles, 0.24 µs apart at today's
    # stamps), which only the next transform, 20 ms later, answers
    step = rospy.Duration(0, 1000000)
    seen = buffer.lookup_transform("world", "mover", zero, rospy.Duration(30)).header.stamp
    while len(delays) < count + 10 and time.time() < deadline:
        buffer.lookup_transform("world", "mover", seen + step, rospy.Duration(1))
        now = time.time()
        stamp = buffer.lookup_transform("world", "mover", zero).header.stamp
        if stamp != seen:
            delays.append(now - stamp.to_sec())
            seen = stamp
else:  # polled: lookups every `poll` seconds until a new one is found
    seen = -1
    while len(delays) < count + 10 and time.time() < deadline:
        try:
            t = buffer.lookup_transform("world", "mover", zero)
        except tf2_ros.TransformException:
            time.sleep(poll)
            continue
        k = int(t.transform.translation.x)
        if k != seen:
            delays.append(time.time() - t.header.stamp.to_sec())
            seen = k
        time.sleep(poll)
delays = sorted(delays[10:])
p50, p99 = delays[len(delays) // 2], delays[len(delays) * 99 // 100]
print(json.dumps({"p50": p50 * 1e6, "p99": p99 * 1e6}))
"""


def command(lib: str, script: Path, *argv: object) -> tuple[list[str], dict[str, str]]:
    """How to run ``script`` with ``lib``: ``ros1`` (Debian's tf2_ros) or ``rosx``."""
    env = dict(os.environ)
    if lib == "ros1":
        env["ROS_PACKAGE_PATH"] = "/usr/share"
        env.pop("PYTHONPATH", None)
        return [ROS1_PYTHON, str(script), *map(str, argv)], env
    env["PYTHONPATH"] = str(ROOT)
    runner = [sys.executable, "-m", "rosx_commands", "run-script", str(script)]
    return [*runner, *map(str, argv)], env


def run(lib: str, script: Path, *argv: object, master: str | None = None) -> dict[str, float]:
    args, env = command(lib, script, *argv)
    if master is not None:
        env["ROS_MASTER_URI"] = master
    done = subprocess.run(args, env=env, capture_output=True, text=True, timeout=600, check=False)
    if done.returncode != 0:
        raise SystemExit(f"{lib} {script.name} failed:\n{done.stderr}")
    result: dict[str, float] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


def spawn(lib: str, script: Path, master: str, *argv: object) -> subprocess.Popen[str]:
    args, env = command(lib, script, *argv)
    env["ROS_MASTER_URI"] = master
    return subprocess.Popen(
        args, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True
    )


def stop(process: subprocess.Popen[str]) -> None:
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(5)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def ratio(mine: float, theirs: float) -> str:
    return f"{mine / theirs:.2f} x" if theirs else "-"


def bench_lookup(folder: Path, rounds: int, count: int, tree: str) -> None:
    script = folder / "lookup.py"
    script.write_text(LOOKUP)
    runs: dict[str, list[dict[str, list[float]]]] = {"ros1": [], "rosx": []}
    frames = json.dumps(TREES[tree][0])
    for _ in range(rounds):
        for lib in ("ros1", "rosx"):
            runs[lib].append(run(lib, script, frames, count))  # type: ignore[arg-type]
    print(
        f"\nlookup_transform, the {tree} tree ({TREES[tree][1]}; 10 s), {count} lookups"
        " (µs, median of rounds)"
    )
    print(f"  {'':<28}{'Debian tf2_ros':>16}{'rosx':>10}{'rosx/ROS 1':>12}   each round")
    for case in ("latest", "random"):
        for index, name in ((0, "p50"), (1, "p99")):
            theirs = sorted(r[case][index] for r in runs["ros1"])[rounds // 2]
            mine = sorted(r[case][index] for r in runs["rosx"])[rounds // 2]
            label = f"{'at the latest time' if case == 'latest' else 'at random times'} {name}"
            pairs = zip(runs["rosx"], runs["ros1"], strict=True)
            each = sorted(r[case][index] / o[case][index] for r, o in pairs)
            spread = f"{each[0]:.2f}-{each[-1]:.2f} x"
            print(f"  {label:<28}{theirs:>16.2f}{mine:>10.2f}{ratio(mine, theirs):>12}   {spread}")


def bench_listener(folder: Path, seconds: float, master: str) -> None:
    publisher = folder / "publisher.py"
    publisher.write_text(PUBLISHER)
    listener = folder / "listener.py"
    listener.write_text(LISTENER)
    sender = spawn("ros1", publisher, master)
    try:
        results = {lib: run(lib, listener, seconds, master=master) for lib in ("ros1", "rosx")}
    finally:
        stop(sender)
    print(f"\nTransformListener, 50 frames at 100 Hz on /tf, {seconds:g} s (% of one core)")
    theirs, mine = results["ros1"]["cpu"], results["rosx"]["cpu"]
    print(f"  Debian tf2_ros {theirs:.1f} %   rosx {mine:.1f} %   rosx/ROS 1 {ratio(mine, theirs)}")
    rates = (results["ros1"]["rate"], results["rosx"]["rate"])
    print(f"  (each frame's rate in the buffer: ROS 1 {rates[0]:.1f} Hz, rosx {rates[1]:.1f} Hz)")


#: How the latency's waiting process learns of each transform (`WAITER`), and what each
#: figure is called.
WAYS = {
    "wait": "a lookup waiting for the next transform (the tutorials' timeout)",
    "stored": "stored by the listener (its callback returned)",
    "polled": "lookups polled every {poll:g} µs at the latest time",
}


def bench_latency(
    folder: Path, messages: int, master: str, rounds: int, poll: float, ways: list[str]
) -> None:
    broadcaster = folder / "broadcaster.py"
    broadcaster.write_text(BROADCASTER)
    waiter = folder / "waiter.py"
    waiter.write_text(WAITER)
    runs: dict[str, dict[str, list[dict[str, float]]]] = {
        way: {"ros1": [], "rosx": []} for way in ways
    }
    for round_ in range(rounds):
        for way in ways:
            for lib in ("ros1", "rosx") if round_ % 2 == 0 else ("rosx", "ros1"):
                listening = spawn(lib, waiter, master, messages, way, poll / 1e6)
                assert listening.stdout is not None
                listening.stdout.readline()  # ready
                sending = spawn(lib, broadcaster, master, messages)
                try:
                    out, _ = listening.communicate(timeout=120)
                finally:
                    stop(sending)
                    stop(listening)
                runs[way][lib].append(json.loads(out.strip().splitlines()[-1]))
    print(
        f"\nsendTransform -> the transform found, {messages} transforms at 50 Hz"
        " (µs, median of rounds)"
    )
    for way in ways:
        print(f"  {WAYS[way].format(poll=poll)}:")
        for name in ("p50", "p99"):
            theirs = sorted(r[name] for r in runs[way]["ros1"])[rounds // 2]
            mine = sorted(r[name] for r in runs[way]["rosx"])[rounds // 2]
            pairs = zip(runs[way]["rosx"], runs[way]["ros1"], strict=True)
            each = sorted(r[name] / o[name] for r, o in pairs)
            print(
                f"    {name}: ROS 1 {theirs:.0f}   rosx {mine:.0f}"
                f"   rosx/ROS 1 {ratio(mine, theirs)}   each round {each[0]:.2f}-{each[-1]:.2f} x"
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", choices=("lookup", "listener", "latency"))
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--messages", type=int, default=500)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument(
        "--poll", type=float, default=20.0, help="µs the latency's polling waiter sleeps"
    )
    parser.add_argument(
        "--way", choices=tuple(WAYS), action="append", help="one way of waiting (all by default)"
    )
    parser.add_argument("--lookups", type=int, default=20000)
    parser.add_argument("--tree", choices=tuple(TREES), help="one lookup tree (both by default)")
    interpreter.add_option(parser)
    args = parser.parse_args()
    interpreter.run_on(args.python)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        if args.only in (None, "lookup"):
            for tree in (args.tree,) if args.tree else TREES:
                bench_lookup(folder, args.rounds, args.lookups, tree)
        if args.only in (None, "listener", "latency"):
            master_process, master = start_master()
            try:
                if args.only in (None, "listener"):
                    bench_listener(folder, args.seconds, master)
                if args.only in (None, "latency"):
                    bench_latency(
                        folder,
                        args.messages,
                        master,
                        args.rounds,
                        args.poll,
                        args.way or list(WAYS),
                    )
            finally:
                master_process.terminate()
                master_process.wait()


if __name__ == "__main__":
    main()
