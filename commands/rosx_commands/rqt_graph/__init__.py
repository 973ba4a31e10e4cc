"""``rosx rqt_graph``: the ROS graph in the terminal, live, as rqt_graph draws it.

On a terminal, a full-screen view that refreshes itself (`rosx_commands.rqt_graph.app`);
with ``--text`` (or when stdout is not a terminal) the graph drawn once as text, with ``--dot``
as Graphviz DOT. Modes, filters and hide rules are rqt_graph's, with its defaults.
"""

from __future__ import annotations

from collections.abc import Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rqt_graph.source import CALLER_ID, REFRESH_PERIOD

USAGE = """usage: %prog [options]

Show the ROS graph: nodes (round boxes), topics (square boxes), namespaces (dotted frames)
and who publishes to whom. On a terminal the view is live: r refreshes, tab selects, m mode,
n/t node/topic filter, g namespace depth, d debug names, q quits."""


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rqt_graph", USAGE)
    add = parser.add_option
    add(
        "-m",
        "--mode",
        dest="mode",
        default="nodes",
        choices=["nodes", "active", "all"],
        help="nodes: Nodes only; active: Nodes/Topics (active); all: Nodes/Topics (all)"
        " [default: %default]",
    )
    add(
        "-n",
        "--ns-filter",
        dest="ns_filter",
        default="/",
        metavar="FILTER",
        help="nodes to show: comma list of names or regexes, -name excludes [default: %default]",
    )
    add(
        "-t",
        "--topic-filter",
        dest="topic_filter",
        default="/",
        metavar="FILTER",
        help="topics to show, as --ns-filter [default: %default]",
    )
    add(
        "--group",
        dest="group",
        type="int",
        default=2,
        metavar="DEPTH",
        help="namespace groups this deep (0: none) [default: %default]",
    )
    for flag, dest, text in (
        ("--no-group-actions", "group_actions", "do not collapse action topics"),
        ("--no-group-tf", "group_tf", "do not collapse /tf and /tf_static"),
        ("--no-group-images", "group_images", "do not collapse image_transport topics"),
        ("--show-dead-sinks", "hide_dead_sinks", "show topics nobody subscribes to"),
        ("--show-leaf-topics", "hide_leaf_topics", "show topics with one connection"),
        ("--show-debug", "hide_debug", "show /rosout, /rqt*, /clock and other debug names"),
        ("--show-unreachable", "hide_unreachable", "show nodes that do not answer"),
        ("--show-params", "hide_params", "show dynamic_reconfigure topics"),
    ):
        add(flag, dest=dest, default=True, action="store_false", help=text)
    add("--hide-tf", dest="hide_tf", default=False, action="store_true", help="hide /tf topics")
    add(
        "--text",
        dest="text",
        default=False,
        action="store_true",
        help="print the graph once as text and exit",
    )
    add(
        "--dot",
        dest="dot",
        default=False,
        action="store_true",
        help="print the graph once as Graphviz DOT and exit",
    )
    add(
        "--no-bus-info",
        dest="bus_info",
        default=True,
        action="store_false",
        help="do not ask the nodes for their connections (the master's view only)",
    )
    add(
        "--period",
        dest="period",
        type="float",
        default=REFRESH_PERIOD,
        metavar="SECONDS",
        help="seconds between refreshes of the live view [default: %default]",
    )
    return parser


def rqt_graph(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosx rqt_graph ARGV…``."""
    return run_command(_rqt_graph, list(argv), env)


def _rqt_graph(argv: list[str], env: Environment) -> int:
    from rosx.graph.builder import build  # noqa: PLC0415 - after option parsing
    from rosx.graph.fetch import fetch_state  # noqa: PLC0415 - graph code loads only when asked for
    from rosx.graph.options import GraphOptions, Mode, NameFilter  # noqa: PLC0415 - graph code loads only when asked for

    options, rest = _parser(env).parse(argv)
    if rest:
        raise CommandError(f"rqt_graph: error: unexpected argument {rest[0]!r}", ExitStatus.USAGE)
    graph_options = GraphOptions(
        mode=Mode(options.mode),
        namespace_filter=options.ns_filter,
        topic_filter=options.topic_filter,
        group_depth=max(0, options.group),
        group_actions=options.group_actions,
        group_tf=options.group_tf,
        group_images=options.group_images,
        hide_dead_sinks=options.hide_dead_sinks,
        hide_leaf_topics=options.hide_leaf_topics,
        hide_debug=options.hide_debug,
        hide_tf=options.hide_tf,
        hide_unreachable=options.hide_unreachable,
        hide_params=options.hide_params,
    )
    for text in (options.ns_filter, options.topic_filter):
        try:
            NameFilter.parse(text)
        except ValueError as error:
            raise CommandError(f"rqt_graph: error: {error}", ExitStatus.USAGE) from None
    uri = env.master_uri
    if not (options.text or options.dot) and env.stdout_isatty:
        from rosx_commands.rqt_graph.app import run_app  # noqa: PLC0415 - textual only here

        return run_app(env, uri, graph_options, options.period, options.bus_info)
    state = fetch_state(uri, CALLER_ID, bus_info=options.bus_info)
    graph = build(state, graph_options)
    if options.dot:
        from rosx.graph.dot import dot  # noqa: PLC0415 - graph code loads only when asked for

        env.stdout.write(dot(graph, grouped=graph_options.group_depth > 0))
        return ExitStatus.OK
    from rosx.graph.text import draw  # noqa: PLC0415 - graph code loads only when asked for

    drawing = draw(graph)
    env.out(str(drawing) if drawing.lines else "(no nodes)")
    return ExitStatus.OK
