"""``rosx rosmsg-proto msg|srv TYPE``: a default message or service request as YAML, quoted.

ROS 1's rosmsg-proto exists for tab completion: ``rostopic pub /topic TYPE <TAB>`` and
``rosservice call /srv <TAB>`` insert what it prints (see `rosx.msg.text.prototype`). Its options
(``-f``, ``-e``, ``-s``, ``-p``, ``-H``, ``-x``), texts and statuses are kept: errors go to stderr
without a line break (``Unknown message name X``, ``Ambiguous message name X``, status 1;
``Insufficient arguments``, status 64), ``-s`` silences them. A bare type name is looked for in
every package. ``rossrv-proto`` is the same command.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rosx_commands.cli import ToolParser, run_command
from rosx_commands.context import Environment, ExitStatus


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rosmsg-proto", "usage: rosmsgproto msg/srv [options]")
    parser.description = (
        "Produces output or a msg or service request, intended for tab completion support."
    )
    add = parser.add_option
    add(
        "-f",
        "--flow_style",
        dest="flow_style",
        type="int",
        default=None,
        action="store",
        help="if 1 always use brackets, if 0 never use brackets. Default is a heuristic mix.",
    )
    add(
        "-e",
        "--empty-arrays",
        dest="empty_arrays",
        default=False,
        action="store_true",
        help="if true flexible size arrays are not filled with default instance",
    )
    add(
        "-s",
        "--silent",
        dest="silent",
        default=False,
        action="store_true",
        help="if true suppresses all error messages",
    )
    add(
        "-p",
        "--prefix",
        metavar="prefix",
        default="",
        help="prefix to print before each line, can be used for indent",
    )
    add(
        "-H",
        "--no-hyphens",
        dest="no_hyphens",
        default="",
        action="store_true",
        help="if true output has no outer hyphens",
    )
    add(
        "-x",
        "--exclude-slots",
        metavar="exclude_slots",
        default="",
        help="comma separated list of slot names not to print",
    )
    return parser


class _Failed(Exception):  # noqa: N818 - rosmsg-proto's report
    def __init__(self, text: str, status: int = ExitStatus.ERROR) -> None:
        super().__init__(text)
        self.text = text
        self.status = status


def _text(args: list[str], options: object, parser: ToolParser, environ: Mapping[str, str]) -> str:
    from rosx.msg.store import TypeStore, UnknownTypeError  # noqa: PLC0415 - the type store loads on first use
    from rosx.msg.text.prototype import prototype  # noqa: PLC0415 - the text forms load on first use

    if len(args) < 2:
        raise _Failed("Insufficient arguments", ExitStatus.EX_USAGE)
    mode, name = args[0], args[1]
    silent = getattr(options, "silent", False)
    if "::" in name and not silent:
        parser.error(
            "rosmsgproto does not understand C++-style namespaces (i.e. '::').\n"
            "Please refer to msg/srv types as 'package_name/Type'."
        )
    elif "." in name and not silent:
        parser.error(
            f"invalid message type '{name}'.\nPlease refer to msg/srv types as 'package_name/Type'."
        )
    store = TypeStore.from_environ(environ)
    if "/" not in name:
        found = store.find(name, mode) if mode in ("msg", "srv") else []
        if len(found) > 1:
            raise _Failed(f"Ambiguous message name {name}")
        if not found:
            raise _Failed(f"Unknown message name {name}")
        name = found[0]
    if mode == "srv":
        try:
            store.srv(name)
        except (UnknownTypeError, ValueError):
            raise _Failed(f"Unknown service class: {name}") from None
        target = name + "Request"
    elif mode == "msg":
        target = name
    else:
        raise _Failed(f"Invalid mode: .{mode}")
    flow_style = getattr(options, "flow_style", None)
    excluded = str(getattr(options, "exclude_slots", "") or "")
    try:
        text = prototype(
            target,
            store.msg,
            flow=None if flow_style is None else bool(flow_style),
            fill_arrays=not getattr(options, "empty_arrays", False),
            exclude=tuple(s for s in excluded.split(",") if s.strip()),
        )
    except (UnknownTypeError, ValueError):
        raise _Failed(f"Unknown message class: {name}") from None
    prefix = str(getattr(options, "prefix", "") or "")
    if prefix:
        text = prefix + ("\n" + prefix).join(text.splitlines())
    return text if getattr(options, "no_hyphens", False) else f'"{text}"'


def _proto(argv: list[str], env: Environment) -> int:
    parser = _parser(env)
    options, args = parser.parse(argv)
    try:
        env.out(_text(args, options, parser, env.environ))
    except _Failed as failed:
        if options.silent:
            return ExitStatus.OK
        env.stderr.write(failed.text)
        return failed.status
    return ExitStatus.OK


def rosmsg_proto(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosmsg-proto ARGV…``."""
    return run_command(_proto, list(argv), env)


__all__ = ["rosmsg_proto"]
