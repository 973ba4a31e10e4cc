"""``rosbag record``: ROS 1's options, a `rosx.bag.recorder.Recorder` on an anonymous node.

Log lines are roscpp's (``[ INFO] [secs.nsecs]: …``; INFO on stdout, warnings and errors on
stderr; ``-q`` keeps only the latter). SIGINT and SIGTERM stop the recording cleanly: what
was queued is written, the index too, and ``NAME.bag.active`` becomes ``NAME.bag``.
"""

from __future__ import annotations

import optparse
import time
from typing import TYPE_CHECKING, Any

from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.errors import unreachable

if TYPE_CHECKING:
    pass

_HELP_USAGE = "rosbag record TOPIC1 [TOPIC2 TOPIC3 ...]"


def _split(option: Any, opt_str: str, value: Any, parser: optparse.OptionParser) -> None:
    values: Any = parser.values
    values.split = True
    rargs = parser.rargs
    if rargs and rargs[0].isdigit():
        env = parser.env  # type: ignore[attr-defined]
        env.err(
            'Use of "--split <MAX_SIZE>" has been deprecated.  Please use --split --size '
            "<MAX_SIZE> or --split --duration <MAX_DURATION>"
        )
        values.size = int(rargs.pop(0))


def build_parser(env: Environment) -> ToolParser:
    """ROS 1's ``rosbag record`` options, in its order and with its help texts."""
    p = ToolParser(env, "rosbag", _HELP_USAGE)
    p.description = "Record a bag file with the contents of specified topics."
    p.formatter = optparse.IndentedHelpFormatter()
    add = p.add_option
    add("-a", "--all", dest="all", default=False, action="store_true", help="record all topics")
    add(
        "-e",
        "--regex",
        dest="regex",
        default=False,
        action="store_true",
        help="match topics using regular expressions",
    )
    add(
        "-p",
        "--publish",
        dest="publish",
        default=False,
        action="store_true",
        help="publish a msg when the record begin",
    )
    add(
        "-x",
        "--exclude",
        dest="exclude_regex",
        default="",
        action="store",
        help="exclude topics matching the follow regular expression (subtracts from -a or regex)",
    )
    add(
        "-q",
        "--quiet",
        dest="quiet",
        default=False,
        action="store_true",
        help="suppress console output",
    )
    add(
        "-o",
        "--output-prefix",
        dest="prefix",
        default=None,
        action="store",
        help="prepend PREFIX to beginning of bag name (name will always end with date stamp)",
    )
    add(
        "-O",
        "--output-name",
        dest="name",
        default=None,
        action="store",
        help="record to bag with name NAME.bag",
    )
    add(
        "--split",
        dest="split",
        default=False,
        callback=_split,
        action="callback",
        help="split the bag when maximum size or duration is reached",
    )
    add(
        "--max-splits",
        dest="max_splits",
        type="int",
        action="store",
        metavar="MAX_SPLITS",
        help="Keep a maximum of N bag files, when reaching the maximum erase the oldest one "
        "to keep a constant number of files.",
    )
    add(
        "--size",
        dest="size",
        type="int",
        action="store",
        metavar="SIZE",
        help="record a bag of maximum size SIZE MB. (Default: infinite)",
    )
    add(
        "--duration",
        dest="duration",
        type="string",
        action="store",
        metavar="DURATION",
        help="record a bag of maximum duration DURATION in seconds, "
        "unless 'm', or 'h' is appended.",
    )
    add(
        "-b",
        "--buffsize",
        dest="buffsize",
        default=256,
        type="int",
        action="store",
        metavar="SIZE",
        help="use an internal buffer of SIZE MB (Default: %default, 0 = infinite)",
    )
    add(
        "--chunksize",
        dest="chunksize",
        default=768,
        type="int",
        action="store",
        metavar="SIZE",
        help="Advanced. Record to chunks of SIZE KB (Default: %default)",
    )
    add(
        "-l",
        "--limit",
        dest="num",
        default=0,
        type="int",
        action="store",
        help="only record NUM messages on each topic",
    )
    add(
        "--node",
        dest="node",
        default=None,
        type="string",
        action="store",
        help="record all topics subscribed to by a specific node",
    )
    add(
        "-j",
        "--bz2",
        dest="compression",
        default=None,
        action="store_const",
        const="bz2",
        help="use BZ2 compression",
    )
    add("--lz4", dest="compression", action="store_const", const="lz4", help="use LZ4 compression")
    add(
        "--tcpnodelay",
        dest="tcpnodelay",
        action="store_true",
        help="Use the TCP_NODELAY transport hint when subscribing to topics.",
    )
    add(
        "--udp",
        dest="udp",
        action="store_true",
        help="Use the UDP transport hint when subscribing to topics.",
    )
    add(
        "--repeat-latched",
        dest="repeat_latched",
        action="store_true",
        help="Repeat latched msgs at the start of each new bag file.",
    )
    return p


def parse_duration(text: str) -> float:
    """``--duration``: seconds, or with ``s``, ``m`` or ``h`` appended."""
    number = text.rstrip("smh")
    unit = text[len(number) :].strip() or "s"
    try:
        value = float(number)
    except ValueError:
        raise CommandError("Duration must start with a floating point number.") from None
    if unit not in ("s", "m", "h"):
        raise CommandError("Duration unit must be s, m, or h")
    seconds = value * {"s": 1.0, "m": 60.0, "h": 3600.0}[unit]
    if seconds <= 0:
        raise CommandError("Duration must be positive.")
    return seconds


class _Console:
    """roscpp's console lines for the recorder's log."""

    def __init__(self, env: Environment, quiet: bool) -> None:
        self.env = env
        self.quiet = quiet

    def __call__(self, level: str, text: str) -> None:
        if level == "INFO" and self.quiet:
            return
        now = time.time_ns()
        line = f"[{level:>5}] [{now // 1_000_000_000}.{now % 1_000_000_000:09d}]: {text}"
        stream = self.env.stdout if level == "INFO" else self.env.stderr
        stream.write(line + "\n")
        stream.flush()


def record(argv: list[str], env: Environment) -> int:
    """Run ``rosbag record ARGV…``."""
    parser = build_parser(env)
    options, args = parser.parse(argv)
    if not args and not options.all and not options.node:
        parser.error("You must specify a topic name or else use the '-a' option.")
    if options.prefix is not None and options.name is not None:
        parser.error("Can't set both prefix and name.")
    if options.split and not options.duration and not options.size:
        parser.error("Split specified without giving a maximum duration or size")
    if options.num and not args:
        env.err("Specifying a count is not valid with automatic topic subscription.")
        return ExitStatus.ERROR
    if options.udp:
        env.err("rosx records over TCPROS only; --udp is ignored.")

    from rosx.bag.recorder import Recorder, RecordOptions  # noqa: PLC0415 - bag code loads only for bags
    from rosx.node import Node  # noqa: PLC0415 - the node runtime loads with the first node
    from rosx.signals import stop_on_signals  # noqa: PLC0415 - signal handling only where it is set up

    exclude = options.exclude_regex
    record_all = options.all
    if exclude and not (record_all or options.regex):
        env.stderr.write(
            "Warning: Exclusion regex given, but no topics to subscribe to.\n"
            "Adding implicit 'record all'."
        )
        record_all = True
    max_duration = parse_duration(options.duration) if options.duration else 0.0
    if options.buffsize < 0:
        raise CommandError("Buffer size must be 0 or positive")
    record_options = RecordOptions(
        topics=args,
        record_all=record_all,
        regex=options.regex,
        exclude=exclude,
        prefix=options.name or options.prefix or "",
        append_date=options.name is None,
        split=options.split,
        max_size=(options.size or 0) * 1024 * 1024,
        max_duration=max_duration,
        max_splits=options.max_splits or 0,
        limit=options.num,
        node=options.node or "",
        compression=options.compression or "none",
        buffer_size=options.buffsize * 1024 * 1024,
        chunk_size=options.chunksize * 1024,
        tcp_nodelay=bool(options.tcpnodelay),
        repeat_latched=bool(options.repeat_latched),
        publish=bool(options.publish),
    )
    if options.node:
        env.out(f"Recording from: {options.node}")
    uri = env.master_uri
    node = Node(f"record_{time.time_ns()}", master_uri=uri, environ=env.environ)
    try:
        node.start()
    except Exception:
        node.shutdown("start-up failed")
        raise unreachable(env, uri) from None
    console = _Console(env, options.quiet)
    recorder = Recorder(node, record_options, console)
    try:
        with stop_on_signals() as stop:
            try:
                recorder.start()
            except OSError as exc:
                problem = f"Error opening file: {exc.filename}" if exc.filename else exc.strerror
                console("ERROR", f"Error writing: {problem or exc}")
                return ExitStatus.ERROR  # ROS 1's exits 0 (README.md)
            while not stop.is_set() and not recorder.stopping and not node.is_shutdown():
                time.sleep(0.05)
            recorder.stop()
    finally:
        node.shutdown("rosbag record exited")
    return ExitStatus.ERROR if recorder.error else ExitStatus.OK
