"""rospy's logging functions, Parameter Server functions and services over rosx."""

from __future__ import annotations

import importlib
import io
import logging
import re
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from rosx.client.roslogging import RosStreamHandler
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from tests.support.procs import wait_for

SetBool = get_service_class("std_srvs/SetBool")
Log = get_message_class("rosgraph_msgs/Log")

LINE = re.compile(r"^\[(INFO|WARN|ERROR|DEBUG|FATAL)\] \[\d+\.\d{6}\]: (.*)$")


def test_logs_go_to_the_console_in_rospys_format(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("logger", disable_signals=True)
    rospy.loginfo("hello %s", "world")
    rospy.logdebug("not at INFO")
    rospy.logwarn("careful")
    rospy.logerr("broken: %d", 3)
    out, err = capsys.readouterr()
    assert [LINE.match(line).groups() for line in out.splitlines()] == [  # type: ignore[union-attr]
        ("INFO", "hello world")
    ]
    assert [LINE.match(line).groups() for line in err.splitlines()] == [  # type: ignore[union-attr]
        ("WARN", "careful"),
        ("ERROR", "broken: 3"),
    ]


def test_once_and_throttle_log_from_each_call_site_once(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("chatty", disable_signals=True)
    for _ in range(5):
        rospy.loginfo_once("once")
        rospy.loginfo_throttle(60, "throttled")
        rospy.loginfo_throttle_identical(60, "same")
    rospy.loginfo_once("once")  # another call site
    out = capsys.readouterr().out
    assert [LINE.match(line).group(2) for line in out.splitlines()] == [  # type: ignore[union-attr]
        "once",
        "throttled",
        "same",
        "once",
    ]


def test_ros_stream_handler_writes_rospys_console_lines() -> None:
    out, err = io.StringIO(), io.StringIO()
    logger = logging.getLogger("rosx-test-stream")
    logger.propagate = False
    logger.setLevel(logging.DEBUG)
    handler = RosStreamHandler(colorize=False, stdout=out, stderr=err)
    logger.addHandler(handler)
    try:
        logger.info("fine %d", 1)
        logger.warning("careful")
        logger.error("broken")
        logger.critical("gone")
    finally:
        logger.removeHandler(handler)
    outs = [LINE.match(line) for line in out.getvalue().splitlines()]
    errs = [LINE.match(line) for line in err.getvalue().splitlines()]
    assert [m.groups() if m else None for m in outs] == [("INFO", "fine 1")]
    assert [m.groups() if m else None for m in errs] == [
        ("WARN", "careful"),
        ("ERROR", "broken"),
        ("FATAL", "gone"),
    ]


def test_before_init_node_only_warnings_and_worse_print(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.loginfo("quiet")
    rospy.logwarn("loud")
    out, err = capsys.readouterr()
    assert (out, err) == ("", "loud\n")


def test_logs_reach_rosout_with_the_callers_place(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> None:
    records: list[Any] = []
    make_node("reader").subscribe("/rosout", Log, records.append)
    rospy.init_node("reporter", disable_signals=True)
    wait_for(lambda: rospy.get_master().getSystemState()[2][1], what="subscriptions")

    def report() -> None:
        rospy.logwarn("to rosout")

    def logged() -> bool:
        report()
        return any(r.msg == "to rosout" for r in records)

    wait_for(logged, what="the record on /rosout")
    record = next(r for r in records if r.msg == "to rosout")
    assert (record.name, record.level, record.function) == ("/reporter", 4, "report")
    assert record.file == "test_rospy_logs_params_services.py"


def test_parameters(rospy: ModuleType) -> None:
    rospy.set_param("/before", 1)  # no node needed, as in rospy
    assert rospy.get_param("/before") == 1
    rospy.init_node("params", disable_signals=True)
    rospy.set_param("~gain", 2.5)
    rospy.set_param("group", {"a": 1, "b": "two"})
    assert rospy.get_param("/params/gain") == 2.5
    assert rospy.get_param("group/b") == "two"
    assert rospy.get_param_cached("group") == {"a": 1, "b": "two"}
    assert rospy.has_param("~gain") and not rospy.has_param("~none")
    assert rospy.get_param("~none", "fallback") == "fallback"
    with pytest.raises(KeyError):
        rospy.get_param("~none")
    assert rospy.search_param("gain") == "/params/gain"  # the node's own namespace first
    assert rospy.search_param("nothing") is None
    assert rospy.search_param("group") == "/group"
    assert {"/params/gain", "/group/a"} <= set(rospy.get_param_names())
    rospy.delete_param("~gain")
    with pytest.raises(KeyError):
        rospy.delete_param("~gain")


def test_parameters_as_another_caller(rospy: ModuleType) -> None:
    rospy.init_node("asker", disable_signals=True)
    names = importlib.import_module(f"{rospy.__name__}.names")  # rospy.names
    rospy.set_param("/depth", 0)
    names._set_caller_id("/deep/er/visitor")
    try:
        assert rospy.get_name() == "/deep/er/visitor"
        assert rospy.get_namespace() == "/deep/er/"
        assert rospy.search_param("depth") == "/depth"
        rospy.set_param("/deep/depth", 1)
        assert rospy.search_param("depth") == "/deep/depth"
        rospy.set_param("~depth", 2)  # private to the caller, found before the rest
        assert rospy.get_param("/deep/er/visitor/depth") == 2
        assert rospy.search_param("depth") == "/deep/er/visitor/depth"
        assert rospy.resolve_name("depth") == "/deep/er/depth"
    finally:
        names._set_caller_id("/asker")
    assert rospy.get_name() == "/asker"
    assert rospy.search_param("depth") == "/depth"
    assert rospy.resolve_name("~depth") == "/asker/depth"


def test_services_answer_proxies(rospy: ModuleType) -> None:
    rospy.init_node("server", disable_signals=True)

    def handle(request: Any) -> object:
        if not request.data:
            raise rospy.ServiceException("say yes")
        return True, "done"

    service = rospy.Service("~toggle", SetBool, handle)
    rospy.wait_for_service("/server/toggle", timeout=5)
    proxy = rospy.ServiceProxy("/server/toggle", SetBool)
    response = proxy(True)
    assert (response.success, response.message) == (True, "done")
    assert proxy.call(data=True).success
    with pytest.raises(rospy.ServiceException, match="service cannot process request: say yes"):
        proxy(False)
    service.shutdown()
    with pytest.raises(rospy.ServiceException, match=r"^service \[/server/toggle\] unavailable$"):
        proxy(True)


def test_wait_for_service_times_out_with_rospys_texts(rospy: ModuleType) -> None:
    with pytest.raises(ValueError, match=r"^timeout must be non-zero$"):
        rospy.wait_for_service("/none", timeout=0)
    with pytest.raises(rospy.ROSException, match=r"^timeout exceeded while waiting for service"):
        rospy.wait_for_service("/none", timeout=0.5)


def test_a_proxy_works_before_init_node(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> None:
    make_node("provider").advertise_service("/yes", SetBool, lambda req: (True, "ok"))
    rospy.wait_for_service("/yes", timeout=5)
    assert rospy.ServiceProxy("/yes", SetBool)(data=True).message == "ok"
