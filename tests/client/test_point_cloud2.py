"""``sensor_msgs.point_cloud2``, as scripts import it: clouds built and read as ROS 1's helper
builds and reads them, byte for byte."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from rosx.client import point_cloud2
from rosx.msg.codec.classes import get_message_class
from tests.support.cli import clean_environ
from tests.support.ros1 import needs_ros1, ros1_python_with_path

Header = get_message_class("std_msgs/Header")
PointField = get_message_class("sensor_msgs/PointField")

#: ROS 1's create_cloud_xyz32 of (1, 2, 3) and (4, 5, NaN): little-endian FLOAT32s.
XYZ_BYTES = "0000803f0000004000004040000080400000a0400000c07f"


def run_script(script: Path) -> object:
    """Run ``script`` as ``rosx rosrun`` runs one; the JSON it prints."""
    done = subprocess.run(
        [sys.executable, "-m", "rosx_commands", "run-script", str(script)],
        env=clean_environ(),
        cwd=script.parent,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_create_cloud_xyz32_is_an_unorganized_little_endian_cloud() -> None:
    cloud = point_cloud2.create_cloud_xyz32(Header(frame_id="map"), [(1, 2, 3), (4, 5, math.nan)])
    assert cloud._type == "sensor_msgs/PointCloud2"
    assert (cloud.height, cloud.width, cloud.point_step, cloud.row_step) == (1, 2, 12, 24)
    assert (cloud.is_bigendian, cloud.is_dense, cloud.header.frame_id) == (False, False, "map")
    assert [(f.name, f.offset, f.datatype, f.count) for f in cloud.fields] == [
        ("x", 0, 7, 1),
        ("y", 4, 7, 1),
        ("z", 8, 7, 1),
    ]
    assert bytes(cloud.data).hex() == XYZ_BYTES


def test_read_points_chooses_fields_skips_nans_and_reads_chosen_places() -> None:
    fields = [PointField("x", 0, 7, 1), PointField("i", 8, 5, 1), PointField("rgb", 12, 2, 3)]
    points = [(0.5, -1, 1, 2, 3), (math.nan, 7, 4, 5, 6), (2.5, 9, 7, 8, 9)]
    cloud = point_cloud2.create_cloud(Header(), fields, points)
    assert cloud.point_step == 15  # x, 4 pad bytes, i, three UINT8s
    read = list(point_cloud2.read_points(cloud))
    assert [r[1:] for r in read] == [p[1:] for p in points]
    assert math.isnan(read[1][0])
    assert list(point_cloud2.read_points(cloud, skip_nans=True)) == [points[0], points[2]]
    assert list(point_cloud2.read_points(cloud, field_names=("i",))) == [(-1,), (7,), (9,)]
    assert list(point_cloud2.read_points(cloud, uvs=[(2, 0), (0, 0)])) == [points[2], points[0]]
    named = point_cloud2.read_points_list(cloud, field_names=["x", "i"], skip_nans=True)
    assert [(p.x, p.i) for p in named] == [(0.5, -1), (2.5, 9)]
    assert type(named[0]).__name__ == "Point"


def test_read_points_refuses_what_is_not_a_cloud() -> None:
    with pytest.raises(AssertionError):
        list(point_cloud2.read_points(Header()))


def test_scripts_import_it_beside_sensor_msgs_msg(tmp_path: Path) -> None:
    script = tmp_path / "script.py"
    script.write_text(
        "import json\n"
        "from sensor_msgs import point_cloud2\n"
        "import sensor_msgs.point_cloud2 as pc2\n"
        "from std_msgs.msg import Header\n"
        "cloud = pc2.create_cloud_xyz32(Header(), [(1, 2, 3)])\n"
        "print(json.dumps([point_cloud2 is pc2, pc2.__name__, cloud.data.hex(),\n"
        "                  [list(p) for p in point_cloud2.read_points(cloud)]]))\n"
    )
    assert run_script(script) == [
        True,
        "sensor_msgs.point_cloud2",
        XYZ_BYTES[:24],
        [[1.0, 2.0, 3.0]],
    ]


BUILD = """
import json, math
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointField
from std_msgs.msg import Header
fields = [PointField('x', 0, 7, 1), PointField('n', 6, 3, 2), PointField('d', 12, 8, 1),
          PointField('u', 20, 6, 1), PointField('b', 24, 1, 1)]
points = [(0.25, -3, 4, 1e300, 4000000000, -7), (float('nan'), 1, 2, -0.5, 0, 127)]
cloud = point_cloud2.create_cloud(Header(), fields, points)
print(json.dumps([bytes(cloud.data).hex(), cloud.point_step, cloud.row_step,
                  [list(p) for p in point_cloud2.read_points(cloud, skip_nans=True)],
                  [list(p) for p in point_cloud2.read_points(cloud, field_names=('u', 'n'))]]))
"""


@needs_ros1
def test_clouds_match_ros1s_helper(tmp_path: Path) -> None:
    ros1 = ros1_python_with_path(BUILD, [], tmp_path)
    assert ros1.returncode == 0, ros1.stderr
    script = tmp_path / "build.py"
    script.write_text(BUILD)
    assert run_script(script) == json.loads(ros1.stdout)
