"""``rostopic echo``: print a topic's messages, a field of them, or CSV rows, as ROS 1 does.

Each message (or the value a field path selects) is printed in the YAML-like text of
`rosx.msg.text.echo` followed by a ``---`` line, or with ``-p`` as a CSV row under a ``%time,…``
header. ``-n COUNT`` stops after COUNT messages; ``--filter`` skips messages its expression
rejects (it sees the whole message as ``m`` and the topic name as ``topic``). The command waits
for the topic to be published, and Ctrl-C ends it quietly with status 0.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

from rosx.msg.text.fieldpath import FieldPathError, field_type, parse_field_path
from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rostopic.listing import resolve
from rosx_commands.rostopic.session import MessageFilter, Session, wait_until

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.text.fieldpath import FieldPath


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rostopic", "usage: %prog echo [options] /topic")
    parser.add_option(
        "-b",
        "--bag",
        dest="bag",
        default=None,
        help="echo messages from .bag file",
        metavar="BAGFILE",
    )
    parser.add_option(
        "-p",
        dest="plot",
        default=False,
        action="store_true",
        help="echo in a plotting friendly format",
    )
    parser.add_option(
        "-w",
        dest="fixed_numeric_width",
        default=None,
        metavar="NUM_WIDTH",
        help="fixed width for numeric values",
    )
    parser.add_option(
        "--filter",
        dest="filter_expr",
        default=None,
        metavar="FILTER-EXPRESSION",
        help="Python expression to filter messages that are printed. Expression can use "
        "Python builtins as well as m (the message) and topic (the topic name).",
    )
    parser.add_option(
        "--nostr",
        dest="nostr",
        default=False,
        action="store_true",
        help="exclude string fields",
    )
    parser.add_option(
        "--noarr", dest="noarr", default=False, action="store_true", help="exclude arrays"
    )
    parser.add_option(
        "-c",
        "--clear",
        dest="clear",
        default=False,
        action="store_true",
        help="clear screen before printing next message",
    )
    parser.add_option(
        "-a",
        "--all",
        dest="all_topics",
        default=False,
        action="store_true",
        help="display all message in bag, only valid with -b option",
    )
    parser.add_option(
        "-n",
        dest="msg_count",
        default=None,
        metavar="COUNT",
        help="number of messages to echo",
    )
    parser.add_option(
        "--offset",
        dest="offset_time",
        default=False,
        action="store_true",
        help="display time as offsets from current time (in seconds)",
    )
    return parser


class Printer:
    """The subscriber's callback: selects, formats and writes each message (ROS 1's rules)."""

    def __init__(
        self,
        env: Environment,
        topic: str,
        *,
        path: FieldPath | None = None,
        field_type: str | None = None,
        plot: bool = False,
        message_filter: MessageFilter | None = None,
        clear: bool = False,
        offset: bool = False,
        count: int | None = None,
        noarr: bool = False,
        nostr: bool = False,
        width: int | None = None,
        clock: Callable[[], Any] | None = None,
        recorded: bool = False,
    ) -> None:
        self.env = env
        self.topic = topic
        self.path = path
        self.field_type = field_type
        self.plot = plot
        self.message_filter = message_filter
        self.clear = clear
        self.offset = offset
        self.max_count = count
        self.noarr = noarr
        self.nostr = nostr
        self.width = width
        # Reading a bag: -p's time column is the clock's (the record time), not a header's.
        self.recorded = recorded
        self.count = 0
        self.first = True
        self.done = threading.Event()
        # Bound once: the callback runs for every message.
        from rosx.msg.text.echo import echo_record, format_value  # noqa: PLC0415 - the text forms load on first use
        from rosx.msg.text.echocsv import csv_header, csv_row  # noqa: PLC0415 - the text forms load on first use
        from rosx.node.clock import now  # noqa: PLC0415 - the node runtime loads with the first node

        self._format, self._record = format_value, echo_record
        self._csv_header, self._csv_row = csv_header, csv_row
        self._path_error, self._now = FieldPathError, clock or now

    def __call__(self, msg: object) -> None:
        """Print ``msg`` if it passes the filter, until ``max_count`` are printed; sets ``done``
        then, when stdout is closed, or when printing fails (the error on stderr)."""
        if self.message_filter is not None and not self.message_filter(msg, self.topic):
            return
        if self.max_count is not None and self.count >= self.max_count:
            self.done.set()
            return
        try:
            self._print(msg)
        except OSError:
            self.done.set()  # the reader went away (a closed pipe)
        except Exception as error:
            self.env.stderr.write(f"ERROR: cannot print message: {type(error).__name__}: {error}\n")
            self.done.set()
        if self.max_count is not None and self.count >= self.max_count:
            self.done.set()

    def _print(self, msg: object) -> None:
        value: Any = msg
        if self.path is not None:
            try:
                value = self.path.evaluate(msg)
            except self._path_error as error:
                self.env.stderr.write(f"{error}\n")
                self.env.stderr.flush()
                return
        if value is None:
            return
        self.count += 1
        offset = self._now() if self.offset else None
        if self.plot:
            text = ""
            if self.first:
                text = self._csv_header(value, noarr=self.noarr, nostr=self.nostr) + "\n"
                self.first = False
            now = self._now()
            text += self._csv_row(
                value,
                now,
                bag_time=now if self.recorded else None,
                time_offset=offset,
                noarr=self.noarr,
                nostr=self.nostr,
            )
            text += "\n"
        else:
            body = self._format(
                value,
                self.field_type,
                noarr=self.noarr,
                nostr=self.nostr,
                fixed_numeric_width=self.width,
                time_offset=offset,
            )
            text = self._record(body, clear=self.clear)
        self.env.stdout.write(text)
        self.env.stdout.flush()


def echo(argv: list[str], env: Environment) -> int:
    """``rostopic echo [options] /topic``."""
    parser = _parser(env)
    options, args = parser.parse(argv)
    if len(args) > 1:
        parser.error("you may only specify one input topic")
    if options.all_topics and not options.bag:
        parser.error("Display all option is only valid when echoing from bag files")
    if options.offset_time and options.bag:
        parser.error("offset time option is not valid with bag files")
    if not options.all_topics and not args:
        parser.error("topic must be specified")
    # As ROS 1's, -a echoes every message whole, whatever topic is named.
    topic = "" if options.all_topics else resolve(env, args[0])
    message_filter = MessageFilter.compile(env, parser, options.filter_expr)
    count = _integer(parser, options.msg_count, "COUNT must be an integer")
    width = _integer(parser, options.fixed_numeric_width, "NUM_WIDTH must be an integer")
    if width is not None and width < 2:
        parser.error("Fixed width for numeric values must be at least 2")
    printing = {
        "path": None,
        "plot": options.plot,
        "message_filter": message_filter,
        "clear": options.clear,
        "count": count,
        "noarr": options.noarr,
        "nostr": options.nostr,
        "width": width,
    }
    if options.bag:
        return _echo_bag(env, options.bag, topic, options.all_topics, printing)
    with Session(env) as session:
        session.check_master()
        node = session.start_node()
        found = session.wait_for_topic(topic)
        if found is None:
            return ExitStatus.OK
        type_name, real_topic = found
        msg_class = session.message_class(type_name)
        path, field_type = _field_path(env, session, type_name, topic[len(real_topic) :])
        printer = Printer(
            env,
            real_topic,
            path=path,
            field_type=field_type,
            plot=options.plot,
            message_filter=message_filter,
            clear=options.clear,
            offset=options.offset_time,
            count=count,
            noarr=options.noarr,
            nostr=options.nostr,
            width=width,
            clock=node.clock.now,
        )
        sim_time = session.use_sim_time("/use_sim_time")
        node.subscribe(real_topic, msg_class, printer)
        if sim_time:
            _warn_without_clock(env, session, printer)
        wait_until(session, printer.done)
    return ExitStatus.OK


def _echo_bag(
    env: Environment, bag: str, topic: str, every_topic: bool, printing: dict[str, Any]
) -> int:
    """``rostopic echo -b BAG``: the bag's messages of ``topic`` (or all), in time order, with
    the bag's times where a time is printed.

    As ROS 1's, ``topic`` may go on into a field of a bag's topic (``/scan/header/frame_id``):
    every topic it starts with is read, and the rest of the name is the path into its messages,
    whatever their type (a missing field is reported per message).
    """
    from pathlib import Path  # noqa: PLC0415 - pathlib is not needed at start-up

    from rosx.bag.api import Bag, ROSBagException  # noqa: PLC0415 - bag code loads only for bags

    if not Path(bag).exists():
        raise CommandError(f"ERROR: bag file [{bag}] does not exist")
    stamp: list[Any] = [None]
    printer = Printer(env, topic, clock=lambda: stamp[0], recorded=True, **printing)
    paths: dict[str, FieldPath | None] = {}

    def wanted(name: str, *_: object) -> bool:
        return name == topic or topic.startswith(name + "/")

    try:
        with Bag(bag) as reader:
            chosen = None if every_topic else wanted
            for name, msg, when in reader.read_messages(connection_filter=chosen):
                if name not in paths:
                    inside = topic.startswith(name + "/")
                    paths[name] = _parse_path(env, topic[len(name) :]) if inside else None
                stamp[0] = when
                printer.topic, printer.path = name, paths[name]
                printer(msg)
                if printer.done.is_set():
                    break
    except (ROSBagException, OSError) as exc:
        raise CommandError(f"ERROR: unable to read bag file [{bag}]: {exc}") from None
    return ExitStatus.OK


def _integer(parser: ToolParser, text: str | None, error: str) -> int | None:
    # As ROS 1: an empty value means "not given".
    if not text:
        return None
    try:
        return int(text)
    except ValueError:
        parser.error(error)


def _field_path(
    env: Environment, session: Session, type_name: str, text: str
) -> tuple[FieldPath | None, str | None]:
    """`_parse_path` of ``text`` and the type of the field it ends at."""
    path = _parse_path(env, text)
    if path is None:
        return None, None
    try:
        return path, field_type(session.store.msg, type_name, path)
    except (FieldPathError, LookupError):
        return path, None


def _parse_path(env: Environment, text: str) -> FieldPath | None:
    """The parsed path after the topic name, None for the whole message.

    A path that does not parse is reported and the whole message is echoed, as ROS 1 does.
    """
    if not text.strip("/"):
        return None
    try:
        path = parse_field_path(text)
    except FieldPathError as error:
        env.stderr.write(f"{error}\n")
        return None
    return path if path.steps else None


def _warn_without_clock(env: Environment, session: Session, printer: Printer) -> None:
    """ROS 1's hint when simulated time is on and nothing arrives within two seconds."""
    for _ in range(20):
        if printer.count or printer.done.is_set() or not session.sleep(0.1):
            return
    env.stderr.write(
        "WARNING: no messages received and simulated time is active.\nIs /clock being published?\n"
    )
