"""``rostopic pub /topic TYPE [args…]``: ROS 1's options, checks and errors, then `Publishing`.

Arguments are YAML, one document per word: field values in declaration order, or one dict
(``'{linear: {x: 2.0}}'``); ``now`` and ``auto`` stand for the current time and a header
stamped now. Without arguments the values come from ``-f FILE`` or standard input.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from rosx.terminal import is_terminal
from rosx_commands.cli import ToolParser
from rosx_commands.context import Environment, ExitStatus
from rosx_commands.rostopic.listing import resolve
from rosx_commands.rostopic.publishing import Publishing
from rosx_commands.rostopic.session import Session, fail

if TYPE_CHECKING:
    from collections.abc import Iterator

    from rosx.msg.codec.message import Message

#: ``-f``/stdin publishing's rate when ``-r`` is not given (and neither ``-l`` nor ``-1``).
DEFAULT_STREAM_RATE = 10.0


def _parser(env: Environment) -> ToolParser:
    parser = ToolParser(env, "rostopic", "usage: %prog pub /topic type [args...]")
    add = parser.add_option
    add("-v", dest="verbose", default=False, action="store_true", help="print verbose output")
    add(
        "-r",
        "--rate",
        dest="rate",
        default=None,
        help="publishing rate (hz).  For -f and stdin input, this defaults to 10.  "
        "Otherwise it is not set.",
    )
    add(
        "-1",
        "--once",
        action="store_true",
        dest="once",
        default=False,
        help="publish one message and exit",
    )
    add(
        "-f",
        "--file",
        dest="file",
        metavar="FILE",
        default=None,
        help="read args from YAML file (Bagy)",
    )
    add(
        "-l",
        "--latch",
        dest="latch",
        default=False,
        action="store_true",
        help="enable latching for -f, -r and piped input.  This latches the first message.",
    )
    add(
        "-s",
        "--substitute-keywords",
        dest="substitute_keywords",
        default=False,
        action="store_true",
        help="When publishing with a rate, performs keyword ('now' or 'auto') substitution "
        "for each message",
    )
    add(
        "--use-rostime",
        dest="use_rostime",
        default=False,
        action="store_true",
        help="use rostime for time stamps, else walltime is used",
    )
    return parser


def pub(argv: list[str], env: Environment) -> int:
    """``rostopic pub [options] /topic type [args...]``."""
    parser = _parser(env)
    options, args = parser.parse(argv)
    rate: float | None = None
    if options.rate is not None:
        if options.once:
            parser.error("You cannot select both -r and -1 (--once)")
        try:
            rate = float(options.rate)
        except ValueError:
            parser.error("rate must be a number")
        if rate <= 0:
            parser.error("rate must be greater than zero")
    if not args:
        parser.error("/topic must be specified")
    if len(args) == 1:
        parser.error("topic type must be specified")
    if len(args) > 2 and options.file:
        parser.error("args conflict with -f setting")
    topic_name, type_name = args[0], args[1]
    from rosx.msg.text.yamlargs import load_args  # noqa: PLC0415 - YAML loads on first use
    from rosx.msg.text.yamlload import YAMLLoadError  # noqa: PLC0415 - the text forms load on first use

    try:
        pub_args = load_args(args[2:])
    except YAMLLoadError as error:
        parser.error(f"Argument error: {error}")
    # Without -r, and also with -l, the publisher latches (decided before -f's default rate).
    latch = rate is None or options.latch
    with Session(env) as session:
        session.check_master()
        topic = resolve(env, topic_name)
        msg_class = _message_class(session, type_name)
        node = session.start_node(rosout=False)
        publisher = node.advertise(topic, msg_class, latch=latch, queue_size=100)
        publishing = Publishing(
            env,
            session,
            publisher,
            verbose=options.verbose,
            substitute_keywords=options.substitute_keywords,
        )
        if pub_args or not msg_class.__slots__:
            publishing.from_argv(pub_args, rate, options.once)
            return ExitStatus.OK
        if not options.file and is_terminal(env.stdin):
            parser.error("Please specify message values")
        if rate is None and not options.latch and not options.once:
            rate = DEFAULT_STREAM_RATE
        if options.file:
            documents = _file_documents(options.file)
            exactly_one = len(documents) == 1
            publishing.from_documents(documents, rate, options.once, exactly_one=exactly_one)
        else:
            publishing.from_documents(_stdin_documents(env), rate, options.once, exactly_one=False)
    return ExitStatus.OK


def _message_class(session: Session, type_name: str) -> type[Message]:
    """The class to publish, or ROS 1's ``invalid topic type`` / ``invalid message type``.

    As genpy looks a class up: a name that is not ``package/Type`` (bare ``Header`` aside) is an
    ``invalid topic type``; any other name that gives no class is an ``invalid message type``,
    with the hint to build its package.
    """
    from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - message classes load on first use

    try:
        return get_message_class(type_name, session.store)
    except Exception:  # unknown, or a definition that does not parse
        package, slash, rest = type_name.partition("/")
        if not (package and slash) or "/" in rest:
            fail(f"invalid topic type: {type_name}")
        fail(
            f"invalid message type: {type_name}.\n"
            f"If this is a valid message type, perhaps you need to type 'rosmake {package}'"
        )


def _file_documents(filename: str) -> list[Any]:
    """The documents of ``-f FILE``, each as the argument list of one message."""
    from rosx.msg.text.yamlload import YAMLLoadError, load_all  # noqa: PLC0415 - the text forms load on first use

    path = Path(filename)
    if not path.is_file():
        fail(f"file does not exist: {filename}")
    try:
        return [[document] for document in load_all(path.read_text(), filename=filename)]
    except YAMLLoadError as error:
        fail(f"invalid YAML in file: {error}")
    except (OSError, UnicodeDecodeError) as error:
        fail(f"cannot read {filename}: {error}")


def _stdin_documents(env: Environment) -> Iterator[Any]:
    """The ``---``-terminated YAML documents of standard input, read as they come."""
    from rosx.msg.text.yamlload import load_stream  # noqa: PLC0415 - the text forms load on first use

    def invalid(error: Exception) -> None:
        env.stderr.write(f"Invalid YAML: {error}\n")
        env.stderr.flush()

    return load_stream(iter(env.stdin.readline, ""), on_error=invalid)
