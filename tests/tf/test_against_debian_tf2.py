"""One script, two tf2s: Debian's python3-tf2-ros (C++ core) and rosx's, on the same inputs.

The script fills a buffer (moving and static frames, rotations, two trees), then prints as JSON
every lookup's numbers (as ``repr``, so equal means equal to the bit), every exception's class
and text, ``can_transform`` answers, the chains, the latest common times and the frames as
YAML, text and dot. rosx runs it under ``rosx run-script`` with its ``tf2_ros`` shim.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.support.ros1 import ros1_environ, ros1_python_imports

needs_tf2 = pytest.mark.skipif(
    not ros1_python_imports("tf2_ros", "rospy"), reason="Debian's python3-tf2-ros is absent"
)

SCRIPT = r"""
import json, math, sys
import rospy
import tf2_ros, tf2_py
from geometry_msgs.msg import TransformStamped

out = {}

def ts(parent, child, secs, nsecs, x, y, z, roll, pitch, yaw):
    t = TransformStamped()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.header.stamp = rospy.Time(secs, nsecs)
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = x, y, z
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    q = t.transform.rotation
    q.x = sr * cp * cy - cr * sp * sy
    q.y = cr * sp * cy + sr * cp * sy
    q.z = cr * cp * sy - sr * sp * cy
    q.w = cr * cp * cy + sr * sp * sy
    return t

def flat(t):
    tr, r = t.transform.translation, t.transform.rotation
    return [t.header.frame_id, t.child_frame_id, t.header.stamp.secs, t.header.stamp.nsecs,
            repr(tr.x), repr(tr.y), repr(tr.z), repr(r.x), repr(r.y), repr(r.z), repr(r.w)]

def attempt(name, f):
    try:
        value = f()
        out[name] = flat(value) if hasattr(value, "transform") else value
    except Exception as e:
        out[name] = [type(e).__module__ + "." + type(e).__name__, str(e)]

b = tf2_ros.Buffer(rospy.Duration(10), debug=False)
out["empty_yaml"] = b.all_frames_as_yaml()
out["empty_dot"] = b._allFramesAsDot()
# A moving arm: base -> shoulder -> elbow -> hand, with odom -> base moving; a sensor static.
for k in range(30):
    s, ns = 100 + k // 10, (k % 10) * 100000000
    b.set_transform(ts("odom", "base", s, ns, 0.1 * k, 0.05 * k, 0.0, 0, 0, 0.03 * k), "/driver")
    b.set_transform(ts("base", "shoulder", s, ns, 0.0, 0.0, 0.5, 0.0, 0.02 * k, 0.0), "/arm")
    b.set_transform(ts("shoulder", "elbow", s, ns, 0.3, 0.0, 0.0, 0.01 * k, -0.7, 0.2), "/arm")
    b.set_transform(ts("elbow", "hand", s, ns, 0.25, 0.01, 0.0, 0.0, 0.0, -0.04 * k), "/arm")
b.set_transform_static(ts("base", "laser", 0, 0, 0.2, 0.0, 0.3, 0.0, 0.0, math.pi), "/static")
b.set_transform_static(ts("laser", "optical", 0, 0, 0.0, 0.0, 0.0, -math.pi / 2, 0, -math.pi / 2), "/static")
# A second tree; one frame with a single transform; one very far in the future.
b.set_transform(ts("island", "palm", 50, 0, 1, 2, 3, 0.1, 0.2, 0.3), "/elsewhere")
b.set_transform(ts("odom", "lonely", 101, 500000000, 1, 0, 0, 0, 0, 1), "/one")
b.set_transform(ts("odom", "beacon", 1700000000, 123456789, 4, 5, 6, 0, 0, 0), "/far")

times = [rospy.Time(), rospy.Time(101, 250000000), rospy.Time(100, 0), rospy.Time(102, 900000000),
         rospy.Time(101, 123456789), rospy.Time(103, 0), rospy.Time(99, 0)]
pairs = [("odom", "hand"), ("hand", "odom"), ("hand", "laser"), ("optical", "hand"),
         ("shoulder", "elbow"), ("elbow", "shoulder"), ("odom", "odom"), ("laser", "laser"),
         ("base", "optical"), ("lonely", "hand"), ("hand", "lonely"), ("palm", "hand"),
         ("hand", "palm"), ("ghost", "hand"), ("hand", "ghost"), ("", "hand"), ("hand", ""),
         ("/odom", "hand"), ("hand", "/odom"), ("beacon", "base"), ("island", "palm")]
for target, source in pairs:
    for i, t in enumerate(times):
        key = f"{target}<-{source}@{i}"
        attempt("lookup " + key, lambda: b.lookup_transform(target, source, t))
        attempt("can " + key, lambda: list(b.can_transform_core(target, source, t)))
        attempt("can_transform " + key, lambda: b.can_transform(target, source, t))
for args in [("hand", rospy.Time(101), "laser", rospy.Time(102), "odom"),
             ("hand", rospy.Time(), "hand", rospy.Time(101, 5), "odom"),
             ("optical", rospy.Time(100, 50), "elbow", rospy.Time(102, 50), "base"),
             ("hand", rospy.Time(101), "palm", rospy.Time(102), "odom"),
             ("hand", rospy.Time(101), "elbow", rospy.Time(102), "ghost"),
             ("ghost", rospy.Time(101), "elbow", rospy.Time(102), "odom"),
             ("hand", rospy.Time(101), "elbow", rospy.Time(150), "odom")]:
    key = "/".join(str(a) for a in args)
    attempt("full " + key, lambda: b.lookup_transform_full(*args))
    attempt("canfull " + key, lambda: list(b.can_transform_full_core(*args)))
    attempt("chain " + key, lambda: b._chain(*args))
for target, source in [("odom", "hand"), ("hand", "optical"), ("palm", "hand"), ("lonely", "hand"),
                       ("hand", "hand"), ("ghost", "hand"), ("laser", "optical")]:
    attempt(f"common {target} {source}",
            lambda: [b.get_latest_common_time(target, source).secs, b.get_latest_common_time(target, source).nsecs])
attempt("exists", lambda: [b._frameExists("hand"), b._frameExists("ghost"), b._frameExists("odom")])
attempt("frames", lambda: sorted(b._getFrameStrings()))
out["yaml"] = b.all_frames_as_yaml()
out["string"] = b.all_frames_as_string()
out["dot"] = b._allFramesAsDot()
out["dot_at"] = b._allFramesAsDot(rospy.Time(200, 500000000))
attempt("bad time", lambda: b.lookup_transform("odom", "hand", 5))
b.clear()
out["cleared_yaml"] = b.all_frames_as_yaml()
out["cleared_string"] = b.all_frames_as_string()
out["cleared_dot"] = b._allFramesAsDot(rospy.Time(200))
attempt("after clear", lambda: b.lookup_transform("odom", "hand", rospy.Time()))
attempt("static after clear", lambda: b.lookup_transform("base", "optical", rospy.Time(5)))
print(json.dumps(out))
"""


# A robot's tree moving in every axis, looked up at many past times (each its own time, as a
# message filter asks); then a frame given a new parent, a static frame sent again under
# another, a clear: what rosx keeps between lookups must follow each change.
DEEP = r"""
import json, math, random
import rospy, tf2_ros
from geometry_msgs.msg import TransformStamped

tree = [("odom", "map"), ("base", "odom"), ("torso", "base"), ("head", "torso"),
        ("camera", "head"), ("laser", "base"), ("imu", "base")]
for side in ("left", "right"):
    tree += [(side + "_1", "torso")] + [(side + "_%d" % i, side + "_%d" % (i - 1)) for i in range(2, 8)]
tree += [("wheel_l", "base"), ("wheel_r", "base"), ("cup", "left_7")]
static = {"laser": "base", "imu": "base", "camera": "head"}
rng = random.Random(30)
out = {}

def ts(parent, child, stamp, k, i):
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id, t.header.stamp = parent, child, stamp
    a = 0.013 * k + 0.7 * i
    t.transform.translation.x = 0.1 * i - 0.3 * math.sin(a)
    t.transform.translation.y = math.sin(a) if i % 3 else 0.0
    t.transform.translation.z = -0.0 if i % 4 == 0 else 0.2 * math.cos(3 * a)
    half = 0.5 * (a if i % 2 else -2.5 * a)
    x, y, z = (math.sin(i), math.cos(i) * 0.5, 0.0 if i % 5 == 0 else 0.3)
    n = math.sqrt(x * x + y * y + z * z)
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = (math.sin(half) * x / n, math.sin(half) * y / n,
                          math.sin(half) * z / n, math.cos(half))
    return t

def flat(t):
    tr, r = t.transform.translation, t.transform.rotation
    return [t.header.stamp.secs, t.header.stamp.nsecs, repr(tr.x), repr(tr.y), repr(tr.z),
            repr(r.x), repr(r.y), repr(r.z), repr(r.w)]

def look(name, target, source, when):
    try:
        out[name] = flat(b.lookup_transform(target, source, when))
    except tf2_ros.TransformException as e:
        out[name] = [type(e).__name__, str(e)]

b = tf2_ros.Buffer(rospy.Duration(10), debug=False)
for i, (child, parent) in enumerate(tree):
    if child in static:
        t = ts(parent, child, rospy.Time(0), 0, i)
        b.set_transform_static(t, "/static")
for k in range(200):  # 2 s at 100 Hz, a little jitter
    for i, (child, parent) in enumerate(tree):
        if child not in static and not (child == "wheel_r" and k > 120):  # one stops early
            stamp = rospy.Time(100, 0) + rospy.Duration(0, 10000000 * k + 37 * (i % 7))
            b.set_transform(ts(parent, child, stamp, k, i), "/robot")
frames = ["map"] + [c for c, _ in tree]

def sweep(tag, count):
    for n in range(count):
        target, source = rng.sample(frames, 2)
        when = rospy.Time(100, 0) + rospy.Duration(0, rng.randrange(-20000000, 2020000000))
        look("%s %d %s<-%s@%s" % (tag, n, target, source, when), target, source, when)
    # at stamps, between, after the data; each pair twice at a time (the second as a view asks)
    for target, source in (("left_7", "right_6"), ("map", "cup"), ("cup", "base"),
                           ("wheel_r", "camera"), ("laser", "right_3")):
        for n, when in enumerate([rospy.Time(100, 0), rospy.Time(100, 10000037),
                                  rospy.Time(101, 990000000), rospy.Time(101, 990000001),
                                  rospy.Time(101, 210000000), rospy.Time(102, 300000000)]):
            look("%s at %d %s<-%s" % (tag, n, target, source), target, source, when)
            look("%s again %d %s<-%s" % (tag, n, source, target), source, target, when)

sweep("first", 600)
# the cup moves from the left hand to the right, and stays there
for k in range(200, 260):
    stamp = rospy.Time(100, 0) + rospy.Duration(0, 10000000 * k)
    for i, (child, parent) in enumerate(tree):
        if child not in static and child != "wheel_r":
            b.set_transform(ts("right_7" if child == "cup" else parent, child, stamp, k, i), "/robot")
sweep("moved", 300)
# the camera now sits on the torso; then the laser a little further forward
b.set_transform_static(ts("torso", "camera", rospy.Time(0), 5, 5), "/static")
sweep("restatic", 200)
b.set_transform_static(ts("base", "laser", rospy.Time(0), 9, 9), "/static")
sweep("laser", 20)
b.clear()
sweep("cleared", 20)
print(json.dumps(out))
"""


def _rosx(script: Path, tmp: Path) -> Any:
    env = {k: v for k, v in ros1_environ().items() if k != "ROS_PACKAGE_PATH"}
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "run-script", str(script)],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _debian(script: Path, tmp: Path) -> Any:
    done = subprocess.run(
        ["/usr/bin/python3", str(script)],
        capture_output=True,
        text=True,
        env=ros1_environ(),
        cwd=tmp,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@needs_tf2
def test_the_same_script_gives_the_same_numbers_and_texts(tmp_path: Path) -> None:
    script = tmp_path / "scenario.py"
    script.write_text(SCRIPT)
    theirs = _debian(script, tmp_path)
    ours = _rosx(script, tmp_path)
    assert ours.keys() == theirs.keys()
    different = {k: (ours[k], theirs[k]) for k in theirs if ours[k] != theirs[k]}
    assert different == {}


@needs_tf2
def test_lookups_at_past_times_on_a_robot_tree_are_tf2s_to_the_bit(tmp_path: Path) -> None:
    script = tmp_path / "deep.py"
    script.write_text(DEEP)
    theirs = _debian(script, tmp_path)
    ours = _rosx(script, tmp_path)
    assert ours.keys() == theirs.keys()
    different = {k: (ours[k], theirs[k]) for k in theirs if ours[k] != theirs[k]}
    assert different == {}
    # most lookups found a transform, some failed (before the data, after a frame stopped)
    assert sum(len(v) == 9 for v in theirs.values()) > 1000
    assert sum(v[0] == "ExtrapolationException" for v in theirs.values()) > 50
    # the cup, under the right hand after it moved, is found where it was not before
    assert theirs["first at 5 map<-cup"][0] == "ExtrapolationException"
    assert len(theirs["moved at 5 map<-cup"]) == 9
