"""``tf_conversions`` in the scripts rosx runs, as the tf2 tutorials' Python broadcaster uses it
(``tf_conversions.transformations.quaternion_from_euler(0, 0, msg.theta)``); its PyKDL half
(``posemath``) says what to use instead rather than failing on a missing module."""

from __future__ import annotations

from pathlib import Path

from tests.support.cli import rosx
from tests.support.scripts import json_of, run_script

SCRIPT = """
import json
import tf
import tf_conversions
q = tf_conversions.transformations.quaternion_from_euler(0, 0, 1.25)
said = []
try:
    tf_conversions.fromMsg
except AttributeError as e:
    said.append(str(e))
try:
    import tf_conversions.posemath
except ImportError as e:
    said.append(str(e))
print(json.dumps({
    "q": [float(v) for v in q],
    "same": tf_conversions.transformations is tf.transformations,
    "said": said,
}))
"""


def test_the_tutorials_broadcaster_gets_its_quaternion(tmp_path: Path) -> None:
    result = json_of(run_script(tmp_path, SCRIPT))
    assert result["q"] == [0.0, 0.0, 0.5850972729404622, 0.8109631195052179]  # Debian python3-tf's
    assert result["same"] is True
    pykdl = (
        "works on PyKDL frames, which rosx does not provide; tf.transformations (also "
        "tf_conversions.transformations) does the same arithmetic on 4x4 matrices, and "
        "tf2_geometry_msgs transforms points and poses"
    )
    assert result["said"] == [f"tf_conversions.fromMsg {pykdl}", f"tf_conversions.posemath {pykdl}"]


def test_rospack_finds_the_package() -> None:
    found = rosx("rospack", "find", "tf_conversions")
    assert found.status == 0
    assert found.out.rstrip().endswith("/share/tf_conversions")
