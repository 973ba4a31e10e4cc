"""``rosx rosmsg`` and ``rosx rossrv``: show, list, md5, package, packages (ROS 1's rosmsg)."""

from collections.abc import Sequence
from typing import Annotated

import typer

from rosx.msg.describe import describe_msg, describe_srv
from rosx.msg.parser import InvalidMsgSpecError
from rosx.msg.store import TypeStore, UnknownTypeError
from rosx_commands.cli import run_app, tool_app, usage_error
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
    lines = [
        f"{tool} is a command-line tool for displaying information about ROS {_WHAT[kind]} types.",
        "",
        "Commands:",
    ]
    lines += [f"\t{tool} {name}\t{text}" for name, text in _COMMANDS[kind]]
    lines += ["", f"Type {tool} <command> -h for more detailed usage", ""]
    return "\n".join(lines)


def _usages(kind: str) -> dict[str, str]:
    noun = "message" if kind == "msg" else "service"
    tool = "ros" + kind
    return {
        "show": f"{tool} show [options] <{noun} type>",
        "info": f"{tool} show [options] <{noun} type>",
        "md5": f"{tool} md5 <{noun} type>",
        "package": f"{tool} package <package>",
        "packages": f"{tool} packages",
        "list": f"{tool} list",
    }


class _Tool:
    """The state of one rosmsg/rossrv run: which kind, and the store."""

    def __init__(self, kind: str, env: Environment) -> None:
        self.kind = kind
        self.tool = "ros" + kind
        self.env = env
        self.store = TypeStore.from_environ(env.environ)

    def check_type_arg(self, command: str, type_name: str) -> None:
        usage = _usages(self.kind)[command]
        if "::" in type_name:
            raise usage_error(
                self.tool,
                usage,
                f"{self.tool} does not understand C++-style namespaces (i.e. '::').\n"
                "Please refer to msg/srv types as 'package_name/Type'.",
            )
        if "." in type_name:
            raise usage_error(
                self.tool,
                usage,
                f"invalid message type '{type_name}'.\n"
                "Please refer to msg/srv types as 'package_name/Type'.",
            )

    def matches(self, type_name: str) -> list[str]:
        """Full names for ``type_name``: itself, or every package's type of that bare name."""
        if "/" in type_name:
            return [type_name]
        return self.store.find(type_name, self.kind)

    def text(self, full_name: str, raw: bool) -> str:
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
            if not error.package_known:
                reason = (
                    f"Cannot locate message [{short}]: unknown package [{package}] "
                    f"on search path [{where}]"
                )
            else:
                reason = (
                    f"Cannot locate message [{short}] in package [{package}] with paths [{where}]"
                )
        else:
            reason = str(error)
        prefix = "Unable to load msg" if self.kind == "msg" else "Unknown srv type"
        return CommandError(f"{prefix} [{full_name}]: {reason}")

    def _search_paths(self, package: str) -> str:
        directory = self.store.package_dir(package)
        if directory is not None:
            return repr([str(directory / self.kind)])
        if self.store.has_package(package):
            return repr([])
        roots = self.store.path_packages
        return repr({name: [str(path / self.kind)] for name, path in roots.items()})


def build_app(kind: str) -> typer.Typer:
    """The typer app of ``rosmsg`` (kind ``msg``) or ``rossrv`` (kind ``srv``)."""
    app = tool_app(f"Displays information about ROS {_WHAT[kind]} types.")
    _add_show(app, kind)
    _add_md5(app, kind)
    _add_listings(app, kind)
    return app


def _add_show(app: typer.Typer, kind: str) -> None:
    noun = "message" if kind == "msg" else "service"

    def show(
        ctx: typer.Context,
        type_names: Annotated[list[str] | None, typer.Argument(metavar=f"<{noun} type>")] = None,
        raw: Annotated[
            bool, typer.Option("-r", "--raw", help="show raw message text, including comments")
        ] = False,
    ) -> int:
        tool = _Tool(kind, ctx.obj)
        command = ctx.info_name or "show"
        names = list(type_names or [])
        if len(names) > 1:
            raise usage_error(
                tool.tool, _usages(kind)[command], f"you may only specify one {noun} type"
            )
        if not names:
            line = tool.env.stdin.readline().strip()
            if not line:
                raise usage_error(
                    tool.tool, _usages(kind)[command], f"please specify a {noun} type"
                )
            names = [line]
        type_name = names[0]
        tool.check_type_arg(command, type_name)
        full_names = tool.matches(type_name)
        if not full_names:
            raise CommandError(f"Could not find msg '{type_name}'")
        for full_name in full_names:
            try:
                text = tool.text(full_name, raw)
            except (UnknownTypeError, InvalidMsgSpecError) as error:
                raise tool.load_error(full_name, error) from None
            if "/" not in type_name:
                tool.env.out(f"[{full_name}]:")
            tool.env.out(text)
        return ExitStatus.OK

    app.command("show", help=f"Show {noun} description")(show)
    app.command("info", help=f"Alias for ros{kind} show")(show)


def _add_md5(app: typer.Typer, kind: str) -> None:
    noun = "message" if kind == "msg" else "service"

    @app.command("md5", help=f"Display {noun} md5sum")
    def md5(
        ctx: typer.Context,
        type_names: Annotated[list[str] | None, typer.Argument(metavar=f"<{noun} type>")] = None,
    ) -> int:
        tool = _Tool(kind, ctx.obj)
        names = list(type_names or [])
        if len(names) != 1:
            raise usage_error(
                tool.tool, _usages(kind)["md5"], f"you may only specify one {noun} type"
            )
        type_name = names[0]
        tool.check_type_arg("md5", type_name)
        if "/" in type_name:
            try:
                tool.env.out(tool.md5(type_name))
            except (UnknownTypeError, InvalidMsgSpecError):
                tool.env.err(f"Cannot locate [{type_name}]")
            return ExitStatus.OK
        full_names = tool.matches(type_name)
        if not full_names:
            tool.env.err(f"No {noun}s matching the name [{type_name}]")
        for full_name in full_names:
            try:
                tool.env.out(f"[{full_name}]: {tool.md5(full_name)}")
            except (UnknownTypeError, InvalidMsgSpecError):
                tool.env.err(f"Cannot locate [{full_name}]")
        return ExitStatus.OK


def _add_listings(app: typer.Typer, kind: str) -> None:
    noun = "message" if kind == "msg" else "service"

    @app.command("list", help=f"List all {noun}s")
    def list_(ctx: typer.Context) -> int:
        tool = _Tool(kind, ctx.obj)
        for name in tool.store.types(kind):
            tool.env.out(name)
        return ExitStatus.OK

    @app.command("package", help=f"List {noun}s in a package")
    def package(
        ctx: typer.Context,
        packages: Annotated[list[str] | None, typer.Argument(metavar="<package>")] = None,
        single: Annotated[bool, typer.Option("-s", help="list all msgs on a single line")] = False,
    ) -> int:
        tool = _Tool(kind, ctx.obj)
        names = list(packages or [])
        if len(names) != 1:
            raise usage_error(
                tool.tool, _usages(kind)["package"], "you must specify one package name"
            )
        name = names[0]
        if not tool.store.has_package(name):
            paths = [str(p) for p in tool.store.package_path]
            lines = [f"Invalid package: {name}"] + [
                f"ROS path [{i}]={p}" for i, p in enumerate(paths)
            ]
            raise CommandError("\n".join(lines), ExitStatus.EX_USAGE)
        found = [t for t in tool.store.types(kind) if t.partition("/")[0] == name]
        _print_list(tool.env, found, single)
        return ExitStatus.OK

    @app.command("packages", help=f"List packages that contain {noun}s")
    def packages_(
        ctx: typer.Context,
        single: Annotated[
            bool, typer.Option("-s", help="list all packages on a single line")
        ] = False,
    ) -> int:
        tool = _Tool(kind, ctx.obj)
        _print_list(tool.env, tool.store.packages(kind), single)
        return ExitStatus.OK


def _print_list(env: Environment, items: list[str], single: bool) -> None:
    if single:
        env.out(" ".join(items))
    else:
        for item in items:
            env.out(item)


def main(argv: Sequence[str], env: Environment, kind: str) -> int:
    """Run ``rosmsg`` (``kind='msg'``) or ``rossrv`` (``kind='srv'``) on ``argv``."""
    commands = {name for name, _ in _COMMANDS[kind]}
    if not argv:
        env.out(_overview(kind))
        return ExitStatus.OK
    if argv[0] not in commands and argv[0] not in ("-h", "--help"):
        env.out(_overview(kind))
        return ExitStatus.EX_USAGE
    return run_app(build_app(kind), argv, env, tool="ros" + kind, usages=_usages(kind))


def rosmsg(argv: Sequence[str], env: Environment) -> int:
    return main(argv, env, "msg")


def rossrv(argv: Sequence[str], env: Environment) -> int:
    return main(argv, env, "srv")
