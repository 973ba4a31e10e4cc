"""rosx rostopic echo / pub against a real ROS 1 graph: same text, messages both ways."""

from __future__ import annotations

import contextlib
import re
import subprocess
import sys
import threading
import xmlrpc.client
from collections.abc import Iterator
from typing import Any

import pytest

from tests.support.cli import Result, clean_environ, rosx
from tests.support.procs import running, stop, wait_for
from tests.support.ros1 import ROS1_PYTHON, ROSCORES, needs_ros1, ros1_environ, roscore, run_ros1

pytestmark = needs_ros1

#: A rospy node latching one message on each topic (so every echo sees the same ones), and
#: publishing /ros1/count at 20 Hz.
TALKER = """
import rospy
from std_msgs.msg import String, Float32MultiArray, MultiArrayDimension, Empty
from geometry_msgs.msg import Twist, PointStamped, PoseArray, Pose
from sensor_msgs.msg import Image, LaserScan
from std_msgs.msg import Int32
rospy.init_node('stream_talker')
def latched(topic, cls):
    return rospy.Publisher(topic, cls, queue_size=1, latch=True)
latched('/ros1/string', String).publish(String('hello "world"'))
t = Twist(); t.linear.x = 2.0; t.angular.z = -1.8
latched('/ros1/twist', Twist).publish(t)
p = PointStamped(); p.header.stamp = rospy.Time(1700000000, 5000); p.header.frame_id = 'map'
p.point.x = 0.1
latched('/ros1/point', PointStamped).publish(p)
a = Float32MultiArray(data=[0.1, 2.5, -3.0])
a.layout.dim = [MultiArrayDimension('x', 3, 3)]
latched('/ros1/array', Float32MultiArray).publish(a)
i = Image(height=1, width=3, encoding='mono8', step=3, data=bytes([1, 2, 250]))
latched('/ros1/image', Image).publish(i)
s = LaserScan(ranges=[1.0, 1.5], intensities=[], range_max=10.0)
latched('/ros1/scan', LaserScan).publish(s)
pa = PoseArray(poses=[Pose(), Pose()]); pa.poses[1].position.y = 4.0
latched('/ros1/poses', PoseArray).publish(pa)
latched('/ros1/empty', Empty).publish(Empty())
count = rospy.Publisher('/ros1/count', Int32, queue_size=10)
rate = rospy.Rate(20)
n = 0
while not rospy.is_shutdown():
    count.publish(Int32(n)); n += 1
    rate.sleep()
"""

LISTENER = """
import sys, rospy
from std_msgs.msg import String
rospy.init_node('stream_listener')
def got(msg):
    print('got ' + msg.data, flush=True)
    rospy.signal_shutdown('done')
rospy.Subscriber('/rosx/to_rospy', String, got)
print('ready', flush=True)
rospy.spin()
"""

#: A rospy node that prints what ``/rosout_agg`` carries from ``/once_probe``, once connected.
AGG_LISTENER = """
import rospy
from rosgraph_msgs.msg import Log
rospy.init_node('agg_listener')
def got(msg):
    if msg.name == '/once_probe':
        print('got ' + msg.msg, flush=True)
        rospy.signal_shutdown('done')
sub = rospy.Subscriber('/rosout_agg', Log, got)
while sub.get_num_connections() == 0 and not rospy.is_shutdown():
    rospy.sleep(0.01)
print('ready', flush=True)
rospy.spin()
"""


@pytest.fixture(scope="module", params=ROSCORES)
def graph(request: pytest.FixtureRequest) -> Iterator[str]:
    """A roscore (ROS 1's or rosx's) with the rospy talker; yields the master URI."""
    with roscore(request.param) as uri:
        env = ros1_environ(ROS_MASTER_URI=uri)
        with running([ROS1_PYTHON, "-c", TALKER], env):
            wait_for(
                lambda: "/ros1/count" in run_ros1(["rostopic", "list"], ROS_MASTER_URI=uri).stdout,
                what="the rospy talker",
            )
            yield uri


ECHOES = [
    ["/ros1/string"],
    ["/ros1/twist"],
    ["/ros1/twist/angular"],
    ["/ros1/twist/linear/x"],
    ["/ros1/point"],
    ["/ros1/point/header/stamp"],
    ["--offset", "/ros1/point/point"],
    ["-w", "4", "/ros1/point"],
    ["/ros1/array"],
    ["--noarr", "/ros1/array"],
    ["/ros1/array/data[1:]"],
    ["/ros1/array/layout/dim[0]/label"],
    ["/ros1/image"],
    ["--nostr", "/ros1/image"],
    ["/ros1/scan"],
    ["/ros1/poses"],
    ["/ros1/poses/poses[1]/position"],
    ["--noarr", "/ros1/poses"],
    ["/ros1/empty"],
    ["-p", "/ros1/point"],
    ["-p", "--nostr", "/ros1/image"],
    ["-p", "/ros1/poses"],
    ["-c", "/ros1/string"],
    ["--filter", "'world' in m.data", "/ros1/string"],
]


def without_seq(text: str) -> str:
    """rospy numbers a latched message anew for each subscriber: ``header.seq`` differs."""
    text = re.sub(r"(seq: *)\d+", r"\1N", text)
    if text.startswith("%time,field.header.seq,"):
        text = re.sub(r"^(\d+),\d+,", r"\1,N,", text, flags=re.MULTILINE)
    return text


@pytest.mark.parametrize("args", ECHOES, ids=" ".join)
def test_echo_prints_what_ros1_prints(graph: str, args: list[str]) -> None:
    argv = ["rostopic", "echo", "-n", "1", *args]
    ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert (without_seq(ours.out), ours.err, ours.status) == (
        without_seq(ros1.stdout),
        ros1.stderr,
        ros1.returncode,
    )


def test_echo_of_a_uint8_array_field_prints_numbers_where_ros1_fails(graph: str) -> None:
    argv = ["rostopic", "echo", "-n", "1", "/ros1/image/data"]
    ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert "Traceback" in ros1.stderr  # Python 3's bytes break ROS 1's uint8[] conversion
    assert (ours.out, ours.err, ours.status) == ("[1, 2, 250]\n---\n", "", 0)


def test_echo_csv_of_a_stream_has_ros1_columns(graph: str) -> None:
    argv = ["rostopic", "echo", "-n", "3", "-p", "/ros1/count"]
    ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
    ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    assert ours.status == ros1.returncode == 0
    ours_lines, ros1_lines = ours.out.splitlines(), ros1.stdout.splitlines()
    assert ours_lines[0] == ros1_lines[0] == "%time,field.data"
    assert len(ours_lines) == len(ros1_lines) == 4
    for line in ours_lines[1:]:
        stamp, value = line.split(",")
        assert stamp.isdigit() and value.isdigit()


def test_rosx_pub_reaches_ros1_echo(graph: str) -> None:
    env = ros1_environ(ROS_MASTER_URI=graph)
    with subprocess.Popen(
        ["rostopic", "echo", "-n", "1", "/rosx/twist"],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    ) as echo:
        try:
            # ROS 1's echo starts its node, then waits for the topic to be published.
            wait_for(
                lambda: "/rostopic_" in run_ros1(["rosnode", "list"], ROS_MASTER_URI=graph).stdout,
                what="ROS 1's echo to start",
            )
            ours = rosx(
                "rostopic", "pub", "-1", "/rosx/twist", "geometry_msgs/Twist",
                "{linear: {x: 2.0}, angular: {z: 1.8}}",
                environ=clean_environ(ROS_MASTER_URI=graph),
            )  # fmt: skip
            out, _ = echo.communicate(timeout=20)
        finally:
            stop(echo)
    assert ours.status == 0
    assert ours.out == "publishing and latching message for 3.0 seconds\n"
    assert out == (
        "linear: \n  x: 2.0\n  y: 0.0\n  z: 0.0\nangular: \n  x: 0.0\n  y: 0.0\n  z: 1.8\n---\n"
    )


def test_ros1_pub_once_reaches_rosx_echo(graph: str) -> None:
    env = ros1_environ(ROS_MASTER_URI=graph)
    with running(
        ["rostopic", "pub", "-1", "/ros1/once", "std_msgs/String", "data: from ROS 1"], env
    ):
        ours = rosx(
            "rostopic", "echo", "-n", "1", "/ros1/once", environ=clean_environ(ROS_MASTER_URI=graph)
        )
    assert (ours.status, ours.out) == (0, 'data: "from ROS 1"\n---\n')
    assert "does not appear to be published yet" in ours.err or ours.err == ""


@contextlib.contextmanager
def rospy_listener(graph: str, script: str) -> Iterator[subprocess.Popen[str]]:
    """A rospy node running ``script`` on ``graph``, once it has printed ``ready``; stopped
    after the block."""
    with subprocess.Popen(
        [ROS1_PYTHON, "-c", script],
        env=ros1_environ(ROS_MASTER_URI=graph),
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        start_new_session=True,
    ) as listener:
        try:
            assert listener.stdout is not None
            assert listener.stdout.readline() == "ready\n"
            yield listener
        finally:
            stop(listener)


def pub_once_to_rospy(graph: str, listener_script: str, *pub_args: str) -> tuple[Result, str]:
    """Start a rospy listener, wait for its ``ready`` line, run ``rosx rostopic pub -1
    PUB_ARGS…``; return that run and what the listener printed until it ended."""
    with rospy_listener(graph, listener_script) as listener:
        ours = rosx("rostopic", "pub", "-1", *pub_args, environ=clean_environ(ROS_MASTER_URI=graph))
        out, _ = listener.communicate(timeout=20)
    return ours, out


def test_rosx_pub_once_waits_for_a_rospy_subscriber_to_get_it(graph: str) -> None:
    ours, out = pub_once_to_rospy(graph, LISTENER, "/rosx/to_rospy", "std_msgs/String", "hi there")
    assert ours.status == 0
    assert out == "got hi there\n"
    # The tool's node is gone from the graph once it exits.
    nodes = run_ros1(["rosnode", "list"], ROS_MASTER_URI=graph).stdout.split()
    assert not [n for n in nodes if n.startswith("/rostopic_")]


def test_pub_errors_match_ros1(graph: str) -> None:
    for argv in (
        ["rostopic", "pub", "/ros1/bad", "geometry_msgs/Twist", "1", "2"],
        ["rostopic", "pub", "/ros1/bad", "std_msgs/Int32", "1", "2"],
        ["rostopic", "pub", "/ros1/bad", "std_msgs/Nope", "1"],
        ["rostopic", "pub", "/ros1/bad", "nope_msgs/Nope", "1"],
        ["rostopic", "pub", "/ros1/bad", "std_msgs/", "1"],
        ["rostopic", "pub", "/ros1/bad", "roscpp/Nope", "1"],
        ["rostopic", "pub", "/ros1/bad", "/String", "1"],
        ["rostopic", "pub", "/ros1/bad", "String", "1"],
        ["rostopic", "pub", "/ros1/bad", "std_msgs/String/x", "1"],
        ["rostopic", "pub", "-r", "0", "/ros1/bad", "std_msgs/Int32", "1"],
        ["rostopic", "pub", "/ros1/bad", "std_msgs/Int32", "{a"],
    ):
        ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
        ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
        if argv[4:] == ["1", "2"] and argv[3] == "geometry_msgs/Twist":
            # ROS 1 fails with a traceback here; rosx says what is wrong, in ROS 1's words.
            assert ros1.returncode == ours.status == 1
            assert ours.err.startswith("ERROR: invalid msg_args type: 1\n\nArgs are: [linear.x")
            continue
        assert (ours.out, ours.err, ours.status) == (ros1.stdout, ros1.stderr, ros1.returncode)


def test_echo_of_a_field_of_an_unknown_type_matches_ros1(graph: str) -> None:
    api = "http://127.0.0.1:9/"
    proxy = xmlrpc.client.ServerProxy(graph)
    proxy.registerPublisher("/odd", "/ros1/unknown_typed", "nope_msgs/Nope", api)
    try:
        argv = ["rostopic", "echo", "-n", "1", "/ros1/unknown_typed/field"]
        ros1 = run_ros1(argv, ROS_MASTER_URI=graph)
        ours = rosx(*argv, environ=clean_environ(ROS_MASTER_URI=graph))
    finally:
        proxy.unregisterPublisher("/odd", "/ros1/unknown_typed", api)
    assert (ours.out, ours.err, ours.status) == (ros1.stdout, ros1.stderr, ros1.returncode)
    assert ours.err.startswith("ERROR: Cannot load message class for [nope_msgs/Nope]")


#: Feeds ROS 1's own hz/bw/delay bookkeeping fixed arrival times (its clocks patched) and
#: prints its reports as JSON: after each arrival listed in REPORT_AT, 10 ms later.
ROS1_STATS = """
import contextlib, io, json, types
import rospy, rostopic
clock = [0.0]
rospy.get_rostime = lambda: rospy.Time.from_sec(clock[0])
rostopic.time = types.SimpleNamespace(time=lambda: clock[0])
ARRIVALS, REPORT_AT = %s, %s
def report(call):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        call()
    return out.getvalue()
hz, hz3, bw = rostopic.ROSTopicHz(-1), rostopic.ROSTopicHz(3), rostopic.ROSTopicBandwidth(4)
delay = rostopic.ROSTopicDelay(-1)
reports = []
for index, (topic, when, size) in enumerate(ARRIVALS):
    clock[0] = when
    hz.callback_hz(None, topic)
    hz3.callback_hz(None, topic)
    bw.callback(types.SimpleNamespace(_buff=b'x' * size))
    stamp = rospy.Time.from_sec(when - size / 1000.0)
    delay.callback_delay(types.SimpleNamespace(_has_header=True, header=types.SimpleNamespace(stamp=stamp)))
    if index in REPORT_AT:
        clock[0] = when + 0.01
        reports.append([report(lambda: hz.print_hz(['/a', '/bb'])), report(lambda: hz.print_hz(['/a'])),
                        report(lambda: hz3.print_hz(['/bb'])), report(bw.print_bw),
                        report(delay.print_delay)])
print(json.dumps(reports))
"""


def test_hz_bw_delay_reports_match_ros1() -> None:
    from rosx.msg.codec.rostime import Time
    from rosx.node.stats import BandwidthTracker, DelayTracker, HzTracker
    from tests.support.ros1 import ros1_python

    arrivals = [
        (
            "/a" if i % 3 else "/bb",
            round(100 + 0.1 * i + 0.003 * (i % 4), 3),
            40 + 700 * (i % 2) * i,
        )
        for i in range(1, 27)
    ]
    report_at = [0, 1, 4, 9, 10, 24, 25]
    expected = ros1_python(ROS1_STATS % (arrivals, report_at))
    hz, hz3, bw, delay = HzTracker(-1), HzTracker(3), BandwidthTracker(4), DelayTracker(-1)
    reports = []
    for index, (topic, when, size) in enumerate(arrivals):
        # ROS 1 reads its clock as a rospy.Time: whole nanoseconds.
        now = Time.from_sec(when).to_sec()
        hz.arrived(topic, now)
        hz3.arrived(topic, now)
        bw.arrived(size, when)
        delay.arrived(now, Time.from_sec(when - size / 1000.0).to_sec())
        if index in report_at:
            texts: list[str | None] = [hz.report(["/a", "/bb"]), hz.report(["/a"])]
            texts.append(hz3.report(["/bb"]))
            texts += [bw.report(when + 0.01), delay.report()]
            reports.append(["" if t is None else t + "\n" for t in texts])
    assert reports == expected


def test_rosx_pub_once_reaches_the_rosout_node(graph: str) -> None:
    """ROS 1's rosout is roscpp, which drops a publisher's connection as soon as the master
    says the publisher left: the message of a ``rostopic pub -1`` that leaves before its 3 s
    must still reach it, and so ``/rosout_agg``."""

    def rosout_subscribed() -> bool:
        state: Any = xmlrpc.client.ServerProxy(graph).getSystemState("/test")
        return ["/rosout", ["/rosout"]] in state[2][1]

    # A core just started may not have subscribed its rosout yet, and a message published
    # before that is ROS 1's to lose too.
    wait_for(rosout_subscribed, what="the core's rosout subscribed to /rosout")
    ours, out = pub_once_to_rospy(
        graph,
        AGG_LISTENER,
        "/rosout",
        "rosgraph_msgs/Log",
        "{level: 2, name: /once_probe, msg: to rosout}",
    )
    assert (ours.status, ours.out, ours.err) == (
        0,
        "publishing and latching message for 3.0 seconds\n",
        "",
    )
    assert out == "got to rosout\n"


#: A rospy subscriber of Twists that says when it is subscribed.
TWIST_LISTENER = """
import rospy
from geometry_msgs.msg import Twist
rospy.init_node('twist_listener')
rospy.Subscriber('/mismatch', Twist, lambda msg: None)
print('ready', flush=True)
rospy.spin()
"""


def refusal_warning(command: list[str], env: dict[str, str]) -> str:
    """Run ``command`` (a ``rostopic pub`` of Poses on ``/mismatch``) until it prints a
    warning on stderr; that warning without its time."""
    lines: list[str] = []
    with running(command, env, stderr=subprocess.PIPE, text=True) as pub:
        stream: Any = pub.stderr  # lines of text (``text=True``)
        reader = threading.Thread(target=lambda: lines.extend(stream), daemon=True)
        reader.start()
        wait_for(lambda: any("[WARN]" in line for line in lines), what=f"{command[0]}'s warning")
    warning = next(line for line in lines if "[WARN]" in line)
    return re.sub(r"^\[WARN\] \[[0-9.]+\]: ", "", warning.rstrip("\n"))


def test_a_subscriber_of_another_type_is_refused_with_ros1s_warning(graph: str) -> None:
    """rospy's publisher warns when it refuses a subscriber of another type (the rospy
    listener's header follows, as a dict); a student publishing the wrong type sees why."""
    with rospy_listener(graph, TWIST_LISTENER):
        pub = ["rostopic", "pub", "-r", "2", "/mismatch", "geometry_msgs/Pose", "{}"]
        theirs = refusal_warning(pub, ros1_environ(ROS_MASTER_URI=graph))
        ours = refusal_warning(
            [sys.executable, "-m", "rosx_commands", *pub], clean_environ(ROS_MASTER_URI=graph)
        )
    assert theirs.startswith(
        "Could not process inbound connection: topic types do not match: "
        "[geometry_msgs/Twist] vs. [geometry_msgs/Pose]{'callerid': '/twist_listener', "
    )
    assert ours == theirs
