"""``rostopic hz``, ``bw`` and ``delay``: subscribe, measure (`rosx.node.stats`),
print a report every second until interrupted, and a last one then.

As ROS 1's, hz and delay measure in ROS time (the node's clock: ``/clock`` when
``/use_sim_time`` is set, where a message that comes while it reads 0 is not counted, and
drops what was measured, saying so once: simulated time restarted), hz with
``--wall-time`` and bw in wall-clock time; the reports come every wall-clock second.

hz and bw subscribe raw (rospy's ``AnyMsg``): messages are never decoded, so any type works and
fast topics cost little; only ``hz --filter`` decodes, to give the expression a message. delay
decodes, to read ``header.stamp``.
"""

from __future__ import annotations

import contextlib
import time
from typing import TYPE_CHECKING, Any

from rosx.node.stats import TIME_RESET, BandwidthTracker, DelayTracker, HzTracker
from rosx_commands.cli import ToolParser
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.rostopic.listing import resolve
from rosx_commands.rostopic.session import MessageFilter, Session

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.node import Node

#: Seconds between two reports.
REPORT_PERIOD = 1.0
SIM_TIME_WARNING = "WARNING: may be using simulated time"


def _report_every_second(session: Session, report: Callable[[], str | None]) -> None:
    """Print ``report()`` every second until the node shuts down or Ctrl-C, then once more:
    ROS 1's last report, of what came before the end."""
    env = session.env

    def write() -> None:
        text = report()
        if text is not None:
            env.stdout.write(text + "\n")
            env.stdout.flush()

    with contextlib.suppress(KeyboardInterrupt):
        while session.sleep(REPORT_PERIOD):
            write()
    write()


def _subscribed(env: Environment, topic: str) -> None:
    env.stdout.write(f"subscribed to [{topic}]\n")
    env.stdout.flush()


def _warn_sim_time(session: Session) -> None:
    if session.use_sim_time():
        session.env.stderr.write(SIM_TIME_WARNING + "\n")


def _window(parser: ToolParser, text: Any) -> int | None:
    if text is None:
        return None
    try:
        return int(text)
    except (TypeError, ValueError):
        parser.error("window size must be an integer")


# -- hz ------------------------------------------------------------------------------------


def hz(argv: list[str], env: Environment) -> int:
    """``rostopic hz [options] /topic_0 [/topic_1 …]``."""
    parser = ToolParser(
        env, "rostopic", "usage: %prog hz [options] /topic_0 [/topic_1 [topic_2 [..]]]"
    )
    parser.add_option(
        "-w",
        "--window",
        dest="window_size",
        default=-1,
        help="window size, in # of messages, for calculating rate",
        metavar="WINDOW",
    )
    parser.add_option(
        "--filter",
        dest="filter_expr",
        default=None,
        help="only measure messages matching the specified Python expression",
        metavar="EXPR",
    )
    parser.add_option(
        "--wall-time",
        dest="use_wtime",
        default=False,
        action="store_true",
        help="calculates rate using wall time which can be helpful when clock isn't published "
        "during simulation",
    )
    parser.add_option(
        "--tcpnodelay",
        dest="tcp_nodelay",
        action="store_true",
        help="use the TCP_NODELAY transport hint when subscribing to topics",
    )
    options, args = parser.parse(argv)
    if not args:
        parser.error("topic must be specified")
    window = _window(parser, options.window_size)
    topics = [resolve(env, name) for name in args]
    message_filter = MessageFilter.compile(env, parser, options.filter_expr)
    tracker = HzTracker(-1 if window is None else window)
    with Session(env) as session:
        session.check_master()
        node = session.start_node()
        for topic in topics:
            found = session.wait_for_topic(topic)
            if found is None:
                return ExitStatus.OK
            type_name, real_topic = found
            msg_class = session.message_class(type_name) if message_filter else None
            clock = time.time if options.use_wtime else _ros_seconds(node)
            node.subscribe(
                real_topic,
                msg_class,
                _hz_callback(env, tracker, topic, real_topic, message_filter, clock),
                tcp_nodelay=bool(options.tcp_nodelay),
            )
            _subscribed(env, real_topic)
        _warn_sim_time(session)
        _report_every_second(session, lambda: tracker.report(topics))
    return ExitStatus.OK


def _ros_seconds(node: Node) -> Callable[[], float | None]:
    """The node's ROS time in seconds, None while simulated time reads 0 (ROS 1's tools then
    leave the message out)."""
    clock = node.clock

    def seconds() -> float | None:
        current = clock.now()
        return None if current.is_zero() else current.to_sec()

    return seconds


def _time_reset(env: Environment) -> None:
    env.stdout.write(TIME_RESET + "\n")
    env.stdout.flush()


def _hz_callback(
    env: Environment,
    tracker: HzTracker,
    key: str,
    topic: str,
    message_filter: MessageFilter | None,
    clock: Callable[[], float | None],
) -> Callable[[Any], None]:
    arrived = tracker.arrived

    def counted(msg: Any) -> None:
        if message_filter is not None and not message_filter(msg, topic):
            return
        now = clock()
        if now is not None:
            arrived(key, now)
        elif tracker.time_reset(key):
            _time_reset(env)

    return counted


# -- bw ------------------------------------------------------------------------------------


def bw(argv: list[str], env: Environment) -> int:
    """``rostopic bw [-w WINDOW] /topic``."""
    parser = ToolParser(env, "rostopic", "usage: %prog bw /topic")
    parser.add_option(
        "-w",
        "--window",
        dest="window_size",
        default=None,
        help="window size, in # of messages, for calculating rate",
        metavar="WINDOW",
    )
    options, args = parser.parse(argv)
    if not args:
        parser.error("topic must be specified")
    if len(args) > 1:
        parser.error("you may only specify one input topic")
    window = _window(parser, options.window_size)
    topic = resolve(env, args[0])
    tracker = BandwidthTracker(window)
    with Session(env) as session:
        session.check_master()
        found = session.wait_for_topic(topic)
        if found is None:
            return ExitStatus.OK
        real_topic = found[1]
        node = session.start_node()
        clock = time.time
        arrived = tracker.arrived
        node.subscribe(real_topic, None, lambda raw: arrived(len(raw), clock()))
        _subscribed(env, real_topic)
        _report_every_second(session, lambda: tracker.report(clock()))
    return ExitStatus.OK


# -- delay ---------------------------------------------------------------------------------


def delay(argv: list[str], env: Environment) -> int:
    """``rostopic delay [-w WINDOW] [--tcpnodelay] /topic``."""
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - delay only

    parser = ToolArgumentParser(env, prog="rostopic")
    parser.usage = "%(prog)s delay [options] /topic"
    parser.add_argument("topic", help="topic name to be calcurated the delay")
    parser.add_argument(
        "-w",
        "--window",
        dest="window_size",
        default=-1,
        type=int,
        help="window size, in # of messages, for calculating rate",
    )
    parser.add_argument(
        "--tcpnodelay",
        dest="tcp_nodelay",
        action="store_true",
        help="use the TCP_NODELAY transport hint when subscribing to topics",
    )
    args = parser.parse(argv)
    topic = resolve(env, args.topic)
    tracker = DelayTracker(args.window_size)
    with Session(env) as session:
        found = session.wait_for_topic(topic)
        if found is None:
            return ExitStatus.OK
        type_name, real_topic = found
        msg_class = session.message_class(type_name)
        node = session.start_node()
        node.subscribe(
            real_topic,
            msg_class,
            _delay_callback(env, tracker, _ros_seconds(node)),
            tcp_nodelay=args.tcp_nodelay,
        )
        _subscribed(env, real_topic)
        _warn_sim_time(session)
        _report_every_second(session, tracker.report)
    return ExitStatus.OK


def _delay_callback(
    env: Environment, tracker: DelayTracker, clock: Callable[[], float | None]
) -> Callable[[Any], None]:
    def callback(msg: Any) -> None:
        if not getattr(msg, "_has_header", False):
            from rosx.node.rosout import ERROR, console_line  # noqa: PLC0415 - the node runtime loads with the first node

            # rospy's logerr, which ROS 1's rostopic delay uses for this.
            env.stderr.write(console_line(ERROR, "msg does not have header") + "\n")
            env.stderr.flush()
            return
        now = clock()
        if now is not None:
            tracker.arrived(now, msg.header.stamp.to_sec())
        elif tracker.time_reset():
            _time_reset(env)

    return callback
