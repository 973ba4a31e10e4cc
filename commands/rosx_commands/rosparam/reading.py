"""``rosparam get``, ``dump`` and ``list``: parameter values as YAML, and their names.

``get`` prints ``yaml.dump`` of the value with PyYAML's ``...`` document end removed and a
blank line added (so a namespace ends with an empty line, a number does not); ``-p`` prints a
namespace key by key, strings raw (not YAML-safe, as ROS 1 warns). ``dump`` writes ``yaml.dump``
of a namespace to a file or stdout.
"""

from __future__ import annotations

from rosx.msg.text.yamlparams import dump_value
from rosx.names.resolution import make_global_ns
from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rosparam.server import ParamServer

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

_DOCUMENT_END = "\n...\n"


def _verbose_option(parser: ToolParser) -> None:
    parser.add_option(
        "-v", dest="verbose", default=False, action="store_true", help="turn on verbose output"
    )


def get(argv: list[str], env: Environment) -> int:
    """``rosparam get NAME``: a parameter or namespace as YAML (``-p`` pretty)."""
    parser = ToolParser(env, "rosparam", "usage: %prog get [options] parameter")
    parser.add_option(
        "-p",
        dest="pretty",
        default=False,
        action="store_true",
        help="pretty print. WARNING: not YAML-safe",
    )
    _verbose_option(parser)
    options, args = parser.parse(argv)
    if not args:
        parser.error("invalid arguments. Please specify a parameter name")
    if len(args) > 1:
        parser.error("too many arguments")
    server = ParamServer(env)
    name = server.resolve(args[0])
    if options.verbose:
        env.out(f"getting parameter [{name}]")
    value = server.get(name)
    if options.pretty and type(value) is dict:
        _pretty_print(env, value, "")
    elif options.pretty and type(value) is str:
        env.out(value)
    else:
        text = dump_value(value)
        if text.endswith(_DOCUMENT_END):
            text = text[: -len(_DOCUMENT_END)]
        env.out(text)
    return ExitStatus.OK


def _pretty_print(env: Environment, tree: dict[str, Any], indent: str) -> None:
    for key in sorted(tree):
        value = tree[key]
        if type(value) is dict:
            env.out(f"{indent}{key}:")
            _pretty_print(env, value, indent + "  ")
        elif type(value) is str and "\n" in value:
            env.out(f"{indent}{key}: |")
            for line in value.split("\n"):
                env.out(f"{indent}  {line}")
        elif type(value) is str:
            env.out(f"{indent}{key}: {value}")
        else:
            text = dump_value(value)
            if text.endswith(_DOCUMENT_END):
                text = text[: -len(_DOCUMENT_END) + 1]
            env.stdout.write(f"{indent}{key}: {text}")


def dump(argv: list[str], env: Environment) -> int:
    """``rosparam dump FILE [NS]``: a namespace written as a YAML file."""
    parser = ToolParser(env, "rosparam", "usage: %prog dump [options] file [namespace]")
    _verbose_option(parser)
    options, args = parser.parse(argv)
    if len(args) > 2:
        parser.error("too many arguments")
    filename = args[0] if args else None
    namespace = args[1] if len(args) > 1 else ""
    if options.verbose:
        env.out(f"dumping namespace [{namespace}] to file [{filename}]")
    server = ParamServer(env)
    name = server.resolve(namespace)
    tree = server.get(name)
    if options.verbose:
        server.print_params(tree, name)
    text = dump_value(tree)
    if not filename:
        env.stdout.write(text)
        return ExitStatus.OK
    from pathlib import Path  # noqa: PLC0415 - only dump writes a file

    try:
        Path(filename).write_text(text, encoding="utf-8")
    except OSError as error:
        raise CommandError(f"ERROR: cannot write [{filename}]: {error.strerror}") from None
    return ExitStatus.OK


def list_params(argv: list[str], env: Environment) -> int:
    """``rosparam list [NS]``: every parameter name."""
    parser = ToolParser(env, "rosparam", "usage: %prog list [namespace]")
    _, args = parser.parse(argv)
    server = ParamServer(env)
    namespace = "/"
    if len(args) == 1:
        namespace = server.resolve(args[0])
    elif len(args) == 2:
        # ROS 1 refuses exactly two arguments, and ignores three or more.
        parser.error("too many arguments")
    prefix = make_global_ns(namespace)
    env.out("\n".join(n for n in sorted(server.names()) if n.startswith(prefix)))
    return ExitStatus.OK
