"""One script, two ``tf``s (and ``tf2_geometry_msgs``): Debian's python3-tf and rosx's.

The script fills a ``tf.Transformer`` and a ``tf2_ros.Buffer``, then prints as JSON what tf's
old API answers (``lookupTransform`` with leading slashes, ``canTransform``, ``chain``,
``getLatestCommonTime``, ``transformPoint``/``Vector3``/``Quaternion``/``Pose``, ``asMatrix``,
``getFrameStrings``, the exceptions, ``tf.Exception`` being tf2's ``TransformException``) and
what ``buffer.transform()`` and ``do_transform_*`` give for geometry_msgs' stamped types.
Numbers must equal Debian's to 1e-12 (tf's matrices are numpy's, KDL's are C++'s; the
arithmetic is the same, the last bits may differ).
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from tests.support.ros1 import ros1_environ, ros1_python_imports

pytestmark = pytest.mark.skipif(
    not ros1_python_imports("tf", "tf2_geometry_msgs", "tf2_ros"), reason="no python3-tf"
)

SCRIPT = r"""
import json, math, sys
import rospy, tf, tf2_ros, tf2_geometry_msgs
from geometry_msgs.msg import (TransformStamped, PointStamped, Vector3Stamped, PoseStamped,
                               QuaternionStamped, WrenchStamped)

out = {}

def ts(parent, child, secs, x, y, z, roll, pitch, yaw):
    t = TransformStamped()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.header.stamp = rospy.Time(secs)
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = x, y, z
    q = tf.transformations.quaternion_from_euler(roll, pitch, yaw)
    t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w = q
    return t

def plain(v):
    if hasattr(v, "tolist"):
        return v.tolist()
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if hasattr(v, "secs"):
        return [v.secs, v.nsecs]
    if hasattr(v, "__slots__"):
        return {k: plain(getattr(v, k)) for k in v.__slots__ if k != "header"}
    return v

def attempt(name, f):
    try:
        out[name] = plain(f())
    except Exception as e:
        out[name] = ["raised", type(e).__module__ + "." + type(e).__name__, str(e),
                     isinstance(e, tf.Exception)]

t = tf.TransformerROS(True, rospy.Duration(10))
for k in range(5):
    t.setTransform(ts("world", "base", 10 + k, 1 + k, 2, 0, 0, 0, 0.1 * k), "/a")
    t.setTransform(ts("base", "arm", 10 + k, 0.5, 0, 0.3, 0.2, -0.1 * k, 0), "/b")
t.setTransform(ts("world", "other", 12, 0, 0, 1, 0, 0, 0), "/c")
at = rospy.Time(12, 500000000)
attempt("lookup", lambda: t.lookupTransform("/world", "/arm", at))
attempt("lookup latest", lambda: t.lookupTransform("arm", "world", rospy.Time()))
attempt("lookup full", lambda: t.lookupTransformFull("arm", rospy.Time(11), "arm", rospy.Time(13), "world"))
attempt("lookup missing", lambda: t.lookupTransform("world", "ghost", at))
attempt("lookup future", lambda: t.lookupTransform("world", "arm", rospy.Time(30)))
attempt("can", lambda: [t.canTransform("world", "arm", at), t.canTransform("world", "ghost", at)])
attempt("chain", lambda: t.chain("arm", at, "other", rospy.Time(12), "world"))
attempt("common", lambda: t.getLatestCommonTime("arm", "other"))
attempt("frames", lambda: sorted(t.getFrameStrings()))
attempt("exists", lambda: [t.frameExists("arm"), t.frameExists("ghost")])
attempt("prefix", lambda: t.getTFPrefix())
attempt("wait", lambda: t.waitForTransform("world", "arm", at, rospy.Duration(0.1)))
hdr = PointStamped().header
hdr.frame_id, hdr.stamp = "arm", at
attempt("matrix", lambda: t.asMatrix("world", hdr))
attempt("from", lambda: t.fromTranslationRotation((1, 2, 3), (0, 0, math.sin(0.3), math.cos(0.3))))
p = PointStamped(); p.header = hdr; p.point.x, p.point.y, p.point.z = 0.3, -0.2, 0.1
attempt("point", lambda: t.transformPoint("world", p))
v = Vector3Stamped(); v.header = hdr; v.vector.x, v.vector.y, v.vector.z = 1.0, 0.5, -0.25
attempt("vector", lambda: t.transformVector3("world", v))
q = QuaternionStamped(); q.header = hdr; q.quaternion.z, q.quaternion.w = math.sin(0.2), math.cos(0.2)
attempt("quaternion", lambda: t.transformQuaternion("world", q))
pose = PoseStamped(); pose.header = hdr; pose.pose.position.x = 1.5
pose.pose.orientation.x, pose.pose.orientation.w = math.sin(0.4), math.cos(0.4)
attempt("pose", lambda: t.transformPose("world", pose))

b = tf2_ros.Buffer(rospy.Duration(10), debug=False)
for k in range(5):
    b.set_transform(ts("world", "base", 10 + k, 1 + k, 2, 0, 0, 0, 0.1 * k), "/a")
    b.set_transform(ts("base", "arm", 10 + k, 0.5, 0, 0.3, 0.2, -0.1 * k, 0), "/b")
w = WrenchStamped(); w.header = hdr; w.wrench.force.x, w.wrench.torque.z = 2.0, -1.0
for name, value in (("point", p), ("vector", v), ("pose", pose), ("wrench", w)):
    attempt("transform " + name, lambda: b.transform(value, "world"))
attempt("transform quaternion", lambda: b.transform(q, "world"))
tr = b.lookup_transform("world", "arm", at)
attempt("do point", lambda: tf2_geometry_msgs.do_transform_point(p, tr))
attempt("do pose", lambda: tf2_geometry_msgs.do_transform_pose(pose, tr))
attempt("exception classes", lambda: [tf.Exception is tf2_ros.TransformException,
                                      issubclass(tf.LookupException, tf.Exception)])
print(json.dumps(out))
"""


def _run(command: list[str], env: dict[str, str], cwd: Path) -> Any:
    done = subprocess.run(
        command, env=env, cwd=cwd, capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _close(a: Any, b: Any, path: str, out: list[str]) -> None:
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            out.append(f"{path}: keys {sorted(a)} != {sorted(b)}")
        for key in a.keys() & b.keys():
            _close(a[key], b[key], f"{path}.{key}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {a} != {b}")
            return
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, f"{path}[{i}]", out)
    elif isinstance(a, float) and isinstance(b, (int, float)) and not isinstance(b, bool):
        if not math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-12):
            out.append(f"{path}: {a!r} != {b!r}")
    elif a != b:
        out.append(f"{path}: {a!r} != {b!r}")


def test_tfs_api_and_tf2_geometry_msgs_answer_as_debians(tmp_path: Path) -> None:
    script = tmp_path / "scenario.py"
    script.write_text(SCRIPT)
    theirs = _run(["/usr/bin/python3", str(script)], ros1_environ(), tmp_path)
    environ = {k: v for k, v in ros1_environ().items() if k != "ROS_PACKAGE_PATH"}
    ours = _run(
        [sys.executable, "-m", "rosx_commands", "run-script", str(script)], environ, tmp_path
    )
    different: list[str] = []
    _close(ours, theirs, "", different)
    assert different == []
