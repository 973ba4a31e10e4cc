"""One script, two rospys: Debian's rospy and rosgraph, and rosx's (``rosx run-script``), on the
same rosx master, print the same answers to the API calls real scripts make (``rospy.names``,
``MasterProxy``, ``remap_name``, ``Service(error_handler=)``, ``/rosout`` records, ``rosgraph``).

Skipped where ROS 1's rospy is absent.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from rosx.master.server import MasterThread
from tests.support.cli import clean_environ
from tests.support.ros1 import ROS1_PYTHON, ros1_python_imports
from tests.support.scripts import script_command

pytestmark = pytest.mark.skipif(
    not ros1_python_imports("rospy", "rosgraph", "std_srvs.srv", "rosgraph_msgs.msg"),
    reason="ROS 1's rospy is absent",
)

PROBE = r"""
import io, os, sys, time
import rospy
from std_msgs.msg import Empty, String
from std_srvs.srv import Trigger
from rosgraph_msgs.msg import Log

def show(label, fn):
    try:
        print(label, "->", repr(fn()))
    except Exception as e:
        print(label, "-> raised", type(e).__name__, e)

show("caller before init", lambda: rospy.names.get_caller_id())
show("mappings", lambda: sorted(rospy.names.get_mappings().items()))
show("resolved mappings before init", lambda: rospy.names.get_resolved_mappings())
show("remap_name before init", lambda: [rospy.remap_name(n) for n in ("a", "/x", "b")])
rospy.init_node("probe")
import rospy.names as names
show("names", lambda: [names.get_caller_id(), names.get_name(), names.get_namespace()])
show("resolve", lambda: [names.resolve_name(n) for n in ("~p", "a", "rel/x", "")])
show("resolve for caller", lambda: names.resolve_name("a", "/other/node"))
show("remap_name", lambda: [names.remap_name(n) for n in ("a", "/x", "b")])
show("resolved mappings", lambda: sorted(names.get_resolved_mappings().items()))
show("helpers", lambda: [names.canonicalize_name("//a//b/"), names.ns_join("/a", "b"),
     names.namespace("/a/b"), names.scoped_name("/a/node", "/a/b/c"), names.SEP,
     names.GLOBALNS, names.TOPIC_ANYTYPE, names.SERVICE_ANYTYPE, names.REMAP])
proxy = rospy.MasterProxy(os.environ["ROS_MASTER_URI"])
show("proxy getPid", lambda: proxy.getPid()[:2])
proxy["~k"] = 5
show("proxy params", lambda: [proxy["~k"], "~k" in proxy, proxy.search_param("k"),
     proxy.getParam("~k")])
show("proxy missing", lambda: proxy["nope"])
show("get_master", lambda: [type(rospy.get_master()).__name__, rospy.get_master().getPid()[:2]])
show("get_ros_root", lambda: rospy.get_ros_root())
buff = io.BytesIO()
rospy.Message().serialize(buff)
show("Message", lambda: buff.tell())
anymsg = rospy.AnyMsg()
show("AnyMsg", lambda: [anymsg.deserialize("foostr") is anymsg, anymsg._buff])
show("AnyMsg serialize", lambda: rospy.AnyMsg().serialize(io.BytesIO()))
seen = []
def boom(request):
    raise RuntimeError("boom")
rospy.Service("~boom", Trigger, boom,
              error_handler=lambda e, t, v, tb: seen.append([str(e), t.__name__, v is e]))
records = []
rospy.Subscriber("/rosout", Log, lambda m: records.append(m) if m.name == "/probe" else None)
rospy.Publisher("/twice", String, queue_size=1)
rospy.Subscriber("/twice", String, lambda m: None)
rospy.wait_for_service("~boom")
try:
    rospy.ServiceProxy("~boom", Trigger)()
except rospy.ServiceException:
    show("error_handler", lambda: seen)
class Thing:
    def method(self):
        rospy.loginfo("from method")
def func():
    rospy.loginfo("from func")
deadline = time.time() + 10
while time.time() < deadline and len({r.msg for r in records if r.msg.startswith("from ")}) < 3:
    Thing().method(); func(); rospy.loginfo("from module")
    time.sleep(0.2)
for text in ("from method", "from func", "from module"):
    r = next(r for r in records if r.msg == text)
    print("rosout", text, "|", r.file, "|", r.function, "|", sorted(r.topics))
import rosgraph, rosgraph.names
master = rosgraph.Master("probe_tool")
show("rosgraph", lambda: [master.caller_id, type(master.getPid()).__name__,
     master.getParam("/probe/k"), master.setParam("/g", [1, "x"]), master.hasParam("/g"),
     master.searchParam("g"), master.is_online(), rosgraph.is_master_online()])
show("rosgraph missing", lambda: master.getParam("/nope"))
show("rosgraph unknown node", lambda: master.lookupNode("/nobody"))
show("rosgraph offline", lambda: rosgraph.Master("/x", master_uri="http://127.0.0.1:9/").getPid())
show("rosgraph bad uri", lambda: rosgraph.Master("/x", master_uri="nope"))
show("rosgraph names", lambda: [rosgraph.myargv(["a", "b:=c"]), rosgraph.names.ns_join("/a", "b"),
     rosgraph.names.resolve_name("~x", "/ns/node"), rosgraph.names.make_caller_id("n"),
     rosgraph.names.script_resolve_name("rostopic", "~p"), rosgraph.names.is_legal_name("a//b"),
     rosgraph.names.load_mappings(["a:=b", "_p:=1", "__ns:=/q"])])
"""

ARGS = ["a:=/remapped/a", "/x:=y", "_p:=1"]


def _run(command: list[str], home: Path) -> list[str]:
    """What the probe prints, run by ``command`` against a fresh rosx master."""
    with MasterThread(port=0, host="127.0.0.1", advertised_host="127.0.0.1") as master:
        env = clean_environ(ROS_MASTER_URI=master.uri, ROS_HOME=str(home), PYTHONWARNINGS="ignore")
        done = subprocess.run(
            [*command, *ARGS], env=env, capture_output=True, text=True, timeout=120, check=False
        )
    assert done.returncode == 0, done.stderr
    # Node URIs differ; the console lines are as many as the loop needed for /rosout to answer.
    text = re.sub(r"http://[^/']+/", "URI", done.stdout)
    return [line for line in text.splitlines() if not line.startswith("[INFO] [")]


def test_the_same_script_gets_the_same_answers(tmp_path: Path) -> None:
    script = tmp_path / "probe.py"
    script.write_text(PROBE)
    theirs = _run([ROS1_PYTHON, str(script)], tmp_path)
    ours = _run(script_command(script), tmp_path)
    assert ours == theirs
    assert "rosout from method | probe.py | Thing.method | ['/rosout', '/twice']" in ours
