"""rospy API that real scripts use beyond the basics: ``rospy.names``, ``MasterProxy``,
``get_ros_root``, ``remap_name``, the ``Message``/``AnyMsg`` trip wires of ROS 1's own API test,
``Service(error_handler=)``, what ``/rosout`` records say, and the ``rosgraph`` shim.

The expected values are what Debian's rospy and rosgraph give for the same calls
(``tests/interop/test_rospy_api_ros1.py`` compares the two side by side).
"""

from __future__ import annotations

import io
import os
import re
import sys
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

from rosx.client import state
from rosx.client.script import SHIM_DIR
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from tests.support.procs import wait_for
from tests.support.ros1 import needs_ros1, ros1_python_with_path
from tests.support.scripts import json_of, run_script

Log = get_message_class("rosgraph_msgs/Log")
String = get_message_class("std_msgs/String")
Trigger = get_service_class("std_srvs/Trigger")

ARGV = ["script.py", "a:=/remapped/a", "/x:=y", "_p:=1", "__ns:=/ns"]


# -- rospy.names, remap_name, get_ros_root ---------------------------------------------------


def test_names_before_and_after_init_node(rospy: ModuleType) -> None:
    from rosx.client import names

    rospy.init_node("probe", argv=ARGV, disable_signals=True)  # reads ARGV from here on
    assert names.get_mappings() == {"a": "/remapped/a", "/x": "y", "__ns": "/ns"}
    assert (names.get_caller_id(), names.get_name()) == ("/ns/probe", "/ns/probe")
    assert names.get_namespace() == "/ns/"
    assert names.resolve_name("~p") == "/ns/probe/p"
    assert names.resolve_name("a") == "/remapped/a"
    assert names.resolve_name("rel/x") == "/ns/rel/x"
    assert names.resolve_name("") == "/ns/"
    assert names.resolve_name("a", "/other/node") == "/other/a"
    assert names.remap_name("a") == rospy.remap_name("a") == "/remapped/a"
    assert (names.remap_name("/x"), names.remap_name("b")) == ("/ns/y", "b")
    assert names.get_resolved_mappings() == {
        "/ns/a": "/remapped/a", "/x": "/ns/y", "__ns": "/ns"
    }  # fmt: skip
    assert names.scoped_name("/a/node", "/a/b/c") == "b/c"
    assert (names.canonicalize_name("//a//b/"), names.namespace("/a/b")) == ("/a/b", "/a/")
    assert (names.SEP, names.GLOBALNS, names.TOPIC_ANYTYPE, names.REMAP) == ("/", "/", "*", ":=")


def test_remap_name_and_mappings_before_init_node(rospy: ModuleType) -> None:
    from rosx.client import names

    assert names.get_resolved_mappings() == {}
    assert names.get_caller_id() == "/unnamed"
    assert rospy.remap_name("b") == "b"


def test_get_ros_root_is_deprecated_and_reads_ros_root(
    rospy: ModuleType, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ROS_ROOT", raising=False)
    with pytest.warns(DeprecationWarning, match="get_ros_root"):
        assert rospy.get_ros_root() is None
    with pytest.warns(DeprecationWarning), pytest.raises(rospy.ROSException, match="ROS_ROOT"):
        rospy.get_ros_root(required=True)
    with pytest.warns(DeprecationWarning):
        assert rospy.get_ros_root(env={"ROS_ROOT": "/opt/ros//share/ros/"}) == "/opt/ros/share/ros"


# -- MasterProxy ------------------------------------------------------------------------------


def test_master_proxy_answers_whole_replies_and_resolves_names(rospy: ModuleType) -> None:
    rospy.init_node("prox", disable_signals=True)
    master = rospy.get_master()
    assert isinstance(master, rospy.MasterProxy) and rospy.get_master() is master
    assert master.getPid()[:2] == [1, ""]
    master["~k"] = 5  # a private name: resolved under the node
    assert (master["~k"], "~k" in master, "nope" in master) == (5, True, False)
    assert master.getParam("~k") == [1, "Parameter [/prox/k]", 5]
    assert master.search_param("k") == "/prox/k"
    assert master.lookupNode("prox")[:2] == [1, "node api"]
    assert "/prox/k" in list(master)
    with pytest.raises(KeyError):
        master["nope"]
    del master["~k"]
    with pytest.raises(KeyError):
        del master["~k"]


# -- Message and AnyMsg, as ROS 1's rospy API test trips them ----------------------------------


def test_message_and_anymsg_trip_wires(rospy: ModuleType) -> None:
    buff = io.BytesIO()
    rospy.Message().serialize(buff)  # no fields: nothing to write
    assert buff.tell() == 0
    rospy.Message().deserialize(b"")
    anymsg = rospy.AnyMsg()
    with pytest.raises(rospy.ROSException, match="AnyMsg is not initialized"):
        anymsg.serialize(io.BytesIO())
    assert anymsg.deserialize("foostr") is anymsg
    assert anymsg._buff == "foostr"  # kept as given
    view = memoryview(b"\x01\x02")
    assert anymsg.deserialize(view)._buff is view


# -- Service(error_handler=) ------------------------------------------------------------------


def test_a_service_error_handler_gets_what_the_handler_raised(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("server", disable_signals=True)
    seen: list[tuple[Any, ...]] = []

    def boom(request: Any) -> Any:
        raise RuntimeError("boom")

    def on_error(exc: Exception, kind: type, value: BaseException, tb: Any) -> None:
        seen.append((type(exc).__name__, str(exc), kind.__name__, value is exc, tb is not None))

    rospy.Service("~boom", Trigger, boom, error_handler=on_error)
    rospy.Service("~plain", Trigger, boom)
    rospy.wait_for_service("~boom", timeout=5)
    with pytest.raises(rospy.ServiceException, match="error processing request: boom"):
        rospy.ServiceProxy("~boom", Trigger)()
    assert seen == [("RuntimeError", "boom", "RuntimeError", True, True)]
    assert "Error processing request" not in capsys.readouterr().err  # handled, not logged
    with pytest.raises(rospy.ServiceException, match="error processing request: boom"):
        rospy.ServiceProxy("~plain", Trigger)()
    assert "Error processing request: boom" in capsys.readouterr().err


# -- /rosout records ----------------------------------------------------------------------------


class _Reporter:
    def method(self, rospy: ModuleType) -> None:
        rospy.logwarn("from a method")


def test_rosout_names_class_and_method_and_each_topic_once(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> None:
    records: list[Any] = []
    make_node("reader").subscribe("/rosout", Log, records.append)
    rospy.init_node("reporter", disable_signals=True)
    rospy.Publisher("/both", String, queue_size=1)
    rospy.Subscriber("/both", String, lambda msg: None)
    wait_for(lambda: rospy.get_master().getSystemState()[2][1], what="subscriptions")

    def logged() -> bool:
        _Reporter().method(rospy)
        return any(r.msg == "from a method" for r in records)

    wait_for(logged, what="the record on /rosout")
    record = next(r for r in records if r.msg == "from a method")
    assert (record.function, record.file) == ("_Reporter.method", "test_rospy_api.py")
    assert sorted(record.topics) == ["/both", "/rosout"]


# -- scripts: import rospy.names, import rosgraph ------------------------------------------------


ROSGRAPH_SCRIPT = """\
import json, sys
import rospy, rospy.names, rosgraph, rosgraph.names
from rosgraph.masterapi import Master as MasterApi
master = rosgraph.Master("tool")
out = [rospy.names.get_caller_id(), rospy.names.get_mappings(), master.caller_id]
out.append(type(master.getPid()).__name__)
out.append(master.setParam("/g", [1, "x"]))
out.append([master.getParam("/g"), master.hasParam("/g"), master.searchParam("g")])
for call in (lambda: master.getParam("/nope"), lambda: master.lookupNode("/nobody")):
    try:
        call()
    except rosgraph.MasterError as error:
        out.append([type(error).__name__, str(error)])
offline = rosgraph.Master("/x", master_uri="http://127.0.0.1:9/")
try:
    offline.getPid()
except ConnectionRefusedError as error:
    out.append(str(error))
out.append([offline.is_online(), rosgraph.is_master_online(), MasterApi is rosgraph.Master])
try:
    rosgraph.Master("/x", master_uri="nope")
except ValueError as error:
    out.append(str(error))
names = rosgraph.names
out.append([
    rosgraph.myargv(["a", "b:=c", "d"]), names.ns_join("/a", "b"),
    names.resolve_name("~x", "/ns/node"), names.resolve_name("x", "/ns/node", {"/ns/x": "/y"}),
    names.script_resolve_name("rostopic", "~p"), names.make_caller_id("n"),
    names.is_legal_name("a//b"), names.load_mappings(["a:=b", "_p:=1", "__ns:=/q"]),
    names.namespace("/a/b"), names.canonicalize_name("a//b/"),
    names.anonymous_name("x").startswith("x_"),
])
print(json.dumps(out))
"""


def test_scripts_import_rospy_names_and_rosgraph(tmp_path: Path, master: str) -> None:
    done = run_script(tmp_path, ROSGRAPH_SCRIPT, "a:=b", ROS_MASTER_URI=master)
    assert json_of(done) == [
        "/unnamed",
        {"a": "b"},
        "/tool",
        "int",
        0,
        [[1, "x"], True, "/g"],
        ["MasterError", "Parameter [/nope] is not set"],
        ["MasterError", "unknown node [/nobody]"],
        "[Errno 111] Connection refused",
        [False, True, True],
        "invalid master URI: nope",
        [
            ["a", "d"], "/a/b", "/ns/node/x", "/y", "/rostopic/p", "/n/", False,
            {"a": "b", "__ns": "/q"}, "/a/", "a/b", True,
        ],
    ]  # fmt: skip


@needs_ros1
def test_ros1s_python_keeps_ros1s_rosgraph_with_the_shim_on_its_path(tmp_path: Path) -> None:
    code = "import rospy, rosgraph.names; print(rosgraph.names.__file__)"
    done = ros1_python_with_path(code, [SHIM_DIR], tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "/usr/lib/python3/dist-packages/rosgraph/names.py"


def test_a_log_argument_gets_rospys_log_file(
    rospy: ModuleType, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    log = tmp_path / "run" / "talker-1.log"
    monkeypatch.setattr(sys, "argv", ["script.py", f"__log:={log}", "__ns:=ns"])
    rospy.init_node("talker", disable_signals=True)
    rospy.loginfo("hello %d", 1)
    rospy.logdebug("not at INFO")
    rospy.logwarn("careful")
    rospy.signal_shutdown("done")
    stamp = r"\d{4}-\d\d-\d\d \d\d:\d\d:\d\d,\d{3}"
    wait_for(lambda: "signal_shutdown" in log.read_text(), what="the shutdown line")
    lines = log.read_text().splitlines()
    patterns = [
        rf"\[rospy\.client\]\[INFO\] {stamp}: init_node, name\[/ns/talker\], pid\[{os.getpid()}\]",
        rf"\[rosout\]\[INFO\] {stamp}: hello 1",
        rf"\[rosout\]\[WARNING\] {stamp}: careful",
        rf"\[rospy\.core\]\[INFO\] {stamp}: signal_shutdown \[done\]",
    ]
    assert len(lines) == len(patterns), lines
    for line, pattern in zip(lines, patterns, strict=True):
        assert re.fullmatch(pattern, line), line


def test_an_exit_before_a_signals_shutdown_has_run_still_logs_the_signal(
    rospy: ModuleType, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A stopping signal's handler hands the shutdown to a thread (`rosx.signals.soon`); the
    # script may end before that thread runs. rospy shuts down in the handler itself: its log
    # names the signal, and so does this one.
    log = tmp_path / "listener-1.log"
    monkeypatch.setattr(sys, "argv", ["script.py", f"__log:={log}"])
    rospy.init_node("listener", disable_signals=True)
    handed: list[Callable[[], object]] = []
    monkeypatch.setattr(state, "soon", handed.append)  # the thread, not run yet
    state.CLIENT.shutdown_in_background("signal-15")  # what the SIGTERM handler calls
    assert (len(handed), rospy.is_shutdown()) == (1, False)
    state.CLIENT.at_exit()  # the interpreter's exit comes first
    handed[0]()  # then the signal's thread: the node is down already
    assert rospy.is_shutdown()
    wait_for(lambda: "signal_shutdown" in log.read_text(), what="the shutdown line")
    shutdowns = [line for line in log.read_text().splitlines() if "signal_shutdown" in line]
    assert [line.split(": ", 1)[1] for line in shutdowns] == ["signal_shutdown [signal-15]"]
