"""How scripts get ``rospy`` and ``<package>.msg``: ``rosx run-script`` and the shim directory.

Each script runs in a child process, as ``rosx rosrun`` runs it, so that the import finders and
``sys.modules`` of this test session stay untouched.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from rosx.client.script import SHIM_DIR
from rosx.master.client import MasterClient
from rosx_commands.scripts import shim_dirs
from tests.support.cli import clean_environ
from tests.support.ros1 import needs_ros1, ros1_python, ros1_python_imports, ros1_python_with_path
from tests.support.scripts import json_of, run_script, script_command, start_script

NUM_PACKAGE = """\
<?xml version="1.0"?>
<package format="2">
  <name>lab2</name>
  <version>0.0.0</version>
  <description>The lab2 package</description>
  <maintainer email="me@todo.todo">me</maintainer>
  <license>TODO</license>
</package>
"""


def test_scripts_import_rospy_and_message_modules_laid_out_as_genpy(tmp_path: Path) -> None:
    done = run_script(
        tmp_path,
        """\
import json, sys
from geometry_msgs.msg import *
from geometry_msgs.msg import Twist
import rospy
import std_msgs.msg
from std_srvs.srv import Empty, EmptyRequest, EmptyResponse
from turtlesim.msg import Pose
import geometry_msgs.msg._Vector3 as vector_module
from rosx.msg.codec.classes import get_message_class
print(json.dumps({
    "rospy": rospy.__file__,
    "same_class": Twist is get_message_class("geometry_msgs/Twist"),
    "string": std_msgs.msg.String._type,
    "empty": [Empty._type, EmptyRequest._type, EmptyResponse._type],
    "pose": Pose._md5sum,
    "star": "Vector3" in dir(),
    "module": vector_module.Vector3._type,
    "main": __name__, "argv": sys.argv[1:], "myargv": rospy.myargv()[1:],
}))
""",
        "a",
        "b:=c",
        "_p:=1",
    )
    found = json_of(done)
    assert found["rospy"] == str(SHIM_DIR / "rospy" / "__init__.py")
    assert found["same_class"] and found["star"]
    assert found["string"] == "std_msgs/String"
    assert found["empty"] == ["std_srvs/Empty", "std_srvs/EmptyRequest", "std_srvs/EmptyResponse"]
    assert found["pose"] == "863b248d5016ca62ea2e895ae5265cf9"
    assert found["module"] == "geometry_msgs/Vector3"
    assert found["main"] == "__main__"
    assert found["argv"] == ["a", "b:=c", "_p:=1"] and found["myargv"] == ["a"]


def test_the_types_of_packages_on_the_package_path_import_too(tmp_path: Path) -> None:
    package = tmp_path / "src" / "lab2"
    (package / "msg").mkdir(parents=True)
    (package / "srv").mkdir()
    (package / "package.xml").write_text(NUM_PACKAGE)
    (package / "msg" / "Num.msg").write_text("int64 num\n")
    (package / "srv" / "AddTwoInts.srv").write_text("int64 a\nint64 b\n---\nint64 sum\n")
    done = run_script(
        tmp_path,
        """\
import json
import rospy
from lab2.msg import Num
from lab2.srv import AddTwoInts, AddTwoIntsRequest, AddTwoIntsResponse
print(json.dumps([Num._md5sum, AddTwoInts._md5sum, AddTwoIntsRequest(a=1, b=2).b]))
""",
        ROS_PACKAGE_PATH=str(tmp_path / "src"),
    )
    # The md5 sums of ROS 1's beginner_tutorials types of the same definitions.
    assert json_of(done) == [
        "57d3c40ec3ac3754af76a83e6e73127a",
        "6a2e34150c00229791cc89ff309fff21",
        2,
    ]


def test_a_syntax_error_names_the_file_and_the_line(tmp_path: Path) -> None:
    done = run_script(tmp_path, "import rospy\ndef main//.\n    pass\n")
    assert done.returncode == 1
    assert f'File "{tmp_path / "script.py"}", line 2' in done.stderr
    assert "\nSyntaxError: " in done.stderr  # the wording is Python's own
    assert "Traceback" not in done.stderr and done.stdout == ""


def test_an_exception_shows_the_scripts_frames_only(tmp_path: Path) -> None:
    done = run_script(tmp_path, "import rospy\n\ndef main():\n    rospy.init_nod('x')\n\nmain()\n")
    assert done.returncode == 1
    lines = done.stderr.splitlines()
    assert lines[0] == "Traceback (most recent call last):"
    assert "rosx" not in "".join(line for line in lines if line.startswith("  File"))
    assert f'  File "{tmp_path / "script.py"}", line 4, in main' in lines
    assert lines[-1].startswith("AttributeError:") and "init_nod" in lines[-1]


def test_a_missing_script_is_reported_as_python_does(tmp_path: Path) -> None:
    done = subprocess.run(
        script_command(tmp_path / "none.py"),
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 2
    assert done.stderr == (
        f"rosx run-script: can't open file '{tmp_path / 'none.py'}': "
        "[Errno 2] No such file or directory\n"
    )


def test_ctrl_c_before_init_node_ends_quietly(tmp_path: Path) -> None:
    script = tmp_path / "wait.py"
    script.write_text("import time, rospy\nprint('ready', flush=True)\ntime.sleep(60)\n")
    process = start_script(script)
    try:
        assert process.stdout is not None and process.stdout.readline() == "ready\n"
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=10)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 130
    assert err == ""


def test_init_node_waits_for_the_master_as_rospy_does(tmp_path: Path) -> None:
    script = tmp_path / "node.py"
    script.write_text("import rospy\nrospy.init_node('early')\n")
    uri = "http://127.0.0.1:9/"
    process = start_script(script, ROS_MASTER_URI=uri)
    try:
        assert process.stderr is not None
        line = process.stderr.readline()  # printed with the signal handlers in place
        process.send_signal(signal.SIGINT)
        _, rest = process.communicate(timeout=10)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert rest == ""  # stopping a script that waits for the master is not an error
    assert line.startswith("[ERROR] [")
    assert line.endswith(
        f"]: Unable to immediately register with master node [{uri}]: "
        "master may not be running yet. Will keep trying.\n"
    )
    assert process.returncode == 0


HELD_WHEN_SIGNALLED = """\
import os, signal, threading, time
import rospy
rospy.init_node('held')
with threading._shutdown_locks_lock:  # what joining a finished thread holds, for a moment
    os.kill(os.getpid(), signal.SIGINT)  # the handler runs here, with the lock held
    deadline = time.monotonic() + 30
    while not rospy.is_shutdown() and time.monotonic() < deadline:
        time.sleep(0.01)
print(rospy.is_shutdown(), flush=True)
"""


@pytest.mark.skipif(
    not hasattr(threading, "_shutdown_locks_lock"),
    reason="this Python's threading holds no such lock while it joins a thread",
)
def test_ctrl_c_shuts_the_node_down_whatever_lock_the_main_thread_holds(
    master: str, tmp_path: Path
) -> None:
    # Python runs a signal handler between any two bytecodes of the main thread, here inside a
    # lock that starting a `threading.Thread` needs: a handler that started one waited forever,
    # and SIGTERM, whose handler is the same, could not end the script either.
    script = tmp_path / "held.py"
    script.write_text(HELD_WHEN_SIGNALLED)
    process = start_script(script, ROS_MASTER_URI=master)
    try:
        out, err = process.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        pytest.fail("the script still runs: its signal handler waits for the lock it holds")
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert (process.returncode, out, err) == (0, "True\n", "")
    client = MasterClient(master, "/test")
    try:
        assert client.lookup_node("/held") is None  # it left the graph
    finally:
        client.close()


def test_a_python_without_rosx_is_told_what_to_do(tmp_path: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-S", "-c", "import rospy"],
        env={**clean_environ(), "PYTHONPATH": str(SHIM_DIR)},
        cwd=tmp_path,
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 1
    assert "this rospy is rosx's, and this Python cannot import rosx" in done.stderr
    assert "rosx rosrun PACKAGE SCRIPT" in done.stderr


#: Each shim rosx has, and a name its ROS 1 module has (``module.name`` when a submodule holds it).
ROS1_NAMES = {
    "actionlib": "SimpleActionClient",
    "genpy": "Message",
    "rosbag": "Bag",
    "rosgraph": "Master",
    "roslib": "load_manifest",
    "rospkg": "RosPack",
    "rospy": "init_node",
    "tf": "transformations.quaternion_from_euler",
    "tf2_geometry_msgs": "do_transform_point",
    "tf2_py": "BufferCore",
    "tf2_ros": "Buffer",
    "tf_conversions": "transformations.quaternion_from_euler",
}


def test_the_ros1_test_knows_every_shim() -> None:
    shims = {p.name for d in shim_dirs() for p in d.iterdir() if (p / "__init__.py").is_file()}
    assert shims == set(ROS1_NAMES)


@needs_ros1
@pytest.mark.parametrize("name", sorted(ROS1_NAMES))
def test_ros1s_python_gets_ros1s_module_with_every_shim_folder_on_its_path(
    tmp_path: Path, name: str
) -> None:
    # rosx's shim folders are on PYTHONPATH in a shell that sourced a workspace; ROS 1's Python
    # there must get ROS 1's module, not loop from one of rosx's shim folders to the next.
    submodule, _, attribute = ROS1_NAMES[name].rpartition(".")
    module = f"{name}.{submodule}" if submodule else name
    code = f"import {module}; print({name}.__file__); {module}.{attribute}"
    done = ros1_python_with_path(code, list(shim_dirs()), tmp_path)
    if not ros1_python_imports(name):  # Debian has no python3-tf-conversions: rosx's says so
        assert done.returncode == 1
        assert f"this {name} is rosx's, and this Python cannot import rosx" in done.stderr
        return
    assert done.returncode == 0, done.stderr
    assert done.stdout == f"/usr/lib/python3/dist-packages/{name}/__init__.py\n"


@needs_ros1
def test_the_ros1_reference_keeps_its_modules_when_the_run_has_the_shim_folders(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # As in a shell that sourced a workspace: ROS 1's Python, started from the checkout (where
    # it could import rosx), must still be ROS 1 alone.
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(str(d) for d in shim_dirs()))
    files = ros1_python(
        "import json, genpy, rospy; print(json.dumps([genpy.__file__, rospy.__file__]))"
    )
    assert files == [
        f"/usr/lib/python3/dist-packages/{name}/__init__.py" for name in ("genpy", "rospy")
    ]


@pytest.mark.parametrize("module", ["rospy.exceptions"])
def test_rospy_submodules_scripts_import(tmp_path: Path, module: str) -> None:
    done = run_script(
        tmp_path,
        f"import json, {module} as m\nprint(json.dumps(m.ROSInterruptException.__name__))\n",
    )
    assert json_of(done) == "ROSInterruptException"


def test_scripts_import_rosbag_from_the_bag_layers_shim(tmp_path: Path) -> None:
    writer = run_script(
        tmp_path,
        """\
import rosbag
from std_msgs.msg import Int32, String
with rosbag.Bag('test.bag', 'w') as bag:
    bag.write('chatter', String(data='foo'))
    bag.write('numbers', Int32(data=42))
""",
    )
    assert writer.returncode == 0, writer.stderr
    reader = run_script(
        tmp_path,
        """\
import json, rosbag
bag = rosbag.Bag('test.bag')
got = [(topic, str(msg).replace(chr(10), ' ')) for topic, msg, t in bag.read_messages()]
print(json.dumps([rosbag.__file__, got]))
bag.close()
""",
    )
    where, got = json_of(reader)
    assert Path(where).parent.parent.name == "shim"
    assert Path(where).parent.parent.parent.name == "bag"
    assert got == [["chatter", 'data: "foo"'], ["numbers", "data: 42"]]


def test_every_name_the_client_api_loads_on_first_use_resolves() -> None:
    import rosx.client

    homes = rosx.client._HOMES
    missing = [name for name in homes if not hasattr(rosx.client, name)]
    assert missing == []
