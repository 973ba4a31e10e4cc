"""Message codec speed, rosx against genpy (ROS 1's generated Python classes) in the same run.

Each side runs in its own interpreter: genpy under ``/usr/bin/python3`` (Debian's ROS 1 packages;
override with ``ROS1_PYTHON``), rosx under this Python and, for a ratio free of interpreter
differences, under ROS 1's Python too (given this environment's site-packages). Every case
builds the same message, then times ``serialize`` into a fresh ``io.BytesIO`` (as rospy does
per publish) and ``Class().deserialize(data)`` (as rospy does per received message). Prints
microseconds per operation for both sides and rosx's speed-up (genpy time / rosx time; above 1
is faster).

    python bench/bench_codec.py [--seconds 0.5]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import sysconfig
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Runs in either interpreter; `load(name)` is defined by the side's prelude.
_CASES = r"""
import io, json, sys, time

def build(name):
    if name == "geometry_msgs/Twist":
        m = load(name)()
        m.linear.x, m.linear.y, m.angular.z = 1.5, -2.0, 0.25
        return m
    if name == "geometry_msgs/PoseStamped":
        m = load(name)()
        m.header.seq, m.header.frame_id = 7, "map"
        m.header.stamp.secs, m.header.stamp.nsecs = 1700000000, 5
        m.pose.position.x, m.pose.orientation.w = 1.0, 1.0
        return m
    if name == "sensor_msgs/LaserScan":
        m = load(name)()
        m.header.frame_id = "laser"
        m.ranges = [float(i % 50) / 4 for i in range(720)]
        m.intensities = [1.0] * 720
        return m
    if name == "sensor_msgs/Image":
        m = load(name)()
        m.header.frame_id = "camera"
        m.height, m.width, m.step, m.encoding = 512, 2048, 2048, "mono8"
        m.data = bytes(range(256)) * 4096
        return m
    raise KeyError(name)

def timeit(fn, seconds):
    n, elapsed = 1, 0.0
    while elapsed < seconds / 5:
        start = time.perf_counter()
        for _ in range(n):
            fn()
        elapsed = time.perf_counter() - start
        n *= 2
    n //= 2
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(n):
            fn()
        best = min(best, (time.perf_counter() - start) / n)
    return best

def run(names, seconds):
    out = {}
    for name in names:
        msg = build(name)
        cls = type(msg)
        def ser():
            b = io.BytesIO()
            msg.serialize(b)
            return b.getvalue()
        data = ser()
        def de():
            return cls().deserialize(data)
        assert de() == msg
        out[name] = {"ser": timeit(ser, seconds), "de": timeit(de, seconds), "size": len(data)}
    return out

names, seconds = json.loads(sys.argv[1])
figures = run(names, seconds)
block = bytearray(1 << 20)
figures["memcpy"] = {"copy": timeit(lambda: bytes(block), seconds), "size": len(block)}
print(json.dumps(figures))
"""

_ROSX_PRELUDE = r"""
import sys
sys.path.insert(0, {root!r})
sys.path.append({site!r})  # rosx's dependencies, when run by another interpreter
from rosx.msg.codec.classes import get_message_class as load
"""

_GENPY_PRELUDE = r"""
import importlib
def load(name):
    package, _, short = name.partition("/")
    return getattr(importlib.import_module(package + ".msg"), short)
"""

CASES = [
    "geometry_msgs/Twist",
    "geometry_msgs/PoseStamped",
    "sensor_msgs/LaserScan",
    "sensor_msgs/Image",
]


def _side(python: str, prelude: str, seconds: float) -> dict[str, dict[str, float]]:
    code = prelude + _CASES
    result = subprocess.run(
        [python, "-c", code, json.dumps([CASES, seconds])],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    )
    figures: dict[str, dict[str, float]] = json.loads(result.stdout)
    return figures


def _try_side(python: str, prelude: str, seconds: float) -> dict[str, dict[str, float]]:
    try:
        return _side(python, prelude, seconds)
    except (OSError, subprocess.CalledProcessError) as exc:
        print(f"{python}: unavailable ({exc})", file=sys.stderr)
        return {}


def _table(
    title: str, rosx: dict[str, dict[str, float]], genpy: dict[str, dict[str, float]]
) -> None:
    print(title)
    print(
        f"  {'message':28} {'op':4} {'bytes':>8} {'rosx µs':>10} {'genpy µs':>10} {'speed-up':>9}"
    )
    for name in CASES:
        for op in ("ser", "de"):
            mine = rosx[name][op] * 1e6
            theirs = genpy.get(name, {}).get(op)
            ref = f"{theirs * 1e6:10.2f}" if theirs else f"{'-':>10}"
            ratio = f"{theirs * 1e6 / mine:8.2f}x" if theirs else f"{'-':>9}"
            size = int(rosx[name]["size"])
            print(f"  {name:28} {op:4} {size:8d} {mine:10.2f} {ref} {ratio}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=0.5, help="time per measurement")
    args = parser.parse_args()
    ros1 = os.environ.get("ROS1_PYTHON", "/usr/bin/python3")
    prelude = _ROSX_PRELUDE.format(root=str(ROOT), site=sysconfig.get_paths()["purelib"])
    rosx = _side(sys.executable, prelude, args.seconds)
    genpy = _try_side(ros1, _GENPY_PRELUDE, args.seconds)
    # Interpreters differ in speed by themselves; the fair ratio runs both under ROS 1's.
    rosx_there = _try_side(ros1, prelude, args.seconds) if genpy else {}
    if rosx_there:
        _table(f"same interpreter ({ros1}):", rosx_there, genpy)
    _table(f"rosx under {sys.executable}, genpy under {ros1}:", rosx, genpy)
    image = rosx["sensor_msgs/Image"]
    round_trip = image["ser"] + image["de"]
    copy = rosx["memcpy"]
    speed = image["size"] / round_trip / 2**30
    print(
        f"Image round trip (serialize + deserialize, this Python): {speed:.2f} GiB/s,"
        f" {round_trip / copy['copy']:.1f} x the time of one 1 MiB bytes copy"
        f" ({copy['size'] / copy['copy'] / 2**30:.1f} GiB/s)"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
