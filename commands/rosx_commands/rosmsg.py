"""``rosx rosmsg`` and ``rosx rossrv``: show, info, list, md5, package, packages, as ROS 1."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from rosx.msg.describe import describe_msg, describe_srv
from rosx.msg.parser import InvalidMsgSpecError, package_resource_name
from rosx.msg.store import TypeStore, UnknownTypeError
from rosx_commands.cli import ToolParser, commands_overview, run_command
from rosx_commands.context import CommandError, Environment, ExitStatus

_COMMANDS = {
    "msg": [
        ("show", "Show message description"),
        ("info", "Alias for rosmsg show"),
        ("list", "List all messages"),
        ("md5", "Display message md5sum"),
        ("package", "List messages in a package"),
        ("packages", "List packages that contain messages"),
    ],
    "srv": [
        ("show", "Show service description"),
        ("info", "Alias for rossrv show"),
        ("list", "List all services"),
        ("md5", "Display service md5sum"),
        ("package", "List services in a package"),
        ("packages", "List packages that contain services"),
    ],
}
_WHAT = {"msg": "Message", "srv": "Service"}


def _overview(kind: str) -> str:
    tool = "ros" + kind
    return commands_overview(
        tool,
        _COMMANDS[kind],
        intro=f"{tool} is a command-line tool for displaying information about ROS"
        f" {_WHAT[kind]} types.",
        footer=f"Type {tool} <command> -h for more detailed usage",
    )


class _Tool:
    """One rosmsg/rossrv run: which kind, its streams and the type store."""

    def __init__(self, kind: str, env: Environment) -> None:
        self.kind = kind
        self.tool = "ros" + kind
        self.noun = "message type" if kind == "msg" else "service type"
        self.env = env
        self._store: TypeStore | None = None

    @property
    def store(self) -> TypeStore:
        if self._store is None:
            self._store = TypeStore.from_environ(self.env.environ)
        return self._store

    def parser(self, usage: str) -> ToolParser:
        return ToolParser(self.env, self.tool, usage)

    def type_arg(self, parser: ToolParser, argv: list[str]) -> tuple[object, str]:
        """The one type argument, or a line read from stdin when there is none (as ROS 1)."""
        options, args = parser.parse(argv)
        if len(args) > 1:
            parser.error(f"you may only specify one {self.noun}")
        if args:
            return options, args[0]
        line = ""
        while not line:
            read = self.env.stdin.readline()
            if not read:
                parser.error(f"please specify a {self.noun}")
            line = read.strip()
        return options, line

    def matches(self, type_name: str) -> list[str]:
        if "/" in type_name:
            return [type_name]
        return self.store.find(type_name, self.kind)

    def text(self, full_name: str, raw: bool) -> str:
        package_resource_name(full_name)  # genmsg's ValueError for a/b/c
        if self.kind == "msg":
            spec = self.store.msg(full_name)
            return spec.text if raw else describe_msg(spec, self.store.msg)
        service = self.store.srv(full_name)
        return service.text if raw else describe_srv(service, self.store.msg)

    def md5(self, full_name: str) -> str:
        return self.store.md5(full_name) if self.kind == "msg" else self.store.srv_md5(full_name)

    def load_error(self, full_name: str, error: Exception) -> CommandError:
        if isinstance(error, UnknownTypeError):
            package, _, short = error.full_name.partition("/")
            where = self._search_paths(package)
            if error.package_known:
                reason = (
                    f"Cannot locate message [{short}] in package [{package}] with paths [{where}]"
                )
            else:
                reason = (
                    f"Cannot locate message [{short}]: unknown package [{package}] "
                    f"on search path [{where}]"
                )
        else:
            reason = str(error)
        prefix = "Unable to load msg" if self.kind == "msg" else "Unknown srv type"
        return CommandError(f"{prefix} [{full_name}]: {reason}")

    def _search_paths(self, package: str) -> str:
        search_path = {
            name: [str(directory) for directory in directories]
            for name, directories in self.store.search_path(self.kind).items()
        }
        if package in search_path:
            return repr(search_path[package])
        if self.store.has_package(package):
            return repr([])
        return repr(search_path)

    def print_list(self, items: list[str], single: bool) -> None:
        self.env.out((" " if single else "\n").join(items))


def _show(tool: _Tool, argv: list[str], alias: str) -> int:
    parser = tool.parser(f"usage: {tool.tool} {alias} [options] <{tool.noun}>")
    parser.add_option(
        "-r",
        "--raw",
        dest="raw",
        default=False,
        action="store_true",
        help="show raw message text, including comments",
    )
    parser.add_option(
        "-b",
        "--bag",
        dest="bag",
        default=None,
        help="show message from .bag file",
        metavar="BAGFILE",
    )
    options, type_name = tool.type_arg(parser, argv)
    if type_name.endswith("." + tool.kind):
        type_name = type_name[: -len(tool.kind) - 1]
    if "::" in type_name:
        parser.error(
            f"{tool.tool} does not understand C++-style namespaces (i.e. '::').\n"
            "Please refer to msg/srv types as 'package_name/Type'."
        )
    if "." in type_name:
        parser.error(
            f"invalid message type '{type_name}'.\n"
            "Please refer to msg/srv types as 'package_name/Type'."
        )
    if getattr(options, "bag", None):
        bag = str(getattr(options, "bag", ""))
        return _show_from_bag(tool, bag, type_name, bool(getattr(options, "raw", False)))
    full_names = tool.matches(type_name)
    if not full_names:
        raise CommandError(f"Could not find msg '{type_name}'")
    for full_name in full_names:
        try:
            text = tool.text(full_name, bool(getattr(options, "raw", False)))
        except (UnknownTypeError, ValueError) as error:
            raise tool.load_error(full_name, error) from None
        if "/" not in type_name:
            tool.env.out(f"[{full_name}]:")
        tool.env.out(text)
    return ExitStatus.OK


def _show_from_bag(tool: _Tool, bag: str, type_name: str, raw: bool) -> int:
    """``rosmsg show -b BAG TYPE``: the definition the bag recorded for ``TYPE``."""
    from rosx.bag.errors import BagError  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.reader import BagReader  # noqa: PLC0415 - bag code loads only for bags
    from rosx.bag.types import DefinitionStore, split_definition  # noqa: PLC0415 - bag code loads only for bags

    if not Path(bag).exists():
        raise CommandError(f"ERROR: bag file [{bag}] does not exist")
    try:
        with BagReader(bag) as reader:
            found = next((c for c in reader.connections.values() if c.type == type_name), None)
    except (BagError, OSError) as exc:
        raise CommandError(f"ERROR: unable to read bag file [{bag}]: {exc}") from None
    if found is not None:
        if raw:
            tool.env.out(found.message_definition)
        else:
            store = DefinitionStore(split_definition(found.type, found.message_definition))
            tool.env.out(describe_msg(store.msg(found.type), store.msg))
    return ExitStatus.OK


def _md5(tool: _Tool, argv: list[str]) -> int:
    parser = tool.parser(f"usage: {tool.tool} md5 <{tool.noun}>")
    _, type_name = tool.type_arg(parser, argv)
    if "/" in type_name:
        try:
            package, _ = package_resource_name(type_name)
        except ValueError as error:
            raise CommandError(f"Invalid type: '{error}'", ExitStatus.EX_USAGE) from None
        if not package:
            raise CommandError(
                f"Invalid type: 'message type is missing package name: {type_name}'",
                ExitStatus.EX_USAGE,
            )
        try:
            tool.env.out(tool.md5(type_name))
        except (UnknownTypeError, InvalidMsgSpecError):
            tool.env.err(f"Cannot locate [{type_name}]")
        return ExitStatus.OK
    full_names = tool.matches(type_name)
    for full_name in full_names:
        try:
            tool.env.out(f"[{full_name}]: {tool.md5(full_name)}")
        except (UnknownTypeError, InvalidMsgSpecError):
            tool.env.err(f"Cannot locate [{full_name}]")
    if not full_names:
        tool.env.err(f"No messages matching the name [{type_name}]")
    return ExitStatus.OK


def _package(tool: _Tool, argv: list[str]) -> int:
    parser = tool.parser(f"usage: {tool.tool} package <package>")
    parser.add_option(
        "-s",
        dest="single_line",
        default=False,
        action="store_true",
        help="list all msgs on a single line",
    )
    options, package = tool.type_arg(parser, argv)
    if not tool.store.has_package(package):
        from rosx.packages.index import ros_path_lines  # noqa: PLC0415 - only for this error

        lines = [f"Invalid package: {package}", *ros_path_lines(tool.store.package_path)]
        raise CommandError("\n".join(lines), ExitStatus.EX_USAGE)
    found = [t for t in tool.store.types(tool.kind) if t.partition("/")[0] == package]
    tool.print_list(found, bool(getattr(options, "single_line", False)))
    return ExitStatus.OK


def _packages(tool: _Tool, argv: list[str]) -> int:
    parser = tool.parser(f"usage: {tool.tool} packages")
    parser.add_option(
        "-s",
        dest="single_line",
        default=False,
        action="store_true",
        help="list all packages on a single line",
    )
    options, _ = parser.parse(argv)
    tool.print_list(tool.store.packages(tool.kind), bool(options.single_line))
    return ExitStatus.OK


def _list(tool: _Tool, argv: list[str]) -> int:
    tool.parser(f"usage: {tool.tool} list").parse(argv)
    tool.print_list(tool.store.types(tool.kind), single=False)
    return ExitStatus.OK


def main(argv: Sequence[str], env: Environment, kind: str) -> int:
    """Run ``rosmsg`` (``kind='msg'``) or ``rossrv`` (``kind='srv'``) on ``argv``."""
    args = list(argv)
    if not args or args[0] == "--help":
        env.out(_overview(kind))
        return ExitStatus.OK
    tool = _Tool(kind, env)
    command, rest = args[0], args[1:]
    handlers: dict[str, Callable[[list[str], Environment], int]] = {
        "show": lambda a, _: _show(tool, a, "show"),
        "info": lambda a, _: _show(tool, a, "info"),
        "md5": lambda a, _: _md5(tool, a),
        "package": lambda a, _: _package(tool, a),
        "packages": lambda a, _: _packages(tool, a),
        "list": lambda a, _: _list(tool, a),
    }
    if command not in handlers:
        env.out(_overview(kind))
        return ExitStatus.EX_USAGE
    return run_command(handlers[command], rest, env)


def rosmsg(argv: Sequence[str], env: Environment) -> int:
    """Run ``rosmsg ARGV…``."""
    return main(argv, env, "msg")


def rossrv(argv: Sequence[str], env: Environment) -> int:
    """Run ``rossrv ARGV…``."""
    return main(argv, env, "srv")
