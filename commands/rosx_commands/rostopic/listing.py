"""``rostopic list``, ``info``, ``type`` and ``find``: what the master knows about topics."""

from __future__ import annotations

import time

from rosx.graph.state import registrations
from rosx.names.resolution import make_global_ns
from rosx.names.script import ros_namespace, script_resolve_name
from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.master.client import MasterClient

CALLER_ID = "/rostopic"

TopicRows = list[tuple[str, str, list[str]]]


def resolve(env: Environment, name: str) -> str:
    """A topic name typed by the user, resolved as ROS 1's tools do (``ROS_NAMESPACE``)."""
    return script_resolve_name("rostopic", name, ros_namespace(env.environ))


def topic_rows(master: MasterClient) -> tuple[TopicRows, TopicRows]:
    """Published and subscribed topics with their types and nodes, in the master's order."""
    state = registrations(master)
    types = master.topic_types()

    def rows(section: Mapping[str, tuple[str, ...]]) -> TopicRows:
        return [
            (topic, types.get(topic, "unknown type"), list(nodes))
            for topic, nodes in section.items()
        ]

    return rows(state.publishers), rows(state.subscribers)


def _list_bag(env: Environment, bag: str, topic: str | None) -> int:
    """``rostopic list -b BAG [TOPIC]``: topics in order of their first message, or how many
    messages ``topic`` (and its namespace) has, and when the first and last were recorded."""
    from pathlib import Path  # noqa: PLC0415 - pathlib is not needed at start-up

    from rosx.bag.errors import BagError  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.reader import BagReader  # noqa: PLC0415 - bag code loads only for bags

    if not Path(bag).exists():
        raise CommandError(f"ERROR: bag file [{bag}] does not exist")
    try:
        with BagReader(bag) as reader:
            names = {c.id: c.topic for c in reader.connections.values()}
            order = [names[conn] for _, _, _, conn in reader.entries()]
    except (BagError, OSError) as exc:
        raise CommandError(f"ERROR: unable to read bag file [{bag}]: {exc}") from None
    if topic is None:
        for name in dict.fromkeys(order):
            env.out(name)
        return ExitStatus.OK
    prefix = make_global_ns(topic)
    with BagReader(bag) as reader:
        ids = {
            c.id
            for c in reader.connections.values()
            if c.topic == topic or c.topic.startswith(prefix)
        }
        stamps = [t for t, _, _, _ in reader.entries(ids)]
    if not stamps:
        raise CommandError("ERROR: no messages of the topic in the bag")

    def day(ns: int) -> str:
        return time.strftime("%d %b %Y %H:%M:%S", time.localtime(ns / 1e9))

    env.out(f"{len(stamps)} message(s) from {day(stamps[0])} to {day(stamps[-1])}")
    return ExitStatus.OK


def list_topics(argv: list[str], env: Environment) -> int:
    """``rostopic list``: the topics (of a namespace, a bag, a host), with ``-v`` their
    publishers and subscribers."""
    parser = ToolParser(env, "rostopic", "usage: %prog list [/namespace]")
    parser.add_option(
        "-b", "--bag", dest="bag", default=None, help="list topics in .bag file", metavar="BAGFILE"
    )
    parser.add_option(
        "-v",
        "--verbose",
        dest="verbose",
        default=False,
        action="store_true",
        help="list full details about each topic",
    )
    parser.add_option(
        "-p", dest="publishers", default=False, action="store_true", help="list only publishers"
    )
    parser.add_option(
        "-s", dest="subscribers", default=False, action="store_true", help="list only subscribers"
    )
    parser.add_option(
        "--host", dest="hostname", default=False, action="store_true", help="group by host name"
    )
    options, names = parser.parse(argv)
    if len(names) > 1:
        parser.error("you may only specify one input topic")
    bag, verbose, host = options.bag, options.verbose, options.hostname
    publishers_only, subscribers_only = options.publishers, options.subscribers
    if bag is not None:
        return _list_bag(env, bag, resolve(env, names[0]) if names else None)
    if publishers_only and subscribers_only:
        raise CommandError("ERROR: cannot specify both subscribers- and publishers-only")
    master = env.master(CALLER_ID)
    pubs, subs = topic_rows(master)
    if names:
        topic = resolve(env, names[0])
        prefix = make_global_ns(topic)
        pubs = [r for r in pubs if r[0] == topic or r[0].startswith(prefix)]
        subs = [r for r in subs if r[0] == topic or r[0].startswith(prefix)]
    if host:
        _print_by_host(env, master, pubs, subs, publishers_only, subscribers_only, verbose)
    else:
        _print_list(env, pubs, subs, publishers_only, subscribers_only, verbose, "")
    return ExitStatus.OK


def _print_list(
    env: Environment,
    pubs: TopicRows,
    subs: TopicRows,
    publishers_only: bool,
    subscribers_only: bool,
    verbose: bool,
    indent: str,
) -> None:
    if not verbose:
        if publishers_only:
            topics = [t for t, _, _ in pubs]
        elif subscribers_only:
            topics = [t for t, _, _ in subs]
        else:
            topics = list({t for t, _, _ in pubs} | {t for t, _, _ in subs})
        env.out("\n".join(indent + t for t in sorted(topics)))
        return
    if not subscribers_only:
        env.out(f"\n{indent}Published topics:")
        for topic, type_name, nodes in pubs:
            count = f"{len(nodes)} publishers" if len(nodes) > 1 else "1 publisher"
            env.out(f"{indent} * {topic} [{type_name}] {count}")
    if not publishers_only:
        env.out(indent)
        env.out(f"{indent}Subscribed topics:")
        for topic, type_name, nodes in subs:
            count = f"{len(nodes)} subscribers" if len(nodes) > 1 else "1 subscriber"
            env.out(f"{indent} * {topic} [{type_name}] {count}")
    env.out("")


def _print_by_host(
    env: Environment,
    master: MasterClient,
    pubs: TopicRows,
    subs: TopicRows,
    publishers_only: bool,
    subscribers_only: bool,
    verbose: bool,
) -> None:

    from rosx.transport.address import uri_hostname  # noqa: PLC0415 - only list --host

    uris: dict[str, str | None] = {}

    def by_host(rows: TopicRows) -> dict[str, TopicRows]:
        hosts: dict[str, TopicRows] = {}
        for topic, type_name, nodes in rows:
            for node in nodes:
                if node not in uris:
                    uris[node] = master.lookup_node(node)
                host = uri_hostname(uris[node] or "")
                mine = hosts.setdefault(host, [])
                match = [n for t, _, n in mine if t == topic]
                if match:
                    match[0].append(node)
                else:
                    mine.append((topic, type_name, [node]))
        return hosts

    host_pubs, host_subs = by_host(pubs), by_host(subs)
    for host in dict.fromkeys([*host_pubs, *host_subs]):
        hp, hs = host_pubs.get(host, []), host_subs.get(host, [])
        if (hp and not subscribers_only) or (hs and not publishers_only):
            env.out(f"Host [{host}]:")
            _print_list(env, hp, hs, publishers_only, subscribers_only, verbose, "  ")


def info(argv: list[str], env: Environment) -> int:
    """``rostopic info TOPIC``: its type, publishers and subscribers."""
    parser = ToolParser(env, "rostopic", "usage: %prog info /topic")
    _, names = parser.parse(argv)
    if not names:
        parser.error("you must specify a topic name")
    if len(names) > 1:
        parser.error("you may only specify one topic name")
    topic = resolve(env, names[0])
    from rosx.graph.describe import topic_description  # noqa: PLC0415 - info only

    env.out(topic_description(env.master(CALLER_ID), topic))
    return ExitStatus.OK


def topic_type(argv: list[str], env: Environment) -> int:
    """``rostopic type TOPIC[/FIELD]``: the type of a topic or of a field of it."""
    from rosx_commands.argparser import ToolArgumentParser  # noqa: PLC0415 - only type uses it

    parser = ToolArgumentParser(env, prog="rostopic type")
    parser.add_argument("topic_or_field", help="Topic or field name")
    name = resolve(env, parser.parse_args(argv).topic_or_field)
    from rosx.msg.text.fieldpath import (  # noqa: PLC0415 - only type needs it
        FieldPathError,
        field_type,
        find_topic,
        parse_field_path,
    )

    types = env.master(CALLER_ID).topic_types()
    if name in types:
        env.out(types[name])
        return ExitStatus.OK
    from rosx.msg.store import TypeStore, UnknownTypeError  # noqa: PLC0415 - field paths only

    store = TypeStore.from_environ(env.environ)
    found = find_topic(name, types, store)
    if found is None:
        raise CommandError(f"unknown topic type [{name}]")
    topic, type_name = found
    field = name[len(topic) + 1 :]
    try:
        # An index gives the element's type (ROS 1 fails on it with a traceback).
        declared = field_type(store.msg, type_name, parse_field_path(field), elements=True)
    except UnknownTypeError as error:
        raise CommandError(
            f"ERROR: Cannot load message class for [{error.full_name}]. Are your messages built?"
        ) from None
    except FieldPathError:
        raise CommandError(f"unknown topic type [{name}]") from None
    env.out(type_name if declared is None else f"{type_name} {field} {declared}")
    return ExitStatus.OK


def find(argv: list[str], env: Environment) -> int:
    """``rostopic find TYPE``: the topics of a type."""
    parser = ToolParser(env, "rostopic", "usage: %prog find msg-type")
    _, names = parser.parse(argv)
    if not names:
        parser.error("please specify a message type")
    if len(names) > 1:
        parser.error("you may only specify one message type")
    types = env.master(CALLER_ID).topic_types()
    env.out("\n".join(t for t, type_name in types.items() if type_name == names[0]))
    return ExitStatus.OK
