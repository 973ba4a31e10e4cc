"""rosx rostopic echo / pub / hz / bw / delay on a rosx master and rosx nodes in this process."""

from __future__ import annotations

import contextlib
import io
import re
import signal
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.transport.client import XmlRpcClient
from rosx_commands.context import Environment
from rosx_commands.main import run_tool
from tests.support.cli import Result, clean_environ, rosx, rosx_popen
from tests.support.procs import free_port, wait_for

String = get_message_class("std_msgs/String")
Int32 = get_message_class("std_msgs/Int32")
Twist = get_message_class("geometry_msgs/Twist")
PointStamped = get_message_class("geometry_msgs/PointStamped")
FloatArray = get_message_class("std_msgs/Float32MultiArray")
Time = type(PointStamped().header.stamp)


@pytest.fixture
def env(master: str) -> dict[str, str]:
    return clean_environ(ROS_MASTER_URI=master)


@pytest.fixture
def stream(make_node: Callable[[str], Node]) -> Iterator[Callable[..., None]]:
    """``stream(topic, msg, hz)``: publish ``msg`` on ``topic`` ``hz`` times a second."""
    stop = threading.Event()
    threads: list[threading.Thread] = []

    def start(topic: str, msg: Any, hz: float = 20.0) -> None:
        node = make_node(f"/streamer{len(threads)}")
        publisher = node.advertise(topic, type(msg), queue_size=10)

        def run() -> None:
            while not stop.wait(1.0 / hz):
                publisher.publish(msg)

        thread = threading.Thread(target=run, daemon=True)
        threads.append(thread)
        thread.start()

    yield start
    stop.set()
    for thread in threads:
        thread.join()


def tool_nodes(master: str) -> set[str]:
    """The rostopic nodes the master knows of."""
    pubs, subs, _ = XmlRpcClient(timeout=2).call(master, "getSystemState", "/test")[2]
    names = {n for _, nodes in pubs + subs for n in nodes}
    return {n for n in names if n.rpartition("/")[2].startswith("rostopic_")}


def run_for(
    master: str,
    seconds: float,
    *argv: str,
    environ: dict[str, str],
    until: Callable[[str, str], bool] | None = None,
) -> Result:
    """Run a tool that never ends by itself; shut its node down (``rosnode kill``) once it has
    run ``seconds`` and, on a loaded machine maybe later, its output (stdout, stderr) holds
    what ``until`` looks for."""
    before = tool_nodes(master)
    out, err = io.StringIO(), io.StringIO()

    def kill() -> None:
        client = XmlRpcClient(timeout=2)
        wait_for(lambda: bool(tool_nodes(master) - before), what="the tool's node")
        (name,) = tool_nodes(master) - before
        uri = client.call(master, "lookupNode", "/test", name)[2]
        time.sleep(seconds)
        if until is not None:
            # Past the deadline the tool is stopped all the same and the test's asserts fail.
            with contextlib.suppress(TimeoutError):
                wait_for(lambda: until(out.getvalue(), err.getvalue()), timeout=60)
        client.call(uri, "shutdown", "/test", "test over")

    killer = threading.Thread(target=kill, daemon=True)
    killer.start()
    env = Environment(stdout=out, stderr=err, stdin=io.StringIO(""), environ=environ)
    status = run_tool(list(argv), env)
    killer.join()
    return Result(int(status), out.getvalue(), err.getvalue())


def _lines(count: int, text: str = "") -> Callable[[str, str], bool]:
    """``until`` for `run_for`: ``count`` whole lines on stdout (stderr, with ``text="err"``)."""
    return lambda out, err: (err if text == "err" else out).count("\n") >= count


def in_thread(*argv: str, environ: dict[str, str]) -> Callable[[], Result]:
    """Start ``rosx ARGV`` on a thread; the returned function waits for its result."""
    results: list[Result] = []
    thread = threading.Thread(
        target=lambda: results.append(rosx(*argv, environ=environ)), daemon=True
    )
    thread.start()

    def result() -> Result:
        thread.join(30)
        return results[0]

    return result


TWIST_TEXT = (
    "linear: \n  x: 1.5\n  y: 0.0\n  z: 0.0\nangular: \n  x: 0.0\n  y: 0.0\n  z: -0.5\n---\n"
)
STAMPED_TEXT = (
    "header: \n  seq: 1\n  stamp: \n    secs: 1700000000\n    nsecs:      5000\n"
    '  frame_id: "map"\npoint: \n  x: 0.1\n  y: 0.0\n  z: 0.0\n---\n'
)


def twist() -> Any:
    msg = Twist()
    msg.linear.x, msg.angular.z = 1.5, -0.5
    return msg


def stamped() -> Any:
    msg = PointStamped()
    msg.header.stamp = Time(1700000000, 5000)
    msg.header.frame_id = "map"
    msg.point.x = 0.1
    return msg


def latch(node: Node, topic: str, msg: Any) -> None:
    node.advertise(topic, type(msg), queue_size=1, latch=True).publish(msg)


# -- echo ----------------------------------------------------------------------------------


def test_echo_prints_messages_as_ros1(
    make_node: Callable[[str], Node], env: dict[str, str]
) -> None:
    node = make_node("/latcher")
    latch(node, "/e/string", String('say "hi"'))
    latch(node, "/e/twist", twist())
    latch(node, "/e/stamped", stamped())
    latch(node, "/e/array", FloatArray(data=[0.1, 2.5]))
    cases = {
        ("/e/string",): 'data: "say \\"hi\\""\n---\n',
        ("/e/twist",): TWIST_TEXT,
        ("/e/stamped",): STAMPED_TEXT,
        ("/e/twist/linear",): "x: 1.5\ny: 0.0\nz: 0.0\n---\n",
        ("/e/twist/angular/z",): "-0.5\n---\n",
        ("/e/stamped/header/stamp",): "\nsecs: 1700000000\nnsecs:      5000\n---\n",
        (
            "/e/array",
        ): "layout: \n  dim: []\n  data_offset: 0\ndata: [0.10000000149011612, 2.5]\n---\n",
        ("/e/array/data[1:]",): "[2.5]\n---\n",
        ("--noarr", "/e/array"): (
            'layout: \n  dim: "<array type: std_msgs/MultiArrayDimension, length: 0>"\n'
            '  data_offset: 0\ndata: "<array type: float32, length: 2>"\n---\n'
        ),
        ("--nostr", "/e/string"): 'data: "<string length: 8>"\n---\n',
        ("-p", "/e/stamped"): (
            "%time,field.header.seq,field.header.stamp,field.header.frame_id,"
            "field.point.x,field.point.y,field.point.z\n"
            "1700000000000005000,1,1700000000000005000,map,0.1,0.0,0.0\n"
        ),
        ("-p", "/e/array/data"): None,  # checked below: the time column is the receipt time
        ("-c", "/e/string"): '\x1b[2J\x1b[;Hdata: "say \\"hi\\""\n---\n',
        ("-w", "4", "/e/twist/linear"): "x: 1.50\ny: 0.00\nz: 0.00\n---\n",
        ("--filter", "m.linear.x > 1", "/e/twist"): TWIST_TEXT,
    }
    for args, expected in cases.items():
        result = rosx("rostopic", "echo", "-n", "1", *args, environ=env)
        assert (result.status, result.err) == (0, ""), args
        if expected is None:
            assert re.fullmatch(
                r"%time,field0,field1\n\d{19},0\.10000000149011612,2\.5\n", result.out
            )
        else:
            assert result.out == expected, args
    assert not tool_nodes(env["ROS_MASTER_URI"])  # each echo's node unregistered on exit


def test_echo_count_and_stream(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/e/stream", twist())
    result = rosx("rostopic", "echo", "-n", "3", "/e/stream", environ=env)
    assert (result.status, result.out, result.err) == (0, TWIST_TEXT * 3, "")
    result = rosx("rostopic", "echo", "-n", "2", "-p", "/e/stream/linear", environ=env)
    lines = result.out.splitlines()
    assert lines[0] == "%time,field.x,field.y,field.z"
    assert all(re.fullmatch(r"\d{19},1\.5,0\.0,0\.0", line) for line in lines[1:])
    assert len(lines) == 3


def test_echo_waits_for_the_topic_and_resolves_relative_names(
    make_node: Callable[[str], Node], master: str
) -> None:
    environ = clean_environ(ROS_MASTER_URI=master, ROS_NAMESPACE="/ns")
    echo = in_thread("rostopic", "echo", "-n", "1", "chatter", environ=environ)
    wait_for(lambda: bool(tool_nodes(master)), what="echo's node")
    latch(make_node("/late_talker"), "/ns/chatter", String("late"))
    result = echo()
    assert result.status == 0
    assert result.err == "WARNING: topic [/ns/chatter] does not appear to be published yet\n"
    assert result.out == 'data: "late"\n---\n'


def test_echo_filter_that_fails_is_reported_once(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/e/filtered", String("x"))
    result = run_for(
        master,
        0.5,
        "rostopic",
        "echo",
        "--filter",
        "m.nope",
        "/e/filtered",
        environ=env,
        until=_lines(1, "err"),
    )
    assert (result.status, result.out) == (0, "")
    assert result.err == (
        "ERROR: filter expression 'm.nope' failed: "
        "AttributeError: 'String' object has no attribute 'nope'\n"
    )


def test_echo_bad_index_is_reported_per_message(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/e/short", FloatArray(data=[1.0]))
    result = run_for(
        master, 0.5, "rostopic", "echo", "/e/short/data[3]", environ=env, until=_lines(1, "err")
    )
    assert (result.status, result.out) == (0, "")
    lines = result.err.splitlines()
    assert lines and set(lines) == {"tuple index out of range: /data[3]"}


@pytest.mark.parametrize("path", ["/e/pose/linear/x/y", "/e/polygon/points/x"])
def test_echo_of_a_path_the_type_lacks_waits_for_the_topic_as_ros1(
    stream: Callable[..., None], env: dict[str, str], master: str, path: str
) -> None:
    stream("/e/pose", twist())
    stream("/e/polygon", get_message_class("geometry_msgs/Polygon")())
    result = run_for(master, 0.5, "rostopic", "echo", path, environ=env, until=_lines(1, "err"))
    assert (result.status, result.out) == (0, "")
    assert result.err == f"WARNING: topic [{path}] does not appear to be published yet\n"


# -- pub -----------------------------------------------------------------------------------


def test_pub_then_echo_round_trip(env: dict[str, str], master: str) -> None:
    echo = in_thread("rostopic", "echo", "-n", "1", "/p/round", environ=env)
    wait_for(lambda: bool(tool_nodes(master)), what="echo's node")
    result = rosx(
        "rostopic", "pub", "-1", "/p/round", "geometry_msgs/Twist",
        "{linear: {x: 1.5}, angular: {z: -0.5}}", environ=env,
    )  # fmt: skip
    assert (result.status, result.out, result.err) == (
        0,
        "publishing and latching message for 3.0 seconds\n",
        "",
    )
    assert echo().out == TWIST_TEXT
    assert not tool_nodes(master)


def test_pub_once_leaves_when_the_subscriber_has_the_message(
    make_node: Callable[[str], Node], env: dict[str, str]
) -> None:
    got: list[Any] = []
    make_node("/once_listener").subscribe("/p/once", Int32, got.append)
    result = rosx("rostopic", "pub", "-1", "/p/once", "std_msgs/Int32", "42", environ=env)
    assert result.status == 0
    wait_for(lambda: bool(got), what="the message")
    assert [m.data for m in got] == [42]


def test_pub_positional_dict_and_keywords(
    make_node: Callable[[str], Node], env: dict[str, str]
) -> None:
    got: list[Any] = []
    make_node("/kw_listener").subscribe("/p/kw", PointStamped, got.append)
    before = time.time()
    result = rosx(
        "rostopic", "pub", "-1", "/p/kw", "geometry_msgs/PointStamped", "auto", "[1, 2, 3]",
        environ=env,
    )  # fmt: skip
    assert result.status == 0, result.err
    wait_for(lambda: bool(got), what="the message")
    msg = got[0]
    assert (msg.point.x, msg.point.y, msg.point.z) == (1.0, 2.0, 3.0)
    assert msg.header.stamp.to_sec() >= int(before)


def test_pub_from_stdin_and_file(
    make_node: Callable[[str], Node], env: dict[str, str], tmp_path: Path
) -> None:
    got: list[str] = []
    make_node("/doc_listener").subscribe("/p/docs", String, lambda m: got.append(m.data))
    result = rosx(
        "rostopic", "pub", "-r", "50", "/p/docs", "std_msgs/String",
        stdin="data: one\n---\ndata: two\n---\ndata: dropped\n", environ=env,
    )  # fmt: skip
    assert result.status == 0, result.err
    assert result.out == "publishing and latching message for 3.0 seconds\n" * 2
    wait_for(lambda: got == ["one", "two"], what="both documents")
    path = tmp_path / "msgs.yaml"
    path.write_text("data: three\n---\ndata: four\n")
    result = rosx(
        "rostopic", "pub", "-r", "50", "-f", str(path), "/p/docs", "std_msgs/String", environ=env
    )
    assert result.status == 0, result.err
    wait_for(lambda: got[2:] == ["three", "four"], what="the file's documents")


def test_pub_latched_stays_until_killed(env: dict[str, str], master: str) -> None:
    result = run_for(
        master, 0.3, "rostopic", "pub", "/p/latched", "std_msgs/String", "hi", environ=env
    )
    assert (result.status, result.out, result.err) == (
        0,
        "publishing and latching message. Press ctrl-C to terminate\n",
        "",
    )


def test_pub_node_follows_its_remapping_arguments(env: dict[str, str], master: str) -> None:
    """As rospy's init_node: ``__name:=``/``__ns:=`` name the node (as rostest launches it),
    ``from:=to`` remaps the topic, ``_param:=`` sets a private parameter."""
    client = XmlRpcClient(timeout=2)
    argv = ["/remap/from", "std_msgs/String", "hi", "/remap/from:=/remap/to"]
    result = in_thread(
        "rostopic", "pub", *argv, "__name:=pubber", "__ns:=/tools", "_hint:=3", environ=env
    )

    def publishers() -> list[Any]:
        found: list[Any] = client.call(master, "getSystemState", "/test")[2][0]
        return found

    wait_for(lambda: ["/remap/to", ["/tools/pubber"]] in publishers(), what="/tools/pubber")
    assert client.call(master, "getParam", "/test", "/tools/pubber/hint")[2] == 3
    uri = client.call(master, "lookupNode", "/test", "/tools/pubber")[2]
    client.call(uri, "shutdown", "/test", "test over")
    assert result().status == 0


@pytest.mark.parametrize(
    ("argv", "status", "err"),
    [
        (["/p/x"], 2, "Usage: rostopic pub /topic type [args...]\n\nrostopic: error: topic type must be specified\n"),
        (["-r", "2", "-1", "/p/x", "std_msgs/Int32", "1"], 2, "Usage: rostopic pub /topic type [args...]\n\nrostopic: error: You cannot select both -r and -1 (--once)\n"),
        (["-r", "x", "/p/x", "std_msgs/Int32", "1"], 2, "Usage: rostopic pub /topic type [args...]\n\nrostopic: error: rate must be a number\n"),
        # As genpy looks the class up: not package/Type is an invalid topic type...
        (["/p/x", "foo"], 1, "ERROR: invalid topic type: foo\n"),
        (["/p/x", "/String"], 1, "ERROR: invalid topic type: /String\n"),
        (["/p/x", "std_msgs/String/x"], 1, "ERROR: invalid topic type: std_msgs/String/x\n"),
        # ... and any other type it cannot find, an invalid message type, known package or not.
        (["/p/x", "std_msgs/Nope"], 1, "ERROR: invalid message type: std_msgs/Nope.\nIf this is a valid message type, perhaps you need to type 'rosmake std_msgs'\n"),
        (["/p/x", "std_msgs/"], 1, "ERROR: invalid message type: std_msgs/.\nIf this is a valid message type, perhaps you need to type 'rosmake std_msgs'\n"),
        (["/p/x", "geometry_msgs/twist"], 1, "ERROR: invalid message type: geometry_msgs/twist.\nIf this is a valid message type, perhaps you need to type 'rosmake geometry_msgs'\n"),
        (["/p/x", "nope_msgs/Nope"], 1, "ERROR: invalid message type: nope_msgs/Nope.\nIf this is a valid message type, perhaps you need to type 'rosmake nope_msgs'\n"),
        (["/p/x", "geometry_msgs/Point", "{x:5}"], 1, "ERROR: No field name [x:5]: YAML needs a space after the colon, write {x: 5}\n\nArgs are: [x y z]\n"),
        (["/p/x", "std_msgs/Int32", "1", "2"], 1, "ERROR: Too many arguments:\n * Given: [1, 2]\n * Expected: ['data']\n\nArgs are: [data]\n"),
        (["/p/x", "std_msgs/Int32", "-f", "/nonexistent.yaml"], 1, "ERROR: file does not exist: /nonexistent.yaml\n"),
    ],
)  # fmt: skip
def test_pub_errors(env: dict[str, str], argv: list[str], status: int, err: str) -> None:
    result = rosx("rostopic", "pub", *argv, environ=env)
    assert (result.status, result.out, result.err) == (status, "", err)


@pytest.mark.parametrize(
    "argv",
    [["echo", "-n", "1", "/unknown_typed/field"], ["type", "/unknown_typed/field"]],
)
def test_a_field_of_a_type_nobody_here_knows_cannot_be_loaded(
    env: dict[str, str], master: str, argv: list[str]
) -> None:
    client = XmlRpcClient(timeout=5)
    api = "http://127.0.0.1:9/"
    client.call(master, "registerPublisher", "/odd", "/unknown_typed", "nope_msgs/Nope", api)
    try:
        result = rosx("rostopic", *argv, environ=env)
    finally:
        client.call(master, "unregisterPublisher", "/odd", "/unknown_typed", api)
        client.close()
    cannot = "ERROR: Cannot load message class for [nope_msgs/Nope]. Are your messages built?\n"
    assert (result.status, result.out, result.err) == (1, "", cannot)


@pytest.mark.parametrize(
    ("name", "status", "out", "err"),
    [
        ("/t/scan/ranges[1]", 0, "sensor_msgs/LaserScan ranges[1] float32\n", ""),
        ("/t/scan/header/stamp/secs", 0, "sensor_msgs/LaserScan header/stamp/secs int32\n", ""),
        (
            "/t/tf/transforms[0]",
            0,
            "tf2_msgs/TFMessage transforms[0] geometry_msgs/TransformStamped\n",
            "",
        ),
        (
            "/t/tf/transforms[0]/header",
            0,
            "tf2_msgs/TFMessage transforms[0]/header std_msgs/Header\n",
            "",
        ),
        ("/t/scan/ranges/x", 1, "", "unknown topic type [/t/scan/ranges/x]\n"),
        ("/t/tf/transforms/header", 1, "", "unknown topic type [/t/tf/transforms/header]\n"),
        ("/t/tf/transforms[0]/nope", 1, "", "unknown topic type [/t/tf/transforms[0]/nope]\n"),
    ],
)
def test_type_of_a_field_or_an_element(
    env: dict[str, str], master: str, name: str, status: int, out: str, err: str
) -> None:
    client = XmlRpcClient(timeout=5)
    api = "http://127.0.0.1:9/"
    topics = {"/t/scan": "sensor_msgs/LaserScan", "/t/tf": "tf2_msgs/TFMessage"}
    for topic, type_name in topics.items():
        client.call(master, "registerPublisher", "/odd", topic, type_name, api)
    try:
        result = rosx("rostopic", "type", name, environ=env)
    finally:
        for topic in topics:
            client.call(master, "unregisterPublisher", "/odd", topic, api)
        client.close()
    assert (result.status, result.out, result.err) == (status, out, err)


def test_pub_value_of_the_wrong_type(env: dict[str, str]) -> None:
    result = rosx("rostopic", "pub", "-1", "/p/wrong", "std_msgs/Int32", "hello", environ=env)
    assert result.status == 1
    assert result.err == (
        "ERROR: Unable to publish message. One of the fields has an incorrect type:\n"
        "  field data must be an integer type\n\nmsg file:\nint32 data\n\n"
    )


def test_pub_bad_yaml_is_a_usage_error(env: dict[str, str]) -> None:
    result = rosx("rostopic", "pub", "/p/x", "std_msgs/Int32", "{a", environ=env)
    assert result.status == 2
    assert result.err.startswith(
        "Usage: rostopic pub /topic type [args...]\n\nrostopic: error: Argument error: "
        "while parsing a flow mapping\n"
    )


# -- hz, bw, delay -------------------------------------------------------------------------


def test_hz_reports_every_second(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/r/hz", Int32(1), hz=20)
    result = run_for(master, 2.3, "rostopic", "hz", "/r/hz", environ=env, until=_lines(5))
    assert result.status == 0, result.err
    lines = result.out.splitlines()
    assert lines[0] == "subscribed to [/r/hz]"
    reports = lines[1:]
    assert len(reports) >= 2 and len(reports) % 2 == 0
    for rate_line, detail in zip(reports[::2], reports[1::2], strict=True):
        match = re.fullmatch(r"average rate: (\d+\.\d{3})", rate_line)
        assert match and 5 < float(match[1]) < 40
        assert re.fullmatch(
            r"\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: \d+", detail
        )


def test_hz_measures_in_simulated_time_unless_told_the_wall(
    env: dict[str, str], master: str, make_node: Callable[[str], Node]
) -> None:
    """With /use_sim_time set, ROS 1's rostopic hz measures gaps on /clock: 20 messages a
    wall second, half a simulated second apart, are 2 a simulated second; --wall-time 20."""
    node = make_node("/simulator")
    node.params.set("/use_sim_time", True)
    clock = node.advertise("/clock", get_message_class("rosgraph_msgs/Clock"), queue_size=10)
    data = node.advertise("/r/sim", Int32, queue_size=10)
    stop = threading.Event()

    def run() -> None:
        seconds = 100.0
        while not stop.wait(0.05):
            seconds += 0.5
            clock.publish(get_message_class("rosgraph_msgs/Clock")(clock=Time.from_sec(seconds)))
            data.publish(Int32(1))

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    try:
        rates = {}
        for extra in ([], ["--wall-time"]):
            result = run_for(
                master, 2.3, "rostopic", "hz", *extra, "/r/sim", environ=env, until=_lines(3)
            )
            assert result.status == 0, result.err
            assert result.err == "WARNING: may be using simulated time\n"
            found = re.search(r"average rate: (\d+\.\d{3})", result.out)
            assert found, result.out
            rates[bool(extra)] = float(found[1])
    finally:
        stop.set()
        thread.join()
        node.params.delete("/use_sim_time")  # the master is the module's
    assert 1.0 < rates[False] < 4.0  # simulated time: 2 a second
    assert rates[True] > 6.0  # the wall clock's 20 a second, give or take a busy machine


def test_hz_says_when_simulated_time_restarts(
    env: dict[str, str], master: str, make_node: Callable[[str], Node]
) -> None:
    """ROS time back at 0 after rates were measured (a simulator restarted): ROS 1's rostopic
    hz prints that the counters were reset, once, and leaves such messages out."""
    node = make_node("/restarting_simulator")
    node.params.set("/use_sim_time", True)
    clock_type = get_message_class("rosgraph_msgs/Clock")
    clock = node.advertise("/clock", clock_type, queue_size=10)
    data = node.advertise("/r/restart", Int32, queue_size=10)
    stop, restarted = threading.Event(), threading.Event()

    def run() -> None:
        seconds = 100.0
        while not stop.wait(0.05):
            seconds = 0.0 if restarted.is_set() else seconds + 0.5
            clock.publish(clock_type(clock=Time.from_sec(seconds)))
            data.publish(Int32(1))

    def measured_then_reset(out: str, err: str) -> bool:
        if "average rate" in out:
            restarted.set()
        # One report after it: what hz says of messages that come while time reads 0.
        return "\n" in out.partition("time has reset, resetting counters\n")[2]

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    try:
        result = run_for(
            master, 1.5, "rostopic", "hz", "/r/restart", environ=env, until=measured_then_reset
        )
    finally:
        stop.set()
        thread.join()
        node.params.delete("/use_sim_time")  # the master is the module's
    assert result.status == 0, result.err
    lines = result.out.splitlines()
    assert lines.count("time has reset, resetting counters") == 1, result.out
    after = lines[lines.index("time has reset, resetting counters") + 1 :]
    assert after and set(after) == {"no new messages"}, result.out


def test_hz_of_several_topics_prints_a_table(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/r/a", Int32(1), hz=20)
    stream("/r/bb", String("x"), hz=10)
    result = run_for(master, 2.3, "rostopic", "hz", "/r/a", "/r/bb", environ=env, until=_lines(7))
    assert result.status == 0, result.err
    lines = result.out.splitlines()
    assert lines[:2] == ["subscribed to [/r/a]", "subscribed to [/r/bb]"]
    header = lines[2]
    assert re.fullmatch(r"topic +rate +min_delta +max_delta +std_dev +window", header)
    assert lines[3] == "=" * len(header)
    assert re.match(r"/r/a +\d", lines[4]) and re.match(r"/r/bb +\d", lines[5])
    assert lines[6] == ""


def test_hz_with_a_filter_counts_matching_messages(
    stream: Callable[..., None], env: dict[str, str], master: str
) -> None:
    stream("/r/filtered", Int32(7), hz=20)
    stream("/r/matching", Int32(8), hz=20)
    for topic, matching in (("/r/filtered", False), ("/r/matching", True)):
        result = run_for(
            master,
            2.3,
            "rostopic",
            "hz",
            "--filter",
            "m.data == 8",
            topic,
            environ=env,
            until=_lines(2),
        )
        lines = result.out.splitlines()
        assert (result.status, lines[0]) == (0, f"subscribed to [{topic}]")
        assert lines[1:]
        if matching:
            assert lines[1].startswith("average rate: ")
        else:
            assert set(lines[1:]) == {"no new messages"}


def test_bw_reports_sizes(stream: Callable[..., None], env: dict[str, str], master: str) -> None:
    stream("/r/bw", stamped(), hz=20)
    result = run_for(master, 2.3, "rostopic", "bw", "/r/bw", environ=env, until=_lines(3))
    lines = result.out.splitlines()
    assert result.status == 0 and lines[0] == "subscribed to [/r/bw]"
    assert len(lines) >= 3
    for rate_line, detail in zip(lines[1::2], lines[2::2], strict=False):
        match = re.fullmatch(r"average: (\d+\.\d\d)B/s", rate_line)
        assert match and 200 < float(match[1]) < 2000  # 43 bytes, about 20 times a second
        assert re.fullmatch(r"\tmean: 43\.00B min: 43\.00B max: 43\.00B window: \d+", detail)


def test_delay_reports_header_delays(
    stream: Callable[..., None], env: dict[str, str], master: str, make_node: Callable[[str], Node]
) -> None:
    node = make_node("/stamper")
    publisher = node.advertise("/r/delay", PointStamped, queue_size=10)
    stop = threading.Event()

    def run() -> None:
        while not stop.wait(0.05):
            msg = PointStamped()
            msg.header.stamp = Time.from_sec(time.time() - 0.25)
            publisher.publish(msg)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    try:
        result = run_for(master, 2.3, "rostopic", "delay", "/r/delay", environ=env, until=_lines(3))
    finally:
        stop.set()
        thread.join()
    lines = result.out.splitlines()
    assert result.status == 0 and lines[0] == "subscribed to [/r/delay]"
    match = re.fullmatch(r"average delay: (\d+\.\d{3})", lines[1])
    assert match and 0.2 <= float(match[1]) < 1.0
    assert re.fullmatch(
        r"\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: \d+", lines[2]
    )


# -- errors and ending ---------------------------------------------------------------------


@pytest.mark.parametrize(
    "argv",
    [
        ["echo", "/x"],
        ["pub", "/x", "std_msgs/String", "hi"],
        ["hz", "/x"],
        ["bw", "/x"],
        ["delay", "/x"],
    ],
)
def test_master_down_is_ros1_error(argv: list[str]) -> None:
    result = rosx(
        "rostopic", *argv, environ=clean_environ(ROS_MASTER_URI=f"http://localhost:{free_port()}")
    )
    assert result.status == 1
    assert result.err.startswith("ERROR: Unable to communicate with master!\n")
    assert "Traceback" not in result.err


@pytest.mark.parametrize(
    ("argv", "err"),
    [
        (["echo"], "Usage: rostopic echo [options] /topic\n\nrostopic: error: topic must be specified\n"),
        (["echo", "-w", "1", "/x"], "Usage: rostopic echo [options] /topic\n\nrostopic: error: Fixed width for numeric values must be at least 2\n"),
        (["echo", "-n", "x", "/x"], "Usage: rostopic echo [options] /topic\n\nrostopic: error: COUNT must be an integer\n"),
        (["echo", "/x", "/y"], "Usage: rostopic echo [options] /topic\n\nrostopic: error: you may only specify one input topic\n"),
        (["hz"], "Usage: rostopic hz [options] /topic_0 [/topic_1 [topic_2 [..]]]\n\nrostopic: error: topic must be specified\n"),
        (["hz", "-w", "x", "/x"], "Usage: rostopic hz [options] /topic_0 [/topic_1 [topic_2 [..]]]\n\nrostopic: error: window size must be an integer\n"),
        (["bw", "/x", "/y"], "Usage: rostopic bw /topic\n\nrostopic: error: you may only specify one input topic\n"),
        (["delay"], "usage: rostopic delay [options] /topic\nrostopic: error: the following arguments are required: topic\n"),
    ],
)  # fmt: skip
def test_usage_errors(env: dict[str, str], argv: list[str], err: str) -> None:
    result = rosx("rostopic", *argv, environ=env)
    assert (result.status, result.out, result.err) == (2, "", err)


def test_echo_from_a_missing_bag_says_so(env: dict[str, str]) -> None:
    result = rosx("rostopic", "echo", "-b", "x.bag", "/x", environ=env)
    assert (result.status, result.err) == (1, "ERROR: bag file [x.bag] does not exist\n")


def test_ctrl_c_exits_quietly_and_unregisters(master: str) -> None:
    with rosx_popen("rostopic", "echo", "/c/never", ROS_MASTER_URI=master) as process:
        wait_for(lambda: bool(tool_nodes(master)), what="echo's node")
        assert process.stderr is not None
        warning = process.stderr.readline()  # echo is waiting for the topic once this is out
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=15)
    assert process.returncode == 0
    assert (out, warning + err) == (
        "",
        "WARNING: topic [/c/never] does not appear to be published yet\n",
    )
    assert not tool_nodes(master)


REPORT = r"\tmin: \d+\.\d{3}s max: \d+\.\d{3}s std dev: \d+\.\d{5}s window: \d+\n"


@pytest.mark.parametrize(
    ("command", "last"),
    [
        ("hz", rf"(average rate: \d+\.\d{{3}}\n{REPORT}|no new messages\n)"),
        ("bw", r"average: \d+\.\d\dB/s\n\tmean: 43\.00B min: 43\.00B max: 43\.00B window: \d+\n"),
        ("delay", rf"(average delay: \d+\.\d{{3}}\n{REPORT}|no new messages\n)"),
    ],
)
def test_ctrl_c_prints_a_last_report_as_ros1(
    stream: Callable[..., None], master: str, command: str, last: str
) -> None:
    stream("/c/rated", stamped(), hz=20)
    with rosx_popen("rostopic", command, "/c/rated", ROS_MASTER_URI=master) as process:
        assert process.stdout is not None
        assert process.stdout.readline() == "subscribed to [/c/rated]\n"
        while not process.stdout.readline().startswith("\t"):  # a whole report is out
            pass
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=15)
    assert (process.returncode, err) == (0, "")
    assert re.fullmatch(last, out), out


def test_pub_once_waits_its_time_when_the_master_goes_away() -> None:
    """``rostopic pub -1`` asks the master who subscribes; a master gone meanwhile is no error
    (it waits its full time, as with no subscriber listed)."""
    from types import SimpleNamespace

    from rosx_commands.context import Environment
    from rosx_commands.rostopic.publishing import Publishing
    from rosx_commands.rostopic.session import Session

    env = Environment(environ=clean_environ(ROS_MASTER_URI=f"http://127.0.0.1:{free_port()}"))
    publisher: Any = SimpleNamespace(data_class=None)
    publishing = Publishing(env, Session(env), publisher)
    assert publishing._known_subscribers() is None
