"""``rosparam set``, ``load`` and ``delete``.

``set`` reads its value as YAML (so ``5`` is an int, ``5.0`` a float, ``'5'`` a string, a dict
updates a namespace), or takes a text file (``-t``, a string) or a binary file (``-b``, XML-RPC
base64). Negative numbers are values, not options: like ROS 1, rosx hands optparse only the
words that are options. ``load`` uploads each document of a YAML file (or stdin, ``-``) under a
namespace, which a document's ``_ns`` key extends.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rosx.msg.text.yamlparams import AngleError, YAMLLoadError, load_documents, load_value
from rosx.names.resolution import GLOBAL_NS, ns_join
from rosx_commands.cli import ToolParser
from rosx_commands.context import CommandError, Environment, ExitStatus
from rosx_commands.rosparam.server import ParamServer
from rosx_commands.yamltext import one_line

#: A document key naming the namespace its parameters go to (relative to the load namespace).
NS_KEY = "_ns"
_FILE_OPTIONS = ("-t", "--textfile", "-b", "--binfile")


def _verbose_option(parser: ToolParser) -> None:
    parser.add_option(
        "-v", dest="verbose", default=False, action="store_true", help="turn on verbose output"
    )


def _split_negative_args(parser: ToolParser, argv: list[str]) -> tuple[Any, list[str]]:
    """Options through optparse, arguments (negative numbers included) kept aside."""
    args: list[str] = []
    option_words: list[str] = []
    takes_value = False
    for word in argv:
        if word.startswith("-"):
            if word in _FILE_OPTIONS:
                takes_value = True
                option_words.append(word)
            elif takes_value:
                parser.error("-t and --textfile options require an argument")
            elif len(word) > 1 and word[1].isdigit() and word[1].isascii():
                args.append(word)
            else:
                option_words.append(word)
        elif takes_value:
            takes_value = False
            option_words.append(word)
        else:
            args.append(word)
    options, _ = parser.parse(option_words)
    return options, args


def set_param(argv: list[str], env: Environment) -> int:
    """``rosparam set NAME VALUE``: a YAML value (or a file's text, ``-t``/``-b``)."""
    parser = ToolParser(env, "rosparam", "usage: %prog set [options] parameter value")
    parser.add_option(
        "-t",
        "--textfile",
        dest="text_file",
        default=None,
        metavar="TEXT_FILE",
        help="set parameters to contents of text file",
    )
    parser.add_option(
        "-b",
        "--binfile",
        dest="bin_file",
        default=None,
        metavar="BINARY_FILE",
        help="set parameters to contents of binary file",
    )
    _verbose_option(parser)
    options, args = _split_negative_args(parser, argv)
    if options.text_file and options.bin_file:
        parser.error("you may only specify one of --textfile or --binfile")
    if not args:
        parser.error("invalid arguments. Please specify a parameter name")
    if len(args) == 1 and not (options.text_file or options.bin_file):
        parser.error("invalid arguments. Please specify a parameter value")
    if len(args) > 2:
        parser.error("too many arguments")
    server = ParamServer(env)
    name = server.resolve(args[0])
    value: Any
    if options.text_file:
        if not Path(options.text_file).is_file():
            parser.error(f"file '{options.text_file}' does not exist")
        value = _read_file(options.text_file, text=True)
    elif options.bin_file:
        if not Path(options.bin_file).is_file():
            parser.error(f"file '{options.bin_file}' does not exist")
        value = _read_file(options.bin_file, text=False)
    else:
        # The empty string is hard to type: rosparam takes it for a YAML empty string.
        value = _load_value(args[1] if args[1] != "" else "!!str")
    server.set_raw(name, value, verbose=options.verbose)
    return ExitStatus.OK


def _read_file(filename: str, *, text: bool) -> str | bytes:
    path = Path(filename)
    try:
        return path.read_text(encoding="utf-8") if text else path.read_bytes()
    except (OSError, UnicodeDecodeError) as error:
        raise CommandError(f"ERROR: cannot read [{filename}]: {error}") from None


def _load_value(text: str) -> Any:
    try:
        return load_value(text)
    except YAMLLoadError as error:
        raise CommandError(f"ERROR: Invalid YAML value: {one_line(str(error))}") from None
    except AngleError as error:
        raise CommandError(f"ERROR: {error}") from None


def load(argv: list[str], env: Environment) -> int:
    """``rosparam load FILE [NS]``: every parameter of a YAML file."""
    parser = ToolParser(env, "rosparam", "usage: %prog load [options] file [namespace]")
    _verbose_option(parser)
    options, args = parser.parse(argv)
    if not args:
        parser.error("invalid arguments. Please specify a file name or - for stdin")
    if len(args) > 2:
        parser.error("too many arguments")
    server = ParamServer(env)
    default_ns = server.resolve(args[1] if len(args) > 1 else None)
    text = _read_source(env, args[0], options.verbose)
    documents: list[tuple[Any, str]] = []
    for document in _load_documents(text, args[0]):
        namespace = default_ns
        if type(document) is dict and NS_KEY in document:
            namespace = ns_join(default_ns, str(document.pop(NS_KEY)))
            if options.verbose:
                env.out(f"reading parameters into namespace [{namespace}]")
        if document is not None:
            documents.append((document, namespace))
    for values, namespace in documents:
        if namespace == GLOBAL_NS and type(values) is not dict:
            raise CommandError("ERROR: global / can only be set to a dictionary")
    for values, namespace in documents:
        if options.verbose:
            server.print_params(values, namespace)
        server.set_raw(namespace, values)
    return ExitStatus.OK


def _read_source(env: Environment, filename: str, verbose: bool) -> str:
    if not filename or filename == "-":
        if verbose:
            env.out("reading parameters from stdin")
        return env.stdin.read()
    if not Path(filename).is_file():
        raise CommandError(f"ERROR: file [{filename}] does not exist")
    if verbose:
        env.out(f"reading parameters from [{filename}]")
    text = _read_file(filename, text=True)
    assert isinstance(text, str)
    return text


def _load_documents(text: str, filename: str) -> list[Any]:
    try:
        return load_documents(text)
    except YAMLLoadError as error:
        source = "stdin" if filename in ("", "-") else filename
        raise CommandError(f"ERROR: Invalid YAML in [{source}]: {one_line(str(error))}") from None
    except AngleError as error:
        raise CommandError(f"ERROR: {error}") from None


def delete(argv: list[str], env: Environment) -> int:
    """``rosparam delete NAME``: remove a parameter or namespace."""
    parser = ToolParser(env, "rosparam", "usage: %prog delete [options] parameter")
    _verbose_option(parser)
    options, args = parser.parse(argv)
    if not args:
        parser.error("invalid arguments. Please specify a parameter name")
    if len(args) > 1:
        parser.error("too many arguments")
    server = ParamServer(env)
    name = server.resolve(args[0])
    if name == GLOBAL_NS:
        # The root must keep a value: deleting it empties the server instead.
        server.replace_root()
        if options.verbose:
            env.out("deleted ENTIRE parameter server")
    else:
        server.delete(name)
        if options.verbose:
            env.out(f"deleted parameter [{name}]")
    return ExitStatus.OK
